"""A cam of arcs drawn to scale, as the books draw it to work its motion: the base circle
about O and the nose circle about Q (thin), the outline (heavy: the flanks and the nose,
the base circle's working part), the line OQ, and for a circular-arc cam the flank
circles' centres P on the far side, each joined to O and Q. The angle of lift α is marked
at O from the start of the lift to OQ; the follower is drawn at the apex (the face across
the nose, or the roller on it)."""

from __future__ import annotations

import math

from tarsim.constructions.narration import numerals, unit_words, words
from ..figure import Circle, Figure, Path, Text, arc_points
from ..fitting import to_sheet
from ..scales import draw_caption, nice_per_cm

__all__ = ["draw_arc_cam"]

_ROOM = 120.0          # paper (mm) the cam's reach across is fitted to


def draw_arc_cam(cam_outline, cam, title: str, unit: str, metre: float,
                 per_cm: float | None = None) -> Figure:
    """The outline ``cam_outline`` of ``cam`` (an :class:`~tarsim.constructions.cams.
    arc_cam.ArcCam`); lengths stated in ``unit`` (``metre`` metres each), at ``per_cm``
    (by default the scale that fits its room, fitted to the sheet it is drawn on)."""
    reach = cam.d + cam.nose + 2 * cam.roller
    if per_cm is None:
        return to_sheet(lambda at: draw_arc_cam(cam_outline, cam, title, unit, metre, at),
                        nice_per_cm(2 * reach / metre, _ROOM))
    k = 10.0 / (per_cm * metre)

    def paper(xy) -> tuple[float, float]:
        return xy[0] * k, -xy[1] * k

    fig = Figure(0.0, 0.0, title=title)
    o, q = paper((0.0, 0.0)), paper((cam.d, 0.0))
    fig.add(Circle(o, cam.base * k, "dimension"))
    fig.add(Circle(q, cam.nose * k, "dimension"))
    fig.add(Path((o, q), "construction"))
    for part in cam_outline.parts:
        if hasattr(part, "normal"):
            fig.add(Path((paper(part.a), paper(part.b)), "link"))
            continue
        fig.add(Path(tuple(arc_points(paper(part.centre), part.radius * k, part.start,
                                      part.sweep)), "link"))
    named = [("O", o), ("Q", q)]
    if cam_outline.flank_centre is not None:
        px, py = cam_outline.flank_centre
        for p in ((px, py), (px, -py)):
            fig.add(Path((paper(p), q), "construction"))
            fig.add(Path((paper(p), o), "construction"))
            fig.add(Circle(paper(p), 0.6, "dot"))
        named.append(("P", paper((px, py))))
    for name, at in named:
        fig.add(Circle(at, 0.6, "dot"))
        left = name == "Q"                 # Q's label inside the nose, clear of its outline
        fig.add(Text((at[0] + (-1.5 if left else 1.5), at[1] + 4.0), name, 3.2,
                     "end" if left else "start", True))
    if cam.kind != "eccentric":
        # The angle of lift at O, from where the lift begins to OQ.
        r = 0.45 * cam.base * k
        fig.add(Path(tuple(arc_points(o, r, 0.0, cam.alpha)), "dimension"))
        start = (math.cos(cam.alpha) * cam.base, math.sin(cam.alpha) * cam.base)
        fig.add(Path((o, paper(start)), "construction"))
        mid = cam.alpha / 2
        fig.add(Text((o[0] + (r + 2.5) * math.cos(mid),
                      o[1] - (r + 2.5) * math.sin(mid) + 1.0), "α", 3.2, "start", True))
    # The follower at the apex.
    apex = cam.d + cam.nose
    if not cam.flat and cam.roller > 0:
        fig.add(Circle(paper((apex + cam.roller, 0.0)), cam.roller * k, "reference"))
    elif not cam.flat:                         # a knife edge at the apex
        fig.add(Path((paper((apex, 0.0)), paper((apex + 0.4 * cam.base, 0.0))), "reference"))
    else:
        fig.add(Path((paper((apex, -0.6 * cam.base)), paper((apex, 0.6 * cam.base))),
                     "reference"))
    lines = [words("the disc's radius {r2}, its eccentricity OQ = {d}", r2=_size(
        cam.nose, metre, unit), d=_size(cam.d, metre, unit))] if cam.kind == "eccentric" else [
        words("r₁ = {r1}, r₂ = {r2}, OQ = {d}, α = {alpha}°", r1=_size(cam.base, metre, unit),
                   r2=_size(cam.nose, metre, unit), d=_size(cam.d, metre, unit),
                   alpha=numerals(f"{math.degrees(cam.alpha):.4g}"))]
    if cam.kind == "circular arc":
        lines.append(words("the flank's radius R = {R}", R=_size(cam.flank_radius, metre, unit)))
    draw_caption(fig, title, lines, per_cm=per_cm, unit=unit,
                 legend=(("link", "the cam's outline"),
                         ("reference", "the follower at the apex")))
    return fig


def _size(v: float, metre: float, unit: str) -> str:
    return f"{numerals(f'{v / metre:.4g}')} {unit_words(unit)}"
