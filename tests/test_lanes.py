"""Arrows drawn side by side where they would hide one another (graphics/linkages/lanes.py).

A short vector along a longer one must be seen: on the crank-shaper's worked page at
t = 2.34 s (seed 003 §2) the Coriolis component at B, 4.7 mm of paper, runs back from b₄′
along A_B₄'s shaft, 3.6° off its line, and was drawn inside it, its head merged with
A_B₄'s. It is moved into a lane of its own, as the arrows of a polygon collapsed onto one
line are.
"""

import math
import re

import pytest
from shapely.geometry import LineString, Polygon

from tarsim.graphics.figure import Path, Text
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
    sol = solved("crank-shaper")
    fig = sol.figures["worked-t-2.34s"]
    arrows = _arrows(fig)
    shaft, head = arrows["ap:B5:cor:vec"]
    # The arrow itself, its shaft and head together, is A^c_B (23.7 mm/s²) at the scale the
    # page states: 4.74 mm at 1 cm = 50 mm/s², 9.48 mm at 25. Its tip is set to 0.05 mm.
    coriolis = sol.results["positions"][1]["quantities"]["A_cor_B"]["value"] * 1e3
    assert coriolis == pytest.approx(23.71, abs=0.01)
    stated = [re.fullmatch(r"Acceleration scale 1 cm = ([\d.]+) mm/s²", t.text)
              for t in fig.items if isinstance(t, Text)]
    per_cm = float(next(m for m in stated if m).group(1))
    assert _length(shaft) + 0.7 * 2.8 == pytest.approx(10.0 * coriolis / per_cm, abs=0.05)
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


# ----- components along a link, on the space diagram ----------------------------------------
OFF_LINK = 1.0      # mm of paper a component arrow stands off a link it runs along: a link is
                    # drawn 0.5 mm thick and an arrowhead 1.4 mm wide, so at less it is hidden
READABLE = 30.0     # mm: the longest arrow of a velocity construction, at least

_ALONG_A_LINK = {
    # Hinkle §5-3 and the four-bar: V_B′ laid off along link 3 (or the plate's edge BE).
    ("four-bar", "V_B-components"): ("vector",),
    ("hinkle-four-bar", "V_E-components"): ("vector",),
    # The offset slider-crank's V_B lies along rod 3, nearly level, from B.
    ("offset-slider-crank", "V_B-parallel-line"): ("vector", "vector_result"),
}


def _links(fig):
    """Every straight edge of a link or plate drawn, on paper."""
    return [(it.points[k], it.points[(k + 1) % len(it.points)]) for it in fig.items
            if isinstance(it, Path) and it.style in ("link", "plate")
            for k in range(len(it.points) - (0 if it.closed else 1))]


def _off_link(arrow, link) -> float | None:
    """How near the arrow comes to the link over the stretch of the link's line both cover
    (more than a millimetre of it), for an arrow within ALONG_DEG of the link; else None."""
    (p, q), (a, b) = link, arrow
    n = math.dist(p, q)
    if n == 0.0 or _angle(arrow, link) >= ALONG_DEG:
        return None
    u = ((q[0] - p[0]) / n, (q[1] - p[1]) / n)
    s, t = ((x[0] - p[0]) * u[0] + (x[1] - p[1]) * u[1] for x in (a, b))
    o, w = ((x[0] - p[0]) * u[1] - (x[1] - p[1]) * u[0] for x in (a, b))
    lo, hi = max(min(s, t), 0.0), min(max(s, t), n)
    if hi - lo <= 1.0:
        return None
    at = [o + (w - o) * (x - s) / (t - s) for x in (lo, hi)]   # offset, linear along it
    return min(abs(v) for v in at) if at[0] * at[1] > 0 else 0.0


def _vectors(fig, styles):
    heads = [it.points[0] for it in fig.items if isinstance(it, Path) and it.style == "arrowhead"]
    out = []
    for it in fig.items:
        if isinstance(it, Path) and it.style in styles:
            tip = min(heads, key=lambda h: math.dist(h, it.points[-1]))  # shaft stops in head
            out.append((it, (it.points[0], tip)))
    return out


@pytest.mark.slow
@pytest.mark.parametrize("exercise_id, stem", _ALONG_A_LINK)
def test_no_component_arrow_lies_on_a_link_and_the_construction_reads(solved, exercise_id,
                                                                      stem):
    fig = solved(exercise_id).figures[stem]
    links = _links(fig)
    near = [(it.steps, round(d, 2)) for it, arrow in _vectors(fig, _ALONG_A_LINK[exercise_id,
                                                                                  stem])
            for link in links if (d := _off_link(arrow, link)) is not None and d < OFF_LINK]
    assert near == []
    longest = max(math.dist(*arrow) for _, arrow in _vectors(fig, ("vector", "vector_result")))
    assert longest >= READABLE


@pytest.mark.slow
def test_a_component_moved_off_its_link_is_named_on_its_own_side(solved):
    """V_B′ of the four-bar, beside link 3: its name stands on the side it was moved to,
    not across the link."""
    fig = solved("four-bar").figures["V_B-components"]
    ((it, (a, b)),) = [(it, arrow) for it, arrow in _vectors(fig, ("vector",))
                       if it.steps == ("cm:B:along-arrow@A",)]
    (link,) = [ln for ln in _links(fig) if _off_link((a, b), ln) is not None]
    (name,) = [t for t in fig.items if isinstance(t, Text) and t.owner
               and math.dist(t.owner[0], it.points[0]) < 1e-6]
    (p, q) = link
    n = math.dist(p, q)

    def side(x):
        return ((x[0] - p[0]) * (q[1] - p[1]) - (x[1] - p[1]) * (q[0] - p[0])) / n
    x0, y0, x1, y1 = name.box()
    assert side(a) * side(((x0 + x1) / 2, (y0 + y1) / 2)) > 0
