"""The flywheel: the step the turning-moment diagram is read at, against its error and time.

tarsim reads a turning-moment diagram (``constructions/reference/flywheel.py``,
:func:`fluctuation`, what ``tarsim sweep`` and the forces chapter's flywheel use) from the
torque sampled at n equal steps: the mean by the periodic trapezoid rule, the energy by
integrating the torque straight between samples, the intercepts between samples. For a
turning moment that is a sum of sines, T = T₀ + Σ aₖ sin kθ, everything is in closed form:

    E(θ) = −Σ (aₖ/k) cos kθ,    ΔE = max E − min E over the zeros of T − T₀.

Two torques:

- **two harmonics**, T = 500 + 300 sin θ + 400 sin 2θ N·m: the zeros are 0, π and
  cos θ = −3/8, and ΔE = 3²·10⁴/1600 + 200 + 500 = 756.25 J exactly;
- **stiff, a sharp engine-like torque**: harmonics 1 to 24 with aₖ = 600/k^0.5 N·m, whose
  zeros are found to 40 digits (mpmath) between the sign changes of a fine grid.

The error bound stated is the straight-line interpolant's, π h²·max|T″|/2 (|T − T_lin| ≤
h²·max|T″|/8, integrated over the turn, on both ends of ΔE; the mean of sines is exact on
any equal grid), with the rounding of the n-term sums, 4·n·u·2π·max|T − T₀|, added.
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath

from tarsim.constructions.reference.flywheel import fluctuation

from .chapter_rows import EPS, ChapterStudy, Row, relative
from .svgplot import Curve, write_plot
from .timing import median_time

__all__ = ["TWO", "SHARP", "torque", "exact_delta_e", "flywheel_study"]

TWO = (500.0, ((1, 300.0), (2, 400.0)))
"""T₀ and the (k, aₖ) of the two-harmonic torque (N·m)."""

SHARP = (500.0, tuple((k, 600.0 / math.sqrt(k)) for k in range(1, 25)))
"""T₀ and the (k, aₖ) of the sharp torque (N·m)."""


def torque(spec, theta: float) -> float:
    """T(θ) of ``spec`` = (T₀, ((k, aₖ), …))."""
    t0, terms = spec
    return t0 + math.fsum(a * math.sin(k * theta) for k, a in terms)


def exact_delta_e(spec, dps: int = 40) -> mpmath.mpf:
    """ΔE of ``spec`` in closed form: E = −Σ (aₖ/k) cos kθ at the zeros of T − T₀, found to
    ``dps`` digits from the sign changes of a 4000-step grid (and at θ = 0, a zero of every
    sine)."""
    _, terms = spec
    with mpmath.workdps(dps):
        def excess(t):
            return mpmath.fsum(mpmath.mpf(a) * mpmath.sin(k * t) for k, a in terms)

        def energy(t):
            return -mpmath.fsum(mpmath.mpf(a) / k * mpmath.cos(k * t) for k, a in terms)
        n = 4000
        grid = [2 * mpmath.pi * i / n for i in range(n + 1)]
        values = [excess(t) for t in grid]
        zeros = [mpmath.mpf(0)]
        for i in range(n):
            if values[i] == 0 or values[i] * values[i + 1] < 0:
                if i and values[i] != 0:
                    zeros.append(mpmath.findroot(excess, (grid[i], grid[i + 1]),
                                                 solver="anderson"))
                elif i:
                    zeros.append(grid[i])
        levels = [energy(z) for z in zeros]
        return max(levels) - min(levels)


def _bound(spec, n: int, delta_e: float) -> float:
    """The stated tolerance of ΔE read at n steps, relative to ΔE."""
    _, terms = spec
    h = 2 * math.pi / n
    curvature = math.fsum(abs(a) * k * k for k, a in terms)
    swing = math.fsum(abs(a) for _, a in terms)
    return (math.pi * h * h * curvature / 2 + 4 * n * (EPS / 2) * 2 * math.pi * swing) / delta_e


def _read(spec, n: int) -> float:
    angles = [2 * math.pi * i / n for i in range(n)]
    return fluctuation(angles, [torque(spec, t) for t in angles]).delta_e


def flywheel_study(out: Path, *, quick: bool = False) -> ChapterStudy:
    """Rows for n = 12 … 36 000 steps a turn, each torque: ΔE's error against its closed
    form, the stated bound, and the median time of sampling and reading the diagram."""
    steps = (12, 72, 360, 3600) if quick else (12, 24, 48, 72, 180, 360, 720, 1440, 3600,
                                               36000)
    rows, curves, times = [], [], []
    for name, spec in (("two harmonics", TWO), ("sharp, 24 harmonics", SHARP)):
        exact = exact_delta_e(spec)
        pts, tpts = [], []
        for n in steps:
            got = _read(spec, n)
            err = relative(got, exact)
            t = median_time(lambda s=spec, n=n: _read(s, n),
                            3 if n > 3600 or quick else 15)
            tol = _bound(spec, n, float(exact))
            rows.append(Row(f"{name}, n = {n} ({360 / n:.3g}°)", "ΔE", 360 / n, err, tol, t,
                            f"ΔE = {got:.6g} J (exact {float(exact):.6g} J)"
                            + ("; bound ≥ 1: the step leaves no digit guaranteed"
                               if tol >= 1 else "")))
            pts.append((t, max(err, 1e-17)))
            tpts.append((360 / n, max(err, 1e-17)))
        curves.append(Curve(f"{name}: error against run time", tuple(pts),
                            tuple(str(n) for n in steps)))
        times.append(Curve(name, tuple(tpts)))
    path = write_plot(out / "flywheel-step.svg",
                      "The turning-moment diagram: ΔE's error against the time to read it",
                      "run time: sampling T and reading the diagram (µs)",
                      "relative error of ΔE against its closed form", curves,
                      note="Labels: steps a turn. The error falls as the step squared, the "
                           "time grows with the steps.")
    two = {r.case: r for r in rows}
    at1 = two["two harmonics, n = 360 (1°)"]
    sharp1 = two["sharp, 24 harmonics, n = 360 (1°)"]
    fine = two[f"sharp, 24 harmonics, n = {steps[-1]} ({360 / steps[-1]:.3g}°)"]
    head = (f"a 1° step reads ΔE to {at1.error:.0e} ({at1.time_us:.0f} µs) for two harmonics "
            f"and to {sharp1.error:.0e} for a sharp torque of 24; the error falls as the step "
            f"squared, to {fine.error:.0e} at {steps[-1]} steps ({fine.time_us / 1e3:.0f} ms); "
            f"{sum(r.within for r in rows)} of {len(rows)} rows within the stated bound "
            f"({sum(r.tolerance >= 1 for r in rows)} of them coarse steps where the bound "
            "guarantees no digit)")
    return ChapterStudy("The flywheel", "ΔE in closed form (E = −Σ aₖ/k·cos kθ at the zeros "
                        "of T − T₀)", "step (°)", head, tuple(rows), path)
