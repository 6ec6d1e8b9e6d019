"""`tarsim solve` with polygons: accelerations, Coriolis, several positions, the worked page.

Numbers are checked against the independent analytic solver and the course project's
own values (seed 003 §7); the output folder is checked as a new user would see it.
"""

import json
import math
import re

import pytest
from click.testing import CliRunner

from tarsim.constructions.reference import solver
from tarsim.exercises.cli import cli
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution import solve_positions
from tarsim.constructions.narration import narrate
from tests.common import four_bar_toml

T = 2.34  # s: the course project's hand-solved instant, θ2 = 90° − 2.34 rad


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args], prog_name="tarsim",
                              catch_exceptions=False)


def four_bar_exercise(find, *, methods='["polygon"]', alpha=None, at=None):
    text = four_bar_toml(angle=60).replace(
        "[input]\nlink = 2\n",
        "[input]\nlink = 2\nomega = 10\n" + (f"alpha = {alpha}\n" if alpha is not None else ""))
    text += f"\n[ask]\nfind = {find}\nmethods = {methods}\n"
    if at:
        text += f"at = {at}\n"
    return parse_exercise(text, "fb.toml", "fb")


@pytest.fixture(scope="module")
def shaper(solved):
    return solved("crank-shaper").positions


# ----- the course project -------------------------------------------------------------------

def test_crank_shaper_is_solved_at_both_positions(shaper):
    assert [s.position.label for s in shaper] == ["θ2 = 90°", "t = 2.34 s (θ2 = −44.0721°)"]
    assert shaper[1].exercise.mechanism.drive.angle == pytest.approx(math.pi / 2 - T, abs=1e-15)
    for s in shaper:
        assert s.failures == []


def test_crank_shaper_at_t_2_34_s_reproduces_the_project_values(shaper):
    q = shaper[1].quantities
    # Seed 003 §7, "my computation" (|ω2| = 1 rad/s, ω2 cw, α2 = 0), to its printed digits.
    assert q["omega4"].value["value"] == pytest.approx(0.19212, abs=5e-6)
    assert q["V_B"].value["vector"][0] == pytest.approx(-0.189192, abs=5e-7)
    assert q["alpha4"].value["value"] == pytest.approx(0.56939, abs=5e-6)
    assert q["A_B"].value["vector"][0] == pytest.approx(-0.535635, abs=5e-7)
    assert q["A_cor_A"].value["value"] == pytest.approx(0.062665, abs=5e-7)
    assert q["A_cor_B"].value["value"] == pytest.approx(0.023711, abs=5e-7)


def test_crank_shaper_hand_solution_was_wrong_where_tarsim_is_right(shaper):
    # The project's hand polygon gave α4 = 0.276 rad/s² cw and a_p = 20.98 cm/s² to the right;
    # the construction gives α4 ccw and the ram decelerating to the left, as the analytic solver.
    q = shaper[1].quantities
    assert q["alpha4"].value["value"] > 0 and q["alpha4"].reference["value"] > 0
    assert abs(q["alpha4"].value["value"] - 0.276) / 0.56939 > 0.5
    assert q["A_B"].value["vector"][0] < 0


def test_crank_on_the_line_of_centres_has_no_coriolis(shaper):
    # θ2 = 90°: A is on O2O4, so neither A nor B slides at this instant (notes §2.11 (c)).
    q = shaper[0].quantities
    for p in "AB":
        assert q[f"A_cor_{p}"].value["value"] == pytest.approx(0.0, abs=1e-15)
        assert q[f"A_cor_{p}"].reference["value"] == pytest.approx(0.0, abs=1e-15)


def test_every_polygon_number_agrees_with_the_analytic_solver(shaper):
    for s in shaper:
        m, kin = s.exercise.mechanism, s.kinematics
        ap = s.acceleration_polygon
        for name, link in (("A", 2), ("A4", 4), ("B", 5), ("B4", 4)):
            point = name[0]
            ref = solver.point_acceleration(kin, m, link, point)
            assert ap.vector(name) == pytest.approx(ref, rel=1e-9, abs=1e-12)
        for n in (3, 4, 5):
            assert ap.rates[n] == pytest.approx(kin.alphas[n], rel=1e-9, abs=1e-12)


