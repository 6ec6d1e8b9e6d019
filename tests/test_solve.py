"""Tests for `tarsim solve`: the exercise's [ask] table, results.json, steps.md, the figures.

Numbers are checked against the independent analytic solver (and the seeds' printed
values); the output folder is checked as a new user would see it.
"""

import json
import math
import re

import pytest
from click.testing import CliRunner

from tarsim.constructions.reference import solver
from tarsim.exercises.cli import cli
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution import solve_exercise
from tests.common import four_bar_toml

ASK = '\n[ask]\nfind = {find}\nmethods = {methods}\n'


def exercise_text(find='["centres", "omega3", "omega4", "V_B"]',
                  methods='["radius-rotation", "parallel-line", "components"]', **kw):
    text = four_bar_toml(**kw).replace("[input]\nlink = 2\n", "[input]\nlink = 2\nomega = 10\n")
    return text + ASK.format(find=find, methods=methods)


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args], prog_name="tarsim",
                              catch_exceptions=False)


# ----- the numbers ----------------------------------------------------------------------

@pytest.mark.parametrize("angle", [0, 30, 60, 135, 200, 290])
def test_every_asked_quantity_matches_the_analytic_solver(angle):
    ex = parse_exercise(exercise_text(angle=angle), "fb.toml", "fb")
    sol = solve_exercise(ex)
    kin = solver.solve(ex.mechanism)
    assert len([q for q in sol.quantities if q.startswith("I")]) == 6
    assert sol.failures == []
    for n in (3, 4):
        assert sol.quantities[f"omega{n}"].value["value"] == pytest.approx(
            kin.omegas[n], rel=1e-9, abs=1e-12)
    v = sol.quantities["V_B"]
    assert set(v.alternatives) == {"parallel-line", "components"}
    ref = solver.point_velocity(kin, ex.mechanism, 4, "B")
    for q in [v, *v.alternatives.values()]:
        assert q.value["vector"] == pytest.approx(list(ref), rel=1e-9, abs=1e-12)


def test_peers_benchmark_omegas():
    # peers.md §4: O2A 100, AB 250, O4B 200, O2O4 300 mm, θ2 = 60°, ω2 = 10 rad/s.
    ex = parse_exercise(exercise_text(find='["omega3", "omega4"]'), "fb.toml", "fb")
    q = solve_exercise(ex).quantities
    assert q["omega3"].value["value"] == pytest.approx(-2.578464796446, abs=5e-12)
    assert q["omega4"].value["value"] == pytest.approx(2.915957761501, abs=5e-12)


def test_crank_shaper_ram_at_t_2_34_s():
    # 003 §2: at t = 2.34 s (θ2 = 90° − 2.34 rad, ω2 = 1 rad/s cw) ṗ = −189.192 mm/s and
    # ω4 = 0.19212, printed to 6 and 5 digits.
    from tarsim.exercises.catalog import resolve
    theta = math.degrees(math.pi / 2 - 2.34)
    text = resolve("crank-shaper").read_text(encoding="utf-8").replace("angle = 90",
                                                                       f"angle = {theta!r}")
    sol = solve_exercise(parse_exercise(text, "cs.toml", "crank-shaper"))
    assert sol.failures == []
    assert sol.quantities["omega4"].value["value"] == pytest.approx(0.19212, abs=5e-6)
    assert sol.quantities["V_B"].value["vector"][0] == pytest.approx(-0.189192, abs=5e-7)
    assert len([q for q in sol.quantities if q.startswith("I")]) == 10


def test_dead_centre_slider_velocity_is_zero_and_checked():
    # 000-part1 §3.8 Q1: at dead centre I13 ≡ I34 and I24 ≡ I12; the slider is at rest.
    from tarsim.exercises.catalog import resolve
    text = (resolve("offset-slider-crank").read_text(encoding="utf-8")
            .replace("offset = 20", "offset = 0").replace("angle = 45", "angle = 0"))
    sol = solve_exercise(parse_exercise(text, "sc.toml", "sc"))
    assert sol.failures == []
    assert sol.quantities["V_B"].value["value"] == pytest.approx(0.0, abs=1e-15)
    p = {k: q.value["point"] for k, q in sol.quantities.items() if "point" in q.value}
    assert p["I13"] == pytest.approx(p["I34"], abs=1e-15)
    assert p["I24"] == pytest.approx(p["I12"], abs=1e-15)


# ----- the [ask] table ----------------------------------------------------------------------

