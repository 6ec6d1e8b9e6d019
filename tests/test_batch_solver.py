"""Tests for constructions.reference.turn (the analytic solver over a whole turn at once).

The property: at every input angle, ``solve_turn`` gives the scalar ``solver.solve``'s
numbers to 1e-12 of each quantity's scale, and the same verdict (assembles, cannot
reach, dead point), with the scalar solver's own message.

Why 1e-12: both solvers start from the same closed forms and are polished by Newton
to round-off (a scaled residual of 4 eps), so positions agree to a few eps of the
mechanism's size. Velocities and accelerations solve the same Jacobian (equal but for
an ulp here and there), once by LAPACK's solve and once through its inverse (the pins'
translations eliminated first, tests/test_pin_elimination.py): they
differ by about eps κ (velocities) and eps κ² (accelerations, which use velocities)
of their scale, κ = 1/rcond. The batch keeps only positions with rcond ≥ TRUSTED =
0.02 and hands the rest to the scalar solver itself, so eps × 2500 × a few ≲ 1e-12.
Measured: the worst over the bundled exercises is 2e-14, over random ones 7e-13.
"""

import math
import random
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import HealthCheck, given, note, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import AssemblyError, InputError, TarsimError
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.assembly_plan import record_plan
from tarsim.constructions.reference.batch_loops import BatchLoops, wrap
from tarsim.constructions.reference.loop_equations import _System
from tarsim.constructions.reference.turn import TurnSolver, _newton, solve_turn
from tarsim.exercises.catalog import bundled, resolve
from tarsim.exercises.linkages.exercise_file import load_exercise, parse_exercise
from tests.common import four_bar, four_bar_toml, inverted_slider_crank, offset_slider_crank
from tests.random_mechanisms import FAMILIES, generate

TOL = 1e-12

ROLLING_WHEEL = """\
name = "rolling wheel"
[units]
length = "mm"
[frame]
O2 = [0, 60]
G = [0, 0]
[[link]]
number = 2
points = ["O2", "A"]
lengths = { O2A = 40 }
[[link]]
number = 3
points = ["A", "B"]
lengths = { AB = 150 }
[[link]]
number = 4
points = ["B", "M"]
lengths = { BM = 30 }
[[contact]]
circle = { link = 4, centre = "B", radius = 30 }
face = { link = 1, through = "G", angle = 0 }
side = "left"
rolling = true
[input]
link = 2
angle = 70
omega = 3
alpha = 1
[assembly]
B = "forward"
[ask]
find = ["dof"]
"""
"""The random generator's rolling-wheel template (tests/random_mechanisms.py): a crank
and rod pushing a wheel that rolls without slip on the frame."""


def _mechanism(name):
    return load_exercise(resolve(name), name).mechanism


def _scales(mech):
    """The size of each kind of quantity in this mechanism (SI)."""
    size = max(abs(c) for k in mech.links for _, xy in k.points for c in xy)
    return {"length": size, "velocity": mech.input_speed, "omega": abs(mech.drive.omega),
            "acceleration": mech.input_acceleration,
            "alpha": math.hypot(mech.drive.omega ** 2, mech.drive.alpha)}


def assert_like_scalar(mech, angles) -> float:
    """Solve ``mech`` at ``angles`` both ways; return the worst difference over its scale."""
    turn = solve_turn(mech, angles)
    scale = _scales(mech)
    worst, rcond = 0.0, None

    def close(kind, got, want, wrapped=False):
        nonlocal worst
        diff = np.abs(np.asarray(got) - np.asarray(want))
        if wrapped:
            diff = np.abs(wrap(diff))
        err = float(np.max(diff)) / max(scale[kind], float(np.max(np.abs(want))), 1e-300)
        worst = max(worst, err)
        assert err <= TOL, (kind, got, want, err, rcond)

    for i, angle in enumerate(np.asarray(angles, dtype=float).tolist()):
        m = mech.with_drive(replace(mech.drive, angle=angle))
        try:
            kin = solver.solve(m)
        except AssemblyError as e:
            assert not turn.ok[i], f"the scalar solver refuses {math.degrees(angle)}°: {e}"
            assert turn.dead[i] == isinstance(e, solver.SingularPosition)
            assert str(turn.refusal(i)) == str(e)
            assert not np.isfinite(turn.points[mech.point_names[0]][i]).any()
            continue
        assert turn.ok[i] and not turn.dead[i], f"{math.degrees(angle)}°: {turn.refusal(i)}"
        rcond = kin.conditioning
        for name in mech.point_names:
            close("length", turn.points[name][i], kin.points[name])
            close("velocity", turn.velocities[name][i], kin.velocities[name])
            close("acceleration", turn.accelerations[name][i], kin.accelerations[name])
        for k in kin.angles:
            close("omega", turn.angles[k][i], kin.angles[k], wrapped=True)
            close("omega", turn.omegas[k][i], kin.omegas[k])
            close("alpha", turn.alphas[k][i], kin.alphas[k])
            close("length", turn.origins[k][i], kin.origins[k])
        for j, rate in enumerate(kin.slide_rates):
            close("length", turn.slide_positions[j][i], rate.position)
            close("velocity", turn.slide_velocities[j][i], rate.velocity)
            close("acceleration", turn.slide_accelerations[j][i], rate.acceleration)
        if not turn.by_scalar[i]:     # a bound of the rcond, within a factor of the columns
            r, n = turn.conditioning[i], 3 * (len(mech.links) - 1)
            assert r <= kin.conditioning * (1 + 1e-9) and kin.conditioning <= n * r * (1 + 1e-9)
    return worst


