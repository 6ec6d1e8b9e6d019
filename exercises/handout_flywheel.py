"""The flywheel chapter's problem sheets (:mod:`.handout`): a turning-moment diagram given as
T(θ) drawn on the solution's axes with no mean line and no area; a flywheel given by numbers
alone (its speeds, a diagram's areas, a punch, an engine's power) stated; a connecting rod
drawn along its line of centres with its pins, G and its given lengths; each with its data
and what is asked, and no answer.

The exercise is solved first, as ``tarsim solve`` solves it, for what is asked is what the
solve finds (its results' keys), and the diagram is drawn over the crank angles the
solution's is; but no number the solve found is put on the sheet.
"""

from __future__ import annotations

import math
from dataclasses import replace
from types import SimpleNamespace

from tarsim.constructions.narration import numerals, unit_words, words
from tarsim.graphics.figure import Figure
from tarsim.graphics.handout import Line, compose_handout, draw_statement

from .handout_text import math_text, number

__all__ = ["flywheel_sheets"]

_ASKED = {
    "mean_torque": "the mean torque",
    "work_per_cycle": "the work done in a cycle",
    "delta_E": "the greatest fluctuation of energy ΔE",
    "power": "the power",
    "energy_supplied": "the energy the motor and flywheel supply a hole",
    "inertia": "the flywheel's moment of inertia I",
    "rim_mass": "the rim's mass",
    "rim_radius": "the rim's mean radius",
    "rim_speed": "the rim's mean speed",
    "rim_thickness": "the rim's section: its thickness and width",
    "speed": "the mean speed",
    "speed_fluctuation": "the coefficient of fluctuation of speed Cs",
    "speed_max": "the greatest and least speeds",
    "energy_fluctuation": "the coefficient of fluctuation of energy CE",
    "kinetic_energy": "the energy the flywheel stores at its mean speed",
    "speed_max_at": "where the speed is greatest and least",
    "greatest_acceleration": "the shaft's greatest acceleration and retardation, and where",
}
"""How the sheet asks each result of a flywheel (by its key in results.json); a key not here
is asked with the one it goes with (rim_width with rim_thickness)."""

_PAIRS = {("mean_torque", "power"): "the mean torque and the power",
          ("rim_mass", "rim_thickness"): "the rim's mass and its section",
          ("speed_max", "speed_max_at"): "the greatest and least speeds, and where each is"}
"""Two results asked in one line where both are asked."""

_ROD_ASKED = {
    "equivalent_masses": "the equivalent dynamical system, one mass at {pin}",
    "pin_masses": "the two masses at the pins {p} and {a}",
    "equivalent_inertia": "their moment of inertia about G, against the rod's",
    "correction_couple": "the correction couple",
}
"""How the sheet asks what a rod file's ``find`` lists."""


def flywheel_sheets(ex, sheet: tuple[float, float]) -> list[Figure]:
    """A flywheel's sheet (or a connecting rod's): the diagram given as T(θ) where the file
    gives one, the data and what is asked."""
    from .chapters import chapter_of

    sol = chapter_of(ex).solve(ex)
    if hasattr(ex, "rod"):
        return _rod_sheets(ex, sheet)
    panels = []
    curve = _given_curve(sol)
    if curve is not None:
        panels.append(curve)
    panels.append(draw_statement(_given_flywheel(ex) + _asked_flywheel(ex, sol)))
    return compose_handout(words("{name}: {what}", name=ex.name, what=words("problem sheet")),
                           panels, sheet=sheet)


