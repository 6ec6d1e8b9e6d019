"""Limit positions by compass: time ratio and stroke, against the notes, closed forms and the
analytic reversal search; the whole-mechanism answers (DOF, Grashof class and ranges).

Tolerances: the construction against the analytic reference uses the conditioning
tolerance it reports (≥ 1e-9); a published number is matched to half a unit in
its last printed digit.
"""

from __future__ import annotations

import json
import math
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.reference.limits import limit_reference
from tarsim.constructions.errors import InputError, TarsimError
from tarsim.constructions.linkages.limit_positions import (draw_limit_positions, drawn_limits,
                                                           limit_kind)
from tarsim.constructions.reference.rotatability import (class_by_rotation, length_range,
                                                         length_range_by_rotation)
from tarsim.exercises.catalog import resolve
from tarsim.exercises.linkages.exercise_file import load_exercise, parse_exercise
from tarsim.exercises.linkages.solution import solve_overall
from tarsim.constructions.record import Slice
from tarsim.graphics.linkages.scene import draw_scene
from tests.common import badge_numbers, four_bar_toml

SLIDER_CRANK = """
name = "slider-crank"
[units]
length = "mm"
angle = "deg"
[frame]
O2 = [0, 0]
[[link]]
number = 2
points = ["O2", "A"]
lengths = {{ O2A = {r} }}
[[link]]
number = 3
points = ["A", "B"]
lengths = {{ AB = {l} }}
[[link]]
number = 4
points = ["B"]
[[slider]]
link = 4
point = "B"
on = 1
through = "O2"
angle = 0
offset = {e}
[input]
link = 2
angle = {angle}
omega = {omega}
[assembly]
B = "forward"
[ask]
find = ["time_ratio", "stroke"]
"""


def _overall(exercise_id: str):
    ex = load_exercise(resolve(exercise_id))
    return ex, solve_overall(ex)


def _printed(value: float, published: str) -> bool:
    """``value`` rounds to ``published`` (half a unit in its last digit)."""
    decimals = len(published.split(".")[1]) if "." in published else 0
    return abs(value - float(published)) <= 0.5 * 10 ** -decimals + 1e-12


# ----- the catalog's published numbers ------------------------------------------------------
@pytest.mark.parametrize("exercise_id, ratio, ratio_text, stroke_mm, stroke_text", [
    # 003 §5: Q = 222.2/137.8 = 1.6125 (the document's 0.73 is wrong); stroke 679.134 mm.
    ("crank-shaper", 1.6125, "1.6125", 679.134, "679.13"),
    # 000-part2 §3.3: 198.46/161.54 = 1.23 (exact 1.2286); stroke 63.34 cm.
    ("offset-slider-crank", 1.2286, "1.23", 633.39, "633.4"),
    # 000-part2 §3.4, P-37: 224.05/135.95 = 1.648 (printed 1.64); stroke 19.50 cm (assumed ram).
    ("slotted-lever-p37", 1.648, "1.648", 195.0, "195.0"),
])
def test_catalog_time_ratio_and_stroke(exercise_id, ratio, ratio_text, stroke_mm, stroke_text):
    _, o = _overall(exercise_id)
    tr, st_ = o.quantities["time_ratio"], o.quantities["stroke"]
    assert tr.passed and st_.passed
    assert _printed(tr.value["value"], ratio_text)
    assert tr.value["value"] == pytest.approx(ratio, abs=5e-5)
    assert _printed(st_.value["value"] * 1000, stroke_text)
    assert st_.value["value"] * 1000 == pytest.approx(stroke_mm, abs=5e-3)


def test_offset_slider_crank_angles_as_the_notes_print_them():
    # Forward 198.46°, return 161.54° (000-part2 §3.3).
    _, o = _overall("offset-slider-crank")
    v = o.quantities["time_ratio"].value
    assert _printed(v["slow_deg"], "198.46") and _printed(v["quick_deg"], "161.54")


def test_crank_shaper_limits_where_the_seed_puts_them():
    # 003 §5: extremes at θ2 = −21.10° and 201.10° (crank ⟂ lever); lever half-swing 21.100°.
    ex = load_exercise(resolve("crank-shaper"))
    lp = draw_limit_positions(ex.mechanism)
    got = sorted(math.degrees(a) % 360 for a in lp.crank_angles)
    assert got == pytest.approx([201.100, 338.900], abs=5e-4)
    # The slow (cutting) stroke at ω2 = −1: from A″ … the crank turns 222.2° clockwise.
    assert math.degrees(lp.slow) == pytest.approx(222.2004, abs=1e-4)


