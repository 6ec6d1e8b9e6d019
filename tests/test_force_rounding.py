"""How far the force polygons' answers round when their inertia loads are read off an
acceleration polygon that keeps none of their digits.

tests/data/shaper-lever-at-its-extreme.toml is a crank-shaper whose crank (9.99 in, about a
pivot 10 in from the lever's) stands square to the slot: the lever is at its extreme, and
α4 is the rounding of a zero (6.1e11 rad/s² beside the 2.2e26 the polygon reads it at,
the crank pin's 2.5e24 m/s² over the 0.0114 m between the lever's pivot and the block). The
polygon reads α4 = 1.68e12 (22 roundings of its extent off); the image of the ram's pin,
250 times as far out along the slot, and the ram's guide crossing the slot at 2.56°
multiply that into a_B, and the ram's polygon and the lever's moments multiply the ram's
inertia force again, by 22 and by 250: F_43 comes out 1.45e18 N where the reference has 5.0e17 N, a
miss of 1.0e-8 of the loads it is made of (9.5e25 N, the crank's inertia couple above
all), which a conditioning of 8.9e-5 (the crossings alone) let fail its check of 1e-9.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from click.testing import CliRunner

import tarsim
from tarsim.constructions import asks as A
from tarsim.constructions.checks import CEILING
from tarsim.constructions.force_polygons import drawn_forces
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.kinetostatics import balance, world_point
from tarsim.exercises.cli import cli
from tests.random_loads import energy_torque, oracle

LEVER = Path(__file__).parent / "data" / "shaper-lever-at-its-extreme.toml"


def _cross(u, v) -> float:
    return u[0] * v[1] - u[1] * v[0]


def _by_virtual_power(work) -> tuple[float, float]:
    """F_43, the slot's push on the block, by the power of the lever and the ram turned
    together by the lever's angle φ, in which no joint force but the block's enters (the
    pivot and the guide do no work, the ram's pin slides square to its push):
    ν·ρ = −(m5·a_B·dB/dφ + m4·G × a_G + I4·α4), with B = s·e_r on the guide through P along
    d, s = (P × d)/(e_r × d), so dB/dφ = s′·e_r + s·e_φ, s′ = −(P × d)(e_φ × d)/(e_r × d)²."""
    kin, mech, loads = work.kinematics, work.reference, work.loads
    a = kin.points["A"]
    rho = math.hypot(*a)
    e_r = (a[0] / rho, a[1] / rho)
    e_phi = (-e_r[1], e_r[0])
    guide = next(s for s in mech.slides if s.link == 5 and s.guide_link == 1)
    p, d = guide.through, guide.direction
    s = _cross(p, d) / _cross(e_r, d)
    ds = -_cross(p, d) * _cross(e_phi, d) / _cross(e_r, d) ** 2
    d_b = (ds * e_r[0] + s * e_phi[0], ds * e_r[1] + s * e_phi[1])
    lever, ram = (next(m for m in loads.masses if m.link == n) for n in (4, 5))
    g = world_point(kin, mech, 4, lever.centre)
    a_g = solver.point_acceleration(kin, mech, 4, g)
    a_b = solver.point_acceleration(kin, mech, 5, kin.points["B"])
    nu = -(ram.mass * (a_b[0] * d_b[0] + a_b[1] * d_b[1]) + lever.mass * _cross(g, a_g)
           + lever.inertia * kin.alphas[4]) / rho
    return (nu * e_phi[0], nu * e_phi[1])


def test_a_lever_at_its_extreme_holds_its_forces_to_the_rounding_of_its_readings():
    runner = CliRunner()
    with runner.isolated_filesystem():
        done = runner.invoke(cli, ["solve", str(LEVER), "-o", "out", "--no-pdf"])
    assert done.exit_code == 0, done.output

    worked = tarsim.solve(tarsim.load(str(LEVER)))
    assert worked.passed
    (sol,) = worked.positions
    work = sol.work
    drawn = drawn_forces(work).joints
    statics = balance(work.reference, work.kinematics, work.loads)
    scale = work.scale_of(A.JointForce(4, 3))
    # The Newton–Euler system and the virtual power of lever and ram share the reference's
    # accelerations and nothing else: they agree to a few roundings of F_43.
    f43 = _by_virtual_power(work)
    assert statics.joint("F_43").force == pytest.approx(f43, rel=1e-12)
    for name, want in (("F_43", f43), ("F_12", (-f43[0], -f43[1]))):
        q = sol.quantities[name]
        miss = math.dist(drawn[name], want) / scale
        # The check now allows what the readings' rounding makes of the force, 64 times
        # its estimate (9.6e17 N, the ram's a_B off by 7e13 m/s² levered through the ram's
        # polygon and the lever), 6.5e-7 of the loads: it covers the miss, within the
        # ceiling and within a thousand times the miss. F_43 (5.5e-9 of the loads) lies
        # below it, so it is said as 0 on both sides rather than as a number no check
        # could fail.
        assert miss <= q.tolerance <= min(CEILING, 1e3 * miss)
        assert math.hypot(*want) < q.tolerance * scale
        assert q.value["value"] == q.reference["value"] == 0.0
    # The block's push runs square to the slot, along the crank through O2, so the driving
    # torque holds the crank's inertia couple alone: T2 = I2·α2, to its rounding; and the
    # balance of energy, which no joint force enters, gives it too.
    t2 = sol.quantities["T2"]
    assert t2.value["value"] == pytest.approx(13.149065760909 * -1e25, rel=1e-15)
    d = work.mechanism.drive
    energy, slack = energy_torque(work.mechanism, work.loads, d.angle, d.omega, d.alpha)
    assert abs(t2.value["value"] - energy) <= slack
    assert oracle(worked, LEVER.read_text(encoding="utf-8")) == []
