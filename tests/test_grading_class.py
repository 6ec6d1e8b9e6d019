"""A class graded as a course runs one: every file of the folder gets a row, each drawing
its own folder, students mapped from a roster or the files' names, gradebooks for Moodle
and Canvas, a page each student reads, the class's plot, and a Dask cluster that is handed
absolute paths.

What a drawing scores is the grader's business (tests/test_grading.py); here the numbers
are read back from what the run wrote: the histogram's bars are counted from grades.csv's
scores, the gradebooks' scores are grades.csv's, the page's tolerances grade.json's.
"""

from __future__ import annotations

import csv
import gzip
import html
import json
import math
import os
import re
import shutil
import socket
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

import tarsim
from tarsim.constructions.narration import speaking
from tarsim.exercises.catalog import resolve
from tarsim.exercises.cli import cli
from tarsim.exercises.grading.batch import folder_for, not_a_drawing
from tarsim.exercises.grading.drawing import Drawing, Label
from tarsim.exercises.grading.grade import Grade, Item
from tarsim.exercises.grading.overlay import overlay_svg, sans_width
from tarsim.exercises.grading.report import CLASS_FILES
from tarsim.exercises.grading.roster import Pattern, Student
from tarsim.exercises.linkages.solution import solve_positions
from tarsim.graphics.export import MANIFEST, cairo_missing
from tests.drawings import Style, drawing

SHAPER = tarsim.load("crank-shaper")
RETURN = solve_positions(SHAPER)[1]          # t = 2.34 s, the crank-shaper's second position
PERSIAN = str.maketrans("۰۱۲۳۴۵۶۷۸۹٫", "0123456789.")


def run(*args, lang: str | None = None):
    extra = ["--lang", lang] if lang else []
    return CliRunner().invoke(cli, ["grade", "crank-shaper", *map(str, args), "--position",
                                    "2", *extra], catch_exceptions=False)


def sheet(out: Path, name: str = "grades.csv") -> list[dict]:
    return list(csv.DictReader((out / name).read_text(encoding="utf-8").splitlines()))


def class_of(folder: Path, styles: dict[str, Style]) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    for name, style in styles.items():
        (folder / name).write_text(drawing(RETURN, style), encoding="utf-8")
    return folder


# ----- 13. every file gets a row ---------------------------------------------------------------
@pytest.mark.parametrize("name, says", [
    ("ali.png", "a PNG is a picture, not a drawing: export the drawing as SVG"),
    ("ali.JPG", "a JPEG is a picture, not a drawing: export the drawing as SVG"),
    ("ali.jpeg", "a JPEG is a picture, not a drawing: export the drawing as SVG"),
    ("ali.pdf", "a PDF is not read: export the drawing as SVG"),
    ("ali.ggb", "a GeoGebra file is not read: export the drawing as SVG"),
    ("ali.zip", "an archive (.zip) is not opened: unpack its drawings into the class folder"),
    ("ali.txt", "a .txt file is not a drawing: hand in an .svg drawing, or a .json or .csv "
                "table of answers"),
    ("ali", "a file with no ending is not a drawing: hand in an .svg drawing, or a .json or "
            ".csv table of answers"),
    ("ali.svg", ""), ("ali.SVGZ", ""), ("ali.json", ""), ("ali.CSV", "")])
def test_a_file_that_is_not_a_drawing_says_what_to_hand_in(tmp_path, name, says):
    (tmp_path / name).write_bytes(b"x")
    assert not_a_drawing(tmp_path / name) == says