# ----- the diagram given -----------------------------------------------------------------------
def _given_curve(sol) -> Figure | None:
    """The turning moment (or resisting torque) as the file gives it, over the cycle the
    solution's diagram spans, at its crank-angle ticks: the file's points, its formula, one
    cylinder's table, or the strokes' triangles to their works' ratio; None for a diagram
    given by numbers alone (its areas, a punch, ΔE or C_E)."""
    from tarsim.graphics.forces.flywheel_figure import _ticks
    from tarsim.graphics.plot import Series, draw_line_plot

    ex = sol.exercise
    if ex.diagram is None or ex.punch is not None or ex.areas:
        return None
    period = math.degrees(ex.cycle)
    torque = unit_words("N·m")
    y_label = f"T ({torque})"
    notes = [words("draw the mean line and the areas here")]
    if ex.single:
        one = [(math.degrees(t), v) for t, v in ex.single] + [(period, ex.single[0][1])]
        series = [Series(words("one cylinder's turning moment"), tuple(one))]
    elif ex.strokes:
        least = min(abs(w) for w in ex.strokes if w)
        peak = 2 * least / (ex.cycle / len(ex.strokes))     # a triangle's height for that work
        pts = [(math.degrees(t), v / peak) for t, v in ex.points] + [(period, 0.0)]
        series = [Series(words("the strokes' triangles"), tuple(pts))]
        y_label = words("T, in the least stroke's peak")
        notes.insert(0, words("each stroke's triangle is drawn to its work's ratio"))
    elif ex.points:
        pts = [(math.degrees(t), v) for t, v in ex.points] + [(period, ex.points[0][1])]
        series = [Series(words("resisting torque") if ex.resisting
                         else words("turning moment"), tuple(pts))]
    else:
        samples = [period * k / 360 for k in range(361)]
        series = [Series(words("engine's turning moment T_e") if ex.machine else
                         words("turning moment"),
                         tuple((d, ex.formula(math.radians(d))) for d in samples))]
        if ex.machine is not None:
            series.append(Series(words("machine's resisting torque T_m"), tuple(
                (d, ex.machine(math.radians(d))) for d in samples), "plot_curve_dash_dot"))
    title = (words("Resisting-torque diagram") if ex.resisting
             else words("Turning-moment diagram"))
    return draw_line_plot(title, words("crank angle θ (°)"), y_label, series, (),
                          x_range=(0.0, period), x_ticks=_ticks(period), notes=notes,
                          subtitle=ex.name)


# ----- the data ------------------------------------------------------------------------------
def _given_flywheel(ex) -> list[Line]:
    """The flywheel's data as the file gives them, in its units."""
    from .table_file import SPEEDS

    out = [Line(words("Given"), heading=True)]
    out += _diagram_lines(ex)
    rpm = SPEEDS[ex.speed_unit]
    speed_unit = unit_words(ex.speed_unit)
    metre = {"m": 1.0, "mm": 1e-3, "cm": 1e-2}.get(ex.length_unit, 1.0)
    length = unit_words(ex.length_unit)

    def speed(w: float) -> str:
        return math_text(number(w / rpm)) + f" {speed_unit}"

    high, low = ex.extremes_given or (ex.speed_max, ex.speed_min)
    if ex.speed is not None and high is None and low is None:
        out.append(Line(words("mean speed {speed}", speed=speed(ex.speed))))
    if high is not None:
        out.append(Line(words("greatest speed {speed}", speed=speed(high))))
    if low is not None:
        out.append(Line(words("least speed {speed}", speed=speed(low))))
    if ex.speed_fluctuation is not None and ex.extremes_given is None:
        out.append(Line(words("coefficient of fluctuation of speed {cs}", cs=math_text(
            f"Cs = (ωmax − ωmin)/ω = {number(ex.speed_fluctuation)}"))))
    if ex.delta_e_given is not None:
        out.append(Line(math_text(f"ΔE = {number(ex.delta_e_given)}") + " J"))
    if ex.inertia is not None and ex.mass is None:
        out.append(Line(words("flywheel: {i}", i=math_text(f"I = {number(ex.inertia)}"))
                        + " kg·m²"))
    if ex.mass is not None:
        said = words("flywheel of {mass} kg", mass=math_text(number(ex.mass)))
        if ex.radius_of_gyration is not None:
            said += words(", ") + words("radius of gyration {k}", k=math_text(
                f"k = {number(ex.radius_of_gyration / metre)}") + f" {length}")
        out.append(Line(said))
    if ex.radius is not None and ex.rim_speed is None:
        out.append(Line(words("the rim's mean radius {r} (its diameter {d})", r=math_text(
            f"r = {number(ex.radius / metre)}") + f" {length}", d=math_text(
            number(2 * ex.radius / metre)) + f" {length}")))
    if ex.rim_share != 1:
        out.append(Line(words("the rim gives {share} of I", share=math_text(
            number(ex.rim_share)))))
    if ex.rim_speed is not None:
        out.append(Line(words("the rim's mean speed {v}", v=math_text(
            f"v = {number(ex.rim_speed)}") + " m/s")))
    if ex.hoop_stress is not None:
        out.append(Line(words("the rim's allowable hoop stress {s}", s=math_text(
            f"σ = {number(ex.hoop_stress / 1e6)}") + " MPa")))
    if ex.density is not None:
        out.append(Line(words("density {rho}", rho=math_text(f"ρ = {number(ex.density)}")
                              + " kg/m³")))
    if ex.width_to_thickness is not None:
        out.append(Line(words("the rim's section {n} times as wide as it is thick",
                              n=math_text(number(ex.width_to_thickness)))))
    return out


