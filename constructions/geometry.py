"""Homogeneous points, lines and circles, and the drafting verbs that act on them.

Points are projective: ``Point(x, y, w)`` with ``w = 0`` is a point at infinity (a
direction), so a slider's instant centre or the meet of two parallel Kennedy lines
needs no special case. Lines are oriented: ``Line(a, b, c)`` is ``a x + b y + c = 0``
with unit normal ``(a, b)`` and direction ``(b, -a)``; "left" of a line is the side
its normal points to.

Every verb returns ``(result, conditioning)``. The conditioning is a number in
``[0, 1]``: 1 is a well-posed act, 0 is singular. It is the sine of the angle at
which two carriers cross, or the ratio of a separation to the size of the
coordinates it was taken from. A result's error is about ``eps / conditioning``
relative to the size of the figure.

Angles are counter-clockwise positive from +x, in radians.

The objects are in :mod:`~tarsim.constructions.homogeneous`, the verbs that draw from
them in :mod:`~tarsim.constructions.drafting_verbs` and the cuts of two carriers in
:mod:`~tarsim.constructions.intersections`; this module gathers them into the one
namespace the methods draw with (``g.Point``, ``g.line_through``).
"""

from __future__ import annotations

# The kernel's one namespace: every name below is read as ``geometry.<name>``.
from .drafting_verbs import (circle_through, join, lay_off, line_through, mark, midpoint,
                             normal_direction, parallel_through, perpendicular_through,
                             project_onto, rotate_about, swing_arc, transfer)
from .homogeneous import Circle, Line, Point, Segment, distance, side_of
from .intersections import Branch, intersect_circles, intersect_line_circle, intersect_lines

__all__ = [
    "Point",
    "Line",
    "Circle",
    "Branch",
    "line_through",
    "perpendicular_through",
    "parallel_through",
    "swing_arc",
    "circle_through",
    "intersect_lines",
    "intersect_line_circle",
    "intersect_circles",
    "rotate_about",
    "project_onto",
    "lay_off",
    "midpoint",
    "mark",
    "normal_direction",
    "join",
    "transfer",
    "Segment",
    "distance",
    "side_of",
]
