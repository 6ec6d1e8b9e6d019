"""Loads as the books give them: a gas pressure on a bore (or a piston area) for a force, a
radius of gyration for a moment of inertia, and a piston that needs no inertia, each
against a closed form."""

from __future__ import annotations

import json
import math

import pytest
from click.testing import CliRunner

from tarsim.constructions.errors import InputError
from tarsim.exercises.catalog import resolve
from tarsim.exercises.chapters import read_file
from tarsim.exercises.cli import cli

R, L, BORE, MASS = 0.06, 0.27, 0.1, 1.2
OMEGA = 1800 * math.pi / 30
THETA = math.radians(20)


def _piston_acceleration() -> float:
    """The piston's exact acceleration along +x (toward the crank's head end), from
    x = r cos θ + √(l² − r² sin² θ) twice differentiated at steady ω."""
    s = L * L - R * R * math.sin(THETA) ** 2
    return OMEGA ** 2 * (-R * math.cos(THETA) - R * R * math.cos(2 * THETA) / math.sqrt(s)
                         - R ** 4 * math.sin(2 * THETA) ** 2 / (4 * s ** 1.5))


def _text(**changes: str) -> str:
    text = resolve("engine-gas-pressure").read_text(encoding="utf-8")
    for old, new in changes.items():
        assert old in text, old
        text = text.replace(old, new)
    return text


def _solve(tmp_path, text: str, name: str = "e") -> dict:
    path = tmp_path / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    out = tmp_path / name
    result = CliRunner().invoke(cli, ["solve", str(path), "--no-pdf", "-o", str(out)])
    assert result.exit_code == 0, result.output
    return json.loads((out / "results.json").read_text(encoding="utf-8"))


def _value(results: dict, name: str) -> float:
    (position,) = results["positions"]
    return position["quantities"][name]["value"]


def test_engine_gas_pressure(tmp_path):
    """650 kN/m² on a 100 mm bore is p·π·d²/4 = 5105.09 N toward the crank; the piston
    effort is that less the reciprocating parts' m·a, the exact a (the books'
    cos θ + cos 2θ/n drops the terms of order (r/l)³, 4 N here)."""
    results = _solve(tmp_path, resolve("engine-gas-pressure").read_text(encoding="utf-8"))
    gas = 650e3 * math.pi * BORE ** 2 / 4
    effort = gas + MASS * _piston_acceleration()
    # the polygons and the Newton–Euler reference both agree with this to rounding
    assert _value(results, "piston_effort") == pytest.approx(effort, rel=1e-12)


def test_a_massless_rod_gives_the_books_crank_effort(tmp_path):
    """With the rod's mass left out, the rod is a two-force member: F_T = F_P·sin(θ + φ)/cos φ
    (sin φ = sin θ/n) and the turning moment F_T·r."""
    text = _text(**{"[[mass]]\nlink = 3\nmass = 2.0\ncentre = [100, 0]           # from the crank "
                    "pin A toward P\nradius_of_gyration = 110    # I = m·k²\n": ""})
    results = _solve(tmp_path, text)
    effort = 650e3 * math.pi * BORE ** 2 / 4 + MASS * _piston_acceleration()
    phi = math.asin(math.sin(THETA) * R / L)
    crank = effort * math.sin(THETA + phi) / math.cos(phi)
    assert _value(results, "crank_effort") == pytest.approx(crank, rel=1e-12)
    assert _value(results, "wall_thrust") == pytest.approx(effort * math.tan(phi), rel=1e-12)
    assert _value(results, "turning_moment") == pytest.approx(crank * R, rel=1e-12)


@pytest.mark.parametrize("given", ['pressure = "0.65 N/mm²"', 'pressure = "6.5 bar"',
                                   "pressure = 650000", 'pressure = "0.65 MPa"',
                                   'pressure = "650 kN/m²"', 'pressure = "0.65 MN/m2"'])
@pytest.mark.parametrize("on", ["bore = 100", f"area = {math.pi * 100 ** 2 / 4!r}"])
def test_a_pressure_in_any_unit_on_a_bore_or_an_area_is_one_force(given, on, tmp_path):
    text = _text(**{'pressure = "650 kPa"': given, "bore = 100": on})
    path = tmp_path / "p.toml"
    path.write_text(text, encoding="utf-8")
    (force,) = read_file(path, "p").loads.forces
    assert force.force[0] == pytest.approx(-650e3 * math.pi * BORE ** 2 / 4, rel=1e-14)
    assert force.force[1] == 0.0 and force.name == "gas force"


def test_a_radius_of_gyration_is_an_inertia_m_k_squared(tmp_path):
    given = read_file(resolve("engine-gas-pressure"), "g").loads
    assert given.mass_of(3).inertia == pytest.approx(2.0 * 0.11 ** 2, rel=1e-15)
    same = _text(**{"radius_of_gyration = 110    # I = m·k²": "inertia = 0.0242"})
    a = _solve(tmp_path, resolve("engine-gas-pressure").read_text(encoding="utf-8"), "a")
    b = _solve(tmp_path, same, "b")
    assert _value(a, "T2") == pytest.approx(_value(b, "T2"), rel=1e-12)


def test_a_piston_needs_no_inertia(tmp_path):
    """It slides without turning: α = 0, so whatever I is, I·α = 0; one given changes
    nothing. A link that turns still needs one (or a length, for a slender rod's)."""
    loads = read_file(resolve("engine-gas-pressure"), "g").loads
    assert loads.mass_of(4).inertia == 0.0
    with_one = _text(**{'centre = "P"\n': 'centre = "P"\ninertia = 0.5\n'})
    a = _solve(tmp_path, resolve("engine-gas-pressure").read_text(encoding="utf-8"), "a")
    b = _solve(tmp_path, with_one, "b")
    assert _value(a, "T2") == _value(b, "T2")


@pytest.mark.parametrize("change, key, words", [
    ({"bore = 100": "bore = 100\narea = 7854"}, "pressure", "give one"),
    ({"bore = 100": ""}, "pressure", "give one"),
    ({'pressure = "650 kPa"': 'pressure = "650 psi"'}, "pressure", "a pressure's unit is one of"),
    ({'pressure = "650 kPa"': 'pressure = "650 kPa"\nforce = [1, 0]'}, "force", "not both"),
    ({"bore = 100": "bore = -100"}, "bore", "the bore is the piston's diameter"),
    ({"bore = 100": "bore = 1e-8"}, "bore", "the bore must be between"),
    ({"bore = 100": "bore = 100\nrod = 1e9"}, "rod", "the piston rod's diameter must be"),
    ({"bore = 100": "area = 1e-9"}, "area", "the area must be between"),
    ({'point = "P"\npressure': 'point = [0, 0]\npressure'}, "pressure", "frame guide"),
    ({"radius_of_gyration = 110    # I = m·k²": "radius_of_gyration = 110\ninertia = 1"},
     "radius_of_gyration", "given twice"),
    ({"radius_of_gyration = 110    # I = m·k²": "radius_of_gyration = 0"},
     "radius_of_gyration", "positive"),
])
def test_a_bad_load_is_refused_at_its_line(change, key, words, tmp_path):
    text = _text(**change)
    line = next(i for i, s in enumerate(text.splitlines(), 1) if s.startswith(f"{key} ="))
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(InputError) as e:
        read_file(path, "bad")
    message = str(e.value)
    assert message.startswith(f"{path}:{line}: ") and words in message, message
    assert "\n" not in message
