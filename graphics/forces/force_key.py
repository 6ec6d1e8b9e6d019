"""The key under a force figure: each kind of name drawn on it (F₁₂, W₃, F_i3, F_R, F_T, t,
x, …) with what it stands for, so that no symbol on the page is left to be guessed."""

from __future__ import annotations

import re
from collections.abc import Sequence

from tarsim.constructions.narration import words
from ..figure import Figure, Text, text_width
from ..rtl import reading

__all__ = ["draw_key", "key_entries"]

_KINDS: tuple[tuple[str, str, str, str, str, str], ...] = (
    # (letter, subscript pattern, tail, the symbol's subscript as keyed, its tail, meaning)
    ("F", r"\d\d", "", "ij", "", "the force of link i on link j"),
    ("F", r"\d\d", "ᵗ", "ij", "ᵗ", "its part square to link j"),
    ("F", r"\d\d", "ⁿ", "ij", "ⁿ", "its part along link j"),
    ("F", r"i\d+", "", "ik", "", "the inertia force of link k"),
    ("M", r"i\d+", "", "ik", "", "the inertia couple of link k"),
    ("M", r"f\d\d", "", "fij", "", "the friction couple of link i on link j at their pin"),
    ("W", r"\d+", "", "k", "", "the weight of link k"),
    ("P", r"\d+", "", "k", "", "the force given on link k"),
    ("T", r"\d\d", "", "ij", "", "the couple of link i on link j"),
    ("T", r"\d", "", "k", "", "the torque that drives link k"),
    ("F", "R", "", "R", "", "the push on the crank pin's part along the crank"),
    ("F", "T", "", "T", "", "its part square to the crank: the crank effort"),
    ("t", "", "", "", "", "where the push on the crank pin parts along the crank and square "
                          "to it"),
    ("x", "", "", "", "", "where the two lines that close a polygon cross"),
    ("X", "", "", "", "", "where a three-force member's lines of action meet"),
)
"""Each kind of name a force figure draws, matched by its letter, subscript and what
follows it: (letter, subscript pattern, tail, subscript keyed, tail keyed, what it means)."""

_SIZE = 2.8
_ROW = 4.6


def key_entries(names: Sequence[Text]) -> list[tuple[str, str, str, str]]:
    """The key's entries for the ``names`` drawn (each (letter, subscript, tail, meaning)),
    in the order of :data:`_KINDS`, each kind once; a load the exercise names by a letter
    (P) is keyed as given, one named in words ("gas force") says itself."""
    found = {k for k in map(_kind, names) if k is not None}
    given = {(t.text, t.sub) for t in names if _kind(t) is None and len(t.text) <= 2
             and not t.tail.split(" = ")[0] and t.text.isalpha() and t.text[0].isupper()}
    return [(_KINDS[k][0], _KINDS[k][3], _KINDS[k][4], words(_KINDS[k][5]))
            for k in sorted(found)] + [(text, sub, "", words("a load the exercise gives"))
                                       for text, sub in sorted(given)]


def _kind(name: Text) -> int | None:
    """Which of :data:`_KINDS` a drawn name is, if any."""
    tail = name.tail.split(" = ")[0].rstrip("′")
    text = name.text.removeprefix("= ")          # a second name of one arrow: "F₃₂ = F_T"
    for k, (letter, sub, end, *_) in enumerate(_KINDS):
        if text == letter and tail == end and (
                re.fullmatch(sub, name.sub) if sub else not name.sub):
            return k
    return None


def draw_key(fig: Figure, names: Sequence[Text], margin: float = 8.0) -> None:
    """Set the key to the ``names`` drawn under ``fig``'s caption, entries side by side in
    rows as wide as the page, and grow the page to hold it."""
    entries = key_entries(names)
    if not entries:
        return
    reads = reading(fig.width)
    room = fig.width - 2 * margin
    y, used = fig.height - 1.0 - _ROW, room      # its first row a legend row below the last
    for letter, sub, tail, meaning in entries:
        symbol = Text((0.0, 0.0), letter, _SIZE, "start", True, sub=sub, tail=tail)
        w = symbol.width + 2.0 + text_width(meaning, _SIZE) + 7.0
        if used + w > room:
            y, used = y + _ROW, 0.0
        x = reads.x(margin + used)
        fig.add(Text((x, y), letter, _SIZE, reads.anchor, True, sub=sub, tail=tail))
        fig.add(Text((x + reads.way * (symbol.width + 2.0), y), meaning, _SIZE, reads.anchor,
                     False))
        used += w
    fig.height = round(y + _ROW, 1)
