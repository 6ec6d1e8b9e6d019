"""A worked page run on over several sheets (graphics/linkages/worked_page.py): a panel
alone on a run-on sheet is drawn again as big as that sheet holds it, at one of the
course's scales, stated truly; and a right-to-left page sets its panels from the right
margin, as it reads."""

from __future__ import annotations

import re
from dataclasses import replace

import pytest

from tarsim import solve
from tarsim.constructions.narration import speaking
from tarsim.exercises.catalog import load
from tarsim.graphics.figure import Figure, Path
from tarsim.graphics.fitting import DRAFTING
from tarsim.graphics.linkages.worked_page import _draw_results, compose_worked_sheets
from tarsim.graphics.paper import MARGIN, filled

A4 = (210.0, 297.0)
TABLE = [("quantity", "construction"), ("V_B", "1 m/s")]


def square(side: float) -> Figure:
    """A panel ``side`` mm square, its ink its whole box."""
    return Figure(side, side, [Path(((0.0, 0.0), (side, 0.0), (side, side), (0.0, side)),
                                    "link", closed=True)])


def frames(page: Figure) -> list[tuple[float, float, float, float]]:
    """Each panel's frame on ``page``, as (x0, y0, x1, y1) mm."""
    out = []
    for p in page.items:
        if getattr(p, "style", "") == "frame":
            xs, ys = zip(*p.points)
            out.append((min(xs), min(ys), max(xs), max(ys)))
    return out


def grows_to(holds) -> Figure:
    """A square panel grown by 10 mm steps while ``holds`` takes it (a stand-in for a
    panel drawn again at finer scales)."""
    side = 100.0
    while holds(square(side + 10.0)):
        side += 10.0
    return square(side)


def test_a_lone_panel_on_a_run_on_sheet_is_drawn_again_to_fill_it():
    # Two 180 mm panels on A4: each takes a sheet. Before, the second stayed 100 mm
    # square on its sheet (a sixth of its usable area); now it is drawn 180 mm, as the
    # first is, the results table beside or under it.
    sheets = compose_worked_sheets("Two panels", [square(180.0), square(100.0)], TABLE,
                                   sheet=A4, regrow=[None, grows_to])
    assert len(sheets) == 2
    (x0, y0, x1, y1), = frames(sheets[1])
    usable = (sheets[1].width - 2 * MARGIN) * (sheets[1].height - 2 * MARGIN)
    assert x1 - x0 >= 180.0 - 1e-9 and y1 - y0 >= 180.0 - 1e-9
    assert (x1 - x0) * (y1 - y0) / usable >= 0.5
    x0, y0, x1, y1 = sheets[1].bounds()     # and it all stays on its sheet
    assert x0 >= 0.0 and y0 >= 0.0 and x1 <= sheets[1].width and y1 <= sheets[1].height


def test_a_panel_without_a_way_to_be_drawn_again_keeps_its_size():
    sheets = compose_worked_sheets("Two panels", [square(180.0), square(100.0)], TABLE,
                                   sheet=A4)
    (x0, y0, x1, y1), = frames(sheets[1])
    assert (x1 - x0, y1 - y0) == pytest.approx((100.0, 100.0))


@pytest.mark.parametrize("lang, edge", [("en", "left"), ("fa", "right")])
def test_a_right_to_left_page_sets_its_panels_from_the_right_margin(lang, edge):
    # Before, a Persian page mirrored its panels within their own extent, so a narrow
    # run-on panel stood at the left margin, as an English one does.
    with speaking(lang):
        sheets = compose_worked_sheets("Two panels", [square(180.0), square(100.0)], TABLE,
                                       sheet=A4)
    page = sheets[-1]                    # the 100 mm panel alone, the results beside it
    (x0, _, x1, _), = frames(page)
    if edge == "right":
        assert x1 == pytest.approx(page.width - MARGIN)
    else:
        assert x0 == pytest.approx(MARGIN)
    assert x1 - x0 == pytest.approx(100.0)


