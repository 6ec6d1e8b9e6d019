"""Small sums on paper points that the kinematic diagram and the scene share.

Differences, centroids, the farthest pair of a set, and the angle and tangent of a
point about a centre, all in paper millimetres with y running down the page.
"""

from __future__ import annotations

import math

__all__ = ["difference", "angle_about", "tangent", "centroid", "farthest_pair"]


def difference(p, q):
    """The paper vector from ``q`` to ``p``.

    >>> difference((4.0, 3.0), (1.0, 1.0))
    (3.0, 2.0)
    """
    return (p[0] - q[0], p[1] - q[1])


def angle_about(centre, p) -> float:
    """The paper angle (rad, CCW as seen) of ``p`` about ``centre``."""
    return math.atan2(centre[1] - p[1], p[0] - centre[0])


def tangent(angle: float) -> tuple[float, float]:
    """The paper direction along a circle at ``angle``, the way the angle grows."""
    return (-math.sin(angle), -math.cos(angle))


def centroid(pts):
    """The mean of paper points.

    >>> centroid([(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0)])
    (2.0, 1.5)
    """
    return (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))


def farthest_pair(pts):
    """The two points of ``pts`` farthest apart, the first such pair in order.

    >>> farthest_pair([(0.0, 0.0), (3.0, 0.0), (3.0, 4.0)])
    ((0.0, 0.0), (3.0, 4.0))
    """
    best = (0.0, pts[0], pts[-1])
    for i, p in enumerate(pts):
        for q in pts[i + 1:]:
            d = math.dist(p, q)
            if d > best[0]:
                best = (d, p, q)
    return best[1], best[2]
