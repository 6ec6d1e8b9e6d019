"""The flywheel's inputs as the books give them: a turning moment as a formula, as a table of
points joined by straight lines, and as the areas of its diagram; the step the diagram is
drawn at against ΔE's error and the run time.

Each case is a flywheel file as a user writes it, read by the chapter's own parser
(``exercises/forces/flywheel_file.py``) and read as its solution reads it
(``constructions/forces/flywheel.py``: :func:`read_diagram` at ``STEPS`` equal steps, set
here to each step studied; :func:`area_reading` for the areas). Closed forms:

- **formula**, T = 5000 + 1500 sin 3θ over a turn: ΔE = 2·1500/3 = 1000 J (a lobe of A sin
  kθ holds 2A/k); T = 20000 + 9500 sin 2θ − 5700 cos 2θ over half a turn: ΔE = √(9500² +
  5700²) J (one lobe of R sin 2θ); and, stiff, T = 10⁶ + 2 sin θ: ΔE = 4 J beside a mean a
  quarter of a million times larger, all of which the samples carry (a table of 10⁵ ± 0.5
  N·m likewise);
- **table**, the energy of a straight-line curve is a sum of trapezoids and its intercepts
  are rational: ΔE is exact in Fractions (in N·m·degrees, times π/180 at 40 digits);
- **areas**, ΔE is the running sum's highest less its lowest, exact in Fractions of the
  areas as read (areas with no exact binary form show the rounding of the running sum).

Tolerances. A formula drawn at step h: the straight lines between steps are off T by at
most h²·max|T″|/8, over the cycle c on both ends of ΔE, c·h²·max|T″|/4; a table's steps fall
on its points, so its lines are its own and only rounding is left. Rounding: each of n
samples carries u·max|T| (the mean subtracted from them), summed over the cycle,
4·n·u·c·max|T|; an area list of m areas, m·u·Σ|a|.
"""

from __future__ import annotations

import math
from fractions import Fraction
from pathlib import Path
from unittest import mock

import mpmath

from tarsim.constructions.forces import flywheel as fw
from tarsim.exercises.forces.flywheel_file import parse_flywheel

from .chapter_rows import EPS, ChapterStudy, Row, relative
from .svgplot import Curve, write_plot
from .timing import median_time

__all__ = ["FORMULAS", "TABLES", "AREAS", "exact_table", "exact_areas",
           "flywheel_input_study"]

_U = EPS / 2

FORMULAS = (
    ("formula 5000 + 1500 sin 3θ", "5000 + 1500*sin(3*theta)", 360, 2 * 1500 / 3,
     1500 * 9.0, 6500.0),
    ("formula 20000 + 9500 sin 2θ − 5700 cos 2θ", "20000 + 9500*sin(2*theta) - "
     "5700*cos(2*theta)", 180, math.hypot(9500, 5700), 4 * math.hypot(9500, 5700),
     20000 + math.hypot(9500, 5700)),
    ("stiff formula 10⁶ + 2 sin θ", "1000000 + 2*sin(theta)", 360, 4.0, 2.0, 1e6 + 2),
)
"""(case, T(θ) as the file writes it, cycle °, ΔE J, max|T″| N·m, max|T| N·m)."""

TABLES = (
    ("table of 4 points (single cylinder)", ((0, 0), (90, 6000), (180, 0), (270, -1000)), 360),
    ("table of 12 points, 30° apart", ((0, 0), (30, 4200), (60, 7000), (90, 5800),
                                        (120, 3000), (150, 800), (180, -1200), (210, -400),
                                        (240, 1500), (270, 2600), (300, 1800), (330, 300)),
     360),
    ("stiff table: 10⁵ ± 0.5 N·m", ((0, 100000), (90, 100000.5), (180, 100000),
                                    (270, 99999.5)), 360),
)
"""(case, the table's (θ °, T N·m) points, cycle °)."""

AREAS = (
    ("areas of a petrol engine (mm² × 5 N·m × 1°)", (295, -685, 40, -340, 960, -270),
     5 * math.pi / 180),
    ("areas of a multi-cylinder engine (J)", (-30, 410, -280, 320, -330, 250, -360, 280,
                                             -260), 1.0),
    ("areas not exact in binary (J)", (0.1, -0.2, 0.3, -0.1, 0.2, -0.3), 1.0),
)
"""(case, the areas as the file gives them, the energy scale J per unit of area)."""


def exact_table(points, cycle_deg: float) -> mpmath.mpf:
    """ΔE (J) of the straight-line curve through ``points`` (θ °, T N·m), the last joined to
    the first a cycle on: the mean, the intercepts and the energy at each, all in Fractions
    (N·m·degrees), times π/180 at 40 digits."""
    pts = [(Fraction(t), Fraction(v)) for t, v in points]
    pts.append((pts[0][0] + Fraction(cycle_deg), pts[0][1]))
    mean = sum((t1 - t0) * (v0 + v1) / 2 for (t0, v0), (t1, v1) in zip(pts, pts[1:])) \
        / Fraction(cycle_deg)
    energy, levels = Fraction(0), []
    for (t0, v0), (t1, v1) in zip(pts, pts[1:]):
        e0, e1 = v0 - mean, v1 - mean
        if e0 == 0:
            levels.append(energy)
        elif e0 * e1 < 0:
            x = t0 + (t1 - t0) * e0 / (e0 - e1)           # the intercept
            levels.append(energy + (x - t0) * e0 / 2)
        energy += (t1 - t0) * (e0 + e1) / 2
    span = max(levels) - min(levels) if levels else Fraction(0)
    with mpmath.workdps(40):
        return mpmath.mpf(span.numerator) / span.denominator * mpmath.pi / 180


