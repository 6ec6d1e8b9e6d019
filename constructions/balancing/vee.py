"""A V engine's two cylinders on one crank: their primary and secondary forces summed as
vectors along their lines of stroke.

The lines stand at ±α from the V's centre line (2α the V's angle); at a crank angle θ from
the centre line, cylinder 1's crank is θ − α from its own line and cylinder 2's θ + α, so
each pushes m·ω²·r·cos(θ ∓ α) (primary) and m·ω²·r·cos 2(θ ∓ α)/n (secondary) along its
line. The two vectors are added head to tail, as the force polygon adds them; the
resultant's components along and across the centre line are what the books tabulate.
"""

from __future__ import annotations

import math

from .rotor import Engine

__all__ = ["vee_forces", "vee_greatest"]


def vee_forces(e: Engine, theta: float) -> tuple[tuple[float, float], tuple[float, float] | None]:
    """The resultant primary and secondary forces (N, along and across the centre line) at
    crank angle ``theta`` (rad) from the centre line; the secondary None with no rod."""
    half = e.vee / 2
    f = e.reciprocating * e.speed ** 2 * e.crank
    lines = ((half, theta - half), (-half, theta + half))
    primary = (math.fsum(f * math.cos(t) * math.cos(a) for a, t in lines),
               math.fsum(f * math.cos(t) * math.sin(a) for a, t in lines))
    if e.rod is None:
        return primary, None
    n = e.rod / e.crank
    secondary = (math.fsum(f / n * math.cos(2 * t) * math.cos(a) for a, t in lines),
                 math.fsum(f / n * math.cos(2 * t) * math.sin(a) for a, t in lines))
    return primary, secondary


def vee_greatest(e: Engine) -> tuple[tuple[float, float], tuple[float, float] | None]:
    """The greatest resultant primary and secondary forces (N) and the crank angle (degrees
    from the centre line) each first comes at. The resultant's tip runs round an ellipse
    whose axes lie along and across the centre line (the two lines are mirror images in
    it), so its greatest is at one end of an axis: θ = 0° or 90° (primary), 2θ = 0° or 90°
    (secondary)."""
    def size(theta: float, k: int) -> float:
        v = vee_forces(e, math.radians(theta))[k]
        return math.hypot(*v)
    primary = max((size(0.0, 0), 0.0), (size(90.0, 0), 90.0), key=lambda p: p[0])
    if e.rod is None:
        return primary, None
    return primary, max((size(0.0, 1), 0.0), (size(45.0, 1), 45.0), key=lambda p: p[0])
