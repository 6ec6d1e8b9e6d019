"""The problem sheets of the chapters a sheet was added for last: a flywheel's, a connecting
rod's, a cam's given by its arcs, a rotor's with unknowns or weights, an engine's. Each holds
the data its file gives and none of the numbers its solution finds."""

from __future__ import annotations

import pytest

from tarsim.constructions.narration import speaking
from tarsim.exercises.chapters import chapter_of
from tarsim.graphics.svg import to_svg
from tests.test_handout import _NUMBER, _answers_on, _given, _sheet, _texts, _without_ticks

FLYWHEELS = ["engine-harmonic-torque", "flywheel-between-speeds", "four-stroke-triangles",
             "petrol-engine-areas", "punch-sheared-area", "punching-press",
             "single-cylinder-table", "steam-engine-energy-coefficient",
             "three-cylinder-triangles", "rod-equivalent-masses"]


def _data_and_answers(name: str, lang: str, *, skip=()):
    """The sheet of ``name`` in ``lang``: the numbers its file gives, those of them missing
    from the sheet, and the numbers its solution finds that stand on it."""
    ex, sheet = _sheet(name, lang)
    svg = _without_ticks(to_svg(sheet.figure))
    tokens = set(_NUMBER.findall(" ".join(_texts(svg, ticks=False))))
    given = _given(name) - set(skip)
    missing = sorted(f"{x:g}" for x in given if f"{x:g}" not in tokens)
    with speaking("en"):
        results = chapter_of(ex).solve(ex).results
    found = _answers_on(svg, results, given, ticks=False)
    return sheet, given, missing, sorted(found)


@pytest.mark.parametrize("lang", ["en", "fa"])
@pytest.mark.parametrize("name", ["circular-arc-flat-face", "tangent-cam-roller"])
def test_a_cam_of_arcs_sheet_draws_what_is_given_and_no_answer(name, lang):
    """The base circle and the nose (where its radius is given) are drawn at the solution's
    scale: the circular arc's r1 = 40 and r2 = 10 mm at 1 cm = 10 mm are circles of 40 and
    10 mm; the tangent cam's nose is found, so only its base circle (30 mm at 1 cm = 20 mm)
    is drawn, its roller (10 mm) dashed at the apex."""
    sheet, _, missing, found = _data_and_answers(name, lang)
    assert not missing and not found, (missing, found)
    circles = sorted(round(c.radius, 6) for c in sheet.figure.items
                     if type(c).__name__ == "Circle" and c.style == "link")
    assert circles == ([10.0, 40.0] if name == "circular-arc-flat-face" else [15.0])


ROTORS = ["unknown-angles", "unknown-plane-and-angle", "unknown-planes",
          "primary-balance-unknowns", "three-masses-between", "weights-one-plane"]


def test_a_mass_with_an_unknown_angle_is_left_out_of_the_end_view_and_its_plane_of_the_side():
    """unknown-plane-and-angle's D is found at 252.72° in a plane 366.7 mm from A: the sheet
    draws A, B and C on their radial lines (A's mass a gap, "…"), three planes at 0, 100 and
    300 mm and no fourth, and leaves D's cells empty but its given radius, 80 mm."""
    _, sheet = _sheet("unknown-plane-and-angle", "en")
    texts = _texts(to_svg(sheet.figure))
    assert "A: … kg at 80 mm, 190°" in texts
    assert not [t for t in texts if t.startswith("D:")]
    assert "not drawn, its radial line to be found: D" in texts
    assert "366.7" not in " ".join(texts) and "252.7" not in " ".join(texts)
    assert "mass D: ? kg at 80 mm, ?, plane at ? mm" in texts
    assert "mass D: its mass, its angle, its plane" in texts


def test_weights_are_given_and_asked_as_weights():
    """weights-one-plane gives 60, 80 and 100 N: the sheet states them in N (not the masses
    W/g it is solved with, 6.116 kg) and asks the balance weight."""
    _, sheet = _sheet("weights-one-plane", "en")
    texts = _texts(to_svg(sheet.figure))
    assert "weight 1: 60 N at 150 mm, 0°, plane at 0 mm" in texts
    assert "in plane B: the balance weight and its angle" in texts
    assert "W (N)" in texts and not [t for t in texts if "6.116" in t]


def test_a_view_names_only_what_it_draws():
    """Every plane of unknown-plane-and-angle's sheet's side view is a mass's plane: its
    legend names no balancing plane. three-masses-between's end view draws mass 1 alone, on
    the reference radius: O stands in the whole turn left free, across from it (x < 0),
    not on the mass's line."""
    _, sheet = _sheet("unknown-plane-and-angle", "en")
    texts = _texts(to_svg(sheet.figure))
    assert "a mass's plane" in texts and "a balancing plane" not in texts
    _, sheet = _sheet("three-masses-between", "en")
    o = next(t for t in sheet.sheets[0].items if getattr(t, "text", "") == "O")
    dot = next(c for c in sheet.sheets[0].items
               if type(c).__name__ == "Circle" and c.style == "dot")
    assert o.at[0] < dot.centre[0] - 3.0      # 4.2 mm to the left of O's dot, less its width


ENGINES = ["inline-four", "inline-three", "radial-three", "single-cylinder",
           "single-cylinder-balance-mass", "two-stroke-four", "v-twin"]


