"""Read a mechanism's loads for its force analysis: ``[forces]``, ``[[mass]]``,
``[[force]]`` and ``[[couple]]`` tables beside the mechanism's own.

Masses are in kg, inertias in kg·m², forces in N and couples in N·m (CCW +); points and
lengths in the file's length unit. A mass's centre is a point of its link ("A"), "mid"
(halfway between the link's first two points) or [x, y] in the link's own frame (its
first point the origin, +x toward its second point or along its slot); its inertia about
that centre is given, or as a radius of gyration k (I = m·k²), or by a pendulum test
(``oscillations``, :mod:`.pendulum`), or defaults to a slender
rod's, (1/12)·m·L², said to be assumed; a link that slides on the frame without turning (a
piston, a ram) needs none, for its inertia couple I·α is 0. A gas force may be given as the
books give it, a pressure on the piston's bore (or area): p·A along the line of stroke
toward the crank. ``[forces]`` may give the engine's ``power`` (W) or ``mean_torque`` (N·m)
with its ``flywheel`` (kg·m², or ``{ mass, radius_of_gyration }``): the flywheel's α at the
position is then (T − T_mean)/I. A pressure (or ``resist``, or ``force``) that changes with
the position is a list, ``pressure = ["0.45 N/mm²", "0.3 N/mm²"]``, one for each of ``[ask]
at``'s positions in order (:func:`pressures_per_position`). Every failure is one line
naming file:line.
"""

from __future__ import annotations

import math
from typing import Any

from tarsim.constructions.loads import GRAVITY, Couple, Loads, Mass, PointForce
from tarsim.constructions.model import Mechanism
from tarsim.constructions.units import LENGTH_UNITS
from ..file_numbers import file_number
from ..table_file import Tables
from ..toml_source import SourceMap
from .pendulum import pendulum_inertia

__all__ = ["LOAD_TABLES", "pressures_per_position", "read_loads"]

LOAD_TABLES = ("forces", "mass", "force", "couple")
"""The top-level tables this module reads; the mechanism reader leaves them alone."""

_KEYS = {"forces": ("gravity", "driver", "speed_fluctuation", "flywheel", "friction",
                    "friction_circle", "power", "mean_torque"),
         "mass": ("link", "mass", "centre", "inertia", "length", "radius_of_gyration",
                  "oscillations"),
         "force": ("link", "point", "force", "resist", "stroke", "name", "pressure", "bore",
                   "area", "rod"),
         "couple": ("link", "moment", "name")}


def pressures_per_position(data: dict[str, Any], where: SourceMap, filename: str,
                           positions: int) -> int:
    """How many positions the file's pressures are given for: 0 if every pressure is one
    number, else the positions' count, each list of pressures holding one per position.

    Raises
    ------
    InputError
        Naming file:line: a list whose length is not the count of ``[ask] at``'s positions.
    """
    tables = Tables(data, where, filename, _KEYS)
    lists = [(i, key, t[key]) for i, t in enumerate(tables.entries("force"))
             for key in _PER_POSITION if _per_position(t, key)]
    for i, key, given in lists:
        if not positions or len(given) != positions:
            raise tables.fail(
                f"a {key} per position is matched to [ask] at's positions in order: "
                + (f"{len(given)} given here, {positions} positions there; give as many"
                   if positions else "list them there, at = [{ angle = 30 }, …]"),
                "force", key, i)
    return positions if lists else 0


_PER_POSITION = ("pressure", "resist", "force")
"""A [[force]]'s settings that may be a list, one for each of [ask] at's positions."""


def _per_position(t: dict, key: str) -> bool:
    """Whether ``t`` gives ``key`` per position: a list of them (a force's, of [x, y] pairs;
    an empty list counts, to be refused as no match)."""
    v = t.get(key)
    return isinstance(v, list) and (key != "force" or not v or isinstance(v[0], list))


