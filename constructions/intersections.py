"""Cutting two carriers: two lines, a line and an arc, or two arcs.

Two lines meet in one point (at infinity when parallel). A line and a circle, or two
circles, cross in two, and the ``Branch`` says which to take: an explicit choice,
never "the first". Each verb returns ``(point, conditioning)``, the conditioning the
sine of the angle at which the carriers cross (see :mod:`~tarsim.constructions.geometry`).
"""

from __future__ import annotations

import math
from enum import StrEnum

from .errors import DegenerateInput, NoIntersection
from .homogeneous import TANGENT_SLACK, Circle, Line, Point, cross

__all__ = ["Branch", "intersect_lines", "intersect_line_circle", "intersect_circles"]


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
    >>> from tarsim.constructions.geometry import line_through
    >>> g, _ = line_through(Point(0, 0), Point(1, 0))
    >>> h, _ = line_through(Point(3, -1), Point(3, 1))
    >>> p, cond = intersect_lines(g, h)
    >>> p.xy, cond
    ((3.0, 0.0), 1.0)
    """
    x, y, w = cross((g.a, g.b, g.c), (h.a, h.b, h.c))
    sine = min(1.0, abs(w)) if not (g.is_at_infinity or h.is_at_infinity) else 1.0
    if max(abs(x), abs(y), abs(w)) <= TANGENT_SLACK * max(1.0, abs(g.c), abs(h.c)):
        raise DegenerateInput("the two lines coincide, so they have no single intersection")
    # With unit normals |w| is the sine of the angle between the lines, so parallelism
    # is judged by angle alone, however far from the origin the lines run.
    if abs(w) <= TANGENT_SLACK and not (g.is_at_infinity or h.is_at_infinity):
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
    >>> from tarsim.constructions.geometry import line_through
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
        if abs(d) - r > TANGENT_SLACK * max(r, circle.centre.size()):
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
        if margin > TANGENT_SLACK * scale:
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