@pytest.mark.parametrize("edit, line, words", [
    ('find = ["centres", "omega3", "omega4", "V_B"]', 'find = ["omega5"]', "cannot find 'omega5'"),
    ('find = ["centres", "omega3", "omega4", "V_B"]', 'find = ["V_Q"]', "cannot find 'V_Q'"),
    ('find = ["centres", "omega3", "omega4", "V_B"]', 'find = ["centers"]',
     "did you mean 'centres'"),
    ('methods = ["radius-rotation", "parallel-line", "components"]', 'methods = ["radius"]',
     "did you mean 'radius-rotation'"),
    ('find = ["centres", "omega3", "omega4", "V_B"]', 'fnd = ["I13"]', "did you mean 'find'"),
])
def test_ask_errors_name_the_line_and_the_closest_name(tmp_path, edit, line, words):
    text = exercise_text().replace(edit, line)
    path = tmp_path / "ex.toml"
    path.write_text(text, encoding="utf-8")
    result = run("solve", path, "-o", tmp_path / "out", "--no-pdf")
    assert result.exit_code == 1
    lineno = text.splitlines().index(line) + 1
    assert result.stderr.startswith(f"Error: {path}:{lineno}")
    assert words in result.stderr and result.stderr.count("\n") == 1
    assert not (tmp_path / "out").exists()


def test_an_impossible_position_writes_nothing(tmp_path):
    path = tmp_path / "ex.toml"
    path.write_text(exercise_text(coupler=150, angle=180), encoding="utf-8")
    result = run("solve", path, "-o", tmp_path / "out")
    assert result.exit_code == 1 and "cannot reach" in result.stderr
    assert not (tmp_path / "out").exists()


# ----- the files -------------------------------------------------------------------------------

@pytest.mark.slow
def test_solve_writes_figures_steps_and_results(tmp_path):
    path = tmp_path / "ex.toml"
    path.write_text(exercise_text(), encoding="utf-8")
    out = tmp_path / "out"
    result = run("solve", path, "-o", out, "--no-pdf")
    assert result.exit_code == 0, result.output
    names = sorted(p.name for p in out.iterdir())
    assert names == sorted(["centres.svg", "circle-diagram.svg", "V_B-radius-rotation.svg",
                            "V_B-parallel-line.svg", "V_B-components.svg", "steps.md",
                            "results.json", "solution.svg", ".tarsim-manifest.json"])
    doc = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert doc["exercise"] == "ex" and doc["quantities"] == {}
    (pos,) = doc["positions"]
    assert pos["input"]["link"] == 2 and pos["input"]["angle_deg"] == 60
    q = pos["quantities"]
    assert set(q) == {"I12", "I13", "I14", "I23", "I24", "I34", "omega3", "omega4", "V_B"}
    for name, entry in q.items():
        assert {"reference", "rel_error", "method", "passed"} <= set(entry), name
        assert entry["passed"] and entry["rel_error"] <= 1e-9
    assert set(q["V_B"]) >= {"value", "vector"}
    assert set(q["V_B"]["by_method"]) == {"parallel-line", "components"}
    assert q["I13"]["point"] == pytest.approx(q["I13"]["reference"]["point"], abs=1e-12)


def solve_v_b_by_radius_rotation(tmp_path):
    """Run `tarsim solve` on a four-bar asking V_B by radius rotation; return the folder."""
    path = tmp_path / "ex.toml"
    path.write_text(exercise_text(find='["V_B"]', methods='["radius-rotation"]'),
                    encoding="utf-8")
    out = tmp_path / "out"
    assert run("solve", path, "-o", out, "--no-pdf").exit_code == 0
    return out


def test_steps_md_numbers_match_the_figure(tmp_path):
    out = solve_v_b_by_radius_rotation(tmp_path)
    steps = (out / "steps.md").read_text(encoding="utf-8")
    section = steps.split("## V_B by radius rotation", 1)[1].split("## ", 1)[0]
    numbers = [int(n) for n in re.findall(r"^(\d+)\. ", section, re.M)]
    assert numbers == list(range(1, len(numbers) + 1)) and numbers
    svg = (out / "V_B-radius-rotation.svg").read_text(encoding="utf-8")
    drawn = {int(n) for n in re.findall(r">\(?(\d+)\)?</text>", svg)}
    # The pins' centres and the Kennedy lines carry no badge, their names being enough;
    # from the centre Kennedy's lines meet at, every step is circled, the answer's last.
    met = next(n for n, line in zip(numbers, re.findall(r"^\d+\. (.*)$", section, re.M))
               if "is where the two lines meet" in line)
    assert set(numbers[numbers.index(met):]) <= drawn


def test_asking_for_one_velocity_draws_no_unused_centres(tmp_path):
    out = solve_v_b_by_radius_rotation(tmp_path)
    assert sorted(p.name for p in out.iterdir()) == [".tarsim-manifest.json",
                                                     "V_B-radius-rotation.svg", "results.json",
                                                     "solution.svg", "steps.md"]
    svg = (out / "V_B-radius-rotation.svg").read_text(encoding="utf-8")
    # B is taken on the coupler (Hinkle Fig 5.1): the transfer point is the pin I23, the
    # coupler turns about I13. I24 plays no part, so neither it nor its lines are drawn.
    assert "I₁₃" in svg and "₂₄" not in svg
    steps = (out / "steps.md").read_text(encoding="utf-8")
    assert "I24" not in steps and "I13 lies on the line" in steps


