"""Persian in the figures: the SVG keeps its text in logical order for a browser to shape;
the copy cairosvg draws a PDF or PNG from is shaped and in visual order, numbers unreversed.
"""

from __future__ import annotations

import io

import arabic_reshaper
import pytest

from tarsim.graphics.export import svg_to
from tarsim.graphics.figure import Figure, Text
from tarsim.graphics.rtl import for_cairo, is_rtl, visual
from tarsim.graphics.svg import to_svg

SCALE = "مقیاس سرعت ۱ سانتی\u200cمتر = ۶۰ میلی\u200cمتر بر ثانیه"


def _figure() -> Figure:
    fig = Figure(120.0, 40.0)
    fig.add(Text((10.0, 10.0), SCALE, 4.0, "start", False))
    fig.add(Text((10.0, 25.0), "V", 4.0, "start", True, sub="B"))
    return fig


def test_the_svg_keeps_persian_in_logical_order_for_the_browser():
    svg = to_svg(_figure())
    assert SCALE in svg                                 # not shaped, not reversed
    assert 'direction="rtl"' in svg and 'font-family="DejaVu Sans"' in svg
    assert 'text-anchor="end"' in svg                   # its box stays where it was laid
    assert svg.count('direction="rtl"') == 1            # the Latin label is left alone


@pytest.mark.parametrize("text, number", [(SCALE, "۶۰"), ("طول ۲۵ میلی\u200cمتر", "۲۵"),
                                          ("نسبت زمانی ۱٫۶۱۲۵", "۱٫۶۱۲۵")])
def test_cairosvg_gets_joined_letters_in_visual_order_and_numbers_unreversed(text, number):
    shown = visual(text)
    assert number in shown and number[::-1] not in shown.replace(number, "")
    words = [w for w in text.replace("\u200c", " ").split()
             if is_rtl(w) and not set(w) <= set("۰۱۲۳۴۵۶۷۸۹٫")]
    for w in words:            # each word's joined forms, laid right to left
        assert arabic_reshaper.reshape(w)[::-1] in shown.replace("\u200c", "") or \
            len(w) == 1, w
    cairo = for_cairo(to_svg(_figure()))
    assert visual(SCALE) in cairo and SCALE not in cairo
    assert 'direction="rtl"' not in cairo and 'text-anchor="start"' in cairo


def test_a_persian_figure_converts_to_pdf_and_png():
    pytest.importorskip("cairosvg")
    from pypdf import PdfReader

    svg = to_svg(_figure())
    pdf = svg_to(svg, "pdf")
    text = PdfReader(io.BytesIO(pdf)).pages[0].extract_text()
    # The PDF's text layer holds the joined presentation forms, not the bare letters.
    assert "\ufee3\ufed8\ufbff\ufe8e\ufeb1" in text or "ﻣﻘﯿﺎﺱ" in text
    assert svg_to(svg, "png").startswith(b"\x89PNG")
