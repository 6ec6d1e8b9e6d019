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
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum

from .errors import DegenerateInput, NoIntersection

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

EPS = 2.220446049250313e-16
# Rounding slack for tangency and parallelism: below this a crossing is taken as exact.
_TANGENT_SLACK = 64 * EPS


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


def _branch(pick: Branch | str) -> Branch:
    try:
        return Branch(pick)
    except ValueError:
        raise DegenerateInput(f"'{pick}' is not a valid branch, must be one of "
                              f"{', '.join(b.value for b in Branch)}") from None


class Branch(StrEnum):
    """Which of two intersections to take.

    ``LEFT``/``RIGHT`` of the directed line from the first circle's centre to the
    second's (two circles); ``FORWARD``/``BACKWARD`` along a line's direction (a line
    and a circle).
    """

    LEFT = "left"
    RIGHT = "right"
    FORWARD = "forward"
    BACKWARD = "backward"


def _cross(u: tuple[float, float, float],
           v: tuple[float, float, float]) -> tuple[float, float, float]:
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


def line_through(p: Point, q: Point) -> tuple[Line, float]:
    """Draw the line through ``p`` and ``q``, directed from ``p`` to ``q``.

    A point at infinity gives the line through the other point in that direction.

    Returns
    -------
    (Line, conditioning)
        Conditioning is ``|pq| / max(|pq|, |p|, |q|)`` for finite points.

    Raises
    ------
    DegenerateInput
        If the points coincide.

    Examples
    --------
    >>> line, cond = line_through(Point(0, 0), Point(0, 2))
    >>> line.direction, cond
    ((0.0, 1.0), 1.0)
    """
    if p.is_at_infinity and q.is_at_infinity:
        if p == q:
            raise DegenerateInput("one direction does not fix a line")
        return Line(0.0, 0.0, 1.0), 1.0
    if p.is_at_infinity or q.is_at_infinity:
        # A direction has no sense (its opposite is the same point), so the line
        # takes the direction's canonical sense.
        fin, inf = (q, p) if p.is_at_infinity else (p, q)
        sx, sy = inf.direction
        x, y = fin.xy
        return Line(-sy, sx, sy * x - sx * y), 1.0
    (px, py), (qx, qy) = p.xy, q.xy
    sep = math.hypot(qx - px, qy - py)
    if sep == 0.0:
        raise DegenerateInput(f"a line needs two distinct points, both are at ({px:g}, {py:g})")
    a, b, c = _cross((px, py, 1.0), (qx, qy, 1.0))
    cond = sep / max(sep, p.size(), q.size())
    return Line(a, b, c), cond


def perpendicular_through(p: Point, line: Line) -> tuple[Line, float]:
    """Draw the perpendicular to ``line`` through ``p``.

    The new line points along the old line's left normal, so it turns +90°.

    Examples
    --------
    >>> base, _ = line_through(Point(0, 0), Point(1, 0))
    >>> perp, _ = perpendicular_through(Point(2, 5), base)
    >>> perp.direction, round(perp.signed_distance(Point(2, 0)), 12)
    ((0.0, 1.0), 0.0)
    """
    if line.is_at_infinity:
        raise DegenerateInput("the line at infinity has no perpendicular")
    if p.is_at_infinity:
        raise DegenerateInput("a perpendicular needs a finite point to pass through")
    x, y = p.xy
    dx, dy = line.normal
    return Line(-dy, dx, dy * x - dx * y), 1.0


def parallel_through(p: Point, line: Line) -> tuple[Line, float]:
    """Draw the parallel to ``line`` through ``p``, with the same direction.

    Examples
    --------
    >>> base, _ = line_through(Point(0, 0), Point(1, 1))
    >>> par, _ = parallel_through(Point(0, 1), base)
    >>> round(par.signed_distance(Point(1, 2)), 12)
    0.0
    """
    if line.is_at_infinity:
        raise DegenerateInput("the line at infinity has no parallels")
    if p.is_at_infinity:
        if abs(p.x * line.a + p.y * line.b) <= _TANGENT_SLACK:
            raise DegenerateInput("every parallel passes through the line's own direction")
        return Line(0.0, 0.0, 1.0), 1.0
    x, y = p.xy
    return Line(line.a, line.b, -(line.a * x + line.b * y)), 1.0


