"""A solved flywheel exercise in words: what the command line prints and steps.md lists
(:func:`lines`), and how the diagram is read, numbered (:func:`document`), in the language
spoken."""

from __future__ import annotations

import math

from tarsim.constructions.narration import numeral, phrase, words
from tarsim.constructions.units import LENGTH_UNITS
from ..table_file import SPEEDS
from ..worked_document import Bullets, Section, numbered, title

__all__ = ["document", "lines"]


def _length(sol, v: float) -> str:
    unit = sol.exercise.length_unit
    return f"{numeral(v / LENGTH_UNITS[unit])} {unit}"


def _level(sol, places: list[float], value: float) -> tuple[float, float] | None:
    """A table's extreme ``value`` (N·m) held along a level stretch between its two
    places (°), as (start, end) going forward round the cycle; None for an extreme at
    points."""
    ex = sol.exercise
    if not ex.points or len(places) != 2:
        return None
    period = math.degrees(ex.cycle)
    for start, end in (places, places[::-1]):
        span = (end - start) % period
        t = [ex.diagram.torque(math.radians(start + f * span)) for f in (0.25, 0.5, 0.75)]
        if max(abs(v - value) for v in t) <= 1e-12 * max(abs(v) for v in t + [1.0]):
            return start, start + span if start + span <= period else start + span - period
    return None


def _speed_unit(sol) -> float:
    return SPEEDS[sol.exercise.speed_unit]


def _theta(sol, theta: float) -> str:
    return numeral(math.degrees(theta) % 360 if sol.exercise.cycle <= 2 * math.pi
                   else math.degrees(theta), ".2f")