# ----- closed forms ---------------------------------------------------------------------------
@settings(max_examples=40, deadline=None)
@given(r=st.floats(10, 60), extra=st.floats(20, 200), e_frac=st.floats(-0.8, 0.8),
       omega=st.sampled_from([1.0, -2.0]))
def test_slider_crank_against_the_notes_formulas(r, extra, e_frac, omega):
    # S1 = √((L+R)² − e²), S2 = √((L−R)² − e²), stroke S1 − S2, δ = atan(S1/e) − atan(S2/e)
    # in the notes' angles from the perpendicular; forward 180° + |δ|, return 180° − |δ|.
    rod = r + extra
    e = e_frac * (rod - r)
    ex = parse_exercise(SLIDER_CRANK.format(r=r, l=rod, e=e, angle=30, omega=omega))
    lp = draw_limit_positions(ex.mechanism)
    s1, s2 = math.sqrt((rod + r) ** 2 - e ** 2), math.sqrt((rod - r) ** 2 - e ** 2)
    delta = abs(math.atan2(s1, e) - math.atan2(s2, e))
    assert lp.stroke * 1000 == pytest.approx(s1 - s2, rel=1e-12, abs=1e-12 * rod)
    assert lp.slow == pytest.approx(math.pi + delta, rel=1e-12)
    assert lp.time_ratio == pytest.approx((math.pi + delta) / (math.pi - delta), rel=1e-12)


def test_slotted_lever_against_the_notes_formula():
    # cos(β/2) = O2A / O2O4 with β the return angle; the ram moves 2 (r1 + h) tan φ.
    ex = load_exercise(resolve("crank-shaper"))
    lp = draw_limit_positions(ex.mechanism)
    beta = 2 * math.acos(180 / 500)
    assert lp.quick == pytest.approx(beta, rel=1e-14)
    phi = math.asin(180 / 500)
    assert lp.stroke == pytest.approx(2 * 0.880 * math.tan(phi), rel=1e-14)


def test_crank_rocker_against_the_law_of_cosines():
    # Crank and coupler in line: |O2B| = AB ± O2A, so the crank's angle at O2 in triangle
    # O2 O4 B follows from the cosine rule.
    ex = parse_exercise(four_bar_toml() + '\n[ask]\nfind = ["time_ratio"]\n')
    lp = draw_limit_positions(ex.mechanism)
    g, a, b, c = 300, 100, 250, 200

    def at(d):                          # angle of O2B above the ground line
        return math.acos((g * g + d * d - c * c) / (2 * g * d))
    extended, folded = at(b + a), at(b - a) + math.pi      # the crank points away from B
    got = sorted(a_ % (2 * math.pi) for a_ in lp.crank_angles)
    assert got == pytest.approx(sorted([extended, folded % (2 * math.pi)]), abs=1e-13)
    assert lp.stroke is None and lp.kind == "crank-rocker"


@pytest.mark.parametrize("exercise_id", ["crank-shaper", "offset-slider-crank",
                                         "slotted-lever-p37"])
def test_construction_against_the_reversal_search(exercise_id):
    ex = load_exercise(resolve(exercise_id))
    lp = draw_limit_positions(ex.mechanism)
    ref = limit_reference(ex.mechanism, point=lp.point, link=lp.output)
    assert lp.time_ratio == pytest.approx(ref.time_ratio, rel=1e-12)
    assert lp.stroke == pytest.approx(ref.stroke, rel=1e-12)
    # The same two crank angles, whatever the order.
    pair = sorted(a % (2 * math.pi) for a in lp.crank_angles)
    assert pair == pytest.approx(sorted(a % (2 * math.pi) for a in ref.crank_angles), abs=1e-10)


def test_reversing_the_crank_keeps_the_ratio_and_swaps_the_strokes():
    fwd = parse_exercise(SLIDER_CRANK.format(r=30, l=70, e=20, angle=45, omega=1))
    back = parse_exercise(SLIDER_CRANK.format(r=30, l=70, e=20, angle=45, omega=-1))
    a, b = draw_limit_positions(fwd.mechanism), draw_limit_positions(back.mechanism)
    assert a.time_ratio == pytest.approx(b.time_ratio, rel=1e-14)
    assert a.slow_from != b.slow_from


