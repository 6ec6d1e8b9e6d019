"""Tests for exercises.worked_document and exercises.checked: the one writer of steps.md and
of results.json's rows, which every chapter's solution says its files through."""

from __future__ import annotations

import json
import math
import re

import pytest

from tarsim.constructions.narration import LANGUAGES, Phrase, Word, catalogue, narrate, phrase
from tarsim.exercises.catalog import bundled
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution_files import solve_worked
from tarsim.exercises.linkages.worked_steps import heading_in
from tests.common import four_bar_toml
from tarsim.exercises.checked import Checked, check_line, results_document, results_text
from tarsim.exercises.worked_document import (Bullets, Notes, Paragraph, Section, Table, markdown,
                                              numbered, title)

CHAPTERS = sorted([*bundled("gears"), *bundled("cams"), *bundled("balancing")])
"""The bundled exercises of the chapters that say their files through ChapterFiles."""

LINKAGES = ["four-bar", "crank-shaper", "crank-shaper-forces", "wheel-driven-slider"]
"""Linkages whose steps.md holds every kind of heading: a velocity by each method, the limit
positions and two positions' worked pages, the force polygons and the inertia loads read
off the acceleration polygon (a part of no figure of its own), and notes."""

ORDER = ["reference", "rel_error", "tolerance", "conditioning", "passed", "method"]
"""The check's fields, in the one order every results.json row writes those it states."""


def test_a_document_sets_a_blank_line_after_each_heading_and_block():
    doc = [title("Four-bar", "As the notes give it."),
           Section(phrase("md.results"), (numbered(["Draw O2O4.", "Bisect it."]),
                                          Bullets(("ω3 = 2 rad/s",))), ("centres", "worked"))]
    assert markdown(doc, "en") == (
        "# Four-bar: worked solution\n\nAs the notes give it.\n\n"
        "## Results (`centres.svg`, `worked.svg`)\n\n1. Draw O2O4.\n2. Bisect it.\n\n"
        "- ω3 = 2 rad/s\n")


def test_a_document_ending_on_a_heading_keeps_the_blank_line_under_it():
    assert markdown([title("Four-bar")], "en") == "# Four-bar: worked solution\n\n"


def test_no_notes_still_stand_as_their_blank_line():
    """A position without notes has two blank lines before its results, as steps.md has
    always set it; with notes, one after them."""
    def doc(notes):
        return [Section(blocks=(Paragraph("x"),)), Section(blocks=(Notes(notes),)),
                Section(phrase("md.results"))]
    assert markdown(doc(()), "en") == "x\n\n\n## Results\n\n"
    assert markdown(doc(("a", "b")), "en") == "x\n\n> a\n> b\n\n## Results\n\n"


def test_a_table_head_sets_its_blank_corner_apart_from_an_empty_cell():
    table = Table(("", "1 ring", "2 sun"), (("total", "0", ""),))
    assert markdown([Section(blocks=(table,))], "en") == (
        "| | 1 ring | 2 sun |\n|---|---|---|\n| total | 0 |  |\n")


def test_a_heading_is_said_in_the_language_asked():
    doc = [Section(phrase("heading.train"), figures=("train",))]
    assert markdown(doc, "fa") == "## قطار چرخدنده (`train.svg`)\n\n"


def test_a_checked_row_writes_its_fields_in_one_order():
    row = Checked({"value": -2.5, "vector": [1.0, 2.0]}, {"value": -2.5}, rel_error=1e-16,
                  tolerance=math.inf, conditioning=0.5, passed=True, method="velocity polygon",
                  beside={"by_method": {}})
    entry = row.entry()
    assert list(entry) == ["value", "vector", "reference", "rel_error", "tolerance",
                           "conditioning", "passed", "method", "by_method"]
    assert entry["tolerance"] is None              # unbounded: null, stated
    assert list(Checked({"value": 3.0}).entry()) == ["value"]    # nothing else stated


def test_results_text_refuses_a_number_json_cannot_hold():
    doc = results_document("x", {"a": Checked({"value": 1.5}, {"value": 1.5}, method="m")})
    assert json.loads(results_text(doc)) == {"exercise": "x", "positions": [], "quantities": {
        "a": {"value": 1.5, "reference": {"value": 1.5}, "method": "m"}}}
    with pytest.raises(ValueError):
        results_text(results_document("x", {"a": Checked({"value": math.nan})}))


