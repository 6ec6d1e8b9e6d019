"""Reproducers of faults in grading drawings, each held to what it must do.

``tests/reproducers/`` holds the drawings and the script that first showed them: a
kilobyte of ``<use>`` that expanded to a million elements, a circle of radius 1e308 that
reached grade.svg as ``r="inf"``, and a class folder whose drawings overwrote each
other's grades and read a file from outside it.
"""

from __future__ import annotations

import csv
import hashlib
import json
import math
import os
import re
import subprocess
import sys
import tracemalloc
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli
from tarsim.graphics.export import MANIFEST, cairo_missing

ROOT = Path(__file__).parent.parent
HERE = Path(__file__).parent / "reproducers"


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args], prog_name="tarsim",
                              catch_exceptions=False)


def finite_json(text: str):
    """grade.json read, refusing the Infinity and NaN Python's json would let through."""
    def refuse(word):
        raise AssertionError(f"grade.json holds {word}")
    return json.loads(text, parse_constant=refuse)


def svg_numbers(svg: str) -> list[str]:
    """Every attribute value of grade.svg that should be a number or a list of them."""
    return [v for k, v in re.findall(r'\s([\w:-]+)="([^"]*)"', svg)
            if k in ("x", "y", "x1", "y1", "x2", "y2", "cx", "cy", "r", "width", "height",
                     "viewBox", "font-size", "stroke-width")]


# ----- dos-svg-use-doubling-16.svg -------------------------------------------------------------
def test_dos_svg_use_doubling_16(tmp_path, monkeypatch):
    """Group l0 holds two labels and a line (4 elements with itself); each l(k) holds two
    <use> of l(k-1), so it expands to c_k = 2 (1 + c_(k-1)) + 1 = 7·2^k − 3 elements. With
    the page, the file's 17 groups expand to 1 + Σ c_k = 7 (2^17 − 1) − 3·17 + 1 = 917,447,
    and the first <use> of l15 to 1 + c_15 = 229,374. Counted on the tree, that is refused
    before svgelements (which took a minute and 1.5 GB to expand it) is ever called."""
    import svgelements

    def never(*args, **kwargs):
        raise AssertionError("svgelements was asked to expand the drawing")
    monkeypatch.setattr(svgelements.SVG, "parse", never)
    total = 7 * (2 ** 17 - 1) - 3 * 17 + 1
    use = 1 + 7 * 2 ** 15 - 3
    assert (total, use) == (917_447, 229_374)
    out = tmp_path / "out"
    tracemalloc.start()
    result = run("grade", "crank-shaper", HERE / "dos-svg-use-doubling-16.svg", "-o", out)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert result.exit_code == 1
    assert result.output == (
        f"Error: dos-svg-use-doubling-16.svg:1: its <use> elements expand it to {total:,} "
        "elements, more than a drawing needs (at most 10,000); this <use> of #l15 alone makes "
        f"{use:,}\n")
    assert not out.exists()
    # The count keeps four numbers for each of the file's 70 elements; the exercise's own
    # solve, done first, takes some megabytes. Expanding took 1.5 GB.
    assert peak < 50_000_000, peak


# ----- nan-svg-circle-inf.svg ------------------------------------------------------------------
def test_nan_svg_circle_inf(tmp_path):
    """The circle of radius 1e308 is left out, and said to be; grade.json and grade.svg
    hold finite numbers only. The line o–a is graded as drawn: at θ2 = 90° with ω2
    clockwise the crank pin moves along +x, as a lies from o, and with no scale written
    (and the crank-shaper's not required) the line sets the drawing's own scale, so a is
    right; the ram's tip b and the slotted link's a4 and b4 are not drawn."""
    out = tmp_path / "out"
    result = run("grade", "crank-shaper", HERE / "nan-svg-circle-inf.svg", "-o", out)
    assert result.exit_code == 0, result.output
    note = ("left out 1 element: <circle> at line 1 (r='1e308' is beyond any drawing)")
    assert f"  note: {note}" in result.output.splitlines()
    grade = finite_json((out / "grade.json").read_text(encoding="utf-8"))
    assert grade["notes"] == [note]
    assert {i["name"]: i["verdict"] for i in grade["items"]} == {
        "a": "correct", "b": "missing", "a4": "missing", "b4": "missing"}
    svg = (out / "grade.svg").read_text(encoding="utf-8")
    numbers = [float(n.removesuffix("mm")) for v in svg_numbers(svg)
               for n in re.split(r"[\s,]+", v.strip())]
    assert len(numbers) > 20 and all(math.isfinite(n) for n in numbers)


