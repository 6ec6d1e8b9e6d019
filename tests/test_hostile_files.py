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
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

import tarsim
from tarsim.constructions.errors import TarsimError
from tarsim.exercises.cli import cli
from tarsim.exercises.linkages.mechanism_file import MOST_POINTS
from tarsim.exercises.toml_source import MOST_BYTES
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


SAYS = {
    "not-utf8": r"is not UTF-8 text \(byte 0x[0-9a-f]{2}\); save it as UTF-8",
    "empty": r"the file has no \[frame\] table",
    "not-toml": r":\d+:\d+: not valid TOML: ",
    # The dotted key nests no table TOML keeps: it is one unknown top-level setting.
    "deep-nesting": r"nests arrays or tables too deeply to read|unknown setting 't'",
    "huge": r"is larger than 1,000 kB, the most tarsim reads",
    "too-many-points": rf"names \d+ points; a mechanism may have at most {MOST_POINTS}",
    "control-characters": r"holds the control character U\+[0-9A-F]{4}; remove it"
                          r"|\[frame\.O\\u202e4\] a frame point must be a point name",
    "unknown-keys": r"unknown [a-z ]*setting '",
    "wrong-types": r"must be a number, got|must be a table|needs points = |whole number from 2 up",
    "numbers-out-of-range": r"is out of the range tarsim takes \(between 1e-30 and 1e30|"
                            r"must be a finite number, got -?(nan|inf)",
    "point-twice": r"Cannot overwrite a value|lists a point twice",
    "link-twice": r"\[link 3, number\] link 3 is defined twice",
    "missing-frame": r"the file has no \[frame\] table",
    "input-on-frame": r"\[input\.link\] the frame \(link 1\) cannot be the input",
}
"""What the one line must say for each class of hostile file (tests/random_mechanisms.py)."""

CASES = [pytest.param(cls, variant, id=f"{cls}/{variant}")
         for cls, variants in HOSTILE.items() for variant in variants]


def test_every_hostile_class_says_what_it_is():
    assert set(SAYS) == set(HOSTILE)


@pytest.mark.parametrize("cls, variant", CASES)
def test_a_hostile_file_is_refused_saying_what_is_wrong(tmp_path, cls, variant):
    data = HOSTILE[cls][variant]
    if cls == "huge":
        assert len(data) > MOST_BYTES
    if cls == "too-many-points":
        assert data.count(b" = [") > MOST_POINTS
    path = tmp_path / f"{cls}-{variant}.toml"
    path.write_bytes(data)
    line = refused_in_one_line(path, tmp_path)
    assert re.search(SAYS[cls], line), line
    # Nothing of the file that could reorder or hide the line is printed as it is.
    assert not re.search("[\x00-\x08\u202a-\u202e\u2066-\u2069]", line), repr(line)


@pytest.mark.parametrize("what, says", [("folder", "is a folder; give a mechanism"),
                                        ("/dev/zero", "is not an ordinary file")])
def test_a_folder_or_a_device_given_as_the_file(tmp_path, what, says):
    if what == "/dev/zero" and not os.path.exists(what):
        pytest.skip("no /dev/zero here")
    path = tmp_path / "a-folder.toml" if what == "folder" else Path(what)
    if what == "folder":
        path.mkdir()
    assert says in refused_in_one_line(path, tmp_path)


def test_a_byte_order_mark_is_read_past(tmp_path):
    """Notepad saves UTF-8 with a byte-order mark (EF BB BF), which tomllib takes for a
    statement ("Invalid statement" at 1:1): the file reads as it does without one."""
    from tarsim.exercises.catalog import bundled
    from tarsim.exercises.toml_source import read_source

    plain = bundled()["four-bar"]
    path = tmp_path / "four-bar-bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + plain.read_bytes())
    assert read_source(path) == plain.read_text(encoding="utf-8")
    assert tarsim.load(str(path)).mechanism.links == tarsim.load(str(plain)).mechanism.links
    result = CliRunner().invoke(cli, ["check", str(path)], catch_exceptions=False)
    assert result.exit_code == 0, result.output
