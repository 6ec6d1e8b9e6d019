"""The guides teach what the software does: the Python example runs, every command is shown.

The Python API page's example (docs/reference/api.md) is run as a doctest in a fresh
folder, so a changed API, a changed number or a missing file shows here. Every command
has ``--help`` text with an example, and an example in the README or a guide.
"""

from __future__ import annotations

import doctest
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli

ROOT = Path(__file__).resolve().parents[1]
API = (ROOT / "docs" / "reference" / "api.md").read_text(encoding="utf-8")
PAGES = "\n".join(p.read_text(encoding="utf-8")
                  for p in [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))])


@pytest.mark.slow
def test_the_python_api_example_runs_as_written(tmp_path, monkeypatch):
    blocks = re.findall(r"```pycon\n(.*?)```", API, re.S)
    assert blocks, "the Python API page shows an interactive example"
    monkeypatch.chdir(tmp_path)
    parser = doctest.DocTestParser()
    test = parser.get_doctest("\n".join(blocks), {}, "Python API", "docs/reference/api.md", 0)
    assert len(test.examples) >= 8
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    report = []
    runner.run(test, out=report.append)
    assert runner.failures == 0, "".join(report)
    assert (tmp_path / "centres.svg").stat().st_size > 1000
    assert (tmp_path / "four-bar-solution" / "results.json").exists()


@pytest.mark.parametrize("command", sorted(cli.commands))
def test_every_command_teaches_with_an_example(command):
    result = CliRunner().invoke(cli, [command, "--help"])
    assert result.exit_code == 0
    assert "Example:" in result.output, f"tarsim {command} --help shows no example"
    assert re.search(rf"^(\$ )?tarsim {command}\b", PAGES, re.M), \
        f"neither the README nor a guide shows `tarsim {command}`"