def exact_areas(areas) -> Fraction:
    """ΔE of ``areas`` (J, floats as read) in Fractions: the running sum's range."""
    level, levels = Fraction(0), [Fraction(0)]
    for a in areas[:-1]:
        level += Fraction(a)
        levels.append(level)
    return max(levels) - min(levels)


def _file(turning_moment: str) -> str:
    return f"name = \"bench\"\n[units]\nspeed = \"rpm\"\nlength = \"m\"\n" \
           f"[turning_moment]\n{turning_moment}\n[flywheel]\nspeed = 600\n" \
           "speed_fluctuation = 0.02\n"


def _read(diagram, n: int) -> float:
    """ΔE as the solution reads the diagram, drawn at ``n`` steps a cycle (or the least
    multiple of a table's spacing past it)."""
    with mock.patch.object(fw, "STEPS", n):
        return fw.read_diagram(diagram).delta_e


def flywheel_input_study(out: Path, *, quick: bool = False) -> ChapterStudy:
    """Rows for each input: a formula and a table at 12 … 36 000 steps a cycle, and the
    areas; ΔE's error against its closed form, the stated bound and the median time."""
    steps = (36, 360, 3600) if quick else (12, 36, 120, 360, 1200, 3600, 36000)
    rows, curves = [], []
    cases = [(name, parse_flywheel(_file(f'torque = "{text}"\ncycle = {cycle}')).diagram,
              mpmath.mpf(de), cycle, curv, top) for name, text, cycle, de, curv, top in FORMULAS]
    cases += [(name, parse_flywheel(_file(f"points = {[list(p) for p in pts]}\n"
                                          f"cycle = {cycle}")).diagram,
               exact_table(pts, cycle), cycle, 0.0, max(abs(v) for _, v in pts))
              for name, pts, cycle in TABLES]
    for name, diagram, exact, cycle, curvature, top in cases:
        c = math.radians(cycle)
        pts = []
        for n in steps:
            got = _read(diagram, n)
            with mock.patch.object(fw, "STEPS", n):
                drawn = fw.steps_for(diagram)
            h = c / drawn
            err = relative(got, exact)
            t = median_time(lambda d=diagram, n=n: _read(d, n), 3 if n > 3600 or quick else 11)
            tol = (c * h * h * curvature / 4 + 4 * drawn * _U * c * top) / float(exact)
            rows.append(Row(f"{name}, n = {drawn} ({cycle / drawn:.3g}°)", "ΔE", cycle / drawn,
                            err, tol, t, f"ΔE = {got:.9g} J (exact {float(exact):.9g} J)"
                            + ("; bound ≥ 1: the step leaves no digit guaranteed"
                               if tol >= 1 else "")))
            pts.append((t, max(err, 1e-17)))
        curves.append(Curve(name, tuple(pts), tuple(str(n) for n in steps)))
    for name, drawn_areas, scale in AREAS:
        ex = parse_flywheel(_file(f"areas = {list(drawn_areas)}\nenergy_scale = {scale!r}"))
        exact = exact_areas(ex.areas)
        got = fw.area_reading(list(ex.areas)).delta_e
        t = median_time(lambda a=list(ex.areas): fw.area_reading(a), 201)
        tol = len(ex.areas) * _U * math.fsum(abs(a) for a in ex.areas) / float(exact)
        rows.append(Row(name, "ΔE", 0.0, relative(got, exact), tol, t,
                        f"ΔE = {got:.9g} J (exact {float(exact):.9g} J), no step"))
    path = write_plot(out / "flywheel-inputs.svg",
                      "The flywheel's inputs: ΔE's error against the time to read the diagram",
                      "run time: reading the diagram as its file gives it (µs)",
                      "relative error of ΔE against its closed form", curves,
                      note="Labels: steps a cycle asked (a table's steps fall on its points). "
                           "A formula's error falls as the step squared; a table's is "
                           "rounding at every step.")
    by = {r.case: r for r in rows}
    f1 = by[f"{FORMULAS[0][0]}, n = 3600 (0.1°)"]
    t1 = next(r for r in rows if r.case.startswith(TABLES[0][0]) and "n = 3600" in r.case)
    head = (f"at the 3600 steps tarsim draws, a formula's ΔE is read to {f1.error:.0e} "
            f"({f1.time_us / 1e3:.1f} ms) and a table's to {t1.error:.0e}; areas to "
            f"rounding; {sum(r.within for r in rows)} of {len(rows)} rows within the stated "
            f"bound ({sum(r.tolerance >= 1 for r in rows)} of them coarse steps where the "
            "bound guarantees no digit)")
    return ChapterStudy("The flywheel's inputs (formula, table, areas)",
                        "ΔE in closed form (2A/k; a table's trapezoids in Fractions; the "
                        "areas' running sum in Fractions)", "step (°; 0 for areas)", head,
                        tuple(rows), path)
