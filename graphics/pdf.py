"""Draw a :class:`~graphics.figure.Figure` straight onto the pages of a PDF with cairo,
not by way of its SVG.

cairosvg, which turns the SVG into PDF, parses the document back and sets every text a
letter at a time, twice over: for a text-heavy page that was two thirds of making its
PDF. The figure is at hand where it is drawn, so its paths, circles and texts go onto the
page here with the cairo calls cairosvg makes for the SVG :func:`~graphics.svg.to_svg`
writes of it, and print the same:
- a page W × H mm is W × H mm, one user unit a millimetre, every number rounded to
  0.001 mm as the SVG writes it;
- strokes, caps, joins, dashes, and SVG's miter limit (4, where cairo's own is 10);
- a text anchored on its inked extent and set a glyph at a time, as cairosvg sets it; its
  spaces as an SVG viewer keeps them; Persian shaped and in visual order
  (:func:`~graphics.rtl.visual`), as it is for cairosvg.
tests/test_pdf.py reads both routes' PDFs back through a third renderer and holds them to
the same pixels and the same letters in the same places.

Like the SVG, the same figure gives the same bytes: cairo would date the document by the
clock, so it is dated by ``SOURCE_DATE_EPOCH`` when that is set and not at all otherwise
(:func:`dated`).
"""

from __future__ import annotations

import io
import math
import os
import re
from datetime import datetime, timezone

from .atomic_files import RenderError
from .figure import FONT, STYLES, Circle, Figure, Path, Style, Text
from .rtl import RTL_FONT, is_rtl, visual
from .svg import runs, text_origin, tspans

__all__ = ["draw_pdf", "dated", "creation_date"]

_PT_PER_MM = 72.0 / 25.4
_MITER_LIMIT = 4.0              # SVG's default, which cairosvg sets (cairo's own is 10)


def draw_pdf(pages: list[Figure]) -> bytes:
    """A PDF of ``pages``, a page each at its own size (a figure's sheets, a solution's
    figures), in order. Needs libcairo2 (see :func:`~graphics.export.figure_pdf`)."""
    import cairocffi  # noqa: PLC0415  (lazy: SVG output must not need libcairo)

    out = io.BytesIO()
    surface = cairocffi.PDFSurface(out, pages[0].width * _PT_PER_MM,
                                   pages[0].height * _PT_PER_MM)
    dated(surface)
    for page in pages:
        surface.set_size(page.width * _PT_PER_MM, page.height * _PT_PER_MM)
        ctx = cairocffi.Context(surface)
        ctx.scale(_PT_PER_MM, _PT_PER_MM)
        _paint(ctx, page)
        surface.show_page()
    surface.finish()
    return out.getvalue()


def dated(surface) -> None:
    """Date the document of a cairo PDF ``surface`` by :func:`creation_date`, in place of
    the clock's time and zone that cairo writes."""
    import cairocffi  # noqa: PLC0415

    surface.set_metadata(cairocffi.PDF_METADATA_CREATE_DATE, creation_date())


def creation_date(environ=os.environ) -> str:
    """The PDF's creation date as cairo takes it (ISO 8601, UTC): ``SOURCE_DATE_EPOCH``'s, or
    "" for none (a document's date is optional), as reproducible builds ask.

    Raises
    ------
    RenderError
        If ``SOURCE_DATE_EPOCH`` is set but is not a whole number of seconds since 1970.

    Examples
    --------
    >>> creation_date({"SOURCE_DATE_EPOCH": "1700000000"}), creation_date({})
    ('2023-11-14T22:13:20Z', '')
    """
    epoch = environ.get("SOURCE_DATE_EPOCH")
    if epoch is None or epoch == "":
        return ""
    try:
        when = datetime.fromtimestamp(int(epoch), timezone.utc) if epoch.isdigit() else None
    except (OverflowError, OSError, ValueError):
        when = None
    if when is None or when.year > 9999:
        raise RenderError(f"SOURCE_DATE_EPOCH is {epoch[:40]!r}, not a whole number of seconds "
                          "since 1970: set it so, or unset it")
    return when.strftime("%Y-%m-%dT%H:%M:%SZ")


def _paint(ctx, fig: Figure) -> None:
    ctx.set_miter_limit(_MITER_LIMIT)
    ctx.set_source_rgb(1.0, 1.0, 1.0)
    ctx.rectangle(0.0, 0.0, fig.width, fig.height)
    ctx.fill()
    for item in fig.items:
        if isinstance(item, Text):
            _label(ctx, item)
        else:
            _shape(ctx, item, STYLES[item.style])


