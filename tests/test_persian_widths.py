"""A Persian label's estimated width (:attr:`~tarsim.graphics.figure.Text.width`, from
DejaVu Sans's advances) covers what cairo sets: on tarsim's PDF (a glyph at a time, on a
surface in mm) and on cairosvg's PNG at its default 200 dpi, whose glyph advances are
rounded to pixels; so a label placed clear of its neighbours by the estimate is clear on
the page."""

from __future__ import annotations

import io
import re

import pytest

from tarsim import solve
from tarsim.constructions.narration import speaking
from tarsim.exercises.catalog import load
from tarsim.graphics.figure import SUB_SIZE, Text
from tarsim.graphics.rtl import RTL_FONT, is_rtl, visual

cairocffi = pytest.importorskip("cairocffi")

SAMPLE = ("crank-shaper", "wheel-driven-slider", "offset-slider-crank", "rolling-wheel",
          "crank-shaper-forces", "planetary-q1", "inline-four", "offset-knife-edge")
"""Exercises whose Persian figures hold every kind of label: headings with a symbol in a
Persian line, captions, notes, tables, plots."""


def _context(kind: str):
    """A cairo context drawing in mm as tarsim's PDF does, or as cairosvg's PNG at 200 dpi."""
    if kind == "pdf":
        surface = cairocffi.PDFSurface(io.BytesIO(), 595.0, 842.0)
        ctx = cairocffi.Context(surface)
        ctx.scale(72 / 25.4, 72 / 25.4)
    else:
        surface = cairocffi.ImageSurface(cairocffi.FORMAT_ARGB32, 8, 8)
        ctx = cairocffi.Context(surface)
        ctx.scale(200 / 25.4, 200 / 25.4)
    return surface, ctx


def set_width(ctx, t: Text) -> float:
    """How far cairo advances setting ``t`` (its text, subscript and tail) in DejaVu Sans,
    shaped and a glyph at a time, as the PDF and cairosvg set a right-to-left label."""
    total = 0.0
    for part, size in ((t.text, t.size), (t.sub, SUB_SIZE * t.size), (t.tail, t.size)):
        if part:
            ctx.select_font_face(RTL_FONT, 0, 1 if t.weight == "bold" else 0)
            ctx.set_font_size(round(size, 3))
            shaped = visual(part) if is_rtl(part) else part
            # a run of spaces is set as one (graphics/pdf.py, and any SVG viewer)
            total += sum(ctx.text_extents(ch)[4] for ch in re.sub(" +", " ", shaped))
    return total


def persian_labels() -> list[Text]:
    seen: dict[tuple, Text] = {}
    for exercise_id in SAMPLE:
        with speaking("fa"):
            done = solve(load(exercise_id))
            figures = done.sheets() if hasattr(done, "sheets") else done.figures
            for fig in figures.values():
                for sheet in fig.sheets or [fig]:
                    for t in sheet.items:
                        if isinstance(t, Text) and is_rtl(t.text + t.sub + t.tail):
                            seen[(t.text, t.sub, t.tail, t.size, t.weight)] = t
    return list(seen.values())


@pytest.mark.slow
@pytest.mark.parametrize("kind, pixel, share", [("pdf", 0.01, 0.0), ("png", 0.127, 0.005)])
def test_a_persian_labels_estimate_covers_what_cairo_sets(kind, pixel, share):
    # Today a heading with a Latin name in a Persian line ("…: V_A به روش", bold) was
    # estimated in the Latin serif's widths though it is set in DejaVu Sans Bold: 1.2 mm
    # short on the PDF; and a long note 3.5 mm short on the 200 dpi PNG. Slack: the PDF
    # sets the advances themselves (0.01 mm: float noise); the PNG rounds each glyph to a
    # pixel (0.127 mm at 200 dpi), a line of Persian digits 2.5 % up, where the estimate
    # allows 2 %: a pixel and half a percent.
    _, ctx = _context(kind)
    labels = persian_labels()
    assert len(labels) > 400
    short = [(round(set_width(ctx, t) - t.width, 2), t.text, t.sub, t.tail) for t in labels
             if set_width(ctx, t) > t.width * (1 + share) + pixel]
    assert not short, sorted(short, reverse=True)[:5]


def test_a_heading_with_a_symbol_in_a_persian_line_is_measured_in_the_face_it_is_set_in():
    _, ctx = _context("pdf")
    heading = Text((0.0, 0.0), "whose end slides on the floor: V", 3.6, weight="bold",
                   sub="A", tail=" به روش")
    assert heading.width >= set_width(ctx, heading)
    # and not much more: the allowance is for the PNG's pixels, 2 %
    assert heading.width <= set_width(ctx, heading) * 1.025
