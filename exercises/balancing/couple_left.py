"""The couple a static balance leaves: one balancing mass cancels the masses' forces, but
where they stand in planes apart (or in a plane other than the balance's) their couple
stays, for a second plane to take, as the books ask "the unbalanced couple that remains".

It is read from what was drawn: with the forces balanced the couple is the same about any
plane, so it is taken about the shaft's origin, Σ mᵢrᵢzᵢ with the balancing product drawn
at its own plane; the reference takes the masses' couple about the balancing plane, where
the balance mass adds none. With the speed given it is in N·m (× ω²), otherwise in kg·m².
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from tarsim.constructions.balancing.polygons import rounding
from tarsim.constructions.narration import numeral, words
from tarsim.constructions.reference.balance import couple_about
from ..checked import Checked
from .balance_figures import angle_deg

if TYPE_CHECKING:
    from .balance_solution import BalanceSolution

__all__ = ["couple_left_checked", "couple_left_line"]


def _left(s: BalanceSolution) -> tuple[tuple[float, float], tuple[float, float]] | None:
    """The couple left (kg·m² vectors) as drawn and by the reference, where one plane
    balances masses that leave one (None otherwise)."""
    r = s.exercise.rotor
    if len(r.planes) != 1:
        return None
    plane = r.planes[0]
    if all(m.plane == plane.position for m in r.masses):
        return None
    product = s.balance.product(plane.name)
    drawn = tuple(math.fsum([*(m.mr[i] * m.plane for m in r.masses),
                             product[i] * plane.position]) for i in (0, 1))
    size = rounding([m.mass * m.radius * (abs(m.plane) + abs(plane.position))
                     for m in r.masses] + [math.hypot(*product) * abs(plane.position)])
    if math.hypot(*drawn) <= size:       # the masses' couple cancels: none is left
        return None
    return drawn, couple_about(r.masses, plane.position)


def couple_left_checked(s: BalanceSolution) -> dict[str, Checked]:
    """results.json's ``couple_left``: N·m at the speed given, else kg·m² (× ω²), with the
    angle of its vector Σ mᵢrᵢlᵢ."""
    left = _left(s)
    if left is None:
        return {}
    (drawn, want), speed = left, s.exercise.rotor.speed
    w2 = 1.0 if speed is None else speed ** 2
    unit = {"unit": "kg·m²", "times": "ω²"} if speed is None else {"unit": "N·m"}
    return {"couple_left": Checked(
        {"value": math.hypot(*drawn) * w2, **unit, "angle_deg": angle_deg(drawn)},
        {"value": math.hypot(*want) * w2, "angle_deg": angle_deg(want)},
        method="force polygon's balance, moments about the shaft's origin")}


def couple_left_line(s: BalanceSolution) -> list[str]:
    """The line that gives the couple left, in N·m where the speed is known."""
    left = _left(s)
    if left is None:
        return []
    r = s.exercise.rotor
    drawn = left[0]
    place, angle = s._length(r.planes[0].position), numeral(angle_deg(drawn), ".2f")
    if r.speed is None:
        return [words("at {place} one plane balances the forces only: a couple of {couple} "
                      "kg·m² (× ω²) at {angle}° is left, for a second plane to take",
                      place=place, couple=numeral(math.hypot(*drawn)), angle=angle)]
    return [words("at {place} one plane balances the forces only: a couple of {couple} N·m at "
                  "{angle}° (at ω = {speed} rad/s) is left, for a second plane to take",
                  place=place, couple=numeral(math.hypot(*drawn) * r.speed ** 2), angle=angle,
                  speed=numeral(r.speed))]