# ----- the exercise file ----------------------------------------------------------------------

def test_relative_velocity_and_acceleration_of_the_coupler():
    ex = four_bar_exercise('["V_B/A", "A_B/A", "alpha3", "alpha4", "omega3"]', alpha=5)
    s = solve_positions(ex)[0]
    m, kin = ex.mechanism, s.kinematics
    vb, va = (solver.point_velocity(kin, m, 3, p) for p in "BA")
    ab, aa = (solver.point_acceleration(kin, m, 3, p) for p in "BA")
    q = s.quantities
    assert q["V_B/A"].value["vector"] == pytest.approx([vb[0] - va[0], vb[1] - va[1]], rel=1e-9)
    assert q["A_B/A"].value["vector"] == pytest.approx([ab[0] - aa[0], ab[1] - aa[1]], rel=1e-9)
    assert q["omega3"].method == "velocity polygon"
    assert q["omega3"].value["value"] == pytest.approx(-2.578464796446, abs=5e-12)
    assert s.failures == []
    assert s.notes == []          # α2 given: nothing to say


def test_alpha_of_the_input_defaults_to_zero_and_says_so():
    s = solve_positions(four_bar_exercise('["alpha4"]'))[0]
    assert s.exercise.mechanism.drive.alpha == 0.0
    assert s.notes == ["α2 is not given, so it is taken as 0."]
    # peers.md four-bar, ω2 = 10 rad/s, α2 = 0: α4 = 49.967389320608.
    assert s.quantities["alpha4"].value["value"] == pytest.approx(49.967389320608, abs=5e-9)


def test_time_positions_follow_the_input_motion():
    ex = four_bar_exercise('["omega4"]', alpha=2, at="[{ time = 0.5 }, { angle = 120 }]")
    a, b = ex.positions
    # θ = θ0 + ω t + α t²/2, less the whole turn it has made (6.297 rad is 0.0140 rad).
    turned = math.radians(60) + 10 * 0.5 + 0.5 * 2 * 0.25
    assert turned > math.tau
    assert a.drive.angle == pytest.approx(turned - math.tau)
    assert a.drive.omega == pytest.approx(11.0)
    assert (a.slug, b.slug) == ("t-0.5s", "theta2-120")
    assert b.drive.angle == pytest.approx(math.radians(120))


@pytest.mark.parametrize("at, words", [
    ('"90"', "at must be a list of positions"),
    ("[{ angel = 90 }]", "gives one of angle, time, stroke"),
    ('[{ time = "soon" }]', "time in at must be a number"),
    ("[{ angle = 90 }, { angle = 90 }]", "the same position twice"),
])
def test_bad_positions_name_the_line(at, words):
    with pytest.raises(Exception) as e:
        four_bar_exercise('["omega4"]', at=at)
    assert words in str(e.value) and "fb.toml:" in str(e.value)


def test_unknown_acceleration_name_suggests_the_closest():
    with pytest.raises(Exception) as e:
        four_bar_exercise('["A_cor_B"]')
    assert "cannot find 'A_cor_B'" in str(e.value)


# ----- the files ----------------------------------------------------------------------------

