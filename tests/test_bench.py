"""`tarsim bench`: the mpmath reference is right, the suite holds, the report is written.

The 50-digit reference (benchmarks/bench/mpref.py) is tested on its own first: against
cases with exact answers (a parallelogram four-bar, an in-line slider-crank at 90°,
the closed-form limit positions of an offset slider-crank), then against the float64
solver where both are well conditioned. Timings are never asserted.
"""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

mpmath = pytest.importorskip("mpmath")

from benchmarks.bench.mpref import mp_limits, mp_solve  # noqa: E402
from benchmarks.bench.readings import run_method  # noqa: E402
from benchmarks.bench.stiff import run_case, stiff_cases  # noqa: E402
from tarsim.constructions.model import Drive, Link, Mechanism  # noqa: E402
from tarsim.constructions.reference import solver  # noqa: E402
from tarsim.exercises import cli as cli_module  # noqa: E402
from tarsim.exercises.catalog import load  # noqa: E402
from tests.common import offset_slider_crank  # noqa: E402

EPS = sys.float_info.epsilon


def _parallelogram(theta):
    return Mechanism((Link(1, (("O2", (0, 0)), ("O4", (4, 0)))),
                      Link(2, (("O2", (0, 0)), ("A", (3, 0)))),
                      Link(3, (("A", (0, 0)), ("B", (4, 0)))),
                      Link(4, (("O4", (0, 0)), ("B", (3, 0))))),
                     Drive(2, theta, omega=2.0, alpha=0.5), branches={"B": "left"})


def test_mp_reference_exact_on_a_parallelogram():
    # At any θ2 the coupler translates: B = A + (4, 0), ω3 = α3 = 0, ω4 = ω2, α4 = α2,
    # every coupler point has the crank pin's acceleration, and I13 is at infinity.
    m = _parallelogram(1.0)
    kin = mp_solve(m, solver.solve_positions(m))
    with mpmath.workdps(120):
        c, s = mpmath.cos(mpmath.mpf(1.0)), mpmath.sin(mpmath.mpf(1.0))
        bx, by = kin.points["B"]
        assert abs(bx - (4 + 3 * c)) < 1e-100 and abs(by - 3 * s) < 1e-100
        assert abs(kin.omegas[3]) < 1e-50 and abs(kin.omegas[4] - 2) < 1e-50
        assert abs(kin.alphas[3]) < 1e-50 and abs(kin.alphas[4] - 0.5) < 1e-50
        ax, ay = kin.acceleration("B")             # −ω² r + α × r on the crank circle
        assert abs(ax - (-4 * 3 * c - 0.5 * 3 * s)) < 1e-50
        assert abs(ay - (-4 * 3 * s + 0.5 * 3 * c)) < 1e-50
        centre = kin.centre(1, 3)
        assert centre.direction is not None or mpmath.hypot(*centre.point) > 1e40


def test_mp_reference_matches_the_slider_crank_closed_form():
    # In line: x_C = R cos θ + √(L² − R² sin² θ), φ3 = −asin(R sin θ / L),
    # ω3 = −ω R cos θ / (L cos φ3), V_C = ω dx_C/dθ.
    theta, r, l_, w = 1.0, 0.3, 0.7, 2.0
    m = offset_slider_crank(theta, crank=r, rod=l_, offset=0.0, omega2=w)
    kin = mp_solve(m, solver.solve_positions(m))
    with mpmath.workdps(120):
        t, r, l_ = mpmath.mpf(theta), mpmath.mpf(r), mpmath.mpf(l_)
        root = mpmath.sqrt(l_ ** 2 - (r * mpmath.sin(t)) ** 2)
        assert abs(kin.points["C"][0] - (r * mpmath.cos(t) + root)) < 1e-100
        phi3 = -mpmath.asin(r * mpmath.sin(t) / l_)
        assert abs(kin.omegas[3] - (-w * r * mpmath.cos(t) / (l_ * mpmath.cos(phi3)))) < 1e-50
        dx = -r * mpmath.sin(t) - r * r * mpmath.sin(t) * mpmath.cos(t) / root
        vx, vy = kin.velocity("C")
        assert abs(vx - w * dx) < 1e-50 and abs(vy) < 1e-50


