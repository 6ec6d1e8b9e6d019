"""Read a flywheel exercise: a turning-moment diagram (``[turning_moment]``) and what is
asked of its flywheel (``[flywheel]``).

The diagram is given one of three ways, as the books give it:

- ``torque = "20000 + 9500*sin(2*theta) - 5700*cos(2*theta)"``, T in N·m, θ the crank
  angle in radians (:mod:`~tarsim.constructions.forces.torque_formula`);
- ``points = [[0, 0], [30, 2100], …]``, (crank angle in degrees, T in N·m) joined by straight
  lines over the cycle;
- ``areas = [295, -685, …]``, the areas above (+) and below (−) the mean line in order, with
  the diagram's scales ``torque_scale`` (N·m per length unit of the drawing) and
  ``angle_scale`` (degrees per length unit), or ``energy_scale`` (J per unit of area).

A machine's torque (a punch's, a press's) against a driver steady at its mean is given the
same way as ``[resisting_torque]`` (a formula or a table); an engine's ``[turning_moment]``
formula beside a machine's ``[resisting_torque]`` formula, their means equal, drives the
flywheel by the net T − R. A table may jump: an angle given
twice, or a last point a cycle on from the first with another T.
``cycle`` (degrees, 360 by default) is how far the crank turns before the diagram repeats.
``[flywheel]`` gives the mean ``speed`` (or one of ``speed_max`` and ``speed_min`` alone,
with the flywheel: the other from ΔE = ½I(ω1² − ω2²)) and either ``speed_fluctuation``
(C_s: the flywheel is found, and a rim's ``mass`` at a stated ``radius`` or its ``radius``
for a stated ``mass``; a ``radius_of_gyration`` alone is where its mass sits) or the flywheel
(``inertia``, or ``mass`` with ``radius_of_gyration``: C_s is found); ``at`` lists crank
angles (degrees) whose T and α are asked. C_s may be written as the books write it ("±1 %",
"2 %"), or given by the greatest and least speeds (two of ``speed``,
``speed_max`` and ``speed_min``); a rim's ``diameter`` may stand for its radius, and its
``density`` with ``width_to_thickness`` asks its section, or with its allowable
``hoop_stress`` sets its speed √(σ/ρ). A length may carry its own unit ("0.6 m"). Every
failure is one line naming file:line.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

from tarsim.constructions.forces.flywheel import Diagram, Punch
from tarsim.constructions.forces.torque_formula import Formula, parse_formula
from tarsim.constructions.reference.flywheel import integrated
from tarsim.constructions.units import LENGTH_UNITS
from ..names import named_in, read_names, renamed_field
from ..table_file import SPEEDS, Tables
from .flywheel_engine import ENGINE_KEYS, read_engine, summed
from .flywheel_wheel import read_given_wheel, read_wheel
from .punch_file import POWERS, PUNCH_KEYS, read_punch

__all__ = ["FlywheelExercise", "parse_flywheel"]

_TOP = ("name", "names", "source", "description", "units", "turning_moment",
        "resisting_torque", "punch", "flywheel")
_KEYS = {"turning_moment": ("torque", "points", "areas", "torque_scale", "angle_scale",
                            "energy_scale", "cycle", *ENGINE_KEYS),
         "resisting_torque": ("torque", "points", "cycle"),
         "punch": PUNCH_KEYS,
         "flywheel": ("speed", "speed_max", "speed_min", "speed_fluctuation", "inertia", "mass",
                      "radius", "diameter", "rim_speed", "rim_share", "density",
                      "width_to_thickness", "hoop_stress",
                      "radius_of_gyration", "at", "delta_E")}


@dataclass(frozen=True)
class FlywheelExercise:
    """A turning-moment diagram and what is asked of its flywheel (SI: rad, N·m, J, kg, m)."""

    chapter: ClassVar[str] = "forces"

    id: str
    name: str
    source: str
    description: str
    cycle: float
    """How far the crank turns before the diagram repeats (rad)."""
    formula: Formula | None = None
    machine: Formula | None = None
    """The machine's resisting torque R(θ), when the engine's T(θ) is given beside it: the
    net T − R drives the flywheel."""
    machine_mean: float = 0.0
    """R's mean over the cycle (N·m): the diagram is T − R + R_mean, its mean the engine's."""
    points: tuple[tuple[float, float], ...] = ()
    """A table's (θ rad, T N·m), in order over the cycle; an angle twice is a jump, and a
    last point a cycle on from the first a jump back to it."""
    punch: Punch | None = None
    """A punching press given by its energy and times; its areas are the flywheel's."""
    resisting: bool = False
    """The diagram is a machine's resisting torque, the driver steady at its mean (a punch,
    a press); otherwise it is the driving torque, the resistance steady."""
    areas: tuple[float, ...] = ()
    """The areas as energies (J), + above the mean, in order."""
    drawn_areas: tuple[float, ...] = ()
    """The areas as the file gives them, in the drawing's units of area."""
    energy_scale: float = 0.0
    """J per unit of the drawing's area."""
    area_scales: tuple[float, float] | None = None
    """The drawing's torque scale (N·m a length unit) and angle scale (degrees a length unit)
    where the file gives them, not its energy_scale."""
    speed: float | None = None
    """The mean speed (rad/s)."""
    speed_fluctuation: float | None = None
    speed_max: float | None = None
    """The greatest speed given alone (rad/s), as the books give a press's speed before it
    punches: the least follows from the flywheel and ΔE."""
    speed_min: float | None = None
    """The least speed given alone (rad/s): the greatest follows as ``speed_max``'s least."""
    inertia: float | None = None
    """The flywheel's moment of inertia (kg·m²), when given."""
    mass: float | None = None
    radius: float | None = None
    radius_of_gyration: float | None = None
    rim_share: float = 1.0
    """The part of the flywheel's I its rim gives, the hub and arms the rest."""
    rim_speed: float | None = None
    """The rim's mean speed (m/s), when the books give it: its radius v/ω and mass
    ΔE/(C_s·v²)."""
    hoop_stress: float | None = None
    """The rim's allowable hoop stress σ (Pa), when the books size it so: v = √(σ/ρ)."""
    density: float | None = None
    """The rim's density (kg/m³): with ``width_to_thickness``, its section is asked."""
    width_to_thickness: float | None = None
    at: tuple[float, ...] = ()
    """Crank angles (rad) whose T and α are asked."""
    delta_e_given: float | None = None
    """ΔE given (J), a file with no diagram: the flywheel or C_s is found from it."""
    power: float | None = None
    """The engine's power given (W): its work a cycle, P·cycle/ω, with ``energy_coefficient``
    or shared among its ``strokes``."""
    energy_coefficient: float | None = None
    """C_E given: ΔE = C_E × the work done in a cycle."""
    strokes: tuple[float, ...] = ()
    """Each stroke's work (J), the cycle shared equally, each a triangle in the ``points``."""
    phases: tuple[float, ...] = ()
    """Each cylinder's lag behind the first (rad), the diagram the sum of theirs; () one."""
    single: tuple[tuple[float, float], ...] = ()
    """One cylinder's table, before the cylinders' are added (``points`` is the sum)."""
    extremes_given: tuple[float, float] | None = None
    """The greatest and least speeds (rad/s) C_s was found from, where the file gave them."""
    length_unit: str = "m"
    speed_unit: str = "rad/s"
    names: tuple[tuple[str, str], ...] = ()
    paper: str = "A4"
    """The sheet its figures are drawn for and set on (``graphics.paper.PAPERS``),
    as ``--paper`` sets it."""

    def named_in(self, lang: str) -> FlywheelExercise:
        """The same exercise named in ``lang``, if its file does."""
        return named_in(self, lang)

    renamed = renamed_field

    @property
    def diagram(self) -> Diagram | None:
        """T(θ) over the cycle; None for a diagram given by its areas."""
        cycle = self.cycle
        # A formula is the diagram over one cycle, repeated: sin(θ/2) over a turn is not
        # periodic by itself, and a search about θ = 0 must find the cycle's end there.
        if self.machine is not None:
            engine, machine, mean = self.formula, self.machine, self.machine_mean
            return Diagram(lambda theta: engine(theta % cycle) - machine(theta % cycle) + mean,
                           cycle)
        if self.formula is not None and self.phases:
            formula, phases = self.formula, self.phases
            return Diagram(lambda theta: math.fsum(formula((theta - lag) % cycle)
                                                   for lag in phases), cycle)
        if self.formula is not None:
            formula = self.formula
            return Diagram(lambda theta: formula(theta % cycle), cycle)
        if self.points:
            return Diagram(_straight(self.points, self.cycle), self.cycle,
                           tuple(t for t, _ in self.points))
        return None

    @property
    def jumps(self) -> bool:
        """Whether the table jumps (an angle given twice, or a last point a cycle on): its
        diagram is then read at its points (:func:`~...forces.flywheel.read_table`)."""
        ts = [t for t, _ in self.points]
        return len(set(ts)) < len(ts) or bool(ts) and ts[-1] >= ts[0] + self.cycle * (1 - 1e-12)


