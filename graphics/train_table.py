"""The tabular method of a planetary train as a typeset figure: a column per member, the
notes' three rows (locked +1, the arm held and the fixed member −1, their sum), then the
row scaled to the input's real speed.

Fractions are set as the notes set them ("7/3", "−140/40 × 40/60" is worked to "7/3");
words read flush left and numbers centred in their columns, with a rule under the heading
and above the total.
"""

from __future__ import annotations

from collections.abc import Sequence

from .figure import Figure, Path, Text, text_width, wrap_text

__all__ = ["draw_train_table"]

_SIZE = 3.4        # cell text, mm
_ROW = 6.4         # row pitch, mm
_PAD = 7.0         # white between columns, mm
_MARGIN = 10.0


def draw_train_table(title: str, heads: Sequence[str], rows: Sequence[tuple[str, Sequence[str]]],
                     *, ruled: Sequence[int] = (), notes: Sequence[str] = ()) -> Figure:
    """Draw ``rows`` (a name and a cell per column) under ``heads``, a rule above each row
    index in ``ruled``; ``title`` over it and ``notes`` under it."""
    names = [name for name, _ in rows]
    first = max(text_width(n, _SIZE) for n in [*names, ""])
    widths = [max(text_width(c, _SIZE) for c in [h, *(cells[k] for _, cells in rows)])
              for k, h in enumerate(heads)]
    lefts = [_MARGIN + first + _PAD + sum(widths[:k]) + _PAD * k for k in range(len(heads))]
    right = lefts[-1] + widths[-1] if heads else _MARGIN + first
    fig = Figure(0.0, 0.0, title=title)
    y = _MARGIN + 4.0
    fig.add(Text((_MARGIN, y), title, 4.2, "start", False, "bold"))
    y += 2.0 * _ROW
    for k, h in enumerate(heads):
        fig.add(Text((lefts[k] + widths[k] / 2, y), h, _SIZE, "middle", False, "bold"))
    fig.add(Path(((_MARGIN, y + 0.5 * _ROW), (right, y + 0.5 * _ROW)), "dimension"))
    for r, (name, cells) in enumerate(rows):
        y += _ROW
        if r in ruled:
            fig.add(Path(((_MARGIN, y - 0.5 * _ROW), (right, y - 0.5 * _ROW)), "dimension"))
        fig.add(Text((_MARGIN, y), name, _SIZE, "start", False))
        for k, c in enumerate(cells):
            fig.add(Text((lefts[k] + widths[k] / 2, y), c, _SIZE, "middle", False))
    y += _ROW
    width = max(right, 150.0, _MARGIN + 1.08 * text_width(title, 4.2)) - _MARGIN
    for note in notes:
        for line in wrap_text(note, 3.0, width):
            y += 4.4
            fig.add(Text((_MARGIN, y), line, 3.0, "start", False))
    fig.width = round(max(right, _MARGIN + width) + _MARGIN, 1)
    fig.height = round(y + _MARGIN, 1)
    return fig
