"""Gear trains posed as the textbooks pose them: the given speed on any member (the output's
too), no speed where only ratios or torques are asked, two given speeds, torques and power
with an efficiency, teeth the data imply, identical planets listed as gears. Each answer is
held to the textbook's closed form (exact fractions: a tolerance of 0)."""

from __future__ import annotations

import json
from fractions import Fraction

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.catalog import load
from tarsim.exercises.gears.train_file import parse_train
from tarsim.exercises.gears.train_solution import solve_train

F = Fraction

SIMPLE = """name = "sun, planet, ring"
fixed = {fixed}

[[gear]]
number = 2
teeth = {sun}

[[gear]]
number = 3
teeth = {planet}
carrier = 5

[[gear]]
number = 4
teeth = {ring}

[arm]
number = 5

[[mesh]]
gears = [2, 3]

[[mesh]]
gears = [3, 4]
kind = "internal"

[input]
{given}

[ask]
find = {find}
"""


def simple(sun=40, planet=20, ring=80, fixed=4, given="member = 2\nspeed = 100",
           find='["omega5"]'):
    return SIMPLE.format(sun=sun, planet=planet, ring=ring, fixed=fixed, given=given, find=find)


# ----- the given speed on any member, and none where none is needed ---------------------------
def test_the_arm_s_speed_given_gives_the_sun_s_by_one_plus_ring_over_sun():
    """The bundled example: ring fixed, the arm (the output) at 100 rpm cw; ω2 = (1 + N4/N2)·ω5
    = 3 × (−100) = −300 rpm, and the planet ω3 = ω5 − (N4/N3)(0 − ω5)… = +300."""
    s = solve_train(load("output-speed-given"))
    q = s.quantities
    assert q["omega2"].exact == F(-300) == q["omega2"].reference
    assert q["omega2/omega5"].exact == 1 + F(80, 40)
    # the planet relative to the arm: (ω3 − ω5)/(ω4 − ω5) = N4/N3
    assert (q["omega3"].exact + 100) / (0 + 100) == F(80, 20)
    assert s.passed


@settings(max_examples=40, deadline=None)
@given(st.integers(12, 60), st.integers(12, 60), st.sampled_from(["2", "3", "5"]),
       st.integers(1, 5000))
def test_the_given_speed_on_any_member_gives_willis_closed_form(sun, planet, member, speed):
    """Whatever member's speed is given, the others follow from the fixed ring's Willis
    equation: ω2 = ω5(1 + N4/N2), ω3 = ω5(1 − N4/N3)."""
    ring = sun + 2 * planet
    ratio = {"2": 1 + F(ring, sun), "3": 1 - F(ring, planet), "5": F(1)}   # ω_k/ω5
    text = simple(sun, planet, ring, given=f"member = {member}\nspeed = {speed}",
                  find='["omega2", "omega3", "omega5"]')
    q = solve_train(parse_train(text, "t.toml")).quantities
    arm = F(speed) / ratio[member]
    assert q["omega5"].exact == arm
    assert q["omega2"].exact == arm * ratio["2"] and q["omega3"].exact == arm * ratio["3"]


def test_ratio_only_needs_no_speed_and_gives_the_torques():
    """The bundled example: ω4/ω2 = N2/(N1 + N2) = 20/100, T4 = −T2/(1/5) = −150 N·m, the
    ring held by −(30 − 150) = 120 N·m; no speed in the file, none in the table."""
    s = solve_train(load("ratio-only"))
    q = s.quantities
    assert q["omega4/omega2"].exact == F(20, 100)
    assert (q["torque4"].exact, q["torque1"].exact) == (F(-150), F(120))
    assert s.passed and s.diagram is not None     # drawn for the sun at 1 rpm: ratios
    heads, rows = s._table()
    assert len(rows) == 3                 # locked, held, total: no row of speeds


def test_a_speed_asked_without_a_speed_given_is_refused_at_the_ask():
    text = simple(given="member = 2", find='["omega5"]')
    with pytest.raises(InputError, match=r"^t\.toml:\d+: \[ask\.find\] cannot find 'omega5' "
                                         r"without a speed"):
        parse_train(text, "t.toml")


def test_without_a_speed_or_an_ask_the_ratios_over_the_input_are_given():
    s = solve_train(parse_train(simple(given="member = 2").replace(
        '[ask]\nfind = ["omega5"]\n', ""), "t.toml"))
    assert set(s.quantities) == {"omega3/omega2", "omega5/omega2"}
    assert s.quantities["omega5/omega2"].exact == F(40, 120)