# ----- what cannot be drawn ----------------------------------------------------------------
def test_a_double_crank_has_no_limit_positions():
    ex = parse_exercise(four_bar_toml(ground=20, crank=50, coupler=100, rocker=90)
                        + '\n[ask]\nfind = ["grashof"]\n')
    with pytest.raises(TarsimError, match=r"crank and rod cannot lie in line, extended: the arc "
                                          r"of radius AB \+ O2A = 150 mm about O2 misses the "
                                          r"arc of B about O4 by 40 mm"):
        solve_overall(ex.asking(("time_ratio",)))


def test_stroke_is_not_offered_without_a_block():
    with pytest.raises(InputError, match=r"m.toml:\d+: \[ask.find\] cannot find 'stroke' for "
                                         r"this mechanism: the stroke is measured on a block"):
        parse_exercise(four_bar_toml() + '\n[ask]\nfind = ["stroke"]\n', "m.toml")


def test_a_rod_shorter_than_the_crank_is_refused():
    ex = parse_exercise(SLIDER_CRANK.format(r=30, l=20, e=0, angle=10, omega=1))
    with pytest.raises(InputError, match=r"the rod AB \(link 3, 20 mm\) is not longer than "
                                         r"the crank O2A \(link 2, 30 mm\): the crank cannot "
                                         r"turn fully"):
        draw_limit_positions(ex.mechanism)


def test_limit_kind_names_each_dyad():
    kinds = {i: limit_kind(load_exercise(resolve(i)).mechanism)
             for i in ("crank-shaper", "offset-slider-crank", "slotted-lever-p37", "four-bar")}
    assert kinds == {"crank-shaper": "slotted lever", "offset-slider-crank": "slider-crank",
                     "slotted-lever-p37": "slotted lever", "four-bar": "crank-rocker"}


# ----- DOF and Grashof ----------------------------------------------------------------------
@pytest.mark.parametrize("exercise_id, span, low, high, kind", [
    ("grashof-crank-rocker", "AB", 65.0, 135.0, "crank-rocker"),     # 001 ch. 1 ex. 1, option 4
    ("grashof-double-crank", "O2O4", 0.0, 40.0, "double-crank"),     # 001 ch. 1 ex. 3, option 3
])
def test_grashof_ranges_from_the_exam_text(exercise_id, span, low, high, kind):
    _, o = _overall(exercise_id)
    q = o.quantities[f"range_{span}"]
    assert q.passed
    assert q.value["low"] * 1000 == pytest.approx(low, abs=1e-9)
    assert q.value["high"] * 1000 == pytest.approx(high, abs=1e-9)
    assert q.value["class"] == kind == o.quantities["grashof"].value["class"]
    assert o.quantities["dof"].value["value"] == 1 and o.quantities["dof"].passed


def test_range_by_turning_agrees_with_the_breakpoints():
    for lengths, i in (((100, 30, 100, 65), 2), ((20, 50, 100, 90), 0), ((300, 100, 250, 200), 3)):
        lo, hi = length_range(lengths, i)
        rlo, rhi = length_range_by_rotation(lengths, i)
        assert rlo == pytest.approx(lo, abs=1e-9 * max(lengths))
        assert (hi is None) == (rhi is None)
        if hi is not None:
            assert rhi == pytest.approx(hi, rel=1e-9)


@settings(max_examples=300, deadline=None, derandomize=True)
@given(lengths=st.lists(st.integers(1, 40), min_size=4, max_size=4), index=st.integers(0, 3))
def test_a_range_by_the_breakpoints_is_the_range_by_turning(lengths, index):
    # Whole-number lengths make change points (S + L = P + Q) common, and exact: a change
    # point ends the range of the class either side of it, by either method.
    lo, hi = length_range(lengths, index)
    rlo, rhi = length_range_by_rotation(lengths, index)
    slack = 1e-9 * max(lengths)             # the bisection's, as the check allows
    if lo == hi:                            # a change point itself: an end of its neighbour's
        assert min(abs(lo - rlo), abs(lo - (math.inf if rhi is None else rhi))) <= slack
        return
    assert rlo == pytest.approx(lo, abs=slack)
    assert (hi is None) == (rhi is None)
    if hi is not None:
        assert rhi == pytest.approx(hi, abs=slack)


@pytest.mark.parametrize("lengths, kind", [((300, 100, 250, 200), "crank-rocker"),
                                           ((20, 50, 100, 90), "double-crank"),
                                           ((100, 80, 30, 90), "double-rocker"),
                                           ((100, 90, 80, 85), "triple-rocker")])
