"""Each point's name on a linkage figure stands by its point, or a leader joins them.

A reader takes a name for the point marked nearest it; a name that stands off in the
white (a centre found by Kennedy's theorem where a dozen lines meet) is read for nothing
unless a line leads from its point to it. Measured on every bundled linkage figure from
the Figure model: the gap from each point's name (its text's box) to the point's mark (the
pin's circle or the dot, and a fixed pivot's triangle) is at most
:data:`~tarsim.graphics.linkages.scene_marks.NEAR`, or a leader runs from that mark to that
name.
"""

from __future__ import annotations

import math
from functools import cache

import pytest
from shapely.geometry import LineString, Point, Polygon, box
from shapely.ops import unary_union

from tarsim import load, solve
from tarsim.exercises.catalog import bundled
from tarsim.graphics.figure import Circle, Path, Text
from tarsim.graphics.linkages.name_leaders import NEAR

TOUCH = 0.6
"""mm: a leader's end within this of the mark or the name reaches it (it stops 0.4 short,
leaving white between them)."""

POLYGONS = ("worked",)
"""Figures whose points' names are set by the polygons' own rules (a tip's name may stand
off in a farther ring rather than cover a label): not the space diagram's."""


KNOWN = {"klein-slider-crank/klein": {"e"}}
"""Names that stand off with no leader: Klein's e, where the rod, the crank's line and the
circle's chord meet by O, every leader crosses another name and no spot nearer is clear."""


@cache
def _figures(name: str) -> dict:
    return solve(load(name)).figures


def _mark(fig, at: tuple[float, float]):
    """What marks the point ``at``: its pin or dot, and a fixed pivot's triangle on it."""
    parts = [Point(c.centre).buffer(c.radius) for c in fig.items if isinstance(c, Circle)
             and c.style in ("pin", "dot") and math.dist(c.centre, at) < 0.05]
    parts += [Polygon(p.points) for p in fig.items if isinstance(p, Path)
              and p.style == "ground" and p.closed and math.dist(p.points[0], at) < 0.05]
    return unary_union(parts) if parts else Point(at)


def strays(fig, arrows: bool = False) -> list[tuple[str, float]]:
    """Each point's name (or, ``arrows``, each arrow's: its owner is its tail and tip)
    farther than NEAR from its mark (or its shaft) with no leader to it, and how far."""
    leaders = [LineString(p.points) for p in fig.items
               if isinstance(p, Path) and p.style == "plot_leader"]
    out = []
    for t in fig.items:
        if not (isinstance(t, Text) and t.owner is not None
                and len(t.owner) == (2 if arrows else 1)
                and isinstance(t.owner[0], tuple)):
            continue
        name = box(*t.box())
        mark = LineString(t.owner) if arrows else _mark(fig, t.owner[0])
        gap = name.distance(mark)
        if gap <= NEAR + 1e-6:
            continue
        if not any(min(mark.distance(Point(e)) for e in (ln.coords[0], ln.coords[-1])) < TOUCH
                   and min(name.distance(Point(e)) for e in (ln.coords[0], ln.coords[-1]))
                   < TOUCH for ln in leaders):
            out.append((t.text + t.sub, round(gap, 2)))
    return out


@pytest.mark.parametrize("name", list(bundled()))
def test_names_stand_by_their_points(name):
    for stem, fig in _figures(name).items():
        if stem.split("-")[0] in POLYGONS:
            continue
        known = KNOWN.get(f"{name}/{stem}", set())
        assert [s for s in strays(fig) if s[0] not in known] == [], f"{name}/{stem}"


KNOWN_ARROWS = {
    "klein-slider-crank/worked": {"AⁿE/C", "AⁿP/C"},
    "wheel-driven-slider/worked": {"AⁿB/A", "AⁿA/C"},
    "wheel-round-circle/worked": {"AᵗC"},
    "whitworth/worked": {"VA₂/A₄"},
}
"""Arrows' names that stand off with no leader: each where a polygon's short arrows crowd,
every spot nearer is covered and every leader would cross another name, a step number or
an arrowhead, or end nearer a point's name than its point (where it would be read, and
graded, as the point that name names)."""


