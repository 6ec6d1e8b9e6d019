"""A radial engine's cylinders on one crank, their primary and secondary forces found as the
books find them, by direct and reverse cranks.

The n cylinders' lines stand φᵢ = 360°·i/n round the crank shaft, cylinder 1's at 0°; with the
crank at θ from cylinder 1's line, cylinder i's primary force m·ω²·r·cos(θ − φᵢ) along its
line is the sum of two half masses' centrifugal forces: one on the direct crank, at θ, and
one on the reverse crank, its mirror image in the line, at 2φᵢ − θ. Its secondary force
(m·ω²·r/n)·cos 2(θ − φᵢ) is likewise half on a direct secondary crank at 2θ − φᵢ and half on
a reverse one at 3φᵢ − 2θ, each of a fourth the crank's length turning at 2ω. The direct
primary cranks all stand at θ, so they sum to (n/2)·m·ω²·r along the crank; the reverse ones
stand evenly round and cancel for n ≥ 3, which is why the primary force is of one size at
every crank angle and turns with the crank.
"""

from __future__ import annotations

import math

from .rotor import Engine

__all__ = ["radial_forces", "radial_lines_at"]


def radial_lines_at(e: Engine) -> tuple[float, ...]:
    """The cylinders' lines (rad from cylinder 1's), evenly round the crank shaft."""
    return tuple(2 * math.pi * i / e.radial for i in range(e.radial))


def _sum(f: float, angles) -> tuple[float, float]:
    """The resultant (x along cylinder 1's line, y across it) of forces of size f at the
    given angles: the cranks' centrifugal forces added head to tail."""
    return (math.fsum(f * math.cos(a) for a in angles),
            math.fsum(f * math.sin(a) for a in angles))


def radial_forces(e: Engine, theta: float
                  ) -> tuple[tuple[float, float], tuple[float, float] | None]:
    """The resultant primary and secondary forces (N, along and across cylinder 1's line)
    with the crank at ``theta`` (rad) from cylinder 1's line, summed over the direct and
    reverse cranks; the secondary None with no rod."""
    half = e.reciprocating * e.speed ** 2 * e.crank / 2
    lines = radial_lines_at(e)
    primary = _sum(half, [theta] * len(lines) + [2 * p - theta for p in lines])
    if e.rod is None:
        return primary, None
    n = e.rod / e.crank
    secondary = _sum(half / n, [2 * theta - p for p in lines] + [3 * p - 2 * theta
                                                                 for p in lines])
    return primary, secondary