@pytest.mark.slow
def test_solve_crank_shaper_writes_a_worked_page_per_position(tmp_path):
    out = tmp_path / "shaper"
    r = run("solve", "crank-shaper", "-o", out, "--no-pdf")
    assert r.exit_code == 0, r.output
    names = sorted(p.name for p in out.iterdir())
    assert "worked-theta2-90.svg" in names and "worked-t-2.34s.svg" in names
    doc = json.loads((out / "results.json").read_text())
    later = doc["positions"][1]
    assert later["position"] == "t = 2.34 s (θ2 = −44.0721°)"
    assert later["input"]["angle_deg"] == pytest.approx(math.degrees(math.pi / 2 - T))
    for key in ("A_B", "A_cor_A", "A_cor_B", "alpha4", "omega4", "V_B"):
        assert later["quantities"][key]["passed"], key
    assert later["quantities"]["A_cor_A"]["vector"] == pytest.approx(
        later["quantities"]["A_cor_A"]["reference"]["vector"], rel=1e-9)
    steps = (out / "steps.md").read_text()
    assert "# At t = 2.34 s" in steps
    assert "turned 90° the way ω4 turns" in steps
    page = (out / "worked-t-2.34s.svg").read_text()
    assert "Acceleration" in page and "Velocity" in page


def test_polygon_steps_in_steps_md_match_the_page_numbers(tmp_path):
    out = tmp_path / "fb"
    path = tmp_path / "fb.toml"
    text = four_bar_toml(angle=60).replace("[input]\nlink = 2\n", "[input]\nlink = 2\nomega = 10\n")
    path.write_text(text + '\n[ask]\nfind = ["A_B"]\n', encoding="utf-8")
    r = run("solve", path, "-o", out, "--no-pdf")
    assert r.exit_code == 0, r.output
    steps = (out / "steps.md").read_text()
    acc = steps.split("## Acceleration polygon")[1].split("##")[0]
    numbers = [int(n) for n in re.findall(r"^(\d+)\. ", acc, re.M)]
    assert numbers == list(range(1, len(numbers) + 1)) and len(numbers) >= 6
    page = (out / "worked.svg").read_text()
    assert "α2 is not given, so it is taken as 0." in page


def test_dead_point_is_one_line_and_writes_nothing(tmp_path):
    # Triple-rocker O2A 200, AB 150, O4B 200, O2O4 300 mm: coupler and rocker in line when
    # |O4A| = 350 mm, i.e. cos θ2 = 1/16.
    text = four_bar_toml(ground=300, crank=200, coupler=150, rocker=200,
                         angle=math.degrees(math.acos(1 / 16)))
    text = text.replace("[input]\nlink = 2\n", "[input]\nlink = 2\nomega = 1\n")
    path = tmp_path / "dead.toml"
    path.write_text(text + '\n[ask]\nfind = ["omega4", "alpha4"]\n', encoding="utf-8")
    r = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "out")])
    assert r.exit_code == 1
    assert "Traceback" not in r.output and len(r.output.strip().splitlines()) == 1
    assert "dead point" in r.output and "86.4167" in r.output
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("asked, prefix", [("V_B/A", "vp"), ("A_B/A", "ap")])
def test_an_asked_relative_vector_is_drawn_from_one_tip_to_the_other_and_named(asked, prefix):
    """V_B/A is the arrow a → b of the polygon; the answer is that arrow, read at its scale,
    and it is narrated ("Join a to b: V_B/A = …")."""
    (sol,) = solve_positions(four_bar_exercise(f'["{asked}"]'))
    poly = sol.velocity_polygon if prefix == "vp" else sol.acceleration_polygon
    c = sol.assembly
    step = c[f"{prefix}:rel:B/A"]
    assert step.label == asked and step.inputs == (poly.tips["A"], poly.tips["B"])
    assert f"{prefix}:rel:B/A" in poly.steps
    assert narrate(step).startswith(f"Join {c[poly.tips['A']].label} to {c[poly.tips['B']].label}")
    drawn = poly.between(*step.inputs)
    assert sol.quantities[asked].value["vector"] == pytest.approx(list(drawn), abs=1e-15)
    kin, m = sol.kinematics, sol.exercise.mechanism
    read = solver.point_velocity if prefix == "vp" else solver.point_acceleration
    ref = [b - a for a, b in zip(read(kin, m, 3, "A"), read(kin, m, 3, "B"))]
    assert drawn == pytest.approx(ref, rel=1e-12, abs=1e-12)
