"""Read a balancing exercise: a rotor (``[rotor]``, ``[[mass]]``, ``[[balance]]``) or an
in-line engine (``[engine]``, ``[[cylinder]]``).

Angles are in degrees, counter-clockwise from the reference radius; radii, crank, rod and
axial positions in the file's length unit; masses in kg; the speed in rpm or rad/s. Every
failure is one line naming file:line.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any, ClassVar

from tarsim.constructions.balancing.rotor import Engine, Mass, Plane, Rotor
from tarsim.constructions.balancing.unknowns import OpenRotor, close_rotor
from tarsim.constructions.units import LENGTH_UNITS
from ..file_numbers import radians_in_turn
from ..toml_source import _CONTROL
from ..names import named_in, read_names, renamed_field
from ..table_file import SPEEDS, Tables
from .engine_unknowns import cylinder_masses, has_unknowns, primary_balance
from .firing_order import firing_cranks, read_firing_order
from .locomotive_file import engine_speed, read_blow_limit, read_wheel
from .one_crank_file import read_radial, read_vee
from .engine_wheels import read_coupled, wheel_rotors
from .open_rotor_file import UNKNOWN, read_open_rotor
from .rotor_discs import Disc, read_disc, refuse_discs
from .rotor_weights import GRAVITY, mass_or_weight, refuse_weights
from .unused_settings import refuse_idle_wheel, refuse_unused

__all__ = ["BalanceExercise", "parse_balance"]

_TOP = ("name", "names", "source", "description", "units", "rotor", "mass", "balance", "engine",
        "cylinder")
_NAME_LENGTH = 12
_NAME = re.compile(rf"^[^\s\x00-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]{{1,{_NAME_LENGTH}}}$")
"""A mass's or a plane's name: a short word with no space or control character in it."""

_UNITS = ("length", "speed")
"""The units a balancing file states; masses are always kg and weights N."""
_KEYS = {"rotor": ("speed", "about", "bearings", "angles"),
         "mass": ("name", "mass", "weight", "density", "diameter", "thickness", "radius", "angle",
                  "plane", "between", "wheels"),
         "balance": ("name", "plane", "radius", "mass", "weight", "bearing"),
         "engine": ("speed", "crank", "stroke", "rod", "reciprocating", "balanced", "at",
                    "revolving", "balance_radius", "balance_mass", "firing_order", "strokes",
                    "road_speed", "wheel_diameter", "vee", "radial", "dead_load", "hammer_blow",
                    "rod_ratio", "coupled"),
         "cylinder": ("crank", "plane", "reciprocating")}


@dataclass(frozen=True)
class BalanceExercise:
    """A rotor to balance, or an engine whose unbalance is asked, and how the file states
    its units."""

    chapter: ClassVar[str] = "balancing"

    id: str
    name: str
    source: str
    description: str
    rotor: Rotor | None = None
    engine: Engine | None = None
    open: OpenRotor | None = None
    """A rotor balanced by its own masses, some of their data unknown ("?")."""
    length_unit: str = "m"
    speed_unit: str = "rad/s"
    speed_default: bool = False
    """The [engine] speed is given with no ``[units] speed``, so read as rad/s (the default),
    and the lines say so."""
    names: tuple[tuple[str, str], ...] = ()
    """The rotor's or engine's name in other languages (``[names]``, :mod:`.names`)."""
    weights: bool = False
    """The file gives its masses as weights in N (:mod:`.rotor_weights`)."""
    discs: tuple[Disc, ...] = ()
    """The masses the file gives as solid discs, by density and size (:mod:`.rotor_discs`)."""
    bearing_planes: tuple[str, ...] = ()
    """The [[balance]] planes the file says are bearings' (``bearing = true``): the force on
    each is then said to be on a bearing, and on a plane elsewhere."""
    clockwise: bool = False
    """The file measures its angles clockwise (``[rotor] angles = "cw"``), as some books do.
    The rotor is then solved as its mirror image, in which every angle given and found reads
    counter-clockwise: the sizes are the same, and each angle found is the clockwise one."""
    trailing: Rotor | None = None
    """A coupled locomotive's other coupled wheels (``[engine] coupled``), balanced in the
    same planes as the driving wheels' ``rotor``: their share of the reciprocating mass and
    the masses on each pair (:mod:`.engine_wheels`)."""
    paper: str = "A4"
    """The sheet its figures are drawn for and set on (``graphics.paper.PAPERS``),
    as ``--paper`` sets it."""

    def named_in(self, lang: str) -> BalanceExercise:
        """The same exercise with its rotor or engine named in ``lang``, if its file does."""
        return named_in(self, lang)

    renamed = renamed_field


def parse_balance(text: str, filename: str = "<string>", exercise_id: str = "rotor",
                  data: dict[str, Any] | None = None) -> BalanceExercise:
    """Parse a balancing exercise from TOML text (:func:`tarsim.load` reads a file); ``data``, the
    tables already parsed from it, spares a second parse."""
    t = Tables.read(text, filename, "balancing", _TOP, _KEYS, data)
    data, fail = t.data, t.fail
    if "rotor" in data and "engine" in data:
        raise fail("a file is a rotor or an engine, not both", "engine")
    if not isinstance(data.get("units", {}), dict):
        raise fail('units is a table: [units] length = "mm", speed = "rpm"', key="units")
    length, speed_unit = t.units("m", "rad/s")
    for key in data.get("units", {}):
        if key not in _UNITS:
            raise fail(f"unknown setting '{key}' in [units]; expected {', '.join(_UNITS)} "
                       "(masses are in kg; a weight in N is weight = …)", "units", key)
    metre = LENGTH_UNITS[length]
    common = dict(id=exercise_id, name=_text(t, "name", exercise_id),
                  source=_text(t, "source", ""), description=_text(t, "description", ""),
                  length_unit=length, speed_unit=speed_unit,
                  speed_default="speed" not in data.get("units", {}) and isinstance(
                      data.get("engine"), dict) and "speed" in data["engine"],
                  names=read_names(data, t.where, filename), clockwise=_clockwise(t))
    if "engine" in data:
        refuse_weights(t, "in an engine's file")
        refuse_discs(t, "in an engine's file")
        _bearing_planes(t, "an engine's wheels")
        engine, primary = _engine(t, metre)
        driving, trailing = (None, None) if primary else wheel_rotors(
            t, _one(t, "engine"), engine, metre, lambda: _planes(t, metre),
            lambda e, i: _name(t, e, "mass", i, f"m{i + 1}", "mass"))
        return BalanceExercise(engine=engine, open=primary, rotor=driving, trailing=trailing,
                               **common)
    if any(v == UNKNOWN for m in t.entries("mass") for v in m.values()):
        refuse_weights(t, "where the masses hold unknowns")
        refuse_discs(t, "where the masses hold unknowns")
        refuse_unused(t, "open")
        return BalanceExercise(open=read_open_rotor(
            t, metre, _speed(t, "rotor", needed=False),
            lambda e, i: _name(t, e, "mass", i, str(i + 1), "mass")), **common)
    refuse_unused(t, "rotor")
    discs: list[Disc] = []
    masses = _masses(t, metre, length, discs)
    planes = _planes(t, metre) if t.entries("balance") else []
    taken = {m.name: f"mass {m.name}" for m in masses}
    for i, p in enumerate(planes):
        if p.name in taken:
            raise fail(f"balancing plane {p.name} has the name of {taken[p.name]}: give each "
                       "mass and plane its own name", "balance", "name", i)
        taken[p.name] = f"plane {p.name}"
    # with no balancing plane the out-of-balance force (N) and couple (N·m) are asked
    speed = _speed(t, "rotor", needed=not planes)
    weights = any("weight" in e for table in ("mass", "balance") for e in t.entries(table))
    return BalanceExercise(rotor=Rotor(tuple(masses), tuple(planes), speed,
                                       _about(t, planes, metre),
                                       _bearings(t, planes, metre, taken)),
                           weights=weights, discs=tuple(discs),
                           bearing_planes=_bearing_planes(t, None, planes), **common)


def _about(t: Tables, planes: list, metre: float) -> float | None:
    """``[rotor] about``: the plane an out-of-balance couple is taken about, where no
    balancing plane is given (a balance takes its couples about plane A)."""
    one = _one(t, "rotor")
    if "about" not in one:
        return None
    if planes:
        raise t.fail("about is where an out-of-balance couple is taken, with no [[balance]] "
                     "planes; a balance takes its couples about plane A: leave it out",
                     "rotor", "about")
    return t.number(one, "about", "rotor", "the reference plane") * metre


def _bearings(t: Tables, planes: list, metre: float, taken: dict[str, str]
              ) -> tuple[tuple[str, float], ...]:
    """``[rotor] bearings = { L = 0, R = 800 }``: the two bearings of a rotor with no
    balancing plane, whose out-of-balance forces are asked (a balance's planes give theirs)."""
    one = _one(t, "rotor")
    if "bearings" not in one:
        return ()
    given = one["bearings"]
    if planes:
        raise t.fail("bearings are asked their forces on a rotor with no [[balance]] planes; a "
                     "balance gives each plane's force (force_A): leave them out", "rotor",
                     "bearings")
    if not (isinstance(given, dict) and len(given) == 2):
        raise t.fail("bearings names the rotor's two bearings and their planes: bearings = "
                     f"{{ L = 0, R = 800 }}, got {given!r:.40}", "rotor", "bearings")
    out = []
    for name in given:
        if not _NAME.match(name) or name in taken:
            raise t.fail(f"bearing {name!r:.20} needs a short name of its own, not a mass's",
                         "rotor", "bearings")
        out.append((name, t.number(given, name, "rotor", f"bearing {name}'s plane") * metre))
    if out[0][1] == out[1][1]:
        raise t.fail("the two bearings stand at the same axial position: they must be apart to "
                     "share a couple", "rotor", "bearings")
    return tuple(out)


def _bearing_planes(t: Tables, refused: str | None, planes: list | None = None
                    ) -> tuple[str, ...]:
    """The names of the [[balance]] planes the file says are bearings' (``bearing = true``),
    read in a rotor's balance; refused, saying ``refused``, where none is read."""
    out = []
    for i, entry in enumerate(t.entries("balance")):
        if "bearing" not in entry:
            continue
        if refused is not None:
            raise t.fail(f"bearing = true says a balancing plane is a bearing's, asked its force; "
                         f"not taken for {refused}: leave it out", "balance", "bearing", i)
        if not isinstance(entry["bearing"], bool):
            raise t.fail(f"bearing says whether the plane is a bearing's: true or false, got "
                         f"{entry['bearing']!r:.20}", "balance", "bearing", i)
        if entry["bearing"]:
            out.append(planes[i].name)
    return tuple(out)


def _clockwise(t: Tables) -> bool:
    """``[rotor] angles``: "ccw" (counter-clockwise, the default) or "cw", the sense the
    file's angles, and so its answers, are measured in."""
    if "rotor" not in t.data:
        return False
    sense = _one(t, "rotor").get("angles", "ccw")
    if sense not in ("ccw", "cw"):
        raise t.fail(f'angles gives the sense the angles are measured in, "ccw" (counter-'
                     f'clockwise, the default) or "cw", got {sense!r:.20}', "rotor", "angles")
    return sense == "cw"


def _one(t: Tables, table: str) -> dict:
    """The single ``[table]``: a list of them is refused at its second."""
    entries = t.entries(table)
    if len(entries) != 1:
        raise t.fail(f"[{table}] is one table, not a list of {len(entries)}", table, None,
                     min(len(entries) - 1, 1))
    return entries[0]


def _speed(t: Tables, table: str, needed: bool = True) -> float | None:
    """``[table]``'s speed in rad/s, positive; None where it is left out and nothing asked
    needs it (``needed``: a force in N, m·r·ω²), refused in one line where something does."""
    one = _one(t, table)
    if "speed" not in one and not needed:
        return None
    if "speed" not in one:      # an engine's is asked for by _engine_speed, with road_speed
        raise t.fail(f"[{table}] needs speed = … (rpm with [units] speed = \"rpm\", else "
                     "rad/s): the out-of-balance force (N) and couple (N·m) are m·r·ω²",
                     table, None)
    v = t.number(one, "speed", table, "the speed")
    if not v > 0:
        raise t.fail(f"the speed must be positive, got {v:g}", table, "speed")
    return v * SPEEDS[t.units("m", "rad/s")[1]]


def _share(t: Tables, one: dict) -> float:
    """The fraction ``balanced`` of the reciprocating mass, as the books give it: a number,
    a fraction ("2/3") or a percentage ("60 %")."""
    v = one.get("balanced", 0.0)
    if isinstance(v, str) and v.strip().endswith("%"):
        return t.number({"balanced": v.strip()[:-1]}, "balanced", "engine",
                        "the balanced percentage") / 100
    return t.number(one, "balanced", "engine", "the balanced fraction", 0, 0.0)


def _text(t: Tables, key: str, default: str) -> str:
    """A free text of the file (its name, source or description): a string with no control
    character in it."""
    v = t.data.get(key, default)
    if not isinstance(v, str):
        raise t.fail(f"{key} must be a string, got {v!r:.40}", key=key)
    bad = _CONTROL.search(v)
    if bad:
        raise t.fail(f"{key} holds the control character U+{ord(bad.group()):04X}; remove it",
                     key=key)
    return v


def _name(t: Tables, entry: dict, table: str, i: int, default: str, what: str) -> str:
    """A mass's or a plane's name: a short word, as the figures write it."""
    v = entry.get("name", default)
    if isinstance(v, int) and not isinstance(v, bool):
        v = str(v)
    if not (isinstance(v, str) and _NAME.match(v)):
        raise t.fail(f"{what} {i + 1}'s name must be a short word such as \"1\" or \"A\" "
                     f"(up to {_NAME_LENGTH} letters or digits), got {v!r:.40}", table, "name", i)
    return v


def _masses(t: Tables, metre: float, length: str, discs: list[Disc]) -> list[Mass]:
    """The rotor's masses; each given as a disc is added to ``discs`` too."""
    masses: list[Mass] = []
    for i, entry in enumerate(t.entries("mass")):
        name = _name(t, entry, "mass", i, str(i + 1), "mass")
        if any(m.name == name for m in masses):
            raise t.fail(f"two masses are named {name}: give each its own name", "mass",
                         "name", i)
        if "between" in entry:
            raise t.fail(f"mass {name}'s between chooses where an unknown angle comes out: give "
                         'its angle = "?", or leave between out', "mass", "between", i)
        disc = read_disc(t, entry, i, name, metre)
        if disc is not None:
            discs.append(disc)
        m, weight = (disc.mass, False) if disc else mass_or_weight(t, entry, "mass", i,
                                                                   f"mass {name}")
        r = t.number(entry, "radius", "mass", f"mass {name}'s radius", i)
        if not m > 0 or not r > 0:
            what = "weight" if weight else "mass"
            raise t.fail(f"mass {name} needs a positive {what} and radius, got "
                         f"{m * (GRAVITY if weight else 1):g} {'N' if weight else 'kg'} at "
                         f"{r:g} {length}", "mass", what if not m > 0 else "radius", i)
        masses.append(Mass(name, m, r * metre,
                           _degrees(t.number(entry, "angle", "mass", f"mass {name}'s angle", i)),
                           t.number(entry, "plane", "mass", f"mass {name}'s plane", i,
                                    0.0) * metre))
    if not masses:
        raise t.fail("list the rotor's masses as [[mass]] tables (mass, radius, angle, plane)",
                     "rotor")
    return masses


def _planes(t: Tables, metre: float) -> list[Plane]:
    planes: list[Plane] = []
    entries = t.entries("balance")
    if not entries:
        raise t.fail("name a balancing plane: [[balance]] with plane = 0 and radius = 0.1 (two "
                     "planes for a dynamic balance)", "rotor")
    if len(entries) > 2:
        raise t.fail("balance in one plane (static) or two (dynamic), not "
                     f"{len(entries)}", "balance", None, 2)
    for i, entry in enumerate(entries):
        name = _name(t, entry, "balance", i, "AB"[i], "balancing plane")
        if any(p.name == name for p in planes):
            raise t.fail(f"two balancing planes are named {name}: give each its own name",
                         "balance", "name", i)
        given = [k for k in ("radius", "mass", "weight") if k in entry]
        if len(given) != 1:
            raise t.fail(f"balancing plane {name} gives the radius its mass goes at, or the "
                         "mass (or its weight in N; the other is found): radius = 0.1",
                         "balance", given[-1] if len(given) > 1 else None, i)
        key = given[0]
        v = t.number(entry, key, "balance", f"plane {name}'s {key}", i)
        if not v > 0:
            raise t.fail(f"balancing plane {name}'s {key} must be positive, got {v:g}",
                         "balance", key, i)
        mass = mass_or_weight(t, entry, "balance", i, f"balancing plane {name}")[0] \
            if key != "radius" else None
        planes.append(Plane(name, t.number(entry, "plane", "balance",
                                           f"plane {name}'s position", i, 0.0) * metre,
                            v * metre if key == "radius" else None, mass))
    if len(planes) == 2 and planes[0].position == planes[1].position:
        raise t.fail(f"the balancing planes {planes[0].name} and {planes[1].name} stand at the "
                     "same axial position: two planes must be apart to hold a couple",
                     "balance", "plane", 1)
    return planes


def _engine(t: Tables, metre: float) -> tuple[Engine, OpenRotor | None]:
    """The engine, and, where its cylinders leave unknowns to a primary balance, the rotor
    whose polygons find them (the engine then the one they complete)."""
    one = _one(t, "engine")
    unit = t.units("m", "rad/s")[0]
    if ("crank" in one) == ("stroke" in one):
        raise t.fail("[engine] gives the crank radius (crank = …) or the stroke (stroke = …, "
                     "twice the crank), one of them", "engine", "stroke" if "crank" in one
                     else None)
    key = "crank" if "crank" in one else "stroke"
    crank = t.number(one, key, "engine", f"the {key}") / (1 if key == "crank" else 2)
    if not crank > 0:
        raise t.fail(f"the {key} must be positive, got {crank:g} {unit}", "engine", key)
    rod = None          # the primary forces need no rod; the secondary ones are its
    if "rod" in one and "rod_ratio" in one:
        raise t.fail("the connecting rod is given by its length (rod = …) or by its ratio to "
                     "the crank (rod_ratio = n), not both", "engine", "rod_ratio")
    if "rod_ratio" in one:          # the books' n = l/r, "the obliquity ratio"
        n = t.number(one, "rod_ratio", "engine", "the connecting rod's ratio to the crank")
        if not n > 1:
            raise t.fail(f"the connecting rod's ratio to the crank, n = l/r, must be more than "
                         f"1, or the piston cannot follow it round; got {n:g}", "engine",
                         "rod_ratio")
        rod = n * crank * metre
    if "rod" in one:
        rod = t.number(one, "rod", "engine", "the connecting rod's length")
        if not rod > crank:
            raise t.fail(f"the connecting rod ({rod:g} {unit}) must be longer than the crank "
                         f"({crank:g} {unit}), or the piston cannot follow it round", "engine",
                         "rod")
        rod *= metre
    balanced = _share(t, one)
    if not 0 <= balanced <= 1:
        raise t.fail(f"the balanced fraction is from 0 to 1, got {balanced:g}", "engine",
                     "balanced")
    vee = read_vee(t, one)
    radial = read_radial(t, one)
    cylinders = t.entries("cylinder") or [{"crank": 0, "plane": 0}]
    refuse_unused(t, "one crank" if vee or radial else "unknowns" if has_unknowns(cylinders)
                  else "single" if len(cylinders) == 1 else "in line", one)
    masses = cylinder_masses(t, one, cylinders)
    if has_unknowns(cylinders):
        # the masses and angles found are free of ω: the speed is asked only by the forces
        if "at" in one and not {"speed", "road_speed"} & set(one):
            raise t.fail("at asks the forces at a crank angle, m·r·ω²: give speed = …, or "
                         "leave at out for the masses and angles alone", "engine", "at")
        primary = primary_balance(t, one, cylinders, masses, crank * metre, metre,
                                  engine_speed(t, one, metre, _speed, optional=True))
        refuse_idle_wheel(t, one)
        found = close_rotor(primary).parts
        each = tuple(found[p.name].mass for p in primary.parts)
        return Engine(tuple(found[p.name].angle for p in primary.parts),
                      tuple(found[p.name].plane for p in primary.parts), crank * metre, rod,
                      max(each), primary.speed, at=_degrees(t.number(
                          one, "at", "engine", "the crank angle", 0, 0.0)),
                      at_given="at" in one, masses=each), primary
    mass = max(masses)
    firing = read_firing_order(t, one, cylinders)
    cranks = tuple(_degrees(d) for d in firing_cranks(*firing)) if firing else tuple(
        _degrees(t.number(c, "crank", "cylinder", f"cylinder {i + 1}'s crank angle", i, 0.0))
        for i, c in enumerate(cylinders))
    planes = tuple(t.number(c, "plane", "cylinder", f"cylinder {i + 1}'s plane", i, 0.0) * metre
                   for i, c in enumerate(cylinders))
    if len(cranks) == 1 and cranks[0] != 0.0:
        raise t.fail("a single cylinder's forces are asked at a crank angle: give it as [engine] "
                     "at = …, its [[cylinder]] crank at 0", "cylinder", "crank")
    for i, p in enumerate(planes):
        if p in planes[:i]:
            j = planes.index(p)
            raise t.fail(f"cylinders {j + 1} and {i + 1} stand in the same plane: cylinders in "
                         "line need their planes apart (plane = …)", "cylinder",
                         "plane" if "plane" in cylinders[i] else None, i)
    revolving, radius, balance = _revolving(t, one, len(cranks), unit)
    if len(set(masses)) > 1 and (t.entries("balance") or len(cranks) == 1 or vee
                                 or radial):
        raise t.fail("cylinders of different reciprocating masses are taken in line, with no "
                     "balance planes: give the mass in [engine] alone", "cylinder",
                     "reciprocating", next(i for i, c in enumerate(cylinders)
                                           if "reciprocating" in c))
    # balance planes find their masses free of ω: a locomotive's speed may be the unknown
    optional = len(cranks) > 1 and bool(t.entries("balance")) and not (vee or radial)
    if optional and "at" in one and not {"speed", "road_speed", "dead_load",
                                         "hammer_blow"} & set(one):
        raise t.fail("at asks the forces at a crank angle, m·r·ω², and no lift speed stands "
                     "in for the speed: give speed = … or road_speed = … (km/h) with "
                     "wheel_diameter", "engine", "at")
    speed = engine_speed(t, one, metre, _speed, optional)
    refuse_idle_wheel(t, one)
    return Engine(cranks, planes, crank * metre, rod, mass, speed,
                  balanced, _degrees(t.number(one, "at", "engine", "the crank angle", 0, 0.0)),
                  revolving, None if radius is None else radius * metre, balance,
                  *read_wheel(t, one, metre, len(cranks)), "at" in one,
                  tuple(masses) if len(set(masses)) > 1 else (),
                  vee, *(firing or ((), 0)), radial=radial, coupled=read_coupled(t, one),
                  hammer_blow=read_blow_limit(t, one, len(cranks))), None


def _revolving(t: Tables, one: dict, cylinders: int, unit: str
               ) -> tuple[float, float | None, float | None]:
    """A cylinder's revolving masses (kg at the crank radius, a number or a list summed:
    crank, crank pin, the rod's revolving part) and a single cylinder's balance mass's
    radius or mass (the other is found), as the file gives them."""
    given = [k for k in ("balance_radius", "balance_mass") if k in one]
    if given and cylinders > 1:
        raise t.fail(f"{given[0]} is a single cylinder's: the balance masses of cylinders in "
                     "line go in [[balance]] planes (plane, and radius or mass)", "engine",
                     given[0])
    if "balance_radius" in one and "balance_mass" in one:
        raise t.fail("the balance mass is given at its radius (balance_radius = …) or by its "
                     "mass (balance_mass = …), not both: the other is found", "engine",
                     "balance_mass")
    parts = one.get("revolving", 0.0)
    parts = parts if isinstance(parts, list) else [parts]
    masses = [t.number({"revolving": p}, "revolving", "engine", "a revolving mass")
              for p in parts]
    if any(not m >= 0 for m in masses):
        raise t.fail("the revolving masses (kg, at the crank radius) must be positive or 0, "
                     f"got {min(masses):g}", "engine", "revolving")
    out = []
    for key, what in (("balance_radius", f"{unit}"), ("balance_mass", "kg")):
        v = t.number(one, key, "engine", f"the {key.replace('_', ' ')}", 0, 0.0) \
            if key in one else None
        if v is not None and not v > 0:
            raise t.fail(f"the {key.replace('_', ' ')} must be positive, got {v:g} {what}",
                         "engine", key)
        out.append(v)
    return math.fsum(masses), out[0], out[1]


def _degrees(value: float) -> float:
    """An angle in degrees as radians, whole turns taken off first, where that is exact: a
    mass at 100030° is the one at 310°, to the last bit."""
    return radians_in_turn(value, "deg")
