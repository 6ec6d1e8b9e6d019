"""The flywheel's data as the books state them: a rim sized by its allowable hoop stress,
a punch's frictional losses (or its efficiency), and a length given with its own unit
("0.6 m" in a file whose holes are in mm); each number against its closed form."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.cli import cli
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


# ----- a punch's frictional losses -----------------------------------------------------------
def test_f1_punch_friction_losses():
    """6 J/mm² on 30 mm holes in 18 mm plate, 12 a minute, each punched in 1.2 s, the
    frictional losses 1/5 of the punching work, 200 to 180 rpm, k = 0.6 m typed as the book
    gives it in a file whose lengths are mm (heldout F1, the losses worked by hand before):
    E = 6·π·30·18 × 1.2 J, P = E/5 s = 2442.90 W, ΔE = E·(1 − 1.2/5), I = ΔE/(C_s·ω²) with
    ω = 190 rpm and C_s = 20/190, m = I/0.6² = 618.794 kg."""
    q = _q(_file("f1-punch-friction-losses"))
    energy = 6 * math.pi * 30 * 18 * 1.2
    delta_e = energy * (1 - 1.2 / 5)
    inertia = delta_e / (20 / 190 * (190 * RPM) ** 2)
    assert q["energy_supplied"] == pytest.approx(energy, rel=EXACT)
    assert q["power"] == pytest.approx(energy / 5, rel=EXACT)
    assert q["delta_E"] == pytest.approx(delta_e, rel=EXACT)
    assert q["inertia"] == pytest.approx(inertia, rel=EXACT)
    assert q["rim_mass"] == pytest.approx(inertia / 0.36, rel=EXACT)
    assert (round(q["power"], 2), round(q["rim_mass"], 3)) == (2442.90, 618.794)


_PUNCH = ('[units]\nspeed = "rpm"\n\n[punch]\nenergy = {energy!r}\nperiod = {period!r}\n'
          'punching_time = {time!r}\n{extra}\n\n[flywheel]\nspeed = 150\n'
          'speed_fluctuation = 0.1\n')


@settings(max_examples=25, deadline=None)
@given(st.floats(100, 1e5), st.floats(1, 60), st.floats(0.05, 0.9),
       st.just(0.0) | st.floats(1e-3, 1))
def test_losses_scale_the_work(energy, period, part, losses):
    """Any punch: with friction taking a share l of the work, the motor's power is
    E·(1 + l)/T and the flywheel's ΔE = E·(1 + l)·(1 − t/T); an efficiency η is 1/η."""
    ex = parse_flywheel(_PUNCH.format(energy=energy, period=period, time=part * period,
                                      extra=f"losses = {losses!r}"), "t.toml")
    q = _q(ex)
    assert q["power"] == pytest.approx(energy * (1 + losses) / period, rel=EXACT)
    assert q["delta_E"] == pytest.approx(energy * (1 + losses) * (1 - part), rel=1e-9)
    eta = 1 / (1 + losses)
    same = _q(parse_flywheel(_PUNCH.format(energy=energy, period=period, time=part * period,
                                           extra=f"efficiency = {eta!r}"), "t.toml"))
    # 1/(1/(1 + l)): two roundings apart
    assert same["power"] == pytest.approx(q["power"], rel=1e-15)


def test_efficiency_by_the_motor_power():
    """A 3 kW motor, 10 000 J a hole at an efficiency of 0.8: a hole every 12500/3000 s,
    60·3000/12500 = 14.4 holes a minute."""
    ex = parse_flywheel('[units]\nspeed = "rpm"\n\n[punch]\nenergy = 10000\npower = "3 kW"\n'
                        'punching_time = 1\nefficiency = 0.8\n\n[flywheel]\nspeed = 150\n'
                        'speed_fluctuation = 0.1\n', "t.toml")
    q = _q(ex)
    assert q["holes_per_minute"] == pytest.approx(14.4, rel=EXACT)
    assert q["energy_supplied"] == pytest.approx(12500, rel=EXACT)
    assert q["delta_E"] == pytest.approx(12500 * (1 - 1 / (12500 / 3000)), rel=EXACT)


@pytest.mark.parametrize("extra, words", [
    ("losses = 0.2\nefficiency = 0.8", "not both"),
    ("efficiency = 80", "0.8, not 80"),
    ("losses = -0.1", "from 0 and below 10"),
])
def test_losses_refused(extra, words):
    with pytest.raises(InputError) as e:
        parse_flywheel(_PUNCH.format(energy=1000.0, period=5.0, time=1.0, extra=extra),
                       "t.toml")
    assert words in str(e.value) and "t.toml:" in str(e.value)
    assert "\n" not in str(e.value) and len(str(e.value)) < 200


# ----- a length with its own unit ------------------------------------------------------------
_RIM = ('[units]\nspeed = "rpm"\nlength = "{unit}"\n\n[turning_moment]\n'
        'areas = [120, -150, 135, -165, 170, -110]\ntorque_scale = 200\nangle_scale = 4\n\n'
        '[flywheel]\nspeed = 500\nspeed_fluctuation = "±1 %"\n{rim}\n')


