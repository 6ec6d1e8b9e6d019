"""`tarsim bench`'s chapter rows: the closed forms each row rests on, and tarsim held to them.

Each study in benchmarks/bench/*_rows.py measures tarsim against a closed form; here each
closed form is checked on its own (a number known by hand, or a law it must obey), then
tarsim's number against it at the tolerance the row states. Timings are never asserted.
"""

from __future__ import annotations

import math
import sys
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

mpmath = pytest.importorskip("mpmath")

import tarsim  # noqa: E402
from benchmarks.bench import (balance_rows, cam_rows, flywheel_rows, force_rows,  # noqa: E402
                              gear_rows)
from tarsim.constructions.balancing.polygons import draw_balance, rounding  # noqa: E402
from tarsim.constructions.gears.tabular import tabulate  # noqa: E402
from tarsim.constructions.reference.flywheel import fluctuation  # noqa: E402
from tarsim.constructions.reference.willis import willis_speeds  # noqa: E402
from tarsim.exercises.cams.cam_solution import solve_cam  # noqa: E402

U = sys.float_info.epsilon / 2                      # the unit roundoff


# ----- gear trains ----------------------------------------------------------------------------
def test_the_reverted_train_of_teeth_31_30_29_32_turns_its_sun_61_960ths_of_the_arm():
    # By hand: 1 − (31·29)/(30·32) = 1 − 899/960 = 61/960, the closed form's (2n + 1)/(n² + 2n)
    # at n = 30; the arm at 100 rpm turns the output sun 6100/960 rpm, exactly.
    assert gear_rows.exact_value(30) == Fraction(61, 960)
    train = gear_rows.reverted_train(30)
    assert tabulate(train).speeds[5] == Fraction(6100, 960)
    assert willis_speeds(train)[5] == Fraction(6100, 960)


@settings(max_examples=40, deadline=None)
@given(st.integers(min_value=3, max_value=10 ** 7))
def test_nearly_cancelling_trains_are_exact_in_fractions_and_floats_keep_the_bound(n):
    train = gear_rows.reverted_train(n)
    exact = gear_rows.exact_value(n) * gear_rows.SPEED
    assert tabulate(train).speeds[5] == exact
    # The float formula rounds four times, the difference amplifying the first three by
    # κ = e/(1 − e): (3κ + 1)u, the row's (3κ + 3)u with two units to spare.
    e = Fraction(n * n - 1, n * n + 2 * n)
    kappa = float(e / (1 - e))
    got = gear_rows.float_formula(train)
    assert abs(Fraction(got) - exact) / exact <= (3 * kappa + 3) * U


# ----- cams -----------------------------------------------------------------------------------
@pytest.mark.parametrize("rb_mm", [40.0, 0.004])
def test_a_knife_edge_on_uniform_velocity_is_steepest_at_atan_h_over_beta_rb(rb_mm):
    # y′ = h/β on the rise and y = 0 at its start: tan φ = y′/(Rb + y) is greatest there.
    # φ is a float near π/2, so it is held to 16 ulps of itself over its complement.
    ex = cam_rows.steep_cam(rb_mm)
    want = math.atan(0.040 / (math.pi / 2 * rb_mm / 1000))
    got = abs(solve_cam(ex).profile.survey.steepest.pressure_angle)
    assert abs(got - want) <= 16 * U * want + 4 * U
    if rb_mm == 40.0:                               # atan(40/(40·π/2)) = atan(2/π)
        assert math.degrees(got) == pytest.approx(32.481637, abs=1e-6)


@pytest.mark.parametrize("delta_mm", [10.0, 1e-4])
def test_a_flat_face_on_harmonic_motion_has_its_least_radius_rb_minus_h(delta_mm):
    # ρ = Rb + y + y″, and at the top of a 90° harmonic rise y = h, y″ = −h·π²/(2β²) = −2h:
    # ρ = Rb − h = δ. The sum's roundings are a few u of its largest term, Rb + h + 2h.
    ex = cam_rows.flat_cam(delta_mm)
    got = solve_cam(ex).profile.survey.sharpest.rho
    scale = ex.base_radius + 0.060
    assert abs(got - delta_mm / 1000) <= 16 * U * scale


# ----- force polygons -------------------------------------------------------------------------
def test_the_engine_at_90_degrees_needs_minus_f_times_r_and_the_polygon_gives_it(tmp_path):
    # At θ = 90° the crank pin is straight above O, and the rod's push along AP, with the
    # piston's 5 kN, has a moment −5000·0.06 = −300 N·m about O whatever the rod's length.
    ex = tarsim.load(force_rows.engine_file(tmp_path, 90.0))
    truth = force_rows.engine_truth(ex)
    # (the crank is the float 0.06 m, and θ the float nearest π/2: 1e-16 of a radian off,
    # which moves the moment by 1e-16 of itself.)
    assert abs(truth["T2"] + 5000 * mpmath.mpf(0.06)) < 1e-12
    got = tarsim.solve(ex).results["positions"][0]["quantities"]["T2"]
    assert got["value"] == pytest.approx(-300.0, rel=16 * U / got["conditioning"])


