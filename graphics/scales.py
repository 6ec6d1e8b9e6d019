"""Nice scales (1, 2 or 5 × 10^k per centimetre) and the scale bar that states them.

The scale is chosen so the panel fits its box; the bar is drawn in paper
millimetres, so on a PDF printed at 100 % it measures true with a ruler.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from tarsim.constructions.narration import numerals, significant, spoken, unit_words, words
from tarsim.constructions.scales import Stated, nice_per_cm

from .figure import Figure, Path, Text, text_width
from .rtl import reading
from .typeset import spoken_numbers
from .wrapping import wrap_formulas

__all__ = ["nice_per_cm", "scale_text", "paper_ratio", "bar_room", "draw_scale_bar", "number_text",
           "draw_caption"]

_NOTE_COLUMN = 150.0
"""The narrowest a caption's notes are set to (mm): a measure that still reads as prose."""


def number_text(value: float) -> str:
    """Format a scale number without float noise ("0.2", "50", "2000").

    Examples
    --------
    >>> number_text(0.30000000000000004), number_text(2e12)
    ('0.3', '2e12')
    """
    return significant(value)


def paper_ratio(per_cm: float) -> tuple[int, float]:
    """Return (k, N) with k centimetres standing for N, the fewest centimetres that make N a
    number of four figures or fewer: a stated "7 cm = 500 mm" reads back as itself, not as
    "1 cm = 71.4286 mm". A ratio no k up to 10 makes round is given per one centimetre.

    Examples
    --------
    >>> paper_ratio(500 / 7)
    (7, 500.0)
    >>> paper_ratio(60.0)
    (1, 60.0)
    """
    for k in range(1, 11):
        amount = per_cm * k
        if abs(amount - float(f"{amount:.4g}")) <= 1e-9 * amount:
            return k, float(f"{amount:.4g}")
    return 1, per_cm


def scale_text(per_cm: float, unit: str) -> str:
    """Return the statement printed on the figure, e.g. "1 cm = 50 mm" or "7 cm = 500 mm";
    a scale the exercise states (:class:`~tarsim.constructions.scales.Stated`) as it states
    it ("3 cm = 18 cm/s")."""
    if isinstance(per_cm, Stated):
        if spoken() == "en":
            return per_cm.words
        return _statement(number_text(per_cm.paper_cm), per_cm.amount, per_cm.unit)
    k, amount = paper_ratio(per_cm)
    return _statement(str(k), amount, unit)


def _statement(paper_cm: str, amount: float, unit: str) -> str:
    """"k cm = N unit" in the language being spoken (the amount in its digits)."""
    return (f"{numerals(paper_cm)} {unit_words('cm')} = {numerals(number_text(amount))}"
            f"{_after(unit)}")


def _after(unit: str) -> str:
    """A unit as it follows its number: after a space, the degree sign set close ("30°")."""
    return unit if unit == "°" else f" {unit_words(unit)}"


def _bar(per_cm: float, unit: str) -> tuple[int, float, str]:
    """The bar of a scale: (centimetres it numbers at its ends, or 1, amount a centimetre
    stands for, unit), in the stated unit when the scale is stated."""
    if isinstance(per_cm, Stated):
        k = round(per_cm.paper_cm)
        whole = abs(per_cm.paper_cm - k) <= 1e-9 and 1 <= k <= 10
        return (k if whole else 1), per_cm.amount / per_cm.paper_cm, per_cm.unit
    k, _ = paper_ratio(per_cm)
    return k, per_cm, unit


def bar_room(per_cm: float, unit: str) -> float:
    """The width (paper mm) :func:`draw_scale_bar` takes with its unit after the last number."""
    k, _, unit = _bar(per_cm, unit)
    return 10.0 * (k if k > 1 else 4) + text_width(f" {unit_words(unit)}", 2.6) + 6.0


