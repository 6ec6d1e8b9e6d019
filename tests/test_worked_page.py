"""A worked-solution page (graphics/linkages/worked_page.py): panels at true scale, then
the results.

What matters to a reader with a ruler: every panel on the page is its figure
moved, not scaled (so its scale bar still measures true), the panels and the
table do not overlap, the page is A3 landscape when they fit and grows when they
do not, and the table reads as a table (header in bold, numbers flush right).
"""

import math

import pytest

from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.record import Panel, Slice
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tarsim.graphics.figure import Circle, Figure, Path, Text
from tarsim.graphics.linkages.polygon_panel import draw_polygon_panel
from tarsim.graphics.linkages.scene import draw_scene
from tarsim.graphics.svg import to_svg
from tarsim.graphics.linkages.worked_page import A3, compose_worked_page
from tests.common import crank_shaper
from tests.test_polygon_panel import SHAPER_T, boxes_overlap, draw_acceleration, shaper_acceleration

TABLE = [("quantity", "construction", "analytic", "relative error"),
         ("V_B", "189.192 mm/s", "189.1924 mm/s", "1.5e-16"),
         ("ω4", "0.192118 rad/s ccw", "0.1921181 rad/s ccw", "2.9e-16"),
         ("A_B", "535.635 mm/s²", "535.6354 mm/s²", "0")]
NOTES = ("α2 not given: taken as 0",)


def shaper_panels():
    """The crank-shaper's space diagram, velocity polygon and acceleration polygon (seed 003)."""
    mech = crank_shaper(SHAPER_T)
    asm = assemble(mech)
    vp = draw_velocity_polygon(asm)
    space = draw_scene(Slice(asm, ()), title="crank shaper: space diagram")
    velocity = draw_polygon_panel(Slice(asm, tuple(vp.steps)), panel=Panel.VELOCITY,
                                  scale=vp.scale, units=mech.units, title="Velocity polygon")
    c, refs, _, _ = shaper_acceleration()
    return [space, velocity, draw_acceleration(c, refs, mech)]


def placed(page, panels):
    """Each panel's offset on the page, from its frame, checking its items came along unscaled."""
    frames = [it for it in page.items if isinstance(it, Path) and it.style == "frame"
              and it.closed and len(it.points) == 4]
    offsets = []
    for panel in panels:
        frame = next(f for f in frames
                     if math.isclose(f.points[2][0] - f.points[0][0], panel.width)
                     and math.isclose(f.points[2][1] - f.points[0][1], panel.height))
        frames.remove(frame)
        dx, dy = frame.points[0]
        start = page.items.index(frame) + 1
        for mine, theirs in zip(panel.items, page.items[start:start + len(panel.items)]):
            assert type(mine) is type(theirs)
            if isinstance(mine, Path):
                assert mine.style == theirs.style
                assert all(math.isclose(p[0] + dx, q[0], abs_tol=1e-9)
                           and math.isclose(p[1] + dy, q[1], abs_tol=1e-9)
                           for p, q in zip(mine.points, theirs.points, strict=True))
            elif isinstance(mine, Circle):
                assert mine.radius == theirs.radius
            else:
                assert (mine.text, mine.size, mine.sub) == (theirs.text, theirs.size, theirs.sub)
                assert math.isclose(mine.at[0] + dx, theirs.at[0], abs_tol=1e-9)
        offsets.append((dx, dy))
    return offsets


# ----- panels at true scale ---------------------------------------------------------------
def test_every_panel_is_moved_not_scaled_and_the_space_diagram_leads():
    panels = shaper_panels()
    page = compose_worked_page("Crank shaper: worked solution", panels, TABLE, NOTES)
    offsets = placed(page, panels)
    # The space diagram is at the top left, under the title.
    assert offsets[0] == min(offsets, key=lambda o: (o[1], o[0]))
    assert offsets[0][0] == min(o[0] for o in offsets)
    boxes = [(x, y, x + p.width, y + p.height) for (x, y), p in zip(offsets, panels)]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert not boxes_overlap(a, b)
        assert a[0] >= 0 and a[1] >= 0 and a[2] <= page.width and a[3] <= page.height


