"""Each name on a linkage figure stands by what it names, or a leader joins them.

A reader takes a name for the point or the arrow marked nearest it; a name that stands
off in the white (a centre found by Kennedy's theorem where a dozen lines meet, a short
arrow's name among a polygon's crowded tips) is read for nothing unless a line leads from
its own to it. Measured on every bundled linkage figure, space diagrams and polygons,
from the Figure model: the gap from each name (its text's box) to its mark (a point's pin,
dot or fixed pivot's triangle; a vector's shaft) is at most
:data:`~tarsim.graphics.linkages.name_leaders.NEAR`, or a leader runs from that mark to
that name.
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

SHAFT = 0.8
"""mm: an arrow's half width at its head, the mark a vector's name stands by."""

TOUCH = 0.6
"""mm: a leader's end within this of the mark or the name reaches it (it stops 0.4 short,
leaving white between them)."""

KNOWN = {"hinkle-slider-crank": {"I₃₄"}, "klein-slider-crank": {"e′"}}
"""Names that stand off with no leader, by exercise, each where every leader to it crosses
another name and every clear spot it could be set again in stands much farther off:
I₃₄ at the slider's pin C, set over the plate behind C's own name; Klein's e′, where the
rod, the crank and two working lines meet by d′ and its leader."""


@cache
def _figures(name: str) -> dict:
    return solve(load(name)).figures


def _mark(fig, own):
    """What marks ``own``: a point's pin or dot, and a fixed pivot's triangle on it; a
    vector's shaft, as wide as its head."""
    if len(own) == 2:
        return LineString(own).buffer(SHAFT)
    at = own[0]
    parts = [Point(c.centre).buffer(c.radius) for c in fig.items if isinstance(c, Circle)
             and c.style in ("pin", "dot") and math.dist(c.centre, at) < 0.05]
    parts += [Polygon(p.points) for p in fig.items if isinstance(p, Path)
              and p.style == "ground" and p.closed and math.dist(p.points[0], at) < 0.05]
    return unary_union(parts) if parts else Point(at)


def strays(fig) -> list[tuple[str, float]]:
    """Each name of a point or a vector farther than NEAR from its mark with no leader to it,
    and how far."""
    leaders = [LineString(p.points) for p in fig.items
               if isinstance(p, Path) and p.style == "plot_leader"]
    out = []
    for t in fig.items:
        if not (isinstance(t, Text) and t.owner is not None):
            continue
        name, mark = box(*t.box()), _mark(fig, t.owner)
        gap = name.distance(mark)
        if gap <= NEAR + 1e-6:
            continue
        if not any(min(mark.distance(Point(e)) for e in (ln.coords[0], ln.coords[-1])) < TOUCH
                   and min(name.distance(Point(e)) for e in (ln.coords[0], ln.coords[-1]))
                   < TOUCH for ln in leaders):
            out.append((t.text + t.sub, round(gap, 2)))
    return out


@pytest.mark.parametrize("name", list(bundled()))
def test_names_stand_by_what_they_name(name):
    for stem, fig in _figures(name).items():
        known = KNOWN.get(name, set())
        assert [s for s in strays(fig) if s[0] not in known] == [], f"{name}/{stem}"


def test_six_link_centres_are_named_beside_or_led_to():
    """The Watt six-bar's centres, where up to six Kennedy lines meet at a centre: each name
    beside its point (the step numbers beyond it), or led to; some are led to."""
    fig = _figures("six-link-homework-3")["centres"]
    assert strays(fig) == []
    gaps = {t.text + t.sub: box(*t.box()).distance(_mark(fig, t.owner))
            for t in fig.items if isinstance(t, Text) and t.owner and len(t.owner) == 1}
    led = sum(1 for p in fig.items if isinstance(p, Path) and p.style == "plot_leader")
    # Some stand off (8 of 22, 3.5 to 6.2 mm off their marks) and are led to; the
    # most stand beside their points.
    assert sum(1 for g in gaps.values() if g > NEAR) <= led < len(gaps) / 2
    # I₁₅ stands beside its point, its number beyond it (before, it stood 7.8 mm off
    # behind its badge).
    assert gaps["I₁₅"] <= NEAR


def test_a_name_led_to_its_own_is_no_stray_of_the_overlap_counter():
    """tests/label_overlaps.py's strays read a name a leader joins to its own for its own:
    A set 4.7 mm off its point, 2.7 mm from B's, is a stray until a leader runs to it."""
    from tarsim.graphics.figure import Figure
    from tests.label_overlaps import strays as nearer_another

    fig = Figure(100.0, 100.0)
    fig.add(Text((50.0, 44.0), "A", owner=((50.0, 50.0),)))
    fig.add(Text((52.5, 40.0), "B", owner=((50.0, 40.0),)))
    assert [name for name, _, _ in nearer_another(fig)] == ["A"]
    x0, y0, x1, y1 = fig.items[0].box()
    fig.add(Path(((50.0, 49.6), ((x0 + x1) / 2, y1 + 0.4)), "plot_leader"))
    assert nearer_another(fig) == []
    assert strays(fig) == []            # and it stands by its own, led to
