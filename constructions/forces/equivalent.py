"""A connecting rod's equivalent dynamical system as the textbooks set it: its mass split
between the crank pin A and the gudgeon pin P, m·GP/AP at A and m·GA/AP at P, which has
the rod's mass and centre of mass but a moment of inertia m·GA·GP about G, not the rod's
own I_G. The correction couple (m·GA·GP − I_G)·α is what the two masses overstate the
rod's inertia couple by: the couple to set beside them for the rod's whole dynamical effect.
"""

from __future__ import annotations

import math

from ..errors import TarsimError
from ..loads import Loads
from ..model import Mechanism

__all__ = ["correction_couple", "reversal_speed", "rod_of"]


def rod_of(mech: Mechanism) -> tuple[int, str, str] | None:
    """The connecting rod of a slider-crank (its number, the crank pin's name, the gudgeon
    pin's), or None where the input's crank pin joins no rod that drives a slide."""
    crank = mech.link(mech.drive.link)
    pin = crank.names[1] if len(crank.names) > 1 else None
    for k in mech.links_at(pin) if pin else ():
        if k == crank.number:
            continue
        for s in mech.slides:
            if s.guide_link == 1 and s.point in mech.link(k).names and s.point != pin:
                return k, pin, s.point
    return None


def correction_couple(mech: Mechanism, loads: Loads, alpha: float) -> float:
    """The rod's correction couple (N·m, CCW + with its angular acceleration ``alpha``):
    (m·GA·GP − I_G)·α, 0 for a rod with no mass.

    >>> from types import SimpleNamespace as S
    >>> rod = S(local=lambda p: {"A": (0.0, 0.0), "P": (1.0, 0.0)}[p])
    >>> mech = S(link=lambda k: rod)
    >>> loads = S(mass_of=lambda k: S(mass=40.0, centre=(0.35, 0.0), inertia=3.6))
    >>> round(_couple(mech, loads, 3, "A", "P", 2.0), 9)      # (40·0.35·0.65 − 3.6)·2
    11.0
    """
    found = rod_of(mech)
    if found is None:
        return 0.0
    return _couple(mech, loads, *found, alpha)


def _couple(mech, loads: Loads, rod: int, pin: str, gudgeon: str, alpha: float) -> float:
    m = loads.mass_of(rod)
    if m is None:
        return 0.0
    link = mech.link(rod)
    ga = math.dist(m.centre, link.local(pin))
    gp = math.dist(m.centre, link.local(gudgeon))
    return (m.mass * ga * gp - m.inertia) * alpha


def reversal_speed(mech: Mechanism, effort: float, inertia: float) -> float:
    """The crank speed (rad/s) at which the piston effort falls to zero at this crank angle,
    the gudgeon pin's load reversing above it: the reciprocating parts' inertia force grows
    as ω² at a steady crank speed while the rest of the piston's load, F_P + F_I, stays, so
    ω_r = |ω|·√((F_P + F_I)/F_I).

    Raises
    ------
    TarsimError
        Where the crank speeds up (the inertia is then not m·a ∝ ω²), or the rest of the
        load and the inertia push opposite ways (no speed reverses the load).

    >>> from types import SimpleNamespace as S
    >>> round(reversal_speed(S(drive=S(omega=-10.0, alpha=0.0)), 300.0, 100.0), 12)  # √4·10
    20.0
    """
    d = mech.drive
    rest = effort + inertia
    if d.alpha != 0.0:
        raise TarsimError(f"reversal_speed: the reciprocating parts' inertia grows as ω² only at "
                          f"a steady crank speed, but α{d.link} = {d.alpha:g} is given: leave "
                          "it out")
    if inertia == 0.0 or rest / inertia <= 0.0:
        raise TarsimError(f"reversal_speed at θ{d.link} = {mech.units.angle_brief(d.angle)}: the "
                          "reciprocating parts' inertia and the rest of the piston's load push "
                          "opposite ways along the stroke, so no speed reverses the load")
    return abs(d.omega) * math.sqrt(rest / inertia)