def _diagram_lines(ex) -> list[Line]:
    """How the file gives the energy: a diagram (its formula, points, strokes, cylinders, areas
    or a punch), an engine's power with C_E, or nothing (the flywheel's two speeds)."""
    out = []
    cycle = math_text(f"{number(math.degrees(ex.cycle))}°")
    if ex.punch is not None:
        return _punch_lines(ex)
    if ex.power is not None:
        out.append(Line(words("the engine's power {p}", p=math_text(
            f"P = {number(ex.power / 1e3)}") + " kW")))
    if ex.energy_coefficient is not None:
        out.append(Line(words("coefficient of fluctuation of energy {ce}", ce=math_text(
            f"CE = {number(ex.energy_coefficient)}"))))
    if ex.diagram is None and not ex.areas:
        if ex.energy_coefficient is not None:
            out.append(Line(words("a cycle of {cycle}", cycle=cycle)))
        return out
    repeats = words("the diagram repeats every {cycle}", cycle=cycle)
    if ex.resisting:
        out.append(Line(repeats + words(", ") + words("the machine's resisting torque as drawn, "
                                                      "the driver's steady")))
    elif ex.areas:
        out.append(Line(repeats))
        areas = words(", ").join(math_text(f"A{i + 1} = " + ("+" if a > 0 else "") + number(a))
                                 for i, a in enumerate(ex.drawn_areas))
        out.append(Line(words("the areas above (+) and below (−) the mean line, in order: "
                              "{areas}", areas=areas)))
        length = unit_words(ex.length_unit)
        if ex.area_scales is None:
            out.append(Line(words("a unit of the drawing's area is {e} J",
                                  e=math_text(number(ex.energy_scale)))))
        else:
            torque, angle = ex.area_scales
            out.append(Line(words("drawn at 1 {unit} = {torque} and 1 {unit} = {angle}",
                                  unit=length, torque=math_text(number(torque)) + " "
                                  + unit_words("N·m"),
                                  angle=math_text(f"{number(angle)}°"))))
    else:
        out.append(Line(repeats + (words(", ") + words("the resisting torque steady")
                                   if not ex.strokes else "")))
    if ex.formula is not None:
        out.append(Line(math_text(f"T = {_formula(ex.formula.text)}") + f" {unit_words('N·m')}"
                        + words(", ") + words("θ in radians")))
    if ex.machine is not None:
        out.append(Line(math_text(f"Tm = {_formula(ex.machine.text)}") + f" {unit_words('N·m')}"))
    table = ex.single or (() if ex.strokes else ex.points)
    if table:
        # a point a line: a right-to-left line would set a list of them out of order
        out.append(Line(words("T at the crank angles given, straight between:")))
        out += [Line(math_text(f"T({number(math.degrees(t))}°) = {number(v)}")
                     + f" {unit_words('N·m')}") for t, v in table]
    if ex.phases and len(ex.phases) > 1:
        n = len(ex.phases)
        even = all(math.isclose(p, k * ex.cycle / n, abs_tol=1e-9)
                   for k, p in enumerate(ex.phases))
        out.append(Line(words("{n} cylinders, set equally over the cycle", n=numerals(str(n)))
                        if even else
                        words("{n} cylinders, each lagging the first by {phases}",
                              n=numerals(str(n)), phases=words(", ").join(
                                  math_text(f"{number(math.degrees(p))}°")
                                  for p in ex.phases))))
    if ex.strokes:
        least = min(abs(w) for w in ex.strokes if w)
        ratio = words(", ").join(math_text(f"W{i + 1} = {number(w / least)}")
                                 for i, w in enumerate(ex.strokes))
        out.append(Line(words("the strokes' works in the ratio {ratio}, each a triangle",
                              ratio=ratio)))
    return out


def _formula(text: str) -> str:
    """A file's formula as the books print it: ``9500*sin(2*theta)`` as 9500·sin(2θ)."""
    import re

    text = re.sub(r"(\d)\s*\*\s*theta", r"\1θ", text).replace("theta", "θ")
    return text.replace("*", "·").replace("-", "−")


def _punch_lines(ex) -> list[Line]:
    """A punch as the file gives it: the energy a hole (or per unit of sheared area, the hole
    and plate), how often, how long the punching takes, its losses, each in the file's
    units."""
    length = unit_words(ex.length_unit)
    out = []
    for key, value in ex.punch.given:
        text, unit = _PUNCH[key]
        unit = {"length": length, "area": unit_words(f"J/{ex.length_unit}²")}.get(unit, unit)
        said = (math_text(number(value)) + (f" {unit_words(unit)}" if unit else "")
                if isinstance(value, (int, float)) else math_text(str(value)))
        out.append(Line(words(text, v=said)))
    return out


