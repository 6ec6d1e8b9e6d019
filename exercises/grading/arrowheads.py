"""Which corner of a small closed polygon an arrowhead points with: the one a shaft runs
along to, or, where no shaft longer than the head runs into it, the one its shape alone
gives (a triangle's one sharp corner, a dart's corner opposite its notch).

:mod:`.marks` asks these of each closed polygon no larger than an arrowhead; sizes are in
paper mm.
"""

from __future__ import annotations

import math

__all__ = ["JOIN", "apex", "sharpest", "barbed", "outward", "within", "turn", "extent"]

Vec = tuple[float, float]

JOIN = 0.25
"""Ends within this (mm, half a 0.5 mm pen's line) meet."""


def turn(a: Vec, b: Vec, c: Vec) -> float:
    """How far a path a → b → c turns at b (radians, either way)."""
    u, v = (b[0] - a[0], b[1] - a[1]), (c[0] - b[0], c[1] - b[1])
    return math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1])


def extent(points: list[Vec]) -> float:
    """How far apart the two of ``points`` farthest from one another stand."""
    return max(math.dist(p, q) for p in points for q in points)


def within(p: Vec, poly: list[Vec]) -> bool:
    """Whether ``p`` lies inside the polygon ``poly`` or within :data:`JOIN` of its edge."""
    inside = False
    for a, b in zip(poly, poly[1:] + poly[:1]):
        if (a[1] > p[1]) != (b[1] > p[1]) and \
                p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]):
            inside = not inside
        d = (b[0] - a[0], b[1] - a[1])
        t = max(0.0, min(1.0, ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1])
                         / max(d[0] ** 2 + d[1] ** 2, 1e-300)))
        if math.dist(p, (a[0] + t * d[0], a[1] + t * d[1])) <= JOIN:
            return True
    return inside


def apex(poly: list[Vec], far: Vec, near: Vec, size: float) -> Vec | None:
    """The corner of ``poly`` a shaft from ``far`` to ``near`` points to: ahead of the
    other corners along it by a tenth of the head at least (an outlined V's inner corner
    stands a line's width behind), on its line, and no nearer the shaft's start than its
    end is; None if no corner is. A stroke from an outward corner (the next arrow leaving
    this one's apex) points to that corner or to none: only a notch, turned inward, is a
    shaft's end behind the apex."""
    length = math.dist(far, near)
    if length == 0.0:
        return None
    u = ((near[0] - far[0]) / length, (near[1] - far[1]) / length)
    ahead = sorted(((p[0] - far[0]) * u[0] + (p[1] - far[1]) * u[1], p) for p in poly)
    (first, apex), (second, _) = ahead[-1], ahead[-2]
    aside = abs((apex[0] - far[0]) * u[1] - (apex[1] - far[1]) * u[0])
    if first - second < 0.1 * size or aside > max(JOIN, 0.15 * size) or \
            first < length - JOIN or ahead[0][0] <= 0.0:
        return None
    if math.dist(near, apex) > JOIN and \
            any(math.dist(near, poly[k]) <= JOIN for k in outward(poly)):
        return None
    return apex


def outward(poly: list[Vec]) -> list[int]:
    """The corners of the polygon ``poly`` that turn outward (all but a notch's), by index."""
    turns = [turn(poly[k - 1], poly[k], poly[(k + 1) % len(poly)]) for k in range(len(poly))]
    sense = 1.0 if sum(turns) > 0.0 else -1.0
    return [k for k, t in enumerate(turns) if t * sense > 0.0]


def sharpest(poly: list[Vec]) -> Vec | None:
    """A triangle's one clearly sharpest corner (60° at most, 15° sharper than the next),
    an arrowhead's apex told by its shape alone; None if it has none."""
    angles = sorted((abs(math.pi - abs(turn(poly[k - 1], poly[k], poly[(k + 1) % 3]))), k)
                    for k in range(3))
    if angles[0][0] <= math.radians(60.0) and angles[1][0] - angles[0][0] >= math.radians(15.0):
        return poly[angles[0][1]]
    return None


def barbed(poly: list[Vec]) -> Vec | None:
    """The apex of a barbed arrowhead (a dart: apex, wing, notch, wing), told by its shape
    alone, as an arrow too short for a shaft longer than its head is: the corner opposite
    its one reflex corner (the notch), square or sharper, the notch on the line from it
    to the wings' middle and between the two; None if ``poly`` is no such dart.

    Examples
    --------
    tarsim's own head, 2.8 mm long and 1.4 wide, its notch at three quarters; a flag whose
    reflex corner stands off that line:

    >>> barbed([(0.0, 0.0), (2.8, 0.7), (2.1, 0.0), (2.8, -0.7)])
    (0.0, 0.0)
    >>> barbed([(0.0, 0.0), (4.0, 1.0), (2.8, 1.3), (0.5, 3.0)]) is None
    True
    """
    if len(poly) != 4:
        return None
    turned = outward(poly)
    if len(turned) != 3:
        return None
    notch = next(k for k in range(4) if k not in turned)
    apex, wings = poly[(notch + 2) % 4], (poly[notch - 1], poly[(notch + 1) % 4])
    if math.pi - abs(turn(poly[(notch + 1) % 4], apex, poly[(notch + 3) % 4])) > \
            math.radians(90.0):
        return None
    base = ((wings[0][0] + wings[1][0]) / 2.0, (wings[0][1] + wings[1][1]) / 2.0)
    axis = math.dist(apex, base)
    if axis == 0.0:
        return None
    u = ((base[0] - apex[0]) / axis, (base[1] - apex[1]) / axis)
    p = (poly[notch][0] - apex[0], poly[notch][1] - apex[1])
    along, aside = p[0] * u[0] + p[1] * u[1], abs(p[0] * u[1] - p[1] * u[0])
    return apex if 0.0 < along < axis and aside <= 0.15 * extent(poly) else None
