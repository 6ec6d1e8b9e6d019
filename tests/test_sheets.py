"""Every page a standard sheet: each bundled exercise's every figure, in English and in
Persian, is set on A4 (or the smallest standard sheet that holds a scale the exercise
states), with all its ink on it; a caption or a page's title is wrapped to its sheet, never
inside a formula; a worked page's results table stands beside a figure where one fits."""

from __future__ import annotations

import re
from dataclasses import replace

import pytest

from tarsim import solve
from tarsim.constructions.narration import speaking
from tarsim.exercises.catalog import everything, load
from tarsim.graphics.figure import Figure, Text
from tarsim.graphics.paper import PAPERS, grown, on_sheet, sheet_name, standard
from tarsim.graphics.wrapping import wrap_formulas

STANDARD = {(s.width, s.height) for s in PAPERS.values()} | {
    (s.height, s.width) for s in PAPERS.values()}


def pages(exercise_id: str, lang: str, paper: str = "A4") -> dict[str, list[Figure]]:
    """Each figure's sheets, as its SVG and PDF print them."""
    with speaking(lang):
        done = solve(replace(load(exercise_id), paper=paper) if paper != "A4"
                     else load(exercise_id))
        figures = done.sheets() if hasattr(done, "sheets") else done.figures
        return {stem: fig.sheets or [fig] for stem, fig in figures.items()}


@pytest.mark.slow
@pytest.mark.parametrize("lang", ["en", "fa"])
def test_every_bundled_page_is_a_standard_sheet_with_its_ink_on_it(lang):
    wrong = []
    for exercise_id in everything():
        for stem, sheets in pages(exercise_id, lang).items():
            for k, s in enumerate(sheets):
                x0, y0, x1, y1 = s.bounds()
                # 0.05 mm: a stroke's half width may touch the sheet's edge, no more
                inside = x0 >= -0.05 and y0 >= -0.05 and x1 <= s.width + 0.05 and \
                    y1 <= s.height + 0.05
                if (round(s.width, 1), round(s.height, 1)) not in STANDARD or not inside:
                    wrong.append((exercise_id, stem, k, s.width, s.height,
                                  tuple(round(v, 1) for v in (x0, y0, x1, y1))))
    assert not wrong, wrong


@pytest.mark.parametrize("lang", ["en", "fa"])
def test_the_crank_shapers_worked_page_keeps_its_long_captions_within_a4(lang):
    # Its space diagram's caption ran to 262 mm, and the page to 298.7 × 210 mm: past A4.
    for stem in ("worked-t-2.34s", "centres-t-2.34s", "V_B-radius-rotation-t-2.34s"):
        sheets = pages("crank-shaper", lang)[stem]
        for s in sheets:
            assert sorted((s.width, s.height)) == [210.0, 297.0], (stem, s.width, s.height)
            x0, y0, x1, y1 = s.bounds()
            assert x0 >= 0 and y0 >= 0 and x1 <= s.width and y1 <= s.height, stem
        # the stated scale is kept: the space diagram's caption says so
        assert any("7 cm = 500 mm" in t.text or "۷" in t.text for t in sheets[0].items
                   if isinstance(t, Text)), stem


def _sheets_holding_the_table(sheets: list[Figure]) -> list[tuple[int, int]]:
    """(sheet, panels framed on it) for each sheet with the results table's header."""
    return [(k, sum(getattr(it, "style", "") == "frame" for it in s.items))
            for k, s in enumerate(sheets)
            if any(isinstance(t, Text) and t.weight == "bold" and t.text in ("quantity", "کمیت")
                   for t in s.items)]


@pytest.mark.parametrize("paper", ["A4", "A3"])
def test_whitworths_results_table_stands_beside_a_figure(paper):
    # Today the table stands alone on the second sheet, on A4 and on A3.
    sheets = pages("whitworth", "en", paper)["worked"]
    (held,) = _sheets_holding_the_table(sheets)
    assert held[1] >= 1, held
    assert all(sorted((s.width, s.height)) == sorted((PAPERS[paper].width, PAPERS[paper].height))
               for s in sheets)


def test_a_figure_no_sheet_of_its_paper_holds_is_set_on_the_next_standard_sheet():
    fig = Figure(228.3, 236.4, [Text((114.15, 118.2), "x")])     # the size the issue saw
    assert grown(fig, PAPERS["A4"]).name == "A3"
    placed = on_sheet(fig, PAPERS["A4"])
    assert (placed.width, placed.height) == (297.0, 420.0)
    assert placed.items[0].at == pytest.approx((148.5, 210.0))       # centred
    assert standard(298.7, 210.0, PAPERS["A4"]) == (420.0, 297.0)
    assert sheet_name(297.0, 420.0) == "A3" and sheet_name(594.0, 420.0) == "A2"
    assert grown(Figure(270.0, 420.0), PAPERS["letter"]).name == "tabloid"


def test_a_formula_is_never_broken_across_lines():
    text = "Crank-shaper quick-return mechanism: space diagram at t = 2.34 s (θ2 = −44.0721°)"
    for width in (40.0, 60.0, 90.0, 120.0):
        lines = wrap_formulas(text, 3.6, width)
        assert " ".join(lines) == text
        assert any("t = 2.34 s" in line for line in lines), lines
        assert any("(θ2 = −44.0721°)" in line for line in lines), lines


_LATIN_NUMBER = re.compile(r"(?<![\w.])[0-9]")
"""A Latin digit opening a number, not a name's ("θ2", "O2A" and "I13" keep theirs)."""


@pytest.mark.parametrize("stem", ["worked-t-2.34s", "centres-t-2.34s",
                                  "V_B-radius-rotation-t-2.34s"])
def test_a_persian_figures_titles_and_captions_use_its_tables_digits(stem):
    # Today: "t = 2.34 s (θ2 = −44.0721°)" in the title and the caption of a figure whose
    # table reads "۱۸۹٫۲".
    (first, *_) = pages("crank-shaper", "fa")[stem]
    said = [t for t in first.items if isinstance(t, Text)
            and (t.weight == "bold" or t.size == 3.2) and " = " in t.text]
    assert said
    latin = [t.text for t in said if _LATIN_NUMBER.search(t.text + t.tail)]
    assert not latin, latin
    assert any("۲٫۳۴" in t.text or "۴۴٫۰۷۲۱" in t.text for t in said)
    # and English keeps its own
    (en, *_) = pages("crank-shaper", "en")[stem]
    assert any("2.34" in t.text or "44.0721" in t.text for t in en.items if isinstance(t, Text))
