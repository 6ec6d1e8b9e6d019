"""Edge cases the random-mechanism run found: each is answered right or refused in one line
that says what and where.

Every number is held to the analytic solver (the check inside the solve) or to a closed
form written out here; every refusal to the words that locate it.
"""

from __future__ import annotations

import math
import re
from dataclasses import replace
import tomllib
from pathlib import Path

import pytest

import tarsim
from tarsim.constructions.errors import InputError, TarsimError
from tarsim.constructions.narration import fixed, significant
from tarsim.exercises.linkages.exercise_file import MOST_TURNED, parse_exercise
from tarsim.exercises.linkages.solution import solve_overall, solve_positions
from tests.common import four_bar_toml
from tests.test_limit_positions import SLIDER_CRANK


def _slider_crank(*, r, rod, e=0, angle=10, omega=1, find='["time_ratio", "stroke"]'):
    text = SLIDER_CRANK.format(r=r, l=rod, e=e, angle=angle, omega=omega)
    return parse_exercise(text.replace('find = ["time_ratio", "stroke"]', f"find = {find}"),
                          "sc.toml")


# ----- a dead point is not a change point ----------------------------------------------
def test_a_crank_at_its_dead_point_keeps_one_degree_of_freedom():
    # Crank 2, rod 1, no offset: A reaches y = 1 at θ2 = 30°, where the rod stands square to
    # the guide and B's two places meet. The crank cannot pass, but the rod still swings:
    # the Jacobian's nullity there is 1, and so is the construction's count.
    ex = _slider_crank(r=2, rod=1, angle=30, find='["dof"]')
    q = solve_overall(ex).quantities["dof"]
    assert q.value == {"value": 1} and q.reference == {"value": 1}
    assert q.passed


def test_a_change_point_still_counts_two_where_its_pivots_fall_in_line():
    # A parallelogram O2O4 = AB = 300, O2A = O4B = 100 at θ2 = 0: all four pivots in line.
    ex = parse_exercise(four_bar_toml(ground=300, crank=100, coupler=300, rocker=100, angle=0)
                        + '\n[ask]\nfind = ["dof"]\n', "pg.toml")
    q = solve_overall(ex).quantities["dof"]
    assert q.value == {"value": 1, "here": 2} == q.reference
    assert "two assemblies meet" in q.method


# ----- conditioning that includes a near cancellation ----------------------------------
def test_a_rod_barely_longer_than_its_crank_is_checked_at_its_conditioning():
    # The folded radius AB − O2A = 1e-9 of AB carries the rounding of AB + O2A: the
    # construction's conditioning says so, and its time ratio passes the check at it.
    r, rod, e = 0.999999999, 1.0, -7.4e-10
    overall = solve_overall(_slider_crank(r=r, rod=rod, e=e, angle=-179.99999997))
    q = overall.quantities["time_ratio"]
    assert q.conditioning <= (rod - r) / (rod + r) * (1 + 1e-6)
    assert q.passed, (q.rel_error, q.tolerance)
    # The offset slider-crank's closed form: the limits are β = asin(e/(l − r)) −
    # asin(e/(l + r)) off half a turn apart, a time ratio of (π + |β|) / (π − |β|). An
    # offset of 0.74 of l − r gives 1.7217, known here to the cancellation's 1e-7.
    beta = abs(math.asin(e / (rod - r)) - math.asin(e / (rod + r)))
    assert q.value["value"] == pytest.approx((math.pi + beta) / (math.pi - beta), rel=1e-6)


# ----- a lever with only its pivot still has its slot drawn --------------------------
LEVER_WITH_ONLY_ITS_PIVOT = """\
[units]
length = "mm"
[frame]
O4 = [0, 0]
O2 = [0, 300]
[[link]]
number = 2
points = ["O2", "A"]
lengths = { O2A = 150 }
[[link]]
number = 3
points = ["A"]
[[link]]
number = 4
points = ["O4"]
[[slider]]
link = 3
point = "A"
on = 4
[input]
link = 2
angle = 30
omega = 2
[ask]
find = ["centres", "omega4", "V_A3/A4"]
methods = ["polygon"]
"""