@pytest.mark.parametrize("name", list(bundled()))
def test_names_stand_by_their_arrows(name):
    """An arrow's name (``Aᵗ_A/P``, ``V_E′(AE)``) stands within NEAR of its shaft or is led
    to: where a polygon's short arrows crowd at a tip their names stand off in the white,
    and would be read for the arrow nearest them."""
    for stem, fig in _figures(name).items():
        known = KNOWN_ARROWS.get(f"{name}/{stem}", set())
        found = {s[0] for s in strays(fig, arrows=True)}
        assert found == known, f"{name}/{stem}"     # none new, and none listed that is led


@pytest.mark.parametrize("name", list(bundled()))
def test_no_leader_crosses_another_name(name):
    """A leader runs from what a name names to that name, crossing no other: not another
    point's or arrow's name, nor its own name's second part ("Aⁿ_A₂ = A_A₂", whose leader
    ran through "= A_A₂" on the crank-shaper's θ₂ = 90° page)."""
    for stem, fig in _figures(name).items():
        texts = [(t.text + t.sub, box(*t.box())) for t in fig.items
                 if isinstance(t, Text) and t.text.strip()]
        for p in fig.items:
            if not (isinstance(p, Path) and p.style == "plot_leader"):
                continue
            ln = LineString(p.points)
            own = min(texts, key=lambda tb: min(tb[1].distance(Point(e)) for e in p.points))
            crossed = [n for n, b in texts if b is not own[1] and ln.intersection(b).length > 0.05]
            assert crossed == [], (f"{name}/{stem}", own[0], crossed)


def test_the_rolling_wheels_crowded_arrows_are_led_to():
    """The wheel round a circle: where five arrows meet at m′, the short Aᵗ_M/C and Aᵗ_M/P
    have their names set off below it; each is led to, from its own shaft short of the
    head, and no leader crosses a name."""
    fig = _figures("wheel-round-circle")["worked"]
    named = {t.text + t.sub: t for t in fig.items if isinstance(t, Text)
             and t.owner is not None and len(t.owner) == 2 and isinstance(t.owner[0], tuple)}
    leaders = [LineString(p.points) for p in fig.items
               if isinstance(p, Path) and p.style == "plot_leader"]
    for n in ("AᵗM/C", "AᵗM/P"):
        shaft, label = LineString(named[n].owner), box(*named[n].box())
        assert label.distance(shaft) > NEAR
        (leader,) = [ln for ln in leaders if label.distance(ln) < TOUCH]
        assert shaft.distance(leader) < TOUCH
    names = [box(*t.box()) for t in fig.items if isinstance(t, Text) and t.text.strip()]
    assert not [1 for ln in leaders for b in names if ln.intersection(b).length > 0.05]


def test_six_link_centres_are_named_beside_or_led_to():
    """The Watt six-bar's centres, where up to six Kennedy lines meet at a centre: each name
    beside its point (the step numbers beyond it), or led to; some are led to."""
    fig = _figures("six-link-homework-3")["centres"]
    assert strays(fig) == []
    gaps = {t.text + t.sub: box(*t.box()).distance(_mark(fig, t.owner[0]))
            for t in fig.items if isinstance(t, Text) and t.owner and len(t.owner) == 1}
    led = sum(1 for p in fig.items if isinstance(p, Path) and p.style == "plot_leader")
    assert led == sum(1 for g in gaps.values() if g > NEAR)
    assert 0 < led < len(gaps) / 2      # the most stand beside their points
    # I₁₅ stands beside its point, its number beyond it (before, it stood 7.8 mm off
    # behind its badge).
    assert gaps["I₁₅"] <= NEAR