def test_a_right_to_left_page_reads_its_panels_from_the_right():
    with speaking("fa"):
        page, = compose_worked_sheets("Two panels", [square(60.0), square(40.0)], TABLE,
                                      sheet=A4)
    first, second = frames(page)
    assert first[2] == pytest.approx(page.width - MARGIN)       # the first at the right
    assert second[2] <= first[0] + 1e-9                          # the second to its left


def _acceleration_scale(page: Figure) -> float:
    """The acceleration polygon's stated N of "1 cm = N mm/s²" on ``page``."""
    text = next(t.text for t in page.items if "Acceleration scale" in getattr(t, "text", ""))
    return float(re.search(r"1 cm = ([\d.]+)", text).group(1))


def whitworth(paper: str, lang: str = "en") -> list[Figure]:
    with speaking(lang):
        return solve(replace(load("whitworth"), paper=paper)).figures["worked"].sheets


def test_whitworths_run_on_acceleration_polygon_fills_its_a3_sheet_at_a_true_scale():
    # Before: on A3, the acceleration polygon stood alone on the second sheet at its A4
    # size, 125 × 102 mm, its sheet 0.30 full, at 1 cm = 40 mm/s².
    first, second = whitworth("A3")
    (x0, y0, x1, y1), = frames(second)
    usable = (second.width - 2 * MARGIN) * (second.height - 2 * MARGIN)
    assert (x1 - x0) * (y1 - y0) / usable >= 0.35, (x1 - x0, y1 - y0)
    # a drafting step (1, 2, 2.5, 4, 5 × 10ᵏ), finer than the one the polygon was fitted at
    n = _acceleration_scale(second)
    mantissa = n / 10 ** int(f"{n:e}".split("e")[1])
    assert any(abs(mantissa - d) < 1e-9 for d in DRAFTING), n
    assert n < 40.0
    # stated truly: its paper mm a drawing metre times its stated N is the same on every
    # sheet it is drawn on (10 mm stand for N), here A4's, drawn at a scale of its own
    other = next(s for s in whitworth("A4") if "acceleration" in s.views)
    assert _acceleration_scale(other) != n
    assert second.views["acceleration"].scale * n == pytest.approx(
        other.views["acceleration"].scale * _acceleration_scale(other), rel=1e-9)
    x0, y0, x1, y1 = second.bounds()
    assert x0 >= 0.0 and y0 >= 0.0 and x1 <= second.width and y1 <= second.height


def test_whitworths_persian_run_on_sheet_stands_at_the_right_margin():
    # Before: on A4 its lone polygon and table stood 49 to 177 mm across a 297 mm sheet.
    sheets = whitworth("A4", "fa")
    for page in sheets:
        x1 = max(f[2] for f in frames(page))
        assert x1 == pytest.approx(page.width - MARGIN), (page.width, x1)


def _space_scale(page: Figure) -> float:
    """The space diagram's stated N of "Scale 1 cm = N mm" on ``page``."""
    text = next(t.text for t in page.items if getattr(t, "text", "").startswith("Scale 1 cm"))
    return float(re.search(r"1 cm = ([\d.]+) mm", text).group(1))


def worked(exercise_id: str, paper: str) -> list[Figure]:
    return solve(replace(load(exercise_id), paper=paper)).figures["worked"].sheets


@pytest.mark.parametrize("exercise_id, a4, a3", [("inverted-slider-crank", 40.0, 20.0),
                                                 ("wheel-driven-slider", 50.0, 25.0)])