def test_every_file_of_a_class_folder_gets_a_row(tmp_path):
    """Drawings (.svg in either case, .svgz), a table of answers, pictures, a PDF, a text
    file, one with no ending, a folder and a pipe: each is a row of grades.csv, named as it
    is, and a hidden drawing too; only a hidden file that is no drawing is passed over. The
    .svgz is handed to the reader: graded, or its row says why not."""
    folder = class_of(tmp_path / "class", {"right.svg": Style(), "upper.SVG": Style()})
    (folder / "packed.svgz").write_bytes(gzip.compress(drawing(RETURN, Style()).encode()))
    (folder / "answers.json").write_text('{"V_B": 0.2}', encoding="utf-8")
    for name in ("photo.png", "scan.jpg", "export.pdf", "readme.txt", "NOENDING"):
        (folder / name).write_bytes(b"\x89PNG\r\n\x1a\n" if name.endswith("png") else b"x")
    (folder / "sub").mkdir()
    (folder / ".hidden.svg").write_text(drawing(RETURN, Style()), encoding="utf-8")
    (folder / ".DS_Store").write_bytes(b"\0\0\0\1Bud1")
    os.mkfifo(folder / "pipe.svg")
    out = tmp_path / "graded"
    result = run(folder, "-o", out)
    assert result.exit_code == 0, result.output
    rows = {r["drawing"]: r for r in sheet(out)}
    assert set(rows) == {p.name for p in folder.iterdir()} - {".DS_Store"}
    assert rows["photo.png"]["note"] == ("a PNG is a picture, not a drawing: export the "
                                         "drawing as SVG")
    assert rows["scan.jpg"]["note"].startswith("a JPEG is a picture")
    assert rows["export.pdf"]["note"] == "a PDF is not read: export the drawing as SVG"
    assert rows["sub"]["note"].startswith("a folder, not a drawing")
    assert rows["pipe.svg"]["note"] == "not read: not a file (a pipe or a device)"
    for name in ("right.svg", "upper.SVG", ".hidden.svg", "answers.json"):
        assert rows[name]["score"] != "" and rows[name]["folder"] != "", rows[name]
    packed = rows["packed.svgz"]
    assert packed["score"] != "" or "svgz" in packed["note"] or "drawing" in packed["note"]
    unread = [r for r in rows.values() if not r["score"]]
    assert all(r["note"] and not r["folder"] for r in unread)
    assert result.output.splitlines()[-1].startswith(
        f"graded {len(rows) - len(unread)} of {len(rows)} drawings")


def test_the_output_folder_inside_the_class_folder_is_no_row(tmp_path):
    folder = class_of(tmp_path / "class", {"a.svg": Style(), "b.svg": Style()})
    for _ in range(2):                      # the second run reads past the first's output
        result = run(folder, "-o", folder / "graded")
        assert result.exit_code == 0, result.output
        assert [r["drawing"] for r in sheet(folder / "graded")] == ["a.svg", "b.svg"]


# ----- 14. one folder per drawing, never shared ------------------------------------------------
COLLIDING = ("a b.svg", "a_b.svg", "..svg", "...svg", "dup.SVG", "dup.svg")


def test_names_that_collide_once_made_safe_get_a_folder_each(tmp_path):
    """class-folder.sh, case 1: six drawings whose names collide once made safe, or differ
    only in case, get six folders, each holding its own drawing's grade."""
    folder = class_of(tmp_path / "class", {n: Style() for n in COLLIDING})
    out = tmp_path / "graded"
    assert run(folder, "-o", out).exit_code == 0
    rows = {r["drawing"]: r["folder"] for r in sheet(out)}
    assert set(rows) == set(COLLIDING)
    assert len({f.casefold() for f in rows.values()}) == 6          # apart on any disk
    for name, sub in rows.items():
        assert json.loads((out / sub / "grade.json").read_text())["drawing"] == name


def test_drawings_named_like_the_runs_own_files_do_not_stop_it(tmp_path):
    """class-folder.sh, case 2: drawings named grades.csv.svg, summary.svg, moodle.csv.svg,
    and a table named grades.csv: each its own folder, none the class's sheet or plot."""
    names = ("grades.csv.svg", "summary.svg", "moodle.csv.svg", "canvas.csv.svg")
    folder = class_of(tmp_path / "class", {n: Style() for n in names})
    (folder / "grades.csv").write_text("name,value\nV_B,0.2\n", encoding="utf-8")
    out = tmp_path / "graded"
    result = run(folder, "-o", out, "--pattern", "{id}.*")
    assert result.exit_code == 0, result.output
    rows = sheet(out)
    assert {r["drawing"] for r in rows} == {*names, "grades.csv"}
    folders = [r["folder"] for r in rows]
    assert all(folders) and len(set(folders)) == 5
    assert not set(folders) & set(CLASS_FILES)
    assert (out / "summary.svg").read_text(encoding="utf-8").startswith("<svg")
    assert (out / "moodle.csv").read_text(encoding="utf-8").startswith("ID number,")


