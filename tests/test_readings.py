"""Numbers read off a drawn construction: ω ratios and the mechanical advantage from the
centres, speed ratios from the velocity polygon, a point's distance to a centre with the
dividers, a four-bar's transmission angle with the protractor. Each against a relation
a textbook states (V_B = ω3·I13B, μ by the law of cosines) and against the solver."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from tarsim.constructions import asks as A
from tarsim.constructions.errors import TarsimError
from tarsim.exercises.catalog import load
from tarsim.exercises.linkages.solution import solve_exercise
from tarsim.exercises.linkages.answer_text import answer_line

ASKED = ("omega3", "omega4", "V_B", "omega4/omega2", "ma_4", "V_B/V_A", "dist_B_I13",
         "dist_A_I13", "mu")


@pytest.fixture(scope="module")
def four_bar():
    ex = load("four-bar")
    return solve_exercise(replace(ex, methods=("radius-rotation", "polygon")).asking(ASKED))


def value(sol, name):
    q = sol.quantities[name]
    assert q.passed and q.rel_error <= q.tolerance, name
    return q.value["value"]


def test_ratios_of_omega_and_the_mechanical_advantage(four_bar):
    w4 = value(four_bar, "omega4")
    assert value(four_bar, "omega4/omega2") == pytest.approx(w4 / 10.0, rel=1e-12)
    assert value(four_bar, "ma_4") == pytest.approx(10.0 / w4, rel=1e-12)
    # V_A = ω2·O2A = 10 rad/s × 100 mm = 1 m/s
    assert value(four_bar, "V_B/V_A") == pytest.approx(value(four_bar, "V_B") / 1.0, rel=1e-12)


def test_a_point_moves_at_omega_times_its_distance_from_the_links_centre(four_bar):
    # Coupler 3 turns about I13: V_B = |ω3|·I13B and V_A = |ω3|·I13A.
    w3 = abs(value(four_bar, "omega3"))
    assert value(four_bar, "dist_B_I13") * w3 == pytest.approx(value(four_bar, "V_B"),
                                                                rel=1e-12)
    assert value(four_bar, "dist_A_I13") * w3 == pytest.approx(1.0, rel=1e-12)


def test_the_transmission_angle_is_the_law_of_cosines(four_bar):
    # O2A 100, AB 250, O4B 200, O2O4 300 mm at θ2 = 60°: AO4² = 100² + 300² − 2·100·300·½
    # = 70000, and cos μ = (AB² + O4B² − AO4²) / (2·AB·O4B) = 32500 / 100000.
    assert math.degrees(value(four_bar, "mu")) == pytest.approx(
        math.degrees(math.acos(0.325)), abs=1e-12)
    line = answer_line("mu", four_bar.quantities["mu"], load("four-bar").mechanism.units)
    assert line.startswith("μ = 71.0344°")
    assert answer_line("omega4/omega2", four_bar.quantities["omega4/omega2"],
                       load("four-bar").mechanism.units).startswith("ω4/ω2 = 0.291596 ")


def test_readings_are_refused_where_they_mean_nothing():
    assert A.parse_ask("V_C/V_B") == A.Ratio("V", "C", "B")
    assert A.parse_ask("dist_B_I13") == A.Distance("B", (1, 3))
    shaper = load("crank-shaper")
    ex = replace(shaper, positions=())
    with pytest.raises(TarsimError, match="transmission angle is asked of a four-bar"):
        solve_exercise(ex.asking(("mu",)))
    with pytest.raises(TarsimError, match="I15 is at infinity at this position"):
        solve_exercise(ex.asking(("dist_B_I15",)))


def test_the_least_velocity_along_a_link_is_its_common_component():
    # Every point of the coupler's line shares V_A's component along AB; the slowest has
    # nothing else: V_min = |V_A · AB/|AB||, at the foot of the perpendicular from I13.
    from tarsim.constructions.reference import solver

    ex = load("four-bar")
    sol = solve_exercise(ex.asking(("Vmin_3", "Vmin_2", "I13")))
    kin = solver.solve(ex.mechanism)
    (ax, ay), (bx, by) = kin.points["A"], kin.points["B"]
    vax, vay = kin.velocities["A"]
    along = abs(vax * (bx - ax) + vay * (by - ay)) / math.hypot(bx - ax, by - ay)
    q = sol.quantities["Vmin_3"]
    assert q.passed and q.value["value"] == pytest.approx(along, rel=1e-12)
    (fx, fy), (cx, cy) = q.value["point"], sol.quantities["I13"].value["point"]
    assert (fx - cx) * (bx - ax) + (fy - cy) * (by - ay) == pytest.approx(0.0, abs=1e-15)
    # the crank's line runs through its pivot: its slowest point is O2, at rest
    q2 = sol.quantities["Vmin_2"]
    assert q2.value["point"] == pytest.approx([0.0, 0.0], abs=1e-15)
    assert q2.value["value"] == pytest.approx(0.0, abs=1e-15) and q2.passed
    line = answer_line("Vmin_3", q, ex.mechanism.units)
    assert line.startswith(f"Vmin_3 = {along * 1000:.6g} mm/s at (")


def test_the_rubbing_velocity_is_the_relative_omega_times_the_pin_radius():
    from tarsim.exercises.catalog import resolve
    from tarsim.exercises.linkages.exercise_file import parse_exercise

    text = resolve("four-bar").read_text(encoding="utf-8")
    text = text.replace('find = ["centres", "omega3", "omega4", "V_B"]',
                        'find = ["omega3", "rub_A", "rub_O2"]\npins = { A = 20, O2 = 25 }')
    ex = parse_exercise(text, "rub.toml", "rub")
    sol = solve_exercise(ex)
    w3 = value(sol, "omega3")
    # At A links 2 and 3 turn at 10 and ω3 rad/s: |10 − ω3| × 10 mm; at O2, 10 × 12.5 mm.
    assert value(sol, "rub_A") == pytest.approx(abs(10.0 - w3) * 0.010, rel=1e-12)
    assert value(sol, "rub_O2") == pytest.approx(10.0 * 0.0125, rel=1e-14)
    line = answer_line("rub_A", sol.quantities["rub_A"], ex.mechanism.units)
    assert line.startswith("rub_A = 125.785 mm/s ")
    with pytest.raises(TarsimError, match=r"rub\.toml:\d+: \[ask\.find\] rub_A needs the "
                                          r"diameter of pin A: give it in \[ask\] as pins"):
        parse_exercise(text.replace("pins = { A = 20, O2 = 25 }", ""), "rub.toml", "rub")
    with pytest.raises(TarsimError, match="pins names 'Q', no point of the mechanism"):
        parse_exercise(text.replace("A = 20,", "Q = 20,"), "rub.toml", "rub")


def test_a_slider_cranks_transmission_angle_is_the_rods_against_the_normal_to_the_stroke():
    from tarsim.constructions.reference import solver

    ex = load("offset-slider-crank")
    sol = solve_exercise(replace(ex, positions=()).asking(("mu",)))
    kin = solver.solve(ex.mechanism)
    ay, by = kin.points["A"][1], kin.points["B"][1]
    # The stroke runs along x: the rod AB = 70 cm stands off its normal by acos(|Δy| / AB).
    mu = value(sol, "mu")
    assert math.cos(mu) == pytest.approx(abs(ay - by) / 0.70, rel=1e-12)
    assert 0.0 <= mu <= math.pi / 2


def test_the_slowest_point_of_a_named_line_of_a_rod_carrying_a_third_point():
    # Hinkle's rod BC carries D off its line: Vmin_3_B_C names the line (Vmin_3 is the
    # plate's, tests/test_vmin_plate.py).
    # Closed form for the slider-crank (O2B = 40, BC = 120 mm, θ2 = 60°, ω2 = 10 rad/s):
    # C = (40 cos 60° + √(120² − (40 sin 60°)²), 0); I13 lies on O2B produced and on the
    # normal to the stroke through C; the slowest point of BC is the foot of the
    # perpendicular from I13, at ω3 × its distance, ω3 = V_B / I13B = 10 × 40 / I13B.
    ex = load("hinkle-slider-crank")
    sol = solve_exercise(ex.asking(("Vmin_3_B_C",)))
    bx, by = 40 * math.cos(math.radians(60)), 40 * math.sin(math.radians(60))
    cx = bx + math.sqrt(120 ** 2 - by ** 2)
    ix, iy = cx, cx * math.tan(math.radians(60))                 # I13
    ux, uy = (cx - bx) / 120, -by / 120                          # B → C, unit
    along = (ix - bx) * ux + (iy - by) * uy
    off = abs((ix - bx) * uy - (iy - by) * ux)
    speed = 10 * 40 / math.hypot(ix - bx, iy - by) * off
    q = sol.quantities["Vmin_3_B_C"]
    # every number here is a few roundings of lengths of order 100 mm: 1e-12 relative
    assert q.passed and q.value["from"] == "B"
    assert q.value["along"] * 1000 == pytest.approx(along, rel=1e-12)
    assert q.value["value"] * 1000 == pytest.approx(speed, rel=1e-12)
    assert [c * 1000 for c in q.value["point"]] == pytest.approx(
        [bx + along * ux, by + along * uy], rel=1e-12)
    line = answer_line("Vmin_3_B_C", q, ex.mechanism.units)
    assert f"{along:.6g} mm from B" in line


def test_a_lever_of_three_points_on_one_line_has_its_slowest_point_at_its_pivot():
    # The p. 292 lever O4BC: three points on one line through its frame pivot O4, which is
    # I14, so the slowest point is O4 itself, at rest, nought from O4.
    ex = load("velocity-homework-292")
    assert "Vmin_4" in A.ask_names(ex.mechanism)
    q = solve_exercise(ex.asking(("Vmin_4",))).quantities["Vmin_4"]
    o4 = dict(ex.mechanism.frame.points)["O4"]
    assert q.passed and q.value["from"] == "O4"
    # O4 is placed exactly; the foot of a line through it is O4 to a few ulps of 0.3 m
    assert q.value["point"] == pytest.approx(list(o4), abs=1e-15)
    assert q.value["value"] == pytest.approx(0.0, abs=1e-14)
    assert q.value["along"] == pytest.approx(0.0, abs=1e-15)
