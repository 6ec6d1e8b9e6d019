"""A rotor as the books give it in weights and asked its bearings' forces, and a balancing
file's units held to those it knows.

- Weights: the balance weight W_B at r_B balances W_i at r_i when W_B·r_B = |Σ W_i r_i e^{iθ_i}|
  (g divides every term alike, so the closed form needs none).
- Bearings: the loads at bearings L and R from moments about the other,
  F_R = ω²·Σ mᵢrᵢzᵢ e^{iθᵢ}/(z_R − z_L) (zᵢ from L), F_L = ω²·Σ mᵢrᵢ(z_R − zᵢ) e^{iθᵢ}/(z_R − z_L):
  in a two-plane balance in the bearings' planes, the balancing products at ω.
Tolerances: sums of a handful of products of exact data, 1e-12 relative.
"""

from __future__ import annotations

import cmath
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.balancing.balance_solution import solve_balance
from tarsim.exercises.balancing.rotor_file import parse_balance
from tarsim.exercises.catalog import bundled, load

ROTOR = """
[units]
length = "mm"
[rotor]
[[mass]]
mass = 2
radius = 100
angle = 0
[[balance]]
radius = 100
"""


@pytest.mark.parametrize("key", ['mass = "N"', 'weight = "N"', 'foo = "bar"'])
def test_an_unknown_unit_is_refused_at_its_line(key):
    """[units] knows length and speed only: a mass unit ("N") would be silently kg."""
    text = ROTOR.replace('length = "mm"', f'length = "mm"\n{key}')
    with pytest.raises(InputError) as e:
        parse_balance(text, "rotor.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("rotor.toml:4:"), message
    assert f"unknown setting '{key.split()[0]}' in [units]" in message


WEIGHTS = """
[units]
length = "mm"
[rotor]
[[mass]]
weight = 60
radius = 150
angle = 0
[[mass]]
weight = 80
radius = 100
angle = 90
[[mass]]
weight = 100
radius = 75
angle = 210
[[balance]]
name = "B"
radius = 200
"""


def _sum_of_weights() -> complex:
    """Σ Wᵢrᵢ e^{iθᵢ} (N·m) of the books' three weights, g nowhere in it."""
    return sum(w * r * cmath.exp(1j * math.radians(a))
               for w, r, a in ((60, 0.15, 0), (80, 0.1, 90), (100, 0.075, 210)))


def test_three_weights_one_plane_give_the_balance_weight_in_n():
    """W_B·r_B = |Σ Wᵢrᵢ e^{iθᵢ}| at the opposite angle: 24.67 N at 239.49° by hand."""
    s = solve_balance(parse_balance(WEIGHTS, "weights.toml"))
    q = s.results["quantities"]
    total = _sum_of_weights()
    assert s.passed
    assert q["weight_B"]["value"] == pytest.approx(abs(total) / 0.2, rel=1e-12)
    assert q["weight_B"]["unit"] == "N"
    assert q["mass_B"]["value"] == pytest.approx(abs(total) / 0.2 / 9.81, rel=1e-12)
    assert q["angle_B"]["value"] == pytest.approx(
        math.degrees(cmath.phase(-total)) % 360, abs=1e-9)
    assert any("g = 9.81 m/s²" in line for line in s.lines())
    assert "the balance weight in plane B: 24.6661 N at 200 mm" in s.lines()


def test_a_file_of_weights_is_drawn_in_n():
    """The end view and the table give each weight as the file did (60 N, not 6.116 kg), and
    the balance weight found, 24.67 N (|Σ Wᵢrᵢ e^{iθᵢ}|/0.2 to the table's 4 figures)."""
    figures = solve_balance(parse_balance(WEIGHTS, "weights.toml")).figures
    table = [t.text for t in figures["table"].items if hasattr(t, "text")]
    assert "W (N)" in table and "60" in table and "m (kg)" not in table
    assert f"{abs(_sum_of_weights()) / 0.2:.4g}" in table
    assert "m = W/g, g = 9.81 m/s²" in table
    space = [t.text for t in figures["space"].items if hasattr(t, "text")]
    assert "1: 60 N at 150 mm, 0°" in space


def test_a_stated_balance_weight_gives_its_radius():
    """A balance weight of 20 N goes at r_B = |Σ Wᵢrᵢ e^{iθᵢ}|/20."""
    text = WEIGHTS.replace("radius = 200", "weight = 20")
    q = solve_balance(parse_balance(text, "weights.toml")).results["quantities"]
    assert q["radius_B"]["value"] == pytest.approx(abs(_sum_of_weights()) / 20, rel=1e-12)


@pytest.mark.parametrize("old, new, line, words", [
    ("weight = 60", "mass = 6\nweight = 60", 7, "gives its mass (kg) or its weight (N), not both"),
    ("weight = 60", "weight = 0", 6, "needs a positive weight and radius, got 0 N"),
    ("radius = 200", "radius = 200\nweight = 20", 20, "or the mass (or its weight in N"),
    ("[rotor]", "[engine]", 6, "not in an engine's file"),
    ("angle = 210", 'angle = "?"', 6, "not where the masses hold unknowns"),
])
def test_a_bad_weight_is_refused_in_one_line(old, new, line, words):
    with pytest.raises(InputError) as e:
        parse_balance(WEIGHTS.replace(old, new, 1), "weights.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith(f"weights.toml:{line}:"), message
    assert words in message, message


SHAFT = """
[units]
length = "mm"
speed = "rpm"
[rotor]
speed = 200
[[mass]]
mass = 4
radius = 75
angle = 45
plane = 225
[[mass]]
mass = 3
radius = 85
angle = 135
plane = 425
[[mass]]
mass = 2.5
radius = 50
angle = 240
plane = 600
"""
PLANES = """
[[balance]]
name = "L"
plane = 0
radius = 60
[[balance]]
name = "R"
plane = 800
radius = 60
"""
MASSES = ((4, 0.075, 45, 0.225), (3, 0.085, 135, 0.425), (2.5, 0.05, 240, 0.6))


def _bearing_loads() -> tuple[float, float]:
    """|F_L| and |F_R| (N) at 200 rpm, by moments about the other bearing:
    F_R = ω² Σ mᵢrᵢ zᵢ e^{iθᵢ}/0.8, F_L = ω² Σ mᵢrᵢ (0.8 − zᵢ) e^{iθᵢ}/0.8."""
    w2 = (200 * 2 * math.pi / 60) ** 2
    turn = [m * r * cmath.exp(1j * math.radians(a)) for m, r, a, _ in MASSES]
    right = sum(v * z for v, (*_, z) in zip(turn, MASSES)) / 0.8
    left = sum(v * (0.8 - z) for v, (*_, z) in zip(turn, MASSES)) / 0.8
    return abs(left) * w2, abs(right) * w2


def test_a_two_plane_balance_gives_each_planes_force_on_its_bearing():
    """Balance planes in the bearings: each balancing product at ω is the out-of-balance
    force on its bearing, 94.90 N and 48.86 N by hand (Rattan's shaft)."""
    s = solve_balance(parse_balance(SHAFT + PLANES, "shaft.toml"))
    q = s.results["quantities"]
    left, right = _bearing_loads()
    assert s.passed
    assert q["force_L"]["value"] == pytest.approx(left, rel=1e-12)
    assert q["force_R"]["value"] == pytest.approx(right, rel=1e-12)
    assert q["force_L"]["unit"] == "N"
    assert any("m·r·ω² = 94.9019 N" in line for line in s.lines())


def test_a_two_plane_balance_with_no_speed_gives_no_force():
    text = (SHAFT + PLANES).replace("speed = 200\n", "")
    q = solve_balance(parse_balance(text, "shaft.toml")).results["quantities"]
    assert not any(k.startswith("force_") for k in q)


def test_an_unbalanced_rotors_bearings_share_its_force_and_couple():
    """With no balancing plane and [rotor] bearings, the polygons' force and couple shared
    by moments give each bearing the same load as the two-plane sums."""
    text = SHAFT.replace("speed = 200", "speed = 200\nbearings = { L = 0, R = 800 }")
    s = solve_balance(parse_balance(text, "shaft.toml"))
    q = s.results["quantities"]
    left, right = _bearing_loads()
    assert s.passed
    assert q["force_L"]["value"] == pytest.approx(left, rel=1e-12)
    assert q["force_R"]["value"] == pytest.approx(right, rel=1e-12)
    assert any(line.startswith("bearing R at 800 mm: the out-of-balance force 48.855 N")
               for line in s.lines())


def _data(low: float, high: float):
    """Numbers as a book writes them, to 3 decimals (a file refuses sizes below 1e-6)."""
    return st.floats(low, high).map(lambda x: round(x, 3))


@given(st.lists(st.tuples(_data(0.5, 50), _data(10, 200), _data(0, 360), _data(-300, 1100)),
                min_size=1, max_size=5), _data(-200, 300), _data(400, 1200))
@settings(max_examples=40, deadline=None)
def test_bearings_carry_the_whole_force_and_couple(masses, za, zb):
    """Whatever the masses, the bearings' loads (vectors) sum to the out-of-balance force and
    their moments about any plane to its couple: F_L + F_R = ω²Σmr, both to 1e-9 of the sums'
    sizes (a few roundings of each product, divided by the bearings' span)."""
    text = "[units]\nlength = \"mm\"\n[rotor]\nspeed = 10\n" + \
        f"bearings = {{ L = {za!r}, R = {zb!r} }}\n" + "".join(
            f"[[mass]]\nmass = {m!r}\nradius = {r!r}\nangle = {a!r}\nplane = {z!r}\n"
            for m, r, a, z in masses)
    q = solve_balance(parse_balance(text, "rotor.toml")).results["quantities"]
    load = {k: q[f"force_{k}"]["value"] * cmath.exp(1j * math.radians(
        q[f"force_{k}"].get("angle_deg", 0.0))) / 100 for k in "LR"}
    turn = [m * r / 1000 * cmath.exp(1j * math.radians(a)) for m, r, a, _ in masses]
    size = sum(abs(v) * (1 + (abs(z) + abs(za)) / (zb - za)) for v, (*_, z) in
               zip(turn, masses))
    assert abs(load["L"] + load["R"] - sum(turn)) <= 1e-9 * size
    couple = sum(v * z / 1000 for v, (*_, z) in zip(turn, masses))
    assert abs(load["L"] * za / 1000 + load["R"] * zb / 1000 - couple) <= 1e-9 * size * (
        abs(za) + abs(zb)) / 1000


@pytest.mark.parametrize("old, new, words", [
    ("speed = 200", "speed = 200\nbearings = [0, 800]", "names the rotor's two bearings"),
    ("speed = 200", "speed = 200\nbearings = { L = 0, R = 0 }", "same axial position"),
    ("speed = 200", "speed = 200\nbearings = { L = 0, R = 800, S = 900 }",
     "names the rotor's two bearings"),
    ("speed = 200", 'speed = 200\nbearings = { "1" = 0, R = 800 }', "not a mass's"),
])
def test_bad_bearings_are_refused_in_one_line(old, new, words):
    with pytest.raises(InputError) as e:
        parse_balance(SHAFT.replace(old, new, 1), "shaft.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("shaft.toml:7:") and words in message, \
        message


def test_bearings_beside_balancing_planes_are_refused():
    text = (SHAFT + PLANES).replace("speed = 200", "speed = 200\nbearings = { L = 0, R = 800 }")
    with pytest.raises(InputError, match=r"^shaft.toml:7: bearings are asked"):
        parse_balance(text, "shaft.toml")


def test_an_engines_balance_planes_give_no_bearing_force():
    """An engine's balance planes are its wheels: their hammer blow is asked, not a bearing's
    load, so no force_A."""
    q = solve_balance(load(bundled("balancing")["locomotive"])).results["quantities"]
    assert "hammer_blow_A" in q and not any(k.startswith("force_") for k in q)


def test_an_unbalanced_rotor_of_weights_gives_its_force_in_n():
    """With no balancing plane, |Σ Wᵢrᵢ e^{iθᵢ}|·ω²/g (N) at 10 rad/s, each weight named in N
    on the end view."""
    text = WEIGHTS[:WEIGHTS.index("[[balance]]")].replace("[rotor]", "[rotor]\nspeed = 10")
    s = solve_balance(parse_balance(text, "weights.toml"))
    assert s.results["quantities"]["unbalanced_force"]["value"] == pytest.approx(
        abs(_sum_of_weights()) * 100 / 9.81, rel=1e-12)
    space = [t.text for t in s.figures["space"].items if hasattr(t, "text")]
    assert "2: 80 N at 100 mm, 90°" in space


def test_a_planes_own_line_stays_one():
    """The balancing mass's line is the one line that begins "plane L:" (the random rotors'
    oracle reads it so); the weight and the bearing's force are said on lines of their own."""
    text = (SHAFT + PLANES).replace("mass = 4", "weight = 39.24")
    lines = solve_balance(parse_balance(text, "shaft.toml")).lines()
    assert [ln for ln in lines if ln.startswith("plane L:")] == [
        next(ln for ln in lines if ln.startswith("plane L: balancing m·r"))]
