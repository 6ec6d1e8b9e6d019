"""The interactive page (``tarsim view``): one self-contained HTML file.

The page is its data (:func:`~tarsim.exercises.linkages.view.view_data`, as JSON), a stylesheet
and a script, all inline: no network, no CDN, no server, so it opens from disk in any
current browser and its Content-Security-Policy forbids it to fetch anything. The
script (``page/view.js``, with ``page/view_numbers.js`` for the readout and the curve)
draws no figure of its own: it writes the figures' primitives
as the SVG writer does (:mod:`.figure_data`) and moves them with the named points each
frame gives (:mod:`.figure_anchors`).
"""

from __future__ import annotations

import json
from functools import cache
from importlib import resources
from typing import Any

__all__ = ["view_html", "ViewPage"]


@cache
def _asset(name: str) -> str:
    return (resources.files(__package__) / "page" / name).read_text(encoding="utf-8")


def view_html(data: dict[str, Any]) -> str:
    """The page for ``data``, as one HTML document."""
    # "</" would end the script element the JSON sits in; "<\\/" reads back the same.
    payload = json.dumps(data, separators=(",", ":"), ensure_ascii=False).replace("</", "<\\/")
    title = data["title"].get("en", "tarsim")
    return (_asset("view.html")
            .replace("__TITLE__", _escape(title))
            .replace("__CSS__", _asset("view.css"))
            .replace("__JS__", _asset("view_numbers.js") + _asset("view.js"))
            .replace("__DATA__", payload))


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


class ViewPage:
    """The page as a notebook shows it: in a frame of its own, so its script and styles
    stay apart from the notebook's."""

    def __init__(self, html: str):
        self.html = html

    def _repr_html_(self) -> str:
        import html as h

        return (f'<iframe srcdoc="{h.escape(self.html, quote=True)}" '
                'style="width:100%;height:900px;border:1px solid #ddd"></iframe>')

    def save(self, path) -> None:
        """Write the page to ``path`` (UTF-8)."""
        from pathlib import Path

        Path(path).write_text(self.html, encoding="utf-8")
