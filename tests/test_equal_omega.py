"""A centre at infinity in a transfer (issue: "I24 is at infinity (links 2 and 4 turn
together)"): on the parallelogram four-bar links 2 and 4 turn with one ω, so the radius
rotation and parallel-line constructions cross from link 2 to link 4 by the equal-ω rule,
a gauge line of link 4 parallel to link 2's. The numbers are the parallelogram's own:
ω4 = ω2, ω3 = 0 (the coupler translates), V_B = V_A = ω2·O2A."""

from __future__ import annotations

import math

import pytest

from tarsim.exercises.catalog import load
from tarsim.exercises.linkages.solution_files import solve_worked


@pytest.fixture(scope="module")
def parallelogram():
    return solve_worked(load("parallelogram-four-bar"))


def test_the_parallelogram_moves_as_a_parallelogram(parallelogram):
    (sol,) = parallelogram.positions
    q = sol.quantities
    assert q["omega4"].value["value"] == pytest.approx(10.0, rel=1e-14)
    assert abs(q["omega3"].value["value"]) <= 1e-14 * 10.0
    for qq in (q["V_B"], *q["V_B"].alternatives.values()):
        # V_B = V_A = 10 rad/s × 100 mm = 1 m/s, at 60° + 90° = 150°
        assert qq.value["value"] == pytest.approx(1.0, rel=1e-14)
        assert math.degrees(math.atan2(qq.value["vector"][1], qq.value["vector"][0])) == \
            pytest.approx(150.0, abs=1e-12)
        assert qq.passed
    assert set(q["V_B"].alternatives) | {q["V_B"].method} == \
        {"radius-rotation", "parallel-line", "components"}


def test_the_transfer_is_said_as_the_equal_omega_rule(parallelogram):
    steps = parallelogram.steps()
    assert "I24 is at infinity: links 2 and 4 turn together, with one ω." in steps
    assert "Through I14 draw the gauge line of link 4 parallel to that of link 2" in steps
