"""Where a sampled turn of the input passes a change point.

At a change point two assemblies of the linkage meet (a parallelogram or a rhombus with
its links in line, or with a moving pin on a frame pivot): the loop equations' Jacobian
loses rank there, and the linkage may go on in either assembly. A branch named by a side
("B = right") is the other assembly beyond such a point, so a turn sampled with it hops
from one motion to another between two steps. Nothing in a turn's samples shows this but
the Jacobian's conditioning, which falls to 0 like the distance to the point (the two
assemblies cross at an angle): a step lands on it only by chance, so it is sought
between the steps, where the sampled conditioning dips. A step that does land on one is
refused by the solver as a dead point, as it refuses the positions a rounding either side:
a rhombus's moving pin on a frame pivot too, where the circles that place the next pin
coincide (refused as no assembly, it would read as a gap, and the turn would run on
past it).
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass

import numpy as np

from ..errors import AssemblyError
from ..model import Drive, Mechanism
from .solver import SINGULAR_RCOND, SingularPosition, solve

__all__ = ["ChangePoint", "change_point_between", "DIP"]

DIP = 0.5
"""A sampled conditioning this fraction or less of the larger of its neighbours' is a dip
worth a search: falling as the distance to a point between them, it is at most half the
farther neighbour's; a smooth minimum so sharp that it passes too is searched in vain."""

_GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0


@dataclass(frozen=True)
class ChangePoint:
    """Where a turn stops being one motion: the input's ``angle`` (rad), and the solver's
    refusal there if it refuses more than a dead point (no assembly between two steps)."""

    angle: float
    refusal: AssemblyError | None = None


def _conditioning(mech: Mechanism, angle: float) -> tuple[float, AssemblyError | None]:
    """The Jacobian's conditioning (rcond) with the input at ``angle``, 0 where the solver
    refuses the position; and its refusal, if it is not a dead point."""
    d = mech.drive
    try:
        return solve(mech.with_drive(Drive(d.link, angle, d.omega, 0.0))).conditioning, None
    except SingularPosition:
        return 0.0, None
    except AssemblyError as e:
        return 0.0, e


def change_point_between(mech: Mechanism, angles: list[float],
                         conditioning: list[float | None]) -> ChangePoint | None:
    """The first input angle of a sampled turn where the linkage stands at a change point.

    Parameters
    ----------
    mech : Mechanism
        The linkage; its drive's link and speed are kept, its angle replaced.
    angles : list of float
        The input's angles at the turn's steps (rad), in the order it turns, round once.
    conditioning : list of float or None
        The solver's conditioning at each step; None where it refused the step.

    Returns
    -------
    ChangePoint or None
        Where the Jacobian's conditioning falls below ``SINGULAR_RCOND`` between two solved
        steps, found by a golden-section search down to the angle's rounding, or a step
        between two solved ones that is itself a dead point (a change point landed on);
        None if there is none. Any other refused step is a gap the turn shows as one.

    Examples
    --------
    A parallelogram of crank 1 and frame 3 lines its four pivots up at θ2 = 180°:

    >>> from tarsim.constructions.model import Link
    >>> m = Mechanism((Link(1, (("O2", (0, 0)), ("O4", (3, 0)))),
    ...                Link(2, (("O2", (0, 0)), ("A", (1, 0)))),
    ...                Link(3, (("A", (0, 0)), ("B", (3, 0)))),
    ...                Link(4, (("O4", (0, 0)), ("B", (1, 0))))),
    ...               Drive(2, 1.0, omega=1.0), branches={"B": "left"})
    >>> angles = [1.0 + 2 * math.pi * k / 36 for k in range(36)]
    >>> rconds = [solve(m.with_drive(Drive(2, a, 1.0))).conditioning for a in angles]
    >>> round(math.degrees(change_point_between(m, angles, rconds).angle), 4)
    180.0
    """
    n = len(angles)
    for k in _dips(conditioning).tolist():
        here, before, after = conditioning[k], conditioning[k - 1], conditioning[(k + 1) % n]
        if here is None:
            if _conditioning(mech, angles[k])[1] is None:
                return ChangePoint(angles[k])
            continue
        if here > DIP * max(before, after):
            continue
        low = angles[k - 1]
        high = low + math.remainder(angles[(k + 1) % n] - low, math.tau)
        found = _least(mech, min(low, high), max(low, high))
        if found is not None:
            return found
    return None


def _dips(conditioning: list[float | None]) -> np.ndarray:
    """The steps, in order, between two solved ones that are refused or dip to ``DIP`` of
    the larger neighbour or less: found at once, as a turn has thousands of steps and
    seldom a dip."""
    here = np.array([math.nan if c is None else c for c in conditioning])
    before, after = np.roll(here, 1), np.roll(here, -1)
    with np.errstate(invalid="ignore"):
        dip = np.isnan(here) | (here <= DIP * np.maximum(before, after))
    return np.flatnonzero(dip & ~np.isnan(before) & ~np.isnan(after))


def _least(mech: Mechanism, low: float, high: float) -> ChangePoint | None:
    """Where in [low, high] (rad) the conditioning falls below ``SINGULAR_RCOND``, sought by
    a golden-section search for its least down to the angles' rounding; None if it does not."""
    tiny = 8 * sys.float_info.epsilon * max(1.0, abs(low), abs(high))
    a, b = low, high
    c, d = b - _GOLDEN * (b - a), a + _GOLDEN * (b - a)
    (fc, ec), (fd, ed) = _conditioning(mech, c), _conditioning(mech, d)
    while b - a > tiny and min(fc, fd) >= SINGULAR_RCOND:
        if fc <= fd:
            b, d, fd, ed = d, c, fc, ec
            c = b - _GOLDEN * (b - a)
            fc, ec = _conditioning(mech, c)
        else:
            a, c, fc, ec = c, d, fd, ed
            d = a + _GOLDEN * (b - a)
            fd, ed = _conditioning(mech, d)
    angle, least, refusal = (c, fc, ec) if fc <= fd else (d, fd, ed)
    return ChangePoint(angle, refusal) if least < SINGULAR_RCOND else None
