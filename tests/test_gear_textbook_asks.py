"""Gear trains asked as the textbooks ask them: the power a member delivers (η·P_in at the
output), and a planetary train's teeth from its speed ratio and the least tooth count. Each
answer is held to the book's closed form: exact fractions, so a tolerance of 0."""

from __future__ import annotations

import json
import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.constructions.narration import narrate
from tarsim.exercises.catalog import load
from tarsim.exercises.gears.train_file import parse_train
from tarsim.exercises.gears.train_solution import solve_train

F = Fraction

PLANETARY = """name = "sun 2, planet 3, ring 1 fixed, arm 4"
fixed = 1
{top}
[units]
speed = "{unit}"

[[gear]]
number = 1
{ring}

[[gear]]
number = 2
{sun}

[[gear]]
number = 3
{planet}
carrier = 4

[arm]
number = 4

[[mesh]]
gears = [2, 3]

[[mesh]]
gears = [3, 1]
kind = "internal"

[input]
{given}

[ask]
find = {find}
"""


def planetary(ring="teeth = 80", sun="teeth = 20", planet="teeth = 30", top="",
              given="member = 2\nspeed = 1440\ntorque = 50", find='["power4"]', unit="rpm"):
    return PLANETARY.format(ring=ring, sun=sun, planet=planet, top=top, given=given,
                            find=find, unit=unit)


# ----- the power a member puts in or takes out ----------------------------------------------------
def test_gearbox_output_power():
    """The textbook corpus's gear box (the bundled one): 7.5 kW in at the sun, η = 0.95, the
    arm delivers 0.95 × 7500 = 7125 W exactly (the π of T = 30P/(πn) cancels against
    ω = 2πn/60), and the sun puts in the 7500 W given."""
    s = solve_train(load("gearbox-power-efficiency"))
    p4 = s.quantities["power4"]
    assert (p4.exact, p4.reference, p4.times_pi, p4.flow) == (F(7125), F(7125), False, "out")
    assert p4.si == 7125.0


def test_the_power_is_written_to_results_json(tmp_path):
    """results.json gives the power in W, its exact fraction and its way out of the train."""
    s = solve_train(load("gearbox-power-efficiency"))
    s.write(tmp_path)
    entry = json.loads((tmp_path / "results.json").read_text())["quantities"]["power4"]
    assert (entry["value"], entry["exact"], entry["unit"], entry["flow"]) == (
        7125.0, "7125", "W", "out")
    assert entry["reference"]["value"] == 7125.0


@settings(max_examples=40, deadline=None)
@given(st.integers(12, 60), st.integers(12, 40), st.integers(1, 3000), st.integers(1, 500),
       st.integers(50, 100), st.sampled_from(["rpm", "rad/s"]))
def test_the_output_power_is_the_efficiency_times_the_input_s(sun, planet, speed, torque,
                                                               percent, unit):
    """P_out = η·T_in·ω_in whatever the teeth; with speeds in rpm ω = 2πn/60, so the power
    of a torque given in N·m is (T·n/30)·π, kept exact as a fraction times π."""
    ring = sun + 2 * planet
    eta = F(percent, 100)
    text = planetary(f"teeth = {ring}", f"teeth = {sun}", f"teeth = {planet}",
                     top=f"efficiency = {percent / 100}",     # read as written: η exact
                     given=f"member = 2\nspeed = {speed}\ntorque = {torque}",
                     find='["power4", "power2"]', unit=unit)
    q = solve_train(parse_train(text, "t.toml")).quantities
    p_in = F(torque * speed) / (30 if unit == "rpm" else 1)
    assert q["power2"].exact == p_in and q["power2"].flow == "in"
    assert q["power4"].exact == eta * p_in and q["power4"].flow == "out"
    assert q["power4"].times_pi is (unit == "rpm")
    # the SI value: the exact fraction, times π in rpm; a rounding or two of a float
    want = float(eta * p_in) * (math.pi if unit == "rpm" else 1.0)
    assert q["power4"].si == pytest.approx(want, rel=1e-15)
    assert q["power4"].passed and q["power2"].passed


