"""Tests for constructions.transmission: ω by the line of transmission (exam text 001 §2.1).

ω_follower / ω_driver = O_d G / O_f H, the perpendiculars from the two fixed centres
to the coupler line, with the same sense when both centres lie on one side of it.
The reference is the analytic solver's ω; the perpendiculars are drawn and read with
a few roundings each, so the ratio agrees to ~1e-15 unless O_f H is short (near a
dead point), where the conditioning reported grows the tolerance.
"""

import math
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString, MultiLineString

import tarsim

from tarsim.constructions.errors import TarsimError
from tarsim.constructions.narration import narrate
from tarsim.constructions.reference import solver
from tarsim.constructions.registry import CHOSEN
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution import solve_exercise
from tests.common import four_bar_toml

ASK = ('\n[ask]\nfind = ["omega4", "omega3"]\n'
       'methods = ["line-of-transmission", "radius-rotation"]\n')


def four_bar(ask=ASK, *, branch="left", **kw) -> str:
    """The peers.md four-bar turning at ω2 = 10 rad/s, with ``ask``."""
    text = four_bar_toml(branch=f'B = "{branch}"', **kw).replace("[input]\n",
                                                                "[input]\nomega = 10\n")
    return text + ask


def solved(**kw):
    return solve_exercise(parse_exercise(four_bar(**kw), "lot.toml"))


@settings(max_examples=40, deadline=None)
@given(angle=st.floats(0.0, 360.0), branch=st.sampled_from(["left", "right"]))
def test_omega_agrees_with_the_analytic_solver_round_the_cycle(angle, branch):
    sol = solved(angle=angle, branch=branch)
    q = sol.quantities["omega4"]
    assert q.method == "line of transmission"          # chosen first, so it answers
    assert q.passed and q.rel_error <= q.tolerance
    ratio = q.alternatives["instant centres (ω ratio)"]
    assert q.value["value"] == pytest.approx(ratio.value["value"], rel=1e-12, abs=1e-12)


def test_the_perpendiculars_are_drawn_and_measured_as_the_text_says():
    sol = solved(angle=60)
    c = sol.assembly
    o2, o4, g, h = (c.output(r).xy for r in ("P:O2", "P:O4", "lt:4:G", "lt:4:H"))
    a, b = sol.assembly.xy("A"), sol.assembly.xy("B")
    ux, uy = (b[0] - a[0]) / math.dist(a, b), (b[1] - a[1]) / math.dist(a, b)
    for centre, foot in ((o2, g), (o4, h)):       # each foot is square under its centre
        assert (centre[0] - foot[0]) * ux + (centre[1] - foot[1]) * uy == pytest.approx(0.0,
                                                                                      abs=1e-15)
    said = narrate(c["lt:4:O4H"])
    kin = solver.solve(sol.exercise.mechanism)
    w = kin.omegas[4] / kin.omegas[2]
    assert f"ω4/ω2 = O2G/O4H = {abs(w):.6g}" in said and "the same side" in said
    assert math.dist(o2, g) / math.dist(o4, h) == pytest.approx(abs(w), rel=1e-13)


@pytest.mark.parametrize("angle, apart", [(300, True), (90, False)])
def test_centres_on_opposite_sides_turn_the_follower_the_other_way(angle, apart):
    # At θ2 = 300° the coupler runs between O2 and O4: the rocker turns against the crank.
    sol = solved(angle=angle)
    q = sol.quantities["omega4"]
    said = narrate(sol.assembly["lt:4:O4H"])
    assert q.passed and ("opposite sides" in said) == apart == (q.value["value"] < 0)


def test_a_link_no_coupler_joins_is_left_to_the_other_methods():
    q = solved(angle=60).quantities["omega3"]         # the coupler itself: no line for it
    assert q.method == "instant centres (ω ratio)" and not q.alternatives


def test_the_method_is_chosen_by_name_in_the_registry():
    assert "line-of-transmission" in CHOSEN
    only = ASK.replace('"line-of-transmission", "radius-rotation"', '"line-of-transmission"')
    ex = parse_exercise(four_bar(only.replace('"omega4", "omega3"', '"omega4"')))
    assert solve_exercise(ex).quantities["omega4"].method == "line of transmission"
    with pytest.raises(TarsimError, match="no method the exercise uses answers omega3"):
        solve_exercise(parse_exercise(four_bar(only)))


def _segments(svg: str, group: str) -> list[list[tuple[float, float]]]:
    """The polylines of every ``<g class="group">`` in ``svg``, in paper mm."""
    out = []
    for body in re.findall(rf'<g class="{group}"[^>]*>(.*?)</g>', svg):
        for d in re.findall(r'<path d="([^"]+)"', body):
            out.append([tuple(map(float, p.split(","))) for p in re.findall(r"[-\d.]+,[-\d.]+", d)])
    return out


def test_the_measured_perpendiculars_stand_clear_of_the_links():
    # O4H runs up from the rocker's pivot with the rocker beside it on its outer side: its
    # dimension line stands on the inner side, where it crosses no link.
    figure = tarsim.solve(parse_exercise(four_bar(angle=60), "lot.toml")).figures[
        "omega4-line-of-transmission"]
    svg = figure._repr_svg_()
    links = MultiLineString(_segments(svg, "link"))
    dimensions = [s for s in _segments(svg, "dimension") if len(s) == 2]
    assert len(dimensions) == 8       # two spans: two extensions, a line drawn out from its middle
    for seg in dimensions:
        assert not LineString(seg).intersects(links), seg
    assert "O₂G 55.15 mm" in svg and "O₄H 189.1 mm" in svg     # drafting precision