def _turn(mech, steps):
    return mech.drive.angle + np.arange(steps) * math.tau / steps


@pytest.mark.parametrize("name", bundled())
def test_every_bundled_exercise_matches_the_scalar_solver(name):
    assert_like_scalar(_mechanism(name), _turn(_mechanism(name), 48))


@pytest.mark.slow
@pytest.mark.parametrize("name", bundled())
def test_every_bundled_exercise_matches_the_scalar_solver_over_120_steps(name):
    worst = assert_like_scalar(_mechanism(name), _turn(_mechanism(name), 120))
    print(f"{name}: worst {worst:.1e}")


def test_a_non_grashof_crank_is_refused_where_the_scalar_solver_refuses_it():
    # ground 300, crank 100, coupler 150, rocker 200 mm: s + l = 400 > p + q = 350, so
    # the crank stops where coupler and rocker fall in line (AO4 = 350 mm): a dead point.
    mech = four_bar(0.0, coupler=0.15, omega2=5.0, alpha2=1.0)
    limit = math.acos((0.1 ** 2 + 0.3 ** 2 - 0.35 ** 2) / (2 * 0.1 * 0.3))
    angles = np.concatenate([_turn(mech, 360), [limit, -limit],
                             limit + np.array([-1e-6, -1e-9, -1e-12, 1e-12, 1e-9, 1e-6])])
    assert_like_scalar(mech, angles)
    turn = solve_turn(mech, angles)
    assert 0 < turn.ok.sum() < len(angles) - 100
    assert "cannot reach" in str(turn.refusal(int(np.flatnonzero(~turn.ok)[0])))


def test_a_dead_point_is_marked_dead_with_the_scalar_message():
    # the parallelogram's change point: crank along the ground, the coupler on it
    mech = four_bar(0.0, crank=0.1, coupler=0.3, rocker=0.1, omega2=1.0)
    turn = solve_turn(mech, [0.0, 0.5, math.pi])
    assert turn.dead.tolist() == [True, False, True] and turn.ok.tolist() == [False, True, False]
    assert str(turn.refusal(0)).startswith("dead point at input angle 0°")
    assert_like_scalar(mech, [0.0, 0.5, math.pi, 1e-9, math.pi - 1e-9])


def test_a_slider_crank_and_a_slotted_lever_match():
    assert_like_scalar(offset_slider_crank(0.0, omega2=-3.0, alpha2=2.0), np.linspace(0, 7, 97))
    assert_like_scalar(inverted_slider_crank(0.0, omega2=2.0, alpha2=-1.0, offset=0.03),
                       np.linspace(-1, 6, 97))


def test_a_rolling_wheel_matches():
    mech = parse_exercise(ROLLING_WHEEL, "wheel.toml", "wheel").mechanism
    assert any(s.rolling for s in mech.slides)
    assert_like_scalar(mech, _turn(mech, 97))


def test_a_near_point_branch_picks_at_each_angle_as_the_scalar_solver_does():
    near = replace(four_bar(0.0, omega2=1.0), branches={"B": (0.3, 0.1)})
    assert_like_scalar(near, _turn(near, 97))
    followed = solver.follow_branches(replace(near, drive=replace(near.drive, angle=1.0)))
    assert followed.branches == {"B": "left"}
    assert_like_scalar(followed, _turn(followed, 97))


def test_a_mechanism_that_never_assembles_is_refused_everywhere():
    text = four_bar_toml(coupler=10, rocker=50, angle=0)
    mech = parse_exercise(text, "m.toml", "m").mechanism
    turn = solve_turn(mech, _turn(mech, 8))
    assert not turn.ok.any() and not turn.dead.any()
    assert_like_scalar(mech, _turn(mech, 8))


