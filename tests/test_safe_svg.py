"""A student's SVG is bounded and cut down before any geometry is read: ``<use>`` counted
before it is expanded, numbers that are no numbers or beyond any paper left out with a word,
pages of no size refused at their line; what real programs write (clones, symbols, markers,
hidden layers, styles) still read as drawn. Random drawings of every family are graded to
finite numbers or refused in one clear line."""

from __future__ import annotations


import pytest

import tarsim
from tarsim.constructions.errors import InputError
from tarsim.exercises.grading.drawing import parse_drawing
from tarsim.exercises.grading.grade import grade
from tarsim.exercises.grading.matching import MAX_NAMES, NEAREST, _near, match
from tarsim.exercises.grading.polygon import read_label
from tarsim.exercises.grading.report import grade_files
from tarsim.exercises.grading.safe_svg import MAX_DEPTH, MAX_ELEMENTS, reduce_svg
from tarsim.exercises.linkages.solution import solve_positions
from tests.random_drawings import nonfinite_in

SHAPER = tarsim.load("crank-shaper")
POSITIONS = solve_positions(SHAPER)

PAGE = ('<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" '
        'width="210mm" height="297mm" viewBox="0 0 210 297">')
OA = ('<text x="10" y="10">o</text><text x="60" y="10">a</text>'
      '<line x1="10" y1="10" x2="60" y2="10"/>')
"""The pole o and the input's tip a, 50 mm apart (viewBox units are mm here)."""


def graded(tmp_path, body: str, page: str = PAGE):
    """The crank-shaper's first position graded on ``page`` holding o–a and ``body``."""
    path = tmp_path / "s.svg"
    path.write_text(page + OA + body + "</svg>", encoding="utf-8")
    g = grade(SHAPER, path, 0, POSITIONS)
    assert nonfinite_in(grade_files(g)) is None
    return g


# ----- numbers beyond any drawing: left out, and said ----------------------------------------
@pytest.mark.parametrize("body, why", [
    ('<circle cx="5" cy="5" r="1e308"/>', "<circle> at line 1 (r='1e308' is beyond any drawing)"),
    ('<circle cx="nan" cy="5" r="1"/>', "<circle> at line 1 (cx='nan' is not a length)"),
    ('<line x1="0" y1="0" x2="1e400" y2="1"/>',
     "<line> at line 1 (x2='1e400' is beyond any drawing)"),
    ('<path d="M 0 0 L 1e309 10"/>', "<path> at line 1 (d holds 1e309, beyond any drawing)"),
    ('<polyline points="0,0 -1e400,5"/>',
     "<polyline> at line 1 (points holds -1e400, beyond any drawing)"),
    ('<g transform="scale(nan)"><circle cx="1" cy="1" r="1"/></g>',
     "<g> at line 1 (its transform 'scale(nan)' cannot be read)"),
    ('<g transform="matrix(1 0 0 1 nan 0)"><circle cx="1" cy="1" r="1"/></g>',
     "<g> at line 1 (its transform 'matrix(1 0 0 1 nan 0)' cannot be read)"),
    ('<g transform="scale(1e400)"><circle cx="1" cy="1" r="1"/></g>',
     "<g> at line 1 (its transform 'scale(1e400)' cannot be read)"),
    ('<g transform="scale(1e200)"><circle cx="1" cy="1" r="1"/></g>',
     "<g> at line 1 (its transform goes beyond any drawing)"),
    # Thirty groups each scaling by 1e11, each a finite transform; together 1e330, past any
    # float: the circle is found at no finite place and left out.
    ('<g transform="scale(1e11)">' * 30 + '<circle cx="1" cy="1" r="1"/>' + "</g>" * 30,
     "<circle> at line 1 (it lies beyond any paper)"),
    # Three groups of 1e5 put a unit line 1e15 mm out: finite, and beyond any paper (1 km).
    ('<g transform="translate(1e5 0) scale(1e5)">' * 3 + '<line x1="0" y1="0" x2="1" y2="0"/>'
     + "</g>" * 3, "<line> at line 1 (it runs beyond any paper)"),
    ('<text x="1e400" y="3">b</text>', "<text> at line 1 (x='1e400' is beyond any drawing)"),
    ('<text x="5" y="7em">b</text>', "<text> at line 1 (y='7em' is not a length in a fixed "
                                     "unit)"),
    ('<use href="#p" x="1e400"/><line id="p" x1="0" y1="0" x2="1" y2="1"/>',
     "<use> at line 1 (x='1e400' is beyond any drawing)"),
    ('<use href="#p" x="50%"/><line id="p" x1="0" y1="0" x2="1" y2="1"/>',
     "<use> at line 1 (x='50%' is not a length in a fixed unit)"),
])
def test_a_shape_beyond_any_drawing_is_left_out_and_said(tmp_path, body, why):
    g = graded(tmp_path, body)
    assert g.notes[0] == f"left out 1 element: {why}"
    assert next(i for i in g.items if i.name == "a").verdict == "correct"   # o, a still read