def test_a_link_out_of_the_class_folder_is_not_followed(tmp_path):
    """class-folder.sh, case 1's link: a drawing outside the class, linked into it, gets a
    row saying so and no folder; nothing of it is read."""
    folder = class_of(tmp_path / "class", {"in.svg": Style()})
    outside = class_of(tmp_path / "outside", {"secret.svg": Style()})
    (folder / "link.svg").symlink_to(outside / "secret.svg")
    out = tmp_path / "graded"
    assert run(folder, "-o", out).exit_code == 0
    rows = {r["drawing"]: r for r in sheet(out)}
    assert rows["link.svg"]["folder"] == "" and rows["link.svg"]["score"] == ""
    note = rows["link.svg"]["note"]                   # the link's target, cut at 80 letters
    assert note.startswith("not read: a link to /") and note.endswith(
        ", outside the class folder")
    assert not any("secret" in p.read_text(encoding="utf-8", errors="replace")
                   for p in out.rglob("grade.json"))


def test_a_link_in_the_output_folder_is_not_written_through(tmp_path):
    """class-folder.sh, case 3: a link where a drawing's folder goes stops the run before
    anything is written, and nothing lands where it leads."""
    folder = class_of(tmp_path / "class", {n: Style() for n in COLLIDING})
    outside = tmp_path / "outside"
    outside.mkdir()
    out = tmp_path / "graded"
    out.mkdir()
    (out / "a_b").symlink_to(outside)
    result = run(folder, "-o", out)
    assert result.exit_code == 1
    assert result.output.splitlines()[-1] == (
        f"Error: cannot write into '{out / 'a_b'}': it is a symbolic link, and tarsim "
        "writes only inside the output folder; remove it")
    assert [p.name for p in out.iterdir()] == ["a_b"] and list(outside.iterdir()) == []


@settings(max_examples=300, deadline=None)
@given(st.lists(st.text(st.characters(blacklist_categories=["Cs"], blacklist_characters="/\0"),
                        min_size=1, max_size=20).map(lambda s: s + ".svg"),
                min_size=2, max_size=8, unique=True))
def test_no_two_names_share_a_folder_on_any_disk(names):
    """Distinct names get distinct folders even where case is not told apart, and none is
    hidden, a name the run writes beside them, or a staging folder's."""
    folders = [folder_for(n) for n in names]
    assert len({f.casefold() for f in folders}) == len(names)
    for f in folders:
        assert not f.startswith(".") and "/" not in f and f not in CLASS_FILES
        assert f != MANIFEST


# ----- 15. students, not files -----------------------------------------------------------------
def test_a_roster_maps_files_to_students_and_the_gradebooks_take_their_scores(tmp_path):
    """A roster headed as a spreadsheet heads it (a byte-order mark, 'Student ID', 'Full
    name', 'File'): a student with no file gets a row "no drawing handed in", a file no row
    names a row saying so; moodle.csv and canvas.csv carry grades.csv's scores by id, and an
    empty score for the student with none."""
    folder = class_of(tmp_path / "class", {"ali.svg": Style(), "sara.svg": Style(kind="a"),
                                           "stray.svg": Style()})
    (folder / "reza.png").write_bytes(b"\x89PNG")
    roster = tmp_path / "roster.csv"
    roster.write_text("\ufeffStudent ID,Full name,File\n9812,Ali Rezaei,ali.svg\n"
                      "9813,Sara Ahmadi,SARA.svg\n9814,Reza Karimi,reza.png\n"
                      "9815,Mina Jafari,\n", encoding="utf-8")
    out = tmp_path / "graded"
    result = run(folder, "-o", out, "--roster", roster)
    assert result.exit_code == 0, result.output
    assert result.output.splitlines()[-1].endswith("; 1 student handed in none")
    rows = sheet(out)
    assert [(r["id"], r["name"], r["drawing"]) for r in rows] == [
        ("9812", "Ali Rezaei", "ali.svg"), ("9813", "Sara Ahmadi", "sara.svg"),
        ("9814", "Reza Karimi", "reza.png"), ("9815", "Mina Jafari", ""),
        ("", "", "stray.svg")]
    by_id = {r["id"]: r for r in rows}
    assert by_id["9815"]["note"] == "no drawing handed in"
    assert by_id["9814"]["note"].startswith("a PNG is a picture")
    assert rows[-1]["note"].startswith("no roster row names this file")
    moodle = sheet(out, "moodle.csv")
    title = "crank-shaper at position 2"
    assert list(moodle[0]) == ["ID number", "Full name", title, f"Feedback: {title}"]
    assert [m["ID number"] for m in moodle] == ["9812", "9813", "9814", "9815"]
    for m in moodle:
        score = by_id[m["ID number"]]["score"]
        assert (float(m[title]) == pytest.approx(float(score), abs=0.05)) if score else \
            m[title] == ""
    assert moodle[3][f"Feedback: {title}"] == "no drawing handed in"
    lines = (out / "canvas.csv").read_text(encoding="utf-8").splitlines()
    assert lines[:2] == [f"Student,ID,SIS User ID,SIS Login ID,Section,{title}",
                         "Points Possible,,,,,100"]
    canvas = {r["SIS User ID"]: r for r in csv.DictReader(lines)}
    assert canvas["9812"]["Student"] == "Ali Rezaei" and canvas["9812"]["ID"] == ""
    assert float(canvas["9812"][title]) == pytest.approx(float(by_id["9812"]["score"]),
                                                         abs=0.05)
    assert canvas["9815"][title] == canvas["9814"][title] == ""


