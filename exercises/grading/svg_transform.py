"""An SVG ``transform`` read strictly into one matrix.

SVG 1.1's functions (matrix, translate, scale, rotate, skewX, skewY) and CSS's one-axis
forms, with the units CSS allows an angle (deg, rad, grad, turn) or a length (px, pt, pc,
mm, cm, in). Anything else, a number that is not finite among it, is not a transform: the
caller leaves its element out rather than guess, as svgelements would (it reads
``scale(nan)`` as no transform at all).
"""

from __future__ import annotations

import math
import re

__all__ = ["matrix", "times", "PX"]

PX = {None: 1.0, "px": 1.0, "mm": 96 / 25.4, "cm": 960 / 25.4, "in": 96.0, "pt": 96 / 72,
      "pc": 16.0}
"""CSS pixels a unit of each absolute length (96 to the inch), None for a bare number."""


def matrix(text: str) -> tuple[float, ...] | None:
    """An SVG transform list as one matrix (a, b, c, d, e, f); None if it is not one. Angles
    may carry deg, rad, grad or turn, lengths px, pt, pc, mm, cm or in, as CSS allows.

    >>> matrix("translate(10, 5) rotate(90)")
    (6.123233995736766e-17, 1.0, -1.0, 6.123233995736766e-17, 10.0, 5.0)
    >>> matrix("rotate(0.25turn)") == matrix("rotate(90)"), matrix("scale(nan)")
    (True, None)
    """
    out = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)
    rest = text.strip()
    while rest:
        m = re.match(r"([A-Za-z]+)\s*\(([^()]*)\)[\s,]*", rest)
        if m is None:
            return None
        rest = rest[m.end():]
        args = [a for a in re.split(r"[\s,]+", m[2].strip()) if a]
        values = [_ARGUMENT.fullmatch(a) for a in args]
        if not all(values):
            return None
        step = _function(m[1], [(float(v[1]), v[2]) for v in values])
        if step is None or not all(math.isfinite(x) for x in step):
            return None
        out = times(out, step)
    return out


_ARGUMENT = re.compile(r"([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)"
                       r"(deg|grad|rad|turn|px|pt|pc|mm|cm|in)?")
_DEGREES = {None: 1.0, "deg": 1.0, "grad": 0.9, "rad": 180 / math.pi, "turn": 360.0}


def _function(name: str, args: list[tuple[float, str | None]]) -> tuple[float, ...] | None:
    """One transform function's matrix, or None if it is not one SVG or CSS has, or an
    argument has a unit it cannot have."""
    n = len(args)
    if name in ("rotate", "skewX", "skewY"):
        if not args or args[0][1] not in _DEGREES or any(u not in PX for _, u in args[1:]):
            return None
        v = [args[0][0] * _DEGREES[args[0][1]]] + [a * PX[u] for a, u in args[1:]]
    elif name in ("translate", "translateX", "translateY"):
        if any(u not in PX for _, u in args):
            return None
        v = [a * PX[u] for a, u in args]
    elif any(u is not None for _, u in args):
        return None
    else:
        v = [a for a, _ in args]
    if name == "matrix" and n == 6:
        return tuple(v)
    if name == "translate" and n in (1, 2):
        return (1.0, 0.0, 0.0, 1.0, v[0], v[1] if n == 2 else 0.0)
    if name in ("translateX", "translateY") and n == 1:
        return (1.0, 0.0, 0.0, 1.0) + ((v[0], 0.0) if name == "translateX" else (0.0, v[0]))
    if name == "scale" and n in (1, 2):
        return (v[0], 0.0, 0.0, v[1] if n == 2 else v[0], 0.0, 0.0)
    if name in ("scaleX", "scaleY") and n == 1:
        return (v[0], 0.0, 0.0, 1.0, 0.0, 0.0) if name == "scaleX" else \
            (1.0, 0.0, 0.0, v[0], 0.0, 0.0)
    if name == "rotate" and n in (1, 3):
        a = math.radians(math.remainder(v[0], 360.0))
        turn = (math.cos(a), math.sin(a), -math.sin(a), math.cos(a), 0.0, 0.0)
        if n == 1:
            return turn
        return times(times((1.0, 0.0, 0.0, 1.0, v[1], v[2]), turn),
                      (1.0, 0.0, 0.0, 1.0, -v[1], -v[2]))
    if name in ("skewX", "skewY") and n == 1:
        t = math.tan(math.radians(math.remainder(v[0], 180.0)))
        return (1.0, 0.0, t, 1.0, 0.0, 0.0) if name == "skewX" else \
            (1.0, t, 0.0, 1.0, 0.0, 0.0)
    return None


def times(m: tuple[float, ...], n: tuple[float, ...]) -> tuple[float, ...]:
    """The matrix ``m`` then ``n`` applied to a point first (SVG's ``m n``)."""
    a, b, c, d, e, f = m
    p, q, r, s, t, u = n
    return (a * p + c * q, b * p + d * q, a * r + c * s, b * r + d * s, a * t + c * u + e,
            b * t + d * u + f)
