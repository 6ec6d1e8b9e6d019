"""Which links of a four-bar turn fully, found by turning them: the check on Grashof's rule.

:func:`grashof` classifies a four-bar by its inequality
S + L ≤ P + Q. The course checks such answers by sweeping the crank round and
asking whether the loop still closes (001 §3, "my check"). This module is that
sweep, and the range of one length over which a class holds, found both ways:
from the breakpoints of the inequalities, and by bisecting the sweep.
"""

from __future__ import annotations

import math

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..model import Mechanism

__all__ = ["GrashofResult", "grashof", "grashof_class", "four_bar_spans", "turns_fully",
           "class_by_rotation", "length_range", "length_range_by_rotation"]

SAMPLES = 720
"""Crank angles per sweep; the diagonal's extremes lie on the ground line, which is sampled."""


@dataclass(frozen=True, slots=True)
class GrashofResult:
    """Grashof class of a 4R four-bar.

    ``kind`` is ``"crank-rocker"``, ``"double-crank"``, ``"double-rocker"``,
    ``"change-point"`` or ``"triple-rocker"``; ``is_grashof`` is S + L ≤ P + Q;
    ``shortest`` is the number of the shortest link; ``links`` and ``lengths`` run
    round the loop (ground, input, coupler, output); ``margin`` is (P + Q) − (S + L).
    """

    kind: str
    is_grashof: bool
    shortest: int
    links: tuple[int, int, int, int]
    lengths: tuple[float, float, float, float]
    margin: float


def grashof(lengths, *, links: tuple[int, int, int, int] = (1, 2, 3, 4)) -> GrashofResult:
    """Classify a four-bar by Grashof's rule from its lengths in loop order.

    ``lengths`` are (ground, input, coupler, output). With S + L < P + Q the
    shortest link decides: the ground gives a double-crank, a link next to the
    ground a crank-rocker, the coupler a (Grashof) double-rocker. S + L = P + Q (to
    a relative 1e-12) is a change-point mechanism; S + L > P + Q a triple-rocker.

    Examples
    --------
    >>> grashof((0.3, 0.1, 0.25, 0.2)).kind
    'crank-rocker'
    >>> grashof((1.0, 2.0, 1.0, 2.0)).kind
    'change-point'
    """
    ls = tuple(float(x) for x in lengths)
    if len(ls) != 4 or min(ls) <= 0.0:
        raise InputError("a four-bar needs four positive lengths")
    order = sorted(range(4), key=lambda i: ls[i])
    short, p, q, long_ = (ls[i] for i in order)
    margin = (p + q) - (short + long_)
    if abs(margin) <= 1e-12 * (p + q):
        kind = "change-point"
    elif margin < 0.0:
        kind = "triple-rocker"
    else:
        kind = ("double-crank", "crank-rocker", "double-rocker", "crank-rocker")[order[0]]
    return GrashofResult(kind, margin >= -1e-12 * (p + q), links[order[0]], links, ls, margin)


def grashof_class(mech: Mechanism) -> GrashofResult | None:
    """Classify ``mech`` by :func:`grashof` if it is a 4R four-bar, else return None."""
    if len(mech.links) != 4 or mech.slides:
        return None
    pins = {n: mech.links_at(n) for n in mech.point_names if len(mech.links_at(n)) > 1}
    if len(pins) != 4 or any(len(at) != 2 for at in pins.values()):
        return None
    ends = {k.number: [n for n in k.names if n in pins] for k in mech.links}
    if any(len(v) != 2 for v in ends.values()):
        return None
    side = sorted(at[0] if at[1] == 1 else at[1] for at in pins.values() if 1 in at)
    if len(side) != 2 or side[0] == side[1]:
        return None
    first = mech.drive.link if mech.drive.link in side else side[0]
    last = side[1] if first == side[0] else side[0]
    coupler = next(k for k in ends if k not in (1, first, last))
    order = (1, first, coupler, last)

    def span(k: int) -> float:
        length = mech.link(k).span(*ends[k])
        if length <= 0.0:
            raise InputError(f"{mech.link(k).label} has no length between {ends[k][0]} and "
                             f"{ends[k][1]}: a four-bar needs four links of positive length")
        return length

    return grashof(tuple(span(k) for k in order), links=order)


_PHI = np.linspace(0.0, 2.0 * math.pi, SAMPLES, endpoint=False)
_COS, _SIN = np.cos(_PHI), np.sin(_PHI)


def turns_fully(ground: float, crank: float, coupler: float, rocker: float) -> bool:
    """True if ``crank`` can turn a full revolution relative to ``ground`` with the loop closed.

    The crank pin is swept round its pivot; at every angle the diagonal from it to
    the far pivot must be spanned by the coupler and rocker.

    Examples
    --------
    >>> turns_fully(300, 100, 250, 200), turns_fully(300, 200, 250, 100)
    (True, False)
    """
    return bool(_turn_each([ground], [crank], [coupler], [rocker])[0])


def _turn_each(ground, crank, coupler, rocker) -> np.ndarray:
    """:func:`turns_fully` of many four-bars at once, one for each row of the lengths."""
    g, a, b, c = (np.asarray(v, dtype=float) for v in (ground, crank, coupler, rocker))
    lo, hi = np.abs(b - c), b + c
    slack = 1e-12 * (g + a + b + c)
    # Every sampled diagonal lies within the bounds exactly when the shortest and the
    # longest do; four-bars that share ground and crank share their diagonals.
    if (g == g[0]).all() and (a == a[0]).all():
        g, a = g[:1], a[:1]
    d = np.hypot(a[:, None] * _COS - g[:, None], a[:, None] * _SIN)
    return (d.min(axis=1) >= lo - slack) & (d.max(axis=1) <= hi + slack)