@pytest.mark.parametrize("unit, rim, metres", [
    ("mm", 'radius_of_gyration = "0.6 m"', 0.6),
    ("m", 'radius_of_gyration = "600 mm"', 0.6),
    ("mm", "radius_of_gyration = 600", 0.6),
    ("mm", 'diameter = "1.2 m"', 0.6),
    ("m", 'radius = "55 cm"', 0.55),
])
def test_a_length_with_its_unit(unit, rim, metres):
    """A radius given with its own unit is that length whatever the file's unit: the mass
    is I/r² with r in metres (I = 800π/(0.02·ω²), ω = 500 rpm)."""
    q = _q(parse_flywheel(_RIM.format(unit=unit, rim=rim), "t.toml"))
    inertia = 800 * math.pi / (0.02 * (500 * RPM) ** 2)
    assert q["rim_mass"] == pytest.approx(inertia / metres ** 2, rel=EXACT)


def test_a_hole_with_its_unit():
    """A punch's hole and plate in their own units are read in the file's: 3 cm and 0.018 m
    in a file of mm are 30 and 18, E = 6·π·30·18 J."""
    text = (HERE / "f1-punch-friction-losses.toml").read_text(encoding="utf-8")
    ex = parse_flywheel(text.replace("hole = 30", 'hole = "3 cm"')
                        .replace("plate = 18", 'plate = "0.018 m"'), "t.toml")
    assert ex.punch.energy == pytest.approx(6 * math.pi * 30 * 18, rel=EXACT)


@pytest.mark.parametrize("rim, words", [
    ('radius_of_gyration = "0.6 furlong"', "a length with its unit"),
    ('radius = "-2 m"', "must be positive"),
])
def test_a_length_refused(rim, words):
    with pytest.raises(InputError) as e:
        parse_flywheel(_RIM.format(unit="mm", rim=rim), "t.toml")
    assert words in str(e.value) and "t.toml:" in str(e.value) and "\n" not in str(e.value)


def test_a_rim_thicker_than_its_diameter_is_refused():
    """The book's 0.55 m rim typed as 0.55 in a file of mm: the rim of 7200 kg/m³ that holds
    0.9·I there would be t = √(m/(ρ·2πr)/2) thick, far past 2r, and a rim reaches in to
    r − t/2 > 0: refused in one line naming the radius in the file's unit, nothing solved."""
    text = _RIM.format(unit="mm", rim="radius = 0.55\ndensity = 7200\nwidth_to_thickness = 2")
    with pytest.raises(InputError) as e:
        _q(parse_flywheel(text, "t.toml"))
    assert "mean radius 0.55 mm" in str(e.value) and "\n" not in str(e.value)
    # the same rim at 550 mm is a rim: t = 54.98 mm < 1100 mm
    ok = _q(parse_flywheel(text.replace("radius = 0.55", "radius = 550"), "t.toml"))
    mass = 800 * math.pi / (0.02 * (500 * RPM) ** 2) / 0.55 ** 2
    assert ok["rim_thickness"] == pytest.approx(math.sqrt(mass / (7200 * 2 * math.pi * 0.55) / 2),
                                                rel=EXACT)


def test_the_length_is_said_where_it_is_used():
    """stdout names the radius of gyration in the file's unit where the mass is found from
    it, and a flywheel given by mass and k where its I is made: 0.6 typed in a file of mm
    shows as 0.6 mm beside a flywheel of 6.19e8 kg."""
    text = (HERE / "f1-punch-friction-losses.toml").read_text(encoding="utf-8")
    runner = CliRunner()
    with runner.isolated_filesystem():
        Path("f1.toml").write_text(text.replace('"0.6 m"', "0.6"), encoding="utf-8")
        done = runner.invoke(cli, ["solve", "f1.toml", "-o", "out", "--no-pdf"])
        assert done.exit_code == 0, done.output
        assert "radius of gyration is 0.6 mm: its mass m = I/k² = 6.18794e+08 kg" in done.output
        Path("r.toml").write_text('[punch]\nenergy = 10000\npower = "3 kW"\npunching_time = 1\n'
                                  '\n[units]\nspeed = "rpm"\nlength = "mm"\n\n[flywheel]\n'
                                  'speed_max = 300\nmass = 150\nradius_of_gyration = "0.6 m"\n',
                                  encoding="utf-8")
        done = runner.invoke(cli, ["solve", "r.toml", "-o", "out2", "--no-pdf"])
        assert done.exit_code == 0, done.output
        assert "a flywheel of 150 kg at 600 mm from the axis: I = m·k² = 54 kg·m²" in done.output


def test_rim_speed_takes_its_share():
    """A rim's speed given with the mean speed places the rim (r = v/ω), so the hub and arms
    may take their share of I as with a radius: m = 0.9·I/r², the hoop stress's rim when
    v = √(6e6/7200)."""
    v = math.sqrt(6e6 / 7200)
    by_speed = _q(_text(f"speed = 500\nspeed_fluctuation = 0.02\nrim_speed = {v!r}\n"
                        "rim_share = 0.9\n"))
    by_stress = _q(_text('speed = 500\nspeed_fluctuation = 0.02\nhoop_stress = "6 MPa"\n'
                         "density = 7200\nrim_share = 0.9\n"))
    r = v / (500 * RPM)
    inertia = 800 * math.pi / (0.02 * (500 * RPM) ** 2)
    assert by_speed["rim_mass"] == pytest.approx(0.9 * inertia / r ** 2, rel=EXACT)
    assert by_stress["rim_mass"] == pytest.approx(by_speed["rim_mass"], rel=EXACT)
