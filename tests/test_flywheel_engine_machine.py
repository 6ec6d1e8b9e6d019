"""An engine's turning moment beside a machine's resisting torque, both varying over the
cycle: the net T − R drives the flywheel, each answer against the hand-integrated energy."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tarsim.constructions.errors import InputError
from tarsim.constructions.forces.flywheel import STEPS
from tarsim.exercises.forces.flywheel_file import parse_flywheel
from tarsim.exercises.forces.flywheel_solution import solve_flywheel

FILE = '''
[units]
speed = "rpm"
[turning_moment]
torque = "5000 + 1500*sin(3*theta)"
[resisting_torque]
torque = "{machine}"
[flywheel]
speed = 250
speed_fluctuation = "±1 %"
'''

DRAWN = (2 * math.pi / STEPS) ** 2 / 12 * 2 * (4500 + 600) / 1600
"""The drawing's error in ΔE relative to it: between two intercepts the trapezoid rule
misses h²/12·(T′(b) − T′(a)), |T′| at most 3·1500 + 600, over a ΔE of some 1600 J."""


def _energy(theta):
    """E(θ) = ∫ (1500 sin 3θ − 600 sin θ) dθ, by hand, up to its constant."""
    return -500 * np.cos(3 * theta) + 600 * np.cos(theta)


def test_flywheel_engine_and_machine_torques():
    """T = 5000 + 1500 sin 3θ, R = 5000 + 600 sin θ: ΔE is E's range over a turn, found by a
    fine scan and at E′'s roots (sin θ = 0, or sin²θ = (3·1500 − 600)/(4·1500))."""
    q = solve_flywheel(parse_flywheel(FILE.format(machine="5000 + 600*sin(theta)"))).checked
    scan = np.linspace(0, 2 * math.pi, 720001)
    s = math.sqrt((3 * 1500 - 600) / (4 * 1500))
    roots = np.array([0, math.pi, math.asin(s), math.pi - math.asin(s),
                      math.pi + math.asin(s), 2 * math.pi - math.asin(s)])
    energies = _energy(roots)
    delta_e = energies.max() - energies.min()
    # the scan's step is 1e-5 rad: at a smooth extreme it misses E by ~E″·h²/2, below 1e-6 J
    assert _energy(scan).max() - _energy(scan).min() == pytest.approx(delta_e, abs=1e-6)
    assert delta_e == pytest.approx(2800 * math.sqrt(0.35), rel=1e-12)
    omega = 250 * 2 * math.pi / 60
    assert q["delta_E"].value["value"] == pytest.approx(delta_e, rel=DRAWN)
    assert q["mean_torque"].value["value"] == pytest.approx(5000, rel=1e-12)
    assert q["inertia"].value["value"] == pytest.approx(delta_e / (0.02 * omega ** 2),
                                                        rel=DRAWN)
    # the speed is greatest where E is: at θ with cos θ = +√0.35, either side of 0
    fastest = [math.degrees(r) for r in roots if _energy(r) > energies.max() - 1e-9]
    slowest = [math.degrees(r) for r in roots if _energy(r) < energies.min() + 1e-9]
    # the intercept is where the drawing's straight line between two steps h = 0.1° apart
    # crosses: off the curve's by some h²/8·|T″|/|T′|, 2e-5° here (|T″| < 4000, |T′| > 4500)
    assert min(abs(q["speed_max_at"].value["value"] - a) for a in fastest) < 1e-4
    assert min(abs(q["speed_min_at"].value["value"] - a) for a in slowest) < 1e-4
    assert all(c.passed is not False for c in q.values())


def test_an_engine_and_a_machine_of_different_means_are_refused_in_one_line():
    with pytest.raises(InputError) as e:
        parse_flywheel(FILE.format(machine="4900 + 600*sin(theta)"), "bad.toml")
    assert "mean torque 5000 N·m differs from the machine's 4900 N·m" in str(e.value)
    assert "must balance" in str(e.value) and "bad.toml:" in str(e.value)
    assert "\n" not in str(e.value)