def lines(sol) -> list[str]:
    """What the command line prints and steps.md lists, in the language spoken."""
    ex, r, q = sol.exercise, sol.reading, sol.checked
    out = []
    if ex.resisting:
        out.append(words("the machine's resisting torque averages T_mean = {mean} N·m over a "
                         "cycle of {cycle}°: the steady driving torque",
                         mean=numeral(r.mean), cycle=numeral(math.degrees(ex.cycle), "g")))
    elif ex.diagram is not None:
        out.append(words("mean turning moment T_mean = {mean} N·m over a cycle of {cycle}°",
                         mean=numeral(r.mean), cycle=numeral(math.degrees(ex.cycle), "g")))
    if ex.punch is not None and ex.punch.efficiency is not None:
        out.append(words("a hole's punching work {work} J at an efficiency of {eta}: the "
                         "motor and flywheel give E = {work} J/η = {energy} J a hole",
                         work=numeral(ex.punch.energy), eta=numeral(ex.punch.efficiency, "g"),
                         energy=numeral(ex.punch.supplied)))
    elif ex.punch is not None and ex.punch.losses is not None:
        out.append(words("a hole's punching work {work} J and the frictional losses, {share} "
                         "of it: the motor and flywheel give E = {work} J × {supply} = "
                         "{energy} J a hole", work=numeral(ex.punch.energy),
                         share=numeral(ex.punch.losses, "g"),
                         supply=numeral(ex.punch.supply, "g"),
                         energy=numeral(ex.punch.supplied)))
    if ex.punch is not None and ex.punch.by_power:
        out.append(words("a motor of {power} kW gives a hole's E = {energy} J in T = E/P = "
                         "{period} s, the hole taking {time} s: {rate} holes a minute",
                         power=numeral(ex.punch.power / 1000),
                         energy=numeral(ex.punch.supplied),
                         period=numeral(ex.punch.period), time=numeral(ex.punch.time, "g"),
                         rate=numeral(q["holes_per_minute"].value["value"])))
    elif ex.punch is not None:
        out.append(words("a hole takes E = {energy} J in {time} s of every {period} s: the "
                         "motor's power P = E/T = {power} kW", energy=numeral(ex.punch.supplied),
                         time=numeral(ex.punch.time, "g"),
                         period=numeral(ex.punch.period, "g"),
                         power=numeral(ex.punch.power / 1000)))
    elif "power" in q:
        out.append(words("power at the mean speed: P = T_mean·ω = {power} kW",
                         power=numeral(q["power"].value["value"] / 1000)))
    k = ex.radius_of_gyration if ex.radius_of_gyration is not None else ex.radius
    if ex.mass is not None and ex.inertia is not None and k is not None:
        # the flywheel given by its mass and where it sits: the length said in its unit, so
        # that a radius in the wrong unit shows where it is used
        out.append(words("a flywheel of {mass} kg at {radius} from the axis: I = m·{k}² = "
                         "{inertia} kg·m²", mass=numeral(ex.mass), radius=_length(sol, k),
                         k="k" if ex.radius_of_gyration is not None else "r",
                         inertia=numeral(ex.inertia)))
    if not sol.drawn:
        out.append(_given(sol))
    elif r.delta_e:
        where = (words("between θ = {low}° and {high}°", low=_theta(sol, r.lowest),
                       high=_theta(sol, r.highest)) if ex.diagram is not None else
                 words("the energy highest after area {high} and lowest after area {low}",
                       high=numeral(r.highest or len(r.areas), "g"),
                       low=numeral(r.lowest or len(r.areas), "g")))
        out.append(words("greatest fluctuation of energy ΔE = {energy} J, {where}",
                         energy=numeral(r.delta_e), where=where))
    else:
        out.append(words("the turning moment is steady: ΔE = 0 and no flywheel is needed"))
    if "energy_fluctuation" in q:
        out.append(words("the coefficient of fluctuation of energy C_E = ΔE/(work done in a "
                         "cycle) = {ce}", ce=numeral(q["energy_fluctuation"].value["value"])))
    if "kinetic_energy" in q:
        out.append(words("the flywheel stores ½·I·ω² = {energy} J at the mean speed",
                         energy=numeral(q["kinetic_energy"].value["value"])))
    if "speed_max_at" in q:
        out.append(words("the shaft runs fastest at θ = {high}° and slowest at θ = {low}°, "
                         "where the energy it holds is highest and lowest",
                         high=numeral(q["speed_max_at"].value["value"], ".2f"),
                         low=numeral(q["speed_min_at"].value["value"], ".2f")))
    if ex.extremes_given is not None:
        high, low = ex.extremes_given
        out.append(words("between the greatest and least speeds, {high} and {low} {unit}: the "
                         "mean ω = (ω1 + ω2)/2 = {mean} {unit}, C_s = (ω1 − ω2)/ω = {cs}",
                         unit=ex.speed_unit, high=numeral(high / _speed_unit(sol)),
                         low=numeral(low / _speed_unit(sol)),
                         mean=numeral(ex.speed / _speed_unit(sol)),
                         cs=numeral(ex.speed_fluctuation)))
    if "inertia" in q and q["inertia"].reference is not None:
        out.append(words("flywheel for C_s = {cs} at ω = {omega} rad/s: I = ΔE/(C_s·ω²) = "
                         "{inertia} kg·m²", cs=numeral(ex.speed_fluctuation, "g"),
                         omega=numeral(ex.speed), inertia=numeral(sol.inertia)))
    if ex.rim_speed is not None and "rim_mass" in q and ex.radius is None:
        out.append(words("a rim whose mean speed is {speed} m/s: m = ΔE/(C_s·v²) = {mass} kg",
                         speed=numeral(ex.rim_speed, "g"),
                         mass=numeral(q["rim_mass"].value["value"])))
    elif ex.rim_speed is not None and "rim_mass" in q:
        if ex.hoop_stress is not None:
            out.append(words("a rim whose hoop stress is {stress} MPa at {density} kg/m³: its "
                             "speed v = √(σ/ρ) = {speed} m/s", stress=numeral(
                                 ex.hoop_stress / 1e6, "g"), density=numeral(ex.density, "g"),
                             speed=numeral(ex.rim_speed)))
        share = "I" if ex.rim_share == 1.0 else f"{numeral(ex.rim_share, 'g')}·I"
        out.append(words("a rim whose mean speed is {speed} m/s: its radius r = v/ω = "
                         "{radius}, its mass m = {share}/r² = {mass} kg",
                         speed=numeral(ex.rim_speed, "g"), radius=_length(sol, ex.radius),
                         share=share, mass=numeral(q["rim_mass"].value["value"])))
    elif "rim_mass" in q and ex.radius_of_gyration is not None:
        out.append(words("a flywheel whose radius of gyration is {radius}: its mass m = I/k² "
                         "= {mass} kg", radius=_length(sol, ex.radius),
                         mass=numeral(q["rim_mass"].value["value"])))
    elif "rim_mass" in q and ex.rim_share != 1.0:
        out.append(words("a rim of mean radius {radius} that gives {share} of I: m = "
                         "{share}·I/r² = {mass} kg", radius=_length(sol, ex.radius),
                         share=numeral(ex.rim_share, "g"),
                         mass=numeral(q["rim_mass"].value["value"])))
    elif "rim_mass" in q:
        out.append(words("a rim of mean radius {radius}: m = I/r² = {mass} kg",
                         radius=_length(sol, ex.radius),
                         mass=numeral(q["rim_mass"].value["value"])))
    if "rim_radius" in q and ex.rim_speed is None:
        out.append(words("a rim of {mass} kg: its mean radius r = √(I/m) = {radius}",
                         mass=numeral(ex.mass),
                         radius=_length(sol, q["rim_radius"].value["value"])))
    if "rim_thickness" in q:
        out.append(words("its section at {density} kg/m³, the width {ratio} times the "
                         "thickness: b·t = m/(ρ·2πr), t = {thickness}, b = {width}",
                         density=numeral(ex.density, "g"),
                         ratio=numeral(ex.width_to_thickness, "g"),
                         thickness=_length(sol, q["rim_thickness"].value["value"]),
                         width=_length(sol, q["rim_width"].value["value"])))
    if "speed" in q and ex.speed is None:
        unit = _speed_unit(sol)
        high, low = ((ex.speed_max, q["speed_min"].value["value"]) if ex.speed_max is not None
                     else (q["speed_max"].value["value"], ex.speed_min))
        out.append(words("a flywheel of I = {inertia} kg·m² giving up ΔE = ½·I·(ω1² − ω2²): "
                         "the greatest speed {high} {unit}, the least {low} {unit}; their "
                         "mean {mean} {unit}, C_s = (ω1 − ω2)/ω = {cs}",
                         inertia=numeral(ex.inertia), unit=ex.speed_unit,
                         high=numeral(high / unit), low=numeral(low / unit),
                         mean=numeral(q["speed"].value["value"] / unit),
                         cs=numeral(q["speed_fluctuation"].value["value"])))
    elif "speed_fluctuation" in q and ex.extremes_given is None:
        out.append(words("a flywheel of I = {inertia} kg·m² holds the speed within C_s = "
                         "ΔE/(I·ω²) = {cs} ({percent} % of the mean, ±{half} %)",
                         inertia=numeral(ex.inertia),
                         cs=numeral(q["speed_fluctuation"].value["value"]),
                         percent=numeral(100 * q["speed_fluctuation"].value["value"]),
                         half=numeral(50 * q["speed_fluctuation"].value["value"])))
    if "speed_max" in q and "speed" not in q:     # not the one found from the other
        out.append(words("the greatest and least speeds ω(1 ± C_s/2): {high} and {low} "
                         "{unit}", unit=ex.speed_unit,
                         high=numeral(q["speed_max"].value["value"] / _speed_unit(sol)),
                         low=numeral(q["speed_min"].value["value"] / _speed_unit(sol))))
    for key, say, held in (
            ("acceleration", "greatest acceleration {alpha} rad/s² at θ = {at}°",
             "greatest acceleration {alpha} rad/s², held from θ = {start}° to {end}°"),
            ("retardation", "greatest retardation {alpha} rad/s² at θ = {at}°",
             "greatest retardation {alpha} rad/s², held from θ = {start}° to {end}°")):
        if f"greatest_{key}" in q:
            c = q[f"greatest_{key}"]
            side = ("greatest" if (key == "acceleration") != ex.resisting else "least")
            level = _level(sol, c.value["angle_deg"], sol.extremes[side][0][1])
            out.append(words(say, alpha=numeral(c.value["value"]), at=", ".join(
                numeral(a, ".2f") for a in c.value["angle_deg"])) if level is None else
                words(held, alpha=numeral(c.value["value"]),
                      start=numeral(level[0], ".2f"), end=numeral(level[1], ".2f")))
    for theta in ex.at:
        key = f"{math.degrees(theta):g}"
        if f"alpha_at_{key}" in q:
            out.append(words("at θ = {at}°: T = {torque} N·m, α = {alpha} rad/s²",
                             at=numeral(math.degrees(theta), "g"),
                             torque=numeral(q[f"T_at_{key}"].value["value"]),
                             alpha=numeral(q[f"alpha_at_{key}"].value["value"])))
    failed = sol.failures
    out.append(words("every number agrees with its reference") if not failed else
               f"OFF: {', '.join(failed)}")
    return out


