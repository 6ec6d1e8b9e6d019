"""A locomotive whose hammer blow is limited, as the books ask it: "find the greatest speed
if the hammer blow is not to exceed 30 kN". ``[engine] hammer_blow`` is the greatest blow
allowed (N): the speed is where the greater wheel's blow B·b·ω² reaches it, ω = √(P/(B·b)),
and the variation of tractive force and the swaying couple are given there. It is worded as
a limit reached, never as a wheel lifting, which only ``dead_load`` says.

The reproducer is an inside-cylinder locomotive (cranks 300 mm at 90°, cylinders 0.65 m and
wheels 1.55 m apart, 300 kg reciprocating and 250 kg revolving a cylinder, ¾ balanced at
0.7 m on 1.85 m wheels). Each closed form is a few products and one square root of numbers
of order 0.1–1000, and the polygons lay off the same few vectors: they agree to a few
roundings, 1e-12 relative (an angle 1e-9°).
"""

from __future__ import annotations

import cmath
import math
from pathlib import Path

import pytest

from tarsim.constructions.errors import InputError
from tarsim.exercises.balancing.balance_solution import solve_balance
from tarsim.exercises.balancing.rotor_file import parse_balance

HERE = Path(__file__).parent / "reproducers"
REL = 1e-12
"""Relative agreement of a few sums and a square root with their hand values (see above)."""

R, M_REC, M_REV, C, B = 0.3, 300.0, 250.0, 0.75, 0.7
Z = (0.45, 1.1)
"""The cylinders' planes (m) from wheel A; wheel B at 1.55 m, the cranks at 0° and 90°."""
SPAN, GAUGE, WHEEL, BLOW = 1.55, 0.65, 1.85, 30000.0


def _solve(text: str, name: str = "l.toml"):
    s = solve_balance(parse_balance(text, name))
    assert s.passed, s.failures
    return s


def test_b5_locomotive_hammer_blow_limit():
    """Moments about each wheel give its product; c·m's share of wheel A's is
    B·b = c·m·r·|(z_B − z₁) + i(z_B − z₂)|/L, so ω = √(30 kN/(B·b)) = 24.0756 rad/s,
    80.1718 km/h. There the tractive variation is (1 − c)·m·r·ω²·√2 = 18 443.9 N and the
    swaying couple (1 − c)·m·r·ω²·a/√2 = 5994.26 N·m."""
    s = _solve((HERE / "b5-locomotive-hammer-blow-limit.toml").read_text(encoding="utf-8"),
               "b5.toml")
    q = s.results["quantities"]
    each = (M_REV + C * M_REC) * R
    at_b = -each * (Z[0] + 1j * Z[1]) / SPAN
    at_a = -each * (1 + 1j) - at_b
    for plane, v in (("A", at_a), ("B", at_b)):
        assert q[f"mass_{plane}"]["value"] == pytest.approx(abs(v) / B, rel=REL)
        assert q[f"angle_{plane}"]["value"] == pytest.approx(
            math.degrees(cmath.phase(v)) % 360, abs=1e-9)
    share = C * M_REC * R * abs((SPAN - Z[0]) + 1j * (SPAN - Z[1])) / SPAN
    w = math.sqrt(BLOW / share)
    assert q["speed_at_hammer_blow"]["value"] == pytest.approx(w, rel=REL)
    assert q["road_speed_at_hammer_blow"]["value"] == pytest.approx(w * WHEEL / 2 * 3.6,
                                                                    rel=REL)
    left = (1 - C) * M_REC * R * w ** 2
    assert q["primary_force_left"]["value"] == pytest.approx(left * math.sqrt(2), rel=REL)
    assert q["primary_couple_left"]["value"] == pytest.approx(left * GAUGE / math.sqrt(2),
                                                              rel=REL)
    assert q["primary_couple_left"]["at_hammer_blow_speed"] == pytest.approx(w, rel=REL)
    assert max(q["hammer_blow_A"]["value"], q["hammer_blow_B"]["value"]) == pytest.approx(
        BLOW, rel=REL)
    # the book's answers, to the figures it gives
    assert abs(at_a) / B == pytest.approx(156.092, abs=5e-4)
    assert w * WHEEL / 2 * 3.6 == pytest.approx(80.1718, abs=5e-5)
    assert "lift_speed" not in q
    lines = s.lines()
    assert not any("lift" in line for line in lines)
    assert any("greatest allowed, 30000 N" in line and "80.1718 km/h" in line
               for line in lines)


def test_a_dead_load_still_lifts_the_wheel():
    """The same locomotive given the 30 kN as a dead load finds the same speed, worded as
    the wheel lifting, under lift_speed: the two differ in words alone."""
    text = (HERE / "b5-locomotive-hammer-blow-limit.toml").read_text(encoding="utf-8")
    blow = _solve(text).results["quantities"]
    lift = _solve(text.replace("hammer_blow = 30000", "dead_load = 30000")).results[
        "quantities"]
    assert lift["lift_road_speed"]["value"] == pytest.approx(
        blow["road_speed_at_hammer_blow"]["value"], rel=REL)
    assert "speed_at_hammer_blow" not in lift


@pytest.mark.parametrize("old, new, says", [
    ("hammer_blow = 30000", "hammer_blow = 30000\ndead_load = 30000", "give one, not both"),
    ("hammer_blow = 30000", "hammer_blow = -30000", "must be positive"),
    ("balanced = 0.75", "", "a fraction balanced"),
])
def test_hammer_blow_refusals(old, new, says):
    """A limit beside a dead load, not positive, or with no fraction balanced to strike the
    rails, is refused in one line at its place."""
    text = (HERE / "b5-locomotive-hammer-blow-limit.toml").read_text(encoding="utf-8")
    assert old in text
    with pytest.raises(InputError) as e:
        parse_balance(text.replace(old, new, 1), "b5.toml")
    message = str(e.value)
    assert says in message and "b5.toml:" in message
    assert "\n" not in message and len(message) < 200
