"""The follower's motion at a stated cam angle: by its law, and by differences of its lift.

The books ask the follower's displacement, velocity and acceleration "when the cam has
turned 40° from the beginning of the rise". The law gives y, y′ and y″ there in closed form
(:mod:`..reference.cam_laws`); the check differentiates the lift alone, y(θ), by second-order
differences on the same analytic piece, so a wrong coefficient in a law's y′ or y″ shows.
On a join of two segments, or where y″ jumps within one, the reading is the motion just
after it (the later piece), as the profile table gives it.

The difference step is h = 10⁻⁴ of the segment's angle: the truncation, of order
(h/β)²·y‴β³ and (h/β)²·y⁗β⁴, is some 10⁻⁷ of a segment's peak y′ or y″ (the laws' π³ and
π⁴ included), and the rounding, of order ε·h_lift/h and ε·h_lift/h², a few 10⁻⁸; the
reading is held to 10⁻⁵ of its segment's peak.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from ..reference.cam_laws import Motion, peaks
from .extremes import Piece, pieces

__all__ = ["Reading", "read_at", "STEP", "AGREE"]

STEP = 1e-4
"""The difference step, as a fraction of the segment's angle."""

AGREE = 1e-5
"""How far (as a fraction of its segment's peak) the differences may stand from the law."""


@dataclass(frozen=True)
class Reading:
    """The follower's motion at ``theta`` (rad from the first segment's start), in
    ``segment`` (from 1): by the law, and y′, y″ by differences of y; ``peak`` the
    segment's greatest |y′| and |y″| (0 for a dwell)."""

    theta: float
    segment: int
    law: Motion
    y1_diff: float
    y2_diff: float
    peak: tuple[float, float]

    @property
    def passed(self) -> bool:
        """The differences agree with the law's coefficients (see the module's bound)."""
        return (abs(self.y1_diff - self.law.y1) <= AGREE * self.peak[0]
                and abs(self.y2_diff - self.law.y2) <= AGREE * self.peak[1])


def _piece_at(segments: Sequence[Any], theta: float) -> Piece:
    """The analytic piece ``theta`` falls in; on a break, the one after it."""
    found = pieces(segments)
    after = [p for p in found if p.start + p.t0 <= theta * (1 + 1e-15)]
    return after[-1] if after else found[0]


def read_at(segments: Sequence[Any], theta: float) -> Reading:
    """The follower's motion at cam angle ``theta`` (rad, 0 to 2π from the first segment's
    start), by its law and checked by differences of its lift.

    Examples
    --------
    >>> from tarsim.constructions.cams.displacement import Segment
    >>> r = read_at([Segment("rise", math.pi, 1.0, "simple harmonic"),
    ...              Segment("return", math.pi, 1.0, "simple harmonic")], math.pi / 2)
    >>> round(r.law.y, 12), round(r.law.y1, 12), r.passed
    (0.5, 0.5, True)
    """
    p = _piece_at(segments, theta)
    s, t = p.law, theta - p.start
    m = p.motion(t)
    if s.kind == "dwell":
        return Reading(theta, p.segment, m, 0.0, 0.0, (0.0, 0.0))
    h = STEP * s.angle

    def y(k: int) -> float:
        return p.motion(t + k * h).y
    if t - 2 * h < 0:              # at the segment's start: forward differences
        d1 = (-3 * y(0) + 4 * y(1) - y(2)) / (2 * h)
        d2 = (2 * y(0) - 5 * y(1) + 4 * y(2) - y(3)) / (h * h)
    elif t + 2 * h > s.angle:      # at its end: backward
        d1 = (3 * y(0) - 4 * y(-1) + y(-2)) / (2 * h)
        d2 = (2 * y(0) - 5 * y(-1) + 4 * y(-2) - y(-3)) / (h * h)
    else:
        d1 = (y(1) - y(-1)) / (2 * h)
        d2 = (y(1) - 2 * y(0) + y(-1)) / (h * h)
    v, a = peaks(s.law, s.lift, s.angle, s.blend, s.split)
    if math.isinf(a):              # uniform velocity: y″ = 0 inside, held to y′'s scale
        a = v / s.angle
    return Reading(theta, p.segment, m, d1, d2, (v, a))