@pytest.mark.parametrize("lang", ["en", "fa"])
@pytest.mark.parametrize("name", FLYWHEELS + ROTORS + ENGINES)
def test_a_sheet_holds_its_data_and_no_answer(name, lang):
    """A flywheel's, a rod's, a rotor's with unknowns and an engine's sheet: each number
    its file gives stands on it, and none its solution finds."""
    _, given, missing, found = _data_and_answers(name, lang)
    assert given, f"{name}'s file gives no number to look for"
    assert not missing, f"{missing} of {name}'s file not on its sheet"
    assert not found, f"answers on {name}'s sheet: {found}"


def test_an_in_line_engine_has_its_cranks_beside_an_empty_frame_for_each_polygon():
    """inline-three's cranks are given at 0°, 120° and 240°: the end view the solution sets
    beside its primary force polygon stands beside that empty frame, and each of the four
    polygons has a frame (the secondary ones with the rod given). two-stroke-four's cranks
    follow from its firing order, an answer: no end view is drawn, the order is given."""
    from tarsim.graphics.handout import FRAME_STYLE

    _, sheet = _sheet("inline-three", "en")
    texts = _texts(to_svg(sheet.figure))
    assert {"1: 0°", "2: 120°", "3: 240°", "end view of the cranks, at θᵢ"} <= set(texts)
    frames = [p for p in sheet.figure.items if getattr(p, "style", "") == FRAME_STYLE]
    assert len(frames) == 4
    for kind in ("primary force", "primary couple", "secondary force", "secondary couple"):
        assert f"In-line three-cylinder engine: {kind}" in texts
    _, sheet = _sheet("two-stroke-four", "en")
    texts = _texts(to_svg(sheet.figure))
    assert "end view of the cranks, at θᵢ" not in texts
    assert "a 2-stroke engine, firing order 1, 4, 2, 3" in texts


def test_a_v_engines_layout_draws_its_lines_and_crank_as_given():
    """v-twin's lines are 90° apart about the centre line and its crank 30° from it: the
    layout's lines run at ±45° and its crank at 30° (paper y down)."""
    import math

    _, sheet = _sheet("v-twin", "en")
    paths = [p for p in sheet.figure.items if type(p).__name__ == "Path"]

    def angle(p):
        (x0, y0), (x1, y1) = p.points[0], p.points[-1]
        return round(math.degrees(math.atan2(y0 - y1, x1 - x0)), 6)

    lines = sorted(angle(p) for p in paths if p.style == "construction")
    assert lines == [-45.0, 45.0]
    assert [angle(p) for p in paths if p.style == "link"] == [30.0]


def test_every_bundled_exercise_has_a_persian_sheet_within_its_paper():
    """Every bundled exercise's sheet, in Persian, is on A4 sheets, upright or on their side
    (the English is held so by test_handout's own walk); none is refused."""
    from tarsim.exercises.catalog import everything, load
    from tarsim.exercises.handout import handout

    names = everything()
    assert len(names) >= 90
    for name in names:
        ex = load(name)
        chapter = chapter_of(ex)
        with speaking("fa"):
            made = handout(chapter.set_up(ex.named_in("fa"), paper="A4"), chapter)
        for s in made.sheets:
            assert (s.width, s.height) in ((210.0, 297.0), (297.0, 210.0)), (name, s.width,
                                                                              s.height)


def test_each_result_of_an_engine_is_asked_once():
    """A single cylinder's greatest secondary force (666.2 N at 1800 rpm) is asked as that,
    not as a V's resultant; primary-balance-unknowns is asked its engine's primary
    balance, not a rotor's."""
    _, sheet = _sheet("single-cylinder", "en")
    texts = _texts(to_svg(sheet.figure))
    assert "the greatest secondary force" in texts
    assert not [t for t in texts if t.startswith("the resultant secondary")]
    _, sheet = _sheet("primary-balance-unknowns", "en")
    texts = _texts(to_svg(sheet.figure))
    assert "for the engine in primary balance (force and couple)" in texts


def test_a_rotor_with_no_balancing_plane_asks_its_out_of_balance_and_its_bearings(tmp_path):
    """The books' shaft of two masses on bearings 1.2 m apart (tests/data/textbook) has no
    [[balance]]: its sheet draws both masses, states the bearings, asks the out-of-balance
    force and couple and each bearing's load, and prints none of them."""
    import tomllib
    from pathlib import Path

    from tarsim.exercises.chapters import read_file
    from tarsim.exercises.handout import handout

    source = Path("tests/data/textbook/balancing-dynamic-loads-on-bearings.toml")
    text = tomllib.loads(source.read_text())["exercise"]["file"]
    (tmp_path / "shaft.toml").write_text(text)
    ex = read_file(tmp_path / "shaft.toml", "shaft")
    chapter = chapter_of(ex)
    with speaking("en"):
        made = handout(chapter.set_up(ex, paper="A4"), chapter)
        results = chapter.solve(ex).results
    svg = to_svg(made.figure)
    texts = _texts(svg)
    assert {"bearing A at 0 mm", "bearing B at 1200 mm", "the out-of-balance force",
            "the load on bearing A", "the load on bearing B"} <= set(texts)
    # the plane the couple is asked about (the central one, 650 mm) is part of the question:
    # results.json carries it beside the couple as its "about", not as a found number
    assert "the out-of-balance couple about the plane at 650 mm" in texts
    assert results["quantities"]["unbalanced_couple"]["about"] == 0.65
    given = {abs(float(x)) for x in _numbers(tomllib.loads(text))} | {650.0}
    assert not _answers_on(svg, results, given, ticks=False)


def _numbers(value):
    if isinstance(value, bool):
        return []
    if isinstance(value, (int, float)):
        return [value]
    if isinstance(value, dict):
        return [x for v in value.values() for x in _numbers(v)]
    if isinstance(value, list):
        return [x for v in value for x in _numbers(v)]
    return []