@pytest.mark.parametrize("pattern", ["{id}_{name}.svg", "{id}_{name}", "{ID}_*"])
def test_a_pattern_reads_each_student_off_the_file_name(tmp_path, pattern):
    folder = class_of(tmp_path / "class", {"9812_Ali Rezaei.svg": Style(),
                                           "9813_Sara.SVG": Style(), "notes.svg": Style()})
    (folder / "9814_Reza.png").write_bytes(b"\x89PNG")
    out = tmp_path / "graded"
    if "{ID}" in pattern:
        result = run(folder, "-o", out, "--pattern", pattern)
        assert result.exit_code == 1
        assert result.output.strip() == ("Error: --pattern: '{ID}_*' must hold {id} once, and "
                                         "may hold {name} once and * for any text (e.g. "
                                         "'{id}_{name}.svg')")
        assert not out.exists()
        return
    result = run(folder, "-o", out, "--pattern", pattern)
    assert result.exit_code == 0, result.output
    rows = {r["drawing"]: r for r in sheet(out)}
    assert (rows["9812_Ali Rezaei.svg"]["id"], rows["9812_Ali Rezaei.svg"]["name"]) == \
        ("9812", "Ali Rezaei")
    assert rows["9813_Sara.SVG"]["id"] == "9813"            # an ending in any case
    png = rows["9814_Reza.png"]
    if pattern.endswith(".svg"):                              # a whole name must fit
        assert png["id"] == "" and "does not fit the pattern" in png["note"]
    else:                                                     # less its ending: any file
        assert png["id"] == "9814" and png["note"].startswith("a PNG is a picture")
    assert rows["notes.svg"]["id"] == ""
    assert rows["notes.svg"]["note"].endswith(f"its name does not fit the pattern {pattern}")
    assert [m["ID number"] for m in sheet(out, "moodle.csv")] == \
        ["9812", "9813"] + (["9814"] if not pattern.endswith(".svg") else [])


def test_a_pattern_with_a_roster_and_two_files_for_one_student(tmp_path):
    """The roster names the students, the pattern their files: one with two files gets
    both graded and their rows say so, the gradebooks an empty score and why; an id the
    roster lacks is said."""
    folder = class_of(tmp_path / "class", {"9812-v.svg": Style(), "9812-a.svg": Style(kind="a"),
                                           "9813-v.svg": Style(), "9999-v.svg": Style()})
    roster = tmp_path / "r.csv"
    roster.write_text("id,name\n9812,Ali\n9813,Sara\n", encoding="utf-8")
    out = tmp_path / "graded"
    assert run(folder, "-o", out, "--roster", roster, "--pattern", "{id}-*").exit_code == 0
    rows = {r["drawing"]: r for r in sheet(out)}
    for name in ("9812-a.svg", "9812-v.svg"):
        assert rows[name]["id"] == "9812" and rows[name]["score"] != ""
        assert rows[name]["note"].startswith("2 files for one student (9812-a.svg, "
                                             "9812-v.svg): their grade is left to you")
    assert rows["9999-v.svg"]["note"].startswith("student 9999 is not on the roster")
    moodle = {m["ID number"]: m for m in sheet(out, "moodle.csv")}
    assert moodle["9812"]["crank-shaper at position 2"] == ""
    assert moodle["9812"]["Feedback: crank-shaper at position 2"].startswith("2 files")
    assert float(moodle["9813"]["crank-shaper at position 2"]) == pytest.approx(
        float(rows["9813-v.svg"]["score"]), abs=0.05)      # grades.csv rounds to 0.1