def test_the_coupler_closed_form_balances_the_coupler_and_the_polygon_meets_it(tmp_path):
    # The closed form's forces on the coupler (P, F_23, F_43 = −P − F_23 along the rocker)
    # must sum to zero and F_43 must lie along O4B; tarsim's polygons then meet it within
    # 16u over their conditioning, with P turned to 1e-9° from the rocker's line.
    ex = tarsim.load(force_rows.coupler_load_file(tmp_path, 1e-9))
    truth = force_rows.coupler_truth(ex)
    p = ex.loads.forces[0].force
    f43 = (-p[0] - truth["F_23"][0], -p[1] - truth["F_23"][1])
    from tarsim.constructions.reference import solver
    places = solver.solve_positions(ex.mechanism)
    u = (places["B"][0] - places["O4"][0], places["B"][1] - places["O4"][1])
    assert abs(f43[0] * u[1] - f43[1] * u[0]) <= 1e-12 * 500 * math.hypot(*u)
    q = tarsim.solve(ex).results["positions"][0]["quantities"]
    for name in ("F_23", "T2"):
        tol = 16 * U / q[name]["conditioning"]
        if name == "T2":
            assert q[name]["value"] == pytest.approx(float(truth[name]), rel=tol)
        else:
            got = q[name]["vector"]
            assert math.dist(got, [float(v) for v in truth[name]]) <= tol * float(
                mpmath.hypot(*truth[name]))


# ----- balancing ------------------------------------------------------------------------------
def test_a_third_mass_delta_heavier_is_balanced_by_delta_times_its_product_opposite():
    # Three equal products at 120° cancel; the third (1 + δ) times as heavy leaves δ·0.1
    # kg·m at 240°, so the balance is 0.1·δ at 60°.
    delta = 1e-3
    rotor = balance_rows.static_rotor(delta)
    want = balance_rows.exact_products(rotor)["A"]
    assert float(mpmath.hypot(*want)) == pytest.approx(0.1 * delta, rel=1e-12)
    assert math.degrees(float(mpmath.atan2(want[1], want[0]))) == pytest.approx(60.0, abs=1e-9)
    drawn = draw_balance(rotor).product("A")
    bound = rounding([m.mass * m.radius for m in rotor.masses])
    assert math.dist(drawn, [float(v) for v in want]) <= bound


def test_a_closing_side_below_rounding_is_no_mass_and_the_two_plane_product_is_known():
    # δ = 1e-16: the third mass's extra 1e-17 kg·m is below the polygon's rounding, so the
    # plane needs no mass. Two planes: the couples about A are (−0.01δ, −0.03δ) kg·m², so B
    # at 0.5 m takes (0.02δ, 0.06δ) kg·m.
    assert "A" in draw_balance(balance_rows.static_rotor(1e-16)).none
    delta = 1e-3
    rotor = balance_rows.dynamic_rotor(delta)
    bx, by = balance_rows.exact_products(rotor)["B"]
    assert float(bx) == pytest.approx(0.02 * delta, rel=1e-9)
    assert float(by) == pytest.approx(0.06 * delta, rel=1e-9)
    drawn = draw_balance(rotor).product("B")
    assert drawn[0] == pytest.approx(0.02 * delta, rel=1e-9)
    assert drawn[1] == pytest.approx(0.06 * delta, rel=1e-9)


# ----- the flywheel ---------------------------------------------------------------------------
def test_two_harmonics_fluctuate_by_756_25_joules():
    # E = −300 cos θ − 200 cos 2θ; its extremes at θ = 0 (−500), π (100) and cos θ = −3/8
    # (300²/1600 + 200 = 256.25): ΔE = 756.25 J.
    assert abs(flywheel_rows.exact_delta_e(flywheel_rows.TWO) - mpmath.mpf("756.25")) < 1e-30


@pytest.mark.parametrize("n", [72, 360, 3600])
def test_the_diagram_read_at_n_steps_is_within_the_interpolants_bound(n):
    spec = flywheel_rows.TWO
    angles = [2 * math.pi * i / n for i in range(n)]
    got = fluctuation(angles, [flywheel_rows.torque(spec, t) for t in angles]).delta_e
    h = 2 * math.pi / n
    # |T − T_lin| ≤ h²·max|T″|/8 over the turn, at both ends of ΔE; max|T″| ≤ 300 + 4·400.
    bound = math.pi * h * h * 1900 / 2 + 4 * n * U * 2 * math.pi * 700
    assert abs(got - 756.25) <= bound
    # and the error is the step's square's: not already at rounding, so the bound is a check
    assert abs(got - 756.25) > bound / 100