def _shape(ctx, item: Path | Circle, style: Style) -> None:
    if not (item.radius if isinstance(item, Circle) else item.points):
        return                  # nothing to draw (cairosvg draws a circle of radius 0 so)
    if isinstance(item, Circle):
        ctx.new_sub_path()
        ctx.arc(round(item.centre[0], 3), round(item.centre[1], 3), round(item.radius, 3),
                0.0, 2 * math.pi)
        ctx.close_path()
    else:
        (x, y), *rest = item.points
        ctx.move_to(round(x, 3), round(y, 3))
        for x, y in rest:
            ctx.line_to(round(x, 3), round(y, 3))
        if item.closed:
            ctx.close_path()
    if style.fill:
        ctx.set_source_rgb(*_rgb(style.fill))
        ctx.fill_preserve()
    if style.stroke:
        ctx.set_source_rgb(*_rgb(style.stroke))
        ctx.set_line_width(round(style.width, 3))
        ctx.set_line_cap(_CAPS[style.cap])
        ctx.set_line_join(_JOINS[style.join])
        ctx.set_dash([round(d, 3) for d in style.dash] if sum(style.dash) else [])
        ctx.stroke()
    else:
        ctx.new_path()


def _label(ctx, item: Text) -> None:
    if (parts := runs(item)) is None:
        _text(ctx, item)
    else:
        for part in parts:
            _label(ctx, part)


def _text(ctx, item: Text) -> None:
    """One <text> as cairosvg sets it: the text from its inked anchor, then the subscript
    dropped and smaller, then the tail back on the baseline, each after the last, their
    spaces as an SVG viewer keeps them."""
    x, y, anchor = text_origin(item)
    rtl = is_rtl(item.text + item.sub + item.tail)
    ctx.select_font_face(RTL_FONT if rtl else FONT, _ITALIC if item.italic and not rtl else 0,
                         _BOLD if item.weight == "bold" else 0)
    ctx.set_source_rgb(0.0, 0.0, 0.0)
    text, spaced = _spaced(item.text, True)
    if not (item.sub or item.tail):
        text = text.rstrip(" ")
    ctx.set_font_size(round(item.size, 3))
    ink_left, _, ink_width, _, _, _ = ctx.text_extents(text)
    shift = {"middle": -(ink_width / 2 + ink_left), "end": -(ink_width + ink_left)}
    ctx.move_to(round(x, 3) + shift.get(anchor, 0.0), round(y, 3))
    _show(ctx, text)
    for words, size, dy in tspans(item):
        words, spaced = _spaced(words, spaced)
        ctx.set_font_size(round(size, 3))
        ctx.rel_move_to(0.0, round(dy, 3))
        _show(ctx, words)


def _show(ctx, text: str) -> None:
    """Set ``text`` from the current point a letter at a time, as cairosvg does, and move
    the point past it. A PDF then places each letter exactly; one run of glyphs would be
    placed by the font's widths in whole thousandths of an em, and drift by up to 0.05 mm
    along a long line."""
    x, y = ctx.get_current_point()
    glyphs = ctx.get_scaled_font().text_to_glyphs(x, y, text, with_clusters=False)
    for letter, glyph in zip(text, glyphs):
        if not letter.isspace():
            ctx.show_glyphs([glyph])
    ctx.move_to(x + ctx.text_extents(text)[4], y)


def _spaced(text: str, after_space: bool) -> tuple[str, bool]:
    """``text`` as cairosvg (and any SVG viewer) sets it, shaped if Persian: its runs of
    spaces made one, a space after a space dropped; and whether what follows it comes
    after a space."""
    text = re.sub(" +", " ", (visual(text) if is_rtl(text) else text)
                  .replace("\n", "").replace("\r", "").replace("\t", " "))
    if after_space:
        text = text.lstrip(" ")
    return text, text.endswith(" ") if text else after_space


def _rgb(hex_colour: str) -> tuple[float, float, float]:
    h = hex_colour.lstrip("#")
    if len(h) == 3:
        h = "".join(c * 2 for c in h)
    return tuple(int(h[i:i + 2], 16) / 255.0 for i in (0, 2, 4))


_CAPS = {"butt": 0, "round": 1, "square": 2}       # cairo's LINE_CAP_* values
_JOINS = {"miter": 0, "round": 1, "bevel": 2}      # cairo's LINE_JOIN_* values
_ITALIC, _BOLD = 1, 1                                # FONT_SLANT_ITALIC, FONT_WEIGHT_BOLD
