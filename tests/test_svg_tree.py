"""The grading's sheets are drawn with graphics.svg_tree, which writes svgwrite's bytes
with svgwrite's calls; svgwrite, still installed, is the reference it is held to."""

from __future__ import annotations

import svgwrite

from tarsim.graphics.svg_tree import Drawing


def _draw(make) -> str:
    """The same drawing through either module's calls: every element the sheets use,
    keyword attributes with underscores, numbers as floats and ints, text to escape."""
    dwg = make(size=("120mm", "80.5mm"), viewBox="0 0 120 80.5", profile="full",
               debug=False)
    group = dwg.add(dwg.g(stroke="#9e9e9e", stroke_width=0.4315, fill="none", class_="marks"))
    group.add(dwg.path(d="M1.5 2L3 4 M5 6L7.25 8"))
    group.add(dwg.line((1.0, 2.5), (30, 40.125), stroke="#1565c0", stroke_width="0.35"))
    group.add(dwg.circle((10.5, 20.25), 0.6 * 1.7))
    dwg.add(dwg.rect((0, 0), (120, 80.5), fill="#fff"))
    dwg.add(dwg.polygon([(1.0, 2.0), (3.5, 4.0), (5, 6.75)], fill="#c62828", stroke="none"))
    words = dwg.add(dwg.g(font_size=3.2, font_family="DejaVu Sans"))
    words.add(dwg.text("V_B & <a′>", insert=(12.5, 30.0), text_anchor="end"))
    words.add(dwg.text("سرعت", insert=(40, 50.5), direction="rtl"))
    dwg["width"], dwg["direction"] = "130mm", "ltr"
    return dwg.tostring()


def test_a_sheet_is_written_byte_for_byte_as_svgwrite_writes_it():
    assert _draw(Drawing) == _draw(svgwrite.Drawing)


def test_a_drawing_of_no_size_is_as_wide_as_its_page():
    assert Drawing().tostring() == svgwrite.Drawing(profile="full", debug=False).tostring()