def swing_arc(centre: Point, radius: float) -> tuple[Circle, float]:
    """Swing an arc of ``radius`` about ``centre``.

    Examples
    --------
    >>> swing_arc(Point(1, 1), 2.0)[0].radius
    2.0
    """
    return Circle(centre, radius), 1.0


def circle_through(centre: Point, p: Point) -> tuple[Circle, float]:
    """Draw the circle about ``centre`` through ``p``.

    Examples
    --------
    >>> circle_through(Point(0, 0), Point(3, 4))[0].radius
    5.0
    """
    r = distance(centre, p)
    if r == 0.0:
        raise DegenerateInput("a circle through its own centre has no radius")
    return Circle(centre, r), r / max(r, centre.size(), p.size())


def intersect_lines(g: Line, h: Line) -> tuple[Point, float]:
    """Intersect two lines; parallel lines meet at infinity.

    Returns
    -------
    (Point, conditioning)
        Conditioning is the sine of the angle between the lines. For parallel
        lines, whose meet is their direction at infinity, it is how far apart they
        are relative to their distance from the origin.

    Raises
    ------
    DegenerateInput
        If the lines coincide.

    Examples
    --------
    >>> g, _ = line_through(Point(0, 0), Point(1, 0))
    >>> h, _ = line_through(Point(3, -1), Point(3, 1))
    >>> p, cond = intersect_lines(g, h)
    >>> p.xy, cond
    ((3.0, 0.0), 1.0)
    """
    x, y, w = _cross((g.a, g.b, g.c), (h.a, h.b, h.c))
    sine = min(1.0, abs(w)) if not (g.is_at_infinity or h.is_at_infinity) else 1.0
    if max(abs(x), abs(y), abs(w)) <= _TANGENT_SLACK * max(1.0, abs(g.c), abs(h.c)):
        raise DegenerateInput("the two lines coincide, so they have no single intersection")
    # With unit normals |w| is the sine of the angle between the lines, so parallelism
    # is judged by angle alone, however far from the origin the lines run.
    if abs(w) <= _TANGENT_SLACK and not (g.is_at_infinity or h.is_at_infinity):
        # Parallel lines meet in their common direction, known as well as the lines are
        # apart: the conditioning is their separation over their distance from the origin.
        sep = math.hypot(x, y)
        return Point(x, y, 0.0), sep / max(sep, abs(g.c), abs(h.c))
    return Point(x, y, w), sine


def intersect_line_circle(line: Line, circle: Circle, pick: Branch | str) -> tuple[Point, float]:
    """Cut ``line`` with ``circle`` and take the ``forward`` or ``backward`` point.

    ``forward`` is the intersection further along the line's direction.

    Returns
    -------
    (Point, conditioning)
        Conditioning is the sine of the angle between line and circle where they
        cross (0 at tangency).

    Raises
    ------
    NoIntersection
        If the line misses the circle; ``margin`` is how far it passes outside.

    Examples
    --------
    >>> line, _ = line_through(Point(-10, 0), Point(10, 0))
    >>> p, cond = intersect_line_circle(line, Circle(Point(0, 3), 5.0), "forward")
    >>> p.xy, cond
    ((4.0, 0.0), 0.8)
    """
    pick = _branch(pick)
    if pick not in (Branch.FORWARD, Branch.BACKWARD):
        raise DegenerateInput(f"a line and a circle take 'forward' or 'backward', not '{pick}'")
    if line.is_at_infinity:
        raise NoIntersection("a circle never reaches the line at infinity", math.inf)
    cx, cy = circle.centre.xy
    r = circle.radius
    d = line.a * cx + line.b * cy + line.c
    fx, fy = cx - d * line.a, cy - d * line.b
    h2 = (r - d) * (r + d)
    if h2 < 0.0:
        if abs(d) - r > _TANGENT_SLACK * max(r, circle.centre.size()):
            raise NoIntersection(
                f"the line passes {abs(d) - r:.6g} outside the circle of radius {r:.6g}",
                abs(d) - r)
        h2 = 0.0
    h = math.sqrt(h2)
    tx, ty = line.direction
    s = h if pick is Branch.FORWARD else -h
    return Point(fx + s * tx, fy + s * ty), h / r