def test_the_power_of_a_second_given_member_follows_the_balance():
    """Sun and arm both given, no losses: the ring's power is what the sun's and the arm's
    leave, T·ω summing to zero, each T from T2 : T1 : T4 = N2 : N1 : −(N2 + N1)."""
    text = planetary(given="member = 2\nspeed = 1000\ntorque = 10",
                     find='["power1", "power4"]').replace("fixed = 1\n", "")
    text = text.replace("[input]\nmember = 2", "[[input]]\nmember = 2").replace(
        "\n[ask]", "\n[[input]]\nmember = 4\nspeed = 100\n\n[ask]")
    q = solve_train(parse_train(text, "t.toml")).quantities
    w4, w2 = F(100), F(1000)
    w1 = w4 - F(20, 80) * (w2 - w4)          # the ring: (ω1 − ω4)/(ω2 − ω4) = −N2/N1
    t1, t4 = F(10 * 80, 20), -F(10 * 100, 20)
    assert q["power1"].exact == abs(t1 * w1) / 30 and q["power4"].exact == abs(t4 * w4) / 30
    assert q["power1"].times_pi and q["power4"].passed


def test_the_fixed_member_s_power_is_refused():
    with pytest.raises(InputError, match=r"^t\.toml:\d+: \[ask\.find\] power1 is asked of "
                                         r"the fixed member 1, which takes no power"):
        parse_train(planetary(find='["power4", "power1"]'), "t.toml")


def test_a_power_needs_the_input_s_torque_or_power():
    with pytest.raises(InputError, match=r"cannot find 'power4' without the input's torque"):
        parse_train(planetary(given="member = 2\nspeed = 100"), "t.toml")


# ----- a planetary train's teeth from its speed ratio -------------------------------------------
def test_gears_teeth_from_ratio_planetary():
    """The textbook corpus's problem, bundled: the carrier at 1/5 of the sun's speed with the
    internal gear fixed, 1 + N_E/N_S = 5, so N_E = 4·N_S and N_P = (N_E − N_S)/2 = 1.5·N_S;
    the least whole set from 16 teeth is 16, 24, 64. The sun's 100 N·m: T_C = −500 N·m, so
    E is held by 400 N·m."""
    s = solve_train(load("planetary-ratio-least-teeth"))
    q = s.quantities
    assert (q["teeth2"].exact, q["teeth3"].exact, q["teeth1"].exact) == (16, 24, 64)
    assert q["omega4/omega2"].exact == F(1, 5)
    assert q["torque1"].exact == 400
    assert s.passed
    steps = [narrate(p) for p in s.train.implied]
    assert any("(N1 + 16)/16" in p and "N1 = 64" in p for p in steps)


