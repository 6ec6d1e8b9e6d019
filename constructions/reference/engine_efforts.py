"""An engine's efforts as the textbooks define them, from the Newton–Euler joint forces of
:mod:`.kinetostatics` and the loads' closed forms: the crank effort, the turning moment and
the bearings' thrust; for a slider-crank the piston effort, the wall's thrust, the
reciprocating parts' inertia force and the rod's correction couple (its two-mass system
built whole by the lever rule)."""

from __future__ import annotations

import math

from ..loads import GRAVITY, Loads, crank_tangent, stroke_axis
from ..model import Mechanism
from .kinetostatics import Statics, loads_on, power_torque, world_point
from .solver import Kinematics, point_acceleration

__all__ = ["efforts"]


def efforts(mech: Mechanism, kin: Kinematics, loads: Loads, statics: Statics
            ) -> dict[str, float]:
    """An engine's efforts by the textbook's definitions, from the Newton–Euler joint forces:
    the crank effort (the push of the link at the crank pin on the crank, square to the
    crank, CCW +), its turning moment and the push along the crank toward the shaft (the
    thrust on the shaft's bearings); for a slider-crank also the piston effort (the
    piston's loads along the stroke, + toward the crank), the size of the wall's push on
    the piston square to the stroke, the reciprocating parts' m·a toward the crank and the
    rod's correction couple."""
    d = mech.drive.link
    pivot, pin = mech.link(d).names[:2]
    (rod,) = [k for k in mech.links_at(pin) if k != d]
    push = statics.joint(f"F_{min(d, rod)}{max(d, rod)}").force    # of the lower on the higher
    if d < rod:
        push = (-push[0], -push[1])                                  # of the rod on the crank
    t = crank_tangent(kin.points[pivot], kin.points[pin])
    effort = push[0] * t[0] + push[1] * t[1]
    r = math.dist(kin.points[pivot], kin.points[pin])
    # the push along the crank, toward the shaft: the thrust on its bearings
    out = {"crank_effort": effort, "turning_moment": effort * r,
           "bearing_thrust": push[1] * t[0] - push[0] * t[1]}
    if loads.flywheel is not None and loads.resisting is not None:
        along = effort * r * (-1.0 if kin.omegas[d] < 0 else 1.0)
        out["flywheel_alpha"] = (along - loads.resisting) / loads.flywheel
    guide = [s for s in mech.slides if s.guide_link == 1 and s.type.turns_with_guide]
    if len(guide) == 1:
        s = guide[0]
        u = stroke_axis(kin.points[pivot], kin.points[s.point], s.direction)
        piston = [f for _, f, _ in loads_on(kin, mech, loads, s.link)]
        out["piston_effort"] = math.fsum(f[0] * u[0] + f[1] * u[1] for f in piston)
        out["wall_thrust"] = abs(statics.pushes[mech.slides.index(s)])
        m = loads.mass_of(s.link)
        a = (point_acceleration(kin, mech, s.link, world_point(kin, mech, s.link, m.centre))
             if m is not None else (0.0, 0.0))
        out["inertia_force"] = (m.mass if m is not None else 0.0) * (a[0] * u[0] + a[1] * u[1])
        out["correction_couple"] = _correction(mech, kin, loads, pin, s.point, d)
        rod = [k for k in mech.links_at(pin) if k != d and s.point in mech.link(k).names]
        m = loads.mass_of(rod[0]) if rod else None
        if m is not None and m.swing is not None:
            # the pendulum about its point of suspension: m·g·h·T²/(4π²) = I_P = m·(k² + h²)
            period, h, _, _ = m.swing
            k2 = GRAVITY * h * period ** 2 / (4 * math.pi ** 2) - h * h
            out["rod_radius_of_gyration"] = math.sqrt(k2)
        elif m is not None and m.inertia > 0.0:
            out["rod_radius_of_gyration"] = math.sqrt(m.inertia / m.mass)
        # the inertia torque split as the books split it, each part's inertia loads alone
        # by the balance of power: their power over ω is what they turn the crank with
        for word, part in (("inertia_torque_reciprocating", s.link),
                           ("inertia_torque_rod", rod[0] if rod else None)):
            m = loads.mass_of(part) if part is not None else None
            if m is not None:
                alone = Loads(masses=(m,), gravity=0.0)
                out[word] = -power_torque(mech, kin, alone)
        # ω² scales the inertia alone: F_P(ω_r) = rest − F_I·(ω_r/ω)² = 0
        rest = out["piston_effort"] + out["inertia_force"]
        if out["inertia_force"] and rest / out["inertia_force"] > 0:
            omega = kin.omegas[d]
            out["reversal_speed"] = math.sqrt(omega * omega * rest / out["inertia_force"])
    return out


def _correction(mech: Mechanism, kin: Kinematics, loads: Loads, pin: str, gudgeon: str,
                crank: int) -> float:
    """The rod's correction couple, its two-mass system built whole: the rod's mass split
    between the pins by the lever rule, m_A = m·GP/AP and m_P = m·GA/AP, whose moment of
    inertia about G, m_A·GA² + m_P·GP², the rod's own I_G falls short of; that difference
    times the rod's α (0 where the crank pin's rod has no mass)."""
    rods = [k for k in mech.links_at(pin) if k != crank and gudgeon in mech.link(k).names]
    m = loads.mass_of(rods[0]) if rods else None
    if m is None:
        return 0.0
    g = world_point(kin, mech, rods[0], m.centre)
    ga, gp = math.dist(g, kin.points[pin]), math.dist(g, kin.points[gudgeon])
    share_a, share_p = m.mass * gp / (ga + gp), m.mass * ga / (ga + gp)
    return (share_a * ga * ga + share_p * gp * gp - m.inertia) * kin.alphas[rods[0]]
