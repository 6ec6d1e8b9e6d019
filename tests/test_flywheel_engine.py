"""The flywheel as the books pose it without a drawn diagram: the flywheel and its speeds
alone (ΔE = ½·I·(ω1² − ω2²)), ΔE given, the engine's power with C_E, the strokes' works as
triangles, and one cylinder's diagram added over several cylinders; each number against
its closed form, the textbook problems typed as the books state them among them."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.catalog import load
from tarsim.exercises.cli import cli
from tarsim.exercises.forces.flywheel_file import parse_flywheel
from tarsim.exercises.forces.flywheel_solution import solve_flywheel

HERE = Path(__file__).parent / "reproducers"
RPM = 2 * math.pi / 60

EXACT = 1e-12
"""Each number here is a product or quotient of a few given ones, or a table's trapezoids:
exact but for a few roundings."""


def _q(ex):
    checked = solve_flywheel(ex).checked
    assert all(c.passed is not False for c in checked.values()), checked
    return {k: c.value["value"] for k, c in checked.items()}


def _file(name):
    path = HERE / f"{name}.toml"
    return parse_flywheel(path.read_text(encoding="utf-8"), str(path))


def test_f1_energy_from_speeds():
    """4 t at k = 1.5 m between 150 and 146 rpm, no diagram: ΔE = ½·I·(ω1² − ω2²) = 58 428 J,
    C_s = 4/148 (heldout F1, refused before: "a flywheel file needs a diagram")."""
    q = _q(_file("f1-energy-from-speeds"))
    inertia = 4000 * 1.5 ** 2
    assert q["delta_E"] == pytest.approx(inertia * ((150 * RPM) ** 2 - (146 * RPM) ** 2) / 2,
                                         rel=EXACT)
    assert round(q["delta_E"]) == 58428
    assert q["speed_fluctuation"] == pytest.approx(4 / 148, rel=EXACT)
    assert q["speed"] == pytest.approx(148 * RPM, rel=EXACT)
    assert q["inertia"] == inertia
    assert q["kinetic_energy"] == pytest.approx(inertia * (148 * RPM) ** 2 / 2, rel=EXACT)


def test_f2_energy_coefficient_rim():
    """185 kW at 100 rpm, C_E = 0.15 of the work a revolution, ±1 %, a rim of 2.4 m mean
    diameter, 7200 kg/m³, four times as wide as thick (heldout F2): W = 185000·0.6 J,
    ΔE = 0.15·W, m = ΔE/(C_s·ω²·r²) = 5271.9 kg, t = 0.15581 m, b = 0.62325 m."""
    q = _q(_file("f2-energy-coefficient-rim"))
    work = 185000 * 60 / 100
    mass = 0.15 * work / (0.02 * (100 * RPM) ** 2 * 1.2 ** 2)
    thickness = math.sqrt(mass / (7200 * 2 * math.pi * 1.2) / 4)
    assert q["work_per_cycle"] == pytest.approx(work, rel=EXACT)
    assert q["delta_E"] == pytest.approx(0.15 * work, rel=EXACT)
    assert q["rim_mass"] == pytest.approx(mass, rel=EXACT)
    assert round(q["rim_mass"], 1) == 5271.9
    assert q["rim_thickness"] == pytest.approx(thickness, rel=EXACT)
    assert q["rim_width"] == pytest.approx(4 * thickness, rel=EXACT)


def test_f3_four_stroke_triangles():
    """18 kW at 360 rpm, four-stroke, the expansion three times the compression, triangles,
    ±1.5 % (heldout F3): W = 6000 J a cycle, 3000 J on compression, 9000 J on expansion;
    the expansion's triangle h = 2·9000/π high over T_mean = 6000/(4π) has ΔE =
    ½·π·(h − T_mean)²/h = 7562.5 J, I = ΔE/(0.03·ω²) = 177.37 kg·m²."""
    q = _q(_file("f3-four-stroke-triangles"))
    mean, h = 6000 / (4 * math.pi), 18000 / math.pi
    delta_e = math.pi / 2 * (h - mean) ** 2 / h
    assert q["power"] == pytest.approx(18000, rel=EXACT)
    assert q["delta_E"] == pytest.approx(delta_e, rel=EXACT)
    assert q["delta_E"] == pytest.approx(7562.5, rel=EXACT)
    assert q["inertia"] == pytest.approx(delta_e / (0.03 * (360 * RPM) ** 2), rel=EXACT)
    assert round(q["inertia"], 2) == 177.37


def test_f4_three_cylinder_triangles():
    """Three cylinders at 120°, each a triangle to 120 N·m at 60° over 180°, 500 rpm,
    15 kg at k = 0.1 m (heldout F4): the sum runs 60 + θ then 180 − θ each third of a
    turn, T_mean = 90 N·m, ΔE = ½·(π/3)·30, P = 4712.4 W, C_s = 0.038197, C_E = 1/36,
    α max = 30/0.15 = 200 rad/s²."""
    q = _q(_file("f4-three-cylinder-triangles"))
    omega, inertia = 500 * RPM, 15 * 0.1 ** 2
    delta_e = math.pi / 6 * 30
    assert q["mean_torque"] == pytest.approx(90, rel=EXACT)
    assert q["power"] == pytest.approx(90 * omega, rel=EXACT)
    assert q["delta_E"] == pytest.approx(delta_e, rel=EXACT)
    assert q["speed_fluctuation"] == pytest.approx(delta_e / (inertia * omega ** 2), rel=EXACT)
    assert q["energy_fluctuation"] == pytest.approx(1 / 36, rel=EXACT)
    assert q["greatest_acceleration"] == pytest.approx(200, rel=EXACT)


def test_f5_harmonic_flywheel_given():
    """T = 8000 + 2400 sin 3θ at 240 rpm, 400 kg at k = 0.6 m (heldout F5): results.json
    gives the greatest and least speeds in rad/s with their rpm beside them, 240·(1 ± C_s/2)
    with C_s = 1600/(144·ω²); the harmonic's ΔE by quadrature, so 1e-9."""
    sol = solve_flywheel(_file("f5-harmonic-flywheel-given"))
    q = {k: c.entry() for k, c in sol.checked.items()}
    cs = 1600 / (144 * (240 * RPM) ** 2)
    for key, side in (("speed_max", 1), ("speed_min", -1)):
        assert q[key]["unit"] == "rad/s"
        assert q[key]["value"] == pytest.approx(240 * RPM * (1 + side * cs / 2), rel=1e-9)
        assert q[key]["rpm"] == pytest.approx(240 * (1 + side * cs / 2), rel=1e-9)
    assert round(q["speed_max"]["rpm"], 2) == 242.11


