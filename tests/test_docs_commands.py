"""Every command the README and the guides show runs, and prints what they say it prints.

Each page is run top to bottom in a folder of its own, as a reader would type it
(:mod:`doc_blocks` says how a page marks its blocks). A command that fails, a printed
sample that no longer matches, or a file the page saves that no longer solves fails
here, naming the page and line.
"""

from __future__ import annotations

import doctest
import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.doc_blocks import blocks, commands, console_pairs

ROOT = Path(__file__).resolve().parents[1]
PAGES = sorted([ROOT / "README.md", *(ROOT / "docs").rglob("*.md")])
_CHECK = doctest.OutputChecker()
_FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE


def _run(command: str, cwd: Path) -> subprocess.CompletedProcess:
    """Run ``command`` as a reader's shell would, its two streams in the order the reader
    sees them."""
    env = dict(os.environ, PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}",
               COLUMNS="100", NO_COLOR="1")
    return subprocess.run(["bash", "-c", command], cwd=cwd, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=600)


def test_the_pages_are_found():
    assert (ROOT / "README.md") in PAGES
    assert len(PAGES) >= 2, "docs/ holds the guides"


@pytest.mark.slow
@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_command_on_the_page_runs_as_shown(page, tmp_path):
    ran = 0
    for block in blocks(page.read_text(encoding="utf-8")):
        if block.skip is not None:
            assert block.skip, f"{block.where(page)}: say why a block is not run"
            continue
        if block.file:
            target = tmp_path / block.file
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(block.body, encoding="utf-8")
        elif block.lang == "sh":
            for command in commands(block.body):
                done = _run(command, tmp_path)
                assert done.returncode == 0, (
                    f"{block.where(page)}: `{command}` exited {done.returncode}:\n"
                    f"{done.stdout[-2000:]}")
                ran += 1
        elif block.lang == "console":
            for command, want in console_pairs(block.body):
                done = _run(command, tmp_path)
                got = done.stdout
                assert _CHECK.check_output(want, got, _FLAGS), (
                    f"{block.where(page)}: `{command}` prints\n{got}\nwhere the page shows\n{want}")
                ran += 1
    runnable = [b for b in blocks(page.read_text(encoding="utf-8"))
                if b.lang in ("sh", "console") and b.skip is None]
    assert ran >= len(runnable), f"{page.name}: a block ran no command"
