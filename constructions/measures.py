"""Measuring acts: the scale rule across two points, the protractor at a vertex.

A construction ends in a reading: the stroke is the distance B″B′ taken off the
drawing, the time ratio comes from the angles the crank turns between its limit
positions. These verbs record those readings as steps, so a figure can draw them
as a drafter would (a dimension line, an angle arc with its degrees) and the
narration can number them like any other act.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import DegenerateInput
from .geometry import Point

__all__ = ["Dimension", "Angle", "measure", "measure_angle"]


@dataclass(frozen=True, slots=True)
class Dimension:
    """The distance from ``start`` to ``end``, read with the scale rule."""

    start: Point
    end: Point

    @property
    def length(self) -> float:
        """The distance read (m)."""
        return math.dist(self.start.xy, self.end.xy)


@dataclass(frozen=True, slots=True)
class Angle:
    """The angle at ``vertex`` from the direction ``start`` (rad) turning ``sweep`` rad,
    counter-clockwise positive, as a protractor reads it. ``reach`` is the length of its
    first arm, so a figure can draw the angle's arc through the points it was read at."""

    vertex: Point
    start: float
    sweep: float
    reach: float

    @property
    def degrees(self) -> float:
        """The angle read, in degrees, without its sense."""
        return math.degrees(abs(self.sweep))


def measure(p: Point, q: Point) -> tuple[Dimension, float]:
    """Read the distance ``pq`` off the drawing.

    Examples
    --------
    >>> measure(Point(0, 0), Point(3, 4))[0].length
    5.0
    """
    if p.is_at_infinity or q.is_at_infinity:
        raise DegenerateInput("a distance is measured between two finite points")
    return Dimension(p, q), 1.0


def measure_angle(vertex: Point, p: Point, q: Point, turn: float) -> tuple[Angle, float]:
    """Read the angle at ``vertex`` from ray ``vertex→p`` to ray ``vertex→q``, turning
    counter-clockwise for ``turn`` > 0 and clockwise for ``turn`` < 0: in (0, 2π).

    Examples
    --------
    >>> a, _ = measure_angle(Point(0, 0), Point(1, 0), Point(0, 1), turn=-1)
    >>> round(a.degrees, 9), a.sweep < 0
    (270.0, True)
    """
    if vertex.is_at_infinity or p.is_at_infinity or q.is_at_infinity:
        raise DegenerateInput("an angle is measured between finite points")
    (vx, vy), (px, py), (qx, qy) = vertex.xy, p.xy, q.xy
    if (px, py) == (vx, vy) or (qx, qy) == (vx, vy):
        raise DegenerateInput("an angle's arms need points apart from its vertex")
    start = math.atan2(py - vy, px - vx)
    ccw = (math.atan2(qy - vy, qx - vx) - start) % (2 * math.pi)
    sweep = ccw if turn > 0 else -((2 * math.pi - ccw) % (2 * math.pi))
    return Angle(vertex, start, sweep, math.hypot(px - vx, py - vy)), 1.0