@pytest.mark.parametrize("text, says", [
    ("name,file\nAli,a.svg\n", "r.csv:1: no column of student ids: head one 'id', "
                               "'student id', 'student number', 'id number' (and the others "
                               "'name' and 'file')"),
    ("id,Student ID,file\n1,2,a.svg\n", "r.csv:1: columns 'id' and 'Student ID' both give "
                                        "the student's id; keep one"),
    ("id,file\n1,a.svg\n1,b.svg\n", "r.csv:3: student 1 is on line 2 too; give each student "
                                    "one row"),
    ("id,file\n1,a.svg\n2,A.SVG\n", "r.csv:3: the file A.SVG is named on line 2 too; one "
                                    "file is one student's"),
    ("id,file\n,a.svg\n", "r.csv:2: a row with no student id; give each student's id"),
    ("id,name\n1,Ali\n", "r.csv: the roster names no student's file: give each in a column headed "
                         "'file', or --pattern to read their ids off the files' names"),
    (b"id,file\n\xff,a.svg\n", "r.csv: is not UTF-8 text; save the roster as CSV (UTF-8)")])
def test_a_bad_roster_is_one_line_and_writes_nothing(tmp_path, text, says):
    folder = class_of(tmp_path / "class", {"a.svg": Style()})
    roster = tmp_path / "r.csv"
    roster.write_bytes(text if isinstance(text, bytes) else text.encode())
    out = tmp_path / "graded"
    result = run(folder, "-o", out, "--roster", roster)
    assert result.exit_code == 1
    assert result.output.strip() == f"Error: {says}"
    assert not out.exists()


def test_the_help_says_the_rosters_headers_and_the_pattern():
    text = CliRunner().invoke(cli, ["grade", "--help"], terminal_width=200).output
    flat = " ".join(text.split())
    assert "headed id (or 'student id', 'student number', 'id number')" in flat
    assert "name (or 'full name', 'student') and file (or 'file name', 'drawing')" in flat
    assert "e.g. '{id}_{name}.svg'" in flat and "summary.svg" in flat
    assert "moodle.csv and canvas.csv" in flat


def test_a_pattern_is_matched_as_written():
    p = Pattern("{name}_{id}_assignsubmission_file_*")
    assert p.match("Ali Rezaei_12345_assignsubmission_file_velocity.svg") == \
        Student("12345", "Ali Rezaei")
    assert p.match("Ali_assignsubmission_file_x.svg") is None
    assert Pattern("{id}.svg").match("a+b(1).svg") == Student("a+b(1)")   # no regex in names


def test_a_file_named_as_a_formula_is_text_in_every_sheet(tmp_path):
    """A student's file named "=HYPERLINK(…).svg" opens as text in a spreadsheet, in
    grades.csv and in the gradebooks' feedback alike."""
    name = '=HYPERLINK("http:x";"y").svg'
    folder = class_of(tmp_path / "class", {name: Style()})
    (folder / "+1.png").write_bytes(b"x")
    out = tmp_path / "graded"
    assert run(folder, "-o", out, "--pattern", "*").exit_code == 1       # no {id}
    assert run(folder, "-o", out, "--pattern", "{id}.png").exit_code == 0
    rows = sheet(out)
    assert [r["drawing"] for r in rows] == ["'+1.png", "'" + name]
    assert [m["ID number"] for m in sheet(out, "moodle.csv")] == ["'+1"]


# ----- 16. feedback a student reads ------------------------------------------------------------
def test_each_student_gets_a_page_that_fetches_nothing(tmp_path):
    """feedback.html beside each grade.json: the overlay inline, every item's verdict,
    tolerance (grade.json's, in mm) and advice; no script, nothing fetched; a name that is
    markup stays text. feedback.pdf beside it where cairo is."""
    folder = class_of(tmp_path / "class", {"<script>x.svg": Style(kind="a",
                                                                 reversed_coriolis="A"),
                                           "ali.svg": Style(moved={"B": (6.0, 0.0)})})
    out = tmp_path / "graded"
    assert run(folder, "-o", out).exit_code == 0
    for row in sheet(out):
        page = (out / row["folder"] / "feedback.html").read_text(encoding="utf-8")
        data = json.loads((out / row["folder"] / "grade.json").read_text(encoding="utf-8"))
        assert "Content-Security-Policy" in page and "default-src 'none'" in page
        assert not re.search(r"<script|\ssrc=|href=\"(?!#)|url\(", page, re.I)
        assert page.count("<svg") == 1
        assert ("&lt;script&gt;x.svg" in page) == (row["drawing"] == "<script>x.svg")
        cells = re.findall(r"<tr><td[^>]*>(.*?)</td><td[^>]*>(.*?)</td><td>(.*?)</td>"
                           r"<td[^>]*>(.*?)</td></tr>", page)
        assert len(cells) == len(data["items"])
        for (name, verdict, tol, advice), item in zip(cells, data["items"]):
            assert (name, verdict) == (item["name"], item["verdict"])
            assert tol == ("" if item["tolerance"] is None else f"± {item['tolerance']:.3g} mm")
            assert advice == html.escape(item["message"])
        assert f"score {data['score']:.0f} %" in page
        if cairo_missing() is None:
            assert (out / row["folder"] / "feedback.pdf").read_bytes().startswith(b"%PDF")