def test_an_ordinary_train_without_a_speed_gives_its_train_value():
    text = open(load("compound-train").train.source).read()
    s = solve_train(parse_train(text.replace('speed = 900\nsense = "cw"', "").replace(
        '"omega6/omega2", "omega6"', '"omega6/omega2"'), "c.toml"))
    assert s.quantities["omega6/omega2"].exact == F(-20 * 25, 60 * 75)
    assert "turns per turn of 2" in str(s.figures["train-value"])


def test_power_without_a_speed_is_refused():
    with pytest.raises(InputError, match="power gives its torque through its speed"):
        parse_train(simple(given="member = 2\npower = 100"), "t.toml")


# ----- two given speeds --------------------------------------------------------------------------
def two(a, sa, b, sb, sun=30, planet=20, ring=70, fixed=None, find='["omega2", "omega3", '
        '"omega4", "omega5"]'):
    text = simple(sun, planet, ring, fixed=0, given=f"member = {a}\nspeed = {sa}\n\n"
                  f"[[input]]\nmember = {b}\nspeed = {sb}", find=find)
    text = text.replace("[input]\nmember", "[[input]]\nmember", 1)
    return text.replace("fixed = 0\n", "" if fixed is None else f"fixed = {fixed}\n")


def test_the_arm_and_the_sun_both_turning_give_the_ring_by_willis():
    """The bundled example: ω4 = ω5 − (N2/N4)(ω2 − ω5) = −100 − (30/70)·300 = −1600/7 rpm,
    ω3 = ω5 − (N2/N3)(ω2 − ω5) = −100 − (30/20)·300 = −550 rpm."""
    s = solve_train(load("two-speeds-arm-and-sun"))
    q = s.quantities
    assert q["omega4"].exact == F(-1600, 7) and q["omega3"].exact == F(-550)
    assert s.passed and s.found.table.weights == (F(-100), F(-300))


@settings(max_examples=40, deadline=None)
@given(st.integers(12, 60), st.integers(12, 40), st.integers(-3000, 3000).filter(bool),
       st.integers(-3000, 3000))
def test_a_sun_and_a_ring_both_driven_give_the_arm_as_their_weighted_mean(sun, planet, w2, w4):
    """With the sun and the ring both driven, Willis (ω4 − ω5)/(ω2 − ω5) = −N2/N4 gives
    ω5 = (N2·ω2 + N4·ω4)/(N2 + N4)."""
    ring = sun + 2 * planet
    q = solve_train(parse_train(two(2, w2, 4, w4, sun, planet, ring), "t.toml")).quantities
    assert q["omega5"].exact == F(sun * w2 + ring * w4, sun + ring)
    assert all(v.exact == v.reference for v in q.values())


@pytest.mark.parametrize("edit, words", [
    (dict(fixed=4), "member 4 is fixed and two speeds are given"),
    (dict(b=2), "turn together"),
])
def test_two_speeds_that_cannot_hold_are_refused_in_one_line(edit, words):
    args = dict(a=2, sa=100, b=5, sb=-50) | {k: v for k, v in edit.items() if k != "fixed"}
    text = two(args["a"], args["sa"], args["b"], args["sb"], fixed=edit.get("fixed"))
    with pytest.raises(InputError) as e:
        parse_train(text, "t.toml")
    assert words in str(e.value) and str(e.value).startswith("t.toml:")
    assert "\n" not in str(e.value)


def test_two_speeds_on_an_ordinary_train_are_refused():
    text = open(load("compound-train").train.source).read().replace(
        "[input]", "[[input]]").replace('sense = "cw"', 'sense = "cw"\n\n[[input]]\nmember = 6\n'
                                        'speed = 100')
    with pytest.raises(InputError, match=r"^c\.toml:\d+: the train has 1 degree of freedom .* "
                                         r"give one \[\[input\]\], not two$"):
        parse_train(text, "c.toml")