def class_by_rotation(lengths) -> str:
    """The four-bar's class from which links turn fully.

    ``lengths`` are (ground, input, coupler, output).

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
    so the interval is bounded by such breakpoints; ``None`` for no upper bound. A
    class is also told by its shortest link: a crank-rocker whose crank is the
    output is another mechanism than one whose crank is the input. A change-point
    linkage (S + L = P + Q) is one at that length alone, so its range is the length
    itself; and a change point ends the range of the class either side of it, even
    where the same class resumes beyond.

    Examples
    --------
    >>> length_range((100, 30, 100, 65), 2)       # 001 §3 Ex 1: the coupler AB
    (65.0, 135.0)
    >>> length_range((300, 100, 300, 100), 2)     # a parallelogram: AB = 300 only
    (300.0, 300.0)
    >>> length_range((100, 100, 101, 100), 0)     # a triple-rocker up to 100 + 101 = 101 + 100
    (99.0, 101.0)
    """
    others = [x for i, x in enumerate(lengths) if i != index]
    here = _kind(lengths, index, lengths[index])
    if here[0] == "change-point":
        return float(lengths[index]), float(lengths[index])
    cuts = {abs(s1 * others[0] + s2 * others[1] + s3 * others[2])
            for s1 in (1, -1) for s2 in (1, -1) for s3 in (1, -1)} | set(others)
    cuts = sorted(float(x) for x in cuts if x > 0.0)
    def ends_range(x: float, beyond: float) -> bool:
        return (_kind(lengths, index, x)[0] == "change-point"
                or _kind(lengths, index, x * beyond) != here)

    lo, hi = 0.0, None
    for x in cuts:
        if x <= lengths[index] * (1 - 1e-12):
            lo = x if ends_range(x, 1 - 1e-9) else lo
        elif ends_range(x, 1 + 1e-9):
            hi = x
            break
    return lo, hi


STEP = 1.01
"""Ratio between neighbouring lengths of the outward scan of
:func:`length_range_by_rotation`: a band of another class narrower than 1 % of the
length could lie unseen between two of them."""


_BATCH = 64
"""Lengths of the scan tested at once: the class mostly changes within the first few."""


def length_range_by_rotation(lengths, index: int) -> tuple[float, float | None]:
    """The same interval, found on the turning test alone.

    The length is stepped outward from its value by the ratio :data:`STEP` until
    the links that turn fully change (so a crank-rocker whose crank becomes the
    output has left its range, though its name is the same), down to a billionth of
    the loop and up to four times it; the edge is then bisected.

    >>> lo, hi = length_range_by_rotation((100, 30, 100, 65), 2)
    >>> round(lo, 6), round(hi, 6)
    (65.0, 135.0)
    """
    x0 = lengths[index]
    total = sum(lengths)

    def kinds(xs: list[float]) -> np.ndarray:
        """Which links turn fully with the length made each of ``xs``, as a code: 1 the
        input, 2 the output, 4 the coupler about the input's pivot when neither does (a
        double-rocker, not a triple-rocker). Equal codes are one class, the same links
        cranks."""
        ls = np.tile(np.asarray(lengths, dtype=float), (len(xs), 1))
        ls[:, index] = xs
        g, a, b, c = ls.T
        crank, rocker = _turn_each(g, a, b, c), _turn_each(g, c, b, a)
        return crank + 2 * rocker + 4 * (_turn_each(a, b, c, g) & ~crank & ~rocker)

    here = kinds([x0])[0]

    def edge(inside: float, outside: float) -> float:
        for _ in range(60):
            mid = 0.5 * (inside + outside)
            if kinds([mid])[0] == here:
                inside = mid
            else:
                outside = mid
        return 0.5 * (inside + outside)

    def scan(ratio: float, stop) -> float | None:
        """The last length of the class before the first one out of it, or None: the
        lengths stepped out to ``stop``, tested a batch at a time."""
        steps = [x0]
        while not stop(steps[-1]):
            steps.append(steps[-1] * ratio)
        for k in range(1, len(steps), _BATCH):
            out = np.flatnonzero(kinds(steps[k:k + _BATCH]) != here)
            if len(out):
                j = k + int(out[0])
                return edge(steps[j - 1], steps[j])
        return None

    lo = scan(1.0 / STEP, lambda x: x < 1e-9 * total)
    hi = scan(STEP, lambda x: x > 4.0 * total)
    # A class may also change at a single length, where the loop can lie flat on one line
    # (a change point): no step of the scan lands there, so each is turned on its own.
    others = [x for i, x in enumerate(lengths) if i != index]
    flat = sorted({abs(s1 * others[0] + s2 * others[1] + others[2])
                   for s1 in (1, -1) for s2 in (1, -1)} - {0.0})
    inside = [x for x in flat if (lo or 0.0) < x < (hi or math.inf) and x != x0]
    for x, odd in zip(inside, kinds(inside) != here if inside else ()):
        if odd and x < x0:
            lo = x
        elif odd:
            hi = x
            break
    return (0.0 if lo is None else lo), hi


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


def _kind(lengths, index: int, x: float) -> tuple[str, int | None]:
    """The class with ``lengths[index]`` made ``x``, and the shortest link that sets it."""
    ls = [x if i == index else v for i, v in enumerate(lengths)]
    g = grashof(ls)
    grashof_kind = g.kind not in ("change-point", "triple-rocker")
    return g.kind, (g.links.index(g.shortest) if grashof_kind else None)
