"""A connecting rod given alone, solved: its equivalent dynamical system with one mass at a
pin, the two masses at its pins, their moment of inertia against the rod's and their
correction couple, each number beside the reference's (the three conditions solved as
equations, :mod:`~tarsim.constructions.reference.rod_equivalent`), and said in words.

Each side is a handful of roundings on numbers of the data's own size, the reference's
2×2 system as well conditioned as the pins are apart from G (its condition number is
below 10³ for any G more than a thousandth of the rod from a pin), so 1e-12 relative holds
with room and a slip of one digit in a formula (k for k², l1 for l3) fails it by ten
orders. The correction couple is a difference, (I′ − I_G)·α: its error is measured
against I′·|α|, the size of what is cancelled, so a rod whose two masses happen to keep
I_G (a couple of 0) is held to the same rounding.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from tarsim.constructions.forces.equivalent import (Equivalent, equivalent_masses, pin_masses,
                                                    rod_couple)
from tarsim.constructions.narration import numeral, phrase, words
from tarsim.constructions.reference.rod_equivalent import (pendulum_period, second_moment,
                                                           second_point, two_masses)
from tarsim.constructions.units import LENGTH_UNITS
from ..checked import Checked
from ..solution_folder import ChapterFiles
from ..worked_document import Bullets, Section, numbered, title
from .rod_file import RodExercise

__all__ = ["RodSolution", "solve_rod"]

ROUNDING = 1e-12
"""Relative agreement asked of every number (see the module's docstring)."""


def _check(value: float, reference: float, method: str, scale: float | None = None,
           **extra: Any) -> Checked:
    """One quantity beside its reference, its error relative to ``scale`` (the reference's
    size unless given)."""
    size = abs(reference) if scale is None else scale
    error = abs(value - reference) / max(size, sys.float_info.min)
    return Checked({"value": value, **extra}, {"value": reference}, rel_error=error,
                   tolerance=ROUNDING, passed=error <= ROUNDING, method=method)


@dataclass(frozen=True)
class RodSolution(ChapterFiles):
    """A solved connecting rod (see :func:`solve_rod`)."""

    exercise: RodExercise

    @cached_property
    def equivalent(self) -> Equivalent:
        """The two masses with the first at the pin the file names."""
        return equivalent_masses(self.exercise.rod, crank_pin=self.exercise.crank_first)

    @cached_property
    def at_pins(self) -> tuple[float, float]:
        """The masses at the gudgeon pin and the crank pin."""
        return pin_masses(self.exercise.rod)

    @property
    def pins_inertia(self) -> float:
        """m·l1·l3, the two pin masses' moment of inertia about G (kg·m²)."""
        rod = self.exercise.rod
        return rod.mass * rod.to_gudgeon * rod.to_crank

    @property
    def couple(self) -> float:
        """The correction couple (N·m, + counter-clockwise)."""
        rod = self.exercise.rod
        return rod_couple(rod.mass, rod.to_crank, rod.to_gudgeon, rod.inertia,
                          self.exercise.alpha)

    @cached_property
    def checked(self) -> dict[str, Checked]:
        """Every asked quantity beside the reference's (SI: kg, m, kg·m², N·m)."""
        ex, rod = self.exercise, self.exercise.rod
        p, a = ex.ends
        out: dict[str, Checked] = {}
        # the pins as the reference places them, from G along the line toward A
        x_p, x_a = -rod.to_gudgeon, rod.to_crank
        ref_pins = two_masses(rod.mass, x_p, x_a)
        if "equivalent_masses" in ex.find:
            e, pin, d = self.equivalent, ex.one_mass_at, ex.second
            x1 = x_a if ex.crank_first else x_p
            x2 = second_point(rod.mass, x1, rod.inertia)
            m1, m2 = two_masses(rod.mass, x1, x2)
            method = "m1 + m2 = m, m1·l1 = m2·l2, m1·l1² + m2·l2² = m·k² solved"
            out["l2"] = _check(e.l2, abs(x2), method, from_pin=e.l1 + e.l2, beyond=pin,
                               unit="m")
            out[f"mass_at_{pin}"] = _check(e.at_pin, m1, method, unit="kg")
            out[f"mass_at_{d}"] = _check(e.beyond, m2, method, unit="kg")
        if "pin_masses" in ex.find:
            method = "m_P + m_A = m, m_P·GP = m_A·GA solved"
            out[f"pin_mass_{p}"] = _check(self.at_pins[0], ref_pins[0], method, unit="kg")
            out[f"pin_mass_{a}"] = _check(self.at_pins[1], ref_pins[1], method, unit="kg")
        ref_inertia = second_moment(ref_pins, (x_p, x_a))
        if "equivalent_inertia" in ex.find:
            out["equivalent_inertia"] = _check(self.pins_inertia, ref_inertia,
                                               "Σ m·x² of the two pin masses", unit="kg·m²")
            out["rod_inertia"] = Checked({"value": rod.inertia, "unit": "kg·m²"},
                                         method="given" if ex.given_inertia else
                                         "pendulum test" if ex.pendulum else "m·k²")
        if "correction_couple" in ex.find:
            ref = (ref_inertia - rod.inertia) * ex.alpha
            out["correction_couple"] = _check(
                self.couple, ref, "(Σ m·x² of the pin masses − I_G)·α",
                scale=ref_inertia * abs(ex.alpha), unit="N·m",
                sense="ccw" if self.couple > 0 else "cw" if self.couple < 0 else "none")
        if ex.pendulum is not None:      # k found from the period gives the period back
            period, h, _, _ = ex.pendulum
            k = math.sqrt(rod.inertia / rod.mass)
            out["pendulum_period"] = _check(period, pendulum_period(k, h),
                                            "compound pendulum, 2π·√((k² + h²)/(g·h))",
                                            unit="s")
        if "rod_radius_of_gyration" in ex.find:
            x2 = second_point(rod.mass, x_p, rod.inertia)
            ref = math.sqrt(second_moment(two_masses(rod.mass, x_p, x2), (x_p, x2)) / rod.mass)
            out["rod_radius_of_gyration"] = _check(math.sqrt(rod.inertia / rod.mass), ref,
                                                   "√(Σ m·x²/m) of the equivalent masses",
                                                   unit="m")
        return out

    @property
    def failures(self) -> list[str]:
        """The quantities that failed their check, by name."""
        return [k for k, c in self.checked.items() if c.passed is False]

    # ----- words -------------------------------------------------------------------------------
    def length(self, v: float) -> str:
        """A length (m) in the file's unit, as the language spoken writes it."""
        unit = self.exercise.length_unit
        return f"{numeral(v / LENGTH_UNITS[unit])} {unit}"

    def sense(self, value: float) -> str:
        """A couple's or α's sense in words."""
        return words("clockwise") if value < 0 else words("counter-clockwise")

    def lines(self) -> list[str]:
        """What the command line prints and steps.md lists, in the language spoken."""
        ex, q, out = self.exercise, self.checked, []
        p, a = ex.ends
        if "equivalent_masses" in ex.find:
            e = self.equivalent
            out.append(words("equivalent dynamical system: {m1} kg at {pin} and {m2} kg at "
                             "{d}, l2 = {l2} from G ({far} from {pin})",
                             m1=numeral(e.at_pin), pin=ex.one_mass_at, m2=numeral(e.beyond),
                             d=ex.second, l2=self.length(e.l2), far=self.length(e.l1 + e.l2)))
        if "pin_masses" in ex.find:
            out.append(words("the masses at the pins: {mp} kg at {p}, {ma} kg at {a}",
                             mp=numeral(self.at_pins[0]), p=p, ma=numeral(self.at_pins[1]),
                             a=a))
        if "equivalent_inertia" in ex.find:
            out.append(words("the pin masses' moment of inertia about G m·l1·l3 = {ieq} "
                             "kg·m², the rod's m·k² = {i} kg·m²",
                             ieq=numeral(self.pins_inertia), i=numeral(ex.rod.inertia)))
        if "correction_couple" in ex.find:
            out.append(words("correction couple (m·l1·l3 − m·k²)·α = {couple} N·m {sense}",
                             couple=numeral(abs(self.couple)), sense=self.sense(self.couple)))
        if "rod_radius_of_gyration" in ex.find:
            out.append(words("radius of gyration about G k = √(I/m) = {k}",
                             k=self.length(q["rod_radius_of_gyration"].value["value"])))
        failed = self.failures
        out.append(words("every number agrees with its reference") if not failed else
                   f"OFF: {', '.join(failed)}")
        return out

    def document(self) -> list[Section]:
        """steps.md: the rod drawn and its masses found, numbered, then the results."""
        from .rod_words import steps
        return [title(self.exercise.name, self.exercise.description),
                Section(phrase("heading.construction"), (numbered(steps(self)),),
                        figures=("rod",)),
                Section(phrase("md.results"), (Bullets(tuple(self.lines())),))]

    @property
    def figures(self) -> dict[str, Any]:
        """The rod to scale with G, its pins and its equivalent masses."""
        from tarsim.graphics.forces.rod_figure import rod_figure
        return {"rod": rod_figure(self)}


def solve_rod(ex: RodExercise) -> RodSolution:
    """Solve a connecting rod given alone."""
    return RodSolution(ex)