def test_the_page_is_a3_landscape_when_the_panels_fit():
    page = compose_worked_page("Crank shaper", shaper_panels(), TABLE, NOTES)
    assert (page.width, page.height) == A3


def test_panels_too_big_for_a3_grow_the_page_and_keep_their_size():
    big = [Figure(300.0, 250.0, [Path(((0.0, 0.0), (300.0, 250.0)), "link")]) for _ in range(3)]
    page = compose_worked_page("Three big panels", big, TABLE)
    offsets = placed(page, big)
    assert page.width >= A3[0] and page.height >= A3[1]
    assert page.width * page.height > A3[0] * A3[1]
    for (x, y), p in zip(offsets, big):
        assert x + p.width <= page.width and y + p.height <= page.height
    boxes = [(x, y, x + 300.0, y + 250.0) for x, y in offsets]
    assert not any(boxes_overlap(a, b) for i, a in enumerate(boxes) for b in boxes[i + 1:])


# ----- the table and the notes ----------------------------------------------------------------
def table_texts(page, panels):
    """The texts the page adds: its title, the table and the notes."""
    own = {(t.text, t.sub) for p in panels for t in p.items if isinstance(t, Text)}
    return [t for t in page.items if isinstance(t, Text) and (t.text, t.sub) not in own]


def test_the_table_reads_as_a_table_under_or_beside_the_last_panel():
    panels = shaper_panels()
    page = compose_worked_page("Crank shaper", panels, TABLE, NOTES)
    texts = table_texts(page, panels)
    header = [t for t in texts if t.text in TABLE[0]]
    assert [t.weight for t in header] == ["bold"] * 4
    assert len({round(t.at[1], 9) for t in header}) == 1
    # Quantities are typeset; numbers flush right under their heading's right end.
    quantities = [(t.text, t.sub) for t in texts if t.italic]
    assert quantities == [("V", "B"), ("ω₄", ""), ("A", "B")]
    for k in (1, 2, 3):
        column = [t for t in texts if t.text in {row[k] for row in TABLE[1:]} | {TABLE[0][k]}]
        ends = {round(t.box()[2], 6) for t in column}
        assert len(ends) == 1, TABLE[0][k]
    assert NOTES[0] in [t.text for t in texts]
    # The table starts no higher than the last panel's top, and overlaps no panel.
    offsets = placed(page, panels)
    panel_boxes = [(x, y, x + p.width, y + p.height) for (x, y), p in zip(offsets, panels)]
    for t in texts[1:]:
        assert t.box()[1] >= offsets[-1][1]
        assert not any(boxes_overlap(t.box(), b) for b in panel_boxes)


def test_no_two_labels_on_the_page_overlap():
    page = compose_worked_page("Crank shaper", shaper_panels(), TABLE, NOTES)
    boxes = [it.box() for it in page.items if isinstance(it, Text)]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert not boxes_overlap(a, b), (a, b)


@pytest.mark.slow
def test_the_same_panels_give_a_byte_identical_page():
    first = to_svg(compose_worked_page("Crank shaper", shaper_panels(), TABLE, NOTES))
    second = to_svg(compose_worked_page("Crank shaper", shaper_panels(), TABLE, NOTES))
    assert first == second


def test_a_page_without_a_table_or_notes_holds_just_the_panels():
    panels = shaper_panels()[:1]
    page = compose_worked_page("Space diagram only", panels, [])
    placed(page, panels)
    assert (page.width, page.height) == A3


# ----- errors --------------------------------------------------------------------------------
def test_a_ragged_table_is_refused_naming_the_row():
    with pytest.raises(TarsimError, match="row 2 of the results table has 3 cells"):
        compose_worked_page("x", shaper_panels()[:1], [*TABLE[:2], ("ω4", "1", "1")])


def test_a_page_without_panels_is_refused():
    with pytest.raises(TarsimError, match="at least one panel"):
        compose_worked_page("x", [], TABLE)