def test_flywheel_between_speeds():
    """The bundled flywheel-between-speeds: 2.5 t at k = 1.2 m, 200 and 196 rpm: ΔE =
    ½·3600·(π/30)²·(200² − 196²) = 3168π² J, C_s = 4/198."""
    q = _q(load("flywheel-between-speeds"))
    assert q["delta_E"] == pytest.approx(3168 * math.pi ** 2, rel=EXACT)
    assert q["speed_fluctuation"] == pytest.approx(4 / 198, rel=EXACT)


def test_steam_engine_energy_coefficient():
    """The bundled steam engine: 120 kW at 150 rpm, C_E = 0.2, ±1.5 %, a rim of 1 m mean
    radius: W = 48 000 J, ΔE = 9600 J, I = 9600/(0.03·(5π)²) = 12 800/π², m = I."""
    q = _q(load("steam-engine-energy-coefficient"))
    assert q["delta_E"] == pytest.approx(9600, rel=EXACT)
    assert q["inertia"] == pytest.approx(12800 / math.pi ** 2, rel=EXACT)
    assert q["rim_mass"] == pytest.approx(12800 / math.pi ** 2, rel=EXACT)


def test_four_stroke_triangles():
    """The bundled four-stroke engine: 12 kW at 300 rpm, the expansion four times the
    compression: W = 4800 J, the strokes 0, −1600, 6400, 0 J, h = 12 800/π, T_mean =
    1200/π, ΔE = ½·π·(h − T_mean)²/h; strokes given in J alone give the same."""
    ex = load("four-stroke-triangles")
    assert ex.strokes == pytest.approx((0, -1600, 6400, 0), rel=EXACT)
    q = _q(ex)
    h, mean = 12800 / math.pi, 1200 / math.pi
    assert q["delta_E"] == pytest.approx(math.pi / 2 * (h - mean) ** 2 / h, rel=EXACT)
    in_joules = parse_flywheel('[units]\nspeed = "rpm"\n[turning_moment]\ncycle = 720\n'
                               'strokes = [0, -1600, 6400, 0]\n[flywheel]\nspeed = 300\n'
                               'speed_fluctuation = "±2 %"\n', "j.toml")
    assert _q(in_joules)["delta_E"] == pytest.approx(q["delta_E"], rel=EXACT)
    words = parse_flywheel('[units]\nspeed = "rpm"\n[turning_moment]\ncycle = 720\n'
                           'power = 12000\nexpansion_to_compression = 4\n[flywheel]\n'
                           'speed = 300\nspeed_fluctuation = "±2 %"\n', "w.toml")
    assert words.points == ex.points