def test_without_cairo_the_page_is_html_alone_and_says_so_once(tmp_path, monkeypatch):
    import tarsim.graphics.export as export

    monkeypatch.setattr(export, "cairo_missing", lambda: "no cairo")
    folder = class_of(tmp_path / "class", {"a.svg": Style(), "b.svg": Style()})
    out = tmp_path / "graded"
    result = run(folder, "-o", out)
    assert result.exit_code == 0, result.output
    said = [line for line in result.stderr.splitlines() if "feedback.pdf" in line]
    assert said == ["note: feedback.pdf is not written, for libcairo2 is not installed "
                    "(Debian/Ubuntu: apt-get install libcairo2); feedback.html is"]
    assert sorted(p.name for p in (out / "a").iterdir()) == ["feedback.html", "grade.json",
                                                             "grade.svg"]


def test_the_page_speaks_persian(tmp_path):
    folder = class_of(tmp_path / "class", {"9812_ali.svg": Style(kind="a",
                                                                 reversed_coriolis="A")})
    out = tmp_path / "graded"
    assert run(folder, "-o", out, "--no-pdf", lang="fa").exit_code == 0
    row = sheet(out)[0]
    page = (out / row["folder"] / "feedback.html").read_text(encoding="utf-8")
    assert '<html lang="fa" dir="rtl">' in page and "بازخورد" in page
    assert "<th>مورد</th><th>نتیجه</th><th>رواداری</th><th>راهنمایی</th>" in page
    assert "<bdi>9812_ali.svg</bdi>" in page              # a name keeps its order
    assert "میلی‌متر" in page and not (out / row["folder"] / "feedback.pdf").exists()


def _fake_grade(size: float) -> Grade:
    """A drawing ``size`` mm across with a wrong tip at its very edge and long advice."""
    k = size / 100.0
    pole, tips = (0.0, 0.0), {"a": (100 * k, 0.0), "b": (0.0, -60 * k), "c": (100 * k, -60 * k)}
    d = Drawing(segments=[(pole, t) for t in tips.values()],
                labels=[Label(n, (t[0] + k, t[1] - k)) for n, t in tips.items()])
    items = [Item("a", "correct", list(tips["a"]), list(tips["a"]), 0.8, ""),
             Item("c", "wrong sense", list(tips["c"]), [101 * k, -61 * k], 1.3,
                  "Coriolis component at A drawn opposite: turn V_rel 90° in the sense of ω4, "
                  "as the notes do, and lay it off from the tip of the relative velocity"),
             Item("b", "wrong magnitude", list(tips["b"]), [0.0, -64 * k], 1.1,
                  "b is 4 mm too long")]
    return Grade("crank-shaper", "ali.svg", items, overlay=(d, [(None, None, pole, tips)]))


def _texts(svg: str):
    """Each text of an SVG: its words, size, anchor, direction and where it stands."""
    root = ET.fromstring(svg)
    ns = "{http://www.w3.org/2000/svg}"

    def walk(el, inherited):
        style = {**inherited, **{k: el.get(k) for k in ("font-size", "text-anchor",
                                                        "direction") if el.get(k)}}
        if el.tag == ns + "text":
            yield ("".join(el.itertext()), float(style["font-size"]),
                   style.get("text-anchor", "start"), style.get("direction", "ltr"),
                   float(el.get("x")), float(el.get("y")))
        for child in el:
            yield from walk(child, style)
    yield from walk(root, {})


