"""The closed forms random linkages are held to agree with the course's own examples, and
catch an answer changed by as little as one and a half hundred-thousandths of its scale."""

from __future__ import annotations

from dataclasses import replace

import pytest

import tarsim
from tests.closed_forms import contradictions


@pytest.mark.parametrize("exercise_id", ["four-bar", "offset-slider-crank", "hinkle-four-bar",
                                         "grashof-crank-rocker"])
def test_the_loop_equations_agree_with_a_bundled_linkage(solved, exercise_id):
    assert contradictions(solved(exercise_id)) == []


@pytest.mark.parametrize("exercise_id, name", [("four-bar", "omega3"), ("four-bar", "V_B"),
                                               ("offset-slider-crank", "V_B")])
def test_an_answer_a_little_off_is_caught(exercise_id, name):
    solution = tarsim.solve(tarsim.load(exercise_id))
    sol = solution.positions[0]
    q = sol.quantities[name]
    # Off by 1.5e-5 of its scale (ω2, or the crank pin's speed ω2·O2A, or itself where it
    # is larger), beyond the checks' ceiling of 1e-5.
    d = sol.work.mechanism.drive
    scale = abs(d.omega) * (sol.work.mechanism.input_radius if name[0] == "V" else 1.0)
    off = 1.5e-5 * max(scale, q.value["value"] if name[0] == "V" else abs(q.value["value"]))
    value = ({**q.value, "vector": [q.value["vector"][0] + off, q.value["vector"][1]]}
             if "vector" in q.value else {**q.value, "value": q.value["value"] + off})
    sol.quantities[name] = replace(q, value=value, alternatives={})
    said = contradictions(solution)
    assert len(said) == 1 and f"{name} by {q.method}" in said[0]


def test_a_rate_far_above_its_scale_is_held_beside_itself():
    """A slider-crank 1e-9 from its toggle: α3 is 2e4 times ω2², and the acceleration polygon
    gives it to 1e-7 of itself (2054965.83 where 60-digit loop equations give
    2054966.02), six figures right; beside ω2² alone that is 2e-3, no contradiction."""
    from pathlib import Path

    path = Path(__file__).parent / "data" / "edge" / "slider-crank-a-billionth-from-toggle.toml"
    solution = tarsim.solve(tarsim.load(path))
    q = solution.positions[0].quantities["alpha3"]
    assert q.passed and abs(q.value["value"] - 2054966.0247629543) < 1e-6 * 2054966.0
    assert contradictions(solution) == []
