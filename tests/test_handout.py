"""The problem sheet (``tarsim handout``): the exercise as given, what is asked, empty frames
at the solution's scales, and none of the answers."""

from __future__ import annotations

import json
import math
import re
import tomllib

import pytest
from click.testing import CliRunner

from tarsim.constructions.asks import Centre, Effort
from tarsim.constructions.narration import speaking
from tarsim.exercises.catalog import load, resolve
from tarsim.exercises.chapters import chapter_of
from tarsim.exercises.cli import cli
from tarsim.exercises.handout import handout
from tarsim.exercises.handout_loads import force_words
from tarsim.exercises.linkages.solution_files import solve_worked
from tarsim.graphics.handout import FRAME_MARGIN, FRAME_STYLE
from tarsim.graphics.svg import to_svg
from tarsim.graphics.typeset import typeset

_PERSIAN = str.maketrans("۰۱۲۳۴۵۶۷۸۹٫", "0123456789.")
_NUMBER = re.compile(r"\d+(?:\.\d+)?")


def _sheet(name: str, lang: str):
    ex = load(name)
    chapter = chapter_of(ex)
    with speaking(lang):
        ex = chapter.set_up(ex.named_in(lang), paper="A4")
        return ex, handout(ex, chapter)


def _texts(svg: str, *, ticks: bool = True) -> list[str]:
    """Every <text>'s words, its tspans joined, in Latin digits; without a scale bar's tick
    numbers (set at 2.6 mm, :func:`~tarsim.graphics.scales.draw_scale_bar`) unless
    ``ticks``: they are the scale's multiples, 0, 100, 200, whatever the answers are."""
    out = []
    for m in re.finditer(r"<text\b([^>]*)>(.*?)</text>", svg, re.S):
        if ticks or 'font-size="2.6"' not in m.group(1):
            # A scale statement's "1 cm" is the scale's, whatever an answer is.
            text = re.sub(r"<[^>]+>", "", m.group(2)).translate(_PERSIAN)
            out.append(re.sub(r"\b1 (cm|سانتی\u200cمتر)", r"\1", text))
    return out


def _without_ticks(svg: str) -> str:
    """``svg`` without a plot's tick numbers (set at 2.9 mm, :mod:`~tarsim.graphics.plot`):
    a flywheel's axes are the solution's, numbered every 30° and every 1000 N·m whatever
    the answers are (a punch's mean torque of 1000 N·m falls on a tick)."""
    return re.sub(r'<text\b[^>]*font-size="2.9"[^>]*>.*?</text>', "", svg, flags=re.S)


def _numbers_in(value, key: str = "") -> list[float]:
    """Every number of a results.json part, but the checks' own (error, tolerance,
    conditioning); a vector's angle too, for a figure prints "232.9 mm/s at 0°"."""
    if key in ("rel_error", "tolerance", "conditioning", "passed"):
        return []
    if isinstance(value, bool):
        return []
    if isinstance(value, (int, float)):
        return [float(value)]
    if isinstance(value, dict):
        return [x for k, v in value.items() for x in _numbers_in(v, k)]
    if isinstance(value, list):
        out = [x for v in value for x in _numbers_in(v)]
        if key == "vector" and len(value) == 2:
            out.append(math.degrees(math.atan2(value[1], value[0])))
        return out
    return []


def _given(name: str) -> set[float]:
    """Every number the exercise file writes: the sheet must print these."""
    data = tomllib.loads(resolve(name).read_text())
    return {abs(float(x)) for x in _numbers_in(data)}


def _renderings(x: float) -> set[str]:
    """``x`` (SI) as a figure could print it in the file's units (mm, mm/s, mm/s², or as
    it is: rad/s, a ratio, degrees), at the precision the figures print: four significant
    figures (Units.length_drawn, the results table), and an angle's two decimals (222.20°).
    Three would make a found 269.8 mm the given 270 of another point."""
    return {f for v in (x, 1000.0 * x)
            for f in (f"{abs(v):.4g}", *([f"{abs(v):.2f}"] if abs(v) >= 1.0 else []))}