def draw_scale_bar(fig: Figure, at: tuple[float, float], per_cm: float, unit: str,
                   cm: int = 4) -> float:
    """Draw a ``cm``-centimetre bar with alternate filled centimetres; return its width.

    ``at`` is the bar's left end on its centre line. A scale stated over k > 1
    centimetres (:func:`paper_ratio`) gets a bar k long, numbered at its two ends.
    """
    x0, y0 = at
    h = 1.4
    k, per_cm, unit = _bar(per_cm, unit)
    cm, ticks = (k, (0, k)) if k > 1 else (cm, range(0, cm + 1, 2 if cm > 3 else 1))
    for i in range(cm):
        style = "scale_fill" if i % 2 == 0 else "scale"
        xa, xb = x0 + 10.0 * i, x0 + 10.0 * (i + 1)
        fig.add(Path(((xa, y0 - h / 2), (xb, y0 - h / 2), (xb, y0 + h / 2), (xa, y0 + h / 2)),
                     style, closed=True))
    for i in ticks:
        label = numerals(number_text(per_cm * i)) + (_after(unit) if i == cm else "")
        fig.add(Text((x0 + 10.0 * i, y0 + h / 2 + 2.4), label, size=2.6,
                     anchor="middle" if i < cm else "start", italic=False))
    return 10.0 * cm


def _heading(text: str) -> Text:
    """A bold heading, its first ``X_Y`` set with a true subscript ("V_B by …")."""
    m = re.search(r"\b([A-Za-zωα])_(\w+)", text)
    if m is None:
        return Text((0.0, 0.0), text, 3.6, "start", italic=False, weight="bold")
    return Text((0.0, 0.0), text[:m.start(2) - 1], 3.6, "start", italic=False, weight="bold",
                sub=m.group(2), tail=text[m.end(2):])


_CAPTION_ROW = 174.0
"""The widest a caption runs (mm) unless its drawing is wider: an A4 sheet upright holds
it within its margins (190 mm), with the caption's own (2 × 8 mm). A longer heading or
line is wrapped, never inside a formula (:func:`~tarsim.graphics.wrapping.wrap_formulas`),
so that a caption never makes its figure wider than the drawing and a sheet."""

_TEXT_COLUMN = 90.0
"""The narrowest a caption's heading and lines are wrapped to (mm)."""

_LEGEND_ROW = 160.0
"""The widest a legend's row runs (mm) before it wraps, unless the drawing is wider."""


def _legend_rows(legend: Sequence[tuple[str, str]], room: float
                 ) -> list[list[tuple[str, str]]]:
    """The legend's samples in rows no wider than ``room`` (one at least in each)."""
    rows: list[list[tuple[str, str]]] = []
    used = room
    for item in legend:
        w = 18.0 + text_width(item[1], 2.8)
        if used + w > room + 6.0:
            rows.append([])
            used = 0.0
        rows[-1].append(item)
        used += w
    return rows


def _wrapped(heading: str, lines: Sequence[str], room: float
             ) -> tuple[list[Text], list[str]]:
    """The heading's lines (bold, each its first ``X_Y`` subscripted) and the lines under
    it, each wrapped to ``room`` mm where it is wider."""
    heads = ([heading] if _heading(heading).width <= room else
             wrap_formulas(heading, 3.6, room, measure=lambda t: _heading(t).width))
    return ([_heading(h) for h in heads],
            [part for line in lines
             for part in ([line] if text_width(line, 3.2) <= room else
                          wrap_formulas(line, 3.2, room))])