def intersect_circles(c1: Circle, c2: Circle, pick: Branch | str) -> tuple[Point, float]:
    """Cut two arcs and take the intersection ``left`` or ``right`` of centre 1 → centre 2.

    Returns
    -------
    (Point, conditioning)
        Conditioning is the sine of the angle between the two radii at the
        intersection (0 when the circles touch).

    Raises
    ------
    NoIntersection
        If the circles do not meet; ``margin`` is the gap (or overlap) that
        keeps them apart.
    DegenerateInput
        If the centres coincide.

    Examples
    --------
    >>> p, cond = intersect_circles(Circle(Point(0, 0), 5.0), Circle(Point(6, 0), 5.0), "left")
    >>> p.xy, round(cond, 12)
    ((3.0, 4.0), 0.96)
    """
    pick = _branch(pick)
    if pick not in (Branch.LEFT, Branch.RIGHT):
        raise DegenerateInput(f"two circles take 'left' or 'right', not '{pick}'")
    (x1, y1), (x2, y2) = c1.centre.xy, c2.centre.xy
    r1, r2 = c1.radius, c2.radius
    dx, dy = x2 - x1, y2 - y1
    d = math.hypot(dx, dy)
    if d == 0.0:
        raise DegenerateInput("concentric circles have no single intersection")
    scale = max(r1, r2, d, c1.centre.size(), c2.centre.size())
    dr = r1 - r2
    outside = d - (r1 + r2)
    inside = abs(dr) - d
    if outside > 0.0 or inside > 0.0:
        margin = max(outside, inside)
        if margin > _TANGENT_SLACK * scale:
            where = "apart" if outside > 0.0 else "inside one another"
            raise NoIntersection(
                f"the circles (radii {r1:.6g} and {r2:.6g}, centres {d:.6g} apart) miss "
                f"by {margin:.6g}: they lie {where}", margin)
    # Product form of the half-chord: stable near tangency.
    # Each small factor is divided by 2d on its own, so d² never underflows.
    # Written with r1 − r2 kept whole, so nearly concentric circles lose nothing.
    h2 = max(0.0, (r1 + r2 - d) * (r1 + r2 + d)
             * ((d - dr) / (2.0 * d)) * ((d + dr) / (2.0 * d)))
    a = (d + dr * (r1 + r2) / d) / 2.0
    ux, uy = dx / d, dy / d
    h = math.sqrt(h2)
    s = h if pick is Branch.LEFT else -h
    px, py = x1 + a * ux - s * uy, y1 + a * uy + s * ux
    return Point(px, py), min(1.0, d * h / (r1 * r2))


def rotate_about(p: Point, centre: Point, angle: float) -> tuple[Point, float]:
    """Rotate ``p`` about ``centre`` by ``angle`` (radians, counter-clockwise).

    Examples
    --------
    >>> q, _ = rotate_about(Point(1, 0), Point(0, 0), math.pi / 2)
    >>> tuple(round(v, 12) for v in q.xy)
    (0.0, 1.0)
    """
    if not math.isfinite(angle):
        raise DegenerateInput(f"a rotation needs a finite angle, got {angle}")
    c, s = math.cos(angle), math.sin(angle)
    if p.is_at_infinity:
        dx, dy = p.direction
        return Point(c * dx - s * dy, s * dx + c * dy, 0.0), 1.0
    (px, py), (ox, oy) = p.xy, centre.xy
    vx, vy = px - ox, py - oy
    return Point(ox + c * vx - s * vy, oy + s * vx + c * vy), 1.0


