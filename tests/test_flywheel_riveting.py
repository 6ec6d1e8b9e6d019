"""A riveting machine or press given as the books give it: the motor's power in [punch] (a
rivet every E/P) and the flywheel with its speed before the operation alone (the least
speed after it from ΔE = ½I(ω1² − ω2²))."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.forces.flywheel_file import parse_flywheel
from tarsim.exercises.forces.flywheel_solution import solve_flywheel

RPM = math.pi / 30

RIVETING = """
[units]
speed = "rpm"
[punch]
energy = 10000
power = "3 kW"
punching_time = 1
[flywheel]
speed_max = 300
mass = 150
radius_of_gyration = 0.6
"""


def _q(text: str):
    return solve_flywheel(parse_flywheel(text, "r.toml")).checked


def test_flywheel_riveting_motor_power():
    """The books' riveting machine: 3 kW, 10 000 J a rivet in 1 s, 150 kg at 0.6 m at
    300 rpm before riveting. A rivet every 10/3 s: 18 a minute; ΔE = 10000 − 3000 = 7000 J;
    ω2 = √(ω1² − 2ΔE/I) = 257.60 rpm (the books' answer)."""
    q = _q(RIVETING)
    w1, inertia = 300 * RPM, 150 * 0.6 ** 2
    w2 = math.sqrt(w1 ** 2 - 2 * 7000 / inertia)
    # sums of a few numbers each rounded once: a few ulps
    assert q["holes_per_minute"].value["value"] == pytest.approx(18, rel=1e-14)
    assert q["delta_E"].value["value"] == pytest.approx(7000, rel=1e-14)
    assert q["speed_min"].value["value"] == pytest.approx(w2, rel=1e-13)
    assert round(q["speed_min"].value["value"] / RPM, 2) == 257.60
    assert q["speed"].value["value"] == pytest.approx((w1 + w2) / 2, rel=1e-13)
    assert q["speed_fluctuation"].value["value"] == pytest.approx(2 * (w1 - w2) / (w1 + w2),
                                                                  rel=1e-12)
    assert all(c.passed for c in q.values())


@pytest.mark.parametrize("power, unit", [('"3 kW"', ""), ("3000", ""), ('"3000 W"', ""),
                                         ('"0.003 MW"', ""), ('"6/2 kW"', ""),
                                         ("3", 'power = "kW"'), ('"3 kW"', 'power = "MW"')])
def test_a_motor_s_power_in_any_unit_gives_the_same_rate(power, unit):
    """A plain number is in [units] power (W unless it says); a string says its own unit."""
    q = _q(RIVETING.replace('"3 kW"', power).replace('speed = "rpm"',
                                                     f'speed = "rpm"\n{unit}'))
    assert q["holes_per_minute"].value["value"] == pytest.approx(18, rel=1e-14)


def test_a_least_speed_alone_gives_the_greatest():
    """speed_min alone: ω1 = √(ω2² + 2ΔE/I), a harmonic torque's ΔE = its amplitude
    6000 J (to the quadrature's and drawing's few parts in 10⁶)."""
    q = _q('[units]\nspeed = "rpm"\n[turning_moment]\ntorque = "15000 + 6000*sin(2*theta)"\n'
           '[flywheel]\nspeed_min = 240\ninertia = 500\n')
    w1 = math.sqrt((240 * RPM) ** 2 + 2 * 6000 / 500)
    # ΔE is drawn within ~2e-6 of 6000 J; ω1 takes 2ΔE/(I·ω1²) ≈ 0.04 of that
    assert q["speed_max"].value["value"] == pytest.approx(w1, rel=1e-7)
    assert q["speed_max"].passed and q["speed_fluctuation"].passed


@given(energy=st.floats(100, 1e5), power=st.floats(100, 1e5), share=st.floats(0.05, 0.95),
       rpm=st.floats(50, 1000), inertia=st.floats(1, 1e4))
def test_the_found_speed_holds_the_energy_balance(energy, power, share, rpm, inertia):
    """Whatever the data, ½I(ω1² − ω2²) is the energy the motor does not give while it
    punches, E − P·t, and the holes a minute 60·P/E."""
    time = share * energy / power
    w1 = rpm * RPM
    text = (f'[units]\nspeed = "rpm"\n[punch]\nenergy = {energy!r}\npower = {power!r}\n'
            f'punching_time = {time!r}\n[flywheel]\nspeed_max = {rpm!r}\n'
            f'inertia = {inertia!r}\n')
    delta_e = energy - power * time
    if inertia * w1 ** 2 / 2 <= delta_e * (1 + 1e-9):
        with pytest.raises(InputError, match="it would stop"):
            _q(text)
        return
    q = _q(text)
    w2 = q["speed_min"].value["value"]
    # ω2 is found from the difference ω1² − 2ΔE/I: its rounding grows as ω1²/ω2²
    assert inertia * (w1 ** 2 - w2 ** 2) / 2 == pytest.approx(
        delta_e, rel=1e-12 * (1 + w1 ** 2 / max(w2 ** 2, 1e-300)) * 10, abs=1e-9 * energy)
    assert q["holes_per_minute"].value["value"] == pytest.approx(60 * power / energy,
                                                                 rel=1e-13)


@pytest.mark.parametrize("old, new, words", [
    ('power = "3 kW"', 'power = "3 kg"', 'a number in W or "3 kW"'),
    ('power = "3 kW"', 'power = -5', "positive"),
    ('power = "3 kW"', 'power = "3 kW"\nperiod = 4', "not period and power"),
    ("mass = 150\nradius_of_gyration = 0.6", "", "speed_max alone needs the flywheel"),
    ("speed_max = 300", "speed_max = 50", "it would stop"),
    ('power = "3 kW"', 'power = "20 kW"', "a punching takes less than"),
    ('speed = "rpm"', 'speed = "rpm"\npower = "hp"', "[units] takes length, speed"),
    ('speed = "rpm"', 'speed = "rpm"\nforce = "kN"', "not force = 'kN'"),
])
def test_a_bad_riveting_machine_is_refused_in_one_line(old, new, words):
    with pytest.raises(InputError) as e:
        _q(RIVETING.replace(old, new))
    assert words in str(e.value) and "\n" not in str(e.value), str(e.value)