def test_bundled_examples_solve_and_check():
    from tarsim.exercises.catalog import bundled
    from tarsim.exercises.linkages.exercise_file import load_exercise
    for name, path in bundled().items():
        sol = solve_exercise(load_exercise(path, name))
        assert sol.failures == [], name
        assert all(math.isfinite(q.rel_error) for q in sol.quantities.values())


@pytest.mark.slow
def test_a_leftward_vector_reads_180_degrees_in_both_columns():
    # Whitworth's ram acceleration points left; the analytic one has a y of rounding
    # noise below zero, which atan2 would give as −180°.
    from tarsim.exercises.catalog import resolve
    from tarsim.exercises.linkages.exercise_file import load_exercise
    from tarsim.exercises.linkages.solution_files import solve_to_files
    _, files = solve_to_files(load_exercise(resolve("whitworth")))
    row = next(r for r in files["steps.md"].splitlines() if r.startswith("| A_C |"))
    assert row.count("211.482 mm/s² at 180°") == 2
    assert "−180°" not in files["steps.md"] and "-180°" not in files["steps.md"]


@pytest.mark.slow
def test_a_failed_check_exits_3_and_still_writes_the_files(tmp_path, monkeypatch):
    # A reference that disagrees with every drawn velocity: the check must say so.
    from tarsim.constructions.reference import solver
    monkeypatch.setattr(solver, "point_velocity", lambda *args: (9.0, 9.0))
    path = tmp_path / "ex.toml"
    path.write_text(exercise_text(), encoding="utf-8")
    result = run("solve", path, "-o", tmp_path / "out", "--no-pdf")
    assert result.exit_code == 3
    assert result.stderr == ("Error: V_B disagrees with the analytic solution beyond "
                             "tolerance\n")
    assert "check FAILED" in result.stdout
    assert all(line.startswith("V_B = ") for line in result.stdout.splitlines()
               if "FAILED" in line)
    assert (tmp_path / "out" / "results.json").exists()


@pytest.mark.slow
def test_a_solution_is_byte_identical_across_hash_seeds_and_folders(tmp_path):
    """Every file of a solve, steps.md and results.json included, is the same whatever the
    hash seed (set and dict order) and wherever it is written."""
    import os
    import subprocess
    import sys

    outputs = []
    for seed in ("1", "2"):
        out = tmp_path / f"seed-{seed}" / "solution"
        subprocess.run([sys.executable, "-m", "tarsim", "solve", "inverted-slider-crank", "-o",
                        str(out), "--no-pdf"], check=True, capture_output=True, timeout=300,
                       cwd=tmp_path, env={**os.environ, "PYTHONHASHSEED": seed})
        outputs.append({p.name: p.read_bytes() for p in sorted(out.iterdir())})
    first, second = outputs
    assert {"steps.md", "results.json", "worked.svg"} <= set(first)
    assert first == second


@pytest.mark.slow
def test_solution_svg_sets_each_figure_as_written_where_stacking_them_would():
    """solution.svg moves each figure's own SVG into place rather than drawing it again;
    it must print as the figures stacked and written afresh do (stack_pages): the same
    sheet, the same ink. Coordinates are written to 0.001 mm either way, a 0.002 px
    shift at 2 px/mm, so no pixel may differ by more than a faint edge (32 of 255)."""
    cairosvg = pytest.importorskip("cairosvg")
    import io

    import numpy as np
    from PIL import Image

    from tarsim import load, solve
    from tarsim.graphics.figure import stack_pages
    from tarsim.graphics.svg import to_svg

    worked = solve(load("hinkle-slider-crank"))
    moved = worked.files()["solution.svg"]
    drawn = to_svg(stack_pages([f.figure for f in worked.pages]))
    root = re.compile(r'<svg [^>]*height="([\d.]+)mm"[^>]*viewBox="([^"]+)"[^>]*width="([\d.]+)mm"')
    assert root.match(moved).groups() == root.match(drawn).groups()
    assert moved.count("<text") == drawn.count("<text") == sum(f.svg.count("<text")
                                                                 for f in worked.pages)

    def grey(svg: str):
        png = cairosvg.svg2png(bytestring=svg.encode(), dpi=50.8)     # 2 px/mm
        return np.asarray(Image.open(io.BytesIO(png)).convert("L"), dtype=int)

    a, b = grey(moved), grey(drawn)
    assert a.shape == b.shape
    assert (a < 128).sum() > 0.005 * a.size          # there is ink to compare
    assert np.abs(a - b).max() <= 32
