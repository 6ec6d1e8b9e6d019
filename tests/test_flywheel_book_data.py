"""The flywheel's data as the books state them: a rim sized by its allowable hoop stress,
a punch's frictional losses (or its efficiency), and a length given with its own unit
("0.6 m" in a file whose holes are in mm); each number against its closed form."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.forces.flywheel_file import parse_flywheel
from tarsim.exercises.forces.flywheel_solution import solve_flywheel

HERE = Path(__file__).parent / "reproducers"
RPM = 2 * math.pi / 60

EXACT = 1e-12
"""Each number here is a product, quotient or square root of a few given ones, or a table's
trapezoids (the areas' energies): exact but for a few roundings."""


def _q(ex):
    checked = solve_flywheel(ex).checked
    assert all(c.passed is not False for c in checked.values()), checked
    return {k: c.value["value"] for k, c in checked.items()}


def _file(name):
    path = HERE / f"{name}.toml"
    return parse_flywheel(path.read_text(encoding="utf-8"), str(path))


def _text(flywheel: str, head: str = "[units]\nspeed = \"rpm\"\n\n[turning_moment]\n"
          "areas = [120, -150, 135, -165, 170, -110]\ntorque_scale = 200\nangle_scale = 4\n"):
    return parse_flywheel(f"{head}\n[flywheel]\n{flywheel}", "t.toml")


# ----- a rim sized by its hoop stress --------------------------------------------------------
def test_f2_multicyl_areas_hoop_stress_rim():
    """Areas +120, −150, +135, −165, +170, −110 mm² at 200 N·m and 4° a mm, 500 rpm ±1 %,
    a rim of 7200 kg/m³ within 6 MPa giving 90 % of I, twice as broad as thick (heldout
    F2, the rim's radius worked by hand before): ΔE = 180 mm² at 200 N·m × 4° = 800π J,
    I = 45.8366 kg·m²,
    v = √(6e6/7200) = 28.8675 m/s, D = 2v/ω = 1.10266 m, t = 52.160 mm, b = 104.321 mm."""
    q = _q(_file("f2-multicyl-areas-hoop-stress-rim"))
    omega = 500 * RPM
    # the energy's running sum: 0, 120, −30, 105, −60, 110; ΔE = 180 mm² at 200·4π/180 J each
    delta_e = 180 * 200 * math.radians(4)
    inertia = delta_e / (0.02 * omega ** 2)
    v = math.sqrt(6e6 / 7200)
    r = v / omega
    mass = 0.9 * inertia / r ** 2
    t = math.sqrt(mass / (7200 * 2 * math.pi * r) / 2)
    assert q["delta_E"] == pytest.approx(delta_e, rel=EXACT)
    assert q["inertia"] == pytest.approx(inertia, rel=EXACT)
    assert q["rim_speed"] == pytest.approx(v, rel=EXACT)
    assert q["rim_radius"] == pytest.approx(r, rel=EXACT)
    assert q["rim_mass"] == pytest.approx(mass, rel=EXACT)
    assert q["rim_thickness"] == pytest.approx(t, rel=EXACT)
    assert q["rim_width"] == pytest.approx(2 * t, rel=EXACT)
    # the heldout's hand values, to the four figures it gives
    assert (round(q["inertia"], 4), round(2 * r, 5)) == (45.8366, 1.10266)
    assert (round(1000 * t, 3), round(2000 * t, 3)) == (52.160, 104.321)


@settings(max_examples=40, deadline=None)
@given(st.floats(1e6, 2e7), st.floats(1000, 9000), st.floats(100, 1000))
def test_hoop_stress_is_rho_v_squared(sigma, rho, rpm):
    """Any stress and density: the rim runs at v = √(σ/ρ) (so ρ·v² = σ), its radius v/ω and
    its mass I/r², and a stress in Pa is the same as in MPa (÷1e6 and back: two roundings)."""
    ex = _text(f'speed = {rpm!r}\nspeed_fluctuation = 0.02\nhoop_stress = {sigma!r}\n'
               f'density = {rho!r}\n')
    q = _q(ex)
    assert rho * q["rim_speed"] ** 2 == pytest.approx(sigma, rel=EXACT)
    assert q["rim_radius"] == pytest.approx(q["rim_speed"] / (rpm * RPM), rel=EXACT)
    assert q["rim_mass"] == pytest.approx(q["inertia"] / q["rim_radius"] ** 2, rel=EXACT)
    same = _text(f'speed = {rpm!r}\nspeed_fluctuation = 0.02\n'
                 f'hoop_stress = "{sigma / 1e6!r} MPa"\ndensity = {rho!r}\n')
    assert same.hoop_stress == pytest.approx(sigma, rel=1e-15)


@pytest.mark.parametrize("extra, words", [
    ("radius = 0.5", "leave radius out"),
    ("rim_speed = 25", "leave rim_speed out"),
    ("diameter = 1", "leave diameter out"),
    ("mass = 100", "leave mass out"),
])
def test_hoop_stress_refuses_another_rim(extra, words):
    """The stress fixes the rim's speed, radius and mass: a second rim given is refused in
    one line at its own line."""
    with pytest.raises(InputError) as e:
        _text(f'speed = 500\nspeed_fluctuation = 0.02\nhoop_stress = "6 MPa"\n'
              f'density = 7200\n{extra}\n')
    assert words in str(e.value) and "t.toml:" in str(e.value)
    assert "\n" not in str(e.value) and len(str(e.value)) < 200


@pytest.mark.parametrize("flywheel, words", [
    ('hoop_stress = "6 MPa"', "give density"),
    ('hoop_stress = "6 furlongs"\ndensity = 7200', "a stress with its unit"),
    ("hoop_stress = -6e6\ndensity = 7200", "must be positive"),
])
def test_hoop_stress_refused(flywheel, words):
    with pytest.raises(InputError) as e:
        _text(f"speed = 500\nspeed_fluctuation = 0.02\n{flywheel}\n")
    assert words in str(e.value) and "\n" not in str(e.value)
