"""The flywheel as the textbooks pose it: a turning-moment diagram given as T(θ) or as its
areas, read for the greatest fluctuation of energy, the flywheel and the shaft's extremes.

A diagram given as T(θ) (a formula, or a table of points joined by straight lines) is drawn
at equal steps over its cycle and read as :func:`~..reference.flywheel.fluctuation` reads a
mechanism's: the mean, the intercepts with it, the areas between them, and ΔE, the highest
energy less the lowest. A diagram given by its areas (the books' "areas above and below the
mean line, in order, with the diagram's scales") is read the same way from the areas: their
running sum is the energy above its value at the first intercept. With the mean speed ω, a
flywheel that holds the speed within C_s = (ω_max − ω_min)/ω has I = ΔE/(C_s·ω²); a rim of
mean radius r has mass I/r². The shaft, loaded by a steady resisting torque equal to the
mean, speeds up at α = (T − T_mean)/I: its greatest acceleration and retardation are where
T is highest and lowest over the whole cycle (the global extremes, found by a scan at every
step and refined by golden-section search; a local peak is not the greatest). A table that
jumps (a punch starting or stopping) is read exactly at its points instead
(:func:`read_table`), since no drawing at equal steps holds a jump.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from ..reference.flywheel import Fluctuation, fluctuation

__all__ = ["Diagram", "Reading", "STEPS", "read_diagram", "read_table", "area_reading", "extreme",
           "rim_mass", "rim_radius", "rim_section", "speed_limits", "Punch"]

STEPS = 3600
"""The steps a cycle's T(θ) is drawn at: ΔE's error from the straight lines between steps is
some h²·|T′| (h the step), a few parts in a million of a book's ΔE."""


@dataclass(frozen=True)
class Diagram:
    """T(θ) (N·m, θ the crank angle in rad) over a cycle of ``cycle`` rad from θ = 0."""

    torque: Callable[[float], float]
    cycle: float
    kinks: tuple[float, ...] = ()
    """The angles where T's slope jumps (a table's points): samples are set on them."""


@dataclass(frozen=True)
class Reading:
    """A diagram read: its mean torque (N·m), the intercepts (rad), each area (J) in order
    from the first intercept, ΔE (J), where the energy is highest and lowest (rad), and the
    step it was drawn at (rad; 0 for a diagram given by its areas)."""

    mean: float
    intercepts: tuple[float, ...]
    areas: tuple[float, ...]
    delta_e: float
    highest: float
    lowest: float
    step: float = 0.0
    samples: tuple[tuple[float, float], ...] = ()
    """(θ rad, T N·m) at each step, for the figure."""


def steps_for(d: Diagram) -> int:
    """How many equal steps to draw ``d`` at: :data:`STEPS`, or the least multiple of a
    table's equal spacing past it, so that every point of the table is a step."""
    if len(d.kinks) < 2:
        return STEPS
    gap = d.kinks[1] - d.kinks[0]
    n = round(d.cycle / gap)
    on_grid = all(abs(k - d.kinks[0] - i * gap) <= 1e-9 * d.cycle for i, k in enumerate(d.kinks))
    start = d.kinks[0] / gap
    if not on_grid or abs(n * gap - d.cycle) > 1e-9 * d.cycle or abs(start - round(start)) > 1e-9:
        return STEPS
    return n * math.ceil(STEPS / n)


def read_diagram(d: Diagram) -> Reading:
    """Draw ``d`` at equal steps over its cycle and read it for its areas and ΔE."""
    n = steps_for(d)
    step = d.cycle / n
    thetas = [k * step for k in range(n)]
    torques = [d.torque(t) for t in thetas]
    # fluctuation reads a turn of 2π: the cycle is scaled to one, and its areas back.
    scale = d.cycle / (2 * math.pi)
    r: Fluctuation = fluctuation([t / scale for t in thetas], torques)
    return Reading(r.mean, tuple(c * scale for c in r.intercepts),
                   tuple(a * scale for a in r.areas), r.delta_e * scale, r.highest * scale,
                   r.lowest * scale, step, tuple(zip(thetas, torques)))


