"""A flywheel exercise solved: its turning-moment diagram read for ΔE, the flywheel and the
shaft's extremes, each number beside an independent reference.

A diagram given as a formula T(θ) is read to the data's precision, its intercepts by
bisection on the formula and each loop by adaptive Gauss–Legendre quadrature
(:mod:`~tarsim.constructions.forces.flywheel_exact`); a table of straight pieces by its
trapezoids (:func:`~tarsim.constructions.forces.flywheel.read_table`). The reference
integrates T(θ) by fixed composite Gauss–Legendre quadrature and finds the intercepts by the
Illinois method (:func:`~tarsim.constructions.reference.flywheel.integrated`). The formula's
drawing at equal steps stays the graphical answer (``delta_E_drawn``): its straight lines
between steps cost ΔE some h²·|T′|max/6 (the trapezoid rule's error between two intercepts,
T′ its slope there), and that, doubled, is its tolerance. A diagram given by its areas is
read by their running sum; the reference is the greatest sum of a run of neighbouring areas
round the cycle, which is ΔE by another road.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from tarsim.constructions.forces.flywheel import (Reading, area_reading, extreme, read_diagram,
                                                  read_table, rim_mass, rim_radius,
                                                  rim_section, speed_limits)
from tarsim.constructions.forces.flywheel_exact import exact_reading
from tarsim.constructions.reference.flywheel import (Integrated, energy_between,
                                                     flywheel_inertia, integrated,
                                                     speed_fluctuation)
from tarsim.constructions.errors import InputError
from tarsim.constructions.units import LENGTH_UNITS
from ..checked import Checked
from ..solution_folder import ChapterFiles
from ..table_file import SPEEDS
from ..worked_document import Section
from .flywheel_file import FlywheelExercise

__all__ = ["FlywheelSolution", "solve_flywheel"]

ROUNDING = 1e-10
"""A table's reading against the quadrature's, relative to max|T|·cycle: each of some hundred
Gauss–Legendre panels exact to rounding on a straight piece, and a few thousand roundings
summed."""

QUADRATURE = 1e-9
"""A formula's reading against the reference's, relative to ΔE. Both integrate a smooth T by
Gauss–Legendre to rounding (the error of n nodes falls as h²ⁿ: a book's dozen harmonics are
done in a few panels) and put the intercepts to the last bit; an intercept off by δθ costs
its two areas only δθ²·|T′|/2, T − T_mean being zero there. Agreement to some 1e-13 is
expected; 1e-9 leaves room for a formula sharp enough (sin(θ)**8) that the reference's fixed
64 panels hold it to fewer figures, and is still a thousand times finer than the drawing."""


def _check(value: float, reference: float, tolerance: float, method: str,
           **extra: Any) -> Checked:
    """One quantity beside its reference, passed within ``tolerance`` (relative)."""
    error = abs(value - reference) / max(abs(reference), sys.float_info.min)
    return Checked({"value": value, **extra}, {"value": reference}, rel_error=error,
                   tolerance=tolerance, passed=error <= tolerance, method=method)


def _rpm(omega: float) -> float:
    """``omega`` (rad/s) in rpm beside it in results.json, as a gear train's speeds are: to 12
    figures, so that the books' 606 rpm is not 606.0000000000001 from the round trip through
    rad/s (a file's data carry a few figures; 12 keep every one and drop the rounding)."""
    return float(f"{omega / SPEEDS['rpm']:.12g}")


@dataclass(frozen=True)
class FlywheelSolution(ChapterFiles):
    """A solved flywheel exercise (see :func:`solve_flywheel`)."""

    exercise: FlywheelExercise

    @cached_property
    def reading(self) -> Reading:
        """The diagram read for its areas and ΔE."""
        ex = self.exercise
        if ex.points:
            return read_table(ex.points, ex.cycle)
        if self.drawn is False:
            mean = ex.power / ex.speed if ex.power is not None else 0.0
            return Reading(mean, (), (), self.given[0], 0.0, 0.0)
        d = ex.diagram
        return exact_reading(d) if d else area_reading(list(ex.areas))

    @property
    def drawn(self) -> bool:
        """Whether the file gives a diagram (T(θ), its areas or a punch): else ΔE is given,
        C_E's share of the work a cycle, or the flywheel's between its two speeds."""
        ex = self.exercise
        return ex.diagram is not None or bool(ex.areas)

    @cached_property
    def given(self) -> tuple[float, float, str]:
        """With no diagram: ΔE, its reference and how it is found. C_E's share of the power
        over the time a cycle takes, P·cycle/ω, beside the mean torque P/ω over the cycle's
        angle; the flywheel's I·ω²·C_s beside ½·I·(ω1² − ω2²) at the two speeds."""
        ex = self.exercise
        if ex.delta_e_given is not None:
            return ex.delta_e_given, ex.delta_e_given, "ΔE given"
        if ex.energy_coefficient is not None:
            ce = ex.energy_coefficient
            return (ce * ex.power * (ex.cycle / ex.speed), ce * (ex.power / ex.speed) * ex.cycle,
                    "ΔE = C_E·P·t, t = cycle/ω the time a cycle takes")
        high, low = ex.extremes_given or speed_limits(ex.speed, ex.speed_fluctuation)
        return (ex.inertia * ex.speed ** 2 * ex.speed_fluctuation,
                energy_between(ex.inertia, high, low), "ΔE = I·ω²·C_s = ½·I·(ω1² − ω2²)")

    @cached_property
    def drawing(self) -> Reading | None:
        """A formula's diagram drawn at equal steps and read off the drawing, the graphical
        answer set beside the exact one; None for a table (its drawing is its trapezoids)
        or areas."""
        ex = self.exercise
        return read_diagram(ex.diagram) if ex.formula is not None else None

    @cached_property
    def reference(self) -> Integrated | None:
        """T(θ) integrated by quadrature; None for a diagram given by its areas."""
        d = self.exercise.diagram
        return integrated(d.torque, d.cycle, d.kinks) if d else None

    @cached_property
    def reference_delta_e(self) -> float:
        """ΔE by the reference: quadrature, or the greatest run of neighbouring areas."""
        if self.reference is not None:
            return self.reference.delta_e
        if not self.drawn:
            return self.given[1]
        if self.exercise.punch is not None:
            return self._punch_reference.delta_e
        a = self.exercise.areas
        n = len(a)
        return max(abs(math.fsum(a[(i + j) % n] for j in range(length)))
                   for i in range(n) for length in range(1, n))

    @cached_property
    def _punch_reference(self) -> Integrated:
        """The punch's torque over a period mapped onto a turn, by the quadrature: its mean
        is the motor's, its ΔE the flywheel's."""
        table = self.exercise.punch.table()
        ts = [t for t, _ in table]

        def torque(theta: float) -> float:
            return table[0][1] if theta % (2 * math.pi) < ts[1] else 0.0
        return integrated(torque, 2 * math.pi, tuple(ts[1:-1]))

    @cached_property
    def tolerance(self) -> float:
        """ΔE's and the mean's tolerance, relative to ΔE (see the module's docstring)."""
        ex, r = self.exercise, self.reading
        if ex.diagram is None:
            # sums of a few numbers, each rounded once (a file with no diagram: a product)
            return 1e-12 * max(len(ex.areas), 1)
        size = max(abs(t) for _, t in r.samples) * ex.cycle
        floor = ROUNDING * size
        quadrature = QUADRATURE if ex.formula is not None else 0.0
        return quadrature + floor / max(r.delta_e, floor, sys.float_info.min)   # T ≡ 0: none

    @cached_property
    def drawn_tolerance(self) -> float:
        """The drawing's ΔE against the exact one, relative to ΔE: the straight lines between
        steps h apart cost each area some h²·|T′|max/6 at either end, doubled."""
        d, r = self.drawing, self.reading
        torques = [t for _, t in d.samples]
        slope = max(abs(b - a) for a, b in zip(torques, torques[1:] + torques[:1])) / d.step
        floor = ROUNDING * max(abs(t) for t in torques) * self.exercise.cycle
        return (d.step ** 2 * slope / 3 + floor) / max(r.delta_e, floor, sys.float_info.min)

    @property
    def inertia(self) -> float | None:
        """The flywheel (kg·m²): given, or found for the C_s asked."""
        ex = self.exercise
        if ex.inertia is not None:
            return ex.inertia
        if ex.speed_fluctuation is not None and self.reading.delta_e and ex.speed is not None:
            return flywheel_inertia(self.reading.delta_e, ex.speed, ex.speed_fluctuation)
        return None

    @property
    def per_speed_unit(self) -> float:
        """rad/s in a unit of the file's speed (1 for rad/s, 2π/60 for rpm)."""
        return SPEEDS[self.exercise.speed_unit]

    @property
    def sign(self) -> float:
        """+1 for a driving torque against a steady resistance, −1 for a machine's resisting
        torque against a steady driver: the shaft speeds up where T − T_mean has this sign."""
        return -1.0 if self.exercise.resisting else 1.0

    def alpha(self, torque: float) -> float:
        """The shaft's angular acceleration (rad/s²) where the diagram's torque is ``torque``:
        (T − T_mean)/I, the resistance steady at the mean; (T_mean − T)/I for a resisting
        torque, the driver steady at the mean."""
        return self.sign * (torque - self.reading.mean) / self.inertia

    @cached_property
    def extremes(self) -> dict[str, tuple[float, float]]:
        """Where T is greatest and least over the cycle, by the drawing (θ rad, T N·m)."""
        d = self.exercise.diagram
        return {"greatest": extreme(d, self.reading.samples, 1.0),
                "least": extreme(d, self.reading.samples, -1.0)}

    # ----- results.json ------------------------------------------------------------------------
    @cached_property
    def checked(self) -> dict[str, Checked]:
        """Every quantity results.json gives, by name, in SI."""
        ex, r, tol = self.exercise, self.reading, self.tolerance
        ref = self.reference
        q: dict[str, Checked] = {}
        method = ("intercepts by bisection on T(θ), each loop by Gauss–Legendre"
                  if ex.formula is not None else "turning-moment diagram" if ex.diagram
                  else "areas of the diagram" if self.drawn else self.given[2])
        if ex.energy_coefficient is not None:
            # the work a cycle: P over the time a cycle takes, beside T_mean over its angle
            q["work_per_cycle"] = _check(ex.power * (ex.cycle / ex.speed),
                                         ex.power / ex.speed * ex.cycle, 1e-15,
                                         "W = P·t, t = cycle/ω", unit="J")
        if ref is not None:
            q["mean_torque"] = _check(r.mean, ref.mean, tol * max(r.delta_e, 1.0) /
                                      max(abs(ref.mean), 1.0) / ex.cycle, method, unit="N·m")
        if ex.punch is not None:
            # E over the period, beside the quadrature's mean torque over the turn it maps to
            p = self._punch_reference
            q["power"] = _check(ex.punch.power, p.mean * 2 * math.pi / ex.punch.period,
                                1e-12, "P = E/T, a hole's energy over the period", unit="W")
            if ex.punch.supply != 1.0:
                # the work with its losses, beside the quadrature's over the turn
                q["energy_supplied"] = _check(
                    ex.punch.supplied, p.mean * 2 * math.pi, 1e-12,
                    "E/η" if ex.punch.efficiency is not None else "E·(1 + losses)", unit="J")
            method = "E·(1 − t/T), the motor steady"
            if ex.punch.by_power:
                # the holes a minute the power given keeps up with: 60·P/E, E by quadrature
                q["holes_per_minute"] = _check(60 / ex.punch.period,
                                               60 * ex.punch.power / (p.mean * 2 * math.pi),
                                               1e-12, "60·P/E, a hole every E/P",
                                               unit="1/min")
        q["delta_E"] = _check(r.delta_e, self.reference_delta_e, tol, method, unit="J")
        if self.drawing is not None:
            q["delta_E_drawn"] = _check(self.drawing.delta_e, r.delta_e, self.drawn_tolerance,
                                        "the drawn areas against the exact ones", unit="J")
        if ex.speed is not None and ref is not None:
            q["power"] = _check(r.mean * ex.speed, ref.mean * ex.speed,
                                q["mean_torque"].tolerance, method, unit="W")
        ref_e = self.reference_delta_e
        if ex.speed is None and ex.rim_speed is not None:
            # no shaft speed: m·v² = I·ω², so the rim's mass is ΔE/(C_s·v²) all the same
            v2cs = ex.rim_speed ** 2 * ex.speed_fluctuation
            q["rim_mass"] = _check(r.delta_e / v2cs, ref_e / v2cs, tol, "m = ΔE/(C_s·v²)",
                                   unit="kg")
        elif ex.speed_fluctuation is not None and ex.inertia is not None:
            # the flywheel and its speeds given: ΔE is what is asked; I as the data make it
            how = ("I = m·k²" if ex.radius_of_gyration is not None else "I = m·r²"
                   if ex.mass is not None else "given")
            q["inertia"] = Checked({"value": ex.inertia, "unit": "kg·m²"}, method=how)
        elif ex.speed_fluctuation is not None:
            if ex.hoop_stress is not None:
                # σ = ρ·v² for a thin rim: v, beside σ/(ρ·v) (five roundings of 1.1e-16)
                v = ex.rim_speed
                q["rim_speed"] = _check(v, ex.hoop_stress / (ex.density * v), 6e-16,
                                        "v = √(σ/ρ)", unit="m/s")
            if ex.rim_speed is not None:
                q["rim_radius"] = _check(ex.radius, ex.rim_speed / ex.speed, 0.0, "r = v/ω",
                                         unit="m")
            q["inertia"] = _check(self.inertia, flywheel_inertia(ref_e, ex.speed,
                                                                 ex.speed_fluctuation),
                                  tol, "I = ΔE/(C_s·ω²)", unit="kg·m²")
            # the rim's share of I (the hub and arms the rest), all of it unless the file says
            share = ex.rim_share
            rim, rim_ref = share * self.inertia, share * q["inertia"].reference["value"]
            if ex.radius is not None:
                q["rim_mass"] = _check(rim_mass(rim, ex.radius), rim_mass(rim_ref, ex.radius),
                                       tol, "m = I/r²", unit="kg")
            if ex.mass is not None:
                q["rim_radius"] = _check(rim_radius(rim, ex.mass), rim_radius(rim_ref, ex.mass),
                                         tol, "r = √(I/m)", unit="m")
            q |= self._section(q, tol)
        elif ex.inertia is not None and ex.speed is None:
            q |= self._other_speed(tol)
        elif ex.inertia is not None:
            q["speed_fluctuation"] = _check(
                speed_fluctuation(r.delta_e, ex.speed, ex.inertia),
                speed_fluctuation(ref_e, ex.speed, ex.inertia), tol, "C_s = ΔE/(I·ω²)")
        if ex.extremes_given is not None:
            high, low = ex.extremes_given
            # C_s from the two speeds, beside 2(ω1 − ω2)/(ω1 + ω2): a few roundings
            q["speed"] = _check(ex.speed, math.fsum(ex.extremes_given) / 2, 1e-15,
                                "ω = (ω1 + ω2)/2", unit="rad/s",
                                rpm=_rpm(ex.speed))
            q["speed_fluctuation"] = _check(ex.speed_fluctuation,
                                            2 * (high - low) / (high + low),
                                            4e-16 * (high + low) / (high - low),
                                            "C_s = (ω1 − ω2)/ω")
        c = q.get("speed_fluctuation")
        cs = ex.speed_fluctuation if c is None else c.value["value"]
        # below 2: a flywheel so small that the speed would stop has no least speed
        if ex.speed is not None and cs is not None and cs < 2:
            got = speed_limits(ex.speed, cs)
            want = speed_limits(ex.speed, cs if c is None else c.reference["value"])
            for key, v, w, side in (("speed_max", got[0], want[0], 1.0),
                                    ("speed_min", got[1], want[1], -1.0)):
                # ω·(1 ± C_s/2): C_s's relative error times (C_s/2)/(1 ± C_s/2)
                spread = 0.0 if c is None else c.tolerance * cs / 2 / (1 + side * cs / 2)
                q[key] = _check(v, w, spread + 1e-15, "ω(1 ± C_s/2), ω the mean of the two",
                                unit="rad/s", rpm=_rpm(v))
        q |= self._energies(q, tol)
        if ref is not None and r.delta_e:
            q |= self._fastest(ref, tol)
        if ref is not None and self.inertia:
            q |= self._extremes(ref)
            for theta in ex.at:
                t = ex.diagram.torque(theta)
                key = f"{math.degrees(theta):g}"
                q[f"T_at_{key}"] = Checked({"value": t, "unit": "N·m",
                                            "angle_deg": math.degrees(theta)})
                q[f"alpha_at_{key}"] = _check(self.alpha(t),
                                              self.sign * (t - ref.mean) / self._ref_inertia,
                                              tol * max(r.delta_e, 1.0) / ex.cycle
                                              / max(abs(t - ref.mean), 1.0) + tol,
                                              "α = (T − T_mean)/I", unit="rad/s²",
                                              angle_deg=math.degrees(theta))
        return q

    def _other_speed(self, tol: float) -> dict[str, Checked]:
        """One extreme speed given alone: the other from ΔE = ½·I·(ω1² − ω2²), as the books
        find a press's speed after it punches from its speed before; the mean is then the
        two's average and C_s = (ω1 − ω2)/ω.

        Raises
        ------
        InputError
            Where the flywheel is too small to give up ΔE from the greatest speed.
        """
        ex = self.exercise
        given = ex.speed_max if ex.speed_max is not None else ex.speed_min
        side = -1.0 if ex.speed_max is not None else 1.0

        def other(delta_e: float) -> float:
            square = given ** 2 + side * 2 * delta_e / ex.inertia
            if not square > 0:
                raise InputError(
                    f"a flywheel of I = {ex.inertia:.6g} kg·m² holds ½·I·ω1² = "
                    f"{ex.inertia * given ** 2 / 2:.6g} J at the greatest speed, less than the "
                    f"ΔE = {delta_e:.6g} J it must give up: it would stop; give a larger one")
            return math.sqrt(square)
        got, want = other(self.reading.delta_e), other(self.reference_delta_e)
        # ω2² = ω1² − 2ΔE/I: ΔE's relative error times 2ΔE/(I·ω2²)/2 in ω2
        spread = tol * self.reference_delta_e / (ex.inertia * want ** 2) + 1e-15
        key = "speed_min" if ex.speed_max is not None else "speed_max"
        out = {key: _check(got, want, spread, "ΔE = ½·I·(ω1² − ω2²)", unit="rad/s",
                           rpm=_rpm(got))}
        high, low = (given, got) if side < 0 else (got, given)
        ref_high, ref_low = (given, want) if side < 0 else (want, given)
        out["speed"] = _check((high + low) / 2, (ref_high + ref_low) / 2, spread,
                              "ω = (ω1 + ω2)/2", unit="rad/s", rpm=_rpm((high + low) / 2))
        out["speed_fluctuation"] = _check(2 * (high - low) / (high + low),
                                          2 * (ref_high - ref_low) / (ref_high + ref_low),
                                          # the found speed's error over ω1 − ω2
                                          spread * 2 * high * low / ((high + low) * (high - low))
                                          + 1e-15,
                                          "C_s = (ω1 − ω2)/ω")
        return out

    def _section(self, q: dict[str, Checked], tol: float) -> dict[str, Checked]:
        """A rectangular rim's thickness and width, from its mass at its radius."""
        ex = self.exercise
        if ex.density is None or ex.width_to_thickness is None:
            return {}
        out = {}
        if "rim_mass" in q:
            got = rim_section(q["rim_mass"].value["value"], ex.radius, ex.density,
                              ex.width_to_thickness)
            want = rim_section(q["rim_mass"].reference["value"], ex.radius, ex.density,
                               ex.width_to_thickness)
        else:
            got = rim_section(ex.mass, q["rim_radius"].value["value"], ex.density,
                              ex.width_to_thickness)
            want = rim_section(ex.mass, q["rim_radius"].reference["value"], ex.density,
                               ex.width_to_thickness)
        radius = ex.radius if "rim_mass" in q else q["rim_radius"].value["value"]
        if not got[0] < 2 * radius:
            # a rim of mean radius r reaches in to r − t/2: one t ≥ 2r has no bore, no rim
            unit = ex.length_unit
            raise InputError(
                f"a rim of mean radius {radius / LENGTH_UNITS[unit]:.6g} {unit} would be "
                f"t = {got[0] / LENGTH_UNITS[unit]:.6g} {unit} thick, past its mean diameter: "
                "no rim holds that mass; is the radius in the right unit?")
        for k, key in enumerate(("rim_thickness", "rim_width")):
            # t ∝ √m (or 1/√r): half the mass's relative error
            out[key] = _check(got[k], want[k], tol, "b·t = m/(ρ·2πr), b = k·t", unit="m")
        return out

    def _energies(self, q: dict[str, Checked], tol: float) -> dict[str, Checked]:
        """The coefficient of fluctuation of energy, ΔE over the work done in a cycle (the
        mean torque times the cycle, or a punch's energy a hole), and the energy the
        flywheel stores at the mean speed, ½·I·ω²."""
        ex, r, ref = self.exercise, self.reading, self.reference
        out = {}
        if ex.punch is not None:
            work, ref_work = ex.punch.supplied, self._punch_reference.mean * 2 * math.pi
        elif ref is not None and r.mean > 0:
            work, ref_work = r.mean * ex.cycle, ref.mean * ex.cycle
        else:
            work = ref_work = 0.0
        if work > 0 and ref_work > 0:
            # ΔE's error and the mean's (each within ΔE's tolerance of ΔE) over the work
            out["energy_fluctuation"] = _check(
                r.delta_e / work, self.reference_delta_e / ref_work,
                tol * (1 + r.delta_e / work), "C_E = ΔE/(work done in a cycle)")
        if self.inertia and ex.speed is not None:
            found = "inertia" in q and q["inertia"].reference is not None
            i_ref = q["inertia"].reference["value"] if found else self.inertia
            out["kinetic_energy"] = _check(self.inertia * ex.speed ** 2 / 2,
                                           i_ref * ex.speed ** 2 / 2,
                                           q["inertia"].tolerance if found else 0.0,
                                           "½·I·ω² at the mean speed", unit="J")
        return out

    def _fastest(self, ref: Integrated, tol: float) -> dict[str, Checked]:
        """Where the shaft runs fastest and slowest: at the intercepts where the energy the
        flywheel holds is highest and lowest (the diagram's for a driving torque, the
        other way round for a resisting one). The reference's energy at the intercept
        nearest each must be its own highest (or lowest), within ΔE's tolerance: two
        intercepts of equal energy (a curve that repeats) are both right."""
        r, ex = self.reading, self.exercise
        top, bottom = (r.lowest, r.highest) if ex.resisting else (r.highest, r.lowest)
        out = {}
        for key, theta, pick in (("speed_max_at", top, max), ("speed_min_at", bottom, min)):
            want = pick(self.sign * e for _, e in ref.levels)     # the flywheel's energy
            near, energy = min(ref.levels, key=lambda p: abs(math.remainder(p[0] - theta,
                                                                             ex.cycle)))
            miss = abs(math.remainder(near - theta, ex.cycle)) / ex.cycle
            off = abs(energy * self.sign - want) / max(ref.delta_e, sys.float_info.min)
            out[key] = Checked({"value": math.degrees(theta) % math.degrees(ex.cycle),
                                "unit": "°"}, {"value": math.degrees(near)},
                               rel_error=max(miss, off), tolerance=max(tol, 1e-6),
                               passed=miss <= 1e-6 and off <= max(tol, 1e-9),
                               method="the intercept of the highest (lowest) energy")
        return out

    @property
    def _ref_inertia(self) -> float:
        ex = self.exercise
        if ex.inertia is not None:
            return ex.inertia
        return flywheel_inertia(self.reference_delta_e, ex.speed, ex.speed_fluctuation)

    def _extremes(self, ref: Integrated) -> dict[str, Checked]:
        """The greatest acceleration and retardation and where each is."""
        out = {}
        ex, tol = self.exercise, self.tolerance
        size = max(abs(t) for _, t in self.reading.samples)
        high, low = ("greatest", ref.greatest), ("least", ref.least)
        if ex.resisting:                       # the shaft speeds up where the machine eases
            high, low = low, high
        for key, (side, (r_theta, r_t)) in (("acceleration", high), ("retardation", low)):
            places = self.extremes[side]
            # the place nearest the reference's, where a repeating curve has more than one
            theta, t = min(places, key=lambda p: abs(math.remainder(p[0] - r_theta, ex.cycle)))
            a, r_a = self.alpha(t), self.sign * (r_t - ref.mean) / self._ref_inertia
            # T at its extreme is the extreme to rounding; α is its small rest over I.
            a_tol = tol + ROUNDING * size / max(abs(t - self.reading.mean), 1.0)
            out[f"greatest_{key}"] = _check(abs(a), abs(r_a), a_tol, "α = (T − T_mean)/I over the "
                                            "whole cycle", unit="rad/s²", angle_deg=[
                                                math.degrees(p) for p, _ in places])
            # Where: at a smooth extreme θ is fixed only to some √(rounding) of T, 1e-8 of
            # the cycle; the reference's place must be one of the drawing's.
            miss = abs(math.remainder(theta - r_theta, ex.cycle))
            if ex.diagram.kinks and any(abs(ex.diagram.torque(u) - r_t) <= ROUNDING * size
                                        for u in (theta, math.nextafter(theta, -math.inf))):
                miss = 0.0      # a table's extreme held along a level or at a jump: T agrees
            at = Checked({"value": math.degrees(theta), "unit": "°"},
                         {"value": math.degrees(r_theta)}, rel_error=miss / ex.cycle,
                         tolerance=1e-6, passed=miss / ex.cycle <= 1e-6,
                         method="every peak of the scan, refined")
            out[f"greatest_{key}_at"] = at
        return out

    @property
    def failures(self) -> list[str]:
        """The quantities that failed their check, by name."""
        return [k for k, c in self.checked.items() if c.passed is False]

    # ----- words -------------------------------------------------------------------------------
    def lines(self) -> list[str]:
        """What the command line prints and steps.md lists, in the language spoken."""
        from .flywheel_words import lines
        return lines(self)

    def document(self) -> list[Section]:
        """steps.md: how the diagram is read, numbered, then the results."""
        from .flywheel_words import document
        return document(self)

    @property
    def figures(self) -> dict[str, Any]:
        """The turning-moment diagram (T(θ)), or the energy at each intercept (areas)."""
        from tarsim.graphics.forces.flywheel_figure import (energy_figure, speed_figure,
                                                            torque_figure)
        if not self.drawn:
            return {"energy": speed_figure(self)}
        if self.exercise.diagram is None:
            return {"energy": energy_figure(self)}
        return {"turning-moment": torque_figure(self)}


def solve_flywheel(ex: FlywheelExercise) -> FlywheelSolution:
    """Solve a flywheel exercise."""
    return FlywheelSolution(ex)
