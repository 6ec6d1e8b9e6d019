"""An in-line engine's balance masses in its wheels, as the books balance a locomotive: each
cylinder's revolving mass and its share of the balanced reciprocating mass along its crank,
with any other revolving masses on cranks of their own (``[[mass]]``: coupling rods, crank
pins, eccentrics), as rotating masses in the ``[[balance]]`` planes.

A coupled locomotive shares the balanced fraction c of the reciprocating mass equally among
its ``coupled`` pairs of wheels ("the balance divided equally between the driving and
trailing wheels"): the driving wheels take the revolving masses and c/k of the
reciprocating; every other pair, coupled to them and turning with them, c/k of the
reciprocating along the same cranks and the masses marked ``wheels = "each"`` (a coupling
rod's share at each of its crank pins). Every failure is one line naming file:line.
"""

from __future__ import annotations

from collections.abc import Callable

from tarsim.constructions.balancing.rotor import Engine, Mass, Plane, Rotor
from ..file_numbers import radians_in_turn
from ..table_file import Tables

__all__ = ["read_coupled", "wheel_rotors"]

_WHEELS = ("driving", "each")
"""Where a ``[[mass]]`` of an engine turns: on the driving wheels alone (an eccentric, the
driving crank pin), or on each pair of coupled wheels (a coupling rod's crank pins)."""


def read_coupled(t: Tables, one: dict) -> int:
    """``[engine] coupled``: how many pairs of coupled wheels, the driving among them, share
    the balanced reciprocating mass equally (1 where the file gives none)."""
    if "coupled" not in one:
        return 1
    k = one["coupled"]
    if isinstance(k, bool) or not isinstance(k, int) or k < 2:
        raise t.fail("coupled is how many pairs of coupled wheels share the balanced "
                     "reciprocating mass equally, the driving wheels among them: 2 or more, "
                     f"got {k!r:.20}", "engine", "coupled")
    return k


def wheel_rotors(t: Tables, one: dict, e: Engine, metre: float,
                 planes: Callable[[], list[Plane]],
                 name_of: Callable[[dict, int], str]) -> tuple[Rotor | None, Rotor | None]:
    """The driving wheels' rotor, and the other coupled wheels' (None with one pair), where
    ``[[balance]]`` planes are given (``one``, the file's [engine]); ``planes()`` reads them
    and ``name_of(entry, i)`` a ``[[mass]]``'s name, as a rotor's file does."""
    entries = t.entries("balance")
    if len(e.cranks) == 1:
        if entries:
            raise t.fail("a single cylinder's balance mass is given in [engine] as "
                         "balance_radius = … (or balance_mass = …), opposite its crank: leave "
                         "out the [[balance]] planes", "balance", None, 0)
        return None, None
    if not entries:
        given = [k for k in ("balanced", "revolving", "coupled") if k in one]
        if given:
            raise t.fail(f"{given[0]} is what balance masses take: give the [[balance]] planes "
                         "they go in (plane, and radius or mass), or leave it out", "engine",
                         given[0])
        if t.entries("mass"):
            raise t.fail("an engine's [[mass]] tables are revolving masses balanced in its "
                         "wheels: give the [[balance]] planes they go in, or leave them out",
                         "mass", None, 0)
        return None, None
    extra = _revolving_masses(t, e, metre, name_of)
    driving = _cylinder_masses(e, e.revolving + e.balanced_each * e.reciprocating)
    if not driving and not extra:
        raise t.fail("the [[balance]] planes balance each cylinder's revolving mass and the "
                     "fraction balanced of its reciprocating mass: give revolving = … or "
                     "balanced = …, or [[mass]] tables", "engine")
    found = planes()
    names = {str(i): "cylinder" for i in range(1, len(e.cranks) + 1)} | {
        m.name: "mass" for m, _ in extra}
    for i, p in enumerate(found):
        if p.name in names:
            raise t.fail(f"balancing plane {p.name} has the name of {names[p.name]} {p.name}: "
                         "name the planes with letters (A, B)", "balance", "name", i)
    # the masses on cranks of their own first: after its cylinders' cranks, a coupling rod's
    # at 180° to the last would retrace it in the polygons
    rotor = Rotor(tuple(m for m, _ in extra) + driving, tuple(found), e.speed)
    if e.coupled == 1:
        return rotor, None
    others = tuple(m for m, each in extra if each) + _cylinder_masses(
        e, e.balanced_each * e.reciprocating)
    if not others:
        raise t.fail("the other coupled wheels carry no mass: coupled shares the fraction "
                     "balanced of the reciprocating mass, so give balanced = …, or mark a "
                     "[[mass]] wheels = \"each\"", "engine", "coupled")
    return rotor, Rotor(others, tuple(found), e.speed)


def _cylinder_masses(e: Engine, each: float) -> tuple[Mass, ...]:
    """Each cylinder's mass ``each`` (kg) at the crank radius along its crank, named by its
    number (none where it is 0)."""
    if not each > 0:
        return ()
    return tuple(Mass(str(i), each, e.crank, theta, z)
                 for i, (theta, z) in enumerate(zip(e.cranks, e.planes), start=1))


def _revolving_masses(t: Tables, e: Engine, metre: float,
                      name_of: Callable[[dict, int], str]) -> list[tuple[Mass, bool]]:
    """The engine's ``[[mass]]`` tables: each a revolving mass on its own crank (mass, radius,
    angle, plane), and whether it turns on each pair of coupled wheels."""
    out: list[tuple[Mass, bool]] = []
    taken = {str(i) for i in range(1, len(e.cranks) + 1)}
    for i, entry in enumerate(t.entries("mass")):
        name = name_of(entry, i)
        if name in taken:
            raise t.fail(f"mass {i + 1} is named {name}, as a cylinder or another mass is: give "
                         "each its own name, such as \"rod\"", "mass", "name", i)
        taken.add(name)
        for key in ("mass", "radius", "angle"):
            if key not in entry:
                raise t.fail(f"mass {name} needs its {key}: a revolving mass in the wheels is "
                             "mass, radius, angle (its crank's) and plane", "mass", None, i)
        if "between" in entry:
            raise t.fail(f"mass {name}'s between chooses where an unknown angle comes out; an "
                         "engine's masses are given whole: leave it out", "mass", "between", i)
        m = t.number(entry, "mass", "mass", f"mass {name}'s mass", i)
        r = t.number(entry, "radius", "mass", f"mass {name}'s radius", i)
        if not (m > 0 and r > 0):
            raise t.fail(f"mass {name} needs a positive mass and radius, got {m:g} kg at {r:g}",
                         "mass", "mass" if not m > 0 else "radius", i)
        wheels = entry.get("wheels", "driving")
        if wheels not in _WHEELS:
            raise t.fail(f"mass {name}'s wheels is \"driving\" (on the driving wheels alone, the "
                         "default) or \"each\" (on each pair of coupled wheels), got "
                         f"{wheels!r:.20}", "mass", "wheels", i)
        if wheels == "each" and e.coupled == 1:
            raise t.fail(f"mass {name}'s wheels = \"each\" puts it on each pair of coupled "
                         "wheels: give [engine] coupled = … (how many pairs), or leave it out",
                         "mass", "wheels", i)
        angle = radians_in_turn(t.number(entry, "angle", "mass", f"mass {name}'s angle", i),
                                "deg")
        plane = t.number(entry, "plane", "mass", f"mass {name}'s plane", i, 0.0) * metre
        out.append((Mass(name, m, r * metre, angle, plane), wheels == "each"))
    return out
