"""The equivalent linkage of a direct contact (notes part 2 §2.13), drawn on request: a link
joining the two centres of curvature of circle-on-circle contact, r₁ + r₂ long; a slot
parallel to the face, a radius off it, for a circle on a flat face."""

from __future__ import annotations

from pathlib import Path

import pytest

from tarsim.constructions.errors import TarsimError
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution_files import solve_worked

DATA = Path(__file__).parent / "data"


def solved(name: str, find: str):
    text = (DATA / f"{name}.toml").read_text(encoding="utf-8") + f"\n[ask]\nfind = {find}\n"
    return solve_worked(parse_exercise(text, f"{name}.toml", name))


def test_a_roller_on_a_cam_is_a_link_of_the_two_radii_between_their_centres():
    worked = solved("roller-cam", '["equiv_R"]')
    (sol,) = worked.positions
    q = sol.quantities["equiv_R"]
    assert q.value["value"] == pytest.approx(0.050 + 0.015, rel=1e-14)   # cam 50 + roller 15
    assert q.passed
    steps = worked.steps()
    assert "so at this instant the contact acts as a link RC pinned at both centres" in steps
    assert "equivalent-linkage" in worked.figures


def test_a_circle_on_a_face_is_a_block_in_a_slot_a_radius_off_the_face():
    (sol,) = solved("offset-cam", '["equiv_C"]').positions
    q = sol.quantities["equiv_C"]
    assert q.value["value"] == pytest.approx(0.040, rel=1e-12)             # the cam's radius
    assert q.passed


def test_no_contact_no_equivalent():
    with pytest.raises(TarsimError, match="cannot find 'equiv_O3'"):
        solved("roller-cam", '["equiv_O3"]')
