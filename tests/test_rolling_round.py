"""A wheel rolling round a circle without slip: carried by an arm (the notes' gear pair, a
higher pair) or held on the circle by the contact alone. Against the rolling relations
themselves, ω_wheel = ω_arm·(R ± r)/r and the contact point at rest accelerating
ω²·r·R/(R ± r) toward the wheel's centre, then the graphical methods against the solver."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import pytest

from tarsim.constructions.errors import InputError
from tarsim.constructions.model import Drive
from tarsim.constructions.reference import solver
from tarsim.exercises.catalog import bundled
from tarsim.exercises.linkages.mechanism_file import load_mechanism
from tarsim.exercises.linkages.solution_files import solve_worked
from tarsim.exercises.linkages.exercise_file import load_exercise

DATA = Path(__file__).parent / "data"
ANGLES = [math.radians(d) for d in (-170, -90, 0, 30, 135, 179)]


def planet(theta: float, side: str = "outside", big: float = 0.100):
    """The bundled arm and wheel (r = 50 mm), the fixed circle of radius ``big`` touched
    from ``side``; the arm KC = R ± r."""
    m = load_mechanism(bundled()["wheel-round-circle"])
    (a,) = m.rolling_arcs
    r = a.contact.circle.radius
    arm_length = big + r if side == "outside" else big - r
    contact = replace(a.contact, side=side, face=replace(a.contact.face, radius=big))
    arcs = (replace(a, contact=contact, radius=arm_length),)
    links = tuple(replace(k, points=(("K", (0.0, 0.0)), ("C", (arm_length, 0.0))))
                  if k.number == 2 else k for k in m.links)
    return replace(m, links=links, arcs=arcs).with_drive(Drive(2, theta, 2.0, 1.0))


@pytest.mark.parametrize("side, big", [("outside", 0.100), ("inside", 0.200)])
@pytest.mark.parametrize("theta", ANGLES)
def test_the_wheel_turns_as_rolling_round_says(theta, side, big):
    m = planet(theta, side, big)
    kin = solver.solve(m)
    r, sign = 0.050, 1.0 if side == "outside" else -1.0
    gain = (r + sign * big) / r                    # (R + r)/r outside, (r − R)/r inside
    assert kin.omegas[3] == pytest.approx(2.0 * gain, rel=1e-13)
    assert kin.alphas[3] == pytest.approx(1.0 * gain, rel=1e-13)
    # its angle: β·(R ± r)/r from the start, β the arm's angle in [−π, π)
    assert math.remainder(kin.angles[3] - theta * gain, math.tau) == pytest.approx(0, abs=1e-13)
    # the contact point, R from K along KC, is the wheel's point at rest
    cx, cy = kin.points["C"]
    d = math.hypot(cx, cy)
    p = (big * cx / d, big * cy / d)
    assert solver.point_velocity(kin, m, 3, p) == pytest.approx((0.0, 0.0), abs=1e-14)
    w = kin.omegas[3]
    a_p = solver.point_acceleration(kin, m, 3, p)
    toward_c = ((cx - p[0]) / r, (cy - p[1]) / r)
    size = w * w * r * big / abs(r + sign * big)
    assert a_p == pytest.approx((size * toward_c[0], size * toward_c[1]), abs=1e-12)


def test_an_arm_holding_the_wheel_makes_the_contact_a_higher_pair():
    m = planet(0.5)
    assert m.mobility() == (1, 3, 2, 1)              # 3(3 − 1) − 2·2 − 1: the gear pair's count


def test_an_arm_of_the_wrong_length_is_refused_in_one_line():
    m = planet(0.5)
    links = tuple(replace(k, points=(("K", (0.0, 0.0)), ("C", (0.140, 0.0))))
                  if k.number == 2 else k for k in m.links)
    with pytest.raises(InputError, match=r"link 2 holds C and K 140 mm apart, but the circles "
                                         r"of the rolling contact of link 3 on link 1 touch at "
                                         r"150 mm"):
        replace(m, links=links)


def test_a_wheel_held_on_its_ring_by_the_contact_alone():
    m = load_mechanism(DATA / "wheel-in-ring.toml")
    assert m.mobility()[0] == 1                       # a rod, a crank and the wheel: F1 = 4
    kin = solver.solve(m)
    (a,) = m.rolling_arcs
    (cx, cy), (kx, ky) = kin.points["C"], kin.points["K"]
    d = math.hypot(cx - kx, cy - ky)
    assert d == pytest.approx(0.150, rel=1e-14)       # R − r from the ring's centre
    p = (kx + 0.200 * (cx - kx) / d, ky + 0.200 * (cy - ky) / d)
    assert solver.point_velocity(kin, m, 4, p) == pytest.approx((0.0, 0.0), abs=1e-14)
    w = kin.omegas[4]
    size = w * w * 0.050 * 0.200 / 0.150
    a_p = solver.point_acceleration(kin, m, 4, p)
    assert a_p == pytest.approx((size * (cx - p[0]) / 0.050, size * (cy - p[1]) / 0.050),
                                abs=1e-12)


@pytest.mark.parametrize("path", [DATA / "wheel-in-ring.toml",
                                  bundled()["wheel-round-circle"]], ids=["ring", "arm"])
def test_every_method_agrees_with_the_solver(path):
    worked = solve_worked(load_exercise(path))
    assert worked.passed
    names = {n for sol in worked.positions for n in sol.quantities}
    assert {"V_M", "A_M"} <= names