def read_loads(data: dict[str, Any], mech: Mechanism, where: SourceMap,
               filename: str, position: int = 0) -> Loads | None:
    """The loads the file gives (None if it gives none), at the ``position``-th of ``[ask]
    at``'s positions where a pressure is given per position.

    Raises
    ------
    InputError
        Naming file:line: an unknown link or point, a mass or inertia that is not positive,
        a driver other than the input link, a setting it does not know.
    """
    if not any(t in data for t in LOAD_TABLES):
        return None
    metre = LENGTH_UNITS[mech.units.length]

    tables = Tables(data, where, filename, _KEYS)
    fail, entries, number = tables.fail, tables.entries, tables.number

    def link(t: dict, table: str, i: int) -> int:
        n = t.get("link")
        moving = sorted(k.number for k in mech.links if k.number != 1)
        if n not in moving:
            raise fail(f"[{table}] names link {n!r}, which is not a moving link of the "
                       f"mechanism ({', '.join(map(str, moving))})", table, "link", i)
        return n

    (settings,) = entries("forces") or [{}]
    gravity = settings.get("gravity", True)
    if not isinstance(gravity, bool):
        raise fail("gravity = true pulls each mass down (−y) at 9.81 m/s²; false leaves "
                   "weight out", "forces", "gravity")
    driver = settings.get("driver", mech.drive.link)
    if driver != mech.drive.link:
        raise fail(f"the driver must be the input link ({mech.drive.link}), whose motion is "
                   f"given; got {driver!r}", "forces", "driver")
    wheel = {}
    if isinstance(settings.get("flywheel"), dict):
        wheel["flywheel"] = _flywheel_of(settings["flywheel"], metre, tables)
    for key, what in (("speed_fluctuation", "a coefficient of speed fluctuation"),
                      ("flywheel", "a flywheel's inertia (kg·m²)")):
        if key in settings and key not in wheel:
            wheel[key] = number(settings, key, "forces", what, 0)
            if not wheel[key] > 0:
                raise fail(f"{what} must be positive, got {wheel[key]:g}", "forces", key)
    if len(wheel) > 1:
        raise fail("give speed_fluctuation (the flywheel is found) or flywheel (its C_s is "
                   "found), not both", "forces", "flywheel")
    resisting = _resisting(settings, mech, tables)
    if resisting is not None:
        if "flywheel" not in wheel:
            key = "power" if "power" in settings else "mean_torque"
            raise fail(f"{key} gives the flywheel's acceleration (T − T_mean)/I: give its "
                       "flywheel = 136.8 (kg·m²) or { mass = 380, radius_of_gyration = 600 }",
                       "forces", key)
        wheel["resisting"] = resisting
    if wheel and not mech.drive.omega:
        key = next(iter(wheel))
        raise fail(f"a flywheel holds a speed, but link {mech.drive.link}'s ω is 0 in [input]: "
                   f"give it the speed the flywheel is to hold, or leave {key} out", "forces",
                   key)
    friction = 0.0
    if "friction" in settings:
        friction = number(settings, "friction", "forces", "a coefficient of friction", 0)
        if not 0.0 <= friction <= 2.0:
            raise fail(f"friction is the coefficient μ at the slides, from 0 (none) to 2; got "
                       f"{friction:g}", "forces", "friction")
    circle = 0.0
    if "friction_circle" in settings:
        circle = number(settings, "friction_circle", "forces",
                        "a friction circle's radius", 0) * metre
        if not circle >= 0.0:
            raise fail(f"friction_circle is the radius ρ = μ·r of every pin's friction "
                       f"circle, in {mech.units.length}, 0 or more; got {circle / metre:g}",
                       "forces", "friction_circle")
        # ρ = μ·r, r a pin's radius, and a pin is smaller than the link it joins: a circle
        # as long as a link would lock it at every position.
        spans = [(k.span(p, q), k) for k in mech.links if k.number != 1
                 for i, p in enumerate(k.names) for q in k.names[i + 1:]]
        if spans and circle >= min(spans, key=lambda t: t[0])[0]:
            span, k = min(spans, key=lambda t: t[0])
            raise fail(f"a friction circle of {circle / metre:g} {mech.units.length} is as long "
                       f"as {k.label}, {span / metre:g} {mech.units.length}: ρ = μ·r, r a pin's "
                       "radius, is far smaller than its link", "forces", "friction_circle")
    masses = []
    for i, t in enumerate(entries("mass")):
        n = link(t, "mass", i)
        k = mech.link(n)
        m = number(t, "mass", "mass", "a mass", i)
        if not m > 0:
            raise fail(f"link {n}'s mass must be positive, got {m:g} kg", "mass", "mass", i)
        centre, named = _centre(t.get("centre", "mid"), k, metre,
                                lambda msg, i=i: fail(msg, "mass", "centre", i))
        given = [key for key in ("inertia", "radius_of_gyration", "oscillations") if key in t]
        if len(given) > 1:
            raise fail(f"link {n}'s inertia is given twice: give inertia (kg·m²), "
                       "radius_of_gyration (I = m·k²) or oscillations, one of them", "mass",
                       given[1], i)
        swing = None
        if "oscillations" in t:
            inertia, assumed, swing = pendulum_inertia(t["oscillations"], k, m, centre, metre,
                                                lambda msg, i=i: fail(msg, "mass",
                                                                      "oscillations", i))
        elif "radius_of_gyration" in t:
            k_g = number(t, "radius_of_gyration", "mass", "a radius of gyration", i) * metre
            if not k_g > 0:
                raise fail(f"link {n}'s radius of gyration must be positive, got "
                           f"{k_g / metre:g} {mech.units.length}", "mass", "radius_of_gyration",
                           i)
            inertia = m * k_g ** 2
            assumed = ""
        elif "inertia" in t:
            inertia = _inertia(t, i, n, fail)
            if not inertia > 0:
                raise fail(f"link {n}'s moment of inertia must be positive, got "
                           f"{inertia:g} kg·m²", "mass", "inertia", i)
            assumed = ""
        elif "length" not in t and _translates(mech, n):
            inertia = 0.0       # it never turns: α = 0, so I·α = 0 whatever I is
            assumed = "it slides without turning, so its inertia couple is 0"
        else:
            if "length" in t:
                length = number(t, "length", "mass", "the rod's length", i) * metre
            elif len(k.names) >= 2:
                length = k.span(k.names[0], k.names[1])
            else:
                raise fail(f"link {n} has one point: give its inertia, or its length for a "
                           "slender rod's (1/12)·m·L²", "mass", None, i)
            if not length > 0:
                raise fail("a slender rod's length must be positive", "mass", "length", i)
            inertia = m * length ** 2 / 12
            assumed = f"slender rod (1/12)·m·L², L = {length / metre:g} {mech.units.length}"
        masses.append(Mass(n, m, centre, inertia, assumed, named, swing))
    forces = []
    for i, t in enumerate(entries("force")):
        n = link(t, "force", i)
        point = t.get("point")
        if isinstance(point, str):
            if not mech.link(n).carries(point):
                raise fail(f"link {n} has no point '{point}'; its points are "
                           f"{', '.join(mech.link(n).names)}", "force", "point", i)
        elif isinstance(point, list) and len(point) == 2:
            point = (number({"point": point[0]}, "point", "force", "a point's x", i) * metre,
                     number({"point": point[1]}, "point", "force", "a point's y", i) * metre)
        else:
            raise fail("a force acts at a point of its link: point = \"B\" or [x, y] in the "
                       "link's own frame", "force", "point", i)
        name = str(t.get("name", ""))
        t = {**t, **{key: t[key][position] for key in _PER_POSITION if _per_position(t, key)}}
        if "pressure" in t:
            forces.append(_gas_force(mech, t, n, point, name, metre, i, fail))
            continue
        for key in ("bore", "area", "rod"):
            if key in t:
                raise fail(f"{key} is the piston's, for a gas pressure: give pressure = "
                           "\"2 MPa\" with it", "force", key, i)
        if "resist" in t:
            size = number(t, "resist", "force", "a resisting force", i)
            if not size > 0 or "force" in t:
                raise fail("resist = 1000 gives a force's size against the point's motion "
                           "(N, positive), in place of force = [x, y]", "force", "resist", i)
            stroke = t.get("stroke", "both")
            if stroke not in ("both", "slow", "fast"):
                raise fail(f"stroke is both, slow or fast, not {stroke!r}", "force", "stroke",
                           i)
            along = None
            if stroke != "both":
                along = _stroke_way(mech, n, point, stroke == "slow")
                if along is None:
                    raise fail(f"a {stroke} stroke belongs to a point on a frame guide; "
                               f"{point!r} of link {n} is not one", "force", "stroke", i)
            forces.append(PointForce(n, point, name=name, resist=size, along=along))
            continue
        f = t.get("force")
        if not (isinstance(f, list) and len(f) == 2):
            raise fail("a force gives its components in N: force = [-1000, 0] (or resist = "
                       "1000 against the point's motion)", "force", "force", i)
        fx = number({"force": f[0]}, "force", "force", "a force's x", i)
        fy = number({"force": f[1]}, "force", "force", "a force's y", i)
        forces.append(PointForce(n, point, (fx, fy), name))
    couples = [Couple(link(t, "couple", i), number(t, "moment", "couple", "a couple", i),
                      str(t.get("name", ""))) for i, t in enumerate(entries("couple"))]
    if not (masses or forces or couples):
        raise fail("nothing loads the mechanism: give [[mass]], [[force]] or [[couple]] "
                   "tables with the [forces] settings", "forces")
    return Loads(tuple(masses), tuple(forces), tuple(couples), GRAVITY if gravity else 0.0,
                 friction=friction, friction_circle=circle, **wheel)


