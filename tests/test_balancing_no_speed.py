"""A primary balance's unknown mass and crank angles, which need no speed, as the books
ask them without one; each held to its closed form worked here.

The primary balance is solved by the law of cosines on the couple polygon about the third
crank's plane (its couple drops out), then the force polygon closed on the third mass. The
products are a few kg·m, summed from four terms: 1e-9 relative and 1e-7° leave room only
for rounding (a near-degenerate triangle would magnify it; these are far from one).
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
DEG = 1e-7


def primary_balance(masses: tuple[float, float, float], arms: tuple[float, float, float]
                    ) -> list[dict[str, float]]:
    """Cylinders 1, 2 and 4 of known masses at arms from cylinder 3's plane, crank 1 at 0°:
    both closings of −a − b e^{iθ₂} + c e^{iθ₄} = 0 (a, b, c each m·|l|, cylinders 1 and 2
    on one side, 4 on the other), with m₃ and θ₃ from the force polygon."""
    (m1, m2, m4), (l1, l2, l4) = masses, arms
    a, b, c = m1 * l1, m2 * l2, m4 * l4
    cos4 = (c * c + a * a - b * b) / (2 * c * a)
    out = []
    for t4 in (math.acos(cos4), -math.acos(cos4)):
        z2 = (c * cmath.exp(1j * t4) - a) / b
        rest = m1 + m2 * z2 + m4 * cmath.exp(1j * t4)
        out.append({"angle_2": math.degrees(cmath.phase(z2)) % 360, "mass_3": abs(rest),
                    "angle_3": math.degrees(cmath.phase(-rest)) % 360,
                    "angle_4": math.degrees(t4) % 360})
    return out


def _one_of(q: dict, roots: list[dict[str, float]]) -> None:
    """The solution is one of the two closings (its mirror image the other), every number
    of it to rounding."""
    taken = min(roots, key=lambda r: abs(r["angle_2"] - q["angle_2"]["value"]))
    assert q["mass_3"]["value"] == pytest.approx(taken["mass_3"], rel=REL)
    for key in ("angle_2", "angle_3", "angle_4"):
        assert q[key]["value"] == pytest.approx(taken[key], abs=DEG), key


def test_b2_primary_balance_unknowns_asstated():
    """The book gives no speed and asks a mass and angles: solved as stated, 64.265 kg and
    the cranks at 198.61°, 123.08°, 327.05° (or the mirror image), nothing in newtons."""
    s = solve_balance(tarsim.load(HERE / "b2-primary-balance-unknowns-asstated.toml"))
    assert s.passed, s.failures
    q = {k: c.value for k, c in s.checked.items()}
    _one_of(q, primary_balance((60, 75, 55), (0.45, 0.25, 0.2)))
    # the hand values of heldout6a/handcalc.py
    assert q["mass_3"]["value"] == pytest.approx(64.265, abs=5e-4)
    assert not any(v.get("unit") in ("N", "N·m") for v in q.values())
    assert s.lines()[0].startswith("no speed is given: the masses and angles found need none")


def test_the_bundled_primary_balance_needs_no_speed():
    s = solve_balance(tarsim.load("primary-balance-unknowns"))
    assert s.passed, s.failures
    _one_of({k: c.value for k, c in s.checked.items()},
            primary_balance((50, 70, 45), (0.5, 0.3, 0.25)))


def test_a_primary_balance_with_a_rod_and_no_speed_gives_its_secondaries_per_omega_squared():
    text = (HERE / "b2-primary-balance-unknowns-asstated.toml").read_text().replace(
        "[engine]\ncrank = 125\n", "[engine]\ncrank = 125\nrod = 500\n")
    s = solve_balance(parse_balance(text, "b2.toml"))
    assert s.passed, s.failures
    said = "\n".join(s.lines())
    assert "secondary force: unbalanced," in said and "kg·m × ω² at most (no speed given)" in said
    assert "secondary_force" not in s.checked


def test_a_primary_balance_asked_forces_at_an_angle_with_no_speed_is_refused():
    text = (HERE / "b2-primary-balance-unknowns-asstated.toml").read_text().replace(
        "[engine]\ncrank = 125\n", "[engine]\ncrank = 125\nat = 30\n")
    with pytest.raises(InputError) as e:
        parse_balance(text, "b2.toml")
    assert str(e.value).startswith("b2.toml:9: at asks the forces at a crank angle"), str(e.value)
