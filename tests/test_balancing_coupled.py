"""A locomotive's wheels balancing revolving masses on cranks of their own (coupling rods,
eccentrics: ``[[mass]]`` in an [engine] file), and a coupled locomotive's reciprocating
balance shared among its pairs of wheels (``coupled``), each held to the two-plane closed
form worked here with complex numbers; and every setting a balancing file's kind of exercise
has no use for refused at its line, never dropped.

The two-plane balance of masses mᵢ at rᵢ, θᵢ, zᵢ (z from plane A, planes a apart) is
(m r)_B = −Σ mᵢrᵢzᵢ e^{iθᵢ}/a and (m r)_A = −Σ mᵢrᵢ e^{iθᵢ} − (m r)_B. The products here are
a few kg·m, summed from a handful of terms: the polygons agree with the sums to a few
roundings, so 1e-9 relative (sizes) and 1e-7° (angles) leave room only for rounding.
"""

from __future__ import annotations

import cmath
import math
from pathlib import Path

import pytest

import tarsim
from tarsim.constructions.errors import InputError
from tarsim.exercises.balancing.balance_solution import solve_balance
from tarsim.exercises.balancing.rotor_file import parse_balance

HERE = Path(__file__).parent / "reproducers"
REL = 1e-9
"""Relative agreement of a balance mass with the closed form: the rounding of a handful of
products of a few kg·m, with room to spare."""
DEG = 1e-7
"""Degrees: an angle off a closing side some kg·m long rounds near 1e-14 rad."""


def two_planes(masses, a: float, radius: float) -> list[tuple[float, float]]:
    """The balance masses (kg at ``radius``) and their angles (°) in planes 0 and ``a`` (m)
    for masses (kg, m, °, m), by the closed form."""
    couple = sum(m * r * z * cmath.exp(1j * math.radians(t)) for m, r, t, z in masses)
    b = -couple / a
    a_ = -(sum(m * r * cmath.exp(1j * math.radians(t)) for m, r, t, _ in masses) + b)
    return [(abs(v) / radius, math.degrees(cmath.phase(v)) % 360) for v in (a_, b)]


def _assert_plane(q: dict, key: str, want: tuple[float, float]) -> None:
    mass, angle = want
    assert q[f"mass_{key}"]["value"] == pytest.approx(mass, rel=REL)
    assert q[f"angle_{key}"]["value"] == pytest.approx(angle, abs=DEG)


def _book_b3(coupled: bool) -> list[tuple]:
    """heldout B3's wheels: each inside crank 250 kg revolving and its share of ⅔ of 300 kg
    at 300 mm, cylinders 0.6 m apart in wheels 1.5 m apart; each coupling rod's 120 kg at
    250 mm on cranks 1.9 m apart, at 180° to the crank beside it."""
    share = 300 * (2 / 3) / (2 if coupled else 1)
    rods = [(120, 0.25, 180, -0.2), (120, 0.25, 270, 1.7)]
    return [(250 + share, 0.3, 0, 0.45), (250 + share, 0.3, 90, 1.05)] + rods


def test_b3_coupled_locomotive():
    """The file as the user typed it: its masses' names have spaces, refused at their line as
    a rotor's are (never dropped: the old answer, 114.237 kg, left the rods out); named as
    words, the rods are balanced with the cranks: 75.869 kg at 221.95° and 228.05°."""
    path = HERE / "b3-coupled-locomotive.toml"
    with pytest.raises(InputError) as e:
        tarsim.load(path)
    assert "b3-coupled-locomotive.toml:23: mass 1's name" in str(e.value)
    assert "\n" not in str(e.value)
    text = path.read_text().replace("coupling rod L", "rodL").replace("coupling rod R", "rodR")
    s = solve_balance(parse_balance(text, "b3.toml"))
    assert s.passed, s.failures
    q = {k: c.value | {"ref": c.reference} for k, c in s.checked.items()}
    # ½ of ⅔ balanced in the driving wheels (the user's own hand step, balanced = "1/3")
    want = two_planes(_book_b3(coupled=True), 1.5, 0.7)
    _assert_plane(q, "A", want[0])
    _assert_plane(q, "B", want[1])
    # the hand values of heldout6a/handcalc.py, to their five figures
    assert q["mass_A"]["value"] == pytest.approx(75.869, abs=5e-4)
    assert q["angle_A"]["value"] == pytest.approx(221.95, abs=5e-3)
    assert q["angle_B"]["value"] == pytest.approx(228.05, abs=5e-3)


def _coupled_text(path: Path) -> str:
    """B3 as the book poses it: ⅔ balanced, shared by two pairs of coupled wheels, the rods
    on each pair."""
    text = path.read_text().replace('balanced = "1/3"', 'balanced = "2/3"\ncoupled = 2')
    for side in "LR":
        text = text.replace(f'name = "coupling rod {side}"',
                            f'name = "rod{side}"\nwheels = "each"')
    return text


def test_b3_as_the_book_poses_it_balances_the_driving_and_the_trailing_wheels():
    s = solve_balance(parse_balance(_coupled_text(HERE / "b3-coupled-locomotive.toml"),
                                    "b3.toml"))
    assert s.passed, s.failures
    q = {k: c.value for k, c in s.checked.items()}
    for key, want in zip("AB", two_planes(_book_b3(coupled=True), 1.5, 0.7)):
        _assert_plane(q, key, want)
    trailing = [(100, 0.3, 0, 0.45), (100, 0.3, 90, 1.05),
                (120, 0.25, 180, -0.2), (120, 0.25, 270, 1.7)]
    for key, want in zip("AB", two_planes(trailing, 1.5, 0.7)):
        _assert_plane(q, f"{key}_trailing", want)
    # the hand values: 26.264 kg at 315° and 135°
    assert q["mass_A_trailing"]["value"] == pytest.approx(26.264, abs=5e-4)
    assert q["angle_A_trailing"]["value"] == pytest.approx(315.0, abs=DEG)
    assert q["angle_B_trailing"]["value"] == pytest.approx(135.0, abs=DEG)
    said = "\n".join(s.lines())
    assert "shared equally among 2 pairs of coupled wheels" in said
    assert "the trailing wheels:" in said
    assert {"space-trailing", "table-trailing", "couple-polygon-trailing",
            "force-polygon-trailing"} <= set(s.figures)