def test_a_scale_no_drawing_is_drawn_at_is_said_and_not_held_to(tmp_path):
    """1 cm = 1e-13 m/s would be 1e14 mm a metre a second: it is not held to, and as the
    crank-shaper does not require its own scale, a sets the drawing's and is right."""
    g = graded(tmp_path, '<text x="100" y="100">1 cm = 0.0000000000001 m/s</text>')
    assert "the scale written '1 cm = 0.0000000000001 m/s' is no scale a drawing is drawn " \
           "at, so it was not held to" in g.notes
    assert next(i for i in g.items if i.name == "a").verdict == "correct"


@pytest.mark.parametrize("page, says", [
    ('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 0 0">',
     "s.svg:1: <svg> viewBox='0 0 0 0' gives the page no size; a drawing's viewBox is four "
     "numbers, its width and height above zero"),
    ('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 -10 10">',
     "s.svg:1: <svg> viewBox='0 0 -10 10' gives the page no size; a drawing's viewBox is four "
     "numbers, its width and height above zero"),
    ('<svg xmlns="http://www.w3.org/2000/svg" width="1e400">',
     "s.svg:1: <svg> width='1e400' is no size for a page; export the drawing again"),
    ('<svg xmlns="http://www.w3.org/2000/svg" width="0">',
     "s.svg:1: <svg> width='0' is no size for a page; export the drawing again"),
    ('<svg xmlns="http://example.com/x">',
     "s.svg: not an SVG drawing (its <svg> is of the namespace 'http://example.com/x', not "
     "SVG's)"),
])
def test_a_page_of_no_size_is_refused_at_its_line(page, says):
    with pytest.raises(InputError) as refused:
        parse_drawing((page + OA + "</svg>").encode(), "s.svg")
    assert str(refused.value) == says


# ----- <use> counted before it is expanded -----------------------------------------------------
def doubling(levels: int) -> bytes:
    """l0 holds o, a and their line (4 elements with itself); l(k) holds two <use> of
    l(k-1), so it expands to c_k = 2 (1 + c_(k-1)) + 1 = 7·2^k − 3."""
    groups = ['<g id="l0">' + OA + "</g>"] + [
        f'<g id="l{k}"><use xlink:href="#l{k - 1}"/><use xlink:href="#l{k - 1}"/></g>'
        for k in range(1, levels + 1)]
    return (PAGE + "\n".join(groups) + "</svg>").encode()


@pytest.mark.parametrize("levels", [8, 9, 12, 25])
def test_use_doubling_is_counted_in_closed_form_and_refused_past_the_bound(levels):
    """With the page, levels + 1 groups expand to 1 + Σ c_k = 7 (2^(levels+1) − 1) −
    3 (levels + 1) + 1 elements: read up to MAX_ELEMENTS, refused past it at the line of
    the <use> that expands most (the first of the last group, its own line), counting
    2^25 copies without making one."""
    total = 7 * (2 ** (levels + 1) - 1) - 3 * (levels + 1) + 1
    if total <= MAX_ELEMENTS:
        d = parse_drawing(doubling(levels), "s.svg")
        assert len(d.segments) == 2 ** (levels + 1) - 1     # each group's copies of l0's line
        return
    with pytest.raises(InputError) as refused:
        parse_drawing(doubling(levels), "s.svg")
    said = f"{total:,}" if total < 1e6 else (f"{total / 1e6:.3g} million" if total < 1e9
                                             else f"{total:.2g}")
    assert str(refused.value).startswith(
        f"s.svg:{levels + 1}: its <use> elements expand it to {said} elements, more than a "
        "drawing needs (at most 10,000); this <use> of #l" + str(levels - 1))