def _given(sol) -> str:
    """How a file with no diagram gives ΔE: given, C_E's share of the work a cycle, or the
    flywheel's energy between its two speeds."""
    ex, energy = sol.exercise, numeral(sol.reading.delta_e)
    if ex.delta_e_given is not None:
        return words("the greatest fluctuation of energy is given: ΔE = {energy} J",
                     energy=energy)
    if ex.energy_coefficient is not None:
        return words("the engine's {power} kW do W = P·t = {work} J in a cycle of {cycle}° "
                     "(t = {time} s at the mean speed); ΔE = C_E·W = {ce} × {work} J = "
                     "{energy} J", power=numeral(ex.power / 1000),
                     work=numeral(sol.checked["work_per_cycle"].value["value"]),
                     cycle=numeral(math.degrees(ex.cycle), "g"),
                     time=numeral(ex.cycle / ex.speed), ce=numeral(ex.energy_coefficient, "g"),
                     energy=energy)
    high, low = ex.extremes_given or (sol.checked["speed_max"].value["value"],
                                      sol.checked["speed_min"].value["value"])
    unit = _speed_unit(sol)
    return words("a flywheel of I = {inertia} kg·m² between {high} and {low} {unit}: ΔE = "
                 "½·I·(ω1² − ω2²) = I·ω²·C_s = {energy} J", inertia=numeral(ex.inertia),
                 high=numeral(high / unit), low=numeral(low / unit), unit=ex.speed_unit,
                 energy=energy)


