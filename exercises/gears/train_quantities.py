"""A gear train's asked quantities beside their checks: a member's power, a pair's centre
distance, a gear's teeth and the involute mesh's readings (:class:`TrainQuantity`), built
by :class:`QuantityParts` for :class:`~.train_solution.TrainSolution`, whose train,
speeds, reference and mesh they read."""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

from tarsim.constructions.gears.chain import mesh_chain
from tarsim.constructions.gears.involute import least_teeth_drawn
from tarsim.constructions.gears.kutzbach import DRAWN
from tarsim.constructions.gears.train import Mesh
from tarsim.constructions.narration import numerals, unit_words, words
from tarsim.constructions.gears.torques import power_at
from tarsim.constructions.reference.gear_mesh import least_teeth
from tarsim.constructions.units import LENGTH_UNITS
from tarsim.constructions.reference.willis import (coaxial_teeth, pitch_distance,
                                                    pitch_distance_times_pi, teeth_to_about)

__all__ = ["TrainQuantity", "QuantityParts"]


@dataclass(frozen=True)
class TrainQuantity:
    """One asked speed or ratio: exact by the method and by Willis, and in SI."""

    name: str
    exact: Fraction
    reference: Fraction
    si: float
    method: str
    tolerance: float = 0.0
    """0 for an exact quantity (a speed, a ratio, a count); a drawn length, angle or ratio
    agrees within this, in its own units: a few roundings of the drawing's size."""
    matched: bool = True
    """False when what the number counts differs (the interference's gears), though the
    counts may agree."""
    over_pi: bool = False
    """True for a torque that is ``exact``/π (a power given, speeds in rpm)."""
    times_pi: bool = False
    """True for a power that is ``exact``·π (a torque given, speeds in rpm)."""
    flow: str = ""
    """A power's way: "in" to the train (the driver's) or "out" of it."""

    @property
    def passed(self) -> bool:
        """True when the method's value is the reference's (within a drawing's rounding)."""
        if not self.matched:
            return False
        if not self.tolerance:
            return self.exact == self.reference
        return abs(float(self.exact) - float(self.reference)) <= self.tolerance

    @property
    def rel_error(self) -> float:
        """0 when the two are one; else how far apart, relative (1 for things counted that
        differ)."""
        if not self.matched:
            return 1.0
        if self.exact == self.reference:
            return 0.0
        size = abs(self.reference) if self.tolerance and self.reference else max(
            abs(self.reference), 1)
        return float(abs(self.exact - self.reference) / size)