@pytest.mark.parametrize("name", ["four-bar", "offset-slider-crank", "inverted-slider-crank",
                                  "crank-shaper"])
def test_mp_reference_agrees_with_the_float64_solver(name):
    # Well-conditioned stated positions: the two agree to rounding (1e-14 of each scale).
    m = load(name).mechanism
    kin = solver.solve(m)
    mk = mp_solve(m, kin.points)
    size = max(math.dist(p, q) for p in kin.points.values() for q in kin.points.values())
    v_in, a_in = m.input_speed, m.input_acceleration
    for n in m.point_names:
        assert math.dist(kin.points[n], tuple(map(float, mk.points[n]))) <= 1e-14 * size
        assert math.dist(kin.velocities[n], tuple(map(float, mk.velocity(n)))) <= 1e-14 * v_in
        assert (math.dist(kin.accelerations[n], tuple(map(float, mk.acceleration(n))))
                <= 1e-14 * a_in)
    for k in kin.omegas:
        if k != 1:
            assert abs(kin.omegas[k] - float(mk.omegas[k])) <= 1e-14 * abs(m.drive.omega)


@pytest.mark.slow
def test_mp_limits_match_the_offset_slider_crank_closed_form():
    # Crank and rod in line: extended at θ = asin(e / (L + R)), folded at
    # π + asin(e / (L − R)), C at √((L ± R)² − e²) along the guide: the stroke is their
    # difference (63.34 cm, notes 000-part2 §3.3).
    m = offset_slider_crank(math.radians(45), omega2=1.0)
    guesses = (math.asin(0.2 / 1.0) + 1e-6, math.pi + math.asin(0.2 / 0.4) - 1e-6)
    starts = [solver.solve_positions(m.with_drive(Drive(2, t, 1.0))) for t in guesses]
    lim = mp_limits(m, guesses, starts, point="C")
    with mpmath.workdps(60):
        r, l_, e = mpmath.mpf(0.3), mpmath.mpf(0.7), mpmath.mpf(0.2)
        ext, fold = mpmath.asin(e / (l_ + r)), mpmath.pi + mpmath.asin(e / (l_ - r))
        assert abs(lim.crank_angles[0] - ext) < 1e-45
        assert abs(lim.crank_angles[1] - fold) < 1e-45
        stroke = mpmath.sqrt((l_ + r) ** 2 - e ** 2) - mpmath.sqrt((l_ - r) ** 2 - e ** 2)
        assert abs(lim.stroke - stroke) < 1e-45
        turn = fold - ext
        assert abs(lim.time_ratio - max(turn, 2 * mpmath.pi - turn)
                   / min(turn, 2 * mpmath.pi - turn)) < 1e-45


def test_the_known_toggle_case_holds_the_construction_and_shows_the_reference():
    # position_accuracy.py's toggle at δ = 1e-8 mm: I13 has conditioning ~6.7e-11; the
    # construction stays within its bound, and the float64 reference's slip is reported.
    case = next(c for c in stiff_cases(quick=True) if c.label.startswith("AB = 200 + 1e-08"))
    rows = run_case(case)
    assert [r.method for r in rows] == ["position by compass", "centres by Kennedy",
                                        "velocity polygon"]
    assert all(r.within and r.err_mp <= r.bound for r in rows)
    # The float64 reference is measured on the same numbers, and is never the weaker: its
    # I34, the pin B, was 3.3e-6 off when taken from the velocity fields.
    centres = rows[1]
    assert centres.key[0] == "I" and centres.err_float <= centres.bound
    kennedy = run_method("centres by Kennedy", case.mechanism, 1)
    i13 = next(r for r in kennedy.readings if r.key == ("I", 1, 3))
    assert 1e-11 < i13.conditioning < 1e-10                       # ~6.7e-11


@pytest.mark.slow
@pytest.mark.parametrize("case", stiff_cases(quick=True), ids=lambda c: c.label)
def test_each_stiff_case_is_within_its_bound_or_refused_as_expected(case):
    for row in run_case(case):
        if case.refusal is not None:
            assert row.refused is not None and row.refused.startswith(case.refusal)
            assert "\n" not in row.refused
        else:
            assert row.refused is None, row.refused
            assert row.err_mp <= row.bound, (row.method, row.key, row.err_mp, row.bound)


