"""Hostile files: each class is refused in one line, by the Python API and by the command line.

A file no mechanism file should be (not UTF-8, empty, not TOML, nested 500 deep, over the
size cap, too many points, control characters, unknown keys, wrong types, numbers out of
range, a name or number used twice, no frame, the frame driven) must raise one
``TarsimError`` line that names the file, and ``tarsim solve`` must print that line after
``Error:``, exit 1, print no traceback and leave no output folder. The files are built in
tests/random_mechanisms.py (``HOSTILE``), which benchmarks/robustness.py runs too.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from click.testing import CliRunner

import tarsim
from tarsim.constructions.errors import TarsimError
from tarsim.exercises.cli import cli
from tarsim.exercises.mechanism_file import MOST_BYTES, MOST_POINTS
from tests.random_mechanisms import HOSTILE


def refused_in_one_line(path: Path, tmp_path: Path) -> str:
    """Assert the API and the CLI both refuse ``path`` in one line; return the API's line."""
    with pytest.raises(TarsimError) as caught:
        tarsim.solve(tarsim.load(str(path)))
    line = str(caught.value)
    assert line.strip() and "\n" not in line.strip(), line
    assert str(path) in line or f"'{path}'" in line, line

    out = tmp_path / "solution"
    result = CliRunner().invoke(cli, ["solve", str(path), "-o", str(out), "--no-pdf"],
                                catch_exceptions=False)
    assert result.exit_code == 1, result.output
    assert result.stdout == ""
    err = result.stderr
    assert err.startswith("Error: ") and err.count("\n") == 1 and err.endswith("\n"), err
    assert "Traceback" not in err
    assert err == f"Error: {line}\n"
    assert not out.exists()
    return line


def hostile(cls: str, variant: str, tmp_path: Path) -> Path:
    path = tmp_path / f"{cls}-{variant}.toml"
    path.write_bytes(HOSTILE[cls][variant])
    return path


def variants(cls: str):
    return pytest.mark.parametrize("variant", list(HOSTILE[cls]))


@variants("not-utf8")
def test_a_file_that_is_not_utf8(tmp_path, variant):
    line = refused_in_one_line(hostile("not-utf8", variant, tmp_path), tmp_path)
    assert "UTF-8" in line


@variants("empty")
def test_an_empty_file(tmp_path, variant):
    refused_in_one_line(hostile("empty", variant, tmp_path), tmp_path)


@variants("not-toml")
def test_a_file_that_is_not_toml(tmp_path, variant):
    line = refused_in_one_line(hostile("not-toml", variant, tmp_path), tmp_path)
    assert "TOML" in line


@variants("deep-nesting")
def test_arrays_and_tables_nested_500_deep(tmp_path, variant):
    refused_in_one_line(hostile("deep-nesting", variant, tmp_path), tmp_path)


@variants("huge")
def test_a_file_over_the_size_cap(tmp_path, variant):
    path = hostile("huge", variant, tmp_path)
    assert path.stat().st_size > MOST_BYTES
    refused_in_one_line(path, tmp_path)


@variants("too-many-points")
def test_too_many_points(tmp_path, variant):
    assert HOSTILE["too-many-points"][variant].count(b" = [") > MOST_POINTS
    refused_in_one_line(hostile("too-many-points", variant, tmp_path), tmp_path)


@variants("control-characters")
def test_control_characters_and_bidi_overrides_in_names(tmp_path, variant):
    refused_in_one_line(hostile("control-characters", variant, tmp_path), tmp_path)


@variants("unknown-keys")
def test_unknown_keys_and_tables(tmp_path, variant):
    line = refused_in_one_line(hostile("unknown-keys", variant, tmp_path), tmp_path)
    assert "unknown" in line


@variants("wrong-types")
def test_wrong_types(tmp_path, variant):
    refused_in_one_line(hostile("wrong-types", variant, tmp_path), tmp_path)


@variants("numbers-out-of-range")
def test_numbers_out_of_range(tmp_path, variant):
    refused_in_one_line(hostile("numbers-out-of-range", variant, tmp_path), tmp_path)


@pytest.mark.parametrize("what", ["folder", "/dev/zero"])
def test_a_folder_or_a_device_given_as_the_file(tmp_path, what):
    if what == "/dev/zero" and not os.path.exists(what):
        pytest.skip("no /dev/zero here")
    path = tmp_path / "a-folder.toml" if what == "folder" else Path(what)
    if what == "folder":
        path.mkdir()
    refused_in_one_line(path, tmp_path)


@variants("point-twice")
def test_a_point_name_used_twice(tmp_path, variant):
    refused_in_one_line(hostile("point-twice", variant, tmp_path), tmp_path)


@variants("link-twice")
def test_a_link_number_used_twice(tmp_path, variant):
    line = refused_in_one_line(hostile("link-twice", variant, tmp_path), tmp_path)
    assert "link 3" in line


@variants("missing-frame")
def test_a_missing_frame(tmp_path, variant):
    line = refused_in_one_line(hostile("missing-frame", variant, tmp_path), tmp_path)
    assert "[frame]" in line


@variants("input-on-frame")
def test_an_input_on_the_frame(tmp_path, variant):
    line = refused_in_one_line(hostile("input-on-frame", variant, tmp_path), tmp_path)
    assert "frame" in line
