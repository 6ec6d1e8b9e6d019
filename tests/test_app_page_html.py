"""The app page as the server sends it: one HTML document holding its styles and scripts,
allowed to talk to its own server and nothing else (no browser needed)."""

from __future__ import annotations

import re
from importlib import resources

from tarsim.graphics.app_page import SCRIPTS, app_html


def test_the_page_holds_every_script_and_its_styles_inline():
    html = app_html()
    page = resources.files("tarsim.graphics") / "page"
    for name in (*SCRIPTS, "app.css"):
        assert (page / name).read_text(encoding="utf-8") in html, name
    assert "__JS__" not in html and "__CSS__" not in html
    # One inline script and no element that loads anything from elsewhere.
    assert html.count("<script>") == 1 and html.lower().count("</script") == 1
    assert not re.search(r"""(src|href)\s*=\s*["']?(https?:|//)""", html)
    assert not re.search(r"""<(script|link|img|iframe)[^>]*\s(src|href)=""", html)


def test_the_page_may_fetch_from_its_server_alone():
    csp = re.search(r'http-equiv="Content-Security-Policy" content="([^"]+)"', app_html()).group(1)
    rules = dict(r.strip().split(" ", 1) for r in csp.split(";"))
    assert rules["default-src"] == "'none'"
    assert rules["connect-src"] == "'self'"
    assert "unsafe-eval" not in csp