def _straight(points: tuple[tuple[float, float], ...], cycle: float):
    """T(θ) straight between the table's points, the last joined to the first a cycle on;
    at a jump, T is the value after it."""
    ts = [t for t, _ in points]
    vs = [v for _, v in points]
    if ts[-1] < ts[0] + cycle * (1 - 1e-12):
        ts.append(ts[0] + cycle)
        vs.append(vs[0])

    def torque(theta: float) -> float:
        x = (theta - ts[0]) % cycle + ts[0]
        for i in range(len(ts) - 1):
            if ts[i] <= x < ts[i + 1]:
                f = (x - ts[i]) / (ts[i + 1] - ts[i])
                return vs[i] + f * (vs[i + 1] - vs[i])
        return vs[-1]           # a cycle on, rounded up from just before it: the last value
    return torque


def parse_flywheel(text: str, filename: str = "<string>", exercise_id: str = "flywheel",
                   data: dict[str, Any] | None = None) -> FlywheelExercise:
    """Parse a flywheel exercise from TOML text; ``data``, the tables already parsed, spares
    a second parse.

    Raises
    ------
    InputError
        Naming file:line and what to fix.
    """
    t = Tables.read(text, filename, "flywheel", _TOP, _KEYS, data)
    fail = t.fail
    tables = [k for k in ("turning_moment", "resisting_torque", "punch") if k in t.data]
    length, speed_unit = _units(t, "punch" in tables)
    if tables == ["turning_moment", "resisting_torque"]:
        return _engine_and_machine(t, filename, exercise_id, length, speed_unit)
    if not tables and "flywheel" in t.data:
        return _exercise(t, filename, exercise_id, 2 * math.pi, length, speed_unit, {})
    if len(tables) != 1:
        raise fail("a flywheel file gives its diagram as [turning_moment] torque = \"…\", "
                   "points = [[θ°, T], …] or areas = […] with the diagram's scales, or a "
                   "machine's [resisting_torque] against a steady driver, or a [punch]: one "
                   "of them", tables[1] if tables else "flywheel")
    (table,) = tables
    if table == "punch":
        return _exercise(t, filename, exercise_id, 2 * math.pi, length, speed_unit,
                         read_punch(t, _one(t, "punch"), LENGTH_UNITS[length]))
    tm = _one(t, table)
    cycle_deg = t.number(tm, "cycle", table, "the cycle (degrees)", 0, 360.0)
    if not 0 < cycle_deg <= 1440:
        raise fail(f"the cycle is how far the crank turns before the diagram repeats, in "
                   f"degrees (360 a turn, 720 a four-stroke engine's), got {cycle_deg:g}",
                   table, "cycle")
    cycle = math.radians(cycle_deg)
    engine = (read_engine(t, tm, cycle_deg, SPEEDS[speed_unit])
              if table == "turning_moment" else {})
    if "energy_coefficient" in engine:
        return _exercise(t, filename, exercise_id, cycle, length, speed_unit, engine)
    if "strokes" in engine:
        tm = tm | {"points": None}          # the strokes' triangles are the table
    given = [k for k in ("torque", "points", "areas") if k in tm]
    if len(given) != 1:
        raise fail(f"[{table}] gives one of torque = \"…\" (a formula in theta), points = "
                   "[[θ°, T], …]" + (" or areas = […]" if table == "turning_moment" else "")
                   + (f", not {' and '.join(given)}" if given else ""), table,
                   given[1] if len(given) > 1 else None)
    diagram: dict[str, Any] = {"resisting": table == "resisting_torque"}
    if "torque" in tm:
        try:
            diagram["formula"] = parse_formula(tm["torque"])
        except ValueError as e:
            raise fail(str(e), table, "torque") from None
    elif "strokes" in engine:
        diagram["points"] = engine["points"]
    elif "points" in tm:
        diagram["points"] = _points(t, tm["points"], cycle_deg, table)
    else:
        diagram.update(_areas(t, tm))
    diagram |= {k: engine[k] for k in ("power", "strokes") if k in engine}
    if "phases" in engine:
        diagram |= _cylinders(t, diagram, engine["phases"], cycle)
    if "areas" not in tm:
        for k in ("torque_scale", "angle_scale", "energy_scale"):
            if k in tm:
                raise fail(f"{k} is a scale of a diagram given by its areas; a diagram given as "
                           "T(θ) needs none: remove it", "turning_moment", k)
    return _exercise(t, filename, exercise_id, cycle, length, speed_unit, diagram)


