"""A rotor as the books give it in weights and asked its bearings' forces, and a balancing
file's units held to those it knows.

- Weights: the balance weight W_B at r_B balances W_i at r_i when W_B·r_B = |Σ W_i r_i e^{iθ_i}|
  (g divides every term alike, so the closed form needs none).
Tolerances: sums of a handful of products of exact data, 1e-12 relative.
"""

from __future__ import annotations

import pytest

from tarsim.constructions.errors import InputError
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
