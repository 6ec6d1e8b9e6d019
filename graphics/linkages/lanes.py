"""Lanes: arrows that would lie over one another, or over a link, drawn side by side.

A textbook draws a short vector that runs along a longer one (the Coriolis component
along A_B₄, two components of a polygon collapsed onto one line) or along a link (a
component of a velocity laid off along the rod it belongs to) a little to one side, in a
lane of its own, true in length and direction, so both can be read. :func:`lanes` gives
each arrow its lane; the drawing moves it :data:`LANE` mm a lane, square to itself.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

__all__ = ["lanes", "moved", "runs_along", "LANE", "ALONG"]

Segment = tuple[tuple[float, float], tuple[float, float]]

LANE = 3.0
"""Paper (mm) between arrows drawn side by side: an arrowhead is 1.6 mm wide at most, so
two heads in neighbouring lanes stand apart with a millimetre of white between them."""

ALONG = 1.5
"""Paper (mm): a shorter arrow whose two ends both lie within this of a longer arrow's (or a
link's) line, over more than half a millimetre of it, lies along it: drawn there, its shaft
is lost in the other's and its head in the other's head."""

_TOUCH = 0.05       # mm: ends closer than this are one point
_SAME = 0.5         # mm: arrows from tails this close, the same way, are drawn one over another
_OVERLAP = 0.5      # mm: arrows sharing less than this of their carrier only meet end to end
_CROSS = 0.8        # mm: an arrow moved aside no nearer than this to another arrow's shaft


def runs_along(a, b, p, q, *, within: float = ALONG) -> tuple[float, float] | None:
    """Where the segment a–b lies along segment p–q: the stretch ``(lo, hi)`` of p–q's
    carrier (mm from p) that both cover, when both ends of a–b lie within ``within`` mm of
    p–q's line; else None.

    >>> runs_along((10, 0.3), (20, 0.2), (0, 0), (30, 0))
    (10.0, 20.0)
    >>> runs_along((10, 2.0), (20, 0.2), (0, 0), (30, 0)) is None
    True
    """
    n = math.dist(p, q)
    if n < _TOUCH or math.dist(a, b) < _TOUCH:
        return None
    u = ((q[0] - p[0]) / n, (q[1] - p[1]) / n)
    if any(abs((x[0] - p[0]) * u[1] - (x[1] - p[1]) * u[0]) > within for x in (a, b)):
        return None
    s, t = sorted((x[0] - p[0]) * u[0] + (x[1] - p[1]) * u[1] for x in (a, b))
    return max(s, 0.0), min(t, n)


def _clash(one: Segment, other: Segment, nested: bool = True) -> bool:
    """Whether two arrows ``(tail, tip)`` drawn where they are would hide one another.

    The shorter is measured against the longer's line. They clash where they share more
    than :data:`_OVERLAP` of it, unless (``nested``) one lies within the other from a
    common tail and the same way (V_A₄ within V_B₄, both from o_v: a textbook's own
    drawing), or they are one and the same arrow; and where they meet head to head,
    their heads stacked.
    """
    if math.dist(*one) < _TOUCH or math.dist(*other) < _TOUCH:
        return False
    (a, b), (p, q) = sorted((one, other), key=lambda s: -math.dist(*s))
    shared = runs_along(p, q, a, b)
    if shared is None:
        return False
    n = math.dist(a, b)
    d = ((b[0] - a[0]) / n, (b[1] - a[1]) / n)
    s, t = (((e[0] - a[0]) * d[0] + (e[1] - a[1]) * d[1]) for e in (p, q))
    if math.dist(b, q) < _TOUCH and t < s:
        # Head to head, their heads stacked: on one line (a collapsed polygon); a side
        # ending a few degrees off where the resultant ends is the polygon's own corner.
        return runs_along(p, q, a, b, within=_TOUCH) is not None
    if shared[1] - shared[0] <= _OVERLAP:
        return False                                  # end to end, or apart
    # Nested from one tail the same way, or one arrow over another (A^n_A/C over A_A
    # where A_C is a quarter millimetre): a textbook's own drawing, named once.
    return not (nested and t > s and math.dist(a, p) < _SAME)


def moved(seg: Segment, lane: int, step: float = LANE) -> Segment:
    """The arrow ``seg`` moved into ``lane``: ``lane × step`` mm square to itself.

    >>> moved(((0.0, 0.0), (10.0, 0.0)), -1)
    ((0.0, -3.0), (10.0, -3.0))
    """
    (a, b) = seg
    n = math.dist(a, b)
    if not lane or n < _TOUCH:
        return seg
    k = lane * step / n
    off = (-(b[1] - a[1]) * k, (b[0] - a[0]) * k)
    return (a[0] + off[0], a[1] + off[1]), (b[0] + off[0], b[1] + off[1])


def _crosses(seg: Segment, other: Segment) -> bool:
    """Whether an arrow moved aside comes within :data:`_CROSS` of another's shaft."""
    from shapely.geometry import LineString

    return LineString(seg).distance(LineString(other)) < _CROSS


