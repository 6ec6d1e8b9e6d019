"""How precisely a student is expected to draw: an exercise's ``[grading]`` table.

```toml
[grading]
pen = 0.5       # mm: how near a careful pen puts a point
angle = 0.5     # degrees: how true a set square lays a direction
floor = 0.01    # the least relative tolerance on a table of answers
weights = { b = 2, "a4′" = 3 }   # the points an item scores (1 each otherwise)
```
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..table_file import Tables

__all__ = ["Drafting", "DRAFTING", "read_drafting"]


@dataclass(frozen=True)
class Drafting:
    """A pen of ``pen`` mm, a set square true to ``angle`` radians, the least relative
    tolerance ``floor`` a table of answers is held to, and each item's points."""

    pen: float = 0.5
    angle: float = math.radians(0.5)
    floor: float = 0.01
    weights: tuple[tuple[str, float], ...] = ()
    """Points an item scores, by its name as grade.json has it; 1 for any other."""


DRAFTING = Drafting()
"""The course's drafting precision: 0.5 mm and 0.5°, and 1 % at least on numbers read off
a drawing (published graphical answers keep to 1–2 %)."""


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
    return Drafting(pen, math.radians(angle), floor, tuple(weights))
