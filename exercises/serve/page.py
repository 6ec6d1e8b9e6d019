"""The app page ``GET /`` answers: one self-contained HTML document, its styles and script
inline, as ``tarsim view``'s page is.

The page is graphics/page/app.html with app.css and the app's scripts set in it. Where
the graphics layer gives the page whole (``tarsim.graphics.app_page.app_html``), that is
what is served; before the page is there, a short page says what the server answers.
"""

from __future__ import annotations

from importlib import import_module, resources

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
        maker = import_module("tarsim.graphics.app_page").app_html
    except (ImportError, AttributeError):
        maker = None
    if maker is not None:
        return maker()
    folder = resources.files("tarsim.graphics") / "page"
    html = folder / "app.html"
    if not html.is_file():
        return _PLACEHOLDER
    css = folder / "app.css"
    # The scripts of the page, the app's own last: its parts are defined before it runs.
    scripts = sorted((p for p in folder.iterdir() if p.name.startswith("app")
                      and p.name.endswith(".js")), key=lambda p: (p.name == "app.js", p.name))
    return (html.read_text(encoding="utf-8")
            .replace("__CSS__", css.read_text(encoding="utf-8") if css.is_file() else "")
            .replace("__JS__", "\n".join(p.read_text(encoding="utf-8") for p in scripts)
                     .replace("</script", "<\\/script")))
