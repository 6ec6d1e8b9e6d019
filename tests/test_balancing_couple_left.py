"""The couple a static balance leaves, as the books ask "the unbalanced couple that
remains": in N·m where the speed is given, in kg·m² (× ω²) where it is not, with its angle;
each held to Σ mᵢrᵢ(zᵢ − z_X) e^{iθᵢ} summed here as complex numbers. The products are a
few kg·m from three terms: 1e-9 relative and 1e-7° leave room only for rounding.
"""

from __future__ import annotations

import cmath
import math
from pathlib import Path

import pytest

import tarsim
from tarsim.exercises.balancing.balance_solution import solve_balance
from tarsim.exercises.balancing.rotor_file import parse_balance

HERE = Path(__file__).parent / "reproducers"
REL = 1e-9
DEG = 1e-7


def couple_left(masses, plane: float) -> tuple[float, float]:
    """|Σ mᵢrᵢ(zᵢ − z_X) e^{iθᵢ}| (kg·m²) and its angle (°) for masses (kg, m, °, m)."""
    c = sum(m * r * (z - plane) * cmath.exp(1j * math.radians(t)) for m, r, t, z in masses)
    return abs(c), math.degrees(cmath.phase(c)) % 360


def test_b4_static_balance_couple_left():
    """The couple left at 300 rpm in N·m, in results.json and on the line: 536.18 N·m."""
    s = solve_balance(tarsim.load(HERE / "b4-static-balance-couple-left.toml"))
    assert s.passed, s.failures
    size, angle = couple_left([(10, 0.1, 0, 0), (8, 0.15, 120, 0.3), (6, 0.12, 225, 0.7)], 0.3)
    w = 300 * 2 * math.pi / 60
    q = s.checked["couple_left"].value
    assert q["unit"] == "N·m"
    assert q["value"] == pytest.approx(size * w * w, rel=REL)
    assert q["angle_deg"] == pytest.approx(angle, abs=DEG)
    assert q["value"] == pytest.approx(536.18, abs=5e-3)       # the hand value
    assert any("a couple of 536.177 N·m at 202.02°" in line for line in s.lines())


def test_the_bundled_static_balance_leaves_its_couple_in_newton_metres():
    s = solve_balance(tarsim.load("static-balance-couple-left"))
    assert s.passed, s.failures
    masses = [(12, 0.09, 0, 0), (10, 0.12, 100, 0.25), (7, 0.15, 230, 0.6)]
    size, angle = couple_left(masses, 0.25)
    w = 450 * 2 * math.pi / 60
    q = s.checked["couple_left"].value
    assert q["value"] == pytest.approx(size * w * w, rel=REL)
    assert q["angle_deg"] == pytest.approx(angle, abs=DEG)


def test_with_no_speed_the_couple_left_is_in_kg_m2_per_omega_squared():
    text = (HERE / "b4-static-balance-couple-left.toml").read_text().replace(
        "speed = 300\n", "")
    s = solve_balance(parse_balance(text, "b4.toml"))
    q = s.checked["couple_left"].value
    size, _ = couple_left([(10, 0.1, 0, 0), (8, 0.15, 120, 0.3), (6, 0.12, 225, 0.7)], 0.3)
    assert (q["unit"], q["times"]) == ("kg·m²", "ω²")
    assert q["value"] == pytest.approx(size, rel=REL)
    assert q["value"] == pytest.approx(0.543261, abs=5e-7)     # the hand value


def test_masses_in_the_balancing_plane_leave_no_couple():
    """Every mass in the balancing plane: the force balance is the whole balance."""
    text = (HERE / "b4-static-balance-couple-left.toml").read_text()
    for z in ("plane = 0", "plane = 700"):
        text = text.replace(z, "plane = 300")
    s = solve_balance(parse_balance(text, "b4.toml"))
    assert "couple_left" not in s.checked
    assert not any("a couple of" in line for line in s.lines())
