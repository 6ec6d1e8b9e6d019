"""The page a student reads their grade on: feedback.html, and feedback.pdf where cairo is.

The page holds the overlay (:mod:`.overlay`: their drawing, tarsim's polygons over it,
each wrong item ringed and explained), the score, and a row for each item: its verdict,
the tolerance it was held to and the advice in words. The HTML is one self-contained file
(the overlay inline, no script, nothing fetched: its Content-Security-Policy forbids it);
the PDF is the same page set as an SVG sheet A4 wide, as long as its rows need, converted
by cairosvg. Headings and verdicts are in the language spoken (``--lang``); the advice is
the grader's own sentence.
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass

from tarsim.constructions.narration import Number, measure_words, numerals, right_to_left, words
from tarsim.graphics.figure import wrap_text
from tarsim.graphics.rtl import RTL_FONT, is_rtl
from .grade import Grade
from .overlay import AMBER, FOLLOWS, RED, credited, named, sans_width

__all__ = ["feedback_html", "feedback_sheet", "feedback_pdf", "Line"]


@dataclass(frozen=True)
class Line:
    """An item as the page says it: its name, verdict, tolerance and advice, in words, and
    whether it earns its points."""

    name: str
    verdict: str
    tolerance: str
    advice: str
    correct: bool


def lines(g: Grade) -> list[Line]:
    """Each item of ``g`` in words: a drawn item's tolerance in paper mm, a table's in
    the answer's own SI unit."""
    out = []
    for i in g.items:
        if i.tolerance is None:
            tol = ""
        elif g.overlay is not None:
            tol = "± " + measure_words(f"{i.tolerance:.3g} mm")
        else:
            tol = "± " + numerals(f"{i.tolerance:.3g}")
        out.append(Line(i.name, words(i.verdict), tol, i.message, credited(g, i)))
    return out


def _heading(g: Grade, who: str, position: int | None,
             name=lambda text: text) -> tuple[str, str, str]:
    """The page's title, what was graded (at the exercise's ``position``-th position, from
    0, if given), and the score, in words; ``name`` marks the names in them (a student's,
    a file's, the exercise's)."""
    took = sum(credited(g, i) for i in g.items)
    title = words("Feedback: {who}", who=name(who or g.source))
    what = (words("{exercise}: {drawing}", exercise=name(g.exercise), drawing=name(g.source))
            if position is None else
            words("{exercise}, position {position}: {drawing}", exercise=name(g.exercise),
                  position=Number(position + 1, "d"), drawing=name(g.source)))
    score = words("score {score} % ({credited} of {total} items credited)",
                  score=Number(g.score, ".0f"), credited=Number(took, "d"),
                  total=Number(len(g.items), "d"))
    return title, what, score


_STYLE = """
body { font-family: "DejaVu Sans", "Vazirmatn", Tahoma, sans-serif; margin: 2em auto;
       max-width: 52em; padding: 0 1em; color: #222; line-height: 1.45; }
h1 { font-size: 1.4em; margin-bottom: 0.2em; }
.what { color: #555; margin-top: 0; }
.score { font-size: 1.25em; font-weight: bold; }
figure { margin: 1em 0; }
figure svg { width: 100%; height: auto; border: 1px solid #ddd; }
table { border-collapse: collapse; width: 100%; }
th, td { border-bottom: 1px solid #ddd; padding: 0.35em 0.5em; vertical-align: top;
         text-align: start; }
td.wrong { color: #c62828; font-weight: bold; }
td.right { color: #2e7d32; }
td.follows { color: #b26a00; }
.notes { color: #555; }
"""

_CSP = "default-src 'none'; style-src 'unsafe-inline'; img-src data:"
"""The page fetches nothing and runs nothing: a student's file name or label in it is
text, whatever it says."""


