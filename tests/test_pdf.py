"""A figure's PDF is drawn with cairo straight from the figure (graphics/pdf.py), not
converted from its SVG by cairosvg; it must print as cairosvg prints that SVG.

Both PDFs are read back as a reader's viewer reads them, through a third renderer
(PDFium), one sheet at a time:
- every line, circle, fill and hatch: the sheet without its texts, rendered at 6 px/mm.
  The two routes issue the same cairo path operators, so the pixels are identical (on all
  232 sheets and plots of the bundled exercises, English and Persian, at 8 px/mm,
  the largest difference was 0); 16 of 255 leaves room for an antialiasing step and no more.
- every letter: the same letters in the same order, each within 0.01 mm of where
  cairosvg sets it. PDFium reports positions to about 0.005 mm; a line set as one run of
  glyphs drifts by up to 0.05 mm (a PDF places a run by its font's widths in whole
  thousandths of an em), which this catches.
Spaces are left out of the letters: cairosvg skips them, and PDFium invents some.
"""

from __future__ import annotations

import datetime
import io
import time
from dataclasses import dataclass
from importlib.util import find_spec

import numpy as np
import pytest

from tarsim.constructions.narration import speaking
from tarsim.graphics.export import figure_pdf, svg_to
from tarsim.graphics.figure import Figure, Text
from tarsim.graphics.svg import to_svg

_PT_PER_MM = 72 / 25.4

pytestmark = pytest.mark.skipif(
    find_spec("pypdfium2") is None or find_spec("cairosvg") is None,
    reason="reading PDFs back needs pypdfium2 and cairosvg (the test extra)")


def _document(pdf: bytes):
    import pypdfium2

    return pypdfium2.PdfDocument(pdf)


def _pixels(pdf: bytes) -> np.ndarray:
    page = _document(pdf)[0]
    return np.asarray(page.render(scale=6 / _PT_PER_MM, grayscale=True).to_pil().convert("L"),
                      dtype=int)


def _letters(pdf: bytes) -> list[tuple[str, float, float]]:
    """Each letter on the page and the left and bottom of its box (mm)."""
    text = _document(pdf)[0].get_textpage()
    out = []
    for i in range(text.count_chars()):
        letter = text.get_text_range(i, 1)
        if not letter.isspace():
            left, bottom, _, _ = text.get_charbox(i)
            out.append((letter, left / _PT_PER_MM, bottom / _PT_PER_MM))
    return out


@dataclass
class _Apart:
    """How far our PDF of a sheet prints from cairosvg's PDF of its SVG."""

    pixels: int
    """The largest grey-level difference with the texts left out."""
    same_letters: bool
    """The same letters, in the same order."""
    letters: int
    letter_mm: float
    """The largest distance between a letter and its counterpart (mm)."""


def _apart(sheet: Figure) -> _Apart:
    bare = Figure(sheet.width, sheet.height, [i for i in sheet.items if not isinstance(i, Text)])
    lines = np.abs(_pixels(svg_to(to_svg(bare), "pdf")) - _pixels(figure_pdf([bare])))
    theirs, ours = _letters(svg_to(to_svg(sheet), "pdf")), _letters(figure_pdf([sheet]))
    same = [c for c, _, _ in ours] == [c for c, _, _ in theirs]
    far = max((max(abs(a[1] - b[1]), abs(a[2] - b[2])) for a, b in zip(theirs, ours)),
              default=0.0)
    return _Apart(int(lines.max()), same, len(theirs), far)


def _sheets(exercise_id: str, lang: str, stems: set[str] | None) -> list[Figure]:
    """The sheets of an exercise's figures (those of ``stems``, or all): a linkage's
    pages, or a chapter's figures."""
    import tarsim

    with speaking(lang):
        solved = tarsim.solve(tarsim.load(exercise_id))
        drawn = ({p.stem: p.figure for p in solved.pages} if hasattr(solved, "pages")
                 else dict(solved.figures))
    return [sheet for stem, fig in drawn.items() if stems is None or stem in stems
            for sheet in (fig.sheets or [fig])]


@pytest.mark.slow
@pytest.mark.parametrize("exercise_id, lang, stems", [
    # the worked page on three sheets, the circle diagram, velocities by centres and by
    # components; long right-to-left lines with Latin in them; loads and force polygons;
    # a gear train, a cam and a rotor's balancing
    ("crank-shaper", "en", {"circle-diagram-theta2-90", "worked-theta2-90"}),
    ("hinkle-four-bar", "en", {"V_B-parallel-line", "V_D-components"}),
    ("crank-shaper", "fa", {"limits"}),
    ("four-bar-forces", "fa", None),
    ("planetary-q4", "en", None),
    ("oscillating-roller", "en", None),
    ("four-mass-shaft", "en", None),
])
def test_a_figure_prints_as_its_svg_does(exercise_id, lang, stems):
    sheets = _sheets(exercise_id, lang, stems)
    assert sheets
    for sheet in sheets:
        apart = _apart(sheet)
        assert apart.pixels <= 16, sheet.title
        assert apart.same_letters and apart.letters, sheet.title
        assert apart.letter_mm <= 0.01, sheet.title


