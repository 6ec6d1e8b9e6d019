"""What an instructor hides of a figure (``tarsim solve --hide``), for a clean one on a
slide or in a book.

Three parts may be hidden, each where it is drawn, so that the rest of the figure is drawn
as it would be, every label where it stood:

* ``badges``: the circled step numbers (:func:`~.symbols.draw_badge`);
* ``answers``: the numbers the solution found, as the figures print them: the results
  table's construction and analytic columns, the stroke and time ratio stated under the
  limit positions, and the other chapters' found numbers (:func:`shown_answer`);
* ``checks``: the results table's check, its construction, analytic and relative-error
  columns, leaving each quantity and the method that found it.

What is hidden is a setting of the drawing, as the language spoken is (:func:`hiding`):
a badge is drawn deep inside a figure's labels. It is kept in the module itself, not a
context variable, so that a figure drawn in a forked worker (:mod:`.workers`) hides what
the process that forked it hides, whichever thread forked it.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from contextlib import contextmanager

from tarsim.constructions.errors import TarsimError
from tarsim.constructions.narration import words

__all__ = ["HIDEABLE", "hiding", "hidden", "parts_to_hide", "shown_answer", "shown_columns"]

HIDEABLE = ("answers", "badges", "checks")
"""What may be hidden, by the names ``--hide`` takes."""

_COLUMNS = {"answers": ("construction", "analytic", "answer"),
            "checks": ("construction", "analytic", "relative error", "check")}
"""The results table's columns each part hides, by their headers' words."""

_HIDDEN: frozenset[str] = frozenset()


def parts_to_hide(text: str) -> frozenset[str]:
    """The parts ``--hide`` names, comma-separated ("answers,badges").

    Raises
    ------
    TarsimError
        If a name is none of :data:`HIDEABLE`, naming them.

    Examples
    --------
    >>> sorted(parts_to_hide("badges, checks"))
    ['badges', 'checks']
    """
    parts = frozenset(p.strip().lower() for p in text.split(",") if p.strip())
    unknown = sorted(parts - set(HIDEABLE))
    if unknown:
        raise TarsimError(f"'{unknown[0]}' is not a part a figure can hide; choose among "
                          f"{', '.join(HIDEABLE)} (comma-separated: --hide answers,badges)")
    return parts


@contextmanager
def hiding(parts: frozenset[str]) -> Iterator[frozenset[str]]:
    """Draw with ``parts`` hidden (names of :data:`HIDEABLE`), inside the block."""
    global _HIDDEN
    outer, _HIDDEN = _HIDDEN, frozenset(parts)
    try:
        yield _HIDDEN
    finally:
        _HIDDEN = outer


def hidden() -> frozenset[str]:
    """What the figures being drawn hide (nothing unless inside :func:`hiding`)."""
    return _HIDDEN


def shown_answer(text: str, blank: str = "") -> str:
    """``text``, a number the solution found, or ``blank`` where answers are hidden.

    A table's cell or a figure's reading keeps its place empty, so the sheet shows where
    the student writes the answer; inside a sentence, ``blank="…"`` keeps the gap seen.
    The chapters whose figures print answers outside a results table (the gear trains'
    speeds, the cams' table, the balancing masses found) pass each such number through
    here.

    Examples
    --------
    >>> shown_answer("−187.5")
    '−187.5'
    >>> with hiding(frozenset({"answers"})):
    ...     shown_answer("−187.5")
    ''
    """
    return blank if "answers" in _HIDDEN else text


def shown_columns(table: Sequence[Sequence[str]]) -> list[tuple[str, ...]]:
    """``table`` (its header first, said in the language spoken) without the columns the
    parts hidden hide; a table they leave whole is returned as it is.

    Examples
    --------
    >>> table = [("quantity", "method", "construction", "analytic", "relative error"),
    ...          ("V_B", "radius rotation", "232.9 mm/s", "232.9 mm/s", "1.2e-16")]
    >>> with hiding(frozenset({"checks"})):
    ...     shown_columns(table)
    [('quantity', 'method'), ('V_B', 'radius rotation')]
    >>> with hiding(frozenset({"answers"})):
    ...     shown_columns(table)[1]
    ('V_B', 'radius rotation', '1.2e-16')
    """
    if not table:
        return [tuple(row) for row in table]
    gone = {words(w) for part in _HIDDEN for w in _COLUMNS.get(part, ())}
    keep = [k for k, head in enumerate(table[0]) if head not in gone]
    return [tuple(row[k] for k in keep) for row in table]