PRESSURES = {"Pa": 1.0, "N/m²": 1.0, "N/m2": 1.0, "kPa": 1e3, "kN/m²": 1e3, "kN/m2": 1e3,
             "bar": 1e5, "MPa": 1e6, "MN/m²": 1e6, "MN/m2": 1e6, "N/mm²": 1e6, "N/mm2": 1e6}
"""The pressure units a gas force may be stated in, as Pa each; a plain number is in Pa."""


def _pressure(v: Any) -> float:
    """A pressure as the file gives it (a number in Pa, or "0.5 N/mm²", "35 bar"), in Pa.

    Raises
    ------
    ValueError
        Saying what is wrong, for the caller to place at its line.
    """
    if isinstance(v, str):
        number, _, unit = v.strip().partition(" ")
        unit = unit.strip()
        if unit not in PRESSURES:
            raise ValueError(f"a pressure's unit is one of {', '.join(PRESSURES)}: \"2 MPa\", "
                             f"got {v!r:.40}")
        try:
            value = float(number)
        except ValueError:
            raise ValueError(f"a pressure is a number and its unit, \"2 MPa\"; got "
                             f"{v!r:.40}") from None
        return file_number(value, "a pressure") * PRESSURES[unit]
    return file_number(v, "a pressure (Pa)")