def test_bench_outside_a_checkout_says_so_in_one_line(monkeypatch, tmp_path):
    monkeypatch.setattr(cli_module, "__file__", str(tmp_path / "tarsim" / "exercises" / "cli.py"))
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(cli_module.cli, ["bench", "--quick", "-o", str(tmp_path)])
    assert result.exit_code == 1
    assert result.output.startswith("Error: tarsim bench runs from a source checkout")
    assert result.output.count("\n") == 1


_NUMBER = r"(—|0|[0-9.]+e[+-][0-9]+)"


@pytest.mark.slow
def test_bench_quick_writes_the_report_and_its_numbers_hold(tmp_path):
    result = CliRunner().invoke(cli_module.cli, ["bench", "--quick", "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    text = (tmp_path / "report.md").read_text(encoding="utf-8")
    # Every linked plot is written, and small.
    links = re.findall(r"!\[[^]]*\]\((report/[^)]+\.svg)\)", text)
    assert len(links) == 6 + 6          # the linkages' and one per chapter (two the flywheel's)
    for link in links:
        svg = tmp_path / link
        assert svg.read_text(encoding="utf-8").startswith("<?xml")
        assert 1000 < svg.stat().st_size < 60_000
    # The method table: eight methods, each largest error against mpmath within
    # 10 eps over the worst conditioning of what it read.
    rows = re.findall(rf"^\| ([^|]+) \| (\d+) \((\d+)\) \| (\d+) \| {_NUMBER} \| {_NUMBER} \| "
                      rf"{_NUMBER} \| {_NUMBER} \| {_NUMBER} \| ([0-9.e-]+) \| ([0-9.e-]+) \| "
                      r"(\d+) \|$", text, re.M)
    assert [r[0] for r in rows] == [
        "position by compass", "centres by Kennedy", "radius rotation", "parallel lines",
        "components", "velocity polygon", "acceleration polygon (with Coriolis)",
        "limit positions"]
    for method, count, _, _, max_f, _, max_mp, _, ref, cond, _, _ in rows:
        assert int(count) > 0, method
        bound = 10 * EPS / float(cond)
        assert float(max_mp) <= bound and float(max_f) <= bound, method
        assert float(ref) <= 1e-14, method              # the float64 solver itself
    # The stiff suite: every row within, the known toggle among them.
    stiff = [line for line in text.splitlines() if re.match(
        r"^\| (toggle|Kennedy angle|at infinity|length ratio|ω range|dead centre|Coriolis)",
        line)]
    assert len(stiff) >= 30
    assert all(line.split(" | ")[8] == "yes" for line in stiff)
    assert any("AB = 200 + 1e-08 mm" in line for line in stiff)
    # Every other chapter: its heading and rows, each row's eight cells, each within.
    part = text[text.index("## 4. Every chapter"):]
    assert [h for h in re.findall(r"^### (.+)$", part, re.M)] == [
        "Gear trains", "Cams", "Force polygons", "Balancing", "The flywheel",
        "The flywheel's inputs (formula, table, areas)"]
    cells = [line.split(" | ") for line in part.splitlines()
             if line.startswith("| ") and not line.startswith("| case")]
    assert len(cells) >= 40 and all(len(c) == 8 for c in cells)
    assert all(c[5] == "yes" for c in cells)


@pytest.mark.parametrize("name", ["parallelogram-four-bar", "rolling-wheel",
                                  "wheel-driven-slider", "wheel-round-circle"])
def test_the_full_bench_takes_a_reference_it_lacks_as_undefined(name):
    """The full benchmark once stopped with a traceback on these: a parallelogram's limit
    positions sit on its change points, where the references refuse, and a wheel's contact
    point P is a reading no reference names. Such a reading is kept, its error undefined
    (nan), as a centre of two links that move together is; every other one is measured."""
    from benchmarks.bench.methods import cases, method_table

    rows = method_table([c for c in cases(quick=False)
                         if c.label.startswith(name + " θ=") and c.stated], repeat=1)
    measured = [e for row in rows for e in row.vs_float if not math.isnan(e)]
    assert measured and max(measured) < 1e-12
    undefined = sum(math.isnan(e) for row in rows for e in row.vs_float)
    assert undefined >= 1