def _answers_on(svg: str, results: dict, given: set[float], *, ticks: bool = True) -> set[str]:
    """The numbers of ``results`` the sheet prints, as figures print them. Not counted:
    a scale statement's ("1 cm = 50 mm", the drawing's, whatever the answers are); a
    number a given one prints as (a found 69.998 mm and the given O4 at 70 both print "70":
    the sheet must print the given one); 0 (every scale bar's start) and a one-digit whole
    number, which the drawing prints as a link's or a gear's number whatever an answer is
    (a dof of 1, ω4/ω2 = 1 of a parallelogram)."""
    texts = [t for t in _texts(svg, ticks=ticks) if not re.search(r"(cm|سانتی\u200cمتر) = ", t)]
    tokens = set(_NUMBER.findall(" ".join(texts)))
    printed = {r for g in given for r in (f"{g:g}", f"{g:.4g}")} | {str(k) for k in range(10)}
    found = {r for x in _numbers_in(results) if abs(x) > 1e-9
             and not any(math.isclose(abs(x) * k, g, rel_tol=1e-6) for g in given
                         for k in (1.0, 1000.0))
             for r in _renderings(x)}
    return (found & tokens) - printed


@pytest.mark.parametrize("lang", ["en", "fa"])
@pytest.mark.parametrize("name", ["crank-shaper", "four-bar", "crank-shaper-forces",
                                  "crank-pin-speed"])
def test_the_sheet_holds_the_data_and_the_asks_and_no_answer(name, lang):
    ex, sheet = _sheet(name, lang)
    svg = to_svg(sheet.figure)
    texts = _texts(svg)
    words = " ".join(texts)
    tokens = set(_NUMBER.findall(words))
    given = _given(name)
    # Every dimension and input the file gives is printed (as the file writes it: 180, 500).
    for x in given:
        assert f"{x:g}" in tokens, f"{x:g} of {name}'s file is not on its sheet"
    # Every asked quantity by its symbol; the centres by their count.
    items = sheet.figure.items
    symbols = {(t.text, t.sub) for t in items if hasattr(t, "sub")}
    said = {t.text for t in items if hasattr(t, "sub")}
    for ask in ex.asks:
        if isinstance(ask, Effort):             # asked by the course's words alone
            with speaking(lang):
                assert force_words(ask)[0] in said, ask.word
        elif ask.scope == "position" and not isinstance(ask, Centre):
            assert typeset(ask.symbol) in symbols, ask.symbol
    if "centres" in ex.find:     # every centre asked, their count not said (it may be asked)
        with speaking(lang):
            from tarsim.constructions.narration import words as said_in
            assert said_in("every instant centre") in said
    # None of the answers: no number results.json gives (at the precision the figures print
    # it, in the file's units) is among the sheet's numbers. A number the file itself gives
    # is printed by design (I23 of the crank-shaper is at (0, 180), O2A = 180), and 0 marks
    # every scale bar's start, so these two are not answers to be hidden.
    with speaking("en"):
        results = solve_worked(ex).results
    found = _answers_on(svg, results, given)
    assert not found, f"answers on {name}'s sheet: {sorted(found)}"


def test_an_input_given_by_a_points_speed_is_given_so_and_no_omega_drawn():
    """The solution draws a crank driven by its pin's speed at ω2 = 1 rad/s and scales the
    polygons after: the sheet gives V_A as the file does and draws no ω2 it was not given."""
    _, sheet = _sheet("crank-pin-speed", "en")
    texts = _texts(to_svg(sheet.figure))
    assert " = 1000 mm/s cw, its rate of change 5000 mm/s² cw" in texts
    assert not [t for t in texts if "ω₂ =" in t]      # no caption states an ω2
    assert texts.count("ω₂") == 1                     # asked, and drawn on no arrow
    assert ("V", "A") in {(t.text, t.sub) for t in sheet.figure.items if hasattr(t, "sub")}


def test_the_frames_are_at_the_stated_scale_and_hold_the_polygon():
    ex, sheet = _sheet("crank-shaper", "en")
    svg = to_svg(sheet.figure)
    texts = _texts(svg)
    # The exercise states 3 cm = 18 cm/s: each velocity frame says so, as the worked page does.
    assert texts.count("Velocity scale 3 cm = 18 cm/s") == 2 + 1   # two frames, the diagram
    frames = [p for p in sheet.figure.items if getattr(p, "style", "") == FRAME_STYLE]
    # A velocity and an acceleration polygon at each of two positions.
    assert len(frames) == 4
    with speaking("en"):
        results = solve_worked(ex).results
    v_b = results["positions"][0]["quantities"]["V_B"]["reference"]["value"]   # m/s
    # At θ2 = 90° every velocity is horizontal (the crank upright, the lever on O2O4) and
    # V_B = 232.9 mm/s is the longest, V_A = 180 mm/s under it: the frame is V_B long at
    # 60 mm/s a cm, with 8 mm to spare each side, and holds no height but its margins.
    first = next(f for f in frames if abs(max(y for _, y in f.points)
                                          - min(y for _, y in f.points)
                                          - 2 * FRAME_MARGIN) < 1e-9)
    xs = [x for x, _ in first.points]
    assert max(xs) - min(xs) - 2 * FRAME_MARGIN == pytest.approx(v_b * 1000 / 60 * 10,
                                                                  rel=1e-9)   # float sums


