"""`tarsim bench`'s rows for the flywheel's inputs (benchmarks/bench/flywheel_input_rows.py):
each closed form checked by hand, then tarsim's reading of the file as a user writes it
held to it at the tolerance the row states. Timings are never asserted."""

from __future__ import annotations

import math
import sys
from fractions import Fraction
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

mpmath = pytest.importorskip("mpmath")

from benchmarks.bench import flywheel_input_rows as rows  # noqa: E402

U = sys.float_info.epsilon / 2                      # the unit roundoff


def test_the_single_cylinder_tables_energy_is_its_triangle_above_the_mean():
    # T rises to 6000 N·m at 90°, falls to 0 at 180° and to −1000 at 270°: the mean is
    # (540000 − 90000)/360 = 1250 N·m, met at 18.75° and 161.25°; the triangle above it,
    # 142.5° wide and 4750 N·m high, holds ΔE = 338437.5 N·m·° = 338437.5·π/180 J.
    pts = rows.TABLES[0][1]
    with mpmath.workdps(40):
        want = mpmath.mpf("338437.5") * mpmath.pi / 180
        assert abs(rows.exact_table(pts, 360) - want) < mpmath.mpf(10) ** -30


def test_the_areas_range_is_the_running_sums():
    # 295, −685, 40, −340, 960 (mm²) run to 295, −390, −350, −690, 270: the range 985 mm²
    # at 5 N·m × 1° a mm² is 985·5·π/180 J, exact in Fractions of the areas as read.
    areas = [a * 5 * math.pi / 180 for a in rows.AREAS[0][1]]
    a = list(map(Fraction, areas))
    assert rows.exact_areas(areas) == a[0] - (a[0] + a[1] + a[2] + a[3])   # 295 − (−690)
    assert float(rows.exact_areas(areas)) == pytest.approx(985 * 5 * math.pi / 180, rel=8 * U)


def test_every_input_row_is_within_its_stated_bound_and_a_formulas_bound_is_a_check(tmp_path):
    study = rows.flywheel_input_study(tmp_path, quick=True)
    assert study.rows and all(r.within for r in study.rows), \
        [r for r in study.rows if not r.within]
    # a formula's error at a step is the step's square's, not rounding: its bound binds
    # within a factor of 100 (the interpolant's bound is some 10 to 30 times the error)
    for r in study.rows:
        if r.case.startswith("formula"):
            assert r.error > r.tolerance / 100, r
    assert (tmp_path / "flywheel-inputs.svg").exists()
