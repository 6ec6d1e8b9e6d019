"""The guides in docs/ build into a site, and their generated pages say what tarsim does now.

The command-line reference and the catalog are made from the software itself
(docs/make_reference.py, docs/make_catalog.py); a command or an exercise added without
making them again fails here, as does a page the site cannot build (a broken link, a
page missing from the navigation, an API docstring that cannot be read: mkdocs' strict
mode turns each warning into a failure).
"""

from __future__ import annotations

import importlib.util
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"


def _script(name: str):
    spec = importlib.util.spec_from_file_location(name, DOCS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_command_line_reference_is_the_commands_own_help():
    page = (DOCS / "reference" / "cli.md").read_text(encoding="utf-8")
    assert page == _script("make_reference").page(), \
        "docs/reference/cli.md is stale: run python docs/make_reference.py"


def test_the_catalog_lists_every_bundled_exercise_with_its_thumbnail():
    from tarsim.exercises.catalog import everything

    page = (DOCS / "catalog.md").read_text(encoding="utf-8")
    listed = re.findall(r"^### `([\w-]+)`$", page, re.M)
    assert listed and sorted(listed) == sorted(everything()), \
        "docs/catalog.md is stale: run python docs/make_catalog.py"
    for name in listed:
        assert (DOCS / "catalog" / f"{name}.png").stat().st_size > 2000, name
    assert page == _script("make_catalog").page()


def test_the_readme_stays_short_and_links_only_to_pages_that_exist():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert readme.count("\n") < 250
    for target in re.findall(r"\]\(([^)#]+)", readme):
        if not target.startswith("http"):
            assert (ROOT / target).exists(), f"the README links to {target}, which is not there"


@pytest.mark.slow
def test_the_site_builds_offline_in_strict_mode(tmp_path):
    if importlib.util.find_spec("mkdocs") is None:
        pytest.skip("mkdocs is not installed: pip install '.[docs]'")
    done = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "-q",
                           "--site-dir", str(tmp_path / "site")], cwd=ROOT,
                          env={**os.environ, "NO_MKDOCS_2_WARNING": "1"},
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-3000:]
    index = (tmp_path / "site" / "index.html").read_text(encoding="utf-8")
    assert "tarsim" in index
    # nothing the reader's browser would fetch from elsewhere: fonts, scripts, styles
    for page in (tmp_path / "site").rglob("*.html"):
        text = page.read_text(encoding="utf-8")
        assert not re.search(r"(src|href)=\"https?://(fonts\.|cdn|unpkg)", text), page.name
    api = (tmp_path / "site" / "reference" / "api" / "index.html").read_text(encoding="utf-8")
    assert "Read an exercise" in api, "the API page carries tarsim.load's docstring"


def _asked_rows():
    page = (DOCS / "reference" / "asks.md").read_text(encoding="utf-8")
    return re.findall(r"^\| `[^|]*` \| `([^`]+)` \| `([\w-]+)` \|", page, re.M)


def test_the_asks_page_has_a_row_for_every_chapter_that_asks():
    rows = _asked_rows()
    assert len(rows) >= 35
    assert {"centres", "F_23", "omega4/omega2", "contact_ratio", "n_centres"} <= \
        {example for example, _ in rows}


@pytest.mark.parametrize("example, exercise", _asked_rows(), ids=lambda v: str(v))
def test_each_example_on_the_asks_page_is_answered_there(example, exercise, tmp_path):
    """The example, asked alone of the bundled exercise the row names, is read without a
    refusal: the page names nothing its chapter would refuse."""
    from tarsim.exercises.catalog import everything
    from tarsim.exercises.chapters import read_file

    text = Path(everything()[exercise]).read_text(encoding="utf-8")
    asked = f'find = ["{example}"]'
    if re.search(r"^find\s*=", text, re.M):
        text = re.sub(r"^find\s*=\s*\[.*?\]", asked, text, count=1, flags=re.S | re.M)
    else:
        text += f"\n[ask]\n{asked}\n"
    path = tmp_path / f"{exercise}.toml"
    path.write_text(text, encoding="utf-8")
    read = read_file(path, exercise)
    # a linkage keeps its asks as the file names them (find), a gear train as asks
    asked = getattr(read, "find", None) or read.asks
    assert tuple(asked) == (example,)
