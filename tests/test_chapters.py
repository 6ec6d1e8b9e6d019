"""The chapter registry: every file finds its chapter by its tables, is read and parsed
once, and no code but the registry chooses a chapter."""

from __future__ import annotations

import ast
import tomllib
from pathlib import Path

import pytest
from click.testing import CliRunner

import tarsim
import tarsim.exercises as exercises
from tarsim.exercises import toml_source
from tarsim.exercises.catalog import bundled, everything, load
from tarsim.exercises.chapters import REGISTERED, chapter_for, chapter_of, chapters
from tarsim.exercises.cli import cli


def test_every_registered_chapter_is_its_package():
    assert [c.key for c in chapters()] == list(REGISTERED)
    # one chapter takes every file no other claims (the linkages), and only one
    assert [c.key for c in chapters() if not c.tables] == ["linkages"]


@pytest.mark.parametrize("chapter", chapters(), ids=lambda c: c.key)
def test_each_bundled_file_is_told_by_its_tables_as_its_folders_chapter(chapter):
    paths = [p for folder in chapter.folders for p in bundled(folder).values()]
    assert paths, f"{chapter.key} bundles no exercise"
    for path in paths:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        assert chapter_for(data) is chapter, path.name
        assert chapter_of(load(str(path))) is chapter, path.name


def test_the_catalog_lists_each_chapter_s_folders_in_the_registry_s_order():
    order = [c.key for c in chapters() for folder in c.folders for _ in bundled(folder)]
    listed = [chapter_of(load(i)).key for i in everything()]
    assert listed == order


@pytest.mark.parametrize("args", [
    ["solve", "four-bar", "--no-pdf"],
    ["solve", "planetary-q1", "--no-pdf"],
    ["solve", "roller-harmonic-cycloidal", "--no-pdf"],
    ["draw", "four-mass-shaft"],
    ["check", "crank-shaper"],
])
def test_a_command_reads_and_parses_its_file_once(args, tmp_path, monkeypatch):
    reads, parses = [], []
    read, parse = toml_source.read_source, tomllib.loads
    monkeypatch.setattr(toml_source, "read_source", lambda p: reads.append(p) or read(p))
    monkeypatch.setattr(tomllib, "loads", lambda t: parses.append(1) or parse(t))
    out = ["-o", str(tmp_path / ("x.svg" if args[0] == "draw" else "out"))]
    result = CliRunner().invoke(cli, args + (out if args[0] != "check" else []))
    assert result.exit_code == 0, result.output
    assert len(reads) == 1 and len(parses) == 1, (reads, parses)


@pytest.mark.parametrize("exercise_id", ["planetary-q1", "oscillating-roller", "inline-four"])
@pytest.mark.parametrize("command", ["solve", "draw"])
def test_an_angle_is_refused_in_one_line_where_a_chapter_has_none(exercise_id, command,
                                                                    tmp_path):
    chapter = chapter_of(load(exercise_id))
    result = CliRunner().invoke(cli, [command, exercise_id, "--angle", "30", "-o",
                                      str(tmp_path / "x.svg")])
    assert result.exit_code == 1
    assert result.output == f"Error: {chapter.no_angle}\n"
    assert not (tmp_path / "x.svg").exists()


def test_a_linkage_command_refuses_another_chapter_s_file_naming_it():
    result = CliRunner().invoke(cli, ["check", "planetary-q1"])
    assert result.exit_code == 1
    assert result.output == ("Error: planetary-q1 is a gear train: `tarsim solve planetary-q1` "
                             "solves it; this command is for linkages\n")


def test_tarsim_solve_finds_the_chapter_of_each_kind_of_exercise():
    # each chapter's solution, found through the registry, agrees with its reference
    for exercise_id in ("four-bar", "planetary-q1", "oscillating-roller", "four-mass-shaft"):
        solution = tarsim.solve(tarsim.load(exercise_id))
        assert solution.failures == [], exercise_id


def test_no_code_outside_the_registry_chooses_a_chapter_by_type():
    # The exercise classes of the chapters: an isinstance test on one of them is a chapter
    # chosen by type, which the registry (chapter_of) replaces.
    kinds = {"Exercise", "TrainExercise", "CamExercise", "BalanceExercise"}
    root = Path(exercises.__file__).parent
    found = []
    for path in root.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (isinstance(node, ast.Call) and getattr(node.func, "id", "") == "isinstance"
                    and len(node.args) == 2):
                named = {n.id for n in ast.walk(node.args[1]) if isinstance(n, ast.Name)}
                if named & kinds:
                    found.append(f"{path.relative_to(root)}:{node.lineno}")
    assert found == []