# ----- torques and power --------------------------------------------------------------------------
def test_power_in_kw_with_an_efficiency_gives_exact_torques_over_pi(tmp_path):
    """The bundled gear box: T2 = 7500/(1440·2π/60) = 625/(4π) N·m, T4 = −0.95·5·T2 =
    −11875/(16π), T1 = −(T2 + T4) = 9375/(16π): exact fractions of the data over π."""
    s = solve_train(load("gearbox-power-efficiency"))
    q = s.quantities
    assert q["omega4"].exact == F(1440, 5)
    assert (q["torque2"].exact, q["torque4"].exact, q["torque1"].exact) == (
        F(625, 4), F(-11875, 16), F(9375, 16))
    assert all(q[t].over_pi and q[t].exact == q[t].reference for t in ("torque2", "torque4",
                                                                       "torque1"))
    # 1e-15: the float of an exact fraction over π, a rounding or two
    assert q["torque4"].si == pytest.approx(-11875 / 16 / 3.141592653589793, rel=1e-15)
    s.write(tmp_path)
    data = json.loads((tmp_path / "results.json").read_text())["quantities"]
    assert data["torque1"]["exact"] == "9375/(16*pi)"
    assert data["torque2"]["exact"] == "625/(4*pi)"


def test_a_decimal_power_keeps_its_torques_fractions_of_its_digits():
    """The issue's holding torque came out as 15452595849824865/281474976710656, a float's
    binary fraction; the input's torque is 30·P/n over π with P as written."""
    text = (simple(given="member = 2\nspeed = 1800\npower = 3769.911184307752",
                   find='["torque5", "torque4"]'))
    q = solve_train(parse_train(text, "t.toml")).quantities
    assert q["torque5"].exact == -F("3769.911184307752") * 30 / 1800 * 3   # ω2/ω5 = 3
    assert q["torque4"].exact.denominator % 2 ** 20 != 0


@settings(max_examples=40, deadline=None)
@given(st.integers(12, 60), st.integers(12, 40), st.integers(-3000, 3000).filter(bool),
       st.integers(-3000, 3000), st.integers(1, 500))
@example(sun=12, planet=12, w2=1, w5=0, torque=1)   # the arm given at rest holds the train
def test_two_speeds_share_the_torque_as_the_teeth_do(sun, planet, w2, w5, torque):
    """With no losses a simple epicyclic's torques stand as T2 : T4 : T5 = N2 : N4 :
    −(N2 + N4), whatever its speeds: the sun driven by T, the ring takes T·N4/N2 and the arm
    the rest (given at rest too, holding the train as a fixed arm would)."""
    ring = sun + 2 * planet
    text = two(2, w2, 5, w5, sun, planet, ring, find='["torque4", "torque5"]')
    text = text.replace(f"speed = {w2}", f"speed = {w2}\ntorque = {torque}", 1)
    s = solve_train(parse_train(text, "t.toml"))
    if s.found.speeds[4] == s.found.speeds[5]:          # the train turns locked: no split
        return
    t2 = torque if w2 > 0 else -torque
    assert s.quantities["torque4"].exact == F(t2 * ring, sun)
    assert s.quantities["torque5"].exact == -F(t2 * (sun + ring), sun)
    assert s.passed


@pytest.mark.parametrize("value, words", [("95", "write 0.95"), ("0", "0 < efficiency ≤ 1"),
                                          ('"high"', "must be a number")])
def test_a_bad_efficiency_is_refused_at_its_line(value, words):
    text = "efficiency = " + value + "\n" + simple(given="member = 2\nspeed = 10\ntorque = 5",
                                                  find='["torque5", "torque4"]')
    with pytest.raises(InputError, match=r"^t\.toml:1: ") as e:
        parse_train(text, "t.toml")
    assert words in str(e.value)


# ----- teeth the data imply ----------------------------------------------------------------------
def test_the_sun_s_teeth_from_its_diameter_and_the_ring_s_from_the_coaxial_condition():
    """The bundled example: N2 = d/m = 80/4 = 20, N1 = N2 + 2·N3 = 80, so the arm turns
    1000·N2/(N1 + N2) = 200 rpm."""
    s = solve_train(load("teeth-implied"))
    q = s.quantities
    assert (q["teeth1"].exact, q["teeth2"].exact) == (80, 20)
    assert q["teeth1"].reference == 80 and q["teeth2"].reference == 20
    assert q["omega4"].exact == 200 and s.passed
    assert "N1 = 80" in s.steps() and "N2 = d/m = 80/4 = 20" in s.steps()
    heads, rows = s._table()
    assert rows[0][1][:2] == ["(80)", "(20)"]          # found teeth, in brackets


