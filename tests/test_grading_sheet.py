"""Grading a whole sheet as a course marks one: the space diagram beside the polygons,
tarsim's own notation, construction points, one tolerance for drawings and tables, and a
drawing of another position than the one asked.

Drawings are tarsim's polygons and space diagram (tests/drawings.py), laid out on one
sheet; the tolerances asserted are worked from the drafting rule itself, a 0.5 mm pen and
a 0.5° set square over a vector drawn at the exercise's scale.
"""

from __future__ import annotations

import json
import math
import re

import pytest

import tarsim
from tarsim.exercises.grading.drafting import DRAFTING, tolerance
from tarsim.exercises.grading.grade import grade
from tarsim.exercises.grading.labels import read_names, read_centre
from tarsim.exercises.linkages.solution import solve_positions
from tests.drawings import Style, centres_drawing, drawing

FOUR_BAR = tarsim.load("four-bar")
SHAPER = tarsim.load("crank-shaper")


def _body(svg: str) -> str:
    """The marks of one of tests/drawings.py's Inkscape pages."""
    return svg.split('<g transform="matrix(1,0,0,1,0,0)">', 1)[1].rsplit("</g></g></svg>", 1)[0]


def _sheet(*parts: tuple[str, float], extra: str = "") -> str:
    """Pages laid one under another (each moved down by its offset, mm) on one sheet."""
    body = "".join(f'<g transform="translate(0,{dy})">{_body(svg)}</g>' for svg, dy in parts)
    return ('<svg xmlns="http://www.w3.org/2000/svg" width="210mm" height="600mm" '
            f'viewBox="0 0 210 600">{body}{extra}</svg>')


def _graded(tmp_path, svg: str, ex, position: int = 0):
    path = tmp_path / "sheet.svg"
    path.write_text(svg, encoding="utf-8")
    g = grade(ex, path, position)
    return g, {i.name: i for i in g.items}


@pytest.mark.parametrize("text, read", [
    ("a₂ ≡ a₄", ("v", ("a2", "a4"))), ("o_a ≡ b₅′", ("a", ("o", "b5"))),
    ("a′₄", ("a", ("a4",))), ("a₄′", ("a", ("a4",))), ("a_{4}'", ("a", ("a4",))),
    ("o<v", None), ("I13", None), ("V_B5 = V_B4", None), ("a''", None)])
def test_tarsims_notation_and_a_prime_either_side_of_the_subscript_are_read(text, read):
    assert read_names(text) == read


@pytest.mark.parametrize("text, centre", [("I13", "I13"), ("31", "I13"), ("I₂₄", "I24"),
                                          ("40", None), ("11", None), ("I1", None)])
def test_a_centre_is_two_links_counted_from_one(text, centre):
    assert read_centre(text) == centre


def test_the_space_diagram_beside_the_polygon_is_told_from_it(tmp_path):
    """A, B, O2, O4 and the centres on the space diagram; a, b, o on the polygon below it:
    every tip and every finite centre right, none of the diagram's points taken for a tip."""
    sol = solve_positions(FOUR_BAR)[0]
    svg = _sheet((centres_drawing(sol), 0.0), (drawing(sol, Style()), 120.0))
    g, items = _graded(tmp_path, svg, FOUR_BAR)
    centres = [n for n in items if n.startswith("I")]
    assert {"a", "b"} <= set(items) and len(centres) >= 5
    assert {i.verdict for i in g.items} == {"correct"}, g.items