def test_a_check_line_pads_the_answer_to_its_width():
    line = check_line("ω4 = 60 rpm ccw (60)", width=34, passed=False, against="(Willis: 60)",
                      method="tabular")
    assert line == "ω4 = 60 rpm ccw (60)               check FAILED (Willis: 60)   tabular"
    assert line.index("check") == 35


def _words_of(said) -> list[str]:
    """The catalogue words a phrase's arguments name (a Word, a clause's own)."""
    out = []
    for _, arg in said.args:
        if isinstance(arg, Word):
            out.append(arg.text)
        elif isinstance(arg, Phrase):
            out += _words_of(arg)
    return out


@pytest.mark.parametrize("exercise_id", CHAPTERS + LINKAGES)
def test_every_heading_of_steps_md_is_a_phrase_each_catalogue_says(solved, exercise_id):
    sections = solved(exercise_id).document()
    headings = [s.heading for s in sections if s.heading is not None]
    assert len(headings) >= 2                      # the title and the results at least
    for heading in headings:
        assert isinstance(heading, Phrase)
        for lang in LANGUAGES:
            assert heading.key in catalogue(lang).PHRASES, (lang, heading.key)
            assert all(w in catalogue(lang).WORDS for w in _words_of(heading) if lang != "en")
        # said in Persian, no English word is left in it but the names it is given (the
        # exercise's, a point's: V_B)
        bare = Phrase(heading.key, tuple((k, "" if isinstance(v, str) else v)
                                         for k, v in heading.args))
        assert not re.search(r"[A-Za-z]{4,}", narrate(bare, "fa")), narrate(bare, "fa")


def test_a_velocity_by_its_method_is_headed_by_one_phrase():
    """"V_B by radius rotation" is the quantity and its method, said whole by each catalogue:
    Persian puts its own words between them."""
    text = four_bar_toml(branch='B = "left"').replace("[input]\n", "[input]\nomega = 10\n")
    text += ('\n[ask]\nfind = ["omega4", "V_B"]\n'
             'methods = ["line-of-transmission", "radius-rotation"]\n')

    doc = solve_worked(parse_exercise(text, "lot.toml")).document()
    said = {narrate(s.heading, "fa") for s in doc if s.heading is not None}
    assert {"ω4 به روش خط انتقال", "V_B به روش دوران شعاع"} <= said


def test_a_heading_with_by_in_its_words_is_said_whole():
    """"Positions by compass" is no quantity and its method: its Persian is the catalogue's
    own words for it, not its English cut at " by "."""
    assert heading_in("Positions by compass", "fa") == catalogue("fa").WORDS[
        "Positions by compass"] == "وضعیت\u200cها با پرگار"


def _in_order(entry: dict, extra: tuple[str, ...] = ()) -> bool:
    """Whether a row's check fields stand in the one order, after what its value carries."""
    keys = [k for k in entry if k not in extra]
    stated = [k for k in keys if k in ORDER]
    return keys[len(keys) - len(stated):] == stated == [k for k in ORDER if k in stated]


@pytest.mark.parametrize("exercise_id", CHAPTERS)
def test_a_chapters_results_rows_keep_the_one_order(solved, exercise_id):
    """Every row is written by Checked.entry: what the value carries, then of the check's
    fields those it states, in the one order (and what follows the check)."""
    s = solved(exercise_id)
    assert s.results["quantities"]
    for name, row in s.checked.items():
        entry = s.results["quantities"][name]
        assert entry == row.entry()
        assert list(entry)[0] == "value"
        assert _in_order(entry, tuple(row.beside)), (name, list(entry))


@pytest.mark.parametrize("exercise_id", LINKAGES)
def test_a_linkages_results_rows_keep_the_one_order(solved, exercise_id):
    doc = solved(exercise_id).results
    rows = [*doc["quantities"].values(), *(q for p in doc["positions"]
                                           for q in p["quantities"].values())]
    rows += [q for r in rows for q in r.get("by_method", {}).values()]
    assert len(rows) >= 4
    for entry in rows:
        assert list(entry)[-1] in ("method", "by_method")
        assert [k for k in entry if k in ORDER] == ORDER      # a linkage states every field
        assert _in_order(entry, ("by_method",)), list(entry)