def _cylinders(t: Tables, diagram: dict, phases: tuple[float, ...],
               cycle: float) -> dict[str, Any]:
    """The cylinders' diagrams added: a table's sum as a table (one cylinder's kept for the
    figure), a formula's as its phases."""
    if "areas" in diagram:
        raise t.fail("cylinders add diagrams given as T(θ), a formula or points; a diagram "
                     "given by its areas cannot be set off by a crank angle", "turning_moment",
                     "cylinders" if "cylinders" in t.data["turning_moment"] else "phases")
    if "formula" in diagram:
        return {"phases": phases}
    one = diagram["points"]
    ts = [a for a, _ in one]
    if len(set(ts)) < len(ts) or ts[-1] >= ts[0] + cycle * (1 - 1e-12):
        raise t.fail("cylinders add tables that run straight between their points; one that "
                     "jumps (an angle twice, or a last point a cycle on) is not added: give "
                     "the summed table", "turning_moment", "points")
    return {"points": summed(one, _straight(one, cycle), phases, cycle), "single": one,
            "phases": phases}


def _units(t: Tables, punch: bool) -> tuple[str, str]:
    """The file's length and speed units. A unit it would not read is refused, lest "kW"
    leave a power read as W: [units] takes length and speed, and power (W, kW or MW) for a
    [punch]'s motor."""
    units = t.units("m", "rad/s")
    tm = t.data.get("turning_moment")
    powered = punch or isinstance(tm, dict) and "power" in tm
    for key, unit in t.data.get("units", {}).items():
        if key not in ("length", "speed") and not (key == "power" and unit in POWERS
                                                   and powered):
            raise t.fail("a flywheel file's [units] takes length, speed and, for a [punch]'s "
                         f"motor, power (W, kW or MW); not {key} = {unit!r:.20}", "units", key)
    return units