def test_the_bundled_coupled_locomotive():
    s = solve_balance(tarsim.load("coupled-locomotive"))
    assert s.passed, s.failures
    q = {k: c.value for k, c in s.checked.items()}
    rods = [(100, 0.2, 180, -0.2), (100, 0.2, 270, 1.75)]
    each = 320 / 3
    driving = [(280 + each, 0.325, 0, 0.45), (280 + each, 0.325, 90, 1.1)] + rods
    trailing = [(each, 0.325, 0, 0.45), (each, 0.325, 90, 1.1)] + rods
    for key, want in zip("AB", two_planes(driving, 1.55, 0.75)):
        _assert_plane(q, key, want)
    for key, want in zip("AB", two_planes(trailing, 1.55, 0.75)):
        _assert_plane(q, f"{key}_trailing", want)


def test_the_hammer_blow_beside_coupling_rods_is_that_of_the_wheels_share_alone():
    """With rods in the wheels the balance product is no multiple of c·m's: the hammer blow
    is B·ω²·b of (c/k)·m alone, (c/k)·m·r·ω²·|Σ zᵢ e^{iθᵢ}|/a in plane B."""
    text = _coupled_text(HERE / "b3-coupled-locomotive.toml").replace(
        "coupled = 2", "coupled = 2\nspeed = 20")
    s = solve_balance(parse_balance(text, "b3.toml"))
    assert s.passed, s.failures
    q = {k: c.value for k, c in s.checked.items()}
    share = 300 * (2 / 3) / 2
    b = share * 0.3 * abs(0.45 + 1.05j) / 1.5 * 20 ** 2
    assert q["hammer_blow_B"]["value"] == pytest.approx(b, rel=REL)


_ENGINE = """name = "e"
[units]
length = "mm"
[engine]
speed = 30
crank = 300
reciprocating = 300
{engine}
[[cylinder]]
crank = 0
plane = 450
[[cylinder]]
crank = {crank2}
plane = 1050
{tables}
"""
_ROD = '[[mass]]\nname = "rod"\nmass = 120\nradius = 250\nangle = 180\nplane = -200\n'
_PLANES = ('[[balance]]\nname = "A"\nplane = 0\nradius = 700\n'
           '[[balance]]\nname = "B"\nplane = 1500\nradius = 700\n')


@pytest.mark.parametrize("engine, crank2, tables, where, says", [
    ("", 90, _ROD, ":15:", "[[mass]] tables are revolving masses balanced in its wheels"),
    ('balanced = "2/3"', 90, _ROD + 'wheels = "each"\n' + _PLANES, ":21:",
     "give [engine] coupled"),
    ('balanced = "2/3"\ncoupled = 1', 90, _PLANES, ":9:", "2 or more"),
    ('coupled = 2', 90, "", ":8:", "coupled is what balance masses take"),
    ("wheel_diameter = 1800", 90, _PLANES, ":8:", "wheel_diameter goes with road_speed"),
    ('dead_load = 1000', '"?"', "", ":8:", "dead_load is not taken"),
    ('strokes = 4\nrevolving = 1', '"?"', "", ":8:", "strokes is not taken"),
    ('', '"?"', _ROD, ":16:", "[[mass]] tables are revolving masses"),
])
def test_a_setting_an_engine_does_not_use_is_refused_at_its_line(engine, crank2, tables,
                                                                    where, says):
    text = _ENGINE.format(engine=engine, crank2=crank2, tables=tables)
    if crank2 == '"?"':         # a primary balance: four unknowns
        text = text.replace("[[cylinder]]\ncrank = 0\nplane = 450", (
            '[[cylinder]]\ncrank = 0\nplane = 450\nreciprocating = "?"'))
    with pytest.raises(InputError) as e:
        parse_balance(text, "e.toml")
    message = str(e.value)
    assert "\n" not in message and says in message and where in message, message


@pytest.mark.parametrize("text, says", [
    ('[rotor]\n[[mass]]\nmass = 1\nradius = 1\nangle = 0\n[[balance]]\nradius = 1\n'
     '[[cylinder]]\ncrank = 0\n', "[[cylinder]] tables are an [engine]'s"),
    ('[rotor]\n[[mass]]\nmass = 1\nradius = 1\nangle = 0\nwheels = "each"\n[[balance]]\n'
     'radius = 1\n', "wheels puts a locomotive's revolving mass"),
    ('[rotor]\nabout = 0\n[[mass]]\nmass = 1\nradius = 1\nangle = 0\n[[mass]]\nmass = "?"\n'
     'radius = 1\nangle = "?"\n', "about is for a rotor's out-of-balance"),
    ('[rotor]\nspeed = 300\n[[mass]]\nmass = 1\nradius = 1\nangle = 0\n[[mass]]\nmass = "?"\n'
     'radius = 1\nangle = "?"\n', "speed is not taken for a rotor whose masses hold unknowns"),
])
def test_a_setting_a_rotor_does_not_use_is_refused_at_its_line(text, says):
    with pytest.raises(InputError) as e:
        parse_balance(text, "r.toml")
    assert "\n" not in str(e.value) and says in str(e.value), str(e.value)
    assert str(e.value).startswith("r.toml:")