@pytest.mark.parametrize("lang", ["en", "fa"])
def test_the_overlay_has_a_legend_text_sized_to_it_and_nothing_cut(lang):
    """The same drawing 10 cm and 20 m across: its text is the same share of it (not 3 mm on
    a 20 m sheet); every text, ring and line stands inside the viewBox; the legend and the
    wrong item's explanation are on it."""
    shares = []
    for size in (100.0, 20000.0):
        with speaking(lang):
            svg = overlay_svg(_fake_grade(size))
        x0, y0, w, h = map(float, ET.fromstring(svg).get("viewBox").split())
        texts = list(_texts(svg))
        words = " ".join(t[0] for t in texts)
        legend = ("your drawing", "expected", "graded wrong") if lang == "en" else \
            ("ترسیم شما", "مورد انتظار", "نادرست")
        assert all(w_ in words for w_ in legend)
        assert "Coriolis component at A drawn opposite" in words and "c: " in words
        for text, fs, anchor, direction, x, y in texts:
            width = sans_width(text, fs)
            visual = {"start": "end", "end": "start"}.get(anchor) if direction == "rtl" \
                else anchor
            left = x if visual == "start" else x - width if visual == "end" else x - width / 2
            assert x0 <= left and left + width <= x0 + w, (text, left, left + width, x0, w)
            assert y0 <= y - fs and y + 0.3 * fs <= y0 + h, text
        for c in re.findall(r'<circle cx="([-\d.e]+)" cy="([-\d.e]+)" r="([\d.e]+)"', svg):
            cx, cy, r = map(float, c)
            assert x0 <= cx - r and cx + r <= x0 + w and y0 <= cy - r and cy + r <= y0 + h
        biggest = max(t[1] for t in texts)
        shares.append(biggest / w)
    # The same share of the sheet at both sizes: a 20 m drawing's text is 200 times a 10 cm
    # one's (to the rounding of the sizes written, four figures).
    assert shares[1] == pytest.approx(shares[0], rel=1e-3)


