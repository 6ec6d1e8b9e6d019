"""Arrows drawn side by side where they would hide one another (graphics/linkages/lanes.py).

A short vector along a longer one must be seen: on the crank-shaper's worked page at
t = 2.34 s (seed 003 §2) the Coriolis component at B, 4.7 mm of paper, runs back from b₄′
along A_B₄'s shaft, 3.6° off its line, and was drawn inside it, its head merged with
A_B₄'s. It is moved into a lane of its own, as the arrows of a polygon collapsed onto one
line are.
"""

import math

import pytest
from shapely.geometry import LineString, Polygon

from tarsim.graphics.figure import Path
from tarsim.graphics.linkages.lanes import LANE, lanes, moved, runs_along

APART = 1.5     # mm of paper between a short arrow's shaft and a longer one it runs along:
                # an arrowhead is 1.6 mm wide, so at less the two read as one stroke
ALONG_DEG = 10.0    # arrows whose lines meet at less than this run along one another


def _arrows(fig):
    """Each arrow of the figure by the step it draws: (shaft, head polygon)."""
    out: dict[str, list] = {}
    for it in fig.items:
        if isinstance(it, Path) and it.style in ("vector", "vector_result", "arrowhead") \
                and it.steps:
            out.setdefault(it.steps[0], []).append(it)
    return {ref: (next(p for p in ps if p.style != "arrowhead").points,
                  Polygon(next(p for p in ps if p.style == "arrowhead").points))
            for ref, ps in out.items()
            if any(p.style == "arrowhead" for p in ps) and any(p.style != "arrowhead"
                                                                for p in ps)}


def _angle(s, t) -> float:
    """The angle (degrees, 0–90) between the lines of two segments."""
    a = math.atan2(s[-1][1] - s[0][1], s[-1][0] - s[0][0])
    b = math.atan2(t[-1][1] - t[0][1], t[-1][0] - t[0][0])
    d = abs(math.degrees(a - b)) % 180.0
    return min(d, 180.0 - d)


def _length(s) -> float:
    return math.dist(s[0], s[-1])


@pytest.mark.slow
def test_the_coriolis_component_at_b_stands_in_its_own_lane_beside_a_b4(solved):
    fig = solved("crank-shaper").figures["worked-t-2.34s"]
    arrows = _arrows(fig)
    shaft, head = arrows["ap:B5:cor:vec"]
    # The arrow itself, its shaft and head together: 4.74 mm at 1 cm = 50 mm/s².
    assert _length(shaft) + 0.7 * 2.8 == pytest.approx(4.74, abs=0.05)
    along = [(ref, s, h) for ref, (s, h) in arrows.items() if ref != "ap:B5:cor:vec"
             and _length(s) > _length(shaft) and _angle(s, shaft) < ALONG_DEG]
    assert "ap:A:B4" in [ref for ref, _, _ in along]        # what it ran inside
    for ref, s, h in along:
        assert LineString(shaft).distance(LineString(s)) >= APART, ref
        assert not head.intersects(h), ref


def test_a_short_arrow_running_back_along_a_longer_one_is_moved_aside():
    """The Coriolis case by hand: 4.7 mm back from the tip of a 100 mm arrow, 0.3 mm off
    its line; it goes a lane aside, the long one stays on its points."""
    ends = [((0.0, 0.0), (100.0, 0.0)), ((100.0, 0.0), (95.3, 0.3))]
    lane = lanes(ends, [True, False])
    assert lane[0] == 0 and lane[1] != 0
    short = moved(ends[1], lane[1])
    # A lane is 3 mm; its tilt of 3.7° brings its far end 0.3 mm nearer the long arrow.
    assert LineString(short).distance(LineString(ends[0])) == pytest.approx(LANE - 0.3,
                                                                            abs=0.02)


def test_arrows_nested_from_one_tail_or_end_to_end_keep_their_points():
    """V_A₄ within V_B₄ from o_v, and a polygon's sides meeting end to end at 5°, stay."""
    nested = [((0.0, 0.0), (100.0, 0.0)), ((0.0, 0.0), (40.0, 0.5))]
    end_to_end = [((0.0, 0.0), (50.0, 0.0)), ((50.0, 0.0), (100.0, 4.4))]
    assert lanes(nested, [True, True]) == [0, 0]
    assert lanes(end_to_end, [False, False]) == [0, 0]


def test_a_lane_that_would_cross_another_arrow_gives_way_to_the_other_side():
    """The short arrow's right-hand lane would put it over a third arrow leaving its
    tail square to the long one; it takes the left."""
    ends = [((0.0, 0.0), (100.0, 0.0)), ((100.0, 0.0), (95.0, 0.0)),
            ((95.0, 0.0), (95.0, -30.0))]
    lane = lanes(ends, [True, False, False])
    short = moved(ends[1], lane[1])
    assert LineString(short).distance(LineString(ends[2])) > 0.5


def test_runs_along_measures_the_shared_stretch():
    assert runs_along((10.0, 0.3), (20.0, -0.2), (0.0, 0.0), (30.0, 0.0)) == (10.0, 20.0)
    assert runs_along((10.0, 1.6), (20.0, 0.0), (0.0, 0.0), (30.0, 0.0)) is None
