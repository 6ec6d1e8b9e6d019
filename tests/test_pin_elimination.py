"""Tests for constructions.reference.pin_elimination (Φ_q⁻¹ of a batch through the pins' tree).

The property: at every position a turn's solver keeps (rcond ≥ TRUSTED = 0.02 of the
length-scaled Jacobian), the inverse taken through the pins' tree is LAPACK's inverse of
the whole Φ_q. Both are backward stable, so they differ by about n eps κ of the
inverse's size, κ ≤ 1/TRUSTED = 50 and n ≤ 15 coordinates: 2e-13. Measured: at most
3e-15 over the bundled exercises (240 steps each).
"""

import math
import random

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import TarsimError
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.batch_loops import BatchLoops
from tarsim.constructions.reference.loop_equations import _System
from tarsim.constructions.reference.pin_elimination import PinElimination, _small_inverse
from tarsim.constructions.reference.turn import solve_turn
from tarsim.exercises.catalog import bundled, resolve
from tarsim.exercises.linkages.exercise_file import load_exercise, parse_exercise
from tests.random_mechanisms import FAMILIES, generate

TOL = 2e-13


def _kept(mech, steps=48):
    """The body coordinates (N, n) of the positions of a turn the batch solver kept."""
    angles = mech.drive.angle + np.arange(steps) * math.tau / steps
    turn = solve_turn(mech, angles)
    sy = _System(mech)
    keep = turn.ok & ~turn.by_scalar
    q = np.zeros((int(keep.sum()), 3 * len(sy.moving)))
    for k in sy.moving:
        c = sy.col[k]
        q[:, c:c + 2], q[:, c + 2] = turn.origins[k][keep], turn.angles[k][keep]
    return sy, q


def assert_like_lapack(sy: _System, q: np.ndarray) -> None:
    """The tree's inverse of Φ_q at each of the positions ``q`` against LAPACK's."""
    if not len(q):
        return
    loops = BatchLoops(sy)
    tree = PinElimination(loops)
    entries = loops.entries(q)
    inv = tree.invert(entries, np.ones(len(q), dtype=bool))
    assert inv.ok.all()
    jac = loops.jacobian(q)
    want = np.linalg.inv(jac)
    size = np.max(np.abs(want), axis=(1, 2))
    rhs = np.random.default_rng(5).uniform(-1.0, 1.0, q.shape)
    got = inv.solve(rhs)
    # each of the n terms of a row off by TOL of the inverse's size at most
    bound = q.shape[1] * TOL
    assert np.max(np.abs(got - np.einsum("nij,nj->ni", want, rhs)) / size[:, None]) <= bound
    drive = len(sy.is_len) - 1                  # the input's row is the last
    assert np.max(np.abs(inv.column(drive) - want[:, :, drive]) / size[:, None]) <= TOL
    scaled = want / loops.cols[None, :, None] / loops.rows[None, None, :]
    frobenius = np.sum(scaled * scaled, axis=(1, 2))
    assert inv.norm2(loops.rows, loops.cols) == pytest.approx(frobenius, rel=TOL)


@pytest.mark.parametrize("name", bundled())
def test_every_bundled_mechanism_inverts_as_lapack_does(name):
    assert_like_lapack(*_kept(load_exercise(resolve(name), name).mechanism))


@pytest.mark.parametrize("name", ["four-bar", "crank-shaper", "wheel-driven-slider",
                                  "velocity-homework-292"])
def test_the_tree_block_is_constant_and_its_inverse_exact(name):
    mech = load_exercise(resolve(name), name).mechanism
    loops = BatchLoops(_System(mech))
    tree = PinElimination(loops)
    n = 3 * len(loops.sy.moving)
    # every coordinate and constraint is in the tree or the rest, once
    assert sorted([*tree.rows, *tree.rest_rows]) == list(range(n))
    assert sorted([*tree.cols, *tree.rest_cols]) == list(range(n))
    q = np.random.default_rng(2).uniform(-1, 1, (3, n))
    blocks = loops.jacobian(q)[:, tree.rows][:, :, tree.cols]
    assert (blocks == blocks[0]).all()          # the pins' ±1, at any position
    assert (blocks[0] @ tree.a_inv == np.eye(len(tree.rows))).all()


def test_a_four_bar_leaves_its_three_angles_to_the_schur_complement():
    # O2, A and O4 reach links 2, 3 and 4 from the frame; B closes the loop
    mech = load_exercise(resolve("four-bar"), "four-bar").mechanism
    tree = PinElimination(BatchLoops(_System(mech)))
    assert len(tree.rest_cols) == 3 and all(c % 3 == 2 for c in tree.rest_cols)


@settings(max_examples=200, deadline=None, derandomize=True)
@given(k=st.integers(1, 5), seed=st.integers(0, 2**32 - 1))
def test_the_small_inverse_is_lapacks(k, seed):
    # well conditioned by a diagonal 3 over unit normal entries: κ ≲ 10, so 1e-14 is slack
    s = np.random.default_rng(seed).standard_normal((k, k, 40)) + 3 * np.eye(k)[:, :, None]
    good = np.ones(40, dtype=bool)
    inv, ok = _small_inverse(s, good)
    assert ok.all()
    want = np.linalg.inv(s.transpose(2, 0, 1)).transpose(1, 2, 0)
    assert np.max(np.abs(inv - want)) <= 1e-14 * np.max(np.abs(want)) * 10


@pytest.mark.parametrize("k", [1, 2, 3, 4])
def test_a_singular_complement_is_not_inverted(k):
    s = np.random.default_rng(k).standard_normal((k, k, 3))
    s[-1, :, 1] = 0.0                           # position 1 has a zero row
    inv, ok = _small_inverse(s, np.array([True, True, False]))
    assert ok.tolist() == [True, False, False]


@pytest.mark.slow
@pytest.mark.parametrize("family", FAMILIES)
def test_random_mechanisms_invert_as_lapack_does(family):
    cases = random.Random(f"pin elimination {family}")      # the same 20 each run
    for _ in range(20):
        text = generate(cases, family)[1]
        try:
            kept = _kept(solver.follow_branches(parse_exercise(text, "r.toml", "r").mechanism))
        except TarsimError:
            continue                    # refused on reading, or a branch it needs is not given
        assert_like_lapack(*kept)
