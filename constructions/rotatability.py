"""Which links of a four-bar turn fully, found by turning them: the check on Grashof's rule.

:func:`~constructions.analytic.grashof` classifies a four-bar by its inequality
S + L ≤ P + Q. The course checks such answers by sweeping the crank round and
asking whether the loop still closes (001 §3, "my check"). This module is that
sweep, and the range of one length over which a class holds, found both ways:
from the breakpoints of the inequalities, and by bisecting the sweep.
"""

from __future__ import annotations

import math

from .analytic import grashof, grashof_class
from .model import Mechanism

__all__ = ["four_bar_spans", "turns_fully", "class_by_rotation", "length_range", "length_range_by_rotation"]

SAMPLES = 720
"""Crank angles per sweep; the diagonal's extremes lie on the ground line, which is sampled."""


def turns_fully(ground: float, crank: float, coupler: float, rocker: float) -> bool:
    """True if ``crank`` can turn a full revolution relative to ``ground`` with the loop closed.

    The crank pin is swept round its pivot; at every angle the diagonal from it to
    the far pivot must be spanned by the coupler and rocker.

    Examples
    --------
    >>> turns_fully(300, 100, 250, 200), turns_fully(300, 200, 250, 100)
    (True, False)
    """
    lo, hi = abs(coupler - rocker), coupler + rocker
    slack = 1e-12 * (ground + crank + coupler + rocker)
    for k in range(SAMPLES):
        phi = 2 * math.pi * k / SAMPLES
        d = math.hypot(crank * math.cos(phi) - ground, crank * math.sin(phi))
        if d < lo - slack or d > hi + slack:
            return False
    return True


def class_by_rotation(lengths) -> str:
    """The four-bar's class from which links turn fully; ``lengths`` = (ground, input, coupler, output).

    Examples
    --------
    >>> class_by_rotation((300, 100, 250, 200))
    'crank-rocker'
    """
    g, a, b, c = lengths
    ends = turns_fully(g, a, b, c) + turns_fully(g, c, b, a)
    if ends == 2:
        return "double-crank"
    if ends == 1:
        return "crank-rocker"
    return "double-rocker" if turns_fully(a, b, c, g) else "triple-rocker"


def length_range(lengths, index: int) -> tuple[float, float | None]:
    """The open interval of ``lengths[index]`` over which Grashof's class stays as it is.

    The class can change only where S + L = P + Q or where two lengths swap order,
    so the interval is bounded by such breakpoints; ``None`` for no upper bound.

    Examples
    --------
    >>> length_range((100, 30, 100, 65), 2)       # 001 §3 Ex 1: the coupler AB
    (65.0, 135.0)
    """
    others = [x for i, x in enumerate(lengths) if i != index]
    here = _kind(lengths, index, lengths[index])
    cuts = {abs(s1 * others[0] + s2 * others[1] + s3 * others[2])
            for s1 in (1, -1) for s2 in (1, -1) for s3 in (1, -1)} | set(others)
    cuts = sorted(float(x) for x in cuts if x > 0.0)
    lo, hi = 0.0, None
    for x in cuts:
        if x <= lengths[index] * (1 - 1e-12):
            lo = x if _kind(lengths, index, x * (1 - 1e-9)) != here else lo
        elif _kind(lengths, index, x * (1 + 1e-9)) != here:
            hi = x
            break
    return lo, hi


def length_range_by_rotation(lengths, index: int) -> tuple[float, float | None]:
    """The same interval, bracketed and bisected on :func:`class_by_rotation` alone."""
    here = class_by_rotation(lengths)
    x0 = lengths[index]
    total = sum(lengths)

    def kind(x: float) -> str:
        return class_by_rotation([x if i == index else v for i, v in enumerate(lengths)])

    def edge(inside: float, outside: float) -> float:
        for _ in range(60):
            mid = 0.5 * (inside + outside)
            if kind(mid) == here:
                inside = mid
            else:
                outside = mid
        return 0.5 * (inside + outside)

    out = x0
    while out > 1e-9 * total and kind(out) == here:
        out *= 0.5
    lo = 0.0 if kind(out) == here else edge(x0, out)
    out = x0
    while out < 4 * total and kind(out) == here:
        out *= 2.0
    hi = None if kind(out) == here else edge(x0, out)
    return lo, hi


def four_bar_spans(mech: Mechanism) -> dict[str, int] | None:
    """A 4R four-bar's lengths by name ("O2O4", "AB", …) → index in Grashof's loop order."""
    gc = grashof_class(mech)
    if gc is None:
        return None
    pins = {n for n in mech.point_names if len(mech.links_at(n)) > 1}
    out = {}
    for i, k in enumerate(gc.links):
        ends = [n for n in mech.link(k).names if n in pins]
        out["".join(ends)] = i
        out["".join(reversed(ends))] = i
    return out


def _kind(lengths, index: int, x: float) -> str:
    ls = [x if i == index else v for i, v in enumerate(lengths)]
    return grashof(ls).kind
