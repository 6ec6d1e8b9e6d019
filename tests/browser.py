"""A real browser for the tests: Debian's chromium, driven by playwright.

playwright cannot download its own browsers here, so it is pointed at the system's
chromium (``apt-get install chromium``). Without either, a browser test skips with one
line saying what to install, so the README's test command passes on a machine that has
no browser. Where a skip would hide a failure (CI, which installs chromium), set
``TARSIM_REQUIRE_BROWSER=1``: a missing browser then fails every browser test with the
same line.
"""

from __future__ import annotations

import os
import shutil
from collections.abc import Iterator
from contextlib import contextmanager

import pytest

REQUIRE = "TARSIM_REQUIRE_BROWSER"
"""Set to 1 (as .ci/run sets it), a missing browser fails the browser tests."""

NEEDS = ("no browser: the browser tests need playwright (pip install '.[test]') and Debian's "
         "chromium (apt-get install chromium)")


def required() -> bool:
    """True if a missing browser must fail the tests (``TARSIM_REQUIRE_BROWSER`` set, and
    not to 0 or empty)."""
    return os.environ.get(REQUIRE, "") not in ("", "0")


def missing() -> None:
    """Skip the test for want of a browser, saying what to install; fail it instead under
    ``TARSIM_REQUIRE_BROWSER``."""
    if required():
        pytest.fail(f"{NEEDS}; {REQUIRE} is set, so this fails rather than skips",
                    pytrace=False)
    pytest.skip(NEEDS)


@contextmanager
def chromium() -> Iterator[object]:
    """A headless chromium (a playwright Browser), closed on leaving."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        missing()
    path = shutil.which("chromium") or shutil.which("chromium-browser")
    if path is None:
        missing()
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=path, args=["--no-sandbox"])
        try:
            yield browser
        finally:
            browser.close()
