"""Where the placer sets a name and its step numbers (graphics/labels.py): beside what it
names, its numbers beyond it; over a thin line before off in a farther ring.

Sizes are the polygon panel's: a tip's name 3.8 mm high, badges 1.55 mm in radius, thin
working lines blocked 0.9 mm wide at a fiftieth of ink's price.
"""

from __future__ import annotations

import pytest
from shapely.geometry import Point, box

from tarsim.graphics.figure import Circle, Figure, Text
from tarsim.graphics.labels import LabelPlacer


def _placed(fig: Figure) -> tuple[Text, list[Circle]]:
    name = next(t for t in fig.items if isinstance(t, Text) and t.owner is not None)
    return name, [c for c in fig.items if isinstance(c, Circle) and c.style == "badge"]


@pytest.mark.parametrize("beside", [True, False])
def test_a_names_numbers_stand_beyond_it_where_the_unit_stands_left_of_its_point(beside):
    """Ink right of the point sends "a₂ ②⑤" to its left. Set beside its point, the name
    follows its numbers ("②⑤ a₂"), its box nearer the point than either badge; set as
    written, the numbers stand between the name and the point."""
    fig = Figure(100.0, 100.0)
    placer = LabelPlacer(fig)
    at = (50.0, 50.0)
    placer.block(box(50.5, 30.0, 90.0, 70.0))               # everything right of the point
    placer.place_numbered("a₂", at, [2, 5], prefer=0.0, gap=1.0, size=3.8, own=at,
                          beside=beside)
    name, badges = _placed(fig)
    x0, y0, x1, y1 = name.box()
    assert x1 < at[0] and all(c.centre[0] < at[0] for c in badges)   # the unit stands left
    mine = box(x0, y0, x1, y1).distance(Point(at))
    theirs = [Point(c.centre).buffer(c.radius).distance(Point(at)) for c in badges]
    if beside:
        assert all(c.centre[0] < x0 for c in badges) and mine < min(theirs)
    else:
        assert all(c.centre[0] > x1 for c in badges) and mine > max(theirs)


def test_a_name_with_no_numbers_is_set_as_written_either_way():
    """With no numbers to set beyond it, ``beside`` moves nothing."""
    spots = []
    for beside in (True, False):
        fig = Figure(100.0, 100.0)
        placer = LabelPlacer(fig)
        placer.block(box(50.5, 30.0, 90.0, 70.0))
        placer.place_numbered("b", (50.0, 50.0), [], prefer=0.0, own=(50.0, 50.0),
                              beside=beside)
        spots.append(_placed(fig)[0].at)
    assert spots[0] == spots[1]


@pytest.mark.parametrize("crossing, near", [(0.4, True), (0.0, False)])
def test_a_name_crosses_a_thin_line_rather_than_stand_off_in_a_farther_ring(crossing, near):
    """The crank-shaper's velocity polygon at θ2 = 90°, all on one line: the tip b where
    two thin working lines cross (one 10 mm either side of it, one run 4 mm past it), the
    line through a 8.8 mm left, the arrow to b, and the panel's edge 16 mm off. Every spot
    within the near rings' 8 mm crosses a line or leaves the page. Let cross a line of a
    fiftieth of ink's price (0.4 mm² of it: twenty of a line), the name stands within
    3 mm of b; let cross none, it stands off in a farther ring, 11 mm away, as far from b
    as the dashed line's end is."""
    fig = Figure(200.0, 200.0)
    placer = LabelPlacer(fig)
    tip = (100.0, 100.0)
    placer.page = box(60.0, 84.0, 116.0, 116.0)
    placer.block_path([(100.0, 90.0), (100.0, 110.0)], 0.3, weight=0.02)    # ⟂ through b
    placer.block_path([(91.2, 90.0), (91.2, 110.0)], 0.3, weight=0.02)      # ⟂ through a
    placer.block_path([(85.0, 100.0), (104.0, 100.0)], 0.3, weight=0.02)    # the carrier
    placer.block_path([(60.0, 100.0), (99.0, 100.0)], 1.6)                  # the arrow to b
    placer.place_numbered("b₄ ≡ b₅", tip, [6, 9], gap=1.0, size=3.8, own=tip,
                          farther=(6.0, 8.0, 11.0, 15.0), crossing=crossing, beside=True)
    name, _ = _placed(fig)
    off = box(*name.box()).distance(Point(tip))
    assert off <= 3.0 if near else off > 8.0, off