def test_a_chapter_with_no_sheet_is_refused_by_name(tmp_path, monkeypatch):
    """A chapter whose sheet is not registered is refused in one line, naming those that
    have one (every bundled chapter has one: the flywheel's taken out here)."""
    from tarsim.exercises import handout as module

    monkeypatch.delitem(module.HANDOUTS, "forces")
    got = CliRunner().invoke(cli, ["handout", "punching-press", "-o", str(tmp_path / "h")])
    assert got.exit_code == 1
    assert got.output == ("Error: punching-press is a flywheel or connecting rod exercise, "
                          "which has no problem sheet yet: tarsim handout writes one for a "
                          "linkage, a gear train, a cam or a balancing exercise\n")
    assert not (tmp_path / "h").exists()


@pytest.mark.parametrize("lang", ["en", "fa"])
@pytest.mark.parametrize("name", ["planetary-q1", "compound-train", "four-mass-shaft",
                                  "four-masses-one-plane", "offset-knife-edge",
                                  "oscillating-roller"])
def test_another_chapters_sheet_holds_its_data_and_no_answer(name, lang):
    ex, sheet = _sheet(name, lang)
    tokens = set(_NUMBER.findall(" ".join(_texts(to_svg(sheet.figure), ticks=False))))
    given = _given(name)
    for x in given:
        assert f"{x:g}" in tokens, f"{x:g} of {name}'s file is not on its sheet"
    with speaking("en"):
        results = chapter_of(ex).solve(ex).results
    found = _answers_on(to_svg(sheet.figure), results, given, ticks=False)
    assert not found, f"answers on {name}'s sheet: {sorted(found)}"


def test_every_bundled_sheet_is_within_its_paper_and_holds_no_answer():
    """Each sheet of every bundled exercise's handout is an A4 sheet, upright or on its side,
    and prints none of the numbers its solution finds (:func:`_answers_on`), or the exercise
    is refused in one line: every bundled exercise now has one."""
    from tarsim.constructions.errors import TarsimError
    from tarsim.exercises.catalog import everything
    from tarsim.exercises.handout import HANDOUTS

    sheets = refused = 0
    for name in everything():
        ex = load(name)
        chapter = chapter_of(ex)
        if chapter.key not in HANDOUTS:
            continue
        try:
            with speaking("en"):
                made = handout(chapter.set_up(ex, paper="A4"), chapter)
        except TarsimError as e:
            assert "\n" not in str(e) and "has none yet" in str(e), name
            refused += 1
            continue
        for s in made.sheets:
            assert (s.width, s.height) in ((210.0, 297.0), (297.0, 210.0)), (name, s.width,
                                                                              s.height)
        sheets += len(made.sheets)
        with speaking("en"):
            results = chapter.solve(chapter.set_up(ex, paper="A4")).results
        found = _answers_on(_without_ticks(to_svg(made.figure)), results, _given(name),
                            ticks=False)
        assert not found, f"answers on {name}'s sheet: {sorted(found)}"
    assert sheets >= 150 and refused == 0      # 90 exercises, most over 2 sheets


def test_the_command_writes_the_sheet(tmp_path):
    got = CliRunner().invoke(cli, ["handout", "four-bar", "-o", str(tmp_path), "--no-pdf"])
    assert got.exit_code == 0, got.output
    assert got.output == f"wrote handout.svg to {tmp_path}/\n"
    assert "Four-bar crank-rocker: problem sheet" in (tmp_path / "handout.svg").read_text()
    assert json.loads((tmp_path / ".tarsim-manifest.json").read_text())


def test_the_sheets_words_change_no_other_figures():
    """fa_handout's words are the sheet's own: one of another module's keys would change
    that module's figures, for fa.WORDS takes the last."""
    from pathlib import Path

    from tarsim.constructions.phrases import (fa_balancing, fa_cams, fa_forces, fa_grading,
                                              fa_handout, fa_rod, fa_trains)

    for module in (fa_balancing, fa_cams, fa_forces, fa_grading, fa_rod, fa_trains):
        assert not set(fa_handout.WORDS) & set(module.WORDS), module.__name__
    source = (Path(fa_handout.__file__).parent / "fa.py").read_text(encoding="utf-8")
    for key in fa_handout.WORDS:     # nor one fa.py sets itself
        assert f'"{key}"' not in source, key