def test_a_figures_sheets_are_its_pdfs_pages_each_at_its_own_size():
    big, small = Figure(300.0, 210.0, title="one"), Figure(100.0, 50.0, title="two")
    big.add(Text((150.0, 100.0), "A", anchor="middle"))
    small.add(Text((50.0, 25.0), "B", anchor="middle"))
    doc = _document(figure_pdf([big, small]))
    assert [tuple(round(v / _PT_PER_MM, 3) for v in page.get_size()) for page in doc] == [
        (300.0, 210.0), (100.0, 50.0)]
    assert [page.get_textpage().get_text_range() for page in doc] == ["A", "B"]


def test_spaces_print_as_an_svg_viewer_keeps_them():
    """A run of spaces prints as one, and a space opening a text not at all: the SVG a
    browser shows and the PDF must read alike ("θ₂ = 90°,  ω₂" was once set wider)."""
    fig = Figure(120.0, 20.0)
    fig.add(Text((10.0, 10.0), "  a,   b", anchor="start", italic=False))
    theirs, ours = _letters(svg_to(to_svg(fig), "pdf")), _letters(figure_pdf([fig]))
    assert [c for c, _, _ in ours] == ["a", ",", "b"]
    assert [round(x, 2) for _, x, _ in ours] == [round(x, 2) for _, x, _ in theirs]


def test_a_circle_of_no_radius_and_a_path_of_no_length_print_nothing():
    """As cairosvg prints them: a round cap would otherwise make a dot of each."""
    from tarsim.graphics.figure import Circle, Path

    fig = Figure(40.0, 20.0)
    fig.add(Circle((10.0, 10.0), 0.0, "pin"))
    fig.add(Path((), "link"))
    fig.add(Path(((30.0, 10.0),), "link"))
    assert _pixels(figure_pdf([fig])).min() == 255
    assert _pixels(svg_to(to_svg(fig), "pdf")).min() == 255


# ----- the same input, the same bytes -----------------------------------------------------------
def _both_routes() -> dict[str, bytes]:
    """A small figure with letters (so fonts are embedded) as each route prints it."""
    fig = Figure(60.0, 30.0, title="dated")
    fig.add(Text((30.0, 15.0), "θ2 = 90°, ω2", anchor="middle"))
    return {"cairo": figure_pdf([fig]), "cairosvg": svg_to(to_svg(fig), "pdf")}


def _metadata(pdf: bytes):
    import pypdf

    return pypdf.PdfReader(io.BytesIO(pdf)).metadata


def test_the_same_figure_gives_the_same_pdf_at_another_time(monkeypatch):
    """cairo dates a document by the clock, to the second: made again over a second
    later, the PDF differed. Undated (no SOURCE_DATE_EPOCH), it is the same to the byte."""
    monkeypatch.delenv("SOURCE_DATE_EPOCH", raising=False)
    first = _both_routes()
    time.sleep(1.1)
    assert _both_routes() == first
    assert all("/CreationDate" not in _metadata(pdf) for pdf in first.values())


def test_source_date_epoch_dates_the_pdf(monkeypatch):
    """As reproducible builds ask: 1,700,000,000 s after 1970 is 19,675 days and 80,000 s,
    2023-11-14 at 22:13:20 UTC."""
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    for pdf in _both_routes().values():
        assert _metadata(pdf).creation_date == datetime.datetime(
            2023, 11, 14, 22, 13, 20, tzinfo=datetime.timezone.utc)


@pytest.mark.parametrize("epoch", ["yesterday", "-5", "1.5e9", "99999999999999999999"])
def test_a_source_date_epoch_that_is_no_time_is_refused_in_one_line(monkeypatch, epoch):
    from tarsim.graphics.export import RenderError

    monkeypatch.setenv("SOURCE_DATE_EPOCH", epoch)
    for route in (lambda: figure_pdf([Figure(10.0, 10.0)]),
                  lambda: svg_to(to_svg(Figure(10.0, 10.0)), "pdf")):
        with pytest.raises(RenderError) as info:
            route()
        assert str(info.value) == (f"SOURCE_DATE_EPOCH is {epoch!r}, not a whole number of "
                                   "seconds since 1970: set it so, or unset it")


@pytest.mark.slow
def test_the_same_solve_writes_the_same_pdfs_a_second_later(tmp_path, monkeypatch):
    """`tarsim solve` twice, over a second apart: every file, its PDFs (each figure's and
    solution.pdf) too, the same to the byte."""
    from click.testing import CliRunner

    from tarsim.exercises.cli import cli

    monkeypatch.delenv("SOURCE_DATE_EPOCH", raising=False)
    for out in ("first", "second"):
        result = CliRunner().invoke(cli, ["solve", "four-bar", "-o", str(tmp_path / out)])
        assert result.exit_code == 0, result.output
        time.sleep(1.1)
    first, second = ({p.name: p.read_bytes() for p in (tmp_path / out).iterdir()}
                     for out in ("first", "second"))
    assert "solution.pdf" in first and "centres.pdf" in first
    assert first == second