def lanes(ends: Sequence[Segment], heavy: Sequence[bool], *,
          fixed: Sequence[Segment] = (), step: float = LANE, nested: bool = True) -> list[int]:
    """The lane of each arrow ``(tail, tip)``: 0 on its points, ±1, ±2 … ``step`` mm to
    either side (+ to the arrow's left on a y-up sheet, its right on paper, y down).

    Arrows clash where one lies along the other (:func:`runs_along`, within
    :data:`ALONG`) over more than half a millimetre, unless one lies within the other
    from a common tail and the same way or they are one and the same arrow; and where
    they meet head to head. A polygon that collapses onto a line (the crank-shaper's at
    θ₂ = 90°) has arrows running back over one another with heads meeting, and the
    Coriolis component at B runs 4.7 mm back along A_B₄ from its tip at t = 2.34 s: each
    goes to the nearest lane where it clashes with none, the absolute vectors
    (``heavy``) and the longest placed first, so they keep to their points. ``fixed``
    segments (the links of a space diagram) stay where they are: an arrow along one
    clashes with it wherever they share its line. With ``nested`` False an arrow within
    another from a common tail takes a lane of its own too: a polygon drawn head to tail
    (a balancing polygon's sides) has no pole its arrows share. Of the two lanes at one
    distance, one that moves an arrow across another arrow is taken only when the other
    does too.

    >>> lanes([((0, 0), (0, 90)), ((0, 90), (0, 24)), ((0, 0), (0, 30)), ((0, 31), (0, 0))],
    ...       [True, False, True, False])
    [0, 1, 0, -1]
    >>> lanes([((0, 0), (100, 0)), ((100, 0.3), (95, 0.2))], [True, False])    # runs back
    [0, 1]
    >>> lanes([((0, 0), (0, 20))], [False], fixed=[((0, -5), (0, 50))])       # along a link
    [1]
    """
    order = sorted(range(len(ends)), key=lambda i: (not heavy[i], -math.dist(*ends[i])))
    lane = [0] * len(ends)

    def clear(i: int, candidate: int, placed: list[int], strict: bool) -> bool:
        seg = moved(ends[i], candidate, step)
        if any(_clash_fixed(seg, f) for f in fixed):
            return False
        for j in placed:
            other = moved(ends[j], lane[j], step)
            if lane[j] == candidate and _clash(ends[i], ends[j], nested):
                return False
            if strict and candidate and _crosses(seg, other):
                return False
        return True

    for k, i in enumerate(order):
        placed = order[:k]
        # The nearest lane, clear of every other arrow if one at that distance is.
        lane[i] = next((c for n in range(5) for strict in (True, False) for c in (n, -n)
                        if clear(i, c, placed, strict)), 0)
    return lane


def _clash_fixed(seg: Segment, link: Segment) -> bool:
    """Whether an arrow lies along a link: within :data:`ALONG` of its line, beside the
    link, over more than half the arrow's length (V_B leaving B 5° off the plate's edge
    BE is lost in the edge for its first half, though its head stands clear).

    >>> _clash_fixed(((0.0, 0.0), (30.0, 2.7)), ((0.0, 0.0), (35.0, 0.0)))
    True
    >>> _clash_fixed(((0.0, 0.0), (-20.0, 0.0)), ((0.0, 0.0), (35.0, 0.0)))   # beyond its end
    False
    """
    (a, b), (p, q) = seg, link
    n, m = math.dist(a, b), math.dist(p, q)
    if n < _TOUCH or m < _TOUCH:
        return False
    u = ((q[0] - p[0]) / m, (q[1] - p[1]) / m)
    s0, s1 = ((x[0] - p[0]) * u[0] + (x[1] - p[1]) * u[1] for x in (a, b))
    o0, o1 = ((x[0] - p[0]) * u[1] - (x[1] - p[1]) * u[0] for x in (a, b))
    # The share of the arrow (0 at its tail, 1 at its tip) beside the link and near its line.
    lo, hi = 0.0, 1.0
    for v0, v1, low, high in ((s0, s1, 0.0, m), (o0, o1, -ALONG, ALONG)):
        if abs(v1 - v0) < 1e-12:
            if not low <= v0 <= high:
                return False
            continue
        t0, t1 = sorted(((low - v0) / (v1 - v0), (high - v0) / (v1 - v0)))
        lo, hi = max(lo, t0), min(hi, t1)
    return (hi - lo) * n > max(_OVERLAP, 0.5 * n)
