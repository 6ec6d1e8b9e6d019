"""Read a balancing exercise: a rotor (``[rotor]``, ``[[mass]]``, ``[[balance]]``) or an
in-line engine (``[engine]``, ``[[cylinder]]``).

Angles are in degrees, counter-clockwise from the reference radius; radii, crank, rod and
axial positions in the file's length unit; masses in kg; the speed in rpm or rad/s. Every
failure is one line naming file:line.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..constructions.balancing.rotor import Engine, Mass, Plane, Rotor
from ..constructions.model import LENGTH_UNITS
from .mechanism_file import read_source
from .names import named_in, read_names, renamed_field
from .table_file import SPEEDS, Tables

__all__ = ["BalanceExercise", "is_balance", "load_balance", "parse_balance"]

_TOP = ("name", "names", "source", "description", "units", "rotor", "mass", "balance", "engine",
        "cylinder")
_KEYS = {"rotor": ("speed",), "mass": ("name", "mass", "radius", "angle", "plane"),
         "balance": ("name", "plane", "radius", "mass"),
         "engine": ("speed", "crank", "rod", "reciprocating", "balanced", "at"),
         "cylinder": ("crank", "plane")}


@dataclass(frozen=True)
class BalanceExercise:
    """A rotor to balance, or an engine whose unbalance is asked, and how the file states
    its units."""

    id: str
    name: str
    source: str
    description: str
    rotor: Rotor | None = None
    engine: Engine | None = None
    length_unit: str = "m"
    speed_unit: str = "rad/s"
    names: tuple[tuple[str, str], ...] = ()
    """The rotor's or engine's name in other languages (``[names]``, :mod:`.names`)."""

    def named_in(self, lang: str) -> BalanceExercise:
        """The same exercise with its rotor or engine named in ``lang``, if its file does."""
        return named_in(self, lang)

    renamed = renamed_field


def is_balance(data: dict[str, Any]) -> bool:
    """True for a file that describes a rotor or an engine to balance."""
    return "rotor" in data or "engine" in data


def load_balance(path: str | Path, exercise_id: str | None = None) -> BalanceExercise:
    """Read a balancing exercise file.

    Raises
    ------
    InputError
        Naming file:line and the setting.
    """
    path = Path(path)
    return parse_balance(read_source(path), str(path), exercise_id or path.stem)


def parse_balance(text: str, filename: str = "<string>",
                  exercise_id: str = "rotor") -> BalanceExercise:
    """Parse a balancing exercise from TOML text (see :func:`load_balance`)."""
    t = Tables.read(text, filename, "balancing", _TOP, _KEYS)
    data, fail, entries, number = t.data, t.fail, t.entries, t.number
    if "rotor" in data and "engine" in data:
        raise fail("a file is a rotor or an engine, not both", "engine")
    length, speed_unit = t.units("m", "rad/s")
    metre = LENGTH_UNITS[length]

    def speed(table: str) -> float:
        (t,) = entries(table)
        v = number(t, "speed", table, "the speed")
        if not v > 0:
            raise fail(f"the speed must be positive, got {v:g}", table, "speed")
        return v * SPEEDS[speed_unit]

    common = dict(id=exercise_id, name=str(data.get("name", exercise_id)),
                  source=str(data.get("source", "")),
                  description=str(data.get("description", "")), length_unit=length,
                  speed_unit=speed_unit, names=read_names(data, t.where, filename))
    if "engine" in data:
        return BalanceExercise(engine=_engine(entries, number, speed, fail, metre), **common)
    masses = []
    for i, t in enumerate(entries("mass")):
        name = str(t.get("name", i + 1))
        m = number(t, "mass", "mass", "a mass", i)
        r = number(t, "radius", "mass", "a mass's radius", i)
        if not m > 0 or not r > 0:
            raise fail(f"mass {name} needs a positive mass and radius, got {m:g} kg at "
                       f"{r:g} {length}", "mass", "mass" if not m > 0 else "radius", i)
        masses.append(Mass(name, m, r * metre,
                           math.radians(number(t, "angle", "mass", "a mass's angle", i)),
                           number(t, "plane", "mass", "a mass's plane", i, 0.0) * metre))
    if not masses:
        raise fail("list the rotor's masses as [[mass]] tables (mass, radius, angle, plane)",
                   "rotor")
    planes = []
    for i, t in enumerate(entries("balance")):
        name = str(t.get("name", "AB"[i] if i < 2 else i + 1))
        radius = t.get("radius")
        mass = t.get("mass")
        if (radius is None) == (mass is None):
            raise fail(f"balancing plane {name} gives the radius its mass goes at, or the mass "
                       "(the other is found): radius = 0.1", "balance", None, i)
        key = "radius" if radius is not None else "mass"
        v = number(t, key, "balance", f"plane {name}'s {key}", i)
        if not v > 0:
            raise fail(f"balancing plane {name}'s {key} must be positive, got {v:g}",
                       "balance", key, i)
        planes.append(Plane(name, number(t, "plane", "balance", f"plane {name}'s position",
                                         i, 0.0) * metre,
                            v * metre if key == "radius" else None,
                            v if key == "mass" else None))
    if not planes:
        raise fail("name a balancing plane: [[balance]] with plane = 0 and radius = 0.1 (two "
                   "planes for a dynamic balance)", "rotor")
    if len(planes) > 2:
        raise fail("balance in one plane (static) or two (dynamic), not "
                   f"{len(planes)}", "balance", None, 2)
    if len(planes) == 2 and planes[0].position == planes[1].position:
        raise fail(f"the balancing planes {planes[0].name} and {planes[1].name} stand at the "
                   "same axial position: two planes must be apart to hold a couple",
                   "balance", "plane", 1)
    return BalanceExercise(rotor=Rotor(tuple(masses), tuple(planes), speed("rotor")),
                           **common)


def _engine(entries, number, speed, fail, metre: float) -> Engine:
    (t,) = entries("engine")
    crank = number(t, "crank", "engine", "the crank radius")
    rod = number(t, "rod", "engine", "the connecting rod's length")
    mass = number(t, "reciprocating", "engine", "the reciprocating mass")
    if not (crank > 0 and rod > crank and mass > 0):
        raise fail("an engine needs a positive crank radius, a connecting rod longer than it "
                   "and a positive reciprocating mass", "engine")
    balanced = number(t, "balanced", "engine", "the balanced fraction", 0, 0.0)
    if not 0 <= balanced <= 1:
        raise fail(f"the balanced fraction is from 0 to 1, got {balanced:g}", "engine",
                   "balanced")
    cylinders = entries("cylinder") or [{"crank": 0, "plane": 0}]
    cranks = tuple(math.radians(number(c, "crank", "cylinder", "a crank angle", i, 0.0))
                   for i, c in enumerate(cylinders))
    planes = tuple(number(c, "plane", "cylinder", "a cylinder's plane", i, 0.0) * metre
                   for i, c in enumerate(cylinders))
    return Engine(cranks, planes, crank * metre, rod * metre, mass, speed("engine"), balanced,
                  math.radians(number(t, "at", "engine", "the crank angle", 0, 0.0)))
