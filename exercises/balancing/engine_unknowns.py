"""An in-line engine's cylinders as the books leave them for a primary balance: each
cylinder's own reciprocating mass, and "?" for a mass, a crank's angle or a cylinder's
plane that complete primary balance must find ("find the reciprocating masses and the
relative angular positions of the inner cranks").

The primary forces are those of the reciprocating masses turning at the crank radius, so a
primary balance is a rotor's complete balance (:mod:`tarsim.constructions.balancing.
unknowns`): the force and couple polygons of mᵢ·r close on four unknowns. The engine is
then the one those polygons complete, its secondary forces and couples drawn as any
engine's.
"""

from __future__ import annotations

from tarsim.constructions.balancing.unknowns import (CannotClose, OpenRotor, Part, close_rotor,
                                                     count_unknowns)
from ..file_numbers import radians_in_turn
from .open_rotor_file import UNKNOWN

__all__ = ["cylinder_masses", "has_unknowns", "primary_balance"]


def has_unknowns(cylinders: list[dict]) -> bool:
    """Whether any cylinder leaves its mass, crank or plane to the primary balance."""
    return any(c.get(k) == UNKNOWN for c in cylinders for k in ("reciprocating", "crank",
                                                                   "plane"))


def cylinder_masses(t, one: dict, cylinders: list[dict]) -> list[float | None]:
    """Each cylinder's reciprocating mass (kg): its own ``reciprocating``, else [engine]'s;
    None where it is "?"; each failure one line."""
    default = None
    if "reciprocating" in one or not all("reciprocating" in c for c in cylinders):
        default = t.number(one, "reciprocating", "engine", "the reciprocating mass")
        if not default > 0:
            raise t.fail(f"the reciprocating mass must be positive, got {default:g} kg",
                         "engine", "reciprocating")
    out: list[float | None] = []
    for i, c in enumerate(cylinders):
        if c.get("reciprocating") == UNKNOWN:
            out.append(None)
            continue
        if "reciprocating" not in c:
            out.append(default)
            continue
        m = t.number(c, "reciprocating", "cylinder", f"cylinder {i + 1}'s reciprocating mass", i)
        if not m > 0:
            raise t.fail(f"cylinder {i + 1}'s reciprocating mass must be positive, got {m:g} kg",
                         "cylinder", "reciprocating", i)
        out.append(m)
    return out


def primary_balance(t, one: dict, cylinders: list[dict], masses: list[float | None],
                    crank: float, metre: float, speed: float) -> OpenRotor:
    """The cylinders as a rotor in complete primary balance, its unknowns "?": refused in
    one line where its polygons cannot close on them (not four unknowns, every crank
    unknown, or carriers that miss), or where the file asks for what the primary balance
    cannot give."""
    for key in ("balanced", "revolving", "balance_radius", "balance_mass", "firing_order"):
        if key in one:
            raise t.fail(f"{key} is not taken where the cylinders' unknowns (\"?\") are found by "
                         "their primary balance: leave it out", "engine", key)
    if t.entries("balance"):
        raise t.fail("the cylinders' unknowns (\"?\") are found by their own primary balance: "
                     "leave out the [[balance]] planes", "balance", None, 0)
    parts, first = [], None
    for i, c in enumerate(cylinders):
        values = {}
        for key in ("crank", "plane"):
            v = c.get(key, 0.0)
            if v == UNKNOWN:
                values[key] = None
                first = first or (key, i)
                continue
            x = t.number(c, key, "cylinder", f"cylinder {i + 1}'s {key}", i, 0.0)
            values[key] = radians_in_turn(x, "deg") if key == "crank" else x * metre
        if masses[i] is None:
            first = first or ("reciprocating", i)
        parts.append(Part(str(i + 1), masses[i], crank, values["crank"], values["plane"]))
    rotor = OpenRotor(tuple(parts), speed, static=False)
    have = count_unknowns(rotor)
    if have != 4:
        raise t.fail(f"{have} unknowns, but complete primary balance closes the force and couple "
                     "polygons on two each: mark four with \"?\" (a cylinder's reciprocating "
                     "mass, crank or plane)", "cylinder", first[0], first[1])
    if all(p.angle is None for p in parts):
        raise t.fail("every crank is unknown: give one crank's angle (0, say) as the reference "
                     "the others are measured from", "cylinder", "crank", 0)
    try:
        close_rotor(rotor)
    except CannotClose as e:
        raise t.fail(f"{e}", "cylinder", first[0], first[1]) from None
    return rotor
