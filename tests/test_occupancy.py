"""The placer's raster prices a box by the ink under it: against shapely's exact areas, to
within the cells along the shapes' edges."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString, Point, box

from tarsim.graphics.labels import LabelPlacer
from tarsim.graphics.figure import Figure
from tarsim.graphics.occupancy import CELL, Occupancy

coord = st.floats(-60.0, 60.0)


@settings(max_examples=60, deadline=None)
@given(x0=coord, y0=coord, x1=coord, y1=coord, w=st.floats(0.3, 3.0),
       cx=coord, cy=coord, hw=st.floats(0.5, 8.0), hh=st.floats(0.5, 8.0),
       weight=st.floats(0.02, 10.0))
def test_the_ink_under_a_box_is_its_exact_overlap_to_a_cell_about_the_edges(
        x0, y0, x1, y1, w, cx, cy, hw, hh, weight):
    line = LineString([(x0, y0), (x1, y1)]).buffer(w, cap_style="flat")
    ring = Point(x1, y0).buffer(6.0).difference(Point(x1, y0).buffer(4.0))   # a hole kept clear
    occ = Occupancy()
    occ.paint(line, weight)
    occ.paint(ring, 1.0)
    got = occ.ink(np.array([[cx, cy]]), (hw, hh))[0, 0]
    b = box(cx - hw, cy - hh, cx + hw, cy + hh)
    exact = weight * b.intersection(line).area + b.intersection(ring).area
    # A cell counts whole or not at all by its centre: the error is at most the cells the
    # edges of the box and of each shape pass through, each weighed.
    edges = 2 * (2 * hw + 2 * hh) + line.length + ring.length
    assert abs(got - exact) <= (weight + 1.0) * edges * CELL


def test_a_box_clear_of_the_ink_costs_nothing_and_one_on_it_costs_its_area():
    occ = Occupancy()
    occ.paint(box(0.0, 0.0, 20.0, 2.0), 1.0)
    clear, half = occ.ink(np.array([[10.0, 5.0], [10.0, 2.0]]), (3.0, 2.0))[0]
    assert clear == 0.0
    assert half == 6.0 * 2.0          # the lower half of a 6 × 4 box lies on the bar


def test_the_raster_grows_to_hold_ink_far_off():
    occ = Occupancy()
    occ.paint(box(0.0, 0.0, 1.0, 1.0), 1.0)
    occ.paint(box(500.0, -300.0, 501.0, -299.0), 2.0)
    got = occ.ink(np.array([[0.5, 0.5], [500.5, -299.5]]), (1.0, 1.0))[0]
    assert np.allclose(got, [1.0, 2.0])


def test_a_label_takes_the_first_clear_spot_of_its_preferred_side():
    fig = Figure(100.0, 100.0)
    placer = LabelPlacer(fig)
    placer.block(box(45.0, 40.0, 80.0, 49.0))        # ink right of and above the anchor
    c, cost = placer.spot(6.0, 3.0, (50.0, 50.0), prefer=0.0)
    assert cost == 0.0
    top, right = c[1] - 1.5, c[0] + 3.0          # the box's top edge and right edge
    assert top >= 49.0 + placer.clearance - 1e-9 or right <= 45.0 - placer.clearance + 1e-9


def test_a_name_is_kept_nearer_its_own_point_than_another():
    fig = Figure(100.0, 100.0)
    placer = LabelPlacer(fig)
    placer.name_points([(50.0, 50.0), (50.0, 44.0)])
    t = placer.place("A", (50.0, 50.0), prefer=np.pi / 2, own=(50.0, 50.0))   # up: toward B
    x0, y0, x1, y1 = t.box()
    assert y0 > 47.0          # above A it would stand nearer B: it goes beside or below


def test_ink_far_off_the_page_does_not_grow_the_raster_past_its_most():
    from tarsim.graphics.occupancy import _MOST

    occ = Occupancy()
    occ.paint(box(0.0, 0.0, 10.0, 10.0), 1.0)
    occ.paint(box(0.0, -5000.0, 10.0, -4990.0), 1.0)      # a point kilometres off
    near, far = occ.ink(np.array([[5.0, 5.0], [5.0, -4995.0]]), (1.0, 1.0))[0]
    rows, cols = occ.grid.shape
    assert rows * CELL <= _MOST + CELL and cols * CELL <= _MOST + CELL
    assert near == 4.0 and far == 0.0                       # the far one is not kept


def test_a_raster_grown_to_its_most_keeps_what_it_holds_when_asked_for_more():
    # Ink wider than the most a raster holds grows it to its most, which, rounded out to
    # whole cells, stands a cell past it; the same ink asked for again (a micro-mechanism's
    # page, drawn at 10⁷ : 1) once cut the raster down, and the old grid could not drop in.
    wide = box(-493.26, -542.61, 542.61, 493.26)
    occ = Occupancy()
    occ.paint(wide, 1.0)
    first = occ.ink(np.array([[0.0, 0.0]]), (1.0, 1.0))[0, 0]
    occ.paint(wide, 1.0)
    again = occ.ink(np.array([[0.0, 0.0]]), (1.0, 1.0))[0, 0]
    assert (first, again) == (4.0, 8.0)             # a 2 × 2 mm box, inked once, then twice


micron = st.integers(-60_000, 60_000).map(lambda i: i / 1000.0)   # paper mm, to a micron


@settings(max_examples=200, deadline=None)
@given(cx=micron, cy=micron, hw=st.floats(0.5, 8.0), hh=st.floats(0.5, 8.0),
       ax=micron, ay=micron, bx=micron, by=micron,
       kind=st.sampled_from(("point", "level", "plumb", "any")))
def test_a_box_is_as_far_from_a_named_thing_as_shapely_measures(cx, cy, hw, hh, ax, ay, bx,
                                                                 by, kind):
    from tarsim.graphics.label_nearness import box_distance as _box_distance

    if kind == "point":
        bx, by = ax, ay
    elif kind == "level":
        by = ay
    elif kind == "plumb":
        bx = ax
    thing = Point(ax, ay) if (ax, ay) == (bx, by) else LineString([(ax, ay), (bx, by)])
    exact = box(cx - hw, cy - hh, cx + hw, cy + hh).distance(thing)
    got = _box_distance(np.array([[cx, cy]]), hw, hh, np.array([[[ax, ay], [bx, by]]]))[0, 0]
    assert abs(got - exact) <= 1e-9 * (1.0 + exact)     # a few roundings of coordinates ≤ 60
