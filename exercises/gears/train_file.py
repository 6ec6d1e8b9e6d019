"""Read a gear-train exercise (TOML with ``[[gear]]`` tables) into the exact model.

The format is documented in docs/howto/gears.md. Tooth counts are whole numbers and
speeds and modules are read exactly (a decimal as written, ``0.5`` as 1/2), so the tabular
method's fractions are the notes' own. Every failure is one line naming file:line.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from fractions import Fraction
from typing import Any, ClassVar

from tarsim.constructions.asks import symbol
from tarsim.constructions.errors import InputError
from tarsim.constructions.gears.chain import mesh_chain
from tarsim.constructions.gears.involute import Involute, check_mesh
from tarsim.constructions.gears.teeth import teeth_from_diameter
from tarsim.constructions.gears.torques import implied_output
from tarsim.constructions.gears.train import Gear, GearTrain, SpeedUnits
from tarsim.constructions.gears.twins import fold_twins
from tarsim.constructions.narration import Phrase, phrase
from tarsim.constructions.units import LENGTH_UNITS
from ..file_numbers import RANGE, _float, arithmetic, in_range
from ..toml_source import SourceMap, read_toml
from ..names import named_in, read_names
from .train_inputs import _POWERS, InputTables, _shown
from .train_meshes import MeshTables
from .train_teeth import TeethTables

__all__ = ["TrainExercise", "parse_train"]

_TOP = ("name", "names", "source", "description", "fixed", "efficiency", "coaxial", "ratio",
        "units", "gear", "arm", "mesh", "shaft", "input", "road", "involute", "ask")
MESH_ASKS = ("contact_ratio", "path_of_contact", "arc_of_contact", "pressure_angle",
             "circular_pitch", "interference", "least_teeth")
"""What the involute mesh answers (with ``[involute]``)."""
_SPEEDS = ("rpm", "rad/s")
_PITCHES = ("module", "diametral_pitch", "circular_pitch")
"""The three ways a gear's tooth size is given: m, P = 1 in/m, p = π·m."""


@dataclass(frozen=True)
class TrainExercise:
    """A gear train and what is asked of it: speeds ``omega<n>``, ratios
    ``omega<a>/omega<b>``."""

    chapter: ClassVar[str] = "gears"
    id: str
    train: GearTrain
    asks: tuple[str, ...]
    description: str = ""
    involute: Involute | None = None
    names: tuple[tuple[str, str], ...] = ()
    """The train's name in other languages (``[names]``, :mod:`.names`)."""
    twins: tuple[tuple[int, int], ...] = ()
    """Identical planets listed as gears, (copy, the planet it turns as): folded into one
    (:mod:`~tarsim.constructions.gears.twins`), asked by their own numbers."""

    listed: GearTrain | None = None
    """The train as listed, every copy a gear, where copies were folded: the Willis
    reference solves it whole (its extra meshes must agree), so each copy's speed is
    checked, not assumed."""
    paper: str = "A4"
    """The sheet its figures are drawn for and set on (``graphics.paper.PAPERS``),
    as ``--paper`` sets it."""

    def member(self, number: int) -> int:
        """The member of the train that a number asked stands for (a copy's planet)."""
        return dict(self.twins).get(number, number)

    @property
    def name(self) -> str:
        """The train's name, as the file gives it."""
        return self.train.name

    def named_in(self, lang: str) -> TrainExercise:
        """The same exercise with the train named in ``lang``, if its file does."""
        return named_in(self, lang)

    def renamed(self, name: str) -> TrainExercise:
        """The same exercise, its train called ``name``."""
        return replace(self, train=replace(self.train, name=name))


def parse_train(text: str, filename: str = "<string>", exercise_id: str = "train",
                data: dict[str, Any] | None = None) -> TrainExercise:
    """Parse a gear-train exercise from TOML text (:func:`tarsim.load` reads a file); ``data``, the
    tables already parsed from it, spares a second parse."""
    data = read_toml(text, filename) if data is None else data
    return _Reader(data, SourceMap(text), filename, exercise_id).read()


