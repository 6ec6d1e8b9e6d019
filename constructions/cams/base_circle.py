"""The least base circle that holds a translating follower's pressure angle to a limit.

The books ask it as "the pressure angle is not to exceed 30°: find the least base circle".
For a knife edge or roller translating on a line e right of the cam centre (e < 0 left),
tan φ = (y′ − σe)/(s₀ + y) with s₀ = √(R_p² − e²) (:mod:`..reference.cam_profile`), so
|φ| ≤ φ_max wherever the follower is exactly when

    s₀ ≥ |y′ − σe| / tan φ_max − y    at every cam angle,

and the least prime circle is R_p = √(s₀² + e²) with s₀ the greatest right side; the base
circle is R_p less the roller's radius. The right side is smooth on each analytic piece of
the motion but where y′ = σe (a least, not a greatest), so its greatest is found piece by
piece as :mod:`.extremes` finds a cam's extremes, at the ends and between samples. The
cam so found touches the limit there; its survey by inversion, which knows nothing of this
formula, must find its greatest pressure angle equal to the limit.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from ..reference.cam_profile import Follower
from .extremes import greatest, pieces

__all__ = ["least_prime_reach", "least_base_radius", "least_flat_base"]


def least_prime_reach(segments: Sequence[Any], f: Follower, sigma: float, limit: float
                      ) -> float:
    """The greatest of |y′ − σe|/tan φ_max − y round the turn: the least s₀ (m)."""
    t = math.tan(limit)
    out = -math.inf
    for p in pieces(segments):
        def need(x: float, p=p) -> float:
            m = p.motion(x)
            return abs(m.y1 - sigma * f.offset) / t - m.y
        out = max(out, greatest(need, p.t0, p.t1))
    return out


def least_flat_base(segments: Sequence[Any], rho: float) -> float:
    """The least base circle (m) whose profile under a flat face curves nowhere tighter than
    ``rho``: the profile's radius there is r_b + y + y″, so r_b is the greatest of
    ρ − y − y″ round the turn (found piece by piece, y″ jumping only between pieces).

    Examples
    --------
    >>> from tarsim.constructions.cams.displacement import Segment
    >>> segs = [Segment("rise", math.pi, 1.0, "simple harmonic"),
    ...         Segment("return", math.pi, 1.0, "simple harmonic")]
    >>> round(least_flat_base(segs, 0.0), 12)      # y + y″ = ½(1 − cos θ) + ½ cos θ = ½
    -0.5
    """
    out = -math.inf
    for p in pieces(segments):
        def need(x: float, p=p) -> float:
            m = p.motion(x)
            return rho - m.y - m.y2
        out = max(out, greatest(need, p.t0, p.t1))
    return out


def least_base_radius(segments: Sequence[Any], f: Follower, sigma: float, limit: float
                      ) -> float:
    """The least base circle (m) that holds the pressure angle of the translating follower
    ``f`` to ``limit`` (rad) for a cam turning in the sense ``sigma``; 0 or less where any
    base circle would.

    Examples
    --------
    A radial knife edge rising 1 m at uniform velocity over a radian: y′ = 1 everywhere,
    greatest against the least y = 0, so s₀ = 1/tan 45° = 1.

    >>> from tarsim.constructions.cams.displacement import Segment
    >>> segs = [Segment("rise", 1.0, 1.0, "uniform velocity"), Segment("dwell", 1.0),
    ...         Segment("return", 2 * math.pi - 2.0, 1.0, "uniform velocity")]
    >>> round(least_base_radius(segs, Follower(), 1.0, math.pi / 4), 12)
    1.0
    """
    s0 = least_prime_reach(segments, f, sigma, limit)
    if s0 <= 0:
        return s0
    return math.hypot(s0, f.offset) - (f.radius if f.kind == "roller" else 0.0)
