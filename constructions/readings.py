"""Numbers read off a drawn construction: speed and ω ratios, the mechanical advantage, the
distance from a point to an instant centre, and a four-bar's transmission angle.

Each is read the way a student reads it with dividers and a protractor, from what is
already drawn: ω ratios from the centres on their line (as ω itself is), speed ratios
from the velocity polygon's vectors, a distance between two drawn points, an angle
between two drawn links.
"""

from __future__ import annotations

import math

from . import asks as A
from .centres import CENTRES_FIGURE, OMEGA_FIGURE, located, ratio_by_centres
from .checks import Answer
from .errors import InputError
from .model import Mechanism
from .record import Panel
from .reference.rotatability import four_bar_spans
from .velocity_polygon import WORKED, drawn_velocity_polygon

__all__ = ["answer_reading", "transmission_pin", "mu_askable", "MU_WHY_NOT"]

MU_WHY_NOT = {A.TransmissionAngle: "a transmission angle is asked of a four-bar of four pins, "
                                   "between its coupler and its output link, and this is not one"}
"""Why a mechanism that is no four-bar has no transmission angle here."""


def transmission_pin(m: Mechanism) -> tuple[str, str, str]:
    """A four-bar's pin B that joins coupler and output, the coupler's other pin A, and the
    output's frame pivot O: μ is the angle ABO.

    Raises
    ------
    InputError
        If the mechanism is no four-bar of four pins.
    """
    if four_bar_spans(m) is None:
        raise InputError(MU_WHY_NOT[A.TransmissionAngle])
    d = m.drive.link
    pivots = {n for n in m.frame.names if len(m.links_at(n)) > 1}
    output = next(k.number for k in m.links if k.number not in (1, d)
                  and any(n in pivots for n in k.names))
    coupler = next(k.number for k in m.links if k.number not in (1, d, output))
    b = next(n for n in m.link(output).names if coupler in m.links_at(n))
    a = next(n for n in m.link(coupler).names if n != b and d in m.links_at(n))
    o = next(n for n in m.link(output).names if n in pivots)
    return b, a, o


def mu_askable(m: Mechanism) -> set[str]:
    """μ, of a four-bar of four pins."""
    return set() if four_bar_spans(m) is None else {"mu"}


def answer_reading(work, ask) -> Answer:
    """A ratio, a mechanical advantage, a distance to a centre, or μ, read off the drawing."""
    m = work.mechanism
    if isinstance(ask, A.Ratio) and ask.letter == "omega":
        ratio, cond, refs = ratio_by_centres(work, int(ask.b), int(ask.a))
        return Answer(ask, {"value": ratio + 0.0}, cond, "instant centres (ω ratio)",
                      refs=refs, figures=(OMEGA_FIGURE,))
    if isinstance(ask, A.MechanicalAdvantage):
        ratio, cond, refs = ratio_by_centres(work, ask.link, m.drive.link)
        return Answer(ask, {"value": ratio + 0.0}, cond, "instant centres (ω_in / ω_out)",
                      refs=refs, figures=(OMEGA_FIGURE,))
    if isinstance(ask, A.Ratio):
        vp = drawn_velocity_polygon(work)
        (ax, ay), (bx, by) = vp.vector(ask.a), vp.vector(ask.b)
        below = math.hypot(bx, by)
        if below == 0.0:
            raise InputError(f"{ask.b} is at rest at this instant, so V_{ask.a}/V_{ask.b} has "
                             "no value; ask the ratio the other way round")
        value = {"value": math.hypot(ax, ay) / below}
        return Answer(ask, value, vp.worst(), "velocity polygon (o_v tips)",
                      refs=(vp.tip(ask.a), vp.tip(ask.b)), arrows=tuple(vp.steps),
                      figures=(WORKED,), panel=Panel.VELOCITY)
    asm = work.assembly
    if isinstance(ask, A.Distance):
        cs = located(work)
        centre = cs.point(*ask.pair)
        if centre.is_at_infinity:
            raise InputError(f"{A.Centre(ask.pair).name} is at infinity at this position, so "
                             f"no distance from {ask.point} to it can be measured")
        ref = asm.points.get(ask.point)
        if ref is None:
            raise InputError(f"there is no point {ask.point}; the points are "
                             f"{', '.join(asm.points)}")
        value = {"value": math.dist(asm.xy(ask.point), centre.xy)}
        cond = min(asm[ref].conditioning, cs.conditioning(*ask.pair))
        return Answer(ask, value, cond, "dividers, on the centres figure",
                      refs=(cs.centre(*ask.pair).ref, ref), figures=(CENTRES_FIGURE,))
    b, a, o = transmission_pin(m)
    value = {"value": _angle_at(asm.xy(b), asm.xy(a), asm.xy(o))}
    cond = min(asm[asm.points[n]].conditioning for n in (a, b, o))
    return Answer(ask, value, cond, f"protractor: angle {a}{b}{o} between coupler and output",
                  refs=tuple(asm.points[n] for n in (a, b, o)))


def _angle_at(vertex, p, q) -> float:
    """The angle pVq (rad, 0 to π)."""
    ux, uy = p[0] - vertex[0], p[1] - vertex[1]
    vx, vy = q[0] - vertex[0], q[1] - vertex[1]
    return math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy)
