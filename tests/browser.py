"""A real browser for the tests: Debian's chromium, driven by playwright.

playwright cannot download its own browsers here, so it is pointed at the system's
chromium (``apt-get install chromium``). Without either, a browser test fails with one
line saying what to install: a browser check that skips itself would pass unseen.
"""

from __future__ import annotations

import shutil
from collections.abc import Iterator
from contextlib import contextmanager

import pytest

NEEDS = ("the browser tests need playwright (pip install '.[test]') and Debian's chromium "
         "(apt-get install chromium)")


@contextmanager
def chromium() -> Iterator[object]:
    """A headless chromium (a playwright Browser), closed on leaving."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        pytest.fail(NEEDS, pytrace=False)
    path = shutil.which("chromium") or shutil.which("chromium-browser")
    if path is None:
        pytest.fail(NEEDS, pytrace=False)
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=path, args=["--no-sandbox"])
        try:
            yield browser
        finally:
            browser.close()
