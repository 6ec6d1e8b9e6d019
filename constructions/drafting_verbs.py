"""The drafting verbs that draw from what is given: lines, arcs, and the acts on points.

Lines through points, perpendiculars and parallels; arcs swung about a centre; a point
rotated, projected, laid off, bisected, carried with dividers, or marked as it stands.
Each is one hand act and returns ``(result, conditioning)``
(see :mod:`~tarsim.constructions.geometry`). The cuts of two carriers are in
:mod:`~tarsim.constructions.intersections`.
"""

from __future__ import annotations

import math

from .errors import DegenerateInput
from .homogeneous import TANGENT_SLACK, Circle, Line, Point, Segment, cross, distance

__all__ = ["line_through", "perpendicular_through", "parallel_through", "swing_arc",
           "circle_through", "rotate_about", "project_onto", "lay_off", "midpoint", "mark",
           "normal_direction", "join", "transfer"]


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
    a, b, c = cross((px, py, 1.0), (qx, qy, 1.0))
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
        if abs(p.x * line.a + p.y * line.b) <= TANGENT_SLACK:
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
