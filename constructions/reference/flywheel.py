"""The turning-moment diagram read as the textbooks read it: the mean torque, the energy
areas between the curve and the mean, the greatest fluctuation of energy, the flywheel.

The torque is sampled at equal steps round one turn. Its mean is the periodic trapezoid
rule's, which is exact to rounding for a smooth periodic torque; it is summed exactly
(``math.fsum``), since a mean off by its rounding tilts the running energy by that much
times the turn. The curve crosses the mean at the intercepts (found between samples by a
straight line); between neighbouring intercepts lies an area, energy given out or taken in.
Added from the first intercept, the areas trace the energy above its value there; the
greatest fluctuation ΔE is its highest less its lowest. A flywheel of inertia I holding the
speed within a coefficient C_s = (ω_max − ω_min)/ω_mean needs I = ΔE/(C_s·ω²), ω the mean
speed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["Fluctuation", "fluctuation", "flywheel_inertia", "speed_fluctuation"]


@dataclass(frozen=True)
class Fluctuation:
    """The diagram's reading: the mean torque (N·m), the intercepts (rad), the signed
    area between each pair of them (J, in order from the first), and the greatest
    fluctuation of energy with the angles of the highest and lowest energy (rad)."""

    mean: float
    intercepts: tuple[float, ...]
    areas: tuple[float, ...]
    delta_e: float
    highest: float
    lowest: float


def fluctuation(angles: list[float], torques: list[float]) -> Fluctuation:
    """Read the turning-moment diagram of ``torques`` at equal ``angles`` round a turn
    (the first angle the start, the step 2π/len).

    Raises
    ------
    ValueError
        For fewer than 4 samples, or samples not equally spaced round one turn.
    """
    n = len(angles)
    if n < 4 or len(torques) != n:
        raise ValueError("a turning-moment diagram needs 4 or more samples round the turn")
    step = 2 * math.pi / n
    if any(abs((angles[i] - angles[0]) - i * step) > 1e-9 for i in range(n)):
        raise ValueError("the samples must be equally spaced round one turn")
    mean = math.fsum(torques) / n
    excess = [t - mean for t in torques] + [torques[0] - mean]
    crossings: list[float] = []
    for i in range(n):
        a, b = excess[i], excess[i + 1]
        if a == 0.0 or (a < 0) != (b < 0) and b != 0.0:
            crossings.append(angles[0] + (i + (a / (a - b) if a != b else 0.0)) * step)
    energy = _energy(angles[0], step, excess)
    if not crossings:
        return Fluctuation(mean, (), (), 0.0, angles[0], angles[0])
    levels = [(t, energy(t)) for t in crossings]
    areas = tuple(levels[(k + 1) % len(levels)][1] - levels[k][1]
                  + (energy(angles[0] + 2 * math.pi) if k == len(levels) - 1 else 0.0)
                  for k in range(len(levels)))
    top = max(levels, key=lambda p: p[1])
    bottom = min(levels, key=lambda p: p[1])
    return Fluctuation(mean, tuple(crossings), areas, top[1] - bottom[1], top[0], bottom[0])


def _energy(start: float, step: float, excess: list[float]):
    """E(θ) = ∫ (T − T_mean) dθ from ``start``, the torque straight between samples."""
    cumulative = [0.0]
    for i in range(len(excess) - 1):
        cumulative.append(cumulative[-1] + (excess[i] + excess[i + 1]) * step / 2)

    def at(theta: float) -> float:
        u = (theta - start) / step
        i = min(int(u), len(excess) - 2)
        f = u - i
        a, b = excess[i], excess[i + 1]
        return cumulative[i] + step * (a * f + (b - a) * f * f / 2)
    return at


def flywheel_inertia(delta_e: float, omega: float, cs: float) -> float:
    """The flywheel (kg·m²) that keeps the speed within C_s of its mean ω: ΔE/(C_s·ω²)."""
    return delta_e / (cs * omega * omega)


def speed_fluctuation(delta_e: float, omega: float, inertia: float) -> float:
    """The coefficient C_s a flywheel of ``inertia`` allows: ΔE/(I·ω²)."""
    return delta_e / (inertia * omega * omega)