@settings(max_examples=40, deadline=None)
@given(st.integers(12, 80), st.integers(12, 60), st.sampled_from(["ring", "planet", "sun"]))
def test_the_coaxial_condition_gives_the_one_tooth_count_left_out(sun, planet, left):
    """N_ring = N_sun + 2·N_planet, whichever of the three is left out (the planet's only
    where N_ring − N_sun is even: else refused as no whole number)."""
    ring = sun + 2 * planet
    counts = {"sun": sun, "planet": planet, "ring": ring}
    text = simple(sun, planet, ring, find='["teeth2", "teeth3", "teeth4", "omega5"]')
    number = {"sun": 2, "planet": 3, "ring": 4}[left]
    text = text.replace(f"number = {number}\nteeth = {counts[left]}\n", f"number = {number}\n")
    q = solve_train(parse_train(text, "t.toml")).quantities
    assert [q[f"teeth{n}"].exact for n in (2, 3, 4)] == [sun, planet, ring]
    assert q[f"teeth{number}"].reference == counts[left]
    assert q["omega5"].exact == F(100 * sun, sun + ring)


def test_an_odd_ring_less_sun_gives_no_whole_planet_and_is_refused():
    text = simple(20, 20, 61).replace("number = 3\nteeth = 20\n", "number = 3\n")
    with pytest.raises(InputError, match=r"^t\.toml:\d+: the coaxial condition .* gives gear 3 "
                                         r"20\.5 teeth, not a whole number"):
        parse_train(text, "t.toml")


SERIES = """name = "ring A, planets B and C in series, sun D"
fixed = 1
[[gear]]
number = 1
teeth = {n1}
[[gear]]
number = 2
teeth = {n2}
carrier = 5
[[gear]]
number = 3
teeth = {n3}
carrier = 5
[[gear]]
number = 4
teeth = {n4}
[arm]
number = 5
[[mesh]]
gears = [2, 1]
kind = "internal"
[[mesh]]
gears = [2, 3]
[[mesh]]
gears = [3, 4]
[input]
member = 5
speed = 100
[ask]
find = ["teeth1", "teeth2", "teeth3", "teeth4", "omega3"]
"""


@settings(max_examples=30, deadline=None)
@example(40, 30, 25, 3)                   # the books' idler planet: N_C = (150 − 40 − 50)/2
@given(st.integers(12, 60), st.integers(12, 40), st.integers(12, 40), st.sampled_from([1, 2,
                                                                                        3, 4]))
def test_the_coaxial_condition_through_planets_in_series_gives_the_count_left_out(
        sun, idler, planet, left):
    """Sun D, planet C, planet B, ring A in series on one arm: N_A = N_D + 2·N_C + 2·N_B,
    whichever of the four is left out; the reference finds it from the carrier radii, and
    ω_C − ω_a = −(N_A/N_C)(0 − ω_a) with A fixed (exact fractions: tolerance 0)."""
    ring = sun + 2 * idler + 2 * planet
    counts = {1: ring, 2: planet, 3: idler, 4: sun}
    text = SERIES.format(**{f"n{n}": ("…" if n == left else c) for n, c in counts.items()})
    text = text.replace("teeth = …\n", "")
    s = solve_train(parse_train(text, "t.toml"))
    q = s.quantities
    assert [q[f"teeth{n}"].exact for n in (1, 2, 3, 4)] == [ring, planet, idler, sun]
    assert q[f"teeth{left}"].reference == counts[left]
    assert q["omega3"].exact == 100 + F(ring, idler) * 100 and s.passed
    assert "through the planets in series" in s.steps() and f"N{left} = {counts[left]}" in \
        s.steps()


def test_a_reverted_train_s_last_gear_from_its_coaxial_shafts():
    """An ordinary reverted train, 2 → 3 = 4 → 5 with 2 and 5 on one axis: N5 = N2 + N3 −
    N4 = 20 + 60 − 25 = 55, and e = (20·25)/(60·55) = 5/33."""
    text = """coaxial = [2, 5]
[[gear]]
number = 2
teeth = 20
[[gear]]
number = 3
teeth = 60
[[gear]]
number = 4
teeth = 25
[[gear]]
number = 5
[[shaft]]
members = [3, 4]
[[mesh]]
gears = [2, 3]
[[mesh]]
gears = [4, 5]
[input]
member = 2
[ask]
find = ["teeth5", "omega5/omega2"]
"""
    q = solve_train(parse_train(text, "r.toml")).quantities
    assert q["teeth5"].exact == 55 == q["teeth5"].reference
    assert q["omega5/omega2"].exact == F(20 * 25, 60 * 55)