def feedback_html(g: Grade, who: str = "", overlay: str | None = None,
                  position: int | None = None) -> str:
    """feedback.html of the grade ``g`` for the student ``who`` (their name and id; the
    file's name if empty), with the overlay's SVG ``overlay`` inline if it has one, at the
    exercise's ``position``-th position (from 0) if given."""
    title, what, score = _heading(g, who, position, lambda text: f"\x00{text}\x01")
    lang, way = ("fa", "rtl") if right_to_left() else ("en", "ltr")

    def e(text: str) -> str:
        """``text`` escaped, each name in it isolated (<bdi>), so that a name of Latin
        letters and digits keeps its order on a right-to-left page."""
        return html.escape(text).replace("\x00", "<bdi>").replace("\x01", "</bdi>")
    rows = "\n".join(
        f'<tr><td dir="ltr">{e(r.name)}</td>'
        f'<td class="{_kind(r)}">{e(r.verdict)}</td>'
        f"<td>{e(r.tolerance)}</td>"
        f'<td dir="{"rtl" if is_rtl(r.advice) else "ltr"}">{e(r.advice)}</td></tr>'
        for r in lines(g))
    head = "".join(f"<th>{e(words(h))}</th>" for h in ("item", "verdict", "tolerance",
                                                        "advice"))
    notes = "".join(f'<li dir="ltr">{e(n)}</li>' for n in g.notes)
    parts = [
        "<!DOCTYPE html>", f'<html lang="{lang}" dir="{way}">', "<head>",
        '<meta charset="utf-8">',
        f'<meta http-equiv="Content-Security-Policy" content="{_CSP}">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f"<title>{html.escape(title.translate({0: None, 1: None}))}</title>",
        f"<style>{_STYLE}</style>", "</head>", "<body>",
        f"<h1>{e(title)}</h1>", f'<p class="what">{e(what)}</p>',
        f'<p class="score">{e(score)}</p>']
    if overlay:
        parts.append(f"<figure>{overlay}</figure>")
    if g.items:
        parts += ["<table>", f"<thead><tr>{head}</tr></thead>", f"<tbody>{rows}</tbody>",
                  "</table>"]
    if notes:
        parts += [f"<h2>{e(words('notes'))}</h2>", f'<ul class="notes">{notes}</ul>']
    parts += ["</body>", "</html>", ""]
    return "\n".join(parts)


def _kind(r: Line) -> str:
    """A verdict's class on the page (its colour): right, follows or wrong."""
    return "follows" if r.verdict == words(FOLLOWS) else "right" if r.correct else "wrong"


# ----- the same page as an SVG sheet, for the PDF ----------------------------------------
_PAGE = 210.0
"""The sheet's width (mm): A4's; it is as long as its rows need, at least A4's 297."""

_MARGIN, _BODY, _SMALL = 15.0, 3.4, 2.9
"""The sheet's margin, and its text sizes (mm)."""

_COLOURS = {"right": "#2e7d32", "follows": AMBER, "wrong": RED}
"""A verdict's colour on the sheet, by its class on the page."""

_COLUMNS = (0.0, 18.0, 58.0, 84.0)
"""Where the item, verdict, tolerance and advice columns start, from the text's edge (mm)."""


