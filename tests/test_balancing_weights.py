"""A rotor as the books give it in weights and asked its bearings' forces, and a balancing
file's units held to those it knows.

- Weights: the balance weight W_B at r_B balances W_i at r_i when W_B·r_B = |Σ W_i r_i e^{iθ_i}|
  (g divides every term alike, so the closed form needs none).
Tolerances: sums of a handful of products of exact data, 1e-12 relative.
"""

from __future__ import annotations

import cmath
import math

import pytest

from tarsim.constructions.errors import InputError
from tarsim.exercises.balancing.balance_solution import solve_balance
from tarsim.exercises.balancing.rotor_file import parse_balance

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
    assert any("balance weight 24.6661 N" in line for line in s.lines())


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