def test_a_slot_that_fixes_no_point_is_drawn_for_the_centres():
    sol = solve_positions(parse_exercise(LEVER_WITH_ONLY_ITS_PIVOT, "lever.toml"))[0]
    assert sol.failures == []
    # ω4 by the closed form: the lever's angle φ = atan2(A − O4), ω4 = dφ/dt.
    a = (150 * math.cos(math.radians(30)), 300 + 150 * math.sin(math.radians(30)))
    va = (-2 * (a[1] - 300), 2 * a[0])
    omega4 = (a[0] * va[1] - a[1] * va[0]) / (a[0] ** 2 + a[1] ** 2)
    assert sol.quantities["omega4"].value["value"] == pytest.approx(omega4, rel=1e-12)


# ----- refusals that say what and where ------------------------------------------------
def test_velocities_asked_of_a_still_input_are_refused_at_the_input_line():
    text = four_bar_toml() + '\n[ask]\nfind = ["V_B"]\n'
    with pytest.raises(InputError, match=r"^m.toml:\d+: \[input\] the exercise asks for V_B "
                                         r"but the input does not turn"):
        parse_exercise(text, "m.toml")


def test_a_bare_mechanism_file_without_omega_still_loads():
    assert parse_exercise(four_bar_toml(), "m.toml").mechanism.drive.omega == 0.0


def test_a_time_that_turns_the_input_past_what_a_float_holds_is_refused():
    text = (four_bar_toml().replace("[input]\n", "[input]\nomega = 1e25\n")
            + '\n[ask]\nfind = ["omega4"]\nat = [{ time = 1e6 }]\n')
    with pytest.raises(InputError, match=r"^m.toml:\d+: \[ask.at\] at t = 1e6 s the input "
                                         r"has turned 1e31 rad, past the 1e9 rad"):
        parse_exercise(text, "m.toml")
    assert MOST_TURNED * 2.2e-16 < 1e-6        # the angle kept to 1e-7 rad at the limit


def test_a_time_position_is_labelled_by_the_angle_it_reaches_in_the_turn():
    text = (four_bar_toml().replace("[input]\n", "[input]\nomega = 10\n")
            + '\n[ask]\nfind = ["omega4"]\nat = [{ time = 100 }]\n')
    (p,) = parse_exercise(text, "m.toml").positions
    reached = math.fmod(math.radians(60) + 1000.0, math.tau)
    assert p.drive.angle == pytest.approx(reached, abs=1e-12)
    assert p.label == f"t = 100 s (θ2 = {math.degrees(reached):.6g}°)"


def test_a_stated_scale_that_draws_nothing_is_refused_at_its_line():
    text = (four_bar_toml().replace("[input]\n", "[input]\nomega = 10\n")
            + '\n[ask]\nfind = ["V_B"]\nscale = ["1 cm = 1e9 mm/s"]\n')
    # V_A = ω2 · O2A = 1000 mm/s drawn at 1 cm = 1e9 mm/s is 1e-6 cm long.
    with pytest.raises(InputError, match=r"^m.toml:\d+: \[ask.scale\] the velocity scale "
                                         r"'1 cm = 1e9 mm/s' draws the input's velocity, "
                                         r"1000 mm/s, 1e-6 cm long"):
        parse_exercise(text, "m.toml")


def test_a_kite_whose_limits_coincide_has_no_time_ratio():
    # O2O4 = O2A = 2, AB = O4B = 5: both rocker limits fall where B is in line with the
    # pivots, at one crank angle.
    text = four_bar_toml(ground=2, crank=2, coupler=5, rocker=5, angle=42,
                         branch='B = "right"').replace("[input]\n", "[input]\nomega = 1\n")
    ex = parse_exercise(text + '\n[ask]\nfind = ["time_ratio"]\n', "kite.toml")
    with pytest.raises(TarsimError, match=r"both limit positions fall at θ2 = .*: the crank "
                                          r"turns through no angle between them"):
        solve_overall(ex)


