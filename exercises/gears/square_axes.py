"""The tabular method's blank columns: gears turning about an axis square to the main axis.

The table's rows are turns about the main axis. A bevel planet spins about its own axis as
the arm carries it round, and a pinion on a side shaft square to the main axis (a car's
propeller shaft) turns about that: neither turn is one about the main axis, so their cells
are blank and a footnote, marked on the column's heading, says why.
"""

from __future__ import annotations

from fractions import Fraction

from tarsim.constructions.gears.train import GearTrain
from tarsim.constructions.narration import numerals, significant, unit_words, words

__all__ = ["square_mark", "square_notes"]

_MARKS = "†‡§¶"


def _squares(train: GearTrain) -> list[int]:
    return [m for m in train.members if train.square(m)]


def square_mark(train: GearTrain, member: int) -> str:
    """The footnote mark on ``member``'s heading (" †"), or "" for a main-axis member."""
    squares = _squares(train)
    return f" {_MARKS[squares.index(member) % len(_MARKS)]}" if member in squares else ""


def square_notes(train: GearTrain, speeds: dict[int, Fraction]) -> list[str]:
    """A footnote for each blank column, in the language being spoken: a bevel planet's
    spin, a square side shaft's gear's speed (from ``speeds``, where one is given) about
    its own axis."""
    out = []
    for m in _squares(train):
        mark = square_mark(train, m).strip()
        if train.carried(m):
            out.append(words("{mark} Gear {gear} spins about its own axis, square to the main "
                             "axis, as the arm {arm} carries it round: its spin is no turn "
                             "about the main axis, so its cells are blank.",
                             mark=mark, gear=str(m), arm=str(train.arm)))
            continue
        mate = next(b for x in train.meshes if x.bevel for a, b in ((x.a, x.b), (x.b, x.a))
                    if a in train.body(m))
        if not train.speed_given:
            out.append(words("{mark} Gear {gear} turns on a fixed axis of its own, square to "
                             "the main axis, meshing gear {mate} through bevel teeth: the "
                             "table, of turns about the main axis, leaves its cells blank.",
                             mark=mark, gear=str(m), mate=str(mate)))
            continue
        out.append(words("{mark} Gear {gear} turns at {speed} {unit} on a fixed axis of its "
                         "own, square to the main axis, meshing gear {mate} through bevel "
                         "teeth: the table, of turns about the main axis, leaves its cells "
                         "blank.", mark=mark, gear=str(m), mate=str(mate),
                         speed=numerals(significant(float(speeds[m]))),
                         unit=unit_words(train.units.speed)))
    return out