def read_table(points: tuple[tuple[float, float], ...], cycle: float) -> Reading:
    """Read a table's diagram exactly, at its points: T straight between them, an angle
    given twice a jump (a punch that starts or stops, which no drawing at equal steps
    holds), a last point a cycle on from the first a jump back to it.

    The mean is the trapezoids' sum over the cycle; the curve crosses the mean inside a
    straight piece (at its root) or at a jump across it; the energy at each crossing is the
    trapezoids' sum up to it. The samples are the points, each jump's two values in turn,
    and the cycle's end (T just before it).

    >>> r = read_table(((0.0, 6.0), (1.0, 6.0), (1.0, 0.0), (6.0, 0.0)), 6.0)   # a sixth at 6
    >>> r.mean, r.delta_e, r.intercepts
    (1.0, 5.0, (0.0, 1.0))
    """
    ts, vs = [t for t, _ in points], [v for _, v in points]
    if ts[-1] < ts[0] + cycle * (1 - 1e-12):
        ts.append(ts[0] + cycle)
        vs.append(vs[0])
    ts[-1] = ts[0] + cycle
    mean = math.fsum((b - a) * (va + vb) / 2 for a, b, va, vb
                     in zip(ts, ts[1:], vs, vs[1:])) / cycle
    e = [v - mean for v in vs]
    last = next((1.0 if x > 0 else -1.0 for x in reversed(e) if x != 0.0), 0.0)
    crossings: list[tuple[float, float]] = []         # (θ, energy there)
    energy, zero_at = 0.0, None
    for i in range(len(ts) - 1):
        a, b, ea, eb = ts[i], ts[i + 1], e[i], e[i + 1]
        if ea != 0.0:
            sign = 1.0 if ea > 0 else -1.0
            if last and sign != last:
                crossings.append(zero_at if zero_at is not None else (a, energy))
            last, zero_at = sign, None
        elif zero_at is None:
            zero_at = (a, energy)
        if b > a and ea * eb < 0.0:                   # across the mean inside the piece
            r = a + ea / (ea - eb) * (b - a)
            crossings.append((r, energy + (r - a) * ea / 2))
            last = 1.0 if eb > 0 else -1.0
        energy += (b - a) * (ea + eb) / 2
    samples = tuple(zip(ts, vs))
    if not crossings:
        return Reading(mean, (), (), 0.0, ts[0], ts[0], 0.0, samples)
    crossings.sort()
    levels = [q for _, q in crossings]
    areas = tuple(levels[k + 1] - levels[k] for k in range(len(levels) - 1)) + (
        levels[0] + energy - levels[-1],)
    top = max(crossings, key=lambda p: p[1])
    bottom = min(crossings, key=lambda p: p[1])
    return Reading(mean, tuple(t for t, _ in crossings), areas, top[1] - bottom[1], top[0],
                   bottom[0], 0.0, samples)


def area_reading(areas: list[float]) -> Reading:
    """The reading of a diagram given as its areas (J, + above the mean, in order from an
    intercept): the energy after each is the running sum; ΔE the highest less the lowest.
    The intercepts are numbered 0, 1, … (their angles are not given)."""
    levels = [0.0]
    for a in areas:
        levels.append(levels[-1] + a)
    levels.pop()            # the last returns to the first, the areas adding to 0
    top = max(range(len(levels)), key=levels.__getitem__)
    bottom = min(range(len(levels)), key=levels.__getitem__)
    return Reading(0.0, tuple(float(i) for i in range(len(areas))), tuple(areas),
                   levels[top] - levels[bottom], float(top), float(bottom))


def extreme(d: Diagram, samples: tuple[tuple[float, float], ...],
            sign: float) -> list[tuple[float, float]]:
    """Where over the whole cycle T is greatest (``sign`` +1) or least (−1), and its value:
    each peak of the scan (a step beyond both its neighbours), refined by golden-section
    search over the steps beside it (a table's peaks are at its points, which are steps),
    and every one within rounding of the best, in order of θ (a curve that repeats within
    its cycle, T = A sin 2θ over a turn, has its greatest twice). A table's straight lines
    have their extremes at its points: each point, either side of it (a jump), is a place,
    so a level stretch at the extreme is found at both its ends."""
    size = max(abs(t) for _, t in samples)
    if d.kinks:
        found = [(k, d.torque(u)) for k in d.kinks for u in (k, math.nextafter(k, -math.inf))]
    else:
        n = len(samples)
        v = [sign * t for _, t in samples]
        peaks = [k for k in range(n) if v[k] >= v[k - 1] and v[k] >= v[(k + 1) % n]
                 and (v[k] > v[k - 1] or v[k] > v[(k + 1) % n])] or [
                     max(range(n), key=v.__getitem__)]
        found = [_refined(d, samples, k, sign) for k in peaks]
    best = max(sign * t for _, t in found)
    same = {}
    for th, t in found:
        if sign * t >= best - 1e-9 * size:
            key = th % d.cycle
            # a point a cycle on is the first again; one place once
            same.setdefault(round(key / d.cycle, 12) % 1.0, (key, t))
    return sorted(same.values())


