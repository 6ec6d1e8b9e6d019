"""Tests for constructions.reference.batch_loops (the loop equations over a batch).

The batch evaluates the scalar ``_System``'s rows with the same formulas, so its Φ_q at
each position is the scalar one but for the order a rotation's two products are summed:
an ulp of the largest entry. We allow 4 eps of it.
"""

import math

import numpy as np
import pytest

from tarsim.constructions.reference.batch_loops import BatchLoops
from tarsim.constructions.reference.loop_equations import _System
from tarsim.exercises.catalog import bundled, resolve
from tarsim.exercises.linkages.exercise_file import load_exercise

EPS = np.finfo(float).eps


def _mechanism(name):
    return load_exercise(resolve(name), name).mechanism


def _positions(sy: _System, count: int = 12) -> np.ndarray:
    """Body coordinates that need not close the loops: Φ_q is defined everywhere."""
    q = np.random.default_rng(count).uniform(-1.0, 1.0, (count, 3 * len(sy.moving)))
    q[:, 0::3] *= sy.lc
    q[:, 1::3] *= sy.lc
    q[:, 2::3] *= math.pi
    return q


@pytest.mark.parametrize("name", bundled())
def test_the_batch_jacobian_is_the_scalar_one(name):
    sy = _System(_mechanism(name))
    q = _positions(sy)
    jac = BatchLoops(sy).jacobian(q)
    for i, row in enumerate(q):
        want = sy.jacobian(row)
        assert np.max(np.abs(jac[i] - want)) <= 4 * EPS * np.max(np.abs(want))


@pytest.mark.parametrize("name", ["four-bar", "crank-shaper", "whitworth"])
def test_the_entries_are_the_jacobian_less_its_zeros_by_form(name):
    loops = BatchLoops(_System(_mechanism(name)))
    q = _positions(loops.sy)
    entries, jac = loops.entries(q), loops.jacobian(q)
    rows, cols = loops.pattern
    assert (jac[:, rows, cols] == entries.T).all()
    off = np.ones(jac.shape[1:], dtype=bool)
    off[rows, cols] = False
    assert (jac[:, off] == 0.0).all()


def test_a_four_bar_jacobian_has_25_entries_of_81():
    # 4 pins: O2 and O4 on the frame give 2 × (1 + 1) entries, A and B 2 × (2 + 2); the
    # input's row 1 (its angle): 4 + 4 + 8 + 8 + 1 = 25.
    loops = BatchLoops(_System(_mechanism("four-bar")))
    assert len(loops.slots) == 25 and loops.jacobian(_positions(loops.sy)).shape[1:] == (9, 9)