class _Reader(InputTables, MeshTables, TeethTables):
    def __init__(self, data: dict[str, Any], where: SourceMap, filename: str, eid: str):
        self.data, self.where, self.filename, self.id = data, where, filename, eid
        self.sized_teeth: list[Phrase] = []      # the steps that found teeth by N = d/m
        self.from_diameter: list[int] = []
        self.road_said: list[Phrase] = []        # the road wheels' speeds from [road]

    def fail(self, message: str, table: str | None = None, key: str | None = None,
             index: int = 0) -> InputError:
        line = (self.where.key(key, table or None, index) if key else None) or (
            self.where.header(table, index) if table else None)
        return InputError(message, file=self.filename, line=line,
                          key=f"{table}.{key}" if table and key else table or key)

    def read(self) -> TrainExercise:
        for k in self.data:
            if k not in _TOP:
                raise self.fail(f"unknown table or setting '{k}' in a gear-train file; expected "
                                f"{', '.join(_TOP)}", key=k)
        units = self.units()
        gears = self.gears(units)
        arm, arm_name, planets = self.arm()
        meshes = self.meshes(units, gears)
        shafts = self.shafts()
        fixed = self.fixed()
        member, speed, second = self.inputs(units)
        torque, power = self.load(speed is not None)
        implied = [g.number for g in gears if g.teeth is None]
        train = GearTrain(gears, meshes, shafts, arm, arm_name, fixed, member,
                          Fraction(1) if speed is None else speed, units, planets, torque,
                          power, self.text("name") or self.id, self.filename,
                          speed_given=speed is not None, second=second,
                          efficiency=self.efficiency())
        try:
            train.check_names()
            train = self.teeth(train, implied)
            arm_table = self.data.get("arm")
            listed = train
            train, twins, said = fold_twins(train, isinstance(arm_table, dict)
                                            and "planets" in arm_table)
            train = replace(train, implied=(*self.road_said, *train.implied, *said))
            train.check()
        except InputError as e:
            raise self.placed(e) from None
        involute = self.involute(train)
        self.twins = dict(twins)
        return TrainExercise(self.id, train, self.asks(train, involute),
                             self.text("description"), involute,
                             read_names(self.data, self.where, self.filename), twins,
                             replace(listed, planets=train.planets) if twins else None)

    def placed(self, error: InputError) -> InputError:
        """A check of the whole train, led by the line of the first gear it names (or of
        the arm, or the input); one the reader placed at its own key keeps its line."""
        if error.line is not None:
            return error
        gears = [g.get("number") if isinstance(g, dict) else None
                 for g in self.data.get("gear") or []]
        m = re.search(r"\bgears? (\d+)", error.message)
        line = None
        if m and int(m.group(1)) in gears:
            line = self.where.header("gear", gears.index(int(m.group(1))))
        elif "arm" in error.message and "arm" in self.data:
            line = self.where.header("arm")
        elif "input" in error.message and "input" in self.data:
            line = self.where.header("input")
        else:                 # a member named that is none: where the file names it
            m = re.search(r"\bmember (\d+)", error.message)
            named = int(m.group(1)) if m else None
            if named is not None and named == self.data.get("fixed"):
                line = self.where.key("fixed")
            elif named is not None and named == (self.data.get("input") or {}).get("member"):
                line = self.where.key("member", "input")
        return InputError(error.message, file=self.filename, line=line)

    def known(self, t: dict[str, Any], keys: tuple[str, ...], table: str, index: int = 0
              ) -> None:
        """Refuse a setting ``table`` does not have (a misspelt key is never ignored)."""
        for k in t:
            if k not in keys:
                raise self.fail(f"unknown {table} setting '{k}'; expected "
                                f"{', '.join(keys)}", table, k, index)

    def text(self, key: str) -> str:
        v = self.data.get(key, "")
        if not isinstance(v, str):
            raise self.fail(f"{key} must be text in quotes", key=key)
        return v

    def units(self) -> SpeedUnits:
        t = self.data.get("units", {})
        if not isinstance(t, dict):
            raise self.fail("must be a table: [units] speed = \"rpm\"", table="units")
        self.known(t, ("speed", "length", "power"), "units")
        speed, length = t.get("speed", "rpm"), t.get("length", "mm")
        if t.get("power", "W") not in _POWERS:
            raise self.fail(f"unknown power unit '{t['power']}'; use W or kW", "units", "power")
        if speed not in _SPEEDS:
            raise self.fail(f"unknown speed unit '{speed}'; use rpm or rad/s", "units", "speed")
        if length not in LENGTH_UNITS:
            raise self.fail(f"unknown length unit '{length}'; use "
                            f"{', '.join(LENGTH_UNITS)}", "units", "length")
        return SpeedUnits(speed, length)

    def integer(self, v: Any, what: str, table: str, key: str, index: int = 0) -> int:
        if isinstance(v, bool) or not isinstance(v, int) or v <= 0 or v > 100_000:
            raise self.fail(f"{what} must be a whole number from 1 to 100000, got {_shown(v)}",
                            table, key, index)
        return v

    def exact(self, v: Any, what: str, table: str, key: str, index: int = 0) -> Fraction:
        """A number as written: an integer, a decimal taken at its digits, or arithmetic
        of them in a string ("2/3", "1440/4") at its exact value."""
        exact = arithmetic(v) if isinstance(v, str) else None
        if exact is None and (isinstance(v, bool) or not isinstance(v, (int, float))):
            raise self.fail(f"{what} must be a number, got {_shown(v)}", table, key, index)
        if not in_range(_float(exact if exact is not None else v)):
            raise self.fail(f"{what} must be {RANGE}, got {_shown(v)}", table, key, index)
        if exact is not None:
            return exact
        return Fraction(repr(v)) if isinstance(v, float) else Fraction(v)

    def gears(self, units: SpeedUnits) -> tuple[Gear, ...]:
        raw = self.data.get("gear")
        if not isinstance(raw, list) or not raw:
            raise self.fail("list the gears as [[gear]] tables", key="gear")
        out: list[Gear] = []
        for i, t in enumerate(raw):
            if not isinstance(t, dict):
                raise self.fail("each [[gear]] must be a table", "gear", index=i)
            for k in t:
                if k not in ("number", "name", "teeth", *_PITCHES, "carrier", "diameter"):
                    raise self.fail(f"unknown gear setting '{k}'; expected number, name, teeth, "
                                    "module (or diametral_pitch, circular_pitch), diameter, "
                                    "carrier", "gear", k, i)
            if "number" not in t:
                raise self.fail("a gear needs its number", "gear", index=i)
            n = self.integer(t["number"], "a gear's number", "gear", "number", i)
            if any(g.number == n for g in out):
                raise self.fail(f"gear {n} is listed twice", "gear", "number", i)
            module, pitch = self.module(t, i, units)
            carrier = (self.integer(t["carrier"], "a carrier", "gear", "carrier", i)
                       if "carrier" in t else None)
            name = t.get("name", "")
            if not isinstance(name, str):
                raise self.fail("a gear's name must be text", "gear", "name", i)
            teeth = (self.integer(t["teeth"], "teeth", "gear", "teeth", i) if "teeth" in t
                     else None)
            diameter = None
            if "diameter" in t:
                teeth = self.diameter(t, i, n, teeth, module, units)
                diameter = teeth * module
            out.append(Gear(n, teeth, module, carrier, name, diameter, pitch))
        return tuple(out)

    def module(self, t: dict[str, Any], i: int, units: SpeedUnits
               ) -> tuple[Fraction | None, Fraction | None]:
        """A gear's module (m) by one of the three ways the books size teeth: its module m,
        its diametral pitch P (teeth per inch of diameter, m = 1 in/P) or its circular pitch
        p (the pitch circle's arc a tooth, m = p/π); and the circular pitch (m), where given.
        """
        given = [k for k in _PITCHES if k in t]
        if len(given) > 1:
            raise self.fail(f"give a gear's {' or its '.join(k.replace('_', ' ') for k in given)}"
                            ", not both", "gear", given[1], i)
        if not given:
            return None, None
        key = given[0]
        value = self.exact(t[key], f"a {key.replace('_', ' ')}", "gear", key, i)
        if value <= 0:
            raise self.fail(f"a {key.replace('_', ' ')} must be positive", "gear", key, i)
        if key == "diametral_pitch":     # P teeth per inch of pitch diameter: m = 1 in / P
            return Fraction(254, 10000) / value, None
        value *= Fraction(repr(LENGTH_UNITS[units.length]))
        if key == "circular_pitch":      # p = π·m: m at the float value of π
            return value / Fraction(math.pi), value
        return value, None

    def diameter(self, t: dict[str, Any], i: int, n: int, teeth: int | None,
                 module: Fraction | None, units: SpeedUnits) -> int:
        """Gear ``n``'s teeth from its pitch diameter and module, N = d/m (a step of the
        solution), or its teeth checked against them."""
        d = self.exact(t["diameter"], "a pitch diameter", "gear", "diameter", i)
        if module is None or d <= 0:
            raise self.fail("a pitch diameter gives the teeth with the module: give module = "
                            "… (or a pitch), and a positive diameter", "gear",
                            "diameter", i)
        m = module / Fraction(repr(LENGTH_UNITS[units.length]))     # in the file's unit
        found = teeth_from_diameter(d, m)
        if teeth is not None and found != teeth:
            raise self.fail(f"gear {n}: {teeth} teeth of module {float(m):g} make a pitch "
                            f"diameter of {float(teeth * m):g} {units.length}, not "
                            f"{float(d):g}; give one of them", "gear", "diameter", i)
        if found.denominator != 1 or not 1 <= found <= 100_000:
            raise self.fail(f"gear {n}'s pitch diameter over its module, {float(d):g}/"
                            f"{float(m):g}, is {float(found):g} teeth, not a whole number: "
                            "check the diameter and the module", "gear", "diameter", i)
        if teeth is None:
            self.from_diameter.append(n)
            self.sized_teeth.append(phrase("gears.teeth_diameter", n=n, d=f"{float(d):g}",
                                           m=f"{float(m):g}", unit=units.length,
                                           teeth=int(found)))
        return int(found)

    def arm(self) -> tuple[int | None, str, int]:
        t = self.data.get("arm")
        if t is None:
            return None, "", 1
        if isinstance(t, list):
            raise self.fail("a train here has one arm, [arm] number = …; a train of "
                            "two arms (a two-stage epicyclic) is solved a stage a file, the "
                            "first stage's output speed and torque the second's input", "arm")
        if not isinstance(t, dict) or "number" not in t:
            raise self.fail("the arm needs its number, e.g. number = 3", "arm")
        self.known(t, ("number", "name", "planets"), "arm")
        if not isinstance(t.get("name", ""), str):
            raise self.fail("the arm's name must be text", "arm", "name")
        n = self.integer(t["number"], "the arm's number", "arm", "number")
        planets = self.integer(t.get("planets", 1), "the number of planets", "arm", "planets")
        gears = self.data.get("gear") or []
        if any(isinstance(g, dict) and g.get("number") == n for g in gears):
            raise self.fail(f"member {n} is both a gear and the arm", "arm", "number")
        return n, t.get("name", ""), planets

    def fixed(self) -> int | None:
        v = self.data.get("fixed")
        if v is None:
            return None
        if isinstance(v, list):
            if len(v) == 1:
                v = v[0]
            else:
                raise self.fail(f"{len(v)} fixed members ({', '.join(map(str, v))}): a train "
                                "holds one still", key="fixed")
        return self.integer(v, "the fixed member", "", "fixed")

    def involute(self, train: GearTrain) -> Involute | None:
        """The involute mesh to draw: a meshing pair, driver first, and its tooth form."""
        t = self.data.get("involute")
        if t is None:
            return None
        if not isinstance(t, dict):
            raise self.fail("must be a table: [involute] gears = [2, 3]", "involute")
        for k in t:
            if k not in ("gears", "pressure_angle", "addendum", "dedendum", "centre_distance"):
                raise self.fail(f"unknown involute setting '{k}'; expected gears, "
                                "pressure_angle, addendum, dedendum, centre_distance",
                                "involute", k)
        pair = t.get("gears")
        if not (isinstance(pair, list) and len(pair) == 2 and all(
                isinstance(g, int) and not isinstance(g, bool) for g in pair)):
            raise self.fail("name the meshing pair, driver first: gears = [2, 3]",
                            "involute", "gears")
        for n in pair:
            if n not in [g.number for g in train.gears]:
                raise self.fail(f"there is no gear {n}; the gears are "
                                f"{', '.join(str(g.number) for g in train.gears)}", "involute",
                                "gears")
        angle = float(self.exact(t.get("pressure_angle", 20), "the pressure angle", "involute",
                                 "pressure_angle"))
        if not 5.0 <= angle <= 45.0:
            raise self.fail(f"a pressure angle of {angle:g}° is not a gear's: use 14.5°, 20° "
                            "or 25° (5° to 45°)", "involute", "pressure_angle")
        add, ded = (float(self.exact(t.get(k, v), f"the {k}", "involute", k))
                    for k, v in (("addendum", 1), ("dedendum", 1.25)))
        if not (0 < add <= 2 and add < ded <= 3):
            raise self.fail(f"addendum {add:g} and dedendum {ded:g} (in modules) must satisfy "
                            "0 < addendum ≤ 2 and addendum < dedendum ≤ 3", "involute",
                            "addendum")
        distance = None
        if "centre_distance" in t:
            distance = float(self.exact(t["centre_distance"], "the centre distance",
                                        "involute", "centre_distance")) * LENGTH_UNITS[
                train.units.length]
        mesh = Involute(pair[0], pair[1], angle, add, ded, distance)
        try:
            check_mesh(train, mesh)
        except InputError as e:
            raise self.fail(e.message, "involute", "centre_distance" if distance is not None
                            and "centre distance" in e.message else "gears") from None
        return mesh

    def asks(self, train: GearTrain, involute: Involute | None = None) -> tuple[str, ...]:
        t = self.data.get("ask")
        every = tuple(f"omega{m}" for m in (*train.members, *getattr(self, "twins", {})))
        if t is None:
            return every if train.speed_given else self.ratios(train)
        find = t.get("find") if isinstance(t, dict) else None
        if isinstance(t, dict):
            self.known(t, ("find",), "ask")
        if not (isinstance(find, list) and find and all(isinstance(q, str) for q in find)):
            raise self.fail('give find = [...], such as "omega4" or "omega5/omega2"',
                            "ask", "find")
        torques = tuple(f"{k}{m}" for k in ("torque", "power") for m in train.members)
        for q in find:
            if q in tuple(f"teeth{g.number}" for g in train.gears):
                continue
            if q.startswith("centre_distance"):
                self.distance_asked(train, q)
                continue
            if q in MESH_ASKS:
                if involute is None:
                    raise self.fail(f"cannot find '{q}' without the mesh to draw: give "
                                    "[involute] gears = [2, 3]", "ask", "find")
                continue
            parts = q.split("/")
            if q in torques and train.input_torque is None and train.input_power is None:
                raise self.fail(f"cannot find '{q}' without the input's torque or power: give "
                                "torque = … (N·m) or power = … (W) in [input]", "ask", "find")
            if q not in torques and (len(parts) > 2 or any(p not in every for p in parts)):
                raise self.fail(f"cannot find '{q}' for this train; ask {', '.join(every)}, a "
                                f"ratio such as {every[-1]}/{every[0]}, a torque "
                                f"torque{train.members[-1]}, a power power{train.members[-1]} "
                                f"or teeth{train.gears[0].number}", "ask", "find")
            square = [m for m in parts if m in every and any(
                mesh.bevel and train.carried(int(m.removeprefix("omega"))) and int(
                    m.removeprefix("omega")) in (mesh.a, mesh.b) for mesh in train.meshes)]
            if square:
                raise self.fail(f"cannot find '{q}': gear {square[0].removeprefix('omega')} is a "
                                "bevel planet, turning about an axis square to the main axis, "
                                "so its speed is no speed along it; ask a main-axis member's",
                                "ask", "find")
            if q in every and not train.speed_given:
                raise self.fail(f"cannot find '{q}' without a speed: give speed = … "
                                f"({train.units.speed}) in [input], or ask a ratio such as "
                                f"{q}/omega{train.input_member}", "ask", "find")
            if len(parts) == 2 and train.fixed is not None and int(
                    parts[1].removeprefix("omega")) in train.body(train.fixed):
                held = int(parts[1].removeprefix("omega"))
                raise self.fail(f"{q} divides by the speed of member {held}, which is "
                                + ("fixed" if held == train.fixed else
                                   f"on one shaft with the fixed member {train.fixed}")
                                + "; ask a ratio over a turning member", "ask", "find")
        held = train.fixed if train.second is None else train.second[0]
        loaded = {int(q.removeprefix("torque").removeprefix("power")) for q in find
                  if q in torques}
        loaded -= {train.input_member, held}
        if len(loaded) > 1:
            raise self.fail(f"torques on {len(loaded)} members besides the input and the "
                            + ("fixed one" if train.second is None else "second given one")
                            + ": the balance of power gives one output's", "ask", "find")
        if f"power{held}" in find and train.second is None:
            raise self.fail(f"power{held} is asked of the fixed member {held}, which takes no "
                            "power: ask the power of a turning member", "ask", "find")
        if any(f"{k}{held}" in find for k in ("torque", "power")) and not loaded \
                and implied_output(train) is None:
            raise self.fail(("the fixed member's" if train.second is None else
                             f"member {held}'s") + " holding torque needs the output's: ask "
                            "the output's torque or power too", "ask", "find")
        return tuple(find)

    def distance_asked(self, train: GearTrain, q: str) -> None:
        """Refuse ``centre_distance<a>_<b>`` unless gears a and b mesh and give their
        module (the distance is m(N_a ± N_b)/2 in length)."""
        pair = q.removeprefix("centre_distance").split("_")
        numbers = [int(n) for n in pair if n.isdigit()]
        pairs = [f"centre_distance{m.a}_{m.b}" for m in train.meshes]
        gears = {g.number for g in train.gears}
        if len(numbers) != 2 or len(pair) != 2 or not set(numbers) <= gears or not any(
                {m.a, m.b} == set(numbers) for m in train.meshes) and mesh_chain(
                train, *numbers) is None:
            raise self.fail(f"cannot find '{q}': ask the centre distance of a pair in mesh, "
                            f"{', '.join(pairs)}, or of a simple train's two gears joined "
                            "through idlers", "ask", "find")
        chain = mesh_chain(train, *numbers) or ()
        numbers = sorted({n for m in chain for n in (m.a, m.b)} | set(numbers))
        if any(train.gear(n).module is None for n in numbers):
            raise self.fail(f"{q} needs the module of gears {', '.join(map(str, numbers))}: "
                            "give module = … (mm) or circular_pitch = … in their [[gear]] "
                            "tables", "ask", "find")

    @staticmethod
    def ratios(train: GearTrain) -> tuple[str, ...]:
        """What a file that gives no speed and asks nothing is told: each turning member's
        speed over the input's."""
        still = set(train.body(train.input_member)) | (
            set(train.body(train.fixed)) if train.fixed is not None else set())
        return tuple(f"omega{m}/omega{train.input_member}" for m in train.members
                     if m not in still)


def ask_symbol(name: str) -> str:
    """"omega5/omega2" as the course writes it: ω5/ω2; "torque5" as T5."""
    if name.startswith("torque"):
        return f"T{name.removeprefix('torque')}"
    if name.startswith("power"):
        return f"P{name.removeprefix('power')}"
    if name.startswith("teeth"):
        return f"N{name.removeprefix('teeth')}"
    if name.startswith("centre_distance"):
        return f"C{name.removeprefix('centre_distance')}"
    return "/".join(symbol(p) for p in name.split("/"))