def test_kennedy_names_the_link_whose_centres_fall_together():
    # A crank 1e-12 of the coupler: I12 and I23 fall together at the mechanism's scale.
    text = four_bar_toml(ground=1837.78, crank=1.8e-9, coupler=1461.8, rocker=1259.7,
                         angle=-288.3).replace("[input]\n", "[input]\nomega = 1\n")
    ex = parse_exercise(text + '\n[ask]\nfind = ["centres"]\n', "tiny.toml")
    with pytest.raises(TarsimError, match=r"Kennedy's theorem cannot reach I13.*: I12 and I23 "
                                          r"of link 2 fall together"):
        solve_positions(ex)


def test_a_mechanism_that_never_assembles_says_why_at_its_stated_angle():
    text = four_bar_toml(ground=17361.9, crank=100, coupler=1466.15, rocker=86.0073, angle=180)
    ex = parse_exercise(text + '\n[ask]\nfind = ["dof"]\n', "far.toml")
    with pytest.raises(TarsimError, match=r"^far.toml: the mechanism assembles at none of 12 "
                                          r"input angles spread over a turn of link 2, so it "
                                          r"has no mobility to count$") as caught:
        solve_overall(ex)
    # Why, at the first angle tried: the story behind the line (tarsim --verbose prints it).
    assert re.fullmatch(r"link 3 .* cannot reach B: .* at input angle 180°",
                        caught.value.detail)


@pytest.mark.parametrize("value, text", [(264.57513110645906, "264.575"), (1.5e25, "1.5e25"),
                                         (-2.5e-7, "−2.5e-7"), (0.0, "0")])
def test_an_error_gives_six_significant_figures(value, text):
    assert significant(value) == text


def test_a_length_of_a_million_or_more_is_not_spelled_out():
    assert fixed(1e25, 4) == "1e25" and fixed(250.5, 4) == "250.5"
    assert fixed(4.6e-10, 4) == "4.6e-10" and fixed(0.00004, 4) == "4e-5"


# ----- near-singular positions, checked at their whole conditioning ------------------------
EDGE = Path(__file__).parent / "data" / "edge"


@pytest.mark.parametrize("name", ["lever-block-near-pivot", "slider-crank-near-toggle",
                                  "shaper-block-near-pivot", "whitworth-block-on-pivot"])
def test_a_near_singular_position_passes_every_check(name):
    worked = tarsim.solve(tarsim.load(EDGE / f"{name}.toml"))
    assert worked.failures == [] and worked.passed


def test_a_lever_pivoted_on_the_crank_circle_turns_at_half_the_crank_speed():
    # O2O4 equals the crank: the lever's angle is an inscribed angle on the crank circle,
    # half the crank's, so ω4 = ω2/2 and α4 = 0 at every position, the block 4e-4 of the
    # crank from the pivot included. α4 is held to its tolerance beside ω2², as checked.
    worked = tarsim.solve(tarsim.load(EDGE / "lever-block-near-pivot.toml"))
    sol = worked.positions[0]
    w2 = sol.exercise.mechanism.drive.omega
    omega4 = sol.quantities["omega4"]
    assert omega4.value["value"] == pytest.approx(w2 / 2, rel=omega4.tolerance)
    alpha4 = sol.quantities["alpha4"]
    assert abs(alpha4.value["value"]) <= alpha4.tolerance * w2 ** 2


def test_a_block_on_its_pivot_leaves_the_slot_without_a_direction():
    # Where the block sits on the pivot of a slot through it, the lever's direction is
    # rounding: neither the compass nor the analytic solver draws the position, so the count
    # there is Grübler's alone, and the position is refused in one line.
    ex = tarsim.load(EDGE / "whitworth-block-on-pivot.toml")
    q = solve_overall(ex).quantities["dof"]
    assert q.value == {"value": 1} == q.reference
    with pytest.raises(TarsimError, match=r"the block A sits on the pivot O4 at θ2 = −90°, so "
                                          r"the slot of link 4 has no direction"):
        solve_positions(replace(ex.asking(("omega4",)), positions=()))


