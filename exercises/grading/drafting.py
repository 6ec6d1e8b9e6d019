"""How precisely a student is expected to draw, and how a course marks: an exercise's
``[grading]`` table.

```toml
[grading]
pen = 0.5       # mm: how near a careful pen puts a point
angle = 0.5     # degrees: how true a set square lays a direction
floor = 0.0     # a least relative tolerance on a table of answers (none by default)
weights = { b = 2, "a4′" = 3 }   # the points an item scores (1 each otherwise)
scale = "required"               # hold drawings to the exercise's scale (default: free)
follow = true                    # a tip drawn rightly from an earlier error scores
aliases = { c = "b4" }           # a label the exercise's statement uses, and the tip it names
```

**One tolerance** (:func:`tolerance`) for a drawn tip and a number in a table: the pen and
the set square over a vector drawn at the exercise's scale, over its conditioning.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..table_file import Tables

__all__ = ["Drafting", "DRAFTING", "read_drafting", "tolerance", "exercise_scale", "LENGTH"]

LENGTH = 100.0
"""Paper (mm) a polygon is drawn across when the exercise states no scale: the ten
centimetres a course asks."""


@dataclass(frozen=True)
class Drafting:
    """A pen of ``pen`` mm, a set square true to ``angle`` radians, the least relative
    tolerance ``floor`` a table of answers is held to, and each item's points."""

    pen: float = 0.5
    angle: float = math.radians(0.5)
    floor: float = 0.0
    weights: tuple[tuple[str, float], ...] = ()
    """Points an item scores, by its name as grade.json has it; 1 for any other."""
    scale_required: bool = False
    """Hold a drawing to the exercise's stated scale (else the drawing's own is taken)."""
    follow: bool = True
    """A tip drawn rightly from an earlier error scores (the course's follow-through)."""
    aliases: dict[str, str] | None = None
    """Labels the exercise's statement uses, by the polygon tip each names (``c`` → ``b4``)."""


DRAFTING = Drafting()
"""The course's drafting precision: 0.5 mm and 0.5°."""


def tolerance(length: float, conditioning: float, drafting: Drafting = DRAFTING) -> float:
    """How far (paper mm) the tip of a vector drawn ``length`` mm long may stand from where it
    belongs: the pen, plus the set square's angle across the length, over the conditioning
    of the construction that found it; never less than the pen.

    >>> round(tolerance(60.0, 1.0), 3), round(tolerance(60.0, 0.5), 3)
    (1.024, 2.047)
    """
    return max(drafting.pen, (drafting.pen + length * math.tan(drafting.angle)) / conditioning)


def exercise_scale(stated: float | None, vectors) -> float:
    """Paper mm per SI unit a polygon is drawn at: the exercise's ``stated`` scale, else the
    one that draws its longest vector :data:`LENGTH` long."""
    if stated:
        return stated
    longest = max([math.hypot(*v) for v in vectors] + [0.0])
    return LENGTH / longest if longest > 0.0 else 1.0



def read_drafting(table: dict[str, Any] | None, tables: Tables) -> Drafting:
    """The ``[grading]`` table's settings, each refused at its line when it is no positive
    number (the floor below 1).

    Raises
    ------
    InputError
        Naming the file, line and setting.
    """
    if table is None:
        return DRAFTING
    (t,) = tables.entries("grading")
    known = {"pen", "angle", "floor", "weights", "scale", "follow", "aliases"}
    for key in t:
        if key not in known:
            raise tables.fail(f"[grading] has no setting '{key}'; its settings are "
                              f"{', '.join(sorted(known))}", "grading", key)
    pen = tables.number(t, "pen", "grading", "a pen's precision (mm)", 0, DRAFTING.pen)
    angle = tables.number(t, "angle", "grading", "a set square's precision (degrees)", 0,
                          math.degrees(DRAFTING.angle))
    floor = tables.number(t, "floor", "grading", "the least relative tolerance", 0,
                          DRAFTING.floor)
    for key, value, ok in (("pen", pen, pen > 0), ("angle", angle, 0 < angle < 45),
                           ("floor", floor, 0 <= floor < 1)):
        if not ok:
            raise tables.fail(f"[grading] {key} must be positive (an angle under 45°, a floor "
                              f"under 1); got {value:g}", "grading", key)
    raw = t.get("weights", {})
    if not isinstance(raw, dict):
        raise tables.fail("[grading] weights is a table of points by item, { b = 2 }",
                          "grading", "weights")
    weights = []
    for item in raw:
        points = tables.number(raw, item, "grading", f"the points of {item}", 0)
        if not points >= 0:
            raise tables.fail(f"[grading] weights: {item} must score 0 points or more; got "
                              f"{points:g}", "grading", "weights")
        weights.append((str(item), points))
    scale = t.get("scale", "free")
    if scale not in ("free", "required"):
        raise tables.fail(f'[grading] scale is "free" or "required"; got {scale!r:.40}',
                          "grading", "scale")
    follow = t.get("follow", True)
    if not isinstance(follow, bool):
        raise tables.fail(f"[grading] follow is true or false; got {follow!r:.40}", "grading",
                          "follow")
    aliases = t.get("aliases", {})
    if not isinstance(aliases, dict) or not all(
            isinstance(v, str) and len(k) <= 16 and len(v) <= 16 for k, v in aliases.items()):
        raise tables.fail('[grading] aliases is a table of labels and the tips they name, '
                          '{ c = "b4" }', "grading", "aliases")
    return Drafting(pen, math.radians(angle), floor, tuple(weights), scale == "required",
                    follow, {plain_name(k): plain_name(v) for k, v in aliases.items()} or None)


def plain_name(label: str) -> str:
    """A label as :func:`.labels.tip_of` compares it: plain, lower case, no prime."""
    from .labels import plain

    return plain(label).replace("'", "").lower()