def _refined(d: Diagram, samples, k: int, sign: float) -> tuple[float, float]:
    """Sample ``k``'s peak, refined by golden-section search over the steps beside it."""
    step = samples[1][0] - samples[0][0]
    a, b = samples[k][0] - step, samples[k][0] + step
    g = (math.sqrt(5) - 1) / 2

    def f(t: float) -> float:
        return -sign * d.torque(t)
    c, e = b - g * (b - a), a + g * (b - a)
    fc, fe = f(c), f(e)
    for _ in range(80):
        if fc < fe:
            b, e, fe = e, c, fc
            c = b - g * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, e, fe
            e = a + g * (b - a)
            fe = f(e)
    t = (a + b) / 2
    return max((samples[k], (t, d.torque(t))), key=lambda p: sign * p[1])


def rim_mass(inertia: float, radius: float) -> float:
    """A thin rim's mass (kg) at mean radius ``radius`` (m) for ``inertia`` (kg·m²): I/r²."""
    return inertia / (radius * radius)


def rim_radius(inertia: float, mass: float) -> float:
    """A thin rim's mean radius (m) for ``inertia`` (kg·m²) and ``mass`` (kg): √(I/m)."""
    return math.sqrt(inertia / mass)


def rim_section(mass: float, radius: float, density: float,
                width_to_thickness: float) -> tuple[float, float]:
    """A rectangular rim's thickness and width (m) for its ``mass`` (kg) at mean radius
    ``radius`` (m), of ``density`` (kg/m³) and width ``width_to_thickness`` times its
    thickness: its section is m/(ρ·2πr) = b·t with b = k·t.

    >>> [round(x, 9) for x in rim_section(7200 * 2 * math.pi * 0.2, 1.0, 7200, 5.0)]
    [0.2, 1.0]
    """
    thickness = math.sqrt(mass / (density * 2 * math.pi * radius) / width_to_thickness)
    return thickness, width_to_thickness * thickness


def speed_limits(speed: float, fluctuation: float) -> tuple[float, float]:
    """The greatest and least speeds (rad/s) about the mean ``speed`` within C_s =
    ``fluctuation``, the mean their average as the books take it: ω(1 ± C_s/2).

    >>> speed_limits(100.0, 0.02)
    (101.0, 99.0)
    """
    return speed * (1 + fluctuation / 2), speed * (1 - fluctuation / 2)


@dataclass(frozen=True)
class Punch:
    """A punching press as the books give it: ``energy`` (J) a hole takes, a hole every
    ``period`` (s), each punched in ``time`` (s). The motor, steady, gives the energy evenly
    over the period; while it punches the motor gives E·t/T and the flywheel the rest.
    Where friction takes a share of the work (the books' "frictional losses are 1/5 of the
    work done in punching"), the hole takes ``supply`` times its punching work, and the
    motor and flywheel give that.

    >>> p = Punch(15000.0, 5.0, 2.0)
    >>> p.power, p.delta_e
    (3000.0, 9000.0)
    >>> Punch(15000.0, 5.0, 2.0, supply=1.2).delta_e
    10800.0
    """

    energy: float
    period: float
    time: float
    by_power: bool = False
    """The period was found from the motor's power given, E/P: the holes a minute are asked."""
    supply: float = 1.0
    """The energy supplied per joule of punching work: 1 + the losses' share, or 1/η."""
    losses: float | None = None
    """The losses' share of the punching work, where the file gives it."""
    efficiency: float | None = None
    """The punch's efficiency η, where the file gives it."""
    given: tuple[tuple[str, float | str], ...] = ()
    """Its data as the file writes them (``("hole", 38)``, ``("power", "3 kW")``), in the
    file's units, for a problem sheet to state the energy per area where E is found."""

    @property
    def supplied(self) -> float:
        """The energy a hole takes with its losses (J): E·(1 + losses), or E/η."""
        return self.energy * self.supply

    @property
    def power(self) -> float:
        """The motor's power (W): a hole's energy, its losses with it, over the period."""
        return self.supplied / self.period

    @property
    def delta_e(self) -> float:
        """The flywheel's greatest fluctuation of energy (J): what the motor does not give
        while it punches, E·(1 − t/T), E with its losses."""
        return self.supplied * (1 - self.time / self.period)

    def table(self) -> tuple[tuple[float, float], ...]:
        """The punch's resisting torque over one period mapped onto a turn (θ = 2π·time/T,
        the shaft's speed nearly steady): E/(2π·t/T) while it punches, then none."""
        theta = 2 * math.pi * self.time / self.period
        return ((0.0, self.supplied / theta), (theta, self.supplied / theta), (theta, 0.0),
                (2 * math.pi, 0.0))