@pytest.mark.parametrize("anchor", ["start", "end"])
@pytest.mark.parametrize("run_on", [(), (1, 2)])
def test_a_results_tables_column_is_no_label_of_the_sheet(tmp_path, anchor, run_on):
    """A results table beside the drawing lists I₁₂, ω₃, I₁₃, … one under another at a
    steady pitch, flush left as an English page sets it or flush right (text-anchor end) as
    a right-to-left one does, where names of different widths start at different places:
    neither column is read as the space diagram's centres, so every centre is still graded
    from the diagram and nothing is said to be near no point. A row whose words run on
    over a second line (``run_on``: the rows after which the next stands two pitches
    down; the narrow table of a lone polygon's sheet) leaves its column a table's still."""
    sol = solve_positions(FOUR_BAR)[0]
    names = ["I₁₂", "ω₃", "I₁₃", "ω₄", "I₂₃", "α₃", "I₂₄", "α₄"]
    rows = [k + sum(1 for r in run_on if r < k) for k in range(len(names))]
    table = "".join(f'<text x="200" y="{300 + 5.6 * row:.2f}" font-size="3.2" '
                    f'text-anchor="{anchor}">{name}</text>' for row, name in zip(rows, names))
    svg = _sheet((centres_drawing(sol), 0.0), (drawing(sol, Style()), 120.0), extra=table)
    g, items = _graded(tmp_path, svg, FOUR_BAR)
    assert len([n for n in items if n.startswith("I")]) >= 5
    assert {i.verdict for i in g.items} == {"correct"}, g.items
    assert not [n for n in g.notes if "near no" in n], g.notes


def test_construction_points_are_said_and_cost_nothing(tmp_path):
    """n and x, labelled where a student marks where two construction lines cross, are no
    answer: the grade says it took them for construction points and the score stays."""
    sol = solve_positions(FOUR_BAR)[0]
    extra = ('<line x1="150" y1="60" x2="170" y2="60" stroke="#000"/>'
             '<text x="171" y="59" style="font-size:4px">n</text>'
             '<line x1="150" y1="80" x2="170" y2="80" stroke="#000"/>'
             '<text x="171" y="79" style="font-size:4px">x</text>')
    g, _ = _graded(tmp_path, _sheet((drawing(sol, Style()), 0.0), extra=extra), FOUR_BAR)
    assert g.score == 100.0
    assert any(re.search(r"construction points.*: n, x$", n) for n in g.notes), g.notes


def test_a_table_and_a_drawing_are_held_to_one_tolerance(tmp_path):
    """V_B in a table is held to what the tip b is on a drawing: the band of each line b is
    cut from (the pen and the set square across it), their parallelogram's far corner, in
    m/s. The drawing at 400 mm per m/s and the table at the exercise's scale give one
    tolerance in m/s; it is at least the pen's and within the pen and set square over the
    lines' crossing."""
    from tarsim.constructions.linkages.velocity_polygon import drawn_velocity_polygon

    sol = solve_positions(FOUR_BAR)[0]
    g, items = _graded(tmp_path, drawing(sol, Style(scale=400.0)), FOUR_BAR)
    path = tmp_path / "answers.json"
    path.write_text(json.dumps({"V_B": sol.quantities["V_B"].reference["value"]}),
                    encoding="utf-8")
    table = {i.name: i for i in grade(FOUR_BAR, path, 0).items}
    assert items["b"].tolerance / 400.0 == pytest.approx(table["V_B"].tolerance, rel=2e-3)
    # The four-bar states no polygon scale: its longest tip is drawn 100 mm long.
    vp = drawn_velocity_polygon(sol.work)
    scale = 100.0 / max(math.hypot(*vp.vector(n)) for n in vp.tips)     # mm per m/s
    c = vp.construction
    lines = [c[r] for r in c[vp.tips["B"]].inputs]
    (d1, d2) = (ln.output.direction for ln in lines)
    crossing = abs(d1[0] * d2[1] - d1[1] * d2[0])              # sin of the lines' angle
    # Each band is at most the pen and the set square over two polygon widths (200 mm),
    # over its line's conditioning; their parallelogram's corner is within both over sin.
    band = (DRAFTING.pen + 200.0 * math.tan(DRAFTING.angle)) / min(
        ln.conditioning for ln in lines)
    assert DRAFTING.pen / scale <= table["V_B"].tolerance <= 2 * band / crossing / scale