def draw_caption(fig: Figure, heading: str, lines: Sequence[str], *, per_cm: float | None,
                 unit: str, legend: Sequence[tuple[str, str]] = (), notes: Sequence[str] = (),
                 margin: float = 8.0, scale_name: str = "Scale",
                 second: tuple[str, float, str] | None = None) -> None:
    """Move the drawing in from a ``margin`` and set the caption under it; size the page.

    Left: the bold ``heading`` and ``lines``. Right: the scale statement, which
    ``scale_name`` opens ("Velocity scale 1 cm = 5 mm/s"), and its bar (none when ``per_cm``
    is None: panels that state scales of their own); then, if given,
    a ``second`` scale (name, per cm, unit) and its bar, as for the velocities drawn on
    a space diagram. Under both: a ``legend`` of (style, name) line samples, then
    ``notes``. In a right-to-left language the caption is mirrored: heading, lines, legend
    and notes align right and the scales stand at the left (a bar still reads left to
    right, as its numbers do). The scale and legend names are said in the language being
    spoken (:func:`~tarsim.constructions.narration.words`); the heading, lines and notes
    come already said, their numbers set in the spoken language's digits
    (:func:`~tarsim.graphics.typeset.spoken_numbers`). The drawing's own size is kept as
    the figure's ``drawing``, from which :func:`~tarsim.graphics.fitting.fit` foretells its
    size at another scale.
    """
    x0, y0, x1, y1 = fig.bounds()
    fig.shift(margin - x0, margin - y0)
    fig.drawing = (x1 - x0, y1 - y0)
    scales = ([] if per_cm is None else [(words(scale_name), per_cm, unit)]) + (
        [(words(second[0]), *second[1:])] if second else [])
    legend = [(style, words(name)) for style, name in legend]
    texts = [f"{name} {scale_text(per, u)}" for name, per, u in scales]
    right = max([text_width(t, 3.2) for t in texts]
                + [bar_room(per, u) for _, per, u in scales], default=0.0)
    heading, lines = spoken_numbers(heading), [spoken_numbers(t) for t in lines]
    notes = [spoken_numbers(t) for t in notes]
    heads, lines = _wrapped(heading, lines, max(max(x1 - x0, _CAPTION_ROW) - right - 8.0,
                                                _TEXT_COLUMN))
    left = max([h.width for h in heads] + [text_width(t, 3.2) for t in lines])
    legend_w = max((sum(18.0 + text_width(name, 2.8) for _, name in row)
                    for row in _legend_rows(legend, max(x1 - x0, left + right + 8.0,
                                                        _LEGEND_ROW))), default=0.0)
    # Notes wrap to the width the rest needs (a long note must not widen the page and so
    # shrink the drawing), but never narrower than a column that reads well.
    width = max(x1 - x0, left + right + 8.0, legend_w) + 2 * margin
    notes = [line for note in notes
             for line in wrap_formulas(note, 3.0, max(width - 2 * margin, _NOTE_COLUMN))]
    width = max(width, max([text_width(n, 3.0) for n in notes], default=0.0) + 2 * margin)
    fig.shift((width - (x1 - x0) - 2 * margin) / 2, 0.0)
    reads = reading(width)
    # The reading edge a text line starts from: the left margin, or the right one.
    edge, anchor, way = reads.x(margin), reads.anchor, reads.way
    top = y1 - y0 + 2 * margin
    y = top + 3.0 - 4.6
    for head in heads:
        y += 4.6
        fig.add(Text((edge, y), head.text, head.size, anchor, False, "bold", head.sub, head.tail))
    for text in lines:
        y += 5.2
        fig.add(Text((edge, y), text, 3.2, anchor, italic=False))
    bar_x = margin if reads.rtl else width - margin - right
    for k, (text, (_, per, u)) in enumerate(zip(texts, scales)):
        x = bar_x + right if reads.rtl else bar_x
        fig.add(Text((x, top + 3.0 + 13.0 * k), text, 3.2, anchor, italic=False))
        draw_scale_bar(fig, (bar_x, top + 8.0 + 13.0 * k), per, u)
    y = max(y + 5.2, top + 15.0 + 13.0 * (len(scales) - 1) if scales else 0.0)
    for row in _legend_rows(legend, width - 2 * margin):
        x = edge
        for style, name in row:
            fig.add(Path(((x, y), (x + way * 10.0, y)), style))
            fig.add(Text((x + way * 12.0, y), name, 2.8, anchor, italic=False))
            x += way * (18.0 + text_width(name, 2.8))
        y += 4.8
    for note in notes:
        fig.add(Text((edge, y), note, 3.0, anchor, italic=False))
        y += 4.4
    fig.width = round(width, 1)
    fig.height = round(y + 1.0, 1)