def test_class_by_turning(lengths, kind):
    assert class_by_rotation(lengths) == kind


# ----- the files ----------------------------------------------------------------------------
def test_crank_shaper_files_carry_the_whole_mechanism(solved):
    worked = solved("crank-shaper")
    overall, files = worked.overall, worked.files()
    doc = json.loads(files["results.json"])
    assert set(doc["quantities"]) == {"dof", "time_ratio", "stroke"}
    assert doc["quantities"]["time_ratio"]["reference"]["value"] == pytest.approx(1.61249, abs=1e-5)
    assert len(doc["positions"]) == 2
    # The limit figure's circled numbers are steps.md's numbers for it.
    lp = drawn_limits(overall.work)
    narrated = Slice(lp.assembly, tuple(lp.steps)).numbered()
    part = files["steps.md"].split("## Limit positions")[1].split("## Results")[0]
    listed = [int(n) for n in re.findall(r"^(\d+)\. ", part, re.M)]
    assert listed == [n for n, _ in narrated] == list(range(1, len(narrated) + 1))
    fig = draw_scene(Slice(lp.assembly, tuple(lp.steps)))
    assert badge_numbers(fig) == listed
    # solution.svg holds every figure, one under another.
    stems = [n[:-4] for n in files if n.endswith(".svg") and n != "solution.svg"]
    assert len(stems) == 9
    assert files["solution.svg"].count("<text") == sum(files[f"{s}.svg"].count("<text")
                                                       for s in stems)


@pytest.mark.slow
def test_solution_pdf_has_a_page_per_figure(tmp_path):
    pytest.importorskip("cairocffi")
    from pypdf import PdfReader

    from tarsim.exercises.linkages.solution_files import solve_worked
    worked = solve_worked(load_exercise(resolve("slotted-lever-p37")))
    worked.write(tmp_path)
    files = worked.files()
    pages = PdfReader(tmp_path / "solution.pdf").pages
    assert len(pages) == 1                      # the limit positions alone
    # A page keeps its figure's size: true scale on paper (1 mm = 72/25.4 pt).
    width_mm = float(re.search(r'width="([\d.]+)mm"', files["limits.svg"]).group(1))
    assert float(pages[0].mediabox.width) == pytest.approx(width_mm * 72 / 25.4, rel=1e-3)


@pytest.mark.parametrize("exercise_id, slow, stroke_text", [
    ("crank-shaper", "222.20° slow", "stroke 679.1 mm"),
    ("offset-slider-crank", "198.46° slow", "stroke 63.34 cm"),
    ("slotted-lever-p37", "224.05° slow", "stroke 19.5 cm")])
def test_the_limit_figure_reads_its_angles_and_its_stroke_as_a_drafter_marks_them(
        exercise_id, slow, stroke_text):
    """The crank's two angles as arcs at O2 with their degrees, the stroke as a dimension line
    whose two heads stand exactly the stroke apart at the figure's scale."""
    ex = load_exercise(resolve(exercise_id))
    lp = draw_limit_positions(ex.mechanism)
    c = lp.assembly
    angles = [c.output(f"limit:{k}") for k in ("slow", "quick")]
    assert [math.radians(a.degrees) for a in angles] == pytest.approx([lp.slow, lp.quick],
                                                                      abs=1e-12)
    assert sum(a.degrees for a in angles) == pytest.approx(360.0, abs=1e-9)
    # Each arc turns with ω from the limit the stroke starts at.
    assert all(math.copysign(1.0, a.sweep) == math.copysign(1.0, ex.mechanism.drive.omega)
               for a in angles)
    fig = draw_scene(Slice(lp.assembly, tuple(lp.steps)))
    texts = [t.text for t in fig.items if hasattr(t, "text")]
    assert slow in texts and stroke_text in texts
    per_cm = float(re.search(r"Scale (\d+) cm = ([\d.]+)", " ".join(texts)).group(2)) / \
        float(re.search(r"Scale (\d+) cm", " ".join(texts)).group(1))
    paper = 10.0 * lp.stroke / (per_cm * ex.mechanism.units.metres)
    dims = [p for p in fig.items if getattr(p, "style", "") == "dimension"]
    heads = [p.points[0] for p in fig.items if getattr(p, "style", "") == "arrowhead"]
    assert any(math.dist(h, k) == pytest.approx(paper, abs=1e-6) for h in heads for k in heads)
    assert len(dims) >= 4                          # two extension lines, two half-shafts