def test_a_kite_range_is_judged_at_the_end_of_its_class():
    # O2O4 = O2A = 1, AB = O4B = 3: a change point (1 + 3 = 1 + 3). Turning, it is a
    # double-crank for O2A in [1, 5): the change point is that range's low end.
    text = four_bar_toml(ground=1, crank=1, coupler=3, rocker=3).replace(
        "[input]\n", "[input]\nomega = 1\n")
    ex = parse_exercise(text + '\n[ask]\nfind = ["range_O2A"]\n', "kite.toml")
    q = solve_overall(ex).quantities["range_O2A"]
    assert q.value["low"] == q.value["high"] == pytest.approx(1e-3)
    assert q.reference["low"] == pytest.approx(1e-3, rel=1e-9)
    assert q.reference["high"] == pytest.approx(5e-3, rel=1e-9)
    assert q.passed


def test_coincident_ground_pivots_refuse_omega_by_the_centres():
    # A Stephenson six-bar whose links 2 and 6 turn about one frame point: I12, I16 and I26
    # fall together, so the ratio of distances that gives ω6 is lost to rounding.
    text = (Path(__file__).parent / "data" / "stephenson-six-bar.toml").read_text()
    data = tomllib.loads(text)
    o2 = data["frame"]["O2"]
    moved = re.sub(r"(?m)^O6 = .*$", f"O6 = [{o2[0]}, {o2[1]}]", text)
    assert "[ask]" not in moved
    ex = parse_exercise(moved + '\n[ask]\nfind = ["omega6"]\n', "six.toml")
    with pytest.raises(TarsimError, match=r"ω6 from the instant centres: I26 and I16 fall "
                                          r"together"):
        solve_positions(ex)


def test_an_offset_slot_cannot_pass_its_block_on_the_pivot():
    ex = tarsim.load(EDGE / "offset-slot-block-on-pivot.toml")
    q = solve_overall(ex).quantities["dof"]
    assert q.value == {"value": 1} == q.reference      # not assembled here: Grübler alone
    with pytest.raises(TarsimError, match=r"the block A comes within 6\.12323e-17 in of O4 at "
                                          r"θ2 = −1\.5708 rad, closer than the slot's offset "
                                          r"of 0\.268189 in"):
        solve_positions(replace(ex.asking(("omega4",)), positions=()))   # at [input]


def test_a_nanometre_mechanism_labels_its_centres_apart():
    # The bundled four-bar shrunk a billion times (O2O4 = 0.3 nm): no two of its centres
    # coincide, so no label joins two of them (I14 ≡ I12 would, were points judged the same
    # within a fixed nanometre rather than relative to the drawing).
    text = four_bar_toml(ground=3e-7, crank=1e-7, coupler=2.5e-7, rocker=2e-7).replace(
        "[input]\n", "[input]\nomega = 10\n")
    worked = tarsim.solve(parse_exercise(text + '\n[ask]\nfind = ["centres"]\n', "micro.toml"))
    assert worked.passed
    svg = worked.files()["centres.svg"]
    assert "≡" not in svg
    for label in ("I₁₂", "I₁₃", "I₁₄", "I₂₃", "I₂₄", "I₃₄"):
        assert label in svg


def test_a_torque_far_below_its_checks_scale_stands_where_it_meets_its_reference():
    # The driving torque here is 2.6e-10 N·m beside inertia loads that make the check's scale
    # some million times larger, so the check alone cannot tell it from 0; it meets the
    # Newton–Euler reference to 1e-5 of itself, so it stands, and the balance of energy
    # (tests/random_loads.py's own finite differences, no joint force in it) agrees.
    from tests.random_loads import oracle

    path = EDGE / "small-torque-beside-big-loads.toml"
    solution = tarsim.solve(tarsim.load(str(path)))
    q = solution.positions[0].quantities["T2"]
    assert q.passed and q.value["value"] != 0.0
    assert q.value["value"] == pytest.approx(q.reference["value"], rel=1e-5)
    assert oracle(solution, path.read_text(encoding="utf-8")) == []
