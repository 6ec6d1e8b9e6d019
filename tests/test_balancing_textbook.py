"""Balancing as the textbooks ask it: a balancing mass's angle, the greatest unbalanced force
or couple of an engine and the crank angle where it comes, each held to its closed form.

- Two planes between the masses (planes measured from A: X 0.1, B 0.3, C 0.4, Y 0.5, D 0.7 m;
  A, B, C, D 200, 300, 400, 200 kg at 80, 70, 60, 80 mm, 0°, 45°, 115°, 235°): couples about
  X by hand, then forces; the books read 184 kg at 346° in Y and 356 kg at 213° in X off
  their drawings.
- An in-line engine's sum along the stroke at a turn θ is Re(R·e^{iθ}), R the polygon's
  resultant: greatest, |R|, at θ = −arg R (every 180°; the secondary's every 90° at
  2θ = −arg S). The three-cylinder engine with cranks 0°, 120°, 240° in planes 0, a, 2a has
  a primary couple about the centre ∝ a·(cos(θ + 240°) − cos θ) = −√3·a·sin(θ + 120°),
  greatest at θ = 150°.
Tolerances: sums of a handful of products of exact data, 1e-12 relative (1e-9 degree for an
angle of a closing side a few hundred times shorter than its vectors).
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.constructions.reference.balance import vee_resultants
from tarsim.exercises.balancing.balance_solution import solve_balance
from tarsim.exercises.balancing.rotor_file import parse_balance
from tarsim.exercises.catalog import bundled, load

TWO_PLANES = """
[units]
length = "mm"
speed = "rpm"
[rotor]
speed = 100
[[mass]]
name = "A"
mass = 200
radius = 80
angle = 0
plane = 0
[[mass]]
name = "B"
mass = 300
radius = 70
angle = 45
plane = 300
[[mass]]
name = "C"
mass = 400
radius = 60
angle = 115
plane = 400
[[mass]]
name = "D"
mass = 200
radius = 80
angle = 235
plane = 700
[[balance]]
name = "X"
plane = 100
radius = 100
[[balance]]
name = "Y"
plane = 500
radius = 100
"""


def _cis(deg: float) -> complex:
    return complex(math.cos(math.radians(deg)), math.sin(math.radians(deg)))


def test_balancing_masses_between_the_planes_give_their_angles():
    """(m r l)_Y = −Σ mᵢrᵢlᵢ about X, (m r)_X = −Σ mᵢrᵢ − (m r)_Y; each over 0.1 m."""
    couple = -1.6 + 4.2 * _cis(45) + 7.2 * _cis(115) + 9.6 * _cis(235)
    force = 16 + 21 * _cis(45) + 24 * _cis(115) + 16 * _cis(235)
    in_y = -couple / 0.4
    in_x = -force - in_y
    q = solve_balance(parse_balance(TWO_PLANES, "t.toml")).results["quantities"]
    for plane, v in (("X", in_x), ("Y", in_y)):
        assert q[f"mass_{plane}"]["value"] == pytest.approx(abs(v) / 0.1, rel=1e-12)
        want = math.degrees(math.atan2(v.imag, v.real)) % 360
        assert q[f"angle_{plane}"]["value"] == pytest.approx(want, rel=1e-12)
        assert q[f"angle_{plane}"]["unit"] == "deg"
    assert round(q["mass_Y"]["value"]) == 184 and round(q["angle_Y"]["value"]) == 347
    assert round(q["angle_X"]["value"]) == 213


def _engine(cranks, planes, rod="rod = 400") -> str:
    rows = "".join(f"[[cylinder]]\ncrank = {c}\nplane = {p}\n" for c, p in zip(cranks, planes))
    return (f'[units]\nlength = "mm"\nspeed = "rpm"\n[engine]\nspeed = 1200\ncrank = 100\n'
            f"{rod}\nreciprocating = 20\n{rows}")


def test_three_cylinders_greatest_primary_couple_with_crank_1_at_150_degrees():
    """m·r = 2 kg·m, a = 0.4 m, ω = 40π: the couples √3·a·m·ω²·r and that over n = 4; the
    primary greatest at 150° (−√3·a·sin(θ + 120°) = ±√3·a), the secondary, ∝
    −a·cos 2θ + a·cos(2θ + 480°) = −√3·a·sin(2θ + 60°), at 2θ + 60° = 90°: 15°."""
    q = solve_balance(parse_balance(_engine((0, 120, 240), (0, 400, 800)), "e.toml")
                      ).results["quantities"]
    f = 20 * 0.1 * (40 * math.pi) ** 2
    assert q["primary_couple"]["value"] == pytest.approx(math.sqrt(3) * 0.4 * f, rel=1e-12)
    assert q["primary_couple_at"]["value"] == pytest.approx(150.0, abs=1e-9)
    assert q["secondary_couple_at"]["value"] == pytest.approx(15.0, abs=1e-9)
    assert q["primary_couple_at"]["every_deg"] == 180.0
    assert "primary_force_at" not in q                   # its polygon closes: no greatest


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 359), st.integers(-1000, 1000)), min_size=2,
                max_size=6, unique_by=lambda c: c[1]))
def test_each_greatest_is_where_the_sum_along_the_stroke_reaches_its_size(cylinders):
    """At the crank angle given, the sum along the stroke, Σ aᵢ·cos(k·(θ + θᵢ)) with θ the
    shaft's turn (crank 1's angle less θ₁), is ± the polygon's greatest, to rounding (the
    sum of |aᵢ| over a million: the closing side's angle is read to its rounding)."""
    cranks, planes = zip(*cylinders)
    s = solve_balance(parse_balance(_engine(cranks, planes), "e.toml"))
    q = s.results["quantities"]
    e = s.exercise.engine
    centre = (min(e.planes) + max(e.planes)) / 2
    w2 = e.reciprocating * e.crank * e.speed ** 2
    for kind in ("primary_force", "primary_couple", "secondary_force", "secondary_couple"):
        if f"{kind}_at" not in q:
            continue
        k = 1 if kind.startswith("primary") else 2
        arms = [1.0 if kind.endswith("force") else z - centre for z in e.planes]
        turn = math.radians(q[f"{kind}_at"]["value"]) - e.cranks[0]
        along = w2 / (1 if k == 1 else e.rod / e.crank) * math.fsum(
            a * math.cos(k * (turn + t)) for a, t in zip(arms, e.cranks))
        size = w2 * math.fsum(abs(a) for a in arms)
        assert abs(along) == pytest.approx(q[kind]["value"], abs=1e-9 * size), kind


