"""The app page of ``tarsim serve``: one self-contained HTML document.

Its stylesheet and scripts are inline, as the view page's are (:mod:`.view_page`), and its
Content-Security-Policy lets it talk to the server that sent it and nothing else: no CDN,
no font or script from the network. The scripts hold the mechanism as the exercise file
itself and write it out as TOML (``page/app_toml.js``, ``page/app_model.js``); the
server solves it and the page shows what comes back (``page/app_view.js``). Nothing of
the mechanism's motion is computed in the page.
"""

from __future__ import annotations

from functools import cache
from importlib import resources

__all__ = ["app_html", "SCRIPTS"]

SCRIPTS = ("app_words.js", "app_toml.js", "app_model.js", "app_editor.js", "app_panel.js",
           "app_view.js")
"""The page's scripts, in the order they are run: each uses only those before it."""


def _asset(name: str) -> str:
    return (resources.files(__package__) / "page" / name).read_text(encoding="utf-8")


@cache
def app_html() -> str:
    """The page, as one HTML document (the same for every request: the server sends it as
    it is, and the page asks for its exercise)."""
    # "</" would end the script element; no script of the page writes one.
    js = "\n".join(_asset(name) for name in SCRIPTS)
    if "</script" in js.lower():
        raise ValueError("a script of the app page holds '</script'")
    return _asset("app.html").replace("__CSS__", _asset("app.css")).replace("__JS__", js)