class QuantityParts:
    """The solution's part that builds a power's, a distance's, a count's and a mesh
    reading's :class:`TrainQuantity`."""

    def _power_quantity(self, m: int, torques: dict[int, Fraction],
                        torques_ref: dict[int, Fraction]) -> TrainQuantity:
        """Member ``m``'s power |T·ω| in W, beside the reference's torque times its Willis
        speed."""
        got, times_pi = power_at(self.train, torques[m], self.found.speeds[m])
        ref, _ = power_at(self.train, torques_ref[m], self.reference[m])
        si = float(got) * (math.pi if times_pi else 1.0)
        flow = "in" if torques[m] * self.found.speeds[m] > 0 else "out"
        return TrainQuantity(f"power{m}", got, ref, si, "balance of power",
                             times_pi=times_pi, flow=flow)

    def _mesh_quantity(self, name: str) -> TrainQuantity:
        """A number read off the involute mesh, beside the formula's."""
        got, ref = self.mesh, self.mesh_reference
        if name == "least_teeth":
            d = self.exercise.involute
            a, b = sorted((self.train.gear(d.pinion), self.train.gear(d.wheel)),
                          key=lambda g: g.teeth)
            ratio = b.teeth / a.teeth
            drawn = least_teeth_drawn(float(a.module), ratio, d)
            return TrainQuantity(name, Fraction(drawn), Fraction(least_teeth(ratio,
                                 d.pressure_angle, d.addendum)), float(drawn),
                                 "involute mesh, drawn with fewer teeth until clear")
        if name == "interference":
            # The gears that interfere, counted; compared as the gears themselves.
            a, b = Fraction(len(got.interference)), Fraction(len(ref.interference))
            return TrainQuantity(name, a, b, float(a), "involute mesh",
                                 matched=got.interference == ref.interference)
        attr = {"contact_ratio": "contact_ratio", "path_of_contact": "path",
                "arc_of_contact": "arc", "pressure_angle": "pressure_angle",
                "circular_pitch": "circular_pitch"}[name]
        value, want = getattr(got, attr), getattr(ref, attr)
        # Drawn on coordinates of the centre distance's size: a length is good to a few
        # thousand roundings of it (the path is a difference of two such lengths), the
        # contact ratio to that over the base pitch, the arc over cos φ′, an angle to that
        # over the radii it is measured on.
        size = DRAWN * math.dist(*got.centres.values())
        allowed = {"contact_ratio": size / got.base_pitch,
                   "arc_of_contact": size / math.cos(got.pressure_angle),
                   "pressure_angle": size / got.radii["base2"]}.get(name, size)
        return TrainQuantity(name, Fraction(value), Fraction(want), value, "involute mesh",
                             allowed)

    def _distance_quantity(self, name: str) -> TrainQuantity:
        """A pair's centre distance (m) from its teeth and module, m(N_a ± N_b)/2, beside
        the sum (or difference) of the two pitch radii, each at its own gear's module."""
        a, b = (int(n) for n in name.removeprefix("centre_distance").split("_"))
        mesh = next((m for m in self.train.meshes if {m.a, m.b} == {a, b}), None)
        if mesh is None:                # a simple train's ends, its gears in one line
            return self._chain_distance(name, mesh_chain(self.train, a, b))
        times_pi = pitch_distance_times_pi(self.train, a, b, mesh.internal)
        if times_pi is not None:        # p(N_a ± N_b)/(2π): over π exactly
            ga, gb = self.train.gear(a), self.train.gear(b)
            got = ga.circular_pitch * (abs(ga.teeth - gb.teeth) if mesh.internal else
                                       ga.teeth + gb.teeth) / 2
            return TrainQuantity(name, got, times_pi, float(got) / math.pi,
                                 "teeth and circular pitch", over_pi=True)
        got = self.train._mesh_length(mesh)
        ref = pitch_distance(self.train, a, b, mesh.internal)
        return TrainQuantity(name, got, ref, float(got), "teeth and module")

    def _chain_distance(self, name: str, chain) -> TrainQuantity:
        """The distance between a simple train's two end gears, the gears in one line as the
        books draw them: the pairs' distances added along the chain of idlers, beside the
        pitch diameters of the idlers and the end gears' radii added (each exact, or each
        over π where the teeth are sized by a circular pitch)."""
        train = self.train
        if all(pitch_distance_times_pi(train, m.a, m.b, False) is not None for m in chain):
            got = sum((train.gear(m.a).circular_pitch * (train.gear(m.a).teeth
                       + train.gear(m.b).teeth) / 2 for m in chain), Fraction(0))
            ref = sum(pitch_distance_times_pi(train, m.a, m.b, False) for m in chain)
            return TrainQuantity(name, got, ref, float(got) / math.pi,
                                 "the pairs' distances added", over_pi=True)
        got = sum((train._mesh_length(m) for m in chain), Fraction(0))
        ref = sum(pitch_distance(train, m.a, m.b, False) for m in chain)
        return TrainQuantity(name, got, ref, float(got), "the pairs' distances added")

    def _pitches(self, name: str) -> dict[str, float]:
        """results.json's circular pitch of a distance's pair (m), and its module p/π, where
        the file sizes the teeth by it, as the book asks them; else nothing."""
        a = int(name.removeprefix("centre_distance").split("_")[0])
        p = self.train.gear(a).circular_pitch
        return {} if p is None else {"circular_pitch": float(p), "module": float(p) / math.pi}

    def _pitch_row(self) -> list[tuple[str, list[str]]]:
        """The table's row of the circular pitches the file sizes teeth by, under the
        teeth found by them (none where no gear gives one)."""
        train = self.train
        scale = LENGTH_UNITS[train.units.length]
        cells = ["" if m == train.arm or train.gear(m).circular_pitch is None else
                 numerals(f"{float(train.gear(m).circular_pitch) / scale:g}")
                 for m in train.members]
        return [(words("circular pitch ({unit})", unit=unit_words(train.units.length)),
                 cells)] if any(cells) else []

    def _teeth_quantity(self, number: int) -> TrainQuantity:
        """A gear's teeth, given or found from the data, beside the reference's: the count
        that makes its mesh's centre distance the other pair's (train.py's distances, solved
        by a secant on the count), or its diameter over its module in floats."""
        train, gear = self.train, self.train.gear(number)
        found = Fraction(gear.teeth)
        if number not in train.implied_teeth:
            return TrainQuantity(f"teeth{number}", found, found, float(found), "given")
        if gear.diameter is not None:
            ref = Fraction(round(float(gear.diameter) / float(gear.module)))
            return TrainQuantity(f"teeth{number}", found, ref, float(found), "d/m")
        by_axis = coaxial_teeth(train, number)
        if not train.ratio_given:
            return TrainQuantity(f"teeth{number}", found, by_axis, float(found),
                                 "coaxial condition")
        # the ratios the file gives, by the Willis speeds of the train with these teeth,
        # and the coaxial condition where the count stands in it
        speeds = self.reference
        holds = all(abs(speeds[x] / speeds[y]) == value for x, y, value in train.ratio_given)
        # and each centre distance the file gives the gear's pairs, by their pitch circles
        holds = holds and all(pitch_distance(train, m.a, m.b, m.internal) == m.distance
                              for m in train.meshes if number in (m.a, m.b) and m.distance)
        about = next((m for m in train.meshes if m.about and number in (m.a, m.b)), None)
        if about is not None:           # designed to an approximate distance: redesigned
            return TrainQuantity(f"teeth{number}", found, Fraction(
                self._about_reference(about, number)) if holds else Fraction(0),
                float(found), "approximate distance and speed ratio")
        return TrainQuantity(f"teeth{number}", found, (by_axis or found) if holds else
                             Fraction(0), float(found), "coaxial condition and speed ratio"
                             if by_axis else "speed ratio")

    def _about_reference(self, mesh: Mesh, number: int) -> int:
        """Gear ``number``'s count by the reference's own design of its pair to the
        approximate centre distance, in floats from the circular pitch (π·m where a module
        is given), the ratio and the least count of the file's [ratio]."""
        train = self.train
        ga, gb = train.gear(mesh.a), train.gear(mesh.b)
        pitch = ga.circular_pitch or gb.circular_pitch
        pitch = float(pitch) if pitch else math.pi * float(ga.module or gb.module)
        ratio = next(float(v) for x, y, v in train.ratio_given if {x, y} == {mesh.a, mesh.b})
        small, large = teeth_to_about(float(mesh.about), pitch, ratio, mesh.internal,
                                      mesh.least)
        return small if train.gear(number).teeth == min(ga.teeth, gb.teeth) else large