# ----- 17. the class at a glance ---------------------------------------------------------------
@pytest.mark.parametrize("lang", [None, "fa"])
def test_the_summary_counts_what_grades_csv_holds(tmp_path, lang):
    """summary.svg's bars: each tenth's count is the number of grades.csv's scores in it,
    and each item's error rate is its share of the drawings graded on it that are not
    correct, "wrong of graded" as grades.csv counts them."""
    styles = {f"s{k}.svg": s for k, s in enumerate([
        Style(), Style(), Style(moved={"B": (8.0, 0.0)}), Style(kind="a"),
        Style(kind="a", reversed_coriolis="A"), Style(left_out=("B4",)),
        Style(moved={"B4": (0.0, 9.0)}), Style(swapped=("A4", "B4"))])}
    folder = class_of(tmp_path / "class", styles)
    (folder / "photo.png").write_bytes(b"x")
    out = tmp_path / "graded"
    assert run(folder, "-o", out, "--no-pdf", lang=lang).exit_code == 0
    rows = [r for r in sheet(out) if r["score"]]
    scores = [float(r["score"]) for r in rows]
    expected = [0] * 10
    for s in scores:
        expected[min(9, int(s // 10))] += 1
    root = ET.fromstring((out / "summary.svg").read_text(encoding="utf-8"))
    ns = "{http://www.w3.org/2000/svg}"
    bars = root.find(f".//{ns}g[@id='histogram']")
    heights = [float(r.get("height")) for r in bars.iter(ns + "rect")]
    counts = [int(t.text.translate(PERSIAN)) for t in bars.iter(ns + "text")]
    assert sum(counts) == len(rows) == sum(expected)
    assert [n for n in expected if n] == counts
    per = max(heights) / max(expected)                     # one drawing's height
    assert [round(h / per) for h in heights] == expected
    items = [c for c in rows[0] if c not in ("drawing", "folder", "id", "name", "score",
                                             "note")]
    said = " ".join(t.text or "" for t in root.iter(ns + "text")).translate(PERSIAN)
    for name in items:
        graded = [r[name] for r in rows if r[name]]
        if not graded:
            continue
        wrong = sum(v != "correct" for v in graded)
        share = f"{100 * wrong / len(graded):.0f}"
        pattern = (f"{share} % ({wrong} of {len(graded)})" if lang is None
                   else f"{share}٪ ({wrong} از {len(graded)})")
        assert pattern in said, (name, pattern, said)


def test_a_class_with_nothing_to_grade_still_says_so_everywhere(tmp_path):
    """Only pictures handed in: each a row, the plot says no drawing could be graded, and
    the gradebooks name the exercise's column and give every student an empty score."""
    folder = tmp_path / "class"
    folder.mkdir()
    for name in ("9812.png", "9813.jpg"):
        (folder / name).write_bytes(b"x")
    out = tmp_path / "graded"
    result = run(folder, "-o", out, "--pattern", "{id}")
    assert result.exit_code == 0, result.output
    assert [r["note"][:12] for r in sheet(out)] == ["a PNG is a p", "a JPEG is a "]
    plot = (out / "summary.svg").read_text(encoding="utf-8")
    assert "0 drawings graded" in plot and "no drawing could be graded" in plot
    assert "2 files could not be graded" in plot
    moodle = sheet(out, "moodle.csv")
    assert [(m["ID number"], m["crank-shaper at position 2"]) for m in moodle] == \
        [("9812", ""), ("9813", "")]


@pytest.mark.skipif(cairo_missing() is not None, reason="libcairo2 is not installed")
def test_the_pages_pdfs_are_the_same_made_on_two_processes(tmp_path):
    folder = class_of(tmp_path / "class", {f"s{k}.svg": Style(moved={"B": (2.0 * k, 0.0)})
                                           for k in range(3)})
    pdfs = []
    for workers in (1, 2):
        out = tmp_path / f"graded{workers}"
        assert run(folder, "-o", out, "--workers", workers).exit_code == 0
        pdfs.append({p.parent.name: p.read_bytes() for p in out.glob("*/feedback.pdf")})
    assert sorted(pdfs[0]) == ["s0", "s1", "s2"] and pdfs[0] == pdfs[1]


# ----- 18. Dask: absolute paths ---------------------------------------------------------------
def test_a_cluster_is_handed_absolute_paths(tmp_path, monkeypatch):
    """A worker runs in a folder of its own: the drawings' paths, and the exercise's if it
    is a file, are sent absolute, whatever folder the class was named from."""
    from tarsim.exercises.grading import batch

    sent = []
    monkeypatch.setattr(batch, "_on_cluster", lambda jobs, *_: iter(sent.extend(jobs) or []))
    class_of(tmp_path / "class", {"a.svg": Style()})
    shutil.copy(resolve("crank-shaper"), tmp_path / "ex.toml")
    monkeypatch.chdir(tmp_path)
    list(batch.grade_many("ex.toml", [Path("class/a.svg")], 1, scheduler="tcp://x:1"))
    assert sent == [(str(tmp_path / "ex.toml"), 1, str(tmp_path / "class" / "a.svg"))]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.mark.slow
def test_a_relative_class_folder_grades_on_a_local_cluster(tmp_path):
    """The README's cluster: `dask scheduler --host 127.0.0.1` and a `dask worker` started
    in another folder. A class named by a relative path grades there as it does on one
    process (it failed on every drawing when the workers were sent relative paths)."""
    dask = shutil.which("dask")
    if dask is None:
        pytest.skip("the dask command is not installed (pip install 'tarsim[dask]')")
    pytest.importorskip("distributed")
    class_of(tmp_path / "class", {"a.svg": Style(), "b.svg": Style(kind="a"),
                                  "c.svg": Style(moved={"B": (6.0, 0.0)})})
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    port = _free_port()
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
    scheduler = subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port",
                                  str(port), "--no-dashboard"], cwd=elsewhere, **quiet)
    worker = subprocess.Popen([dask, "worker", f"tcp://127.0.0.1:{port}", "--nworkers", "1",
                               "--nthreads", "1", "--no-dashboard"], cwd=elsewhere, **quiet)
    try:
        for _ in range(120):                     # the scheduler and its worker come up
            try:
                from distributed import Client
                with Client(f"tcp://127.0.0.1:{port}", timeout="2s") as c:
                    if c.scheduler_info()["workers"]:
                        break
            except OSError:
                pass
            time.sleep(0.5)
        grade = [sys.executable, "-m", "tarsim", "grade", "crank-shaper", "class", "--position",
                 "2", "--no-pdf"]
        serial = subprocess.run(grade + ["-o", "serial"], cwd=tmp_path, capture_output=True,
                                text=True, timeout=300)
        assert serial.returncode == 0, serial.stderr
        done = subprocess.run(grade + ["-o", "cluster", "--scheduler",
                                       f"tcp://127.0.0.1:{port}"], cwd=tmp_path,
                              capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, done.stderr[-2000:]
    finally:
        for p in (worker, scheduler):
            p.terminate()
            p.wait(timeout=30)
    rows = sheet(tmp_path / "cluster")
    assert rows == sheet(tmp_path / "serial")
    assert all(r["score"] for r in rows) and not any("No such file" in r["note"] for r in rows)
    assert math.isfinite(sum(float(r["score"]) for r in rows))
