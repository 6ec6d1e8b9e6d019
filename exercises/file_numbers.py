"""The numbers a file may give: finite, and of a size every figure and rate can carry.

:data:`LARGEST` bounds a mechanism's numbers, so that squaring them (ω² r, |A|²) never
overflows a float; :data:`SIZES` bounds a cam's, rotor's or load's, so that every figure
can be drawn; :func:`radians_in_turn` takes an angle of any size less whole turns.
"""

from __future__ import annotations

import math

__all__ = ["LARGEST", "RANGE", "SIZES", "file_number", "in_range", "radians_in_turn"]

LARGEST = 1e30
"""The largest size of a number tarsim takes from a file; its reciprocal is the smallest
non-zero one. Velocities and accelerations multiply and square these (ω² r, |A|²), and
within this range none of them overflows or underflows a float."""

RANGE = "between 1e-30 and 1e30 in size, or 0"
""":data:`LARGEST` as an error message says it."""

SIZES = (1e-6, 1e6)
"""The sizes a cam, rotor or load file's numbers may have (0 aside), in the file's own
units: wide enough for any textbook part, narrow enough that every figure can be drawn."""


def _float(v: int | float) -> float:
    """``v`` as a float; an integer too large for one is infinite."""
    try:
        return float(v)
    except OverflowError:
        return math.inf


def file_number(v, what: str) -> float:
    """A cam, rotor or load file's number: finite, and 0 or of a size within :data:`SIZES`.

    Raises
    ------
    ValueError
        Saying what is wrong, for the caller to place at its file:line.
    """
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise ValueError(f"{what} must be a number, got {v!r}")
    low, high = SIZES
    if v != 0 and not low <= abs(v) <= high:
        raise ValueError(f"{what} must be between {low:g} and {high:g} in size (or 0), "
                         f"got {v:g}")
    return float(v)


def in_range(x: float) -> bool:
    """True if ``x`` is 0 or finite and of a size within 1/:data:`LARGEST` … :data:`LARGEST`."""
    return x == 0.0 or (math.isfinite(x) and 1.0 / LARGEST <= abs(x) <= LARGEST)


def radians_in_turn(value: float, unit: str) -> float:
    """An angle in ``unit`` ("deg" or "rad") as radians, less whole turns.

    Degrees are reduced before they are converted, where the remainder is exact, so
    θ = 1e9° is the 280° it means; the sign is kept (−90° stays −90°).

    >>> round(math.degrees(radians_in_turn(-1e9, "deg")), 9)
    -280.0
    """
    if unit == "rad":
        return math.fmod(value, math.tau)
    return math.radians(math.fmod(value, 360.0))
