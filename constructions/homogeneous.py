"""Homogeneous points, lines and circles: what every drafting verb takes and gives.

Points are projective: ``Point(x, y, w)`` with ``w = 0`` is a point at infinity (a
direction), so a slider's instant centre or the meet of two parallel Kennedy lines
needs no special case. Lines are oriented: ``Line(a, b, c)`` is ``a x + b y + c = 0``
with unit normal ``(a, b)`` and direction ``(b, -a)``; "left" of a line is the side
its normal points to. A ``Segment`` is a drawn vector. The measures ``distance`` and
``side_of`` are here too, and the rounding slack the verbs judge tangency by.

Angles are counter-clockwise positive from +x, in radians.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import DegenerateInput

__all__ = ["Point", "Line", "Circle", "Segment", "distance", "side_of", "cross", "EPS",
           "TANGENT_SLACK"]

EPS = 2.220446049250313e-16
TANGENT_SLACK = 64 * EPS
"""Rounding slack for tangency and parallelism: below this a crossing is taken as exact."""


@dataclass(frozen=True, slots=True)
class Point:
    """A projective point; finite points are stored with ``w = 1``.

    Examples
    --------
    >>> Point(6.0, 8.0, 2.0) == Point(3.0, 4.0)
    True
    >>> Point(0.0, 2.0, 0.0).is_at_infinity
    True
    """

    x: float
    y: float
    w: float = 1.0

    def __post_init__(self) -> None:
        x, y, w = float(self.x), float(self.y), float(self.w)
        if not all(math.isfinite(v) for v in (x, y, w)):
            raise DegenerateInput(f"a point needs finite coordinates, got ({x}, {y}, {w})")
        if w != 0.0:
            x, y, w = x / w + 0.0, y / w + 0.0, 1.0
            if not (math.isfinite(x) and math.isfinite(y)):
                raise DegenerateInput("a point lies too far away to represent; "
                                      "treat it as a point at infinity")
        else:
            n = math.hypot(x, y)
            if n == 0.0:
                raise DegenerateInput("(0, 0, 0) is not a point")
            x, y = x / n, y / n
            # A direction and its opposite are the same point at infinity.
            if x < 0 or (x == 0 and y < 0):
                x, y = -x, -y
            x, y = x + 0.0, y + 0.0
        object.__setattr__(self, "x", x)
        object.__setattr__(self, "y", y)
        object.__setattr__(self, "w", w)

    @classmethod
    def at_infinity(cls, dx: float, dy: float) -> Point:
        """Return the point at infinity in direction ``(dx, dy)``."""
        return cls(dx, dy, 0.0)

    @property
    def is_at_infinity(self) -> bool:
        """True for a direction (``w = 0``)."""
        return self.w == 0.0

    @property
    def xy(self) -> tuple[float, float]:
        """Cartesian coordinates; a point at infinity has none."""
        if self.is_at_infinity:
            raise DegenerateInput("a point at infinity has no Cartesian coordinates")
        return (self.x, self.y)

    @property
    def direction(self) -> tuple[float, float]:
        """Unit direction of a point at infinity."""
        if not self.is_at_infinity:
            raise DegenerateInput("a finite point has no direction at infinity")
        return (self.x, self.y)

    def size(self) -> float:
        """Distance from the origin (1 for a point at infinity), the scale for rounding."""
        return 1.0 if self.is_at_infinity else math.hypot(self.x, self.y)


@dataclass(frozen=True, slots=True)
class Line:
    """An oriented line ``a x + b y + c = 0`` with ``a² + b² = 1``.

    Its direction is ``(b, -a)``. ``Line(0, 0, 1)`` is the line at infinity.

    Examples
    --------
    >>> from tarsim.constructions.geometry import line_through
    >>> line, _ = line_through(Point(0, 0), Point(3, 4))
    >>> tuple(round(v, 12) for v in line.direction)
    (0.6, 0.8)
    """

    a: float
    b: float
    c: float

    def __post_init__(self) -> None:
        a, b, c = float(self.a), float(self.b), float(self.c)
        if not all(math.isfinite(v) for v in (a, b, c)):
            raise DegenerateInput("a line needs finite coefficients")
        big = max(abs(a), abs(b), abs(c))
        if big > 0.0:  # rescale first so a² + b² can neither overflow nor underflow
            a, b, c = a / big, b / big, c / big
        n = math.hypot(a, b)
        if n == 0.0:
            if c == 0.0:
                raise DegenerateInput("(0, 0, 0) is not a line")
            a, b, c = 0.0, 0.0, 1.0
        else:
            a, b, c = a / n, b / n, c / n
            if not math.isfinite(c):
                raise DegenerateInput("the line lies too far away to represent; "
                                      "treat it as the line at infinity")
        object.__setattr__(self, "a", a + 0.0)
        object.__setattr__(self, "b", b + 0.0)
        object.__setattr__(self, "c", c + 0.0)

    @property
    def is_at_infinity(self) -> bool:
        """True for the line at infinity, which joins two directions."""
        return self.a == 0.0 and self.b == 0.0

    @property
    def direction(self) -> tuple[float, float]:
        """Unit direction along the line."""
        return (self.b, -self.a)

    @property
    def normal(self) -> tuple[float, float]:
        """Unit normal, pointing to the line's left."""
        return (self.a, self.b)

    def signed_distance(self, p: Point) -> float:
        """Signed distance of a finite point; positive on the left."""
        x, y = p.xy
        return self.a * x + self.b * y + self.c

    def anchor(self) -> tuple[float, float]:
        """The foot of the perpendicular from the origin."""
        return (-self.a * self.c, -self.b * self.c)


@dataclass(frozen=True, slots=True)
class Circle:
    """A circle with a finite centre and a positive radius.

    Examples
    --------
    >>> Circle(Point(0, 0), 5.0).radius
    5.0
    """

    centre: Point
    radius: float

    def __post_init__(self) -> None:
        if self.centre.is_at_infinity:
            raise DegenerateInput("a circle needs a finite centre")
        r = float(self.radius)
        if not (math.isfinite(r) and r > 0.0):
            raise DegenerateInput(f"a circle needs a positive radius, got {r}")
        object.__setattr__(self, "radius", r)


@dataclass(frozen=True, slots=True)
class Segment:
    """A drawn segment from ``start`` to ``end``: a vector when its sense matters.

    A velocity laid off at a point is the segment from the point to the tip, and
    the figure draws it as an arrow.
    """

    start: Point
    end: Point

    @property
    def vector(self) -> tuple[float, float]:
        """``end − start`` (both finite)."""
        (x0, y0), (x1, y1) = self.start.xy, self.end.xy
        return x1 - x0, y1 - y0

    @property
    def length(self) -> float:
        """The segment's length."""
        return math.hypot(*self.vector)


def cross(u: tuple[float, float, float],
          v: tuple[float, float, float]) -> tuple[float, float, float]:
    """The cross product of two homogeneous triples: the line through two points, or the
    point where two lines meet."""
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def distance(p: Point, q: Point) -> float:
    """Return the distance between two finite points.

    Examples
    --------
    >>> distance(Point(0, 0), Point(3, 4))
    5.0
    """
    (px, py), (qx, qy) = p.xy, q.xy
    return math.hypot(qx - px, qy - py)


def side_of(p: Point, a: Point, b: Point) -> float:
    """Return the cross product sign test: > 0 when ``p`` is left of ``a → b``.

    Examples
    --------
    >>> side_of(Point(0, 1), Point(0, 0), Point(1, 0)) > 0
    True
    """
    (px, py), (ax, ay), (bx, by) = p.xy, a.xy, b.xy
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax)

