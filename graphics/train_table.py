"""The tabular method of a planetary train as a typeset figure: a column per member, the
notes' three rows (locked +1, the arm held and the fixed member −1, their sum), then the
row scaled to the input's real speed.

Fractions are set as the notes set them ("7/3", "−140/40 × 40/60" is worked to "7/3");
words read flush left and numbers centred in their columns, with a rule under the heading
and above the total. In a right-to-left language the table is mirrored: the names' column
stands at the right, the columns follow it leftwards, and the words read flush right; a
number keeps its sign at its left, as a formula does.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from .figure import Figure, Path, Text, text_width, wrap_text
from .rtl import is_rtl, reading

__all__ = ["draw_train_table"]

_SIZE = 3.4        # cell text, mm
_ROW = 6.4         # row pitch, mm
_PAD = 7.0         # white between columns, mm
_MARGIN = 10.0
_TALL = 9.6        # the pitch of a row that holds a stacked fraction, mm
_FRACTION = re.compile(r"([+−]?)(\d+)/(\d+)")
"""A cell the notes set as a fraction: a sign, then the numerator over the denominator."""
_SIGNED = re.compile(r"([+−])(\S+)")
"""A signed cell: in right-to-left text its sign is set apart, at its left."""


def _bold_width(text: str, size: float) -> float:
    """A bold heading's width: Latin as the regular face (the 8 % slack allows for bold), a
    right-to-left one in DejaVu Sans Bold's own advances."""
    return text_width(text, size, bold=is_rtl(text))


def _cell_width(text: str) -> float:
    m = _FRACTION.fullmatch(text)
    if m is None:
        return text_width(text, _SIZE)
    sign, num, den = m.groups()
    return text_width(sign, _SIZE) + max(text_width(num, _SIZE), text_width(den, _SIZE)) + 0.6


def _set_cell(fig: Figure, text: str, at: tuple[float, float]) -> None:
    """Set a cell centred at ``at``: a fraction stacked, numerator over a bar over the
    denominator, its sign before it; anything else on the line."""
    m = _FRACTION.fullmatch(text)
    signed = _SIGNED.fullmatch(text) if m is None and is_rtl(text) else None
    if signed is not None:
        # Persian digits read right to left would carry the sign to the number's right:
        # the sign is its own run, at the left, as a fraction's is.
        sign, rest = signed.groups()
        s, w = text_width(sign, _SIZE), text_width(rest, _SIZE)
        left = at[0] - (s + w) / 2
        fig.add(Text((left + s / 2, at[1]), sign, _SIZE, "middle", False))
        fig.add(Text((left + s + w / 2, at[1]), rest, _SIZE, "middle", False))
        return
    if m is None:
        fig.add(Text(at, text, _SIZE, "middle", False))
        return
    sign, num, den = m.groups()
    x, y = at
    w = _cell_width(text)
    s = text_width(sign, _SIZE)
    bar = max(text_width(num, _SIZE), text_width(den, _SIZE)) + 0.6
    left = x - w / 2
    if sign:
        fig.add(Text((left + s / 2, y), sign, _SIZE, "middle", False))
    mid = left + s + bar / 2
    fig.add(Text((mid, y - 2.1), num, _SIZE, "middle", False))
    fig.add(Path(((left + s, y), (left + s + bar, y)), "dimension"))
    fig.add(Text((mid, y + 2.3), den, _SIZE, "middle", False))


def draw_train_table(title: str, heads: Sequence[str], rows: Sequence[tuple[str, Sequence[str]]],
                     *, ruled: Sequence[int] = (), notes: Sequence[str] = ()) -> Figure:
    """Draw ``rows`` (a name and a cell per column) under ``heads``, a rule above each row
    index in ``ruled``; ``title`` over it and ``notes`` under it. In a right-to-left
    language the page is mirrored: the names at the right, the first column next to them."""
    names = [name for name, _ in rows]
    first = max(text_width(n, _SIZE) for n in [*names, ""])
    widths = [max([_bold_width(h, _SIZE)] + [_cell_width(cells[k]) for _, cells in rows])
              for k, h in enumerate(heads)]
    lefts = [_MARGIN + first + _PAD + sum(widths[:k]) + _PAD * k for k in range(len(heads))]
    right = lefts[-1] + widths[-1] if heads else _MARGIN + first
    width = max(right, 150.0, _MARGIN + 1.08 * _bold_width(title, 4.2)) - _MARGIN
    page = round(max(right, _MARGIN + width) + _MARGIN, 1)
    reads = reading(page)
    start, x = reads.anchor, reads.x
    fig = Figure(0.0, 0.0, title=title)
    y = _MARGIN + 4.0
    fig.add(Text((x(_MARGIN), y), title, 4.2, start, False, "bold"))
    y += 2.0 * _ROW
    for k, h in enumerate(heads):
        fig.add(Text((x(lefts[k] + widths[k] / 2), y), h, _SIZE, "middle", False, "bold"))
    fig.add(Path(((x(_MARGIN), y + 0.5 * _ROW), (x(right), y + 0.5 * _ROW)), "dimension"))
    half = 0.5 * _ROW                      # the half pitch of the row above
    for r, (name, cells) in enumerate(rows):
        mine = 0.5 * (_TALL if any(_FRACTION.fullmatch(c) for c in cells) else _ROW)
        if r in ruled:                     # between the rows, whatever their heights
            fig.add(Path(((x(_MARGIN), y + half), (x(right), y + half)), "dimension"))
        y += half + mine
        half = mine
        fig.add(Text((x(_MARGIN), y), name, _SIZE, start, False))
        for k, c in enumerate(cells):
            _set_cell(fig, c, (x(lefts[k] + widths[k] / 2), y))
    y += _ROW
    for note in notes:
        for line in wrap_text(note, 3.0, width):
            y += 4.4
            fig.add(Text((x(_MARGIN), y), line, 3.0, start, False))
    fig.width = page
    fig.height = round(y + _MARGIN, 1)
    return fig
