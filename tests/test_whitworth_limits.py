"""A Whitworth quick return's limit positions: the crank longer than the distance between
the fixed centres, the lever turning right round, the ram reversing where the lever and
its rod lie in line. Held to the closed form of a line of stroke through the lever's pivot,
square to the line of centres: the crank pin is then on that line at cos(β/2) = O2O4/O2A
either side of O4, the return taking β, and the ram travels twice the lever's arm."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import TarsimError
from tarsim.exercises.catalog import load, resolve
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution import solve_overall


def closed_form(centres: float, crank: float, lever: float) -> tuple[float, float]:
    """(time ratio, stroke) of a Whitworth whose line of stroke runs through the lever's
    pivot, square to the line of centres."""
    beta = 2 * math.acos(centres / crank)
    return (2 * math.pi - beta) / beta, 2 * lever


def _whitworth(centres: float, crank: float, lever: float, rod: float, angle: float = 15):
    text = resolve("whitworth").read_text(encoding="utf-8")
    for old, new in (("O4 = [0, -70]", f"O4 = [0, {-centres!r}]"),
                     ("lengths = { O2A = 100 }", f"lengths = {{ O2A = {crank!r} }}"),
                     ("lengths = { O4B = 200 }", f"lengths = {{ O4B = {lever!r} }}"),
                     ("lengths = { BC = 250 }", f"lengths = {{ BC = {rod!r} }}"),
                     ("angle = 15\n", f"angle = {angle!r}\n")):
        assert old in text
        text = text.replace(old, new)
    ex = parse_exercise(text, "w.toml", "w").asking(("time_ratio", "stroke"))
    return solve_overall(ex).quantities


def test_the_bundled_whitworth_returns_in_2_acos_0_7_and_strokes_twice_its_lever():
    q = solve_overall(load("whitworth")).quantities
    ratio, stroke = closed_form(0.070, 0.100, 0.200)
    # the cuts of arcs and lines at lengths near 0.1 m, a few roundings each: 1e-12
    assert q["time_ratio"].value["value"] == pytest.approx(ratio, rel=1e-12)
    assert q["stroke"].value["value"] == pytest.approx(stroke, rel=1e-12)
    assert q["time_ratio"].method == "limit positions by compass (lever and rod in line)"
    assert q["time_ratio"].passed and q["stroke"].passed


@settings(max_examples=25, deadline=None)
@given(centres=st.floats(20, 90), ratio=st.floats(1.1, 3.0), lever=st.floats(60, 300),
       rod_ratio=st.floats(1.2, 3.0), angle=st.floats(0, 359))
def test_every_whitworth_of_a_line_of_stroke_through_its_pivot_meets_the_closed_form(
        centres, ratio, lever, rod_ratio, angle):
    q = _whitworth(centres, centres * ratio, lever, lever * rod_ratio, angle)
    want_ratio, want_stroke = closed_form(centres / 1000, centres * ratio / 1000, lever / 1000)
    # acos near its ends loses digits as 1/sin(β/2): with centres/crank ≤ 1/1.1, sin(β/2) ≥
    # 0.41, so a few roundings of 1e-16 stay below 1e-12 of the ratio
    assert q["time_ratio"].value["value"] == pytest.approx(want_ratio, rel=1e-12)
    assert q["stroke"].value["value"] == pytest.approx(want_stroke, rel=1e-12)
    assert q["time_ratio"].passed and q["stroke"].passed


def test_a_whitworth_whose_rod_is_shorter_than_its_lever_is_refused_in_one_line():
    with pytest.raises(TarsimError, match=r"the rod BC \(link 5, 150 mm\) is not longer than the "
                                          r"lever O4B \(200 mm\): the lever cannot turn right"):
        _whitworth(70, 100, 200, 150, angle=0)