def test_the_space_diagram_grows_into_the_room_beside_the_velocity_polygon(exercise_id, a4,
                                                                           a3):
    """Each page stays on two A3 sheets, as at 1 cm = 50 mm."""
    # Before, the space diagram kept the scale the solve chose for A4 on an A3 sheet
    # (1 cm = 50 mm: inverted-slider-crank's first A3 sheet 0.44 full): now it is drawn
    # at the finest drafting step at which the first sheet still holds it and the
    # velocity polygon, on no more sheets than before.
    small, big = worked(exercise_id, "A4"), worked(exercise_id, "A3")
    assert (_space_scale(small[0]), _space_scale(big[0])) == (a4, a3)
    assert len(big) == 2 and "velocity" in big[0].views
    # stated truly: paper mm a drawing metre times N is 10 mm, the scale bar's centimetre
    for page in (small[0], big[0]):
        assert page.views["space"].scale * _space_scale(page) / 1000.0 == pytest.approx(10.0)
    first = big[0]
    (x0, y0, x1, y1) = first.bounds()
    assert x0 >= 0.0 and y0 >= 0.0 and x1 <= first.width and y1 <= first.height
    assert filled(first) >= 0.5


def test_a_lone_polygon_is_drawn_bigger_above_a_table_whose_long_words_run_on():
    # Before, the wheel round a circle's acceleration polygon stood at 1 cm = 500 mm/s²,
    # 127 × 106 mm on a landscape sheet, the table under it: its 213 mm ("inspection
    # (rolling contact: the contact point)") is wider than an upright A4 holds (190 mm).
    # Now the table's long words run on over two lines and the polygon is drawn at
    # 1 cm = 200 mm/s² above it, upright: 2.5 times as big, where its short arrows crowd.
    first, second = worked("wheel-round-circle", "A4")
    assert (second.width, second.height) == (210.0, 297.0)
    assert _acceleration_scale(second) == 200.0
    (x0, y0, x1, y1), = frames(second)
    assert (x1 - x0) * (y1 - y0) / ((210.0 - 2 * MARGIN) * (297.0 - 2 * MARGIN)) >= 0.35
    texts = [t for t in second.items if getattr(t, "text", "")]
    broken = [t.text for t in texts if t.text.startswith("inspection (rolling")]
    assert broken == ["inspection (rolling contact: the"]
    assert any(t.text == "contact point)" for t in texts)
    x0, y0, x1, y1 = second.bounds()
    assert x0 >= 0.0 and y0 >= 0.0 and x1 <= second.width and y1 <= second.height


def test_a_narrow_table_keeps_its_numbers_whole():
    # The words of a method run on; a quantity's name and a column of numbers never do,
    # and a run-on row leaves them blank.
    table = [("quantity", "method", "relative error"),
             ("V_B", "inspection (rolling contact: the contact point)", "1.2e-16"),
             ("ω3", "velocity polygon", "4.4e-17")]
    rows: dict[float, list[str]] = {}
    for t in _draw_results(table, (), narrow=True).items:
        if getattr(t, "text", ""):
            rows.setdefault(round(t.at[1], 3), []).append(t.text + (t.sub or ""))
    assert list(rows.values()) == [["quantity", "method", "relative error"],
                                   ["VB", "inspection (rolling contact: the", "1.2e-16"],
                                   ["contact point)"],
                                   ["ω₃", "velocity polygon", "4.4e-17"]]
    wide = _draw_results(table, ())
    assert _draw_results(table, (), narrow=True).width < wide.width


def test_the_crank_shapers_collapsed_polygon_at_90_degrees_is_drawn_upright_and_bigger():
    # Its acceleration polygon lies on one line (θ₂ = 90°), alone on the second sheet,
    # drawn again bigger. A leader to "Aⁿ_A₂ = A_A₂" that ran through its own "= A_A₂"
    # would be one more label over a line than the smaller drawing has, and the sheet
    # would keep the polygon at 1 cm = 20 mm/s², a quarter of a landscape sheet: the
    # leader passes its own name's parts, and the polygon stands upright at 10 mm/s².
    sheets = solve(load("crank-shaper")).figures["worked-theta2-90"].sheets
    second = sheets[1]
    assert (second.width, second.height) == (210.0, 297.0)
    assert _acceleration_scale(second) == 10.0
    (x0, y0, x1, y1), = frames(second)
    assert (y1 - y0) >= 0.8 * (297.0 - 2 * MARGIN)
