"""A two-plane balance's force in each plane is said to be on a bearing only where the file
says the plane is a bearing's (``[[balance]] bearing = true``); elsewhere it is the force in
that plane, the masses' force and couple shared between the two planes.

The bundled ``bearing-forces`` (4, 3 and 2.5 kg at 75, 85 and 50 mm, at 45°, 135° and 240°,
in planes 225, 425 and 600 mm from bearing L, bearings 800 mm apart, 200 rpm) is held to
moments about each bearing: F_R = ω²·|Σ mᵢrᵢzᵢ e^{iθᵢ}|/800 mm and
F_L = ω²·|Σ mᵢrᵢ(800 − zᵢ) e^{iθᵢ}|/800 mm, sums of three products of order 0.1 kg·m
agreeing to a few roundings, 1e-12 relative.
"""

from __future__ import annotations

import cmath
import math

import pytest

from tarsim.constructions.errors import InputError
from tarsim.exercises.balancing.balance_solution import solve_balance
from tarsim.exercises.balancing.rotor_file import parse_balance
from tarsim.exercises.catalog import load

MASSES = [(4.0, 0.075, 45.0, 0.225), (3.0, 0.085, 135.0, 0.425), (2.5, 0.050, 240.0, 0.600)]
OMEGA = 200 * 2 * math.pi / 60


def test_bundled_bearings_are_named_bearings():
    """The bundled shaft's planes are its bearings': each force is on a bearing, by moments."""
    s = solve_balance(load("bearing-forces"))
    q = s.checked
    sums = {"R": sum(m * r * cmath.exp(1j * math.radians(a)) * z for m, r, a, z in MASSES)
            / 0.8,
            "L": sum(m * r * cmath.exp(1j * math.radians(a)) * (0.8 - z)
                     for m, r, a, z in MASSES) / 0.8}
    for name, v in sums.items():
        assert q[f"force_{name}"].value["value"] == pytest.approx(abs(v) * OMEGA ** 2,
                                                                  rel=1e-12)
        assert any(line.startswith(f"the out-of-balance force on a bearing in plane {name}:")
                   for line in s.lines())


def _rotor(extra: str, engine: bool = False) -> str:
    return ('[rotor]\nspeed = 10\n[[mass]]\nmass = 1\nradius = 0.1\nangle = 0\nplane = 0.2\n'
            f'[[balance]]\nplane = 0\nradius = 0.1\n{extra}'
            '[[balance]]\nplane = 1\nradius = 0.1\n')


def test_planes_not_bearings_are_planes():
    """Without bearing = true, the force is in the plane, and no line speaks of a bearing."""
    s = solve_balance(parse_balance(_rotor(""), "r.toml"))
    lines = [line for line in s.lines() if "out-of-balance force" in line]
    assert len(lines) == 2 and not any("bearing" in line for line in lines)
    mine = solve_balance(parse_balance(_rotor("bearing = true\n"), "r.toml")).lines()
    assert sum("on a bearing in plane A" in line for line in mine) == 1
    assert not any("on a bearing in plane B" in line for line in mine)


@pytest.mark.parametrize("text, says", [
    (_rotor('bearing = "yes"\n'), "true or false"),
    ("[engine]\nspeed = 10\ncrank = 0.3\nreciprocating = 300\nbalanced = 0.5\n"
     "[[cylinder]]\ncrank = 0\nplane = 0.45\n[[cylinder]]\ncrank = 90\nplane = 1.1\n"
     "[[balance]]\nplane = 0\nradius = 0.7\nbearing = true\n"
     "[[balance]]\nplane = 1.55\nradius = 0.7\n", "not taken for an engine's wheels"),
])
def test_bearing_refusals(text, says):
    """bearing is a boolean, and a rotor's: refused in one line at its place otherwise."""
    with pytest.raises(InputError) as e:
        parse_balance(text, "r.toml")
    assert says in str(e.value) and "r.toml:" in str(e.value)
    assert "\n" not in str(e.value) and len(str(e.value)) < 200