def _least_set(k: int, least: int) -> tuple[int, int, int]:
    """The books' choice, apart from tarsim: (N_S, N_P, N_E) ∝ (2, k − 2, 2(k − 1)) for
    ω_S/ω_C = k with E fixed, the smallest scaled to the fewest teeth ≥ ``least``."""
    base = [2, k - 2, 2 * (k - 1)]
    g = math.gcd(*base)
    base = [b // g for b in base]
    scale = -(-least // min(base))
    return tuple(b * scale for b in base)


@settings(max_examples=30, deadline=None)
@given(st.integers(3, 9), st.integers(8, 30), st.integers(1, 300))
def test_the_least_set_of_teeth_meets_the_ratio(k, least, torque):
    """Whatever the ratio and least count, the counts are the least whole set in the ratio
    the speed ratio and the coaxial condition fix, and the holding torque is (k − 1)·T."""
    text = planetary("", "", "", top=f"[ratio]\nof = \"omega2/omega4\"\nvalue = {k}\n"
                     f"least_teeth = {least}\n", given=f"member = 2\ntorque = {torque}",
                     find='["teeth2", "teeth3", "teeth1", "torque1"]')
    q = solve_train(parse_train(text, "t.toml")).quantities
    sun, planet, ring = _least_set(k, least)
    assert (q["teeth2"].exact, q["teeth3"].exact, q["teeth1"].exact) == (sun, planet, ring)
    assert q["torque1"].exact == (k - 1) * torque
    assert all(q[n].passed for n in q)


def test_one_count_given_needs_no_least_count():
    """The sun given 20 teeth: the ratio gives the ring N_E = (5 − 1)·20 = 80 whatever the
    planet's, and the coaxial condition the planet (80 − 20)/2 = 30."""
    text = planetary("", "teeth = 20", "", top="[ratio]\nof = \"omega2/omega4\"\nvalue = 5\n",
                     given="member = 2", find='["teeth1", "teeth3"]')
    q = solve_train(parse_train(text, "t.toml")).quantities
    assert (q["teeth1"].exact, q["teeth3"].exact) == (80, 30)


def test_a_ratio_no_planetary_teeth_can_meet_is_refused():
    """|ω_S/ω_C| = 3/2 with E fixed asks N_E = N_S/2, smaller than the sun: the planet
    would have fewer than none, so no counts give it."""
    text = planetary("", "", "", top="[ratio]\nof = \"omega2/omega4\"\nvalue = 1.5\n"
                     "least_teeth = 16\n", given="member = 2", find='["teeth1"]')
    with pytest.raises(InputError, match=r"no whole counts of 16 teeth or more for gears "
                                         r"1, 2, 3 give the speed ratio ω2/ω4 = 1\.5"):
        parse_train(text, "t.toml")


def test_unknown_planetary_teeth_without_a_least_count_are_refused():
    text = planetary("", "", "", top="[ratio]\nof = \"omega2/omega4\"\nvalue = 5\n",
                     given="member = 2", find='["teeth1"]')
    with pytest.raises(InputError, match=r"give least_teeth = … in \[ratio\]"):
        parse_train(text, "t.toml")


# ----- a reverted train to design, and two shafts a given distance apart -------------------------
def test_gears_reverted_train_design():
    """The corpus's reverted train, bundled: N_B = 4·N_A, N_D = 3·N_C, and the shafts in line,
    3.125·5·N_A = 2.5·4·N_C, so N_C = 25/16·N_A, whole from N_A = 32 (≥ 24): 32, 128, 50,
    150, and 3.125 mm·(32 + 128)/2 = 250 mm between the shafts."""
    s = solve_train(load("reverted-train-design"))
    q = s.quantities
    assert [q[f"teeth{n}"].exact for n in (1, 2, 3, 4)] == [32, 128, 50, 150]
    assert q["omega4/omega1"].exact == F(1, 12)
    assert q["centre_distance1_2"].exact == F(250, 1000)      # m, exact
    assert s.passed


def test_gears_parallel_shafts_teeth():
    """The corpus's shafts 600 mm apart at 360 and 120 rpm, module 5 mm, bundled:
    d1 + d2 = 1200 mm with d2 = 3·d1, so N1 = 300/5 = 60 and N2 = 900/5 = 180."""
    s = solve_train(load("shafts-apart"))
    q = s.quantities
    assert (q["teeth1"].exact, q["teeth2"].exact, q["omega2"].exact) == (60, 180, -120)
    assert s.passed


TWO = """name = "a pair"
[units]
length = "mm"
[[gear]]
number = 1
module = {module}
{first}
[[gear]]
number = 2
module = {module}
[[mesh]]
gears = [1, 2]
centre_distance = {distance}
{ratio}
[input]
member = 1
speed = 100
[ask]
find = {find}
"""


@settings(max_examples=40, deadline=None)
@given(st.integers(8, 80), st.integers(1, 9), st.sampled_from(["1", "2.5", "4", "6"]))
def test_a_centre_distance_and_a_ratio_give_the_pair(n1, k, module):
    """C = m(N1 + N2)/2 with N2 = k·N1: N1 = 2C/(m(1 + k)), whatever the module; and the
    distance asked back is C itself."""
    m = F(module)
    distance = m * n1 * (1 + k) / 2
    text = TWO.format(module=module, first="", distance=float(distance),
                      ratio=f'[ratio]\nof = "omega1/omega2"\nvalue = {k}',
                      find='["teeth1", "teeth2", "centre_distance1_2"]')
    q = solve_train(parse_train(text, "t.toml")).quantities
    assert (q["teeth1"].exact, q["teeth2"].exact) == (n1, k * n1)
    assert q["centre_distance1_2"].exact == distance / 1000        # mm → m, exact
    assert all(x.passed for x in q.values())


def test_one_count_from_a_centre_distance():
    """A pinion of 20 teeth, module 4 mm, 100 mm from its wheel: N2 = 2·100/4 − 20 = 30."""
    text = TWO.format(module=4, first="teeth = 20", distance=100, ratio="",
                      find='["teeth2"]')
    assert solve_train(parse_train(text, "t.toml")).quantities["teeth2"].exact == 30


def test_a_distance_that_breaks_a_count_is_refused():
    """A pinion of 20 teeth at 4 mm, 101 mm from its wheel: 2·101/4 − 20 = 30.5 teeth."""
    text = TWO.format(module=4, first="teeth = 20", distance=101, ratio="", find='["teeth2"]')
    with pytest.raises(InputError, match=r"the centre distance 101 mm = 4 mm·\(20 \+ N2\)/2 "
                                         r"gives gear 2 30\.5 teeth"):
        parse_train(text, "t.toml")


def test_teeth_that_miss_the_centre_distance_are_refused():
    """20 and 30 teeth at 4 mm stand 100 mm apart, not the 120 mm given."""
    text = TWO.format(module=4, first="teeth = 20", distance=120, ratio="",
                      find='["omega2"]').replace("number = 2\n", "number = 2\nteeth = 30\n")
    with pytest.raises(InputError, match=r"stand 100 mm apart by their teeth and module, not "
                                         r"the centre distance 120 mm given"):
        parse_train(text, "t.toml")


def test_a_centre_distance_is_asked_of_a_pair_in_mesh_with_a_module():
    text = TWO.format(module=4, first="teeth = 20", distance=100, ratio="",
                      find='["centre_distance1_3"]')
    with pytest.raises(InputError, match=r"cannot find 'centre_distance1_3': ask the centre "
                                         r"distance of a pair in mesh, centre_distance1_2"):
        parse_train(text, "t.toml")


# ----- bevel gears: a car's differential -----------------------------------------------------
def test_gears_car_differential():
    """The corpus's car on a turn, bundled: the crown at 1000·12/60 = 200 rpm, and the axle
    gears either side of the bevel pinion turn opposite ways relative to the cage, so
    ω_P + ω_Q = 2·ω_crown: ω_P = 400 − 210 = 190 rpm."""
    s = solve_train(load("car-differential"))
    q = s.quantities
    assert (q["omega2"].exact, q["omega3"].exact) == (200, 190)
    assert s.passed and s.diagram is None


DIFFERENTIAL = """name = "bevel differential"
{fixed}
[[gear]]
number = 3
teeth = {p}
[[gear]]
number = 4
teeth = {q}
[[gear]]
number = 5
teeth = {pinion}
carrier = 6
[arm]
number = 6
[[mesh]]
gears = [3, 5]
kind = "bevel"
[[mesh]]
gears = [5, 4]
kind = "bevel"
{given}
[ask]
find = {find}
"""


@settings(max_examples=40, deadline=None)
@given(st.integers(10, 60), st.integers(10, 60), st.integers(8, 30),
       st.integers(-2000, 2000).filter(bool), st.integers(-2000, 2000))
def test_the_side_gears_turn_opposite_ways_relative_to_the_cage(p, q, pinion, cage, wheel):
    """Willis for a bevel differential: N_P(ω_P − ω_c) = −N_Q(ω_Q − ω_c), the pinion's teeth
    cancelling; with equal side gears ω_P + ω_Q = 2ω_c."""
    text = DIFFERENTIAL.format(fixed="", p=p, q=q, pinion=pinion, find='["omega3"]',
                               given=f"[[input]]\nmember = 6\nspeed = {cage}\n"
                                     f"[[input]]\nmember = 4\nspeed = {wheel}")
    s = solve_train(parse_train(text, "t.toml"))
    assert s.quantities["omega3"].exact == cage - F(q, p) * (wheel - cage)
    assert s.passed


def test_a_fixed_side_gear_doubles_the_cage_s_speed():
    """One side gear held, equal side gears: ω_Q = ω_c − (ω_P − ω_c) = 2ω_c; no velocity
    diagram (the pinion's axis is square to the main axis)."""
    text = DIFFERENTIAL.format(fixed="fixed = 3", p=20, q=20, pinion=12, find='["omega4"]',
                               given="[input]\nmember = 6\nspeed = 100")
    s = solve_train(parse_train(text, "t.toml"))
    assert s.quantities["omega4"].exact == 200 and s.diagram is None


def test_a_bevel_planet_s_speed_is_refused():
    text = DIFFERENTIAL.format(fixed="fixed = 3", p=20, q=20, pinion=12, find='["omega5"]',
                               given="[input]\nmember = 6\nspeed = 100")
    with pytest.raises(InputError, match=r"cannot find 'omega5': gear 5 is a bevel planet"):
        parse_train(text, "t.toml")


def test_a_third_bevel_mesh_on_a_planet_is_refused():
    text = DIFFERENTIAL.format(fixed="fixed = 3", p=20, q=20, pinion=12, find='["omega4"]',
                               given="[input]\nmember = 6\nspeed = 100").replace(
        "[[mesh]]\ngears = [5, 4]", "[[mesh]]\ngears = [5, 7]\nkind = \"bevel\"\n"
        "[[mesh]]\ngears = [5, 4]").replace("[arm]", "[[gear]]\nnumber = 7\nteeth = 20\n[arm]")
    with pytest.raises(InputError, match=r"gear 5 has a third bevel mesh"):
        parse_train(text, "t.toml")


def test_a_compound_bevel_planet_is_refused():
    """Humpage's gear's compound planet: which side of its spindle each main-axis gear
    stands (so the sense of each bevel mesh) is not in the file; refused, not guessed."""
    text = DIFFERENTIAL.format(fixed="fixed = 3", p=20, q=20, pinion=12, find='["omega4"]',
                               given="[input]\nmember = 6\nspeed = 100").replace(
        "[[mesh]]\ngears = [5, 4]", "[[mesh]]\ngears = [7, 4]").replace(
        "[arm]", "[[gear]]\nnumber = 7\nteeth = 20\ncarrier = 6\n[[shaft]]\nmembers = [5, 7]"
        "\n[arm]")
    with pytest.raises(InputError, match=r"which side of the spindle each main-axis gear "
                                         r"stands cannot be told"):
        parse_train(text, "t.toml")


# ----- the velocity diagram with no speed given ---------------------------------------------
def test_the_velocity_diagram_with_no_speed_gives_the_ratios(tmp_path):
    """ratio-only gives no speed: the diagram is drawn for the sun at 1 rpm and each
    slope over the sun's is a speed ratio, ω4/ω2 = N2/(N1 + N2) = 20/100, read within the
    drawing's rounding; results.json gives the reading beside the ratio, and the figure
    names each line by its ratio."""
    s = solve_train(load("ratio-only"))
    assert s.diagram is not None and s.passed and not s.diagram_misses
    read = s.diagram.said(4) / s.diagram.said(2)
    beside = s.diagram_ratio(4, 2)
    assert abs(read - 0.2) <= beside["tolerance"] < 1e-6      # a drawing's rounding, no more
    s.write(tmp_path)
    entry = json.loads((tmp_path / "results.json").read_text())["quantities"]["omega4/omega2"]
    assert entry["velocity_diagram"]["value"] == pytest.approx(0.2, abs=beside["tolerance"])
    svg = (tmp_path / "kutzbach.svg").read_text()
    assert "ω₄/ω₂ = 0.2<" in svg and "ω₂/ω₂ = 1<" in svg


def test_the_velocity_diagram_with_two_given_speeds():
    """The sun at 200 rpm ccw and the arm at 100 rpm cw: their two lines through O give the
    planet's line (through the sun's pitch point and the arm's C) and the ring's; the ring
    reads ω4 = ω5 − (N2/N4)(ω2 − ω5) = −100 − (30/70)·300 = −1600/7 rpm, within the
    drawing's rounding."""
    s = solve_train(load("two-speeds-arm-and-sun"))
    assert s.diagram is not None and s.passed and not s.diagram_misses
    per = 2 * math.pi / 60
    miss, allowed = s.diagram_check(4)
    assert abs(s.diagram.said(4) / per + F(1600, 7)) <= 1e-6 and miss <= allowed < 1e-6


@settings(max_examples=30, deadline=None)
@given(st.integers(12, 60), st.integers(12, 40), st.integers(-3000, 3000).filter(bool),
       st.integers(-3000, 3000).filter(bool))
def test_a_sun_and_a_ring_driven_read_the_arm_off_the_diagram(sun, planet, w_sun, w_ring):
    """No member fixed, the sun and the ring driven: the arm's line reads ω_a = (N_s·ω_s +
    N_r·ω_r)/(N_s + N_r) off the diagram, to its rounding (each line drawn at the paper's
    scale: a few parts in a million of the fastest at most)."""
    ring = sun + 2 * planet
    text = planetary(f"teeth = {ring}", f"teeth = {sun}", f"teeth = {planet}",
                     given=f"member = 2\nspeed = {w_sun}", find='["omega4"]').replace(
        "fixed = 1\n", "").replace("[input]", "[[input]]").replace(
        "\n[ask]", f"\n[[input]]\nmember = 1\nspeed = {w_ring}\n\n[ask]")
    s = solve_train(parse_train(text, "t.toml"))
    want = F(sun * w_sun + ring * w_ring, sun + ring)
    assert s.quantities["omega4"].exact == want
    assert s.diagram is not None
    miss, allowed = s.diagram_check(4)
    assert miss <= allowed <= 1e-3
    assert s.passed


# ----- a planet held from turning: the sun-and-planet gear ----------------------------------
def test_gears_sun_and_planet_watt():
    """The corpus's sun-and-planet gear, bundled: the planet (48) held from turning, the
    crank at 40 rpm: ω_sun = 40·(1 + 48/32) = 100 rpm."""
    s = solve_train(load("sun-and-planet"))
    assert s.quantities["omega1"].exact == 100 and s.quantities["omega1/omega3"].exact == F(5, 2)
    assert s.passed


@settings(max_examples=30, deadline=None)
@given(st.integers(12, 80), st.integers(12, 80), st.integers(-500, 500).filter(bool))
def test_a_held_planet_turns_the_sun_at_one_plus_the_ratio(sun, planet, crank):
    """With the planet held, Willis relative to the arm gives ω_s = ω_a(1 + N_p/N_s)."""
    text = f"""name = "held planet"
fixed = 2
[[gear]]
number = 1
teeth = {sun}
[[gear]]
number = 2
teeth = {planet}
carrier = 3
[arm]
number = 3
[[mesh]]
gears = [1, 2]
[input]
member = 3
speed = {crank}
[ask]
find = ["omega1"]
"""
    s = solve_train(parse_train(text, "t.toml"))
    assert s.quantities["omega1"].exact == crank * (1 + F(planet, sun)) and s.passed


def test_a_ring_s_teeth_from_its_centre_distance():
    """A pinion of 30 teeth inside an annulus, module 2 mm, axes 50 mm apart: the ring
    listed second, C = m(N_ring − N)/2 gives N_ring = 30 + 2·50/2 = 80."""
    text = TWO.format(module=2, first="teeth = 30", distance=50, ratio="",
                      find='["teeth2", "omega2"]').replace(
        'gears = [1, 2]', 'gears = [1, 2]\nkind = "internal"')
    q = solve_train(parse_train(text, "t.toml")).quantities
    assert q["teeth2"].exact == 80 and q["omega2"].exact == F(100 * 30, 80)
