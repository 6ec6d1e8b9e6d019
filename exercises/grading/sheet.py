"""One sheet, two drawings: the space diagram and the polygons, told apart by their labels.

tarsim's own worked page, and many a student's sheet, put the space diagram beside the
polygons. Its points (``A``, ``B``, ``O2``) read like the polygons' tips (``a``, ``b``,
``o2``), so each label is given to one of them (:func:`split`):

* a centre (``I13``, ``13``) is the space diagram's, a label only a polygon uses (a pole,
  a prime, a subscript no point has) the polygons';
* one that could be either goes by its case where the sheet writes the two in different
  cases (capitals for points, small letters for tips, as the course does), else to the
  nearer of the two: the space diagram's own labels, or the polygons' poles;
* a number in a ring is a step's number (tarsim's figures circle them), and a column of
  labels at a steady pitch a table's (a results table lists I12, I13, …): neither labels a
  point, and a step's ring is no dot.
"""

from __future__ import annotations

import math
import re
from dataclasses import replace

from .drawing import RING, Drawing, Label, ringed
from .labels import plain, read_centre, read_names

__all__ = ["split", "RING"]

APART = 15.0
"""Paper (mm) a pivot's label stands from every pole to be the space diagram's."""

COLUMN = 5
"""The fewest labels one under another at a steady pitch that make a table's column."""


def split(drawing: Drawing, point_names) -> tuple[Drawing, Drawing]:
    """(the polygons' drawing, the space diagram's drawing): the same marks, each with the
    labels that are its own; a step's ring and its number, and a table's column, in
    neither."""
    points = {n.lower() for n in point_names}
    rings = _rings(drawing)
    circles = [c for k, c in enumerate(drawing.circles) if k not in rings.values()]
    labels = [lb for k, lb in enumerate(drawing.labels)
              if k not in rings and k not in _table_columns(drawing.labels)]
    tips, space, either = [], [], []
    for lb in labels:
        as_tip = read_names(lb.text) is not None
        as_point = _names_point(lb.text, points) or read_centre(lb.text) is not None
        (either if as_tip and as_point else tips if as_tip else space if as_point
         else tips).append(lb)           # a label of neither is said by the polygons
    if either:
        cases = {_capital(lb.text) for lb in either}
        tip_cases = {_capital(lb.text) for lb in tips
                     if read_names(lb.text) is not None and not _is_pole(lb.text)}
        poles = [lb.at for lb in tips if _is_pole(lb.text)]
        # A pivot's name (O2) stands at the pole on a polygon, so one far from every pole is
        # the space diagram's, and says where it is where nothing else does.
        own = [lb.at for lb in space] + [
            lb.at for lb in either if re.fullmatch(r"o\d+", plain(lb.text).lower())
            and poles and _nearest(lb.at, poles) > APART]
        for lb in either:
            if len(cases) == 2:                   # A on the diagram, a on the polygon
                side = space if _capital(lb.text) else tips
            elif tip_cases and _capital(lb.text) not in tip_cases:
                side = space                      # the polygons write their tips otherwise
            elif poles and own:
                side = space if _nearest(lb.at, own) < _nearest(lb.at, poles) else tips
            else:
                side = tips if poles else space
            side.append(lb)
    return (replace(drawing, labels=tips, circles=circles),
            replace(drawing, labels=space, circles=circles, notes=[]))


def _rings(drawing: Drawing) -> dict[int, int]:
    """The numbers a figure circles as its steps' numbers: label index → ring index."""
    return ringed(drawing.labels, drawing.circles)


def _table_columns(labels: list[Label]) -> set[int]:
    """Labels standing in a table's column: :data:`COLUMN` or more aligned one under
    another at a steady pitch (or a few pitches, below a row whose words run on over more
    lines), as a results table lists its quantities: flush left, or
    flush right as a right-to-left page sets them (its end read where the text is
    anchored, its letters' width taken off to find its start, and put back)."""
    by_x: dict[tuple[str, int], list[int]] = {}
    for k, lb in enumerate(labels):
        by_x.setdefault(("start", round(lb.at[0] / 0.2)), []).append(k)
        by_x.setdefault(("end", round((lb.at[0] + lb.width()) / 0.2)), []).append(k)
    out: set[int] = set()
    for column in by_x.values():
        column.sort(key=lambda k: labels[k].at[1])
        run = [column[0]] if column else []
        row = 0.0           # the run's row pitch: its least step yet
        for a, b in zip(column, column[1:]):
            pitch = labels[b].at[1] - labels[a].at[1]
            steady = 0.0 < pitch <= _RUN_ON * 12.0 and (
                not row or _rows(pitch, row) or _rows(row, pitch))
            if steady:
                run.append(b)
                row = min(row, pitch) if row else pitch
            else:
                out |= set(run) if len(run) >= COLUMN else set()
                run, row = [b], 0.0
        out |= set(run) if len(run) >= COLUMN else set()
    return out


_RUN_ON = 3
"""The most lines a table's row runs on over (its words broken to keep the table narrow):
its next quantity stands that many of the column's pitch below."""


def _rows(step: float, pitch: float) -> bool:
    """Whether ``step`` is a whole number of rows of ``pitch``, one to :data:`_RUN_ON`, to
    within 5 % of a row."""
    n = round(step / pitch)
    return 1 <= n <= _RUN_ON and abs(step - n * pitch) <= 0.05 * pitch


def _names_point(text: str, points: set[str]) -> bool:
    t = plain(text)
    return "'" not in t and t.lower() in points


def _capital(text: str) -> bool:
    t = plain(text)
    return bool(t) and t[0].isupper()


def _is_pole(text: str) -> bool:
    read = read_names(text)
    return read is not None and "o" in read[1]


def _nearest(p, others) -> float:
    return min(math.dist(p, q) for q in others)