def test_three_cylinder_triangles():
    """The bundled three-cylinder engine: 0 at 0°, 150 at 75°, 0 at 180°, none on the
    return, 120° apart: each third of a turn the sum runs 600/7 + 4θ/7 to 120 at 60°, 2θ to
    150 at 75°, 150·(180 − θ)/105 back to 600/7 at 120°; T_mean = 3·(½·180·150)/360 =
    112.5 crosses it at 46.875° and 101.25°, and the area above, three trapezoids (0, 7.5,
    37.5, 0 N·m at 46.875°, 60°, 75°, 101.25°), is ΔE = 878.90625° N·m; α max = 37.5/0.288,
    the greatest retardation (112.5 − 600/7)/0.288; phases = [0, 120, 240] give the same."""
    ex = load("three-cylinder-triangles")
    q = _q(ex)
    assert q["mean_torque"] == pytest.approx(112.5, rel=EXACT)
    above = 13.125 * 7.5 / 2 + 15 * (7.5 + 37.5) / 2 + 26.25 * 37.5 / 2
    assert above == 878.90625
    assert q["delta_E"] == pytest.approx(math.radians(above), rel=EXACT)
    assert q["greatest_acceleration"] == pytest.approx(37.5 / 0.288, rel=EXACT)
    assert q["greatest_retardation"] == pytest.approx((112.5 - 600 / 7) / 0.288, rel=EXACT)
    text = (HERE.parent.parent / "exercises" / "catalog" / "flywheel" /
            "three-cylinder-triangles.toml").read_text(encoding="utf-8")
    phased = parse_flywheel(text.replace("cylinders = 3", "phases = [0, 120, 240]"), "p.toml")
    assert [x for p in phased.points for x in p] == pytest.approx(
        [x for p in ex.points for x in p], abs=1e-12)


def test_a_formulas_cylinders_add_their_harmonics():
    """Two cylinders 180° apart, each T = 1000 + 400 sin θ: the sines cancel and the sum is
    steady at 2000 N·m; three 120° apart, each 500 + 300 sin 3θ: the third harmonics add,
    1500 + 900 sin 3θ, ΔE = 2·900/3 (quadrature: to some 1e-12)."""
    two = parse_flywheel('[turning_moment]\ntorque = "1000 + 400*sin(theta)"\ncylinders = 2\n'
                         '[flywheel]\nspeed = 50\ninertia = 10\n', "two.toml")
    assert two.diagram.torque(0.7) == pytest.approx(2000, rel=EXACT)
    three = parse_flywheel('[turning_moment]\ntorque = "500 + 300*sin(3*theta)"\n'
                           'cylinders = 3\n[flywheel]\nspeed = 50\ninertia = 10\n', "3.toml")
    q = _q(three)
    assert q["mean_torque"] == pytest.approx(1500, rel=1e-12)
    assert q["delta_E"] == pytest.approx(600, rel=1e-9)


