"""A rocker's or slotted lever's angle of swing between its limit positions (``swing_k``),
and a slotted lever's inclination to the line of centres, held to the closed forms of the
triangles the limits make."""

from __future__ import annotations

import math

import pytest

from tarsim.constructions.errors import TarsimError
from tarsim.exercises.catalog import load, resolve
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution import solve_overall


def _at_d(ad: float, cd: float, ac: float) -> float:
    """The angle at D of triangle ACD (cosine rule)."""
    return math.acos((ad * ad + cd * cd - ac * ac) / (2 * ad * cd))


def test_a_crank_rocker_swings_between_crank_and_coupler_in_line():
    # O2O4 = 100, O2A = 30, AB = 100, O4B = 65 mm: the rocker stops with O2B = 130 and 70
    # mm; its swing is the difference of its angles at O4 in the two triangles O2BO4.
    q = solve_overall(load("grashof-crank-rocker")).quantities["swing_4"]
    want = _at_d(100, 65, 130) - _at_d(100, 65, 70)
    # cuts of arcs of lengths near 0.1 m, a few roundings each: 1e-12
    assert q.value["value"] == pytest.approx(want, rel=1e-12)
    assert "inclination" not in q.value
    assert q.passed and q.method == "limit positions by compass (protractor at O4)"


def test_a_slotted_lever_swings_2_asin_r_over_c_and_leans_asin_r_over_c():
    # P-37: crank 6 cm, centres 16 cm apart: at each limit the crank is square to the lever,
    # so the lever leans asin(6/16) from the line of centres either way.
    text = resolve("slotted-lever-p37").read_text(encoding="utf-8")
    ex = parse_exercise(text, "p.toml", "p").asking(("swing_4",))
    q = solve_overall(ex).quantities["swing_4"]
    assert q.value["value"] == pytest.approx(2 * math.asin(6 / 16), rel=1e-12)
    assert q.value["inclination"] == pytest.approx(math.asin(6 / 16), rel=1e-12)
    assert q.passed


def test_a_link_that_does_not_swing_between_limits_is_refused_with_the_reason():
    text = resolve("offset-slider-crank").read_text(encoding="utf-8")
    with pytest.raises(TarsimError, match=r"^o\.toml:\d+: \[ask\.find\] cannot find 'swing_3' for "
                                          r"this mechanism: swing_<k> is asked of the rocker"):
        parse_exercise(text.replace('find = [', 'find = ["swing_3", '), "o.toml", "o")
