"""The numbers a file may give: finite, and of a size every figure and rate can carry.

:data:`LARGEST` bounds a mechanism's numbers, so that squaring them (ω² r, |A|²) never
overflows a float; :data:`SIZES` bounds a cam's, rotor's or load's, so that every figure
can be drawn; :func:`radians_in_turn` takes an angle of any size less whole turns.
"""

from __future__ import annotations

import ast
import math
from fractions import Fraction

__all__ = ["LARGEST", "RANGE", "SIZES", "arithmetic", "file_number", "in_range",
           "radians_in_turn"]

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


_LONGEST = 80
"""The most characters a number written as arithmetic may take."""

_OPERATIONS = {ast.Add: Fraction.__add__, ast.Sub: Fraction.__sub__,
               ast.Mult: Fraction.__mul__, ast.Div: Fraction.__truediv__}


def arithmetic(text: str, *, pi: bool = False) -> Fraction | None:
    """A number the way a book writes it from its data, "120/2", "2/3", "45 + 70", exactly;
    None if ``text`` is not such sums, differences, products and quotients of numbers.

    Exact, so that a gear's "2/3" stays two thirds; no names, powers or calls, so that a
    file's text is never run. With ``pi``, where the number is taken as a float anyway (a
    cam's "2*pi" rad/s), ``pi`` or ``π`` stands for π.

    >>> arithmetic("120/2"), arithmetic("(45 + 70) * 2"), arithmetic("2/3")
    (Fraction(60, 1), Fraction(230, 1), Fraction(2, 3))
    >>> arithmetic("A + 45") is None, arithmetic("1/0") is None, arithmetic("2*pi") is None
    (True, True, True)
    >>> float(arithmetic("2*pi", pi=True)) == 2 * math.pi
    True
    """
    if not isinstance(text, str) or not text.strip() or len(text) > _LONGEST:
        return None
    try:
        tree = ast.parse(text.strip(), mode="eval").body
        return _value(tree, pi)
    except (SyntaxError, ValueError, ZeroDivisionError):
        return None


def _value(node: ast.AST, pi: bool) -> Fraction:
    if isinstance(node, ast.Constant) and type(node.value) in (int, float):
        return Fraction(repr(node.value)) if isinstance(node.value, float) \
            else Fraction(node.value)
    if pi and isinstance(node, ast.Name) and node.id in ("pi", "π"):
        return Fraction(math.pi)
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        inner = _value(node.operand, pi)
        return -inner if isinstance(node.op, ast.USub) else inner
    if isinstance(node, ast.BinOp) and type(node.op) in _OPERATIONS:
        return _OPERATIONS[type(node.op)](_value(node.left, pi), _value(node.right, pi))
    raise ValueError("not arithmetic")


def file_number(v, what: str) -> float:
    """A cam, rotor or load file's number: finite, and 0 or of a size within :data:`SIZES`.
    Arithmetic of numbers in a string ("120/2", "2*pi") is taken at its value.

    Raises
    ------
    ValueError
        Saying what is wrong, for the caller to place at its file:line.
    """
    exact = arithmetic(v, pi=True) if isinstance(v, str) else None
    if exact is not None:
        v = _float(exact)
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
