"""The app page ``GET /`` answers: one self-contained HTML document, its styles and scripts
inline, as the graphics layer makes it (``tarsim.graphics.app_page.app_html``); where that
is not installed, a short page that says what the server answers."""

from __future__ import annotations

from importlib import import_module

__all__ = ["app_page"]

_PLACEHOLDER = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>tarsim serve</title></head>
<body><h1>tarsim serve</h1>
<p>The app page is not installed with this tarsim. The server answers
<code>GET /api/exercises</code>, <code>GET /api/exercise?id=four-bar</code> and
<code>POST /api/solve</code> (see docs/howto/app.md).</p></body></html>
"""


def app_page() -> str:
    """The app's page as one HTML document (a short placeholder if it is not installed)."""
    try:
        make = import_module("tarsim.graphics.app_page").app_html
    except (ImportError, AttributeError):
        return _PLACEHOLDER
    return make()
