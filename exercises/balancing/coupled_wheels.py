"""A locomotive's wheels as the books balance them: what the driving wheels' balance masses
take (each cylinder's revolving mass, its share of the reciprocating mass, any revolving
masses on cranks of their own), and, on a coupled locomotive, the trailing wheels solved as
a rotor of their own in the same planes (their share of the reciprocating mass and the
coupling rods' masses at their pins).

The trailing wheels' answers are the rotor's, each named with ``_trailing``
(``mass_A_trailing``), their figures ``-trailing`` and their checks ``trailing …``.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from tarsim.constructions.narration import numeral, words
from ..checked import Checked

if TYPE_CHECKING:
    from .balance_solution import BalanceSolution

__all__ = ["trailing_checked", "trailing_figures", "trailing_lines", "trailing_misses",
           "trailing_solution", "wheel_lines"]


def _mass_list(s: BalanceSolution, masses) -> str:
    """The revolving masses on cranks of their own, as "rod 120 kg at 250 mm, 180°"."""
    return ", ".join(words("{name} {mass} kg at {radius}, {angle}°", name=m.name,
                           mass=numeral(m.mass), radius=s._length(m.radius),
                           angle=numeral(math.degrees(m.angle) % 360, "g")) for m in masses)


def wheel_lines(s: BalanceSolution) -> list[str]:
    """What the driving wheels' balance masses take: each cylinder's revolving mass and its
    share of the reciprocating mass, the coupled wheels' sharing of it, and the revolving
    masses on cranks of their own."""
    e, r = s.exercise.engine, s.exercise.rotor
    cylinders = {str(i) for i in range(1, len(e.cranks) + 1)}
    out = [words("balance masses: each cylinder's revolving mass and {share} of its "
                 "reciprocating mass, {mass} kg at the crank radius along its crank, balanced "
                 "as rotating masses", share=numeral(e.balanced_each, "g"),
                 mass=numeral(e.revolving + e.balanced_each * e.reciprocating))]
    if e.coupled > 1:
        out.append(words("the {share} of the reciprocating mass balanced is shared equally "
                         "among {pairs} pairs of coupled wheels: {each} of it in the driving "
                         "wheels and in each other pair", share=numeral(e.balanced, "g"),
                         pairs=numeral(e.coupled, "g"), each=numeral(e.balanced_each, "g")))
    extra = [m for m in r.masses if m.name not in cylinders]
    if extra:
        out.append(words("with them, the revolving masses on cranks of their own: {masses}",
                         masses=_mass_list(s, extra)))
    return out


def trailing_solution(s: BalanceSolution, named: bool = False) -> BalanceSolution | None:
    """The trailing wheels solved as a rotor of their own (None where the locomotive has
    one pair of wheels), ``named`` in the language spoken for its figures."""
    ex = s.exercise
    if ex.trailing is None:
        return None
    name = words("{name}, trailing wheels", name=ex.name) if named else ex.name
    return type(s)(replace(ex, name=name, engine=None, rotor=ex.trailing, trailing=None,
                           open=None, description=""))


def trailing_lines(s: BalanceSolution) -> list[str]:
    """The trailing wheels' lines: what they carry, then the rotor's own."""
    sub = trailing_solution(s)
    if sub is None:
        return []
    e = s.exercise.engine
    cylinders = {str(i) for i in range(1, len(e.cranks) + 1)}
    each = [m for m in s.exercise.trailing.masses if m.name not in cylinders]
    head = words("the trailing wheels: {share} of each cylinder's reciprocating mass, {mass} kg "
                 "at the crank radius along its crank, balanced in the same planes",
                 share=numeral(e.balanced_each, "g"),
                 mass=numeral(e.balanced_each * e.reciprocating))
    if each:
        head += words(", with the masses on each pair of coupled wheels: {masses}",
                      masses=_mass_list(s, each))
    return [head] + sub._rotor_lines()


def trailing_checked(s: BalanceSolution) -> dict[str, Checked]:
    """results.json's trailing-wheel quantities, each the rotor's named ``…_trailing``."""
    sub = trailing_solution(s)
    return {} if sub is None else {f"{k}_trailing": c for k, c in sub._checked().items()}


def trailing_misses(s: BalanceSolution) -> list[tuple[str, float]]:
    """The trailing wheels' polygons against the closed form, each named ``trailing …``."""
    sub = trailing_solution(s)
    return [] if sub is None else [(f"trailing {name}", miss) for name, miss in sub.misses]


def trailing_figures(s: BalanceSolution) -> dict[str, Any]:
    """The trailing wheels' space diagram, table and polygons, each named ``…-trailing``."""
    sub = trailing_solution(s, named=True)
    return {} if sub is None else {f"{k}-trailing": f for k, f in sub.figures.items()}


def trailing_records(s: BalanceSolution) -> list:
    """The trailing wheels' construction, for steps.md."""
    sub = trailing_solution(s)
    return [] if sub is None else [sub.balance.construction]