@settings(max_examples=40, deadline=None)
@given(st.floats(1.0, 1e4), st.floats(10.0, 500.0), st.floats(0.001, 0.3))
def test_no_diagram_energy_is_the_kinetic_energies_difference(inertia, rpm, share):
    """Any flywheel between any two speeds: ΔE = ½·I·(ω1² − ω2²), C_s = (ω1 − ω2)/ω with ω
    their mean; the reading rounds a product of three numbers, so 1e-12."""
    high, low = rpm, rpm * (1 - share)
    ex = parse_flywheel(f'[units]\nspeed = "rpm"\n[flywheel]\nspeed_max = {high!r}\n'
                        f'speed_min = {low!r}\ninertia = {inertia!r}\n', "p.toml")
    q = _q(ex)
    w1, w2 = high * RPM, low * RPM
    assert q["delta_E"] == pytest.approx(inertia * (w1 * w1 - w2 * w2) / 2, rel=1e-12)
    assert q["speed_fluctuation"] == pytest.approx(2 * (w1 - w2) / (w1 + w2), rel=1e-12)


@pytest.mark.parametrize("text, message", [
    ('[flywheel]\nspeed = 100\ninertia = 5\n',
     r"f.toml:1: a flywheel file with no diagram gives the flywheel with its greatest"),
    ('[flywheel]\nspeed_max = 100\nspeed_min = 98\n',
     r"f.toml:1: give the flywheel once: inertia"),
    ('[flywheel]\nspeed_max = 100\nspeed_min = 98\ninertia = 5\ndensity = 7200\n',
     r"f.toml:5: density needs ΔE from a diagram"),
    ('[turning_moment]\npower = 1000\n[flywheel]\nspeed = 10\nspeed_fluctuation = 0.02\n',
     r"f.toml:2: power gives the work done in a cycle: give with it energy_fluctuation"),
    ('[turning_moment]\npower = 1000\nenergy_fluctuation = 0.1\n[flywheel]\n'
     'speed_fluctuation = 0.02\nradius = 1\n', r"f.toml:3: energy_fluctuation needs the "
     r"engine's mean speed"),
    ('[turning_moment]\ntorque = "100 + sin(theta)"\npower = 1000\n[flywheel]\nspeed = 10\n'
     'inertia = 1\n', r"f.toml:3: power gives the work done in a cycle, for"),
    ('[turning_moment]\nstrokes = [0, -3, 1, 0]\n[flywheel]\nspeed = 10\ninertia = 1\n',
     r"f.toml:2: the strokes' works add to -2"),
    ('[turning_moment]\npoints = [[0, 0], [60, 5], [60, 0]]\ncylinders = 3\n[flywheel]\n'
     'speed = 10\ninertia = 1\n', r"f.toml:2: cylinders add tables that run straight"),
    ('[turning_moment]\npoints = [[0, 0], [60, 5], [180, 0]]\ncylinders = 2.5\n[flywheel]\n'
     'speed = 10\ninertia = 1\n', r"f.toml:3: cylinders is how many, a whole number"),
    ('[turning_moment]\ntorque = "100 + sin(theta)"\n[flywheel]\nspeed = 10\ninertia = 1\n'
     'delta_E = 5\n', r"f.toml:6: delta_E is given where no diagram gives it"),
])
def test_a_bad_book_engine_is_refused_in_one_line(text, message):
    with pytest.raises(InputError, match=message) as e:
        parse_flywheel(text, "f.toml")
    assert "\n" not in str(e.value) and len(str(e.value)) < 260


def test_given_energy_finds_the_flywheel_and_the_cli_writes_it(tmp_path):
    """ΔE = 50 kJ given, 300 rpm within ±1 %: I = 50000/(0.02·(10π)²) = 25 000/π²; the
    solve writes results.json with it, and energy.svg."""
    path = tmp_path / "given.toml"
    path.write_text('[units]\nspeed = "rpm"\n[flywheel]\nspeed = 300\n'
                    'speed_fluctuation = "±1 %"\ndelta_E = 50000\n', encoding="utf-8")
    result = CliRunner().invoke(cli, ["solve", str(path), "--no-pdf", "-o",
                                      str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    q = json.loads((tmp_path / "out" / "results.json").read_text())["quantities"]
    assert q["inertia"]["value"] == pytest.approx(25000 / math.pi ** 2, rel=EXACT)
    assert (tmp_path / "out" / "energy.svg").exists()
