"""A figure as plain data, for a page that draws it in the browser as the SVG writer does.

The page (``page/view.js``) draws no figure of its own: it writes each primitive of a
:class:`~.figure.Figure` as :mod:`.svg` writes it (a path, a circle, a text with its
tspans), in the styles of :data:`~.figure.STYLES`, which the data names once. So a new
symbol or a new kind of line that the figures learn is on the page with no line of
script. Each primitive is a short list:

* ``["p", style, [x0, y0, x1, y1, …]]``: a polyline (``"z"`` for a closed one);
* ``["c", style, [x, y, r]]``: a circle;
* ``["t", "", [run, …]]``: a text, as the runs of one direction each it is set as, each
  ``[x, y, size, anchor, face, text, [[tspan text, size, dy], …]]``; ``face`` holds
  ``r`` (right to left, in its own face), ``i`` (italic) and ``b`` (bold);

all in paper millimetres written as the SVG writes them, and, where the caller says
more of it, a fourth element: a dict of what the page needs to show the primitive step by
step or move it (:mod:`tarsim.exercises.linkages.view` says which).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any

from .figure import STYLES, Circle, Figure, Path, Text
from .rtl import RTL_FONT
from .svg import TEXT_ATTRIBUTES, coordinate, runs, style_attributes, text_attributes, tspans

__all__ = ["figure_data", "style_data", "number", "FONTS"]

FONTS = {"text": TEXT_ATTRIBUTES["font-family"], "rtl": RTL_FONT}
"""The faces a text is set in: the figures' own, and a right-to-left text's."""


def number(v: float) -> float | int:
    """A length on paper as the SVG writes it (to a micrometre), as a JSON number: a page
    that prints it back writes the same characters.

    >>> number(12.34049), number(-0.0001), number(3.0)
    (12.34, 0, 3)
    """
    f = float(coordinate(v))
    return int(f) if f.is_integer() else f


def style_data(names: Iterable[str]) -> dict[str, dict[str, str]]:
    """Each named style once, as the SVG attributes it is written with; ``text`` is the
    attributes of every text.

    >>> style_data(["dot"])["dot"]
    {'fill': '#000', 'stroke': 'none'}
    """
    out = {name: style_attributes(STYLES[name]) for name in sorted(set(names))}
    out["text"] = dict(TEXT_ATTRIBUTES)
    return out


def figure_data(fig: Figure, more: Sequence[dict[str, Any] | None] = ()) -> dict[str, Any]:
    """``fig`` as data: its size, the box its drawing fills (x0, y0, x1, y1), its
    primitives in order (each with ``more[i]`` when given and not empty) and its views,
    each as ``[scale, x, y]`` (paper mm per world unit and where the world's origin
    stands).

    >>> fig = Figure(20.0, 10.0)
    >>> fig.add(Path(((0.0, 0.0), (10.0, 5.25)), "link"))
    >>> fig.add(Text((10.0, 5.0), "V", sub="B"))
    >>> data = figure_data(fig)
    >>> data["items"][0]
    ['p', 'link', [0, 0, 10, 5.25]]
    >>> data["items"][1][2][0][5:]
    ['V', [['B', 2.52, 0.98]]]
    """
    items = []
    for k, item in enumerate(fig.items):
        out = _primitive(item)
        extra = more[k] if k < len(more) else None
        if extra:
            out.append(extra)
        items.append(out)
    box = [number(v) for v in fig.bounds()] if fig.items else [0, 0, 0, 0]
    return {"w": number(fig.width), "h": number(fig.height), "box": box, "items": items,
            "views": {name: [v.scale, v.origin[0], v.origin[1]]
                      for name, v in fig.views.items()}}


def _primitive(item: Path | Circle | Text) -> list:
    if isinstance(item, Path):
        return ["z" if item.closed else "p", item.style,
                [number(v) for p in item.points for v in p]]
    if isinstance(item, Circle):
        return ["c", item.style, [number(item.centre[0]), number(item.centre[1]),
                                  number(item.radius)]]
    return ["t", "", [_run(run) for run in _runs(item)]]


def _runs(item: Text) -> list[Text]:
    """The texts of one direction each a text is written as, as :mod:`.svg` writes them."""
    parts = runs(item)
    return [item] if parts is None else [r for part in parts for r in _runs(part)]


def _run(item: Text) -> list:
    """One text of one direction: where and how it is set, its words and its tspans."""
    attrs = text_attributes(item)
    face = ("r" if attrs.get("direction") == "rtl" else "") \
        + ("i" if attrs.get("font-style") == "italic" else "") \
        + ("b" if attrs.get("font-weight") == "bold" else "")
    return [number(float(attrs["x"])), number(float(attrs["y"])), number(item.size),
            attrs["text-anchor"], face, item.text,
            [[words, number(size), number(dy)] for words, size, dy in tspans(item)]]
