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
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

__all__ = ["Fluctuation", "Integrated", "energy_between", "fluctuation", "flywheel_inertia",
           "integrated", "speed_fluctuation"]


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


def energy_between(inertia: float, high: float, low: float) -> float:
    """The energy (J) a flywheel of ``inertia`` gives up from ``high`` to ``low`` (rad/s):
    ½·I·(ω1² − ω2²), the kinetic energies' difference.

    >>> energy_between(2.0, 3.0, 1.0)
    8.0
    """
    return inertia * (high * high - low * low) / 2


def speed_fluctuation(delta_e: float, omega: float, inertia: float) -> float:
    """The coefficient C_s a flywheel of ``inertia`` allows: ΔE/(I·ω²)."""
    return delta_e / (inertia * omega * omega)


@dataclass(frozen=True)
class Integrated:
    """A T(θ) read by quadrature: the mean (N·m), ΔE (J), and the greatest and least T over
    the cycle with where each is (θ rad, N·m)."""

    mean: float
    delta_e: float
    greatest: tuple[float, float]
    least: tuple[float, float]
    levels: tuple[tuple[float, float], ...] = ()
    """Each intercept (rad) and the energy there, ∫₀ (T − mean) dθ (J): the speed is
    greatest where it is highest."""


SCAN = 7919
"""The points :func:`integrated` scans a cycle at for sign changes and extremes: a prime, so
that no scan point is a step of the diagram's own drawing."""

START = (math.sqrt(5) - 1) / 2 / 16
"""Where :func:`integrated`'s scan starts, as a share of the cycle: an irrational one, off 0
and off every simple fraction of the cycle where a book's curve crosses its mean."""

PANELS = 64
"""Gauss–Legendre panels a whole cycle is split into (each interval its share, at least one):
20 nodes on a panel of a sixty-fourth of a turn integrate a dozen harmonics to rounding."""

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(20)


def integrated(torque: Callable[[float], float], cycle: float,
               kinks: tuple[float, ...] = ()) -> Integrated:
    """Read T(θ) over ``cycle`` (rad) by composite 20-point Gauss–Legendre quadrature, split
    at the ``kinks`` (where a table's straight lines meet, so each piece is integrated
    exactly), sharing nothing with the diagram's drawing at steps: the mean is ∫T dθ /
    cycle, the intercepts the roots of T − mean (the Illinois method in each bracket of a
    scan; at a table's jump across the mean, the jump), the energy at each ∫₀ (T − mean) dθ,
    and ΔE the highest less the lowest. T's extremes are the scan's best, refined where T's
    central difference changes sign (and a table's points, either side of each, where a
    straight-line curve has them)."""
    inside = sorted(k for k in kinks if 0.0 < k < cycle)
    # the kinks over two cycles, for a scan that starts within the first and runs a cycle on
    edges_all = sorted(set(inside + [0.0, cycle] + [k + cycle for k in inside]))

    def area(a: float, b: float, f) -> float:
        edges = [a] + [k for k in edges_all if a < k < b] + [b]
        total = []
        for lo, hi in zip(edges, edges[1:]):
            n = max(1, math.ceil(PANELS * (hi - lo) / cycle))
            for i in range(n):
                x0, x1 = lo + (hi - lo) * i / n, lo + (hi - lo) * (i + 1) / n
                half, mid = (x1 - x0) / 2, (x1 + x0) / 2
                total.append(half * math.fsum(w * f(mid + half * x)
                                              for x, w in zip(_NODES, _WEIGHTS)))
        return math.fsum(total)

    mean = area(0.0, cycle, torque) / cycle

    def excess(t: float) -> float:
        return torque(t) - mean

    # The scan starts off 0, where a curve often crosses its mean exactly (T = A sin kθ):
    # there a rounded zero may show no change of sign on either side of the wrap.
    start = START * cycle
    grid = [start + cycle * i / SCAN for i in range(SCAN + 1)]
    values = [excess(t) for t in grid]
    roots = []
    for i in range(SCAN):
        a, b = values[i], values[i + 1]
        if a == 0.0:
            roots.append(grid[i])
        elif a * b < 0.0:
            roots.append(_root(excess, grid[i], grid[i + 1], a, b))
    energies = []
    if roots:
        at, total = start, 0.0
        for r in roots:
            total += area(at, r, excess)
            energies.append(total)
            at = r
        delta_e = max(energies) - min(energies)
    else:
        delta_e = 0.0
    found = []
    h = cycle / SCAN
    for sign in (1.0, -1.0):
        k = max(range(SCAN), key=lambda i, s=sign: s * values[i])
        options = [(grid[k], torque(grid[k]))]
        if not kinks:
            t = _peak(torque, grid[k] - h, grid[k] + h, cycle)
            options.append((t, torque(t)))
        # a table's points, and the value just before each (a jump's first, at a punch)
        options += [(t, torque(u)) for t in inside + ([0.0] if kinks else [])
                    for u in (t, math.nextafter(t, -math.inf))]
        t, v = max(options, key=lambda p, s=sign: s * p[1])
        found.append((t % cycle, v))
    return Integrated(mean, delta_e, found[0], found[1],
                      tuple((r % cycle, e) for r, e in zip(roots, energies)))


def _root(f, a: float, b: float, fa: float, fb: float) -> float:
    """The root of ``f`` between ``a`` and ``b`` (``fa``, ``fb`` of opposite signs) by the
    Illinois method: regula falsi, the stale end's value halved each time it stays."""
    side = 0
    for _ in range(200):
        c = (a * fb - b * fa) / (fb - fa)
        if not a < c < b:
            c = (a + b) / 2
        fc = f(c)
        if fc == 0.0 or b - a <= 4 * math.ulp(max(abs(a), abs(b))):
            return c
        if (fc < 0) == (fb < 0):
            b, fb = c, fc
            if side == -1:
                fa /= 2
            side = -1
        else:
            a, fa = c, fc
            if side == 1:
                fb /= 2
            side = 1
    return (a + b) / 2


def _peak(torque, a: float, b: float, cycle: float) -> float:
    """Where T's central difference changes sign between ``a`` and ``b`` (a smooth peak or
    trough), found by bisection; the nearer end if it does not."""
    step = 1e-6 * cycle

    def slope(t: float) -> float:
        return torque(t + step) - torque(t - step)
    sa, sb = slope(a), slope(b)
    if (sa < 0) == (sb < 0):
        return a if abs(sa) < abs(sb) else b
    for _ in range(100):
        m = (a + b) / 2
        sm = slope(m)
        if (sm < 0) == (sa < 0):
            a, sa = m, sm
        else:
            b = m
    return (a + b) / 2
