"""Each frame's polygon scales on the interactive page: a polygon rescaled at every
position of the turn to fill its panel, as a figure drawn there would be.

A polygon drawn at one scale for the whole turn shrinks to a blob where its velocities
are small and outgrows its panel where they are large. So each frame chooses, for each
polygon panel of a figure the page turns (:func:`~.view_figures._turning`), the nice
scale (1, 2 or 5 × 10^k a paper cm, :func:`~tarsim.constructions.scales.nice_per_cm`, as
the figures choose theirs) at which that frame's polygon fills the room a figure gives a
polygon, and the page draws the polygon at it in its panel, the panel's frame grown or
shrunk round it, and states it in the panel's scale statement.
"""

from __future__ import annotations

from typing import Any

from tarsim.constructions.units import Units
from tarsim.constructions.narration import speaking, words
from tarsim.constructions.scales import nice_per_cm
from tarsim.graphics.linkages.polygon_panel import POLYGON_BOX
from tarsim.graphics.scales import scale_text

__all__ = ["frame_fits", "CLEAR"]

_QUANTITY = {"velocity": ("Velocity scale", "v", "/s"),
             "acceleration": ("Acceleration scale", "a", "/s²")}
"""Each polygon view: its scale statement's name, its key in the frames' scales, and the
time part of its unit."""


def frame_fits(panels: dict[str, list[float]], frames: list[dict], scales: dict[str, float],
               units: Units, languages: tuple[str, ...]) -> dict[str, Any]:
    """The scale of each polygon of ``panels`` (its frame on paper, ``[x0, y0, width,
    height, caption]`` mm, by view) at each frame: ``{"at": {view: [mm, x, y, i, width,
    height, …]}, "said": {view: [{lang: statement}, …]}}``. For each frame: paper mm a
    world unit of the view, at the nice scale that fits the frame's polygon in
    :data:`~tarsim.graphics.linkages.polygon_panel.POLYGON_BOX` as a figure fits it;
    the world point set at the middle of the polygon's room (the middle of the frame's
    polygon); ``i``, the frame's scale statement among ``said``'s; and the panel's size
    round it, :data:`CLEAR` of white round the polygon and its caption under it (no
    narrower than drawn). Six nulls for a frame not drawn. ``scales`` are the polygons'
    construction scales (drawing m per m/s, per m/s²) the frames are sent at.

    Examples
    --------
    A velocity polygon 0.3 m/s across and 0.1 m/s high (at a drawing metre per m/s): 1
    cm = 50 mm/s fits it in 120 mm across, so 2000 mm a drawing metre, a polygon 60 mm
    by 20 mm in a panel 80 mm by 40 mm above its caption of 12 mm.

    >>> fits = frame_fits({"velocity": [0, 0, 50, 30, 12]},
    ...                   [{"at": {"velocity": [0.0, 0.0, 0.3, 0.1]}}],
    ...                   {"v": 1.0, "a": 1.0}, Units("mm"), ("en",))
    >>> fits["at"]["velocity"], fits["said"]["velocity"]
    ([200.0, 0.15, 0.05, 0, 80.0, 52.0], [{'en': 'Velocity scale 1 cm = 50 mm/s'}])
    """
    out: dict[str, Any] = {"at": {}, "said": {}}
    for view, (_, _, width, _, caption) in panels.items():
        name, key, per_time = _QUANTITY[view]
        drawn = scales[key] * units.metres          # drawing metres per file unit a second
        per_cms: list[float] = []
        at: list[float | None] = []
        for f in frames:
            xy = f.get("at", {}).get(view)
            pts = [(x, y) for x, y in zip(xy[::2], xy[1::2]) if x is not None] if xy else []
            if not pts:
                at += [None] * 6
                continue
            xs, ys = [x for x, _ in pts], [y for _, y in pts]
            spans = (max(xs) - min(xs), max(ys) - min(ys))
            per_cm = max((nice_per_cm(span / drawn, room)
                          for span, room in zip(spans, POLYGON_BOX) if span > 0.0), default=1.0)
            if per_cm not in per_cms:
                per_cms.append(per_cm)
            mm = 10.0 / (per_cm * drawn)
            at += [float(f"{mm:.9g}"), round((min(xs) + max(xs)) / 2, 9),
                   round((min(ys) + max(ys)) / 2, 9), per_cms.index(per_cm),
                   round(max(width, spans[0] * mm + 2 * CLEAR), 3),
                   round(spans[1] * mm + 2 * CLEAR + caption, 3)]
        said = []
        for per_cm in per_cms:
            statement = {}
            for lang in languages:
                with speaking(lang):
                    statement[lang] = f"{words(name)} {scale_text(per_cm, units.length + per_time)}"
            said.append(statement)
        out["at"][view], out["said"][view] = at, said
    return out


CLEAR = 10.0
"""The white (mm) round a polygon the page rescales, inside its panel's frame: room for
the labels round its tips."""
