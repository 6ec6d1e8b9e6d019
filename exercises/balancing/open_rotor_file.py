"""Read a rotor that balances itself, its unknowns marked "?" as the textbooks leave them.

Any of a ``[[mass]]``'s ``mass``, ``radius``, ``angle`` or ``plane`` may be ``"?"``; the rotor
then has no ``[[balance]]`` planes: its own masses balance it, in force alone where no mass
states a plane (one plane, two unknowns), in force and couple where they do (four). A
mass's mass and radius show only as their product, so one of them is given. Whether the
polygons can close on the unknowns is found here, by closing them, so a file that cannot is
refused at its line.
"""

from __future__ import annotations

from tarsim.constructions.balancing.unknowns import (CannotClose, OpenRotor, Part, close_rotor,
                                                     count_unknowns)
from ..file_numbers import radians_in_turn

__all__ = ["UNKNOWN", "read_open_rotor"]

UNKNOWN = "?"
"""What a file writes for a quantity it asks for."""


def read_open_rotor(t, metre: float, speed: float, name_of) -> OpenRotor:
    """The rotor's masses with their unknowns, refused in one line where the polygons
    cannot close on them (too many, too few, or tangled in one mass); ``name_of(entry, i)``
    reads a mass's name as every rotor file does."""
    if t.data.get("balance"):
        raise t.fail('a rotor whose masses have unknowns ("?") is balanced by those masses: '
                     "leave out the [[balance]] planes, or give every mass whole",
                     "balance", None, 0)
    entries = t.entries("mass")
    static = not any("plane" in e for e in entries)
    parts: list[Part] = []
    first = None
    for i, e in enumerate(entries):
        name = name_of(e, i)
        if any(p.name == name for p in parts):
            raise t.fail(f"two masses are named {name}: give each its own name", "mass",
                         "name", i)
        values = {}
        for key in ("mass", "radius", "angle", "plane"):
            v = e.get(key, 0.0 if key == "plane" else None)
            if v == UNKNOWN:
                first = first or (key, i)
                values[key] = None
                continue
            if v is None:
                raise t.fail(f"mass {name} needs its {key}, or \"?\" where it is asked",
                             "mass", None, i)
            x = t.number(e, key, "mass", f"mass {name}'s {key}", i,
                         0.0 if key == "plane" else None)
            if key in ("mass", "radius") and not x > 0:
                raise t.fail(f"mass {name}'s {key} must be positive, got {x:g}", "mass", key, i)
            values[key] = radians_in_turn(x, "deg") if key == "angle" else \
                x * (metre if key in ("radius", "plane") else 1.0)
        if values["mass"] is None and values["radius"] is None:
            raise t.fail(f"mass {name}'s mass and radius show only as m·r: give one of them",
                         "mass", "radius", i)
        parts.append(Part(name, values["mass"], values["radius"], values["angle"],
                          values["plane"], _between(t, e, name, i, values["angle"])))
    rotor = OpenRotor(tuple(parts), speed, static)
    need = 2 if static else 4
    have = count_unknowns(rotor)
    if have != need:
        why = ("the force polygon closes on two" if static else
               "the force and couple polygons close on two each")
        raise t.fail(f"{have} unknowns, but {why}: mark {need} with \"?\" (a mass's mass or "
                     "radius, its angle, its plane)", "mass", first[0], first[1])
    if all(p.angle is None for p in parts):
        raise t.fail("every angle is unknown: give one mass's angle (0, say) as the reference "
                     "the others are measured from", "mass", "angle", 0)
    try:
        close_rotor(rotor)
    except CannotClose as e:
        raise t.fail(f"{e}", "mass", first[0], first[1]) from None
    return rotor


def _between(t, e: dict, name: str, i: int, angle) -> tuple[float, float] | None:
    """A mass's ``between = [from, to]`` (degrees, counter-clockwise from the first to the
    second): where its unknown angle must come out, the file's choice of the mirror image
    (the books' "measured counter-clockwise", their masses' order round the shaft)."""
    if "between" not in e:
        return None
    v = e["between"]
    if angle is not None:
        raise t.fail(f"mass {name}'s between chooses where an unknown angle comes out: its "
                     'angle is given; leave between out, or make the angle "?"', "mass",
                     "between", i)
    if not (isinstance(v, list) and len(v) == 2):
        raise t.fail(f"mass {name}'s between is two angles, [from, to] in degrees "
                     "counter-clockwise, such as [0, 180]", "mass", "between", i)
    lo, hi = (t.number({"between": x}, "between", "mass", f"mass {name}'s between", i)
              for x in v)
    if (hi - lo) % 360 == 0:
        raise t.fail(f"mass {name}'s between, [{lo:g}, {hi:g}], spans no angle or the whole "
                     "turn: give the range its angle lies in, such as [0, 180]", "mass",
                     "between", i)
    return radians_in_turn(lo, "deg"), radians_in_turn(hi, "deg")
