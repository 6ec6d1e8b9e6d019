"""A connecting rod's equivalent dynamical system as the textbooks set it: its mass split
between the crank pin A and the gudgeon pin P, m·GP/AP at A and m·GA/AP at P, which has
the rod's mass and centre of mass but a moment of inertia m·GA·GP about G, not the rod's
own I_G. The correction couple (m·GA·GP − I_G)·α is what the two masses overstate the
rod's inertia couple by: the couple to set beside them for the rod's whole dynamical effect.

A rod given alone, as the books give it (its mass, the length between its pins, G's distance
from one of them, k about G), is a :class:`RodLine`: with one mass at a pin, the dynamically
equivalent system has the other at l2 = k²/l1 beyond G (:func:`equivalent_masses`); with the
two at the pins, the couple above corrects it (:func:`pin_masses`, :func:`rod_couple`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import TarsimError
from ..loads import Loads
from ..model import Mechanism

__all__ = ["RodLine", "Equivalent", "correction_couple", "equivalent_masses", "pin_masses",
           "reversal_speed", "rod_couple", "rod_of"]


@dataclass(frozen=True, slots=True)
class RodLine:
    """A connecting rod along its line of centres (SI): the gudgeon pin at 0, the crank pin
    at ``length``, G at ``centre`` between them; ``inertia`` its I about G (kg·m²)."""

    mass: float
    length: float
    centre: float
    inertia: float

    @property
    def to_gudgeon(self) -> float:
        """GP, G's distance from the gudgeon pin (m)."""
        return self.centre

    @property
    def to_crank(self) -> float:
        """GA, G's distance from the crank pin (m)."""
        return self.length - self.centre


@dataclass(frozen=True, slots=True)
class Equivalent:
    """Two masses standing for a rod: ``at_pin`` kg at the pin, l1 from G; ``beyond`` kg at
    l2 from G on the pin's other side (m)."""

    l1: float
    l2: float
    at_pin: float
    beyond: float


def equivalent_masses(rod: RodLine, crank_pin: bool = False) -> Equivalent:
    """The dynamically equivalent two masses with one at the gudgeon pin (or the crank pin):
    l2 = k²/l1 beyond G, m·l2/(l1 + l2) at the pin and m·l1/(l1 + l2) at l2. The two keep
    the rod's mass, its G (m1·l1 = m2·l2) and its I_G (m1·l1² + m2·l2² = m·l1·l2 = m·k²).

    >>> e = equivalent_masses(RodLine(2.0, 0.25, 0.1, 2.0 * 0.11 ** 2))
    >>> round(e.l2, 12), round(e.at_pin, 12), round(e.beyond, 12)   # the books' rod
    (0.121, 1.095022624434, 0.904977375566)
    """
    l1 = rod.to_crank if crank_pin else rod.to_gudgeon
    l2 = rod.inertia / rod.mass / l1
    return Equivalent(l1, l2, rod.mass * l2 / (l1 + l2), rod.mass * l1 / (l1 + l2))


def pin_masses(rod: RodLine) -> tuple[float, float]:
    """The rod's mass split between its pins so that G stays: (m·GA/l at the gudgeon pin,
    m·GP/l at the crank pin).

    >>> pin_masses(RodLine(2.0, 0.25, 0.1, 0.0))
    (1.2, 0.8)
    """
    return rod.mass * rod.to_crank / rod.length, rod.mass * rod.to_gudgeon / rod.length


def rod_couple(mass: float, ga: float, gp: float, inertia: float, alpha: float) -> float:
    """The correction couple (m·GA·GP − I_G)·α of two masses at the pins (N·m, in α's sense
    where they overstate I_G): what the rod's inertia couple wants beside theirs.

    >>> round(rod_couple(2.0, 0.15, 0.1, 2.0 * 0.11 ** 2, -23000.0), 9)   # clockwise
    -133.4
    """
    return (mass * ga * gp - inertia) * alpha


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
    return rod_couple(m.mass, ga, gp, m.inertia, alpha)


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