def test_a_single_cylinder_gives_its_greatest_secondary_and_where_the_force_left_peaks():
    """m·ω²·r/n with n = 4.5 (30 kg, 100 mm, 600 rpm); 60 % balanced leaves c·m·ω²·r across
    the stroke, greater than (1 − c)·m·ω²·r along it, so the greatest is at 90°; 30 %
    balanced, at 0°."""
    text = ('[units]\nlength = "mm"\nspeed = "rpm"\n[engine]\nspeed = 600\ncrank = 100\n'
            "rod = 450\nreciprocating = 30\nbalanced = 0.6\nat = 30\n")
    q = solve_balance(parse_balance(text, "e.toml")).results["quantities"]
    f = 30 * 0.1 * (20 * math.pi) ** 2
    assert q["secondary_max"]["value"] == pytest.approx(f / 4.5, rel=1e-12)
    assert q["unbalanced_max_at"]["value"] == 90.0
    q = solve_balance(parse_balance(text.replace("0.6", "0.3"), "e.toml")).results["quantities"]
    assert q["unbalanced_max_at"]["value"] == 0.0
    assert q["unbalanced_max"]["value"] == pytest.approx(0.7 * f, rel=1e-12)



TWO_CYLINDERS = """
[units]
length = "mm"
speed = "rpm"
[engine]
speed = 300
crank = 150
reciprocating = 120
revolving = 80
balanced = 0.6666666666666666
[[cylinder]]
crank = 0
plane = 450
[[cylinder]]
crank = 90
plane = 1050
[[balance]]
name = "A"
plane = 0
radius = 500
[[balance]]
name = "B"
plane = 1500
radius = 500
"""


