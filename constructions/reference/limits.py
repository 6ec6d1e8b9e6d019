"""The reference for the limit positions: where the output's velocity changes sign.

Independent of the compass construction in :mod:`.limit_positions`, which draws
the limits from their geometry (rod and crank in line, lever tangent to the
crank circle). Here the analytic solver is run round the crank's revolution; the
output's velocity (a block's along its frame guide, or a link's ω) is bracketed
where it changes sign and each zero narrowed to the last bit. The stroke is the
distance between the block's two places there, the time ratio the crank angles
between the zeros.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .solver import SingularPosition, follow_branches, solve
from ..errors import AssemblyError, InputError
from ..model import Drive, Mechanism

__all__ = ["LimitReference", "limit_reference", "section_zero", "turn_zeros"]

SAMPLES = 360
"""Crank angles sampled to bracket the reversals: far more than a linkage's two."""


@dataclass(frozen=True)
class LimitReference:
    """The output's two reversals over a revolution (SI, radians)."""

    crank_angles: tuple[float, float]
    slow: float
    quick: float
    stroke: float | None

    @property
    def time_ratio(self) -> float:
        """Slow stroke over quick stroke."""
        return self.slow / self.quick


def limit_reference(mech: Mechanism, *, point: str | None = None,
                    link: int | None = None) -> LimitReference:
    """Find where the output reverses: block ``point`` on its frame guide, or link ``link``.

    Raises
    ------
    InputError
        If the crank cannot turn fully, or the output does not reverse exactly twice.
    """
    mech = follow_branches(mech)
    d = mech.drive
    sense = 1.0 if d.omega >= 0 else -1.0
    slide = None
    if point is not None:
        slide = next(i for i, s in enumerate(mech.slides) if s.point == point and s.guide_link == 1)

    mech = mech.with_drive(Drive(d.link, d.angle, sense, 0.0))

    def refused(theta: float, e: AssemblyError) -> InputError:
        stops = "stands at a dead point" if isinstance(e, SingularPosition) else "cannot assemble"
        return InputError(f"the crank cannot turn fully, so it has no limit positions to pass: at "
                          f"θ{d.link} = {mech.units.angle_brief(theta)} the mechanism {stops}"
                          ).because(e)

    def state(theta: float) -> tuple[float, float]:
        """(output velocity, block position along its guide) at crank angle ``theta``."""
        try:
            kin = solve(mech.with_drive(Drive(d.link, theta, sense, 0.0)))
        except (SingularPosition, AssemblyError) as e:
            raise refused(theta, e) from None
        if slide is None:
            return kin.omegas[link], 0.0
        rate = kin.slide_rates[slide]
        return rate.velocity, rate.position

    def speeds_at(angles: np.ndarray) -> np.ndarray:
        """The output's velocity at each of ``angles``, solved together."""
        from .turn import solve_turn     # the vectorised solver: only a turn's scan needs it

        turn = solve_turn(mech, angles)
        if not turn.ok.all():
            first = int(turn.ok.argmin())
            raise refused(float(angles[first]), turn.refusal(first))
        return turn.omegas[link] if slide is None else turn.slide_velocities[slide]

    zeros = turn_zeros(speeds_at, d.angle, sense)
    if len(zeros) != 2:
        output = f"the block {point}" if point is not None else mech.link(link).label
        raise InputError(f"{output} reverses {len(zeros)} times in a turn of link {d.link}, "
                         "not twice; a time ratio needs exactly two limit positions")
    first = (sense * (zeros[1] - zeros[0])) % (2 * math.pi)
    slow, quick = max(first, 2 * math.pi - first), min(first, 2 * math.pi - first)
    stroke = abs(state(zeros[1])[1] - state(zeros[0])[1]) if slide is not None else None
    return LimitReference((zeros[0], zeros[1]), slow, quick, stroke)


def turn_zeros(f, start: float, sense: float, samples: int = SAMPLES) -> list[float]:
    """The angles of a turn from ``start`` (rad, the way ``sense`` turns) where ``f`` is 0,
    in turn order: ``f`` (an array of angles to its values, solved together) is scanned at
    ``samples`` steps and each change of sign narrowed by :func:`section_zero`."""
    thetas = [start + sense * 2 * math.pi * k / samples for k in range(samples + 1)]
    values = np.asarray(f(np.asarray(thetas[:-1]))).tolist()     # the scan, at once
    values.append(values[0])     # a turn on is the same position: a zero at the start,
    zeros = []                   # rounded two ways, is then seen once, not missed or twice
    for k in range(samples):
        if values[k] == 0.0:
            zeros.append(thetas[k])
        elif values[k] * values[k + 1] < 0.0:
            zeros.append(section_zero(f, thetas[k], thetas[k + 1], values[k]))
    return zeros


def section_zero(f, lo: float, hi: float, f_lo: float, parts: int = 32) -> float:
    """A zero of ``f`` between ``lo`` and ``hi`` (``f(lo) = f_lo``, ``f(hi)`` of the other
    sign), narrowed until the two ends are neighbouring floats. ``f`` is taken at
    ``parts − 1`` points of the bracket at once (it maps an array of them to values), so
    each round narrows the bracket ``parts``-fold: a few vectorised solves rather than
    fifty scalar ones.

    >>> import math
    >>> root = section_zero(lambda t: [math.cos(x) for x in t], 0.0, 3.0, 1.0)
    >>> abs(root - math.pi / 2) < 1e-15
    True
    """
    for _ in range(80):
        inner = np.linspace(lo, hi, parts + 1)[1:-1]
        inner = inner[(inner - lo) * (hi - inner) > 0.0]      # strictly inside, either way
        if not len(inner):
            break
        values = np.asarray(f(inner))
        if (values == 0.0).any():
            return float(inner[np.argmax(values == 0.0)])
        other = np.flatnonzero((values < 0.0) != (f_lo < 0.0))
        if not len(other):
            lo, f_lo = float(inner[-1]), float(values[-1])
            continue
        k = int(other[0])
        hi = float(inner[k])
        if k:
            lo, f_lo = float(inner[k - 1]), float(values[k - 1])
    return 0.5 * (lo + hi)
