"""Polygon scales written on a drawing: "1 cm = 0.5 m/s", "3 cm = 18 cm/s", "1 cm = 2 m/s²".

A scale written on the sheet is what the student says the polygon is drawn at, so it is held
to; see :mod:`.polygon`.
"""

from __future__ import annotations

import math
import re

from .drawing import Drawing

__all__ = ["stated_scales"]

# A number starts where no digit stands before it, so a long run of digits is tried once.
_SCALE = re.compile(r"(?<![\d.,])(\d+(?:[.,]\d+)?)\s*cm\s*=\s*(\d+(?:[.,]\d+)?)\s*"
                    r"(mm|cm|m)\s*/\s*s\s*(²|\^2|2)?", re.IGNORECASE)
_UNIT = {"mm": 1e-3, "cm": 1e-2, "m": 1.0}

_SCALES = (1e-9, 1e9)
"""The scales a drawing may state, paper mm per SI unit: beyond them a statement is a slip
of the pen, not a scale, and is not held to."""


def stated_scales(drawing: Drawing, notes: list[str]) -> dict[str, float]:
    """Scales written on the drawing, paper mm per SI unit, by kind ("v" or "a"); one no
    drawing is drawn at is said in ``notes``.

    >>> from tarsim.exercises.grading.drawing import Label
    >>> stated_scales(Drawing(labels=[Label("Velocity scale 3 cm = 18 cm/s", (0, 0))]), [])
    {'v': 166.66666666666669}
    """
    out = {}
    for label in drawing.labels:
        m = _SCALE.search(label.text.replace("\u202f", " ").replace("\u00a0", " "))
        if m:
            cm, amount = float(m[1].replace(",", ".")), float(m[2].replace(",", "."))
            scale = 10.0 * cm / (amount * _UNIT[m[3].lower()]) if amount > 0 else math.inf
            if _SCALES[0] <= scale <= _SCALES[1]:
                out["a" if m[4] else "v"] = scale
            else:
                notes.append(f"the scale written '{m[0][:40]}' is no scale a drawing is drawn "
                             "at, so it was not held to")
    return out
