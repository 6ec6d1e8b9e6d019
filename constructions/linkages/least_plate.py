"""The slowest point of a plate: a link whose points do not lie on one line, drawn as the
plate their outline (convex hull) bounds.

Every point of link k moves at |ω_k| times its distance from the centre I_1k it turns
about, so the slowest point of the plate is its point nearest I_1k: I_1k itself when it
lies within the plate (that point of the plate is at rest), else the foot of the
perpendicular from I_1k onto the side that passes nearest it, or the corner where two
sides meet when neither foot falls on its side. Its distance is given from the plate's
named point nearest it, as a book asks "how far from B".
"""

from __future__ import annotations

import math

__all__ = ["outline", "nearest_on_plate"]

Pt = tuple[float, float]


def _cross(o: Pt, a: Pt, b: Pt) -> float:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def outline(points: dict[str, Pt]) -> list[str]:
    """The names of the plate's corners, counter-clockwise round its convex hull (Andrew's
    monotone chain); a point on a side between two corners is no corner."""
    names = sorted(points, key=lambda n: points[n])
    if len(names) < 3:
        return names
    lower: list[str] = []
    upper: list[str] = []
    for chain, order in ((lower, names), (upper, names[::-1])):
        for n in order:
            while len(chain) >= 2 and _cross(points[chain[-2]], points[chain[-1]],
                                             points[n]) <= 0.0:
                chain.pop()
            chain.append(n)
    return lower[:-1] + upper[:-1]


def nearest_on_plate(points: dict[str, Pt], centre: Pt) -> tuple[str, tuple[str, str] | None]:
    """Where the plate's point nearest ``centre`` lies: ("inside", None) when the centre is
    within the outline; ("side", (a, b)) on the side ab, at the foot of the perpendicular;
    ("corner", (a, a)) at the corner a."""
    ring = outline(points)
    if len(ring) >= 3 and all(_cross(points[a], points[b], centre) >= 0.0
                              for a, b in zip(ring, ring[1:] + ring[:1])):
        return "inside", None
    best = (math.inf, "corner", (ring[0], ring[0]))
    for a, b in zip(ring, ring[1:] + ring[:1]):
        (ax, ay), (bx, by) = points[a], points[b]
        dx, dy = bx - ax, by - ay
        t = ((centre[0] - ax) * dx + (centre[1] - ay) * dy) / (dx * dx + dy * dy)
        if 0.0 < t < 1.0:
            where = ("side", (a, b))
            d = abs(_cross(points[a], points[b], centre)) / math.hypot(dx, dy)
        else:
            c = a if t <= 0.0 else b
            where, d = ("corner", (c, c)), math.dist(points[c], centre)
        if d < best[0]:
            best = (d, *where)
    return best[1], best[2]