def project_onto(p: Point, line: Line) -> tuple[Point, float]:
    """Drop the perpendicular from ``p`` to ``line`` and return its foot.

    Examples
    --------
    >>> base, _ = line_through(Point(0, 0), Point(1, 0))
    >>> project_onto(Point(3, 4), base)[0].xy
    (3.0, 0.0)
    """
    if line.is_at_infinity:
        raise DegenerateInput("cannot project onto the line at infinity")
    d = line.signed_distance(p)
    x, y = p.xy
    return Point(x - d * line.a, y - d * line.b), 1.0


def lay_off(start: Point, toward: Point | Line, length: float) -> tuple[Point, float]:
    """Lay off ``length`` from ``start`` towards ``toward``.

    ``toward`` is a point, a direction (a point at infinity, which has no sense) or
    an oriented line, whose direction gives the sense. A negative length lays it
    off the other way.

    Returns
    -------
    (Point, conditioning)
        Conditioning is the separation of ``start`` and ``toward`` relative to
        their size (1 when ``toward`` is a direction).

    Examples
    --------
    >>> lay_off(Point(0, 0), Point(3, 4), 10.0)[0].xy
    (6.0, 8.0)
    """
    x, y = start.xy
    if isinstance(toward, Line):
        if toward.is_at_infinity:
            raise DegenerateInput("the line at infinity has no direction to lay off along")
        ux, uy = toward.direction
        cond = 1.0
    elif toward.is_at_infinity:
        ux, uy = toward.direction
        cond = 1.0
    else:
        tx, ty = toward.xy
        n = math.hypot(tx - x, ty - y)
        if n == 0.0:
            raise DegenerateInput("a direction needs two distinct points")
        ux, uy = (tx - x) / n, (ty - y) / n
        cond = n / max(n, start.size(), toward.size())
    return Point(x + length * ux, y + length * uy), cond


def midpoint(p: Point, q: Point) -> tuple[Point, float]:
    """Bisect the segment ``pq``.

    Examples
    --------
    >>> midpoint(Point(0, 0), Point(4, 2))[0].xy
    (2.0, 1.0)
    """
    (px, py), (qx, qy) = p.xy, q.xy
    return Point((px + qx) / 2.0, (py + qy) / 2.0), 1.0


def mark(p: Point) -> tuple[Point, float]:
    """Name a point already drawn: a pin is the instant centre of the links it joins.

    Examples
    --------
    >>> mark(Point(1, 2))[0].xy
    (1.0, 2.0)
    """
    return p, 1.0


def normal_direction(line: Line) -> tuple[Point, float]:
    """The direction perpendicular to ``line``, as a point at infinity.

    A block on a straight guide has its instant centre here.

    Examples
    --------
    >>> base, _ = line_through(Point(0, 0), Point(1, 0))
    >>> p, _ = normal_direction(base)
    >>> p.is_at_infinity, p.direction
    (True, (0.0, 1.0))
    """
    if line.is_at_infinity:
        raise DegenerateInput("the line at infinity has no normal direction")
    a, b = line.normal
    return Point.at_infinity(a, b), 1.0


def join(p: Point, q: Point) -> tuple[Segment, float]:
    """Join ``p`` to ``q``: the segment (a vector, when drawn with an arrow) from p to q.

    Examples
    --------
    >>> join(Point(0, 0), Point(3, 4))[0].length
    5.0
    """
    if p.is_at_infinity or q.is_at_infinity:
        raise DegenerateInput("a segment needs two finite end points")
    return Segment(p, q), 1.0


def transfer(p: Point, a: Point, b: Point) -> tuple[Point, float]:
    """Carry the segment ``a → b`` with dividers to start at ``p``: return ``p + (b − a)``.

    This is how a velocity component is laid off again at another point of the
    same link.

    Examples
    --------
    >>> transfer(Point(10, 0), Point(0, 0), Point(3, 4))[0].xy
    (13.0, 4.0)
    """
    if p.is_at_infinity or a.is_at_infinity or b.is_at_infinity:
        raise DegenerateInput("dividers carry a segment between finite points only")
    (px, py), (ax, ay), (bx, by) = p.xy, a.xy, b.xy
    return Point(px + bx - ax, py + by - ay), 1.0
