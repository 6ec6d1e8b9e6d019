"""A rotor's masses given by material and size, as the books give eccentrics: a ``[[mass]]``
with ``density`` (kg/m³), ``diameter`` and ``thickness`` is a solid disc, m = ρ·πd²/4·t.

The reproducers are a book's three eccentrics (80 mm across, 20 mm thick, 7200 kg/m³, 10, 16
and 10 mm out at 0°, 120°, 240°, 50 mm apart, 750 rpm), typed as the book gives them: out of
balance, then balanced by two masses at 60 mm, 90 mm either side of the middle one. Each is
held to its closed form worked here. The sums are of a few products of order 1e-3 kg·m, so
the polygons agree with the hand's to a few roundings: 1e-9 relative is ample and still far
below any slip in a mass, radius or angle (each a part in a hundred or more).
"""

from __future__ import annotations

import cmath
import math
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.balancing.balance_solution import solve_balance
from tarsim.exercises.balancing.rotor_file import parse_balance

HERE = Path(__file__).parent / "reproducers"
REL = 1e-9
"""Relative tolerance: a few roundings of sums of order 1e-3 kg·m (see the module's note)."""

DISC = 7200 * math.pi * 0.080 ** 2 / 4 * 0.020
"""Each eccentric's mass, kg: ρ·πd²/4·t."""
OMEGA = 750 * 2 * math.pi / 60
ECCENTRICS = [(0.010, 0.0, 0.000), (0.016, 120.0, 0.050), (0.010, 240.0, 0.100)]
"""Each eccentric's radius (m), angle (°) and plane (m)."""


def _mr(r: float, degrees: float) -> complex:
    return DISC * r * cmath.exp(1j * math.radians(degrees))


def _solve(name: str):
    path = HERE / name
    s = solve_balance(parse_balance(path.read_text(), str(path)))
    assert s.passed, s.failures
    return s


def test_b2a_eccentrics_out_of_balance():
    """The force m·ω²·|Σ rᵢe^{iθᵢ}| and the couple about the middle plane,
    m·ω²·|Σ rᵢ(zᵢ − 50 mm)e^{iθᵢ}|: 26.7894 N and 3.86672 N·m by the book's data."""
    s = _solve("b2a-eccentrics-out-of-balance.toml")
    q = s.checked
    force = abs(sum(_mr(r, a) for r, a, _ in ECCENTRICS)) * OMEGA ** 2
    couple = abs(sum(_mr(r, a) * (z - 0.050) for r, a, z in ECCENTRICS)) * OMEGA ** 2
    assert q["unbalanced_force"].value["value"] == pytest.approx(force, rel=REL)
    assert q["unbalanced_couple"].value["value"] == pytest.approx(couple, rel=REL)
    assert force == pytest.approx(26.7894, abs=5e-5)        # the book's answer, 6 figures
    assert couple == pytest.approx(3.86672, abs=5e-6)
    assert any("solid disc" in line and "0.723823 kg" in line for line in s.lines())


def test_b2b_eccentrics_balanced():
    """Balance planes L and M at −40 and 140 mm, 60 mm radius: moments about L give
    (m r)_M = −Σ mᵢrᵢ(zᵢ − z_L)/(z_M − z_L), and (m r)_L = −Σ mᵢrᵢ − (m r)_M."""
    s = _solve("b2b-eccentrics-balanced.toml")
    q = s.checked
    zl, zm = -0.040, 0.140
    at_m = -sum(_mr(r, a) * (z - zl) for r, a, z in ECCENTRICS) / (zm - zl)
    at_l = -sum(_mr(r, a) for r, a, _ in ECCENTRICS) - at_m
    for name, v in (("L", at_l), ("M", at_m)):
        assert q[f"mass_{name}"].value["value"] == pytest.approx(abs(v) / 0.060, rel=REL)
        assert q[f"angle_{name}"].value["value"] == pytest.approx(
            math.degrees(cmath.phase(v)) % 360, abs=1e-7)
        assert q[f"force_{name}"].value["value"] == pytest.approx(abs(v) * OMEGA ** 2,
                                                                  rel=REL)
    # L and M are balance masses, not bearings: no force is said to be on a bearing
    assert not any("bearing" in line for line in s.lines())
    assert abs(at_l) / 0.060 == pytest.approx(0.0684005, abs=5e-8)   # the book's answers
    assert math.degrees(cmath.phase(at_l)) % 360 == pytest.approx(241.945, abs=5e-4)
    assert math.degrees(cmath.phase(at_m)) % 360 == pytest.approx(358.055, abs=5e-4)


def _file(mass: str) -> str:
    return ('[units]\nlength = "mm"\n[rotor]\nspeed = 100\n[[mass]]\n' + mass
            + "radius = 10\nangle = 0\n[[mass]]\nmass = 1\nradius = 10\nangle = 90\n"
            "[[balance]]\nplane = 0\nradius = 50\n")


@pytest.mark.parametrize("mass, says", [
    ("mass = 1\ndensity = 7800\ndiameter = 150\nthickness = 25\n", "not both"),
    ("density = 7800\ndiameter = 150\n", "give its thickness too"),
    ("density = 7800\n", "give its diameter and thickness too"),
    ("diameter = 150\nthickness = 25\n", "add density"),
    ("density = -7800\ndiameter = 150\nthickness = 25\n", "must be positive"),
])
def test_disc_refusals(mass, says):
    """A density beside a mass, or without its sizes, is refused in one line at its place."""
    with pytest.raises(InputError) as e:
        parse_balance(_file(mass), "disc.toml")
    assert says in str(e.value) and "disc.toml:" in str(e.value)
    assert "\n" not in str(e.value) and len(str(e.value)) < 200


def test_disc_refused_in_an_engine():
    """An engine's revolving masses are given in kg: a disc there is refused."""
    text = ("[engine]\nspeed = 10\ncrank = 0.3\nreciprocating = 300\nbalanced = 0.5\n"
            "[[cylinder]]\ncrank = 0\nplane = 0.45\n[[cylinder]]\ncrank = 90\nplane = 1.1\n"
            "[[mass]]\ndensity = 7800\ndiameter = 0.1\nthickness = 0.02\nradius = 0.3\n"
            "angle = 0\nplane = 0.45\n"
            "[[balance]]\nplane = 0\nradius = 0.7\n[[balance]]\nplane = 1.55\nradius = 0.7\n")
    with pytest.raises(InputError, match="solid disc"):
        parse_balance(text, "engine.toml")


@settings(max_examples=30, deadline=None)
@given(rho=st.floats(1000, 20000), d=st.floats(5, 500), t=st.floats(1, 100))
def test_disc_is_its_mass(rho, d, t):
    """A disc balances as the mass ρ·πd²/4·t given in kg does: one plane, m_B·r_B = |Σ m r|."""
    disc = parse_balance(_file(f"density = {rho!r}\ndiameter = {d!r}\nthickness = {t!r}\n"),
                         "disc.toml")
    m = rho * math.pi * (d / 1000) ** 2 / 4 * (t / 1000)
    got = solve_balance(disc).checked["mass_A"].value["value"]
    assert got == pytest.approx(math.hypot(m, 1.0) * 10 / 50, rel=REL)
