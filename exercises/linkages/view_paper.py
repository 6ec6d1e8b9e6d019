"""What of a page's figure stands on the paper rather than on the mechanism: its title,
caption, scale bars and legend, which a frame the page turns to keeps.

The page shows a turned frame with the primitives that move with the mechanism alone
(:mod:`.view_figures`); a frame downloaded as a figure of its own needs its captions and
scales too, and its caption must say the frame's angle, not the exercise's. A primitive
that stands on no named point and on no step is the paper's if the figure drawn a little
further on, in the same language, draws it identically; a text that says the input's
angle (``θ₂ = 90°``) and changes with it is the caption the page sets at each frame's
angle.
"""

from __future__ import annotations

import re
from typing import Any

from tarsim.graphics.figure import Figure
from tarsim.graphics.figure_data import figure_data

__all__ = ["mark_paper", "ANGLE", "home_points"]

ANGLE = r"θ[₀-₉0-9]+ = [−\-0-9.۰-۹٫]+°"
"""An angle as a caption says it ("θ₂ = 90°", "θ2 = −30.5°", "θ₂ = ۹۰°"); the page's
script finds the input's by the same pattern (graphics/page/view.js, ``ANGLE``)."""


def _said(item: list) -> str:
    """A text primitive's words, its runs and their subscripts in order."""
    return "".join(run[5] + "".join(s[0] for s in run[6]) for run in item[2])


NEAR = 0.02
"""How near (paper mm) the figure drawn a little on must draw a path's shape for it to be
the paper's: a scale bar or a legend's line keeps its shape exactly, wherever the caption
is set, and a path of the drawing turns or stretches with the mechanism."""


def _key(item: list) -> tuple[str, str, str]:
    """What a primitive is, its place aside: its kind, its style and its words."""
    return (item[0], item[1], _said(item) if item[0] == "t" else "")


def _shape(item: list) -> list[float]:
    """A primitive's shape, where it is set aside: a path's points from its first, a
    circle's radius; nothing of a text, set by its words."""
    if item[0] == "t":
        return []
    if item[0] == "c":
        return [item[2][2]]
    g = item[2]
    return [v - g[k % 2] for k, v in enumerate(g)]


def _words(item: list) -> bool:
    """Whether a text is words of the paper: set upright, as a caption, a title, a scale
    or a legend is, where the drawing's names and symbols (θ₂, ω₂, B) are italic."""
    return all("i" not in run[4] for run in item[2])


def mark_paper(data: dict[str, Any], near: Figure | None) -> dict[str, Any]:
    """``data`` (a figure as :func:`~tarsim.graphics.figure_data.figure_data` wrote it, its
    primitives' page fields in place) with ``p`` set on each primitive of the paper: 1
    for one every frame keeps as it is, ``"angle"`` for a text that says the input's angle.
    ``near`` is the figure drawn a little further on, in the same language (None where
    it is not: then no primitive is marked). A caption is set where the drawing leaves
    room, so a primitive of the paper is known by its words or its shape, not its place.
    """
    if near is None:
        return data
    drawn: dict[tuple, list[list[float]]] = {}
    for it in figure_data(near)["items"]:
        drawn.setdefault(_key(it), []).append(_shape(it))

    def kept(item: list) -> bool:
        here = _shape(item)
        return any(len(xy) == len(here) and all(abs(a - b) <= NEAR for a, b in zip(xy, here))
                   for xy in drawn.get(_key(item), ()))

    for item in data["items"]:
        more = item[3] if len(item) > 3 else {}
        if "m" in more or "s" in more:
            continue
        mark = None
        if item[0] == "t" and not _words(item):
            continue
        if item[0] == "t" and re.search(ANGLE, _said(item)) and not kept(item):
            mark = "angle"
        elif kept(item):
            mark = 1
        if mark is not None:
            if len(item) > 3:
                item[3]["p"] = mark
            else:
                item.append({"p": mark})
    return data


def home_points(mech, names: dict[str, list[str]]) -> dict[str, Any]:
    """The named points the page's opening view is fitted to at every frame, beside all
    the figure draws at the exercise's position: the mechanism's joints (their indices
    in ``names["space"]``, as the frames send them). An instant centre is left out: it
    runs off toward infinity as the mechanism turns, and would shrink the view to
    nothing."""
    own = set(mech.point_names)
    return {"view": "space", "points": [i for i, n in enumerate(names["space"]) if n in own]}