# ----- class-folder.sh -------------------------------------------------------------------------
DRAWING = ('<svg xmlns="http://www.w3.org/2000/svg" width="210mm" height="297mm" '
           'viewBox="0 0 210 297"><text x="10" y="10">o</text><text x="60" y="10">a</text>'
           '<line x1="10" y1="10" x2="60" y2="10" stroke="black"/></svg>')
"""The script's drawing: a pole o and the input's tip a, 50 mm apart."""

NAMES = ("a b.svg", "a_b.svg", "..svg", "...svg", "dup.SVG", "dup.svg")


def hashed(name: str, readable: str) -> str:
    """The folder of a name that is not plain: a readable part, a dot, and ten hex digits
    of the name's SHA-256."""
    return f"{readable}.{hashlib.sha256(name.encode()).hexdigest()[:10]}"


def class_folder(tmp_path: Path) -> tuple[Path, Path]:
    """The script's class: six drawings whose names collide once made safe, and a link to
    a drawing outside the class folder."""
    folder, outside = tmp_path / "class", tmp_path / "outside"
    folder.mkdir()
    outside.mkdir()
    for name in NAMES:
        (folder / name).write_text(DRAWING, encoding="utf-8")
    (outside / "secret.svg").write_text(DRAWING, encoding="utf-8")
    (folder / "link-outside.svg").symlink_to(outside / "secret.svg")
    return folder, outside


def tree(folder: Path) -> set[str]:
    return {str(p.relative_to(folder)) for p in folder.rglob("*")}


def test_class_folder(tmp_path):
    """1) Six drawings, six folders: a plain name keeps its stem, any other gets a readable
    part and its own hash, so "a b" and "a_b", "..svg" and "...svg", "dup.SVG" and
    "dup.svg" stay apart; the link out of the class is not followed and its row says why.
    2) A drawing named grades.csv.svg is one more folder, not the class's sheet.
    3) A link planted in the output folder, where a drawing's folder goes, stops the run
    before anything is written, and nothing is written through it."""
    folder, outside = class_folder(tmp_path)
    folders = {"a b.svg": hashed("a b.svg", "a_b"), "a_b.svg": "a_b",
               "..svg": hashed("..svg", "drawing"), "...svg": hashed("...svg", "drawing"),
               "dup.SVG": hashed("dup.SVG", "dup"), "dup.svg": "dup"}
    graded = tmp_path / "graded1"
    result = run("grade", "crank-shaper", folder, "-o", graded)
    assert result.exit_code == 0, result.output
    assert result.output.splitlines()[-1] == (
        f"graded 6 of 7 drawings into {graded}/; 1 could not be read (see grades.csv)")
    each = ("grade.json", "grade.svg", "feedback.html",
            *(("feedback.pdf",) if cairo_missing() is None else ()))
    made = {f"{d}/{n}" for d in folders.values() for n in each}
    assert tree(graded) == set(folders.values()) | made | {"grades.csv", "summary.svg",
                                                           MANIFEST}
    rows = {r["drawing"]: r for r in csv.DictReader(
        (graded / "grades.csv").read_text(encoding="utf-8").splitlines())}
    assert {n: rows[n]["folder"] for n in NAMES} == folders
    assert rows["link-outside.svg"]["folder"] == ""
    assert rows["link-outside.svg"]["note"] == (
        f"not read: a link to {outside / 'secret.svg'}, outside the class folder")
    for name, sub in folders.items():             # each folder holds its own drawing's grade
        assert json.loads((graded / sub / "grade.json").read_text())["drawing"] == name

    (folder / "grades.csv.svg").write_text(DRAWING, encoding="utf-8")
    graded = tmp_path / "graded2"
    result = run("grade", "crank-shaper", folder, "-o", graded)
    assert result.exit_code == 0, result.output
    assert (graded / hashed("grades.csv.svg", "grades_csv") / "grade.json").is_file()
    assert (graded / "grades.csv").read_text(encoding="utf-8").startswith("drawing,folder,")

    (folder / "grades.csv.svg").unlink()
    graded = tmp_path / "graded3"
    graded.mkdir()
    (graded / "a_b").symlink_to(outside)
    result = run("grade", "crank-shaper", folder, "-o", graded)
    assert result.exit_code == 1
    assert result.output.splitlines()[-1] == (
        f"Error: cannot write into '{graded / 'a_b'}': it is a symbolic link, and tarsim "
        "writes only inside the output folder; remove it")
    assert tree(graded) == {"a_b"} and tree(outside) == {"secret.svg"}