def _engine_steps(sol) -> list[str]:
    """The steps that make the diagram of an engine given by its strokes or cylinders."""
    ex, steps = sol.exercise, []
    if ex.strokes and ex.power is not None:
        steps.append(words("At {power} kW the engine does P·t = {work} J in a cycle of "
                           "{cycle}°, t = cycle/ω; shared in the ratio given, its strokes' "
                           "works are {works} J.", power=numeral(ex.power / 1000),
                           work=numeral(math.fsum(ex.strokes)),
                           cycle=numeral(math.degrees(ex.cycle), "g"),
                           works=", ".join(numeral(w, ".6g") for w in ex.strokes)))
    if ex.strokes:
        steps.append(words("Each stroke's diagram is a triangle on its base of {span}°, its "
                           "apex at mid-stroke 2W/s high so that its area is its work W: "
                           "{heights} N·m.", span=numeral(math.degrees(ex.cycle)
                                                          / len(ex.strokes), "g"),
                           heights=", ".join(numeral(2 * w / (ex.cycle / len(ex.strokes)),
                                                     ".6g") for w in ex.strokes)))
    if ex.phases:
        steps.append(words("Add the {n} cylinders' diagrams, each set behind the first by "
                           "{lags}°: T(θ) = ΣT₁(θ − φ).", n=numeral(len(ex.phases), "d"),
                           lags=", ".join(numeral(math.degrees(p), "g") for p in ex.phases)))
    return steps


def document(sol) -> list[Section]:
    """steps.md: how the diagram is read, numbered, then the results."""
    ex, r = sol.exercise, sol.reading
    steps = _engine_steps(sol)
    if not sol.drawn:
        return [title(ex.name, ex.description),
                Section(phrase("heading.construction"), (numbered([_given(sol)]),)),
                Section(phrase("md.results"), (Bullets(tuple(lines(sol))),))]
    if ex.punch is not None:
        steps.append(words("While it punches, the steady motor gives E·t/T = {given} J of the "
                           "{energy} J a hole takes; the flywheel gives up the rest, "
                           "E·(1 − t/T) = {delta} J, and takes it back before the next "
                           "hole.", given=numeral(ex.punch.supplied - ex.punch.delta_e),
                           energy=numeral(ex.punch.supplied), delta=numeral(ex.punch.delta_e)))
    elif ex.diagram is None:
        steps.append(words("Each area times the diagram's scale ({scale} J per unit of area) "
                           "is an energy: {energies} J.", scale=numeral(ex.energy_scale),
                           energies=", ".join(numeral(a) for a in ex.areas)))
    elif not r.step:
        steps.append(words("Draw the table's points joined by straight lines, each jump "
                           "upright; its mean is the area under it over the cycle."))
    else:
        steps.append(words("Draw T(θ) at {n} equal steps of {step}° over the cycle; its "
                           "mean is the area under it over the cycle.",
                           n=numeral(len(r.samples), "d"),
                           step=numeral(math.degrees(r.step), "g")))
    if sol.drawing is not None:
        steps.append(words("The drawn areas give ΔE = {drawn} J. To the data's precision, the "
                           "intercepts are the roots of T(θ) − T_mean found on the formula, "
                           "and each area is T − T_mean integrated between two of them by "
                           "Gauss–Legendre quadrature.", drawn=numeral(sol.drawing.delta_e)))
    if ex.diagram is not None:
        steps.append(words("The curve crosses the mean at {n} intercepts; between them "
                           "lie the areas {energies} J.", n=numeral(len(r.intercepts), "d"),
                           energies=", ".join(numeral(a, ".5g") for a in r.areas)))
    steps.append(words("Add the areas in turn from the first intercept: the energy's "
                       "highest less its lowest is the greatest fluctuation ΔE."))
    if sol.inertia and ex.resisting:
        steps.append(words("With the driving torque steady at the mean, α = (T_mean − T)/I: "
                           "greatest where the resisting torque is lowest over the whole "
                           "cycle, most negative where it is highest."))
    elif sol.inertia and ex.diagram is not None:
        steps.append(words("With the resistance steady at the mean, α = (T − T_mean)/I: "
                           "greatest where T is highest over the whole cycle, most "
                           "negative where it is lowest."))
    return [title(ex.name, ex.description),
            Section(phrase("heading.construction"), (numbered(steps),)),
            Section(phrase("md.results"), (Bullets(tuple(lines(sol))),))]
