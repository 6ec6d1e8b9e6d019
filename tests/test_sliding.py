"""The sliding velocity and acceleration along a moving slot (``V_slide_A``, ``A_slide_A``),
read off the polygons that draw them, against the course's own numbers for the
crank-shaper at t = 2.34 s (seed 003 §7, printed to 1e-3 mm/s and mm/s²) and against the
vector-loop solver's slide rates everywhere else."""

from __future__ import annotations

import math

import pytest

from tarsim.constructions import asks as A
from tarsim.constructions.errors import TarsimError
from tarsim.exercises.catalog import load
from tarsim.exercises.linkages.solution import solve_positions
from tarsim.exercises.linkages.solution_files import solve_worked

SLIDING = ("V_slide_A", "A_slide_A", "V_slide_B", "A_slide_B")


@pytest.fixture(scope="module")
def shaper_at_2_34():
    sols = solve_positions(load("crank-shaper").asking(SLIDING))
    return next(s for s in sols if s.position.slug == "t-2.34s")


@pytest.mark.parametrize("name, magnitude", [
    ("V_slide_A", 163.089), ("A_slide_A", 90.805),     # ṙ3 and r̈3 along the lever
    ("V_slide_B", 61.710), ("A_slide_B", 140.353),     # ṙ4 and |r̈4|
])
def test_the_crank_shapers_sliding_is_the_courses(shaper_at_2_34, name, magnitude):
    q = shaper_at_2_34.quantities[name]
    assert q.value["value"] * 1000 == pytest.approx(magnitude, abs=5e-4)
    assert q.passed and q.rel_error <= 1e-14


def test_each_slides_along_the_lever_the_way_the_course_signs_it(shaper_at_2_34):
    q = shaper_at_2_34.quantities
    # The lever O4 → A: r̈3 = +90.805 runs outward along it, r̈4 = −140.353 inward.
    sol = shaper_at_2_34
    (ax, ay), (ox, oy) = sol.kinematics.points["A"], sol.kinematics.points["O4"]
    out = ((ax - ox) / math.hypot(ax - ox, ay - oy), (ay - oy) / math.hypot(ax - ox, ay - oy))
    along = {n: (q[n].value["vector"][0] * out[0] + q[n].value["vector"][1] * out[1]) * 1000
             for n in SLIDING}
    assert along["A_slide_A"] == pytest.approx(90.805, abs=5e-4)
    assert along["A_slide_B"] == pytest.approx(-140.353, abs=5e-4)
    for n in SLIDING:     # along the slot: nothing across it
        assert abs(along[n]) == pytest.approx(q[n].value["value"] * 1000, rel=1e-12)


@pytest.mark.parametrize("name", ["inverted-slider-crank", "whitworth"])
def test_a_slotted_levers_sliding_agrees_with_the_solver(name):
    (sol,) = solve_positions(load(name).asking(("V_slide_A", "A_slide_A")))
    for q in sol.quantities.values():
        assert q.passed and q.rel_error <= q.tolerance


def test_the_sliding_component_is_drawn_on_the_worked_page():
    worked = solve_worked(load("inverted-slider-crank").asking(("A_slide_A",)))
    page = worked.figures["worked"]
    texts = [t.text + t.sub for s in (page.sheets or [page]) for t in s.items
             if hasattr(t, "sub")]
    assert any(t.endswith("Aˢ") or "Aˢ" in t for t in texts)


def test_a_point_in_no_moving_slot_has_no_sliding_velocity():
    assert A.parse_ask("V_slide_B") == A.Sliding("V", "B")
    with pytest.raises(TarsimError, match="point O2 runs in no straight slot of a moving link"
                                          ".*the points that do: A, B"):
        solve_positions(load("crank-shaper").asking(("V_slide_O2",)))
