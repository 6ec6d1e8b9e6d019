"""How near a tip cut from two lines must stand: within each line's drafting tolerance,
measured across that line.

A student draws each line through a tip found before (or the pole) with a set square: it
stands off true by the pen's width and turns by the set square's angle about its point, so
at the tip it is off by ``pen + lever·tan(angle)`` across itself, ``lever`` being the tip's
distance from the point the line is drawn through. The tip is where the two lines cross, so
it may stand anywhere in the parallelogram those two bands make: far along a line that the
other crosses at a slant, near across both. A circle round the tip would either pass a tip
pushed off one line (a magnitude a few per cent long, where the lines cross square) or fail
one drawn rightly along a slanting crossing.
"""

from __future__ import annotations

import math

from tarsim.constructions import geometry as g

__all__ = ["Band", "bands", "within", "reach"]

Vec = tuple[float, float]


class Band:
    """One line a tip is cut from, on paper: its unit normal, and how far across it the
    tip may stand."""

    __slots__ = ("normal", "width")

    def __init__(self, normal: Vec, width: float):
        self.normal, self.width = normal, width


def bands(polygon, key: str, frame, exp: Vec, pen: float, angle: float,
          least: float) -> list[Band] | None:
    """The two bands of the tip ``key`` of tarsim's ``polygon``, laid by ``frame`` with its
    tip at ``exp`` (paper), for a pen of ``pen`` mm and a set square true to ``angle``; each
    widened by its line's conditioning (at least ``least``): the point it is drawn through
    and the space diagram's line it takes its direction from, as found. None if the tip
    is not cut from two lines through points."""
    c = polygon.construction
    step = c[polygon.tip(key)]
    if step.verb != "intersect_lines":
        return None
    pole = c.output(polygon.pole).xy
    origin = frame.place((0.0, 0.0))

    def paper(p) -> Vec:
        return frame.place(((p[0] - pole[0]) / polygon.scale, (p[1] - pole[1]) / polygon.scale))
    out = []
    for ref in step.inputs:
        line_step = c[ref]
        line = line_step.output
        through = c.output(line_step.inputs[0]) if line_step.inputs else None
        if not isinstance(line, g.Line) or line.is_at_infinity or \
                not isinstance(through, g.Point) or through.is_at_infinity:
            return None
        d = frame.place(line.direction)
        d = (d[0] - origin[0], d[1] - origin[1])
        size = math.hypot(*d)
        if size == 0.0:
            return None
        lever = math.dist(exp, paper(through.xy))
        widen = max(line_step.conditioning, least)
        out.append(Band((-d[1] / size, d[0] / size),
                        (pen + lever * math.tan(angle)) / widen))
    return out


def within(found: Vec, exp: Vec, tip_bands: list[Band]) -> bool:
    """True if ``found`` stands within every band of the tip expected at ``exp``."""
    d = (found[0] - exp[0], found[1] - exp[1])
    return all(abs(b.normal[0] * d[0] + b.normal[1] * d[1]) <= b.width for b in tip_bands)


def reach(tip_bands: list[Band]) -> float:
    """The farthest a tip within its two bands may stand (their parallelogram's far
    corner): the tolerance grade.json gives it.

    >>> round(reach([Band((0.0, 1.0), 1.0), Band((1.0, 0.0), 1.0)]), 6)
    1.414214
    """
    (a, b) = tip_bands
    det = a.normal[0] * b.normal[1] - a.normal[1] * b.normal[0]
    if abs(det) < 1e-12:
        return math.inf
    far = 0.0
    for sa in (1.0, -1.0):
        for sb in (1.0, -1.0):
            ra, rb = sa * a.width, sb * b.width
            x = (ra * b.normal[1] - rb * a.normal[1]) / det
            y = (a.normal[0] * rb - b.normal[0] * ra) / det
            far = max(far, math.hypot(x, y))
    return far