def _gas_force(mech: Mechanism, t: dict, n: int, point, name: str, metre: float, i: int,
               fail) -> PointForce:
    """A gas pressure on the piston's bore (or area) as a force: p·A along the line of stroke
    toward the crank's pivot (away from it for a pressure below 0, a suction, or the back
    pressure on a double-acting piston's crank side, whose rod takes π·d²/4 off the bore)."""
    for key in ("force", "resist"):
        if key in t:
            raise fail(f"a gas force is given by its pressure or as {key}, not both",
                       "force", key, i)
    try:
        p = _pressure(t["pressure"])
    except ValueError as e:
        raise fail(str(e), "force", "pressure", i) from None
    if ("bore" in t) == ("area" in t):
        raise fail("a pressure acts on the piston's bore (its diameter, bore = 100) or on its "
                   "area (area = 7854, in the length unit squared): give one", "force",
                   "pressure", i)
    if "bore" in t:
        bore = t["bore"] if isinstance(t["bore"], (int, float)) else None
        size = _sized(bore, "the bore", "bore", i, fail) * metre if bore is not None else 0.0
        if not size > 0:
            raise fail(f"the bore is the piston's diameter, positive, in {mech.units.length}; "
                       f"got {t['bore']!r:.40}", "force", "bore", i)
        area = math.pi * size * size / 4
        if "rod" in t:
            # A double-acting piston's crank side: its rod takes the middle of the bore.
            rod = t["rod"] if isinstance(t["rod"], (int, float)) else None
            d = _sized(rod, "the piston rod's diameter", "rod", i, fail) * metre \
                if rod is not None else 0.0
            if not 0 < d < size:
                raise fail(f"the piston rod's diameter is positive and less than the bore's "
                           f"({t['bore']:g} {mech.units.length}); got {t['rod']!r:.40}",
                           "force", "rod", i)
            area -= math.pi * d * d / 4
    else:
        if "rod" in t:
            raise fail("rod is the piston rod's diameter, taken off the bore (bore = 300, rod = "
                       "50); an area given is the area the pressure acts on already", "force",
                       "rod", i)
        a = t["area"] if isinstance(t["area"], (int, float)) else None
        area = _sized(a, "the area", "area", i, fail) * metre * metre if a is not None else 0.0
        if not area > 0:
            raise fail(f"the piston's area must be positive, in {mech.units.length}²; got "
                       f"{t['area']!r:.40}", "force", "area", i)
    way = _toward_crank(mech, n, point) if isinstance(point, str) else None
    if way is None:
        raise fail(f"a gas pressure pushes a piston along its line of stroke: {point!r} of link "
                   f"{n} must be a point on a frame guide of a mechanism driven by a crank",
                   "force", "pressure", i)
    size = p * area
    return PointForce(n, point, (size * way[0], size * way[1]), name or "gas force")


