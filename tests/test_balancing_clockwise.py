"""A rotor whose angles the book measures clockwise, ``[rotor] angles = "cw"``: solved as its
mirror image, every angle given and found read clockwise, the sizes unchanged.

Tolerances: 1e-9 relative for masses and 1e-9° for angles, a few roundings of the couple and
force sums (each a handful of products of the data's own size).
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

MASSES = ((18, 50, 0, 0), (14, 60, 60, 80), (16, 70, 135, 160), (12, 60, 270, 280))
"""The books' four masses (kg, mm, degrees clockwise from mass 1, plane mm)."""


def _file(masses, sense: str, sign: int, planes=((0 + 80) / 2, (160 + 280) / 2)) -> str:
    text = '[units]\nlength = "mm"\n[rotor]\n' + (f'angles = "{sense}"\n' if sense else "")
    for i, (m, r, a, lx) in enumerate(masses):
        text += (f'[[mass]]\nname = "{i + 1}"\nmass = {m}\nradius = {r}\nangle = {sign * a}\n'
                 f"plane = {lx}\n")
    for name, lx in zip("AB", planes):
        text += f'[[balance]]\nname = "{name}"\nplane = {lx}\nradius = 50\n'
    return text


def _closed_form(masses, planes, radius=50.0):
    """The balancing masses (kg) and their angles (degrees, in the sense the angles are
    given) by moments about plane A and then forces, with complex m·r·e^{iθ}."""
    a, b = planes
    couple = sum(m * r * cmath.exp(1j * math.radians(t)) * (lx - a) for m, r, t, lx in masses)
    mr_b = -couple / (b - a)
    mr_a = -sum(m * r * cmath.exp(1j * math.radians(t)) for m, r, t, _ in masses) - mr_b
    return {name: (abs(v) / radius, math.degrees(cmath.phase(v)) % 360.0)
            for name, v in (("A", mr_a), ("B", mr_b))}


def test_b1_four_masses_midway():
    """The books' four masses measured clockwise from mass 1, balanced at 50 mm in planes
    midway between the 1st and 2nd and the 3rd and 4th: 31.599 kg at 222.62° and 13.797 kg
    at 23.07°, clockwise, as the book gives them."""
    s = solve_balance(parse_balance(_file(MASSES, "cw", 1), "b1-four-masses-midway.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    want = _closed_form(MASSES, (40.0, 220.0))
    for name in "AB":
        assert q[f"mass_{name}"]["value"] == pytest.approx(want[name][0], rel=1e-9)
        assert q[f"angle_{name}"]["value"] == pytest.approx(want[name][1], abs=1e-9)
        assert q[f"angle_{name}"]["sense"] == "cw"
    assert q["mass_A"]["value"] == pytest.approx(31.599, abs=0.0005)
    assert q["angle_A"]["value"] == pytest.approx(222.62, abs=0.005)
    assert q["angle_B"]["value"] == pytest.approx(23.07, abs=0.005)
    assert s.lines()[0].startswith("angles are measured clockwise")


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(st.integers(1, 50), st.integers(10, 200), st.integers(0, 359),
                          st.integers(-300, 600)), min_size=2, max_size=5))
def test_a_clockwise_rotor_is_the_mirror_of_its_counter_clockwise_twin(masses):
    """The same rotor given clockwise, and counter-clockwise with every angle negated: the
    same balancing masses, each angle the other's negative (mod 360°)."""
    planes = (-400, 800)
    cw = solve_balance(parse_balance(_file(masses, "cw", 1, planes), "cw.toml"))
    ccw = solve_balance(parse_balance(_file(masses, "", -1, planes), "ccw.toml"))
    assert cw.passed and ccw.passed
    q, p = cw.results["quantities"], ccw.results["quantities"]
    for name in "AB":
        if "none_needed" in q[f"mr_{name}"]:
            assert "none_needed" in p[f"mr_{name}"]
            continue
        assert q[f"mass_{name}"]["value"] == pytest.approx(p[f"mass_{name}"]["value"],
                                                           rel=1e-9)
        back = (-p[f"angle_{name}"]["value"]) % 360.0
        assert abs(math.remainder(q[f"angle_{name}"]["value"] - back, 360.0)) < 1e-6
        assert "sense" not in p[f"angle_{name}"]


def test_a_sense_it_does_not_know_is_refused_in_one_line():
    with pytest.raises(InputError) as e:
        parse_balance(_file(MASSES, "clockwise", 1), "r.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("r.toml:") and '"cw"' in message