_PUNCH = {"energy": ("the energy a hole takes {v}", "J"),
          "energy_per_area": ("the energy per unit of sheared area {v}", "area"),
          "hole": ("the hole's diameter {v}", "length"),
          "plate": ("the plate's thickness {v}", "length"),
          "holes_per_hour": ("{v} holes an hour", ""),
          "holes_per_minute": ("{v} holes a minute", ""),
          "period": ("a hole every {v}", "s"),
          "power": ("the motor's power {v}", "W"),
          "punching_time": ("each punching takes {v}", "s"),
          "punching_fraction": ("each punching takes {v} of the time between holes", ""),
          "losses": ("frictional losses {v} of the punching work", ""),
          "efficiency": ("the punch's efficiency {v}", "")}
"""How the sheet states each of a punch's keys, and the unit its number is in."""


# ----- what is asked -------------------------------------------------------------------------
def _asked_flywheel(ex, sol) -> list[Line]:
    """What the solve finds, each asked once in the course's words; the numbers the file gives
    (its speeds, its flywheel) are not asked."""
    out = [Line(words("Find"), heading=True)]
    given = ({"speed_max", "speed_min"} if ex.extremes_given else
             {"speed_max"} if ex.speed_max is not None else set())
    if ex.inertia is not None or ex.mass is not None:
        given.add("inertia")
    keys = [k for k in sol.checked if k not in given and k in _ASKED]
    for key in keys:
        pair = next((p for p in _PAIRS if key in p), None)
        if pair is None:
            out.append(Line(words(_ASKED[key])))
        elif key == pair[0]:
            both = pair[1] in keys
            out.append(Line(words(_PAIRS[pair] if both else _ASKED[key])))
        elif pair[0] not in keys:
            out.append(Line(words(_ASKED[key])))
    for theta in ex.at:
        out.append(Line(words("the turning moment and the shaft's acceleration at {theta}",
                              theta=math_text(f"θ = {number(math.degrees(theta))}°"))))
    return out


# ----- a connecting rod -------------------------------------------------------------------------
def _rod_sheets(ex, sheet: tuple[float, float]) -> list[Figure]:
    """A rod's sheet: the rod along its line of centres, its pins, G and its lengths given, as
    the solution draws it but with none of its rows of masses, and what is asked."""
    from tarsim.graphics.forces.rod_figure import rod_figure

    # k is given only where the file gives it; one found by a pendulum test is an answer
    rod = ex.rod if ex.pendulum is None else replace(ex.rod, inertia=0.0)
    drawing = rod_figure(SimpleNamespace(exercise=replace(ex, rod=rod, find=())))
    statement = draw_statement(_given_rod(ex) + _asked_rod(ex))
    return compose_handout(words("{name}: {what}", name=ex.name, what=words("problem sheet")),
                           [drawing, statement], sheet=sheet)


def _given_rod(ex) -> list[Line]:
    from tarsim.constructions.units import LENGTH_UNITS

    metre, unit = LENGTH_UNITS[ex.length_unit], unit_words(ex.length_unit)
    rod, (p, a) = ex.rod, ex.ends
    out = [Line(words("Given"), heading=True),
           Line(words("mass {m} kg", m=math_text(f"m = {number(rod.mass)}"))),
           Line(words("{l} between the pins' centres", l=math_text(
               f"{p}{a} = {number(rod.length / metre)}") + f" {unit}")),
           Line(math_text(f"G{p} = {number(rod.to_gudgeon / metre)}") + f" {unit}")]
    if ex.pendulum is not None:
        period, below, pin, knife = ex.pendulum
        out.append(Line(words("hung from {pin}, it swings with a period of {t} s",
                              pin=pin, t=math_text(number(period)))))
    elif rod.inertia > 0:
        k = math.sqrt(rod.inertia / rod.mass)
        out.append(Line(words("radius of gyration about G: {k}", k=math_text(
            f"k = {number(k / metre)}") + f" {unit}")))
    if ex.alpha is not None:
        out.append(Line(words("the rod's angular acceleration {alpha}", alpha=math_text(
            f"α = {number(abs(ex.alpha))}") + " rad/s² "
            + words("ccw" if ex.alpha > 0 else "cw"))))
    return out


def _asked_rod(ex) -> list[Line]:
    p, a = ex.ends
    out = [Line(words("Find"), heading=True)]
    out += [Line(words(_ROD_ASKED[f], pin=ex.one_mass_at, p=p, a=a))
            for f in ex.find if f in _ROD_ASKED]
    out += [Line(words(f.replace("_", " "))) for f in ex.find if f not in _ROD_ASKED]
    return out