@pytest.mark.parametrize("old, new, words", [
    ("number = 3\nteeth = 20\n", "number = 3\n", None),
    ("number = 2\nteeth = 40\n", "number = 2\ndiameter = 81\nmodule = 2\n",
     "is 40.5 teeth, not a whole number"),
    ("number = 2\nteeth = 40\n", "number = 2\nteeth = 40\ndiameter = 84\nmodule = 2\n",
     "make a pitch diameter of 80 mm, not 84"),
])
def test_teeth_nothing_gives_are_refused_at_the_gear(old, new, words):
    text = simple().replace(old, new)
    if words is None:                    # the planet's from the ring's and the sun's: fine
        text = text.replace("number = 4\nteeth = 80\n", "number = 4\n")
        words = "gear 3 needs its teeth"
    with pytest.raises(InputError) as e:
        parse_train(text, "t.toml")
    assert words in str(e.value) and str(e.value).startswith("t.toml:")


# ----- identical planets listed as gears ---------------------------------------------------------
def test_two_identical_planets_listed_are_two_planets_turning_alike():
    """The bundled example: ω3 = 600·N2/(N1 + N2) = 1200/7 rpm, ω4 = ω3 − (N2/N4)(ω2 − ω3)
    = −400 rpm; the second planet 5, solved by Willis as a gear of its own, turns so too."""
    s = solve_train(load("two-planets-listed"))
    q = s.quantities
    assert q["omega3"].exact == F(1200, 7)
    assert q["omega4"].exact == q["omega5"].exact == F(-400) == q["omega5"].reference
    assert s.train.planets == 2 and s.exercise.twins == ((5, 4),) and s.passed


@settings(max_examples=30, deadline=None)
@given(st.integers(6, 40), st.integers(6, 30), st.integers(2, 4))
def test_k_planets_listed_count_as_planets_k(half_sun, planet, k):
    """k copies of the planet fold into planets = k, the last copy turning as the first:
    with the ring fixed, Willis gives ω_a = ω2·N2/(N2 + N_ring) and ω_p = ω_a(1 − N_ring/N_p)."""
    sun = 2 * half_sun * k            # sun + ring a multiple of k (the assembly condition)
    ring = sun + 2 * planet
    if (sun + ring) % k:
        return
    copies = "".join(f"[[gear]]\nnumber = {10 + i}\nteeth = {planet}\ncarrier = 5\n\n"
                     for i in range(k - 1))
    meshes = "".join(f"[[mesh]]\ngears = [2, {10 + i}]\n\n[[mesh]]\ngears = [{10 + i}, 4]\n"
                     'kind = "internal"\n\n' for i in range(k - 1))
    text = simple(sun, planet, ring, find=f'["omega5", "omega3", "omega{8 + k}"]').replace(
        "[arm]", copies + meshes + "[arm]")
    try:
        s = solve_train(parse_train(text, "t.toml"))
    except InputError as e:                  # k planets too big to fit round the sun
        assert "do not fit round the sun" in str(e)
        return
    arm = F(100 * sun, sun + ring)
    assert s.quantities["omega5"].exact == arm and s.train.planets == k
    assert s.quantities["omega3"].exact == s.quantities[f"omega{8 + k}"].exact == \
        arm * (1 - F(ring, planet))


def test_a_planets_count_that_contradicts_the_copies_listed_is_refused():
    text = open(load("two-planets-listed").train.source).read().replace(
        "[arm]\nnumber = 3", "[arm]\nnumber = 3\nplanets = 3")
    with pytest.raises(InputError, match=r"^p\.toml:\d+: the arm 3 lists 2 identical planets as "
                                         r"gears but says planets = 3"):
        parse_train(text, "p.toml")


# ----- gears of different modules on one arm ----------------------------------------------------
def test_a_differential_of_nearly_equal_gears_is_solved_not_refused():
    """The bundled example: 100 and 101 teeth against a 20/20 planet, 60 and 60.5 modules
    out, no sizes given; Willis: ω3 = ω6(1 − N2·N5/(N4·N3)) = 100·(1 − 100/101) = 100/101."""
    s = solve_train(load("differential-near-equal"))
    assert s.quantities["omega3"].exact == F(100, 101)
    assert s.quantities["omega3/omega6"].exact == F(1, 101) and s.passed
    assert s.diagram is None                 # its radii disagree: the table alone
    assert "gear 2 60 modules from the main axis and gear 3 60.5 modules" in s.steps()


