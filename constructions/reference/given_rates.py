"""An input given by another member's motion, converted by the vector-loop solver.

The conversion of :mod:`..given_rate` by drawing is checked against this one: the solver
solves the mechanism at provisional rates of the input and reads the member's speed (or ω)
and acceleration (or α) off its solution, each linear in the input's ω and α.
"""

from __future__ import annotations

from ..model import Drive, Mechanism
from . import solver

__all__ = ["member_rate", "with_input_rates"]


def with_input_rates(m: Mechanism, w: float, a: float) -> Mechanism:
    """``m`` with its input turning at ω = ``w``, α = ``a``, the member's rates still
    given (so the drive keeps whether its α is)."""
    d = m.drive
    return m.with_drive(Drive(d.link, d.angle, w, a, m.given.second_given))


def member_rate(m: Mechanism, w: float, a: float, *, second: bool = False) -> float:
    """The given member's speed along its frame guide (or ω; with ``second``, its
    acceleration or α) when the input turns at ω = ``w``, α = ``a``."""
    kin = solver.solve(with_input_rates(m, w, a))
    g = m.given
    if g.kind == "omega":
        return (kin.alphas if second else kin.omegas)[g.target]
    guide = next(i for i, s in enumerate(m.slides)
                 if s.point == g.target and s.guide_link == 1)
    rate = kin.slide_rates[guide]
    return rate.acceleration if second else rate.velocity