def _sized(v, what: str, key: str, i: int, fail) -> float:
    """A piston's bore, rod or area as :func:`file_number` takes it, refused at its line."""
    try:
        return file_number(v, what)
    except ValueError as e:
        raise fail(str(e), "force", key, i) from None


def _toward_crank(mech: Mechanism, link: int, point: str) -> tuple[float, float] | None:
    """The line of stroke of ``point`` (on a frame guide) turned toward the crank's pivot,
    at the input's given angle; None where there is no such guide or pivot."""
    import numpy as np

    from tarsim.constructions.loads import stroke_axis
    from tarsim.constructions.model import Drive
    from tarsim.constructions.reference.turn import solve_turn

    guide = next((s for s in mech.slides if s.guide_link == 1 and s.link == link
                  and s.point == point), None)
    crank = mech.link(mech.drive.link)
    pivot = next((mech.frame.local(q) for q in crank.names if mech.frame.carries(q)), None)
    if guide is None or pivot is None:
        return None
    drive = mech.drive
    turn = solve_turn(mech.with_drive(Drive(drive.link, drive.angle, drive.omega or 1.0)),
                      np.zeros(1))
    if not turn.ok[0]:
        return None
    pin = tuple(float(c) for c in turn.points[point][0])
    return stroke_axis(pivot, pin, guide.direction)


def _translates(mech: Mechanism, link: int) -> bool:
    """Whether ``link`` slides on the frame as a block (a piston, a ram): it keeps its angle,
    so it never turns."""
    return any(s.guide_link == 1 and s.link == link and s.type.turns_with_guide
               for s in mech.slides)


INERTIAS = (1e-15, 1e6)
"""The moments of inertia (kg·m²) a file may give: a link a few millimetres long has some
1e-9, so the range runs well below a length's or a mass's."""


def _flywheel_of(raw: dict, metre: float, tables: Tables) -> float:
    """A flywheel's I (kg·m²) given as the books give it, { mass = 380, radius_of_gyration =
    600 } (k in the file's length unit): m·k²."""
    if set(raw) != {"mass", "radius_of_gyration"}:
        raise tables.fail("flywheel is its inertia (kg·m²) or { mass = 380, "
                          "radius_of_gyration = 600 }, k in the file's length unit, I = m·k²",
                          "forces", "flywheel")
    m = tables.number(raw, "mass", "forces", "the flywheel's mass")
    k = tables.number(raw, "radius_of_gyration", "forces", "its radius of gyration") * metre
    if not (m > 0 and k > 0):
        raise tables.fail(f"the flywheel's mass and radius of gyration must be positive, got "
                          f"{m:g} and {k / metre:g}", "forces", "flywheel")
    return m * k * k