def _engine_and_machine(t: Tables, filename: str, exercise_id: str, length: str,
                        speed_unit: str) -> FlywheelExercise:
    """An engine's turning moment T(θ) and a machine's resisting torque R(θ), each a formula:
    the net T − R drives the flywheel, so the exercise is read as the diagram T − R + R_mean
    (its areas those of T − R, its mean the engine's). Over a cycle the two must do equal
    work: their means must agree."""
    formulas = {}
    for table in ("turning_moment", "resisting_torque"):
        tm = _one(t, table)
        extra = [k for k in tm if k not in ("torque", "cycle")]
        if "torque" not in tm or extra:
            raise t.fail("an engine's [turning_moment] beside a machine's [resisting_torque] "
                         "gives each as torque = \"…\" (a formula in theta) and cycle alone",
                         table, extra[0] if extra else None)
        try:
            formulas[table] = parse_formula(tm["torque"])
        except ValueError as e:
            raise t.fail(str(e), table, "torque") from None
    cycles = [t.number(_one(t, k), "cycle", k, "the cycle (degrees)", 0, 360.0)
              for k in formulas]
    if cycles[0] != cycles[1] or not 0 < cycles[0] <= 1440:
        raise t.fail(f"the engine's and the machine's torques repeat over one cycle, in degrees "
                     f"(360 a turn, at most 1440): got {cycles[0]:g} and {cycles[1]:g}",
                     "resisting_torque", "cycle")
    cycle = math.radians(cycles[0])
    engine, machine = formulas["turning_moment"], formulas["resisting_torque"]
    means = [integrated(f, cycle).mean for f in (engine, machine)]
    size = max(abs(f(k * cycle / 360)) for f in (engine, machine) for k in range(360))
    # The quadrature is exact to rounding on a book's harmonics; the books' means are
    # written to their last figure, so a difference past rounding is a different mean.
    if abs(means[0] - means[1]) > 1e-9 * max(size, 1.0):
        raise t.fail(f"the engine's mean torque {means[0]:.6g} N·m differs from the machine's "
                     f"{means[1]:.6g} N·m: over a cycle they must balance", "resisting_torque",
                     "torque")
    return _exercise(t, filename, exercise_id, cycle, length, speed_unit,
                     {"formula": engine, "machine": machine, "machine_mean": means[1]})


