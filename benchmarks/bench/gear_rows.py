"""Gear trains: exact rational arithmetic against floats on nearly cancelling trains.

A reverted planetary train (the arm 6 drives, the sun 2 is fixed, the compound planet 3–4
meshes it and the output sun 5) with N2 = n + 1, N3 = n, N4 = n − 1, N5 = n + 2 is
coaxial for every n (N2 + N3 = N4 + N5) and has the train value

    ω5/ω6 = 1 − e,   e = N2·N4 / (N3·N5) = (n² − 1)/(n² + 2n),   1 − e = (2n + 1)/(n² + 2n),

about 2/n: the train nearly cancels. tarsim solves it in Fractions (the tabular method,
``constructions/gears/tabular.py``, and the Willis reference,
``constructions/reference/willis.py``): exact. A float tool computes 1 − e from rounded
ratios, and loses the digits the cancellation amplifies, κ = e/|1 − e|:

- the **float formula** rounds N2/N3, N4/N5, their product and the difference: its error
  is at most (3κ + 1)·u (u = eps/2), the tolerance stated, with two units to spare;
- a **float linear solve** (numpy) of the same Willis equations tarsim solves exactly is
  backward stable: its error is at most a few u·cond(A) of the speeds' size, here over the
  small output speed, the tolerance stated (8 u · cond₂(A) · ‖ω‖/|ω5|).
"""

from __future__ import annotations

import math
from fractions import Fraction
from pathlib import Path

import numpy as np

from tarsim.constructions.gears.tabular import tabulate
from tarsim.constructions.gears.train import Gear, GearTrain, Mesh
from tarsim.constructions.reference.willis import willis_speeds

from .chapter_rows import EPS, ChapterStudy, Row, relative
from .svgplot import Curve, write_plot
from .timing import median_time

__all__ = ["reverted_train", "exact_value", "float_formula", "float_willis", "gear_study"]

SPEED = Fraction(100)
"""The arm's speed (rpm)."""


def reverted_train(n: int) -> GearTrain:
    """The reverted train of teeth n + 1, n, n − 1, n + 2, its arm at 100 rpm, sun 2 fixed."""
    return GearTrain(
        gears=(Gear(2, n + 1, name="fixed sun"), Gear(3, n, carrier=6, name="planet"),
               Gear(4, n - 1, carrier=6, name="planet"), Gear(5, n + 2, name="output sun")),
        meshes=(Mesh(2, 3), Mesh(4, 5)), shafts=((3, 4),), arm=6, fixed=2, input_member=6,
        input_speed=SPEED, name=f"reverted train, n = {n}")


def exact_value(n: int) -> Fraction:
    """ω5/ω6 in closed form: (2n + 1)/(n² + 2n)."""
    return Fraction(2 * n + 1, n * n + 2 * n)


def float_formula(train: GearTrain) -> float:
    """ω5 by the tabular method in floats: ω6·(1 − (N2/N3)·(N4/N5))."""
    n2, n3, n4, n5 = (train.gear(k).teeth for k in (2, 3, 4, 5))
    return float(train.input_speed) * (1.0 - (n2 / n3) * (n4 / n5))


def _willis_matrix(train: GearTrain) -> tuple[np.ndarray, np.ndarray, list[int]]:
    """The Willis equations of the reverted train as floats: one per mesh (relative to the
    arm), the shaft, the fixed sun and the input."""
    members = [2, 3, 4, 5, 6]
    col = {m: i for i, m in enumerate(members)}
    rows, rhs = [], []
    for mesh in train.meshes:
        a, b = train.gear(mesh.a).teeth, train.gear(mesh.b).teeth
        row = [0.0] * 5
        row[col[mesh.a]] += a
        row[col[mesh.b]] += b
        row[col[6]] -= a + b
        rows.append(row)
        rhs.append(0.0)
    rows.append([0.0, 1.0, -1.0, 0.0, 0.0])
    rhs.append(0.0)
    rows.append([1.0, 0.0, 0.0, 0.0, 0.0])
    rhs.append(0.0)
    rows.append([0.0, 0.0, 0.0, 0.0, 1.0])
    rhs.append(float(train.input_speed))
    return np.array(rows), np.array(rhs), members


def float_willis(train: GearTrain) -> float:
    """ω5 by a float linear solve of the Willis equations (what a float tool does)."""
    a, b, members = _willis_matrix(train)
    return float(np.linalg.solve(a, b)[members.index(5)])