def test_the_point_velocity_on_a_link_is_the_scalar_one():
    mech = _mechanism("hinkle-slider-crank")
    angles = _turn(mech, 12)
    turn = solve_turn(mech, angles)
    for i, angle in enumerate(angles.tolist()):
        m = mech.with_drive(replace(mech.drive, angle=angle))
        kin = solver.solve(m)
        for name in m.point_names:
            for link in m.links_at(name):
                want = solver.point_acceleration(kin, m, link, name)
                got = turn.acceleration_on(link, name)[i]
                assert got == pytest.approx(want, rel=TOL, abs=TOL * m.input_acceleration)
                want = solver.point_velocity(kin, m, link, name)
                got = turn.velocity_on(link, name)[i]
                assert got == pytest.approx(want, rel=TOL, abs=TOL * m.input_speed)


def test_the_polish_brings_a_perturbed_start_back_to_the_closed_form():
    # The bundled starts are at round-off already (no row needs Newton); shake them.
    mech = _mechanism("slotted-lever-p37")
    angles = _turn(mech, 36)
    start = record_plan(mech, angles).place(angles).q
    loops = BatchLoops(_System(mech))
    shaken = start + 1e-10 * loops.sy.lc * np.random.default_rng(3).standard_normal(start.shape)
    polished, vouched = _newton(loops, shaken, angles)
    assert vouched.all()
    assert np.max(np.abs(polished - start)) <= 1e-14 * loops.sy.lc   # a few eps of the size


def _same(a, b) -> bool:
    """Two turns' every array equal, bit for bit (NaN where either is refused)."""
    fields = ("inputs", "ok", "dead", "residual", "conditioning", "by_scalar")
    dicts = ("points", "angles", "omegas", "alphas", "velocities", "accelerations", "origins",
             "origin_velocities", "origin_accelerations")
    tuples = ("slide_positions", "slide_velocities", "slide_accelerations")
    return (all(np.array_equal(getattr(a, f), getattr(b, f), equal_nan=True) for f in fields)
            and all(getattr(a, f).keys() == getattr(b, f).keys()
                    and all(np.array_equal(getattr(a, f)[k], getattr(b, f)[k], equal_nan=True)
                            for k in getattr(a, f)) for f in dicts)
            and all(np.array_equal(x, y, equal_nan=True)
                    for f in tuples for x, y in zip(getattr(a, f), getattr(b, f))))


@pytest.mark.parametrize("name", ["crank-shaper", "six-link-homework-1", "wheel-round-circle"])
def test_a_solver_made_once_solves_each_batch_as_solve_turn_does(name):
    # what it keeps between calls (the equations, the pins' tree, the assembly's acts)
    # is the same at every angle: a bisection's rounds give what fresh solves give
    mech = _mechanism(name)
    once = TurnSolver(mech)
    for angles in (_turn(mech, 36), np.linspace(0.1, 0.2, 31), [2.0], _turn(mech, 7)):
        assert _same(once.solve(angles), solve_turn(mech, angles))


def test_a_solver_whose_stated_angle_does_not_assemble_records_its_acts_where_one_does():
    # ground 300, crank 100, coupler 150, rocker 200 mm: the crank stops short of 180°
    mech = four_bar(math.pi, coupler=0.15, omega2=5.0)
    once = TurnSolver(mech)
    assert not once.solve([math.pi]).ok.any()
    for angles in ([0.0, 0.5], _turn(mech, 36)):
        turn = once.solve(angles)
        assert turn.ok.any() and _same(turn, solve_turn(mech, angles))


def test_wrap_is_math_remainder():
    x = np.random.default_rng(7).uniform(-1e3, 1e3, 10_000)
    assert wrap(x).tolist() == [math.remainder(v, math.tau) for v in x.tolist()]


@pytest.mark.slow
@pytest.mark.parametrize("family", FAMILIES)
@settings(max_examples=15, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 2**32 - 1))
def test_a_random_mechanism_matches_the_scalar_solver(family, seed):
    _, text = generate(random.Random(seed), family)
    note(text)
    try:
        mech = parse_exercise(text, "random.toml", "random").mechanism
        solver.follow_branches(mech)
    except TarsimError:
        return                          # refused on reading: nothing to solve
    angles = _turn(mech, 36)
    try:
        assert_like_scalar(mech, angles)
    except InputError as e:             # a missing branch: the scalar solver says so too
        assert str(e) in _input_errors(mech, angles)


def _input_errors(mech, angles) -> list[str]:
    said = []
    for angle in angles.tolist():
        try:
            solver.solve(mech.with_drive(replace(mech.drive, angle=angle)))
        except InputError as e:
            said.append(str(e))
        except AssemblyError:
            pass
    return said
