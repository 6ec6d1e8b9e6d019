"""A turning moment given as a formula T(θ) read to the data's own precision: the mean by
quadrature, the intercepts by root-finding on the formula, each loop's area by adaptive
Gauss–Legendre quadrature between its intercepts.

The drawing at equal steps (:func:`~.flywheel.read_diagram`) joins its steps by straight
lines, which costs ΔE some h²·|T′| (5999.99 J for the books' T = 15000 + 6000 sin 2θ, whose
ΔE is 6000 J to the last figure). That drawing stays the graphical answer; this reading is
the number given, the drawing compared with it. A table of straight pieces needs none of
this: its trapezoids are its exact areas (:func:`~.flywheel.read_table`).
"""

from __future__ import annotations

import math

import numpy as np

from .flywheel import Diagram, Reading, read_diagram

__all__ = ["exact_reading", "loop_area"]

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(16)
MAX_PANELS = 4096
"""The most panels a loop is split into: a formula smooth enough to be a book's is done
within a few dozen; one with a pole (1/sin θ) stops here, its area then as good as that."""


def loop_area(f, a: float, b: float) -> float:
    """∫ₐᵇ f dθ by 16-point Gauss–Legendre on 1, 2, 4, … equal panels until two counts agree
    to rounding (a smooth f's error falls as h³² with the panel h, so once it is below the
    sum's own rounding it stays there).

    >>> round(loop_area(math.sin, 0.0, math.pi), 15)
    2.0
    """
    if b <= a:
        return 0.0
    last, n = None, 1
    while True:
        parts = []
        h = (b - a) / n
        for i in range(n):
            lo = a + i * h
            half, mid = h / 2, lo + h / 2
            parts.append(half * math.fsum(w * f(mid + half * x)
                                          for x, w in zip(_NODES, _WEIGHTS)))
        total = math.fsum(parts)
        scale = math.fsum(abs(p) for p in parts)
        if last is not None and (abs(total - last) <= 1e-14 * max(scale, 1e-300)
                                 or n >= MAX_PANELS):
            return total
        last, n = total, 2 * n


def _bisect(f, a: float, b: float, fa: float) -> float:
    """The root of ``f`` between ``a`` and ``b`` (f(a) = ``fa`` and f(b) of opposite signs),
    halved to the last bit: slow beside the secant's family, but never misled by a flat
    curve, and some 60 halvings are cheap beside the quadrature."""
    while True:
        m = (a + b) / 2
        if not a < m < b:
            return m
        fm = f(m)
        if fm == 0.0:
            return m
        if (fm < 0) == (fa < 0):
            a, fa = m, fm
        else:
            b = m


def exact_reading(d: Diagram) -> Reading:
    """Read the formula ``d`` to its own precision: the mean ∫T dθ / cycle; the intercepts,
    each change of sign of T − T_mean between the drawing's steps (or a step where it is 0
    between two of opposite signs) narrowed by bisection; each area ∫ (T − T_mean) dθ
    between neighbouring intercepts; ΔE the highest energy less the lowest. The drawing's
    steps are kept as the samples (for the figure) and its step."""
    drawn = read_diagram(d)
    mean = loop_area(d.torque, 0.0, d.cycle) / d.cycle
    # The drawing's mean is the periodic trapezoid rule's, exact to rounding for a smooth
    # periodic T and, summed by fsum over steps set symmetrically, free of the quadrature's
    # last-bit noise (15000, not 14999.999999999998): it is taken where the two agree.
    if abs(drawn.mean - mean) <= 1e-12 * max(abs(t) for _, t in drawn.samples):
        mean = drawn.mean

    def excess(t: float) -> float:
        # T as the cycle gives it, repeating: a formula need not repeat on its own
        return d.torque(t - d.cycle if t >= d.cycle else t) - mean

    thetas = [t for t, _ in drawn.samples] + [d.cycle]
    values = [excess(t) for t in thetas[:-1]]
    values.append(values[0])
    crossings: list[float] = []
    last = next((1.0 if v > 0 else -1.0 for v in reversed(values) if v != 0.0), 0.0)
    zero_at = None
    for i in range(len(thetas) - 1):
        v = values[i]
        if v != 0.0:
            sign = 1.0 if v > 0 else -1.0
            if last and sign != last:
                crossings.append(zero_at if zero_at is not None else thetas[i])
            last, zero_at = sign, None
        elif zero_at is None:
            zero_at = thetas[i]
        w = values[i + 1]
        if v * w < 0.0:
            crossings.append(_bisect(excess, thetas[i], thetas[i + 1], v))
            last = 1.0 if w > 0 else -1.0
    crossings = sorted({c % d.cycle for c in crossings})
    if len(crossings) < 2:
        return Reading(mean, (), (), 0.0, 0.0, 0.0, drawn.step, drawn.samples)
    ends = crossings + [crossings[0] + d.cycle]
    # the last loop runs over the cycle's end, where T may kink: it is split there
    areas = tuple(loop_area(excess, a, min(b, d.cycle)) + loop_area(excess, d.cycle, b)
                  if b > d.cycle else loop_area(excess, a, b) for a, b in zip(ends, ends[1:]))
    levels = [0.0]
    for a in areas[:-1]:
        levels.append(levels[-1] + a)
    # a curve that repeats within its cycle has its highest twice, equal but for rounding:
    # the first is taken, as the drawing and a reader would
    tie = 1e-12 * math.fsum(abs(a) for a in areas)
    top = next(i for i, v in enumerate(levels) if v >= max(levels) - tie)
    bottom = next(i for i, v in enumerate(levels) if v <= min(levels) + tie)
    return Reading(mean, tuple(crossings), areas, levels[top] - levels[bottom],
                   crossings[top], crossings[bottom], drawn.step, drawn.samples)