def gear_study(out: Path, *, quick: bool = False) -> ChapterStudy:
    """Rows for n from 30 to 10⁶ (train values 1/15 to 2e-6): each way's error against the
    exact Fraction and its median time, with a plot of error against κ."""
    ns = (30, 300, 3000, 10 ** 5) if quick else (30, 100, 300, 600, 1000, 3000, 10 ** 4,
                                                 10 ** 5, 10 ** 6)
    repeat = 20 if quick else 200
    rows, formula_pts, solve_pts = [], [], []
    for n in ns:
        train = reverted_train(n)
        exact = exact_value(n) * SPEED
        table = tabulate(train).speeds[5]
        willis = willis_speeds(train)[5]
        e = Fraction(n * n - 1, n * n + 2 * n)
        kappa = float(e / (1 - e))
        label = f"n = {n} (ω5/ω6 = {float(exact / SPEED):.2g})"
        t_tab = median_time(lambda t=train: tabulate(t), repeat)
        t_wil = median_time(lambda t=train: willis_speeds(t), repeat)
        for number, value, t in (("ω5, tabular method (Fractions)", table, t_tab),
                                 ("ω5, Willis reference (Fractions)", willis, t_wil)):
            rows.append(Row(label, number, kappa, 0.0 if value == exact
                            else relative(float(value), exact), 0.0, t,
                            "exact: the closed form" if value == exact
                            else "**not the closed form**"))
        got = float_formula(train)
        err = relative(got, exact)
        t_f = median_time(lambda t=train: float_formula(t), repeat)
        rows.append(Row(label, "ω5, float formula", kappa, err, (3 * kappa + 3) * EPS / 2,
                        t_f, f"{max(0.0, -_log10(err)):.1f} digits kept"))
        formula_pts.append((kappa, max(err, 1e-17)))
        a, _, _ = _willis_matrix(train)
        got = float_willis(train)
        err = relative(got, exact)
        x = np.linalg.solve(*_willis_matrix(train)[:2])
        tol = 8 * (EPS / 2) * float(np.linalg.cond(a)) * float(np.linalg.norm(x)) / abs(got)
        t_s = median_time(lambda t=train: float_willis(t), repeat)
        rows.append(Row(label, "ω5, float linear solve (numpy)", kappa, err, tol, t_s,
                        f"cond₂(A) = {np.linalg.cond(a):.1e}"))
        solve_pts.append((kappa, max(err, 1e-17)))
    bound = tuple((k, (3 * k + 3) * EPS / 2) for k, _ in formula_pts)
    path = write_plot(out / "gears-cancelling.svg",
                      "Nearly cancelling reverted trains: floats against exact Fractions",
                      "cancellation κ = e/(1 − e) (train value 1 − e)",
                      "relative error of ω5 against the exact Fraction",
                      [Curve("float formula ω6(1 − N2N4/N3N5)", tuple(formula_pts)),
                       Curve("float linear solve of the Willis equations", tuple(solve_pts)),
                       Curve("bound (3κ + 3)·u of the formula", bound)],
                      note="tarsim's tabular method and Willis reference, in Fractions, are "
                           "exact at every n (not drawn: error 0).")
    worst = max((r for r in rows if "formula" in r.number), key=lambda r: r.conditioning)
    at300 = next(r for r in rows if r.number.endswith("float formula")
                 and r.case.startswith(f"n = {300}"))
    frac = next(r for r in rows if r.number.startswith("ω5, tabular") and r.case == at300.case)
    flt = at300.time_us
    head = (f"exact at every n in Fractions (the tabular method and the Willis reference); the "
            f"float formula keeps {-_log10(max(at300.error, 1e-17)):.0f} digits at a train "
            f"value of {float(exact_value(300)):.2g} (n = 300) and "
            f"{-_log10(max(worst.error, 1e-17)):.0f} at "
            f"κ = {worst.conditioning:.0e}; exactness costs {frac.time_us:.0f} µs for the "
            f"tabular method against {flt:.1f} µs for the float formula")
    return ChapterStudy("Gear trains", "the exact Fraction (2n + 1)/(n² + 2n)·ω6",
                        "κ = e/(1 − e)", head, tuple(rows), path)


def _log10(x: float) -> float:
    return math.log10(x) if x > 0 else -17.0