@pytest.mark.parametrize("share, verdict", [(0.5, "correct"), (1.5, "wrong magnitude")])
def test_a_rate_in_a_table_is_held_to_the_pen_on_the_velocity_it_is_read_from(
        tmp_path, share, verdict):
    """ω4 is read off the polygon as V_B/O4B: it is held to the tolerance of that vector
    drawn at the exercise's scale (100 mm for the longest tip, as the four-bar states no
    scale), over ω4's conditioning; half of it passes and one and a half fails."""
    from tarsim.constructions.linkages.velocity_polygon import drawn_velocity_polygon

    sol = solve_positions(FOUR_BAR)[0]
    q = sol.quantities["omega4"]
    w = q.reference["value"]
    vp = drawn_velocity_polygon(sol.work)
    scale = 100.0 / max(math.hypot(*vp.vector(n)) for n in vp.tips)        # mm per m/s
    span = math.dist(sol.work.kinematics.points["O4"], sol.work.kinematics.points["B"])
    tol = tolerance(abs(w) * span * scale, max(q.conditioning, 0.05)) / (span * scale)
    path = tmp_path / "answers.json"
    path.write_text(json.dumps({"omega4": w + share * tol}), encoding="utf-8")
    items = {i.name: i for i in grade(FOUR_BAR, path, 0).items}
    assert items["omega4"].tolerance == pytest.approx(tol, rel=1e-9)
    assert items["omega4"].verdict == verdict


def test_a_drawing_of_another_position_says_which(tmp_path):
    """The crank-shaper's polygon at θ2 = 90° handed in for its second position (t = 2.34 s)
    scores poorly there, and the grade says it is the first position's."""
    first = solve_positions(SHAPER)[0]
    g, _ = _graded(tmp_path, drawing(first, Style()), SHAPER, position=1)
    assert g.position_matched == 1 and g.score < 75.0
    assert g.notes[0].startswith("this drawing matches position 1 (θ2 = 90°), where it "
                                 "scores 100 %")
    assert g.as_json()["position_matched"] == 1


def test_an_exercises_alias_names_a_tip(tmp_path):
    """A statement that calls the ram's point c: the exercise's aliases map c to b, so a
    drawing labelled as the statement names it is graded."""
    from dataclasses import replace

    sol = solve_positions(FOUR_BAR)[0]
    svg = drawing(sol, Style()).replace(">b<", ">c<")
    g, items = _graded(tmp_path, svg, FOUR_BAR)
    assert items["b"].verdict == "missing"
    aliased = replace(FOUR_BAR, drafting=replace(DRAFTING, aliases={"c": "b"}))
    g, items = _graded(tmp_path, svg, aliased)
    assert items["b"].verdict == "correct"


@pytest.mark.parametrize("file, exercise, position", [
    ("frame-point-label-crank-shaper.svg", "crank-shaper", 2),
    ("frame-point-label-six-link.svg", "six-link-homework-1", 1)])
def test_a_frame_points_label_never_joins_the_search_for_swapped_labels(file, exercise,
                                                                       position):
    """Random drawings (CAD, LibreOffice) with o4 or o6 labelled at a pole and two tips
    wrong: the search for a swapped pair once looked the frame's tip up among the items it
    is never graded as (KeyError). Every item graded is a tip the polygon grades, or a
    centre, and the frame's own point is none of them."""
    from pathlib import Path

    path = Path(__file__).parent / "data" / "grading" / "regressions" / file
    g = grade(tarsim.load(exercise), path, position - 1)
    names = {i.name.rstrip("′") for i in g.items}
    assert names and not names & {"o2", "o4", "o6"}
    assert all(i.verdict in ("correct", "follows from an earlier error", "wrong magnitude",
                             "wrong direction", "wrong sense", "reversed Coriolis",
                             "swapped", "wrong position", "missing") for i in g.items)


def test_a_space_diagram_and_a_polygon_both_in_capitals_are_told_apart(tmp_path):
    """A, B, O2, O4 on the space diagram (no centres) and A, B for the polygon's tips: one
    case, and nothing but the space diagram's pivots (O2, O4, far from the pole, where a
    polygon would put them) says where it stands; the polygon's A and B are its tips."""
    import re as regex

    sol = solve_positions(FOUR_BAR)[0]
    space = regex.sub(r'<circle[^>]*r="0.6"/>', "", centres_drawing(sol))
    space = regex.sub(r"<text[^>]*><tspan[^>]*>I\d\d</tspan></text>", "", space)
    polygon = drawing(sol, Style()).replace(">a<", ">A<").replace(">b<", ">B<")
    g, items = _graded(tmp_path, _sheet((space, 0.0), (polygon, 120.0)), FOUR_BAR)
    assert set(items) == {"a", "b"}
    assert {i.verdict for i in g.items} == {"correct"}