COMPOUND = """fixed = 2
[[gear]]
number = 2
teeth = 40
{m2}
[[gear]]
number = 3
teeth = 20
carrier = 6
[[gear]]
number = 4
teeth = 20
carrier = 6
{m4}
[[gear]]
number = 5
teeth = {n5}
[[shaft]]
members = [3, 4]
[arm]
number = 6
[[mesh]]
gears = [2, 3]
[[mesh]]
gears = [4, 5]
[input]
member = 6
speed = 10
[ask]
find = ["omega5"]
"""


def test_each_mesh_is_held_to_the_arm_s_radius_at_its_own_module():
    """Module 2 on the 40/20 mesh, 3 on the 20/20 one: 2(40 + 20)/2 = 60 mm = 3(20 + 20)/2,
    so the arm carries the compound planet; ω5 = ω6(1 − N2·N4/(N3·N5)) = 10(1 − 2) = −10."""
    s = solve_train(parse_train(COMPOUND.format(m2="module = 2", m4="module = 3", n5=20),
                                "c.toml"))
    assert s.quantities["omega5"].exact == -10 and s.passed


def test_meshes_whose_own_modules_put_the_planet_at_two_radii_are_refused():
    """3(20 + 21)/2 = 61.5 mm against 60 mm: the book's sizes do not fit one arm."""
    with pytest.raises(InputError, match=r"^c\.toml:\d+: the arm cannot carry gear 3 and gear 4 "
                                         r"on one axis: meshing with gear 2 puts it 60 mm from "
                                         r"the main axis, with gear 5 61\.5 mm$"):
        parse_train(COMPOUND.format(m2="module = 2", m4="module = 3", n5=21), "c.toml")


def test_a_speed_ratio_and_a_least_count_give_the_second_pair():
    """The bundled example: (80/20)(N5/N4) = 12, the pinion at the least 18, the wheel
    3·18 = 54; the output 1440/12 = 120 rpm."""
    s = solve_train(load("ratio-least-teeth"))
    q = s.quantities
    assert (q["teeth4"].exact, q["teeth5"].exact, q["omega5"].exact) == (18, 54, 120)
    assert s.passed and "N4 = 18" in s.steps()
    # 12.5 = 4·N5/N4 asks N5/N4 = 25/8: no whole wheel from 18 to 23, so 24 and 75
    text = open(load("ratio-least-teeth").train.source).read().replace("value = 12",
                                                                        "value = 12.5")
    q = solve_train(parse_train(text, "r.toml")).quantities
    assert (q["teeth4"].exact, q["teeth5"].exact) == (24, 75)


@settings(max_examples=40, deadline=None)
@given(st.integers(12, 60), st.integers(12, 60), st.integers(12, 60), st.integers(1, 6))
def test_a_speed_ratio_gives_the_one_count_left_out(n2, n3, n4, k):
    """|ω2/ω5| = (N3/N2)(N5/N4), N5 = k·N4 left out: N5 = ratio·N2·N4/N3."""
    n5 = k * n4
    ratio = F(n3 * n5, n2 * n4)
    text = open(load("ratio-least-teeth").train.source).read().replace(
        "teeth = 20\n", f"teeth = {n2}\n").replace("teeth = 80\n", f"teeth = {n3}\n").replace(
        'name = "pinion"', f'teeth = {n4}\nname = "pinion"').replace(
        "value = 12", f"value = {float(ratio)!r}" if ratio.denominator in (1, 2, 4, 5, 8, 10)
        else "value = 12")
    if f"value = {float(ratio)!r}" not in text:
        return                              # a ratio a decimal cannot write exactly
    q = solve_train(parse_train(text, "r.toml")).quantities
    assert q["teeth5"].exact == n5 == q["teeth5"].reference


@pytest.mark.parametrize("edit, words", [
    (("value = 12", "value = 4.0001"), "no whole counts of 18 teeth or more"),
    (("least_teeth = 18\n", ""), "give the others, or least_teeth for a pair"),
    (('of = "omega2/omega5"', 'of = "omega2/omega9"'), "name the ratio of two members"),
])
def test_a_ratio_that_cannot_give_the_teeth_is_refused(edit, words):
    text = open(load("ratio-least-teeth").train.source).read().replace(*edit)
    with pytest.raises(InputError) as e:
        parse_train(text, "r.toml")
    assert words in str(e.value) and "\n" not in str(e.value)