def _exercise(t: Tables, filename: str, exercise_id: str, cycle: float, length: str,
              speed_unit: str, diagram: dict[str, Any]) -> FlywheelExercise:
    """The exercise of ``diagram`` (however the file gave it) with its texts, names and
    what its ``[flywheel]`` table gives and asks."""
    wheel = _flywheel(t, LENGTH_UNITS[length], SPEEDS[speed_unit], diagram)
    return FlywheelExercise(
        id=exercise_id, name=_text(t, "name", exercise_id), source=_text(t, "source", ""),
        description=_text(t, "description", ""), cycle=cycle, length_unit=length,
        speed_unit=speed_unit, names=read_names(t.data, t.where, filename), **diagram, **wheel)


def _one(t: Tables, table: str) -> dict:
    entries = t.entries(table)
    if len(entries) != 1:
        raise t.fail(f"[{table}] is one table, not a list of {len(entries)}", table, None,
                     min(len(entries) - 1, 1))
    return entries[0]


def _text(t: Tables, key: str, default: str) -> str:
    v = t.data.get(key, default)
    if not isinstance(v, str) or any(ord(c) < 32 and c not in "\n\t" for c in v):
        raise t.fail(f"{key} must be text with no control character", key=key)
    return v


def _points(t: Tables, raw: Any, cycle_deg: float,
            table: str = "turning_moment") -> tuple[tuple[float, float], ...]:
    """A table's points, each [θ°, T N·m], in increasing θ within one cycle. An angle given
    twice is a jump, from the first T to the second (a punch that starts or stops); a last
    point a cycle on from the first closes the cycle, and jumps back to the first's T if it
    differs (it is kept then, the table's last straight line ending on it)."""
    if not isinstance(raw, list) or len(raw) < 3:
        raise t.fail("points lists 3 or more [crank angle°, T N·m] pairs over the cycle",
                     table, "points")
    out, degrees = [], []
    for i, p in enumerate(raw):
        if not (isinstance(p, list) and len(p) == 2):
            raise t.fail(f"point {i + 1} must be [crank angle°, T N·m], got {p!r:.40}",
                         table, "points")
        theta = t.number({"p": p[0]}, "p", table, f"point {i + 1}'s angle")
        torque = t.number({"p": p[1]}, "p", table, f"point {i + 1}'s torque")
        if degrees and (theta < degrees[-1] or theta == degrees[-1] and (
                len(degrees) > 1 and degrees[-2] == theta or i == 1)):
            raise t.fail(f"point {i + 1}'s angle {theta:g}° must be past the one before it "
                         "(or the same once, a jump, after the first)", table, "points")
        out.append((math.radians(theta), torque))
        degrees.append(theta)
    span = degrees[-1] - degrees[0]
    if span >= cycle_deg:
        if abs(span - cycle_deg) > 1e-9 * cycle_deg:
            raise t.fail(f"the points span {span:g}°, past the cycle of {cycle_deg:g}°: give "
                         "one cycle (a last point a cycle on from the first closes it)",
                         table, "points")
        # The point a cycle on from the first: the same T closes the cycle as a straight
        # line would, so it is dropped; another T is a jump back to the first's, and stays.
        out[-1] = (out[0][0] + math.radians(cycle_deg), out[-1][1])
        if out[-1][1] == out[0][1]:
            out.pop()
    if len(set(degrees) - {degrees[0] + cycle_deg}) < 2:
        raise t.fail("points gives T at two or more crank angles in the cycle", table, "points")
    return tuple(out)


