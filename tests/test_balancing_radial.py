"""A radial engine, its cylinders evenly round the crank shaft and every rod on one crank,
as the books pose it: the primary and secondary forces by direct and reverse cranks, each
against the closed forms Σ cos(θ − φᵢ)·e^{iφᵢ} = (n/2)·e^{iθ} (n ≥ 3) and
Σ cos 2(θ − φᵢ)·e^{iφᵢ} = (3/2)·e^{−2iθ} (n = 3; 0 for more), with F = m·ω²·r.

Tolerances: 1e-12 relative, a few roundings of the 2n products each sum adds up.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.balancing.balance_solution import solve_balance
from tarsim.exercises.balancing.rotor_file import parse_balance
from tarsim.exercises.catalog import load

RADIAL = """
[units]
length = "mm"
speed = "rpm"
[engine]
speed = 1200
stroke = 125
rod = 225
reciprocating = 2
radial = 3
"""

F = 2 * 0.0625 * (1200 * math.pi / 30) ** 2
"""m·ω²·r of the books' three-cylinder radial engine: 2 kg, crank 62.5 mm, 1200 rpm."""


def test_b3_radial_three():
    """The books' three-cylinder radial engine (stroke 125 mm, rods 225 mm, 2 kg a cylinder,
    1200 rpm): the primary (3/2)·F = 2960.88 N and the secondary (3/2)·F/n = 822.467 N
    (n = 225/62.5 = 3.6), each at every crank angle."""
    s = solve_balance(parse_balance(RADIAL, "b3-radial-three.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    for name, want in (("primary", 1.5 * F), ("secondary", 1.5 * F / 3.6)):
        for key in ("resultant", "max", "min"):
            assert q[f"{name}_{key}"]["value"] == pytest.approx(want, rel=1e-12)
            assert q[f"{name}_{key}"]["constant"] is True
        assert f"{name}_max_at" not in q
    assert q["primary_resultant"]["value"] == pytest.approx(2960.88, abs=0.005)
    assert q["secondary_resultant"]["value"] == pytest.approx(822.467, abs=0.0005)
    assert set(s.figures) == {"forces"}
    assert "the primary resultant is 2960.88 N at every crank angle" in "\n".join(s.lines())


def test_b3b_vee120():
    """vee = 120 is a V of two cylinders, not a radial engine of three: its primary runs
    round an ellipse, 2F·cos²60° = 0.5F along the centre line (θ = 0°) to 2F·sin²60° = 1.5F
    across it (θ = 90°); the radial engine's (3/2)·F is its greatest alone."""
    text = RADIAL.replace("radial = 3", "vee = 120")
    q = solve_balance(parse_balance(text, "b3b-vee120.toml")).results["quantities"]
    assert q["primary_max"]["value"] == pytest.approx(1.5 * F, rel=1e-12)
    assert q["primary_max_at"]["value"] == 90.0
    assert q["primary_min"]["value"] == pytest.approx(0.5 * F, rel=1e-12)
    assert "constant" not in q["primary_max"]


@settings(max_examples=40, deadline=None)
@given(st.integers(3, 12), st.integers(0, 359))
def test_a_radial_engines_primary_turns_with_the_crank_and_its_secondary_against_it(n, at):
    """Any number of cylinders n ≥ 3 at any crank angle θ: the primary (n/2)·F along the
    crank (direction θ); the secondary (3/2)·F/n_rod at −2θ for three cylinders, 0 for more
    (the reverse cranks 3φᵢ − 2θ stand together only where n divides 3)."""
    text = RADIAL.replace("radial = 3", f"radial = {n}\nat = {at}")
    s = solve_balance(parse_balance(text, "r.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    p = q["primary_resultant"]
    assert p["value"] == pytest.approx(n / 2 * F, rel=1e-12)
    assert p["along"] == pytest.approx(n / 2 * F * math.cos(math.radians(at)), abs=1e-12 * n * F)
    assert p["across"] == pytest.approx(n / 2 * F * math.sin(math.radians(at)), abs=1e-12 * n * F)
    sec = q["secondary_resultant"]
    if n == 3:
        assert sec["value"] == pytest.approx(1.5 * F / 3.6, rel=1e-12)
        turn = math.radians(-2 * at)
        assert sec["along"] == pytest.approx(1.5 * F / 3.6 * math.cos(turn), abs=1e-12 * n * F)
        assert sec["across"] == pytest.approx(1.5 * F / 3.6 * math.sin(turn), abs=1e-12 * n * F)
    else:
        assert sec["value"] == 0.0 and "direction_deg" not in sec


def test_the_bundled_radial_engine_points_its_forces_as_its_description_says():
    """radial-three at θ = 30°: the primary along the crank, 30°; the secondary at −60°."""
    s = solve_balance(load("radial-three"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    assert q["primary_resultant"]["direction_deg"] == pytest.approx(30.0, abs=1e-9)
    assert q["secondary_resultant"]["direction_deg"] == pytest.approx(300.0, abs=1e-9)


def test_a_radial_engine_with_no_rod_has_no_secondary():
    text = RADIAL.replace("rod = 225\n", "")
    q = solve_balance(parse_balance(text, "r.toml")).results["quantities"]
    assert q["primary_resultant"]["value"] == pytest.approx(1.5 * F, rel=1e-12)
    assert not any(k.startswith("secondary") for k in q)


@pytest.mark.parametrize("old, new, words", [
    ("radial = 3", "radial = 2", "radial is the number of cylinders"),
    ("radial = 3", 'radial = "3"', "radial is the number of cylinders"),
    ("radial = 3", "radial = true", "radial is the number of cylinders"),
    ("radial = 3", "radial = 3\nvee = 120", "a V of two cylinders (vee = …) or a radial one"),
    ("radial = 3", "radial = 3\nbalanced = 0.5", "balanced is not taken for a radial engine"),
    ("radial = 3", "radial = 3\n[[cylinder]]\ncrank = 0",
     "a radial engine's cylinders work on one crank"),
])
def test_a_radial_engine_it_cannot_take_is_refused_in_one_line(old, new, words):
    with pytest.raises(InputError) as e:
        parse_balance(RADIAL.replace(old, new, 1), "r.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("r.toml:") and words in message, message