@pytest.mark.parametrize("body, line", [
    ('<g id="a">\n<use href="#a"/></g>', 2),
    ('<g id="a"><use href="#b"/></g>\n<g id="b">\n<use href="#a"/></g>', 3),
    ('<defs><symbol id="s">\n<use href="#s" x="1"/></symbol></defs>', 2),
])
def test_a_use_that_loops_is_refused_at_its_line(body, line):
    with pytest.raises(InputError, match=rf"^s.svg:{line}: <use> of #\w refers to an element "
                                         "that holds it: a <use> may not loop$"):
        parse_drawing((PAGE + body + "</svg>").encode(), "s.svg")


def test_nesting_past_the_bound_is_refused_at_its_line():
    body = "\n".join(["<g>"] * (MAX_DEPTH + 5)) + "</g>" * (MAX_DEPTH + 5)
    with pytest.raises(InputError) as refused:
        parse_drawing((PAGE + body + "</svg>").encode(), "s.svg")
    # The page is element 1 on line 1; the g on line k is element k + 1.
    assert str(refused.value) == (f"s.svg:{MAX_DEPTH}: <g> is nested {MAX_DEPTH + 1} deep, "
                                  f"deeper than a drawing's elements go (at most {MAX_DEPTH})")


def test_clones_symbols_markers_and_hidden_layers_are_read_as_drawn():
    """An Inkscape clone (x, y) is its original moved; a symbol is drawn where a <use> puts
    it, not where it is defined; a marker's arrowhead and a hidden layer are not drawn; a
    style block, a script and metadata are left out without a word; a <use> of nothing
    draws nothing."""
    svg = (PAGE + '<defs><marker id="m"><path d="M0,0 L5,2 L0,4 z"/></marker>'
           '<symbol id="s"><line x1="0" y1="0" x2="10" y2="0"/></symbol></defs>'
           '<style>line { stroke: red }</style><script>alert(1)</script><metadata><x/>'
           '</metadata><line id="v" x1="10" y1="10" x2="20" y2="10" marker-end="url(#m)"/>'
           '<use xlink:href="#v" x="5" y="7"/><use href="#s" transform="translate(50 50)"/>'
           '<g style="display:none"><line x1="0" y1="0" x2="99" y2="99"/></g>'
           '<g display="none"><circle cx="1" cy="1" r="1"/></g>'
           '<use href=""/><use href="#nothing"/>'
           '<text x="3" y="4">b<tspan style="baseline-shift:sub">4</tspan></text></svg>')
    d = parse_drawing(svg.encode(), "s.svg")
    ends = sorted((round(a[0], 3), round(a[1], 3), round(b[0], 3), round(b[1], 3))
                  for a, b in d.segments)
    assert ends == [(10, 10, 20, 10), (15, 17, 25, 17), (50, 50, 60, 50)]
    assert d.circles == [] and d.notes == []
    assert [(lb.text, tuple(round(v, 3) for v in lb.at)) for lb in d.labels] == [("b4", (3, 4))]


def test_only_what_grading_reads_reaches_svgelements():
    kept = reduce_svg((PAGE + '<g style="stroke:red" class="x" onclick="f()"><line x1="1" '
                       'y1="2" x2="3" y2="4" stroke="red" data-x="y"/></g></svg>').encode(),
                      "s.svg")
    assert kept.data.decode().split("><")[1:] == [
        'g tarsim-n="1"', 'line tarsim-n="2" x1="1" y1="2" x2="3" y2="4" /', "/g", "/svg>"]


# ----- labels paired in time linear in the drawing ----------------------------------------------
def test_a_label_is_paired_with_its_nearest_points_only():
    """Fifty thousand line ends heaped under one label: it is offered its NEAREST nearest
    (found by sorting, not by trying every pair), the nearest first."""
    from tarsim.exercises.grading.drawing import Label

    points = [(50.0 + k * 1e-4, 50.0) for k in range(50_000)]
    (near,) = _near(points, [Label("b", (50.0, 50.0))]).values()
    assert sorted(near) == list(range(NEAREST))


def test_more_labels_naming_points_than_a_drawing_has_are_refused():
    from tarsim.exercises.grading.drawing import Drawing, Label

    d = Drawing(labels=[Label("b", (k, 0.0)) for k in range(MAX_NAMES + 1)], source="s.svg")
    with pytest.raises(InputError) as refused:
        match(d, read_label)
    assert str(refused.value) == (f"s.svg: {MAX_NAMES + 1} labels name a point, more than a "
                                  f"drawing has (at most {MAX_NAMES}); a page of polygons "
                                  "names some dozens")