def test_an_inline_engines_balance_masses_take_its_revolving_and_a_share_of_its_reciprocating():
    """Each cylinder counts as 80 + ⅔·120 = 160 kg at 0.15 m, 24 kg·m, cranks 0° and 90° at
    0.45 and 1.05 m from A. Couples about A: (m r)_B = −(24·0.45, 24·1.05)/1.5 = (−7.2,
    −16.8); forces: (m r)_A = −(24, 24) − (m r)_B = (−16.8, −7.2); each mass |m r|/0.5."""
    s = solve_balance(parse_balance(TWO_CYLINDERS, "e.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    for plane, (x, y) in (("A", (-16.8, -7.2)), ("B", (-7.2, -16.8))):
        assert q[f"mass_{plane}"]["value"] == pytest.approx(math.hypot(x, y) / 0.5, rel=1e-12)
        assert q[f"angle_{plane}"]["value"] == pytest.approx(
            math.degrees(math.atan2(y, x)) % 360, rel=1e-12)
    # the engine's own polygons stand beside them: the primary force m·ω²·r·√2
    assert q["primary_force"]["value"] == pytest.approx(
        120 * 0.15 * (10 * math.pi) ** 2 * math.sqrt(2), rel=1e-12)
    assert {"space", "couple-polygon", "force-polygon", "primary-force"} <= set(s.figures)


@pytest.mark.parametrize("old, new, words", [
    ("[[balance]]\nname = \"A\"\nplane = 0\nradius = 500\n[[balance]]\nname = \"B\"\n"
     "plane = 1500\nradius = 500\n", "", "balanced is what balance masses take: give the "
                                         "[[balance]] planes they go in"),
    ("revolving = 80\nbalanced = 0.6666666666666666\n", "",
     "give revolving = … or balanced = …"),
    ("revolving = 80\n", "revolving = 80\nbalance_radius = 500\n",
     "the balance masses of cylinders in line go in [[balance]] planes"),
    ('name = "A"', 'name = "1"', "balancing plane 1 has the name of cylinder 1"),
    ("[[cylinder]]\ncrank = 90\nplane = 1050\n", "", "a single cylinder's balance mass is "
                                                     "given in [engine] as balance_radius"),
])
def test_an_engines_balance_masses_are_refused_in_one_line_where_they_cannot_be(old, new, words):
    assert old in TWO_CYLINDERS
    with pytest.raises(InputError) as e:
        parse_balance(TWO_CYLINDERS.replace(old, new, 1), "e.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("e.toml:") and words in message, message


THREE_MASSES = """
[units]
length = "mm"
[rotor]
[[mass]]
name = "1"
mass = 8
radius = 80
angle = 0
[[mass]]
name = "2"
mass = 12
radius = 100
angle = "?"
between = [0, 180]
[[mass]]
name = "3"
mass = 15
radius = 60
angle = "?"
"""


@pytest.mark.parametrize("between, sign", [("[0, 180]", 1), ("[180, 360]", -1),
                                           ("[200, 300]", -1), ("[-90, 170]", 1)])
def test_between_chooses_the_mirror_image_of_masses_in_balance(between, sign):
    """A triangle of 0.64, 1.2 and 0.9 kg·m: cos θ₂ = (0.9² − 0.64² − 1.2²)/(2·0.64·1.2)
    (law of cosines), θ₂ = ±132.596°; the 15 kg mass closes it, 0.9·e^{iθ₃} = −0.64 −
    1.2·e^{iθ₂}. ``between`` takes the image whose θ₂ it holds; the line says so."""
    cos2 = (0.81 - 0.4096 - 1.44) / 1.536
    theta2 = sign * math.acos(cos2)
    v3 = -0.64 - 1.2 * complex(math.cos(theta2), math.sin(theta2))
    s = solve_balance(parse_balance(THREE_MASSES.replace("[0, 180]", between), "m.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    assert q["angle_2"]["value"] == pytest.approx(math.degrees(theta2) % 360, rel=1e-9)
    assert q["angle_3"]["value"] == pytest.approx(
        math.degrees(math.atan2(v3.imag, v3.real)) % 360, rel=1e-9)
    assert q["angle_2"]["mirror"] == pytest.approx(math.degrees(-theta2) % 360, rel=1e-9)
    assert any("as its between asks" in line for line in s.lines())


def test_with_no_between_the_rule_taken_is_said():
    s = solve_balance(parse_balance(THREE_MASSES.replace("between = [0, 180]\n", ""), "m.toml"))
    assert any(line.startswith("taken: the crossing left of the last tip") for line in s.lines())


@pytest.mark.parametrize("old, new, words", [
    ("[0, 180]", "[300, 350]", "mass 2's angle comes out 227.40° or 132.60°, none between 300° "
                               "and 350°"),
    ("[0, 180]", "[10, 370]", "spans no angle or the whole turn"),
    ("[0, 180]", "180", "between is two angles, [from, to]"),
    ('angle = "?"\nbetween', "angle = 10\nbetween", "its angle is given; leave between out"),
])
def test_a_between_that_cannot_be_held_is_refused_in_one_line(old, new, words):
    assert old in THREE_MASSES
    with pytest.raises(InputError) as e:
        parse_balance(THREE_MASSES.replace(old, new, 1), "m.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("m.toml:") and words in message, message


def test_a_whole_rotor_refuses_between():
    text = TWO_PLANES.replace("angle = 45\n", "angle = 45\nbetween = [0, 90]\n", 1)
    with pytest.raises(InputError, match=r"t.toml:\d+: mass B's between chooses where an "
                                         r"unknown angle comes out"):
        parse_balance(text, "t.toml")


FIRING = """
[units]
length = "mm"
speed = "rpm"
[engine]
speed = 1500
stroke = 200
rod = 400
reciprocating = 5
strokes = 2
firing_order = [1, 4, 2, 3]
[[cylinder]]
plane = 0
[[cylinder]]
plane = 300
[[cylinder]]
plane = 600
[[cylinder]]
plane = 900
"""


def test_a_two_stroke_four_fired_1_4_2_3_leaves_its_couples():
    """Firing every 90°, each crank 90° behind the one fired before: 1 at 0°, 4 at 270°,
    2 at 180°, 3 at 90°. About the centre (arms −0.45, −0.15, 0.15, 0.45 m), by hand: the
    primary couple −0.45 + 0.15 + 0.15i − 0.45i = −0.3 − 0.3i, √2·0.3·m·ω²·r; the secondary
    (2θ: 0, 0, 180, 180°) −0.45 − 0.15 − 0.15 − 0.45 = −1.2, over n = 4."""
    s = solve_balance(parse_balance(FIRING, "e.toml"))
    e = s.exercise.engine
    assert [round(math.degrees(t), 9) for t in e.cranks] == [0, 180, 90, 270]
    q = s.results["quantities"]
    f = 5 * 0.1 * (50 * math.pi) ** 2
    assert q["primary_couple"]["value"] == pytest.approx(math.sqrt(2) * 0.3 * f, rel=1e-12)
    assert q["secondary_couple"]["value"] == pytest.approx(1.2 * f / 4, rel=1e-12)
    assert q["primary_force"]["value"] == 0.0 and q["secondary_force"]["value"] == 0.0
    assert s.lines()[0].startswith("firing order 1-4-2-3, 2-stroke: a cylinder fires every 90°")


def test_a_four_stroke_six_fired_1_5_3_6_2_4_is_in_complete_balance():
    """Every 120°: 1 and 6 at 0°, 5 and 2 at 240°, 3 and 4 at 120°, mirror images about the
    centre, so every force and couple polygon closes (the books' six in line)."""
    rows = "".join(f"[[cylinder]]\nplane = {100 * i}\n" for i in range(6))
    text = (FIRING.split("[[cylinder]]")[0].replace("strokes = 2", "strokes = 4")
            .replace("[1, 4, 2, 3]", "[1, 5, 3, 6, 2, 4]") + rows)
    s = solve_balance(parse_balance(text, "e.toml"))
    assert [round(math.degrees(t), 9) for t in s.exercise.engine.cranks] == [
        0, 240, 120, 120, 240, 0]
    q = s.results["quantities"]
    assert all(q[k]["value"] == 0.0 for k in ("primary_force", "primary_couple",
                                              "secondary_force", "secondary_couple"))


@pytest.mark.parametrize("old, new, words", [
    ("[1, 4, 2, 3]", "[1, 4, 2, 2]", "firing_order must name each of the 4 [[cylinder]] tables "
                                     "once"),
    ("[1, 4, 2, 3]", '"1-4-2-3"', "firing_order is the cylinders' numbers in the order"),
    ("strokes = 2\n", "", "with a firing order, give strokes = 4"),
    ("strokes = 2\n", "strokes = 3\n", "with a firing order, give strokes = 4"),
    ("firing_order = [1, 4, 2, 3]\n", "", "strokes goes with firing_order"),
    ("plane = 300", "crank = 90\nplane = 300", "cylinder 2 gives its crank and [engine] its "
                                               "firing order"),
])
def test_a_firing_order_that_cannot_set_the_cranks_is_refused_in_one_line(old, new, words):
    assert old in FIRING
    with pytest.raises(InputError) as e:
        parse_balance(FIRING.replace(old, new, 1), "e.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("e.toml:") and words in message, message


LOCOMOTIVE = """
[units]
length = "mm"
[engine]
road_speed = 60
wheel_diameter = 1800
crank = 325
reciprocating = 330
revolving = 300
balanced = 0.6666666666666666
[[cylinder]]
crank = 0
plane = 450
[[cylinder]]
crank = 90
plane = 1050
[[balance]]
name = "A"
plane = 0
radius = 650
[[balance]]
name = "B"
plane = 1500
radius = 650
"""


def test_an_uncoupled_locomotive_gives_its_hammer_blow_tractive_force_and_swaying_couple():
    """The books' locomotive: cranks at 90°, r = 0.325 m, wheels 1.5 m apart and 1.8 m
    across, cylinders 0.6 m apart, 330 kg reciprocating and 300 kg rotating a cylinder,
    60 km/h, ⅔ balanced at 0.65 m. By hand: ω = (60/3.6)/0.9; each cylinder 520 kg at 0.325 m
    (169 kg·m) gives (m r)_B = −169·(0.45, 1.05)/1.5, 198.0 kg; the hammer blow of c·m's share,
    ⅔·330·0.325·|(0.45, 1.05)|/1.5·ω² (18.67 kN); the tractive force ±√2·(1 − c)·m·ω²·r
    (17.34 kN) and the swaying couple ±(0.6/√2)·(1 − c)·m·ω²·r (5.20 kN·m)."""
    s = solve_balance(parse_balance(LOCOMOTIVE, "l.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    w = (60 / 3.6) / 0.9
    f = (1 / 3) * 330 * 0.325 * w ** 2
    assert s.exercise.engine.speed == pytest.approx(w, rel=1e-15)
    assert q["mass_A"]["value"] == pytest.approx(169 * math.hypot(1.05, 0.45) / 1.5 / 0.65,
                                                 rel=1e-12)
    for plane in "AB":
        assert q[f"hammer_blow_{plane}"]["value"] == pytest.approx(
            2 / 3 * 330 * 0.325 * math.hypot(0.45, 1.05) / 1.5 * w ** 2, rel=1e-12)
    assert q["primary_force_left"]["value"] == pytest.approx(math.sqrt(2) * f, rel=1e-12)
    assert q["primary_couple_left"]["value"] == pytest.approx(0.6 / math.sqrt(2) * f,
                                                              rel=1e-12)
    assert round(q["hammer_blow_A"]["value"]) == 18674


def test_a_locomotives_wheels_lift_where_the_hammer_blow_reaches_the_dead_load():
    """P = 40 kN on each wheel: B·ω²·b = P at ω = √(P/(B·b)), B·b = ⅔·330·0.325·|(0.45,
    1.05)|/1.5 kg·m; on 1.8 m wheels v = ω·0.9 m/s, ×3.6 km/h (87.81 km/h)."""
    text = LOCOMOTIVE.replace("wheel_diameter = 1800\n", "wheel_diameter = 1800\n"
                                                         "dead_load = 40000\n")
    q = solve_balance(parse_balance(text, "l.toml")).results["quantities"]
    w = math.sqrt(40000 / (2 / 3 * 330 * 0.325 * math.hypot(0.45, 1.05) / 1.5))
    assert q["lift_speed"]["value"] == pytest.approx(w, rel=1e-12)
    assert q["lift_road_speed"]["value"] == pytest.approx(w * 0.9 * 3.6, rel=1e-12)
    assert round(q["lift_road_speed"]["value"], 2) == 87.81
    with pytest.raises(InputError, match=r"l.toml:\d+: dead_load is what a hammer blow lifts"):
        parse_balance(text.replace("balanced = 0.6666666666666666\n", ""), "l.toml")


@pytest.mark.parametrize("old, new, words", [
    ("wheel_diameter = 1800\n", "", "give their wheel_diameter with it"),
    ("road_speed = 60\n", "road_speed = 60\nspeed = 100\n", "not both"),
    ("wheel_diameter = 1800", "wheel_diameter = 0", "the wheel diameter must be positive"),
])
def test_a_locomotives_speed_given_half_is_refused_in_one_line(old, new, words):
    with pytest.raises(InputError) as e:
        parse_balance(LOCOMOTIVE.replace(old, new, 1), "l.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("l.toml:") and words in message, message


def test_balance_masses_for_revolving_masses_alone_leave_no_hammer_blow():
    """balanced = 0: the whole reciprocating mass is left, and there is no share of it in
    the balance masses to strike the rails: no hammer blow, nothing written of it."""
    q = solve_balance(parse_balance(LOCOMOTIVE.replace("balanced = 0.6666666666666666\n", ""),
                                    "l.toml")).results["quantities"]
    assert "mass_A" in q and not any(k.startswith(("hammer", "primary_force_left")) for k in q)


VEE = """
[units]
length = "mm"
speed = "rpm"
[engine]
speed = 3000
crank = 50
rod = 200
reciprocating = 1.5
vee = 90
at = 30
"""


def test_a_v_twin_at_90_degrees_has_a_constant_primary_and_its_secondary_across():
    """α = 45°: the primary 2F·cos²α·cos θ along and 2F·sin²α·sin θ across, F = m·ω²·r, so F
    at every angle; the secondary 2(F/n)·cos α·cos 2α·cos 2θ = 0 along and
    2(F/n)·sin α·sin 2α·sin 2θ = √2·(F/n)·sin 2θ across, greatest √2·F/n at 45°."""
    s = solve_balance(parse_balance(VEE, "v.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    f = 1.5 * 0.05 * (100 * math.pi) ** 2
    assert q["primary_resultant"]["value"] == pytest.approx(f, rel=1e-12)
    assert q["primary_max"]["value"] == pytest.approx(f, rel=1e-12)
    assert q["primary_max"]["constant"] is True and "primary_max_at" not in q
    assert q["secondary_resultant"]["value"] == pytest.approx(
        math.sqrt(2) * f / 4 * math.sin(math.radians(60)), rel=1e-12)
    assert q["secondary_max"]["value"] == pytest.approx(math.sqrt(2) * f / 4, rel=1e-12)
    assert q["secondary_max_at"]["value"] == 45.0
    assert set(s.figures) == {"forces"}


def test_a_60_degree_v_has_its_greatest_primary_on_the_centre_line_and_a_constant_secondary():
    """α = 30°: primary 1.5F·cos θ along, 0.5F·sin θ across, greatest 1.5F at 0°; secondary
    2·cos 30°·cos 60° = 2·sin 30°·sin 60° = √3/2, so (√3/2)·F/n at every angle."""
    q = solve_balance(parse_balance(VEE.replace("vee = 90", "vee = 60"), "v.toml")
                      ).results["quantities"]
    f = 1.5 * 0.05 * (100 * math.pi) ** 2
    assert q["primary_max"]["value"] == pytest.approx(1.5 * f, rel=1e-12)
    assert q["primary_max_at"]["value"] == 0.0
    assert q["secondary_max"]["value"] == pytest.approx(math.sqrt(3) / 2 * f / 4, rel=1e-12)
    assert q["secondary_max"]["constant"] is True
    assert q["secondary_min"]["value"] == pytest.approx(math.sqrt(3) / 2 * f / 4, rel=1e-12)
    assert q["secondary_min"]["constant"] is True and "secondary_min_at" not in q


def test_b3_vtwin60():
    """The books' 60° V-twin, 1.5 kg a cylinder, stroke 100 mm, rod 250 mm, 2500 rpm, asked
    its greatest and least primary and secondary forces and where they come: the primary's
    tip runs round an ellipse of semi-axes 2F·cos²30° = 1.5F (along, θ = 0°) and
    2F·sin²30° = 0.5F (across, θ = 90°), F = m·ω²·r; the secondary (√3/2)·F/n at every
    angle. 1e-12: a few roundings of two products."""
    text = ('[units]\nlength = "mm"\nspeed = "rpm"\n[engine]\nspeed = 2500\nstroke = 100\n'
            "rod = 250\nreciprocating = 1.5\nvee = 60\nat = 0\n")
    s = solve_balance(parse_balance(text, "b3.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    f = 1.5 * 0.05 * (2500 * math.pi / 30) ** 2
    assert q["primary_max"]["value"] == pytest.approx(1.5 * f, rel=1e-12)
    assert q["primary_max_at"]["value"] == 0.0
    assert q["primary_min"]["value"] == pytest.approx(0.5 * f, rel=1e-12)
    assert q["primary_min_at"]["value"] == 90.0
    assert q["primary_min_at"]["every_deg"] == 180.0
    assert q["secondary_min"]["value"] == pytest.approx(math.sqrt(3) / 2 * f / 5, rel=1e-12)
    assert "the least primary resultant" in "\n".join(s.lines())


@settings(max_examples=40, deadline=None)
@given(st.integers(1, 179), st.integers(0, 359))
def test_a_v_engines_greatest_is_no_less_than_any_angle_gives(vee, at):
    """The greatest resultant, read at an end of the ellipse's axes, against the resultant
    sampled every half degree by the closed form: none above it, and one within the
    sampling's reach (1 − cos of a quarter degree, doubled for 2θ)."""
    s = solve_balance(parse_balance(VEE.replace("vee = 90", f"vee = {vee}")
                                    .replace("at = 30", f"at = {at}"), "v.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    e = s.exercise.engine
    sampled = [vee_resultants(e, math.radians(d / 2)) for d in range(720)]
    for k, name in enumerate(("primary", "secondary")):
        top = max(v[k] for v in sampled)
        most = q[f"{name}_max"]["value"]
        assert top <= most * (1 + 1e-12)
        assert top >= most * (1 - 4 * (1 - math.cos(math.radians(0.5))))
        # the least likewise, from below: none under it (to the rounding of the sums, at
        # the size of the greatest), one within the sampling's reach of the greatest
        bottom = min(v[k] for v in sampled)
        least = q[f"{name}_min"]["value"]
        assert bottom >= least - 1e-12 * most
        assert bottom <= least + most * 4 * (1 - math.cos(math.radians(0.5)))
        if f"{name}_min_at" in q:
            assert vee_resultants(e, math.radians(q[f"{name}_min_at"]["value"]))[k] == \
                pytest.approx(least, abs=1e-12 * most)


@pytest.mark.parametrize("old, new, words", [
    ("vee = 90", "vee = 180", "the V's angle between its cylinders' lines is between 0° and 180°"),
    ("at = 30", "at = 30\n[[cylinder]]\ncrank = 0", "a V engine's two cylinders work on one crank"),
    ("at = 30", "at = 30\nbalanced = 0.5", "balanced is not taken for a V engine"),
])
def test_a_v_engine_it_cannot_take_is_refused_in_one_line(old, new, words):
    with pytest.raises(InputError) as e:
        parse_balance(VEE.replace(old, new, 1), "v.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("v.toml:") and words in message, message


FOUR_CRANKS = """
[units]
length = "mm"
speed = "rpm"
[engine]
speed = 240
crank = 300
rod = 1200
reciprocating = 400
[[cylinder]]
crank = 0
plane = 0
[[cylinder]]
reciprocating = "?"
crank = "?"
plane = 450
[[cylinder]]
reciprocating = "?"
crank = "?"
plane = 1200
[[cylinder]]
crank = 120
plane = 1800
"""


def test_a_four_crank_engine_in_primary_balance_finds_its_inner_cranks_then_its_secondary():
    """Outer cranks 400 kg at 0° and 120°, planes 0, 0.45, 1.2, 1.8 m. Couples about crank 2's
    plane (r common): m₃·0.75·e^{iθ₃} = 400·0.45 − 400·1.35·e^{i120°}; forces: m₂·e^{iθ₂} =
    −(400 + 400·e^{i120°} + m₃·e^{iθ₃}). The secondary force ω²·r/n·|Σ mᵢ·e^{2iθᵢ}| (ω = 8π,
    n = 4), each mᵢ·e^{2iθᵢ} = (mᵢ·e^{iθᵢ})²/mᵢ."""
    s = solve_balance(parse_balance(FOUR_CRANKS, "e.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    c120 = complex(math.cos(math.radians(120)), math.sin(math.radians(120)))
    v3 = (400 * 0.45 - 400 * 1.35 * c120) / 0.75
    v2 = -(400 + 400 * c120 + v3)
    for name, v in (("2", v2), ("3", v3)):
        assert q[f"mass_{name}"]["value"] == pytest.approx(abs(v), rel=1e-12)
        assert q[f"angle_{name}"]["value"] == pytest.approx(
            math.degrees(math.atan2(v.imag, v.real)) % 360, rel=1e-12)
    assert q["primary_force"]["value"] == 0.0 and q["primary_couple"]["value"] == 0.0
    doubled = 400 + 400 * c120 ** 2 + v2 ** 2 / abs(v2) + v3 ** 2 / abs(v3)
    assert q["secondary_force"]["value"] == pytest.approx(
        (8 * math.pi) ** 2 * 0.3 / 4 * abs(doubled), rel=1e-12)
    assert {"space", "force-polygon", "couple-polygon", "secondary-force"} <= set(s.figures)


def test_cylinders_of_their_own_masses_sum_each_at_its_crank():
    """Two cylinders, 10 kg at 0° and 20 kg at 90°, 0.1 m apart: the primary force
    ω²·r·|10 + 20i| and, about the centre plane, the couple ω²·r·|−0.05·10 + 0.05·20i|."""
    text = FOUR_CRANKS.split("[[cylinder]]")[0].replace("reciprocating = 400\n", "") + (
        "[[cylinder]]\ncrank = 0\nplane = 0\nreciprocating = 10\n"
        "[[cylinder]]\ncrank = 90\nplane = 100\nreciprocating = 20\n")
    q = solve_balance(parse_balance(text, "e.toml")).results["quantities"]
    w = (8 * math.pi) ** 2 * 0.3
    assert q["primary_force"]["value"] == pytest.approx(w * math.hypot(10, 20), rel=1e-12)
    assert q["primary_couple"]["value"] == pytest.approx(w * math.hypot(0.5, 1.0), rel=1e-12)


@pytest.mark.parametrize("old, new, words", [
    ('reciprocating = "?"\ncrank = "?"\nplane = 450', 'crank = "?"\nplane = 450',
     "3 unknowns, but complete primary balance closes the force and couple polygons"),
    ("reciprocating = 400\n", "reciprocating = 400\nbalanced = 0.5\n",
     "balanced is not taken where the cylinders' unknowns"),
])
def test_an_engine_whose_primary_balance_cannot_close_is_refused_in_one_line(old, new, words):
    assert old in FOUR_CRANKS
    with pytest.raises(InputError) as e:
        parse_balance(FOUR_CRANKS.replace(old, new, 1), "e.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("e.toml:") and words in message, message


def test_an_engine_with_every_crank_unknown_is_refused_for_want_of_a_reference():
    rows = "".join(f'[[cylinder]]\ncrank = "?"\nplane = {100 * i}\n' for i in range(4))
    with pytest.raises(InputError, match=r"e.toml:\d+: every crank is unknown: give one "):
        parse_balance(FOUR_CRANKS.split("[[cylinder]]")[0] + rows, "e.toml")


@pytest.mark.parametrize("given, share", [('"60 %"', 0.6), ('"2/3"', 2 / 3), ("0.25", 0.25),
                                          ('"100%"', 1.0)])
def test_the_balanced_fraction_is_taken_as_the_books_give_it(given, share):
    """A percentage is its number over 100, a fraction its quotient: both exact to the
    last bit of the float the division gives."""
    text = ('[units]\nlength = "mm"\nspeed = "rpm"\n[engine]\nspeed = 600\ncrank = 100\n'
            f"reciprocating = 30\nbalanced = {given}\n")
    assert parse_balance(text, "e.toml").engine.balanced == share


def test_a_balanced_percentage_past_the_whole_is_refused():
    text = ('[units]\nlength = "mm"\nspeed = "rpm"\n[engine]\nspeed = 600\ncrank = 100\n'
            'reciprocating = 30\nbalanced = "120 %"\n')
    with pytest.raises(InputError, match=r"e.toml:\d+: the balanced fraction is from 0 to 1, "
                                         r"got 1.2"):
        parse_balance(text, "e.toml")


def test_an_inline_engines_forces_at_a_crank_angle_are_the_cylinders_cos_terms():
    """Three cylinders, cranks 0°, 120°, 240°, planes 0, 0.4, 0.8 m, crank 1 at 45° from the
    i.d.c.: the primary couple about the centre F·(−0.4·cos 45° + 0.4·cos 285°) and the
    secondary F/n·(−0.4·cos 90° + 0.4·cos 570°), F = 20·0.1·(40π)²; the forces cancel."""
    text = _engine((0, 120, 240), (0, 400, 800)).replace("[engine]", "[engine]\nat = 45")
    s = solve_balance(parse_balance(text, "e.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    f = 20 * 0.1 * (40 * math.pi) ** 2
    c = [math.cos(math.radians(d)) for d in (45, 285, 90, 570)]
    assert q["primary_couple_at_theta"]["value"] == pytest.approx(f * 0.4 * (c[1] - c[0]),
                                                                  rel=1e-12)
    assert q["secondary_couple_at_theta"]["value"] == pytest.approx(f / 4 * 0.4 * (c[3] - c[2]),
                                                                    rel=1e-12)
    assert q["primary_force_at_theta"]["value"] == 0.0
    no_at = solve_balance(parse_balance(_engine((0, 120, 240), (0, 400, 800)), "e.toml"))
    assert not any(k.endswith("_at_theta") for k in no_at.results["quantities"])


ECCENTRICS = """
[units]
length = "mm"
speed = "rpm"
[rotor]
speed = 600
[[mass]]
name = "1"
mass = 0.8
radius = 12
angle = 0
plane = 0
[[mass]]
name = "2"
mass = 0.8
radius = 18
angle = 120
plane = 60
[[mass]]
name = "3"
mass = 0.8
radius = 12
angle = 240
plane = 120
"""


@pytest.mark.parametrize("about, arms", [(None, (-0.06, 0.0, 0.06)), ("0", (0.0, 0.06, 0.12))])
def test_a_rotor_with_no_balancing_plane_gives_its_out_of_balance_force_and_couple(about, arms):
    """Three eccentrics 120° apart, 0.8 kg at 12, 18 and 12 mm, planes 60 mm apart, 600 rpm:
    Σ m r e^{iθ} = 0.0096 + 0.0144·e^{i120°} + 0.0096·e^{i240°}, and the couple Σ m r l e^{iθ}
    about the middle plane (the default) or plane 0 (about = 0); each × (20π)²."""
    text = ECCENTRICS if about is None else ECCENTRICS.replace("speed = 600",
                                                               f"speed = 600\nabout = {about}")
    s = solve_balance(parse_balance(text, "r.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    w2 = (20 * math.pi) ** 2
    mr = (0.0096, 0.0144, 0.0096)
    cis = [_cis(a) for a in (0, 120, 240)]
    force = sum(m * c for m, c in zip(mr, cis))
    couple = sum(m * a * c for m, a, c in zip(mr, arms, cis))
    assert q["unbalanced_force"]["value"] == pytest.approx(abs(force) * w2, rel=1e-12)
    assert q["unbalanced_force"]["angle_deg"] == pytest.approx(
        math.degrees(math.atan2(force.imag, force.real)) % 360, rel=1e-12)
    assert q["unbalanced_couple"]["value"] == pytest.approx(abs(couple) * w2, rel=1e-12)
    assert {"space", "side", "force-polygon", "couple-polygon"} == set(s.figures)


def test_about_with_balancing_planes_is_refused():
    text = TWO_PLANES.replace("speed = 100", "speed = 100\nabout = 0")
    with pytest.raises(InputError, match=r"t.toml:\d+: about is where an out-of-balance couple "):
        parse_balance(text, "t.toml")


def test_a_rod_given_by_its_ratio_to_the_crank_gives_the_secondary_force_its_share():
    """n = l/r = 4.5 as the books give it: the same engine as rod = 450 mm on a 100 mm
    crank, the greatest secondary m·ω²·r/n."""
    text = ('[units]\nlength = "mm"\nspeed = "rpm"\n[engine]\nspeed = 600\ncrank = 100\n'
            "rod_ratio = 4.5\nreciprocating = 30\nat = 30\n")
    q = solve_balance(parse_balance(text, "e.toml")).results["quantities"]
    assert q["secondary_max"]["value"] == pytest.approx(30 * 0.1 * (20 * math.pi) ** 2 / 4.5,
                                                        rel=1e-12)
    for bad, words in (("rod_ratio = 4.5", "must be more than 1"),
                       ("rod_ratio = 4.5\nrod = 450", "not both")):
        with pytest.raises(InputError, match=words):
            parse_balance(text.replace("rod_ratio = 4.5", bad.replace("4.5", "0.5")
                                       if "more" in words else bad), "e.toml")


# ----- a mass's m·r and plane read as one in the couple polygon ------------------------------
def test_b1_four_masses_unknowns():
    """The books' shaft A, B, C, D in complete balance, A's mass and D's mass, angle and
    plane unknown, no speed given. By hand, couples about A's plane (B 0.1 m, C 0.3 m from
    it): D's m·r·l closes them, −(18·0.06·0.1 + 12.5·0.06·0.3·e^{i100°}), which gives D's
    angle; the forces then have two sizes along 190° and θ_D, by Cramer's rule; l_D is
    |m·r·l|/(m_D·0.08). 1e-9: lines meeting at 62.7°, sums of order 1 (the books' 9.669 kg,
    7.911 kg, 366.7 mm and 252.72° to their rounding)."""
    s = solve_balance(load("unknown-plane-and-angle"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    couple = -(18 * 0.06 * 0.1 + 12.5 * 0.06 * 0.3 * _cis(100))
    theta = math.atan2(couple.imag, couple.real)
    target = -(18 * 0.06 + 12.5 * 0.06 * _cis(100))
    ea, ed = 0.08 * _cis(190), 0.08 * complex(math.cos(theta), math.sin(theta))
    det = ea.real * ed.imag - ea.imag * ed.real
    m_a = (target.real * ed.imag - target.imag * ed.real) / det
    m_d = (ea.real * target.imag - ea.imag * target.real) / det
    assert q["mass_A"]["value"] == pytest.approx(m_a, rel=1e-9)
    assert q["mass_D"]["value"] == pytest.approx(m_d, rel=1e-9)
    assert q["angle_D"]["value"] == pytest.approx(math.degrees(theta) % 360, abs=1e-9)
    assert q["plane_D"]["value"] == pytest.approx(abs(couple) / (m_d * 0.08), rel=1e-9)
    # the books' figures, each to half its last digit
    for got, book, half in ((q["mass_A"]["value"], 9.669, 5e-4), (q["mass_D"]["value"], 7.911,
                            5e-4), (q["plane_D"]["value"] * 1000, 366.7, 0.05),
                            (q["angle_D"]["value"], 252.72, 5e-3)):
        assert abs(got - book) <= half, (got, book)
    assert s.exercise.open.speed is None


@pytest.mark.parametrize("flip", [1, -1])
def test_a_plane_found_behind_the_reference_turns_the_angle_half_round(flip):
    """The shaft above mirrored along its axis (B and C at −100 and −300 mm): D's m·r·l
    about A points the other way, its angle read to a half turn; the force polygon gives
    m_D along that line negative, so D is at 252.72° again, its plane −366.7 mm. Its mass,
    angle and plane agree with the unmirrored file's to 1e-9."""
    text = Path(bundled("balancing")["unknown-plane-and-angle"]).read_text(encoding="utf-8")
    text = text.replace("plane = 100\n", f"plane = {100 * flip}\n").replace(
        'plane = "100 + 200"', f"plane = {300 * flip}")
    q = solve_balance(parse_balance(text, "f.toml")).results["quantities"]
    base = solve_balance(load("unknown-plane-and-angle")).results["quantities"]
    assert q["angle_D"]["value"] == pytest.approx(base["angle_D"]["value"], abs=1e-9)
    assert q["mass_D"]["value"] == pytest.approx(base["mass_D"]["value"], rel=1e-9)
    assert q["plane_D"]["value"] == pytest.approx(flip * base["plane_D"]["value"], rel=1e-9)


def test_a_known_m_r_with_its_plane_and_angle_unknown_is_refused():
    """D's mass given, its angle and plane not, with A's mass and angle: the couple polygon
    about A would read |l_D| and θ_D to a half turn that nothing settles (D's force vector
    is then known but for its sign), so it is refused, naming the masses."""
    text = Path(bundled("balancing")["unknown-plane-and-angle"]).read_text(encoding="utf-8")
    text = text.replace('angle = 190                # B to A', 'angle = "?"').replace(
        'mass = "?"                 # found: 7.911 kg', "mass = 7.911")
    with pytest.raises(InputError, match=r"r.toml:\d+: neither polygon has just two unknowns"):
        parse_balance(text, "r.toml")


def test_a_rotor_needs_no_speed_where_nothing_asked_is_a_force():
    """Balancing planes ask masses alone: the four-mass shaft without its speed gives the
    same masses; with no planes the out-of-balance force is m·r·ω², refused in one line
    that names the speed to add."""
    with_speed = solve_balance(parse_balance(TWO_PLANES, "t.toml")).results["quantities"]
    without = solve_balance(parse_balance(TWO_PLANES.replace("speed = 100\n", "", 1),
                                          "t.toml")).results["quantities"]
    for name in ("mass_X", "mass_Y", "angle_X", "angle_Y"):
        assert without[name]["value"] == with_speed[name]["value"]
    with pytest.raises(InputError) as e:
        parse_balance(ECCENTRICS.replace("speed = 600\n", "", 1), "r.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("r.toml:") and \
        "needs speed = …" in message, message


@pytest.mark.parametrize("between, root", [("[0, 180]", -1), ("[180, 360]", 1)])
def test_between_on_a_mass_read_to_a_half_turn_chooses_its_crossing(between, root):
    """The shaft with A's mass 20 kg and its angle unknown: D's m·r·l about A fixes D's line
    (252.72°), and A's 1.6 kg·m arc about the pole, which holds the last tip inside it, cuts
    that line either side of the tip: x² − 2x·Re(T·e^{−iθ}) + |T|² − 1.6² = 0 for D's signed
    m·r along 252.72°, one root each sign. D's between takes the negative root (D at
    72.72°, its plane behind A) or the positive; l_D = |m·r·l|/x. 1e-9: a line cut by an
    arc at some 50°."""
    text = Path(bundled("balancing")["unknown-plane-and-angle"]).read_text(encoding="utf-8")
    text = text.replace('mass = "?"                 # found: 9.669 kg', "mass = 20").replace(
        'angle = 190                # B to A', 'angle = "?"').replace(
        'angle = "?"                # found: 252.72°', f'angle = "?"\nbetween = {between}')
    s = solve_balance(parse_balance(text, "d.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    couple = -(18 * 0.06 * 0.1 + 12.5 * 0.06 * 0.3 * _cis(100))
    line = couple / abs(couple)
    target = -(18 * 0.06 + 12.5 * 0.06 * _cis(100))
    p = (target * line.conjugate()).real
    x = p + root * math.sqrt(p * p - (abs(target) ** 2 - 1.6 ** 2))
    assert q["mass_D"]["value"] == pytest.approx(abs(x) / 0.08, rel=1e-9)
    assert q["angle_D"]["value"] == pytest.approx(
        (math.degrees(math.atan2(line.imag, line.real)) + (180 if x < 0 else 0)) % 360, abs=1e-9)
    assert q["plane_D"]["value"] == pytest.approx(abs(couple) / x, rel=1e-9)
    assert "as its between asks" in "\n".join(s.lines())


@pytest.mark.parametrize("change, words", [
    ({"speed = 600\n": ""}, "[engine] needs speed = …"),
    ({"speed = 600\n": "road_speed = 60\n"}, "give their wheel_diameter with it"),
    ({"speed = 600\n": "speed = 600\nroad_speed = 60\nwheel_diameter = 1800\n"}, "not both"),
])
def test_an_engine_s_speed_missing_or_given_twice_is_named(change, words):
    """Each way an engine's speed can be wrong says which, at the line that makes it so:
    none at all, a road speed with no wheels to turn it into the cranks' speed, both."""
    from tarsim.exercises.templates import template

    text = template("engine")
    for old, new in change.items():
        text = text.replace(old, new, 1)
    with pytest.raises(InputError) as e:
        parse_balance(text, "e.toml")
    assert str(e.value).startswith("e.toml:") and words in str(e.value), str(e.value)


def test_a_wheel_diameter_beside_the_speed_alone_is_refused_as_unused():
    """A wheel diameter turns a road speed into the cranks' speed, or a lift speed into km/h:
    beside a speed alone nothing uses it, and a setting read and dropped is refused."""
    from tarsim.exercises.templates import template

    text = template("engine").replace("speed = 600\n", "speed = 600\nwheel_diameter = 1800\n",
                                      1)
    with pytest.raises(InputError) as e:
        parse_balance(text, "e.toml")
    assert str(e.value).startswith("e.toml:") and "wheel_diameter goes with road_speed" in str(
        e.value), str(e.value)
