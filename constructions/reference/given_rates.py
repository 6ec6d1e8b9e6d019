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
    """The given member's speed along its frame guide or, a point of the input link, along
    its circle (or ω; with ``second``, its acceleration, tangential on the circle, or α)
    when the input turns at ω = ``w``, α = ``a``."""
    kin = solver.solve(with_input_rates(m, w, a))
    g = m.given
    if g.kind == "omega":
        return (kin.alphas if second else kin.omegas)[g.target]
    if g.kind == "input_point":
        # along the point's circle about the pivot, k × (P − O) / |P − O|: ω·r and α·r
        d = m.drive.link
        pivot = next(n for n in m.link(d).names if n in m.frame.names)
        (px, py), (ox, oy) = kin.points[g.target], kin.points[pivot]
        r = ((px - ox) ** 2 + (py - oy) ** 2) ** 0.5
        vx, vy = (solver.point_acceleration if second else solver.point_velocity)(
            kin, m, d, g.target)
        return (vy * (px - ox) - vx * (py - oy)) / r
    guide = next(i for i, s in enumerate(m.slides)
                 if s.point == g.target and s.guide_link == 1)
    rate = kin.slide_rates[guide]
    return rate.acceleration if second else rate.velocity
