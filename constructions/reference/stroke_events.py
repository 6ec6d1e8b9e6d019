"""Where a block on a frame guide stops accelerating over a turn, and how fast it goes there.

The books ask of an engine "the crank angle at which the piston's acceleration is zero"
and "the crank angle at which its velocity is greatest, and that velocity". The crank
turns at a steady speed (α = 0, as the books take it); angles are turned from the
dead centre where the block stands farthest from the crank shaft (the books' inner dead
centre), the way the crank turns, and the out-stroke runs from it to the other dead
centre. The velocity peaks where the acceleration is 0, so both asks rest on the zeros
of the block's acceleration along its guide.

:func:`stroke_events` takes the zeros from a root finder it is given: the solution's is
the vectorised turn narrowed by :func:`~.limits.section_zero` (as ``tarsim sweep``
narrows its zeros); :func:`bisected_zeros`, the reference's, scans the scalar solver and
halves each change of sign's bracket, one position at a time.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..model import Drive, Mechanism
from .limits import SAMPLES, limit_reference
from .solver import follow_branches, solve

__all__ = ["StrokeEvents", "stroke_events", "bisected_zeros", "steady"]


@dataclass(frozen=True)
class StrokeEvents:
    """The block's acceleration zeros over a turn (SI, radians).

    ``dead`` is the crank angle at the dead centre the angles are turned from, ``out`` the
    turn from it to the other dead centre, ``zeros`` the crank angles where the
    acceleration is 0 in the order the crank reaches them, ``speeds`` the block's speed
    at each."""

    dead: float
    out: float
    sense: float
    zeros: tuple[float, ...]
    speeds: tuple[float, ...]

    def turned(self, angle: float) -> float:
        """The crank's turn from the dead centre to ``angle`` (rad, in [0, 2π))."""
        return (self.sense * (angle - self.dead)) % math.tau

    @property
    def on_out_stroke(self) -> tuple[float, ...]:
        """The zeros between the dead centre and the other, the out-stroke's."""
        return tuple(z for z in self.zeros if self.turned(z) < self.out)

    @property
    def fastest(self) -> int:
        """The zero the block goes fastest at, the first reached of those that tie to
        rounding (a centred slider-crank's two)."""
        top = max(self.speeds)
        return next(i for i, v in enumerate(self.speeds) if v >= top * (1 - 1e-12))


def steady(mech: Mechanism) -> Mechanism:
    """The mechanism's branches followed round a turn, its crank at its ω and α = 0."""
    m = follow_branches(mech)
    d = m.drive
    return m.with_drive(Drive(d.link, d.angle, d.omega, 0.0))


def stroke_events(mech: Mechanism, point: str,
                  zeros_of: Callable[[Mechanism, int, float, float], list[float]]
                  ) -> StrokeEvents:
    """The zeros of block ``point``'s acceleration along its frame guide over a turn.

    ``zeros_of(mech, slide, start, sense)`` gives the crank angles of a turn from
    ``start`` (the way ``sense`` turns) where slide ``slide``'s acceleration is 0.

    Raises
    ------
    InputError
        If the crank cannot turn fully or the block does not reverse twice (from
        :func:`~.limits.limit_reference`), or its acceleration never changes sign.
    """
    m = steady(mech)
    d = m.drive
    if d.omega == 0.0:
        raise InputError(f"link {d.link} stands still (ω = 0): the block's speed over a turn "
                         "needs the crank's speed, [input] omega")
    sense = 1.0 if d.omega > 0 else -1.0
    slide = next(i for i, s in enumerate(m.slides) if s.point == point and s.guide_link == 1)
    pivot = next(p for p in m.link(d.link).names if 1 in m.links_at(p))
    limits = limit_reference(m, point=point).crank_angles

    def far(theta: float) -> float:
        kin = solve(m.with_drive(Drive(d.link, theta, d.omega, 0.0)))
        return math.dist(kin.points[point], kin.points[pivot])

    dead, other = sorted(limits, key=far, reverse=True)
    zeros = zeros_of(m, slide, dead, sense)
    if not zeros:
        raise InputError(f"the block {point}'s acceleration never changes sign in a turn of "
                         f"link {d.link}, so it has no zero and its speed no peak")
    speeds = tuple(abs(solve(m.with_drive(Drive(d.link, z, d.omega, 0.0)))
                       .slide_rates[slide].velocity) for z in zeros)
    return StrokeEvents(dead, (sense * (other - dead)) % math.tau, sense, tuple(zeros), speeds)


def bisected_zeros(mech: Mechanism, slide: int, start: float, sense: float) -> list[float]:
    """The reference's zeros: the scalar solver at each step of the turn, each change of
    sign's bracket halved, one position at a time, until its ends are neighbouring floats."""
    d = mech.drive

    def a(theta: float) -> float:
        kin = solve(mech.with_drive(Drive(d.link, theta, d.omega, 0.0)))
        return kin.slide_rates[slide].acceleration

    thetas = (start + sense * np.linspace(0.0, math.tau, SAMPLES + 1)).tolist()
    values = [a(t) for t in thetas[:-1]]
    values.append(values[0])
    out = []
    for k in range(SAMPLES):
        if values[k] == 0.0:
            out.append(thetas[k])
        elif values[k] * values[k + 1] < 0.0:
            out.append(_halved(a, thetas[k], thetas[k + 1], values[k]))
    return out


def _halved(f: Callable[[float], float], lo: float, hi: float, f_lo: float) -> float:
    """The zero of ``f`` between ``lo`` and ``hi`` (``f(lo) = f_lo``, ``f(hi)`` the other
    sign), by halving the bracket until no float lies strictly inside it."""
    while True:
        mid = 0.5 * (lo + hi)
        if not (lo < mid < hi or hi < mid < lo):
            return mid
        f_mid = f(mid)
        if f_mid == 0.0:
            return mid
        if (f_mid < 0.0) == (f_lo < 0.0):
            lo, f_lo = mid, f_mid
        else:
            hi = mid