def _resisting(settings: dict, mech: Mechanism, tables: Tables) -> float | None:
    """The mean resisting torque (N·m) [forces] gives, as ``mean_torque`` or the engine's
    ``power`` (W) at the input's speed, P/|ω|; None where it gives neither."""
    given = [k for k in ("power", "mean_torque") if k in settings]
    if not given:
        return None
    if len(given) > 1:
        raise tables.fail("give the engine's power (W) or the mean resisting torque (N·m), "
                          "not both: T_mean = P/ω", "forces", "mean_torque")
    key = given[0]
    v = tables.number(settings, key, "forces", "the engine's power (W)" if key == "power"
                      else "the mean resisting torque (N·m)")
    if not v > 0:
        raise tables.fail(f"{key} must be positive, got {v:g}", "forces", key)
    if key == "mean_torque":
        return v
    if not mech.drive.omega:
        raise tables.fail(f"the power gives the mean torque P/ω, but link {mech.drive.link}'s "
                          "ω is 0 in [input]: give its speed", "forces", "power")
    return v / abs(mech.drive.omega)


def _inertia(t: dict, i: int, link: int, fail) -> float:
    """Link ``link``'s moment of inertia as [[mass]] ``i`` gives it (kg·m²)."""
    v = t.get("inertia")
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise fail(f"link {link}'s moment of inertia must be a number, got {v!r:.40}", "mass",
                   "inertia", i)
    low, high = INERTIAS
    if v != 0 and not low <= abs(v) <= high:
        raise fail(f"link {link}'s moment of inertia must be between {low:g} and {high:g} "
                   f"kg·m², got {v:g}", "mass", "inertia", i)
    return float(v)


def _centre(v: Any, k, metre: float, fail) -> tuple[tuple[float, float], str]:
    """A centre of mass in the link's own frame, and how the file named it."""
    if v == "mid":
        if len(k.names) < 2:
            raise fail(f"{k.label} has one point, so no mid-length: give centre = [x, y] "
                       "in its own frame")
        (ax, ay), (bx, by) = k.local(k.names[0]), k.local(k.names[1])
        return ((ax + bx) / 2, (ay + by) / 2), "mid"
    if isinstance(v, str):
        if not k.carries(v):
            raise fail(f"{k.label} has no point '{v}'; its points are {', '.join(k.names)}")
        return k.local(v), v
    if isinstance(v, list) and len(v) == 2:
        try:
            return tuple(file_number(c, "a centre's coordinate") * metre for c in v), ""
        except ValueError as e:
            raise fail(str(e)) from None
    raise fail(f"a centre of mass is a point of the link, \"mid\" or [x, y], not {v!r}")


_TURN = 360
"""Crank positions a stroke's way is judged over."""


def _stroke_way(mech: Mechanism, link: int, point, slow: bool) -> tuple[float, float] | None:
    """The way a point on a frame guide moves during its slow (or fast) stroke: the way it
    moves over more of the input's turn. None if the point runs on no frame guide."""
    import numpy as np

    from tarsim.constructions.model import Drive
    from tarsim.constructions.reference.turn import solve_turn

    guide = next((s for s in mech.slides if s.guide_link == 1 and s.link == link
                  and s.point == point), None)
    if guide is None:
        return None
    d, drive = guide.direction, mech.drive
    # The whole turn at once (the vectorised solver); a dead point or a gap moves no way.
    turn = solve_turn(mech.with_drive(Drive(drive.link, drive.angle, drive.omega or 1.0)),
                      2 * np.pi * np.arange(_TURN) / _TURN)
    v = turn.velocities[point]
    w = np.where(turn.ok, v[:, 0] * d[0] + v[:, 1] * d[1], 0.0)
    ahead = int(np.sum(w > 0)) > int(np.sum(w < 0))
    return d if ahead == slow else (-d[0], -d[1])
