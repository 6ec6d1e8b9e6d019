"""The follower's displacement diagram as a textbook draws it: the construction inked.

Cam angle runs across and lift up, both to scale. The figure draws the base line with the
cam angle every 30°, each ordinate up to the curve, the working lines the construction
inked (projections across, the divided line and its parallels, the runs along the
diagonal) and its arcs (the semicircles, the cycloid's circles), the constructed points
numbered, and the curve through them (the law's, so it runs smooth between them).
"""

from __future__ import annotations

import math

from ..constructions.cams.displacement import Displacement
from .figure import Circle, Figure, Path, Text, arc_points
from .scales import draw_caption, nice_per_cm

__all__ = ["draw_displacement_figure"]

_ROOM = (230.0, 80.0)      # paper (mm) a turn and the greatest lift are fitted to


def draw_displacement_figure(d: Displacement, curve: list[tuple[float, float]], title: str,
                             unit: str, metre: float) -> Figure:
    """The diagram ``d`` with the smooth ``curve`` (cam angle in rad, lift in m) through its
    points; lengths stated in ``unit`` (``metre`` metres each)."""
    c = d.construction
    top = max(y for _, y in curve) or 1.0
    width = 2 * math.pi * d.per_rad
    per_cm = max(nice_per_cm(width / metre, _ROOM[0]), nice_per_cm(top / metre, _ROOM[1]))
    k = 10.0 / (per_cm * metre)                    # paper mm per drawing metre

    def paper(xy) -> tuple[float, float]:
        return xy[0] * k, -xy[1] * k

    fig = Figure(0.0, 0.0, title=title)
    right = width * k
    fig.add(Path(((0.0, 0.0), (right, 0.0)), "link"))            # the base line
    for deg in range(0, 361, 30):
        x = math.radians(deg) * d.per_rad * k
        fig.add(Path(((x, 0.0), (x, 1.5)), "dimension"))
        fig.add(Text((x, 4.5), f"{deg}°", 2.8, "middle", False))
    for start, end in d.strokes:
        fig.add(Path((paper(c.output(start).xy), paper(c.output(end).xy)), "construction"))
    for centre, first, sweep in d.arcs:
        cx, cy = paper(c.output(centre).xy)
        fx, fy = paper(c.output(first).xy)
        r = math.hypot(fx - cx, fy - cy)
        start = math.atan2(-(fy - cy), fx - cx)
        fig.add(Path(tuple(arc_points((cx, cy), r, start, sweep)), "construction"))
    for segment in d.curves:
        for i, (_, ref) in enumerate(segment):
            x, y = paper(c.output(ref).xy)
            fig.add(Path(((x, 0.0), (x, y)), "reference"))          # its ordinate
            fig.add(Circle((x, y), 0.6, "dot"))
            if 0 < i < len(segment) - 1:
                fig.add(Text((x + 1.6, y - 1.8), str(i), 2.6, "start", False))
    fig.add(Path(tuple(paper((t * d.per_rad, y)) for t, y in curve), "vector_result"))
    draw_caption(fig, title, ["cam angle across, the follower's lift up; the construction "
                              "of each segment inked thin, its points numbered"],
                 per_cm=per_cm, unit=unit,
                 legend=(("vector_result", "displacement"), ("construction",
                                                             "construction lines"),
                         ("reference", "ordinates")))
    return fig
