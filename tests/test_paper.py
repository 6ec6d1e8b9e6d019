"""Every figure is set on one sheet of the paper asked for (A4 by default), upright or on its
side, at a nice scale that fills it; a worked page one sheet cannot hold runs on over more,
a page each in its PDF. Only a figure drawn at a scale the exercise states may need more
than its sheet, and the solve says so."""

from __future__ import annotations

import re
from dataclasses import replace

import pytest

from tarsim.constructions.errors import InputError
from tarsim.exercises.catalog import bundled, load
from tarsim.exercises.linkages.solution_files import solve_worked
from tarsim.graphics.figure import Figure, Text
from tarsim.graphics.paper import PAPERS, on_sheet, paper
from tests.test_cli import run

STATES_ITS_SCALE = {"crank-shaper"}          # "7 cm = 500 mm": kept, whatever the sheet


def sheets(fig: Figure) -> list[Figure]:
    return fig.sheets or [fig]


@pytest.mark.slow
@pytest.mark.parametrize("exercise_id", sorted(bundled()))
def test_every_figure_is_a_sheet_of_a4_unless_its_scale_is_stated(solved, exercise_id):
    worked = solved(exercise_id)
    a4 = {(210.0, 297.0), (297.0, 210.0)}
    for f in worked.pages:
        for s in sheets(f.figure):
            size = (round(s.width, 1), round(s.height, 1))
            if exercise_id in STATES_ITS_SCALE and size not in a4:
                assert f.stem in worked.oversize()        # said, not hidden
                continue
            assert size in a4, (f.stem, size)
            x0, y0, x1, y1 = s.bounds()
            assert x0 >= 0 and y0 >= 0 and x1 <= s.width and y1 <= s.height, f.stem


@pytest.mark.slow
def test_on_a3_even_the_stated_scale_fits_and_the_centres_are_drawn_bigger(solved):
    a4 = solved("four-bar")
    a3 = solve_worked(replace(load("four-bar"), paper="A3"))
    assert a3.oversize() == {}
    assert {(s.width, s.height) for f in a3.pages for s in sheets(f.figure)} <= \
        {(297.0, 420.0), (420.0, 297.0)}
    shaper = solve_worked(replace(load("crank-shaper"), paper="A3"))
    assert shaper.oversize() == {}

    def per_cm(fig: Figure) -> float:
        (n,) = [float(m.group(1)) for t in fig.items if isinstance(t, Text)
                for m in [re.fullmatch(r"Scale 1 cm = ([\d.]+) mm", t.text)] if m]
        return n
    # A bigger sheet draws the same mechanism at a finer nice scale (fewer mm per cm).
    assert per_cm(a3.figures["centres"]) < per_cm(a4.figures["centres"])


@pytest.mark.slow
def test_a_worked_page_too_big_for_a4_runs_on_over_sheets_a_pdf_page_each(solved, tmp_path):
    pypdf = pytest.importorskip("pypdf")
    from tarsim.graphics.export import cairo_missing
    if cairo_missing():
        pytest.skip("PDF needs libcairo2")
    worked = solved("whitworth")
    page = worked.figures["worked"]
    assert len(page.sheets) >= 2
    texts = [t.text for s in page.sheets for t in s.items if isinstance(t, Text)]
    assert sum("(continued)" in t for t in texts) == len(page.sheets) - 1
    worked.write(tmp_path / "w")
    pdf = pypdf.PdfReader(tmp_path / "w" / "worked.pdf")
    assert len(pdf.pages) == len(page.sheets)
    for p in pdf.pages:            # PDF points: 72 to the inch
        size = sorted(round(float(v) / 72 * 25.4) for v in (p.mediabox.width, p.mediabox.height))
        assert size == [210, 297]


def test_a_figure_is_centred_on_the_sheet_that_holds_it():
    fig = Figure(250.0, 100.0, [Text((125.0, 50.0), "x")])
    placed = on_sheet(fig, PAPERS["A4"])
    assert (placed.width, placed.height) == (297.0, 210.0)      # wide: on its side
    assert placed.items[0].at == pytest.approx((148.5, 105.0))
    big = on_sheet(Figure(300.0, 300.0, [Text((150.0, 150.0), "x")]), PAPERS["A4"])
    # Never shrunk: set on the smallest standard sheet that holds it (A3 is 297 mm wide).
    assert (big.width, big.height) == (420.0, 594.0)
    assert big.items[0].at == pytest.approx((210.0, 297.0))


def test_an_unknown_paper_is_refused_naming_those_there_are():
    with pytest.raises(InputError, match="unknown paper 'B5'; choose one of A4, A3, letter"):
        paper("B5")
    result = run("solve", "four-bar", "--paper", "B5", "--no-pdf")
    assert result.exit_code == 2 and "Traceback" not in result.output
    assert "'B5' is not one of" in result.output


def test_solve_says_which_figure_its_stated_scale_puts_on_a_bigger_sheet(tmp_path):
    # The crank-shaper at twice the books' scale (14 cm = 500 mm): its drawing, some
    # 150 × 340 mm, no A4 sheet holds, either way up; an A3 sheet does.
    text = (bundled()["crank-shaper"].read_text(encoding="utf-8")
            .replace('"7 cm = 500 mm"', '"14 cm = 500 mm"'))
    (tmp_path / "big.toml").write_text(text, encoding="utf-8")
    result = run("solve", tmp_path / "big.toml", "-o", tmp_path / "cs", "--no-pdf")
    assert result.exit_code == 0, result.output
    assert re.search(r"note: centres-t-2\.34s at the exercise's scale is more than A4 holds: "
                     r"it is set on A3 \(297 × 420 mm\)", result.output), result.output
    svg = (tmp_path / "cs" / "centres-t-2.34s.svg").read_text(encoding="utf-8")
    assert 'width="297mm" height="420mm"' in svg or 'height="420mm"' in svg