def _areas(t: Tables, tm: dict) -> dict[str, Any]:
    """The areas as energies, from the diagram's scales."""
    raw = tm["areas"]
    if not isinstance(raw, list) or len(raw) < 2:
        raise t.fail("areas lists the areas above (+) and below (−) the mean line in order, two "
                     "or more", "turning_moment", "areas")
    drawn = tuple(t.number({"a": a}, "a", "turning_moment", f"area {i + 1}")
                  for i, a in enumerate(raw))
    for i, a in enumerate(drawn):
        if a == 0 or (i and (a > 0) == (drawn[i - 1] > 0)):
            raise t.fail(f"area {i + 1} ({a:g}) must be nonzero and of the other sign from the "
                         "one before it: the areas alternate above (+) and below (−) the mean",
                         "turning_moment", "areas")
    if "energy_scale" in tm:
        if "torque_scale" in tm or "angle_scale" in tm:
            raise t.fail("give energy_scale (J per unit of area), or torque_scale and "
                         "angle_scale, not both", "turning_moment", "energy_scale")
        scale = t.number(tm, "energy_scale", "turning_moment", "the energy scale")
    else:
        missing = [k for k in ("torque_scale", "angle_scale") if k not in tm]
        if missing:
            raise t.fail("a diagram given by its areas needs its scales: torque_scale (N·m per "
                         "length unit of the drawing) and angle_scale (degrees per length unit),"
                         " or energy_scale (J per unit of area)", "turning_moment",
                         None)
        scale = (t.number(tm, "torque_scale", "turning_moment", "the torque scale")
                 * math.radians(t.number(tm, "angle_scale", "turning_moment", "the angle scale")))
    if not scale > 0:
        raise t.fail(f"the diagram's scales must be positive, got {scale:g} J per unit area",
                     "turning_moment", "energy_scale" if "energy_scale" in tm else "torque_scale")
    total, size = math.fsum(drawn), math.fsum(abs(a) for a in drawn)
    # Areas read off a drawing to a few figures: over a cycle they must cancel to about that.
    if abs(total) > 1e-3 * size:
        raise t.fail(f"the areas add to {total:g}, not 0: over a cycle the areas above the mean "
                     f"line and below it are equal (those above add to "
                     f"{math.fsum(a for a in drawn if a > 0):g}, below to "
                     f"{math.fsum(a for a in drawn if a < 0):g})", "turning_moment", "areas")
    scales = (None if "energy_scale" in tm else
              (t.number(tm, "torque_scale", "turning_moment", "the torque scale"),
               t.number(tm, "angle_scale", "turning_moment", "the angle scale")))
    return {"areas": tuple(a * scale for a in drawn), "drawn_areas": drawn,
            "energy_scale": scale, "area_scales": scales}


def _flywheel(t: Tables, metre: float, rad_s: float, diagram: dict) -> dict[str, Any]:
    """What ``[flywheel]`` gives and asks, in SI (none where the file has no such table).
    With no diagram, ΔE is given (``delta_E``, or C_E with the power), or found from the
    flywheel and its speeds."""
    if "flywheel" not in t.data:
        return {}
    fw = _one(t, "flywheel")
    drawn = any(k in diagram for k in ("formula", "points", "areas", "punch"))
    if "delta_E" in fw and (drawn or "energy_coefficient" in diagram):
        raise t.fail("delta_E is given where no diagram gives it; here ΔE is found: leave it "
                     "out", "flywheel", "delta_E")
    if drawn:
        return read_wheel(t, fw, metre, rad_s, diagram)
    if "delta_E" not in fw and "energy_coefficient" not in diagram:
        return read_given_wheel(t, fw, metre, rad_s)
    out = read_wheel(t, fw, metre, rad_s, diagram)
    if "inertia" not in out and "speed_fluctuation" not in out:
        raise t.fail("with ΔE known, give speed_fluctuation (or the greatest and least speeds: "
                     "the flywheel is found) or the flywheel (inertia, or mass with "
                     "radius_of_gyration: its C_s is found)", "flywheel", None)
    if "energy_coefficient" in diagram:
        return out
    delta_e = t.number(fw, "delta_E", "flywheel", "the greatest fluctuation of energy (J)")
    if not delta_e > 0:
        raise t.fail(f"delta_E is the greatest fluctuation of energy, positive, got {delta_e:g}",
                     "flywheel", "delta_E")
    return out | {"delta_e_given": delta_e}