def feedback_sheet(g: Grade, who: str = "", overlay: str | None = None,
                   position: int | None = None) -> str:
    """feedback.html's page (its arguments are :func:`feedback_html`'s) as an SVG sheet:
    the heading, the overlay fitted to the sheet's width, and a row an item, its verdict
    and advice wrapped to their columns."""
    from tarsim.graphics.svg_tree import Drawing

    title, what, score = _heading(g, who, position, named)
    width = _PAGE - 2 * _MARGIN
    rtl = right_to_left()
    dwg = Drawing(profile="full", debug=False)
    body = dwg.add(dwg.g(font_family="DejaVu Sans", font_size=_BODY, fill="#222"))

    def say(text: str, x: float, y: float, **style):
        """A text from ``x`` along the line (from the right edge in Persian)."""
        at = _PAGE - _MARGIN - x if rtl else _MARGIN + x
        if is_rtl(text):
            style |= {"direction": "rtl", "text_anchor": "start", "font_family": RTL_FONT}
        elif rtl:
            style |= {"text_anchor": "end"}
        body.add(dwg.text(text, insert=(at, y), **style))

    y = _MARGIN + 6.0
    say(title, 0, y, font_size=5.0, font_weight="bold")
    y += 7.0
    say(what, 0, y, fill="#555")
    y += 7.0
    say(score, 0, y, font_size=4.2, font_weight="bold")
    y += 4.0 if overlay else 10.0
    inner = ""
    if overlay:
        shown = _fitted(overlay, width)
        x = _PAGE - _MARGIN - _width(shown) if rtl else _MARGIN
        inner = shown.replace("<svg ", f'<svg x="{x:.2f}" y="{y:.2f}" ', 1)
        y += _height(shown) + 6.0
    if g.items:
        for x, h in zip(_COLUMNS, ("item", "verdict", "tolerance", "advice")):
            say(words(h), x, y, font_weight="bold")
        y += 2.0
        for r in lines(g):
            y += 1.4 * _BODY
            say(r.name, _COLUMNS[0], y)
            say(r.tolerance, _COLUMNS[2], y)
            cells = [(wrap_text(r.verdict, _BODY, _COLUMNS[2] - _COLUMNS[1] - 2.0,
                                measure=sans_width), _COLUMNS[1], _BODY, _COLOURS[_kind(r)]),
                     (wrap_text(r.advice, _SMALL, width - _COLUMNS[3], measure=sans_width),
                      _COLUMNS[3], _SMALL, "#222")]
            for parts, x, size, colour in cells:
                for k, part in enumerate(parts):
                    say(part, x, y + 1.3 * size * k, font_size=size, fill=colour)
            y += max(1.3 * size * (len(parts) - 1) for parts, _, size, _ in cells)
    if g.notes:
        y += 2.4 * _BODY
        say(words("notes"), 0, y, font_weight="bold")
        for note in g.notes:
            for part in wrap_text(note, _SMALL, width, measure=sans_width):
                y += 1.3 * _SMALL
                say(part, 0, y, font_size=_SMALL, fill="#555")
    height = max(297.0, y + _MARGIN)
    dwg["width"], dwg["height"] = f"{_PAGE}mm", f"{height:.2f}mm"
    dwg["viewBox"] = f"0 0 {_PAGE} {height:.2f}"
    dwg["direction"] = "ltr"
    sheet = dwg.tostring()                   # the overlay nested whole, as its own <svg>
    return sheet[:sheet.rindex("</svg>")] + inner + "</svg>"


def feedback_pdf(g: Grade, who: str = "", overlay: str | None = None,
                 position: int | None = None) -> bytes:
    """feedback.pdf: :func:`feedback_sheet` converted by cairosvg (Persian shaped first).

    Raises
    ------
    RenderError
        If cairosvg or libcairo2 is missing.
    """
    from tarsim.graphics.export import svg_to

    return svg_to(feedback_sheet(g, who, overlay, position), "pdf")


def _fitted(svg: str, width: float) -> str:
    """The overlay ``svg`` with its width set to ``width`` mm and its height to match."""
    w = float(re.search(r'\swidth="([\d.]+)mm"', svg)[1])
    h = float(re.search(r'\sheight="([\d.]+)mm"', svg)[1])
    shown_w = min(width, w)
    shown_h = h * shown_w / w
    svg = re.sub(r'\swidth="[\d.]+mm"', f' width="{shown_w:.2f}"', svg, count=1)
    return re.sub(r'\sheight="[\d.]+mm"', f' height="{shown_h:.2f}"', svg, count=1)


def _height(svg: str) -> float:
    """The height (mm) of an overlay :func:`_fitted` to the sheet."""
    return float(re.search(r'\sheight="([\d.]+)"', svg)[1])


def _width(svg: str) -> float:
    """The width (mm) of an overlay :func:`_fitted` to the sheet."""
    return float(re.search(r'\swidth="([\d.]+)"', svg)[1])