def test_class_folder_refuses_a_file_it_did_not_write_before_writing_anything(tmp_path):
    """A drawing's folder holding a grade.json tarsim did not write: the run stops, and
    every folder stays as it was."""
    folder, _ = class_folder(tmp_path)
    graded = tmp_path / "graded"
    (graded / "dup").mkdir(parents=True)
    (graded / "dup" / "grade.json").write_text("mine", encoding="utf-8")
    result = run("grade", "crank-shaper", folder, "-o", graded)
    assert result.exit_code == 1
    assert result.output.splitlines()[-1] == (
        f"Error: cannot write '{graded / 'dup' / 'grade.json'}': a file of that name is "
        "already there and tarsim did not write it; move it or choose another folder with -o")
    assert tree(graded) == {"dup", "dup/grade.json"}


def test_class_folder_grades_again_into_its_own_folders(tmp_path):
    """A second run into the same folder replaces the first's files (they are listed as
    tarsim's), a drawing gone from the class takes its folder with it, and grades.csv,
    written by tarsim into the class folder, is not a drawing."""
    folder, _ = class_folder(tmp_path)
    graded = tmp_path / "graded"
    assert run("grade", "crank-shaper", folder, "-o", graded).exit_code == 0
    (folder / "dup.svg").unlink()
    result = run("grade", "crank-shaper", folder, "-o", graded)
    assert result.exit_code == 0, result.output
    assert not (graded / "dup").exists() and (graded / hashed("dup.SVG", "dup")).is_dir()
    for _ in range(2):
        result = run("grade", "crank-shaper", folder, "-o", folder)
        assert result.exit_code == 0, result.output
        assert "graded 5 of 6 drawings" in result.output


def test_class_folder_link_planted_while_grading_is_not_written_through(tmp_path,
                                                                          monkeypatch):
    """The link appears while the class is graded, after the output folder was looked at:
    the class is written as one set, which refuses it before anything moves."""
    from tarsim.exercises.grading import class_grades

    folder, outside = class_folder(tmp_path)
    graded = tmp_path / "graded"
    grade_many = class_grades.grade_many

    def planting(*args, **kwargs):
        graded.mkdir(exist_ok=True)
        (graded / "a_b").symlink_to(outside)
        yield from grade_many(*args, **kwargs)
    monkeypatch.setattr(class_grades, "grade_many", planting)
    result = run("grade", "crank-shaper", folder, "-o", graded)
    assert result.exit_code == 1
    assert result.output.splitlines()[-1] == (
        f"Error: cannot write into '{graded / 'a_b'}': it is a symbolic link, and tarsim "
        "writes only inside the output folder; remove it")
    assert tree(graded) == {"a_b"} and tree(outside) == {"secret.svg"}


@pytest.mark.slow
def test_class_folder_script(tmp_path):
    """The script itself, run with this Python's tarsim: the same six folders, the same
    refusal of the planted link, nothing written outside."""
    env = {**os.environ, "T": f"{sys.executable} -m tarsim", "TMPDIR": str(tmp_path)}
    done = subprocess.run(["sh", str(HERE / "class-folder.sh")], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=300, check=False)
    lines = done.stdout.splitlines()
    listing = ["a_b", hashed("a b.svg", "a_b"), hashed("...svg", "drawing"),
               hashed("..svg", "drawing"), "dup", hashed("dup.SVG", "dup"), "grades.csv"]
    first = lines.index("a_b")
    assert lines[first:first + 7] == listing, done.stdout
    assert "rc=0" in lines
    second = lines.index("a_b", first + 1)
    assert lines[second:second + 8] == sorted(listing + [hashed("grades.csv.svg",
                                                                "grades_csv")]), done.stdout
    assert lines[-3:] == [".", "..", "secret.svg"], done.stdout
    assert "it is a symbolic link, and tarsim writes only inside the output folder" in \
        done.stderr
