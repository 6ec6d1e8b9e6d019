"""A locomotive's file: its driving wheels' diameter, their dead load or the greatest hammer
blow allowed, and the engine's speed as the books give it, ``speed``, a ``road_speed``
(km/h) on wheels of ``wheel_diameter``, or none where the speed is the unknown (the balance
masses need none, and a dead load or a hammer blow's limit gives the speed).
Every failure is one line naming file:line."""

from __future__ import annotations

from collections.abc import Callable

from ..table_file import Tables

__all__ = ["engine_speed", "read_blow_limit", "read_wheel"]


def read_wheel(t: Tables, one: dict, metre: float, cylinders: int
               ) -> tuple[float | None, float | None]:
    """A locomotive's wheel diameter (m) and the dead load on each driving wheel (N), where
    the file gives them; the load only where balance masses in the wheels strike the rails."""
    wheel = t.number(one, "wheel_diameter", "engine", "the wheels' diameter") * metre \
        if "wheel_diameter" in one else None
    return wheel, _load(t, one, "dead_load", cylinders)


def read_blow_limit(t: Tables, one: dict, cylinders: int) -> float | None:
    """The greatest hammer blow allowed on a wheel (N), ``hammer_blow``, where the books ask
    the speed at which it is reached ("the hammer blow is not to exceed 30 kN"): the same
    ω = √(P/(B·b)) as a dead load's lift, but no wheel lifts. A file gives one or the other."""
    if "hammer_blow" in one and "dead_load" in one:
        raise t.fail("hammer_blow (the greatest blow allowed) and dead_load (the load a blow "
                     "lifts the wheel against) each find one speed: give one, not both",
                     "engine", "hammer_blow")
    return _load(t, one, "hammer_blow", cylinders)


_LOADS = {"dead_load": ("the dead load on a wheel", "dead_load is what a hammer blow lifts a "
                        "wheel against"),
          "hammer_blow": ("the greatest hammer blow allowed", "hammer_blow is the greatest "
                          "blow the balance masses may strike the rails with")}


def _load(t: Tables, one: dict, key: str, cylinders: int) -> float | None:
    """``key``'s load on a wheel (N), positive, in a file whose balance planes (the wheels)
    balance a fraction of the reciprocating mass; None where it is not given."""
    if key not in one:
        return None
    what, why = _LOADS[key]
    load = t.number(one, key, "engine", what)
    if not load > 0:
        raise t.fail(f"{what} must be positive, got {load:g} N", "engine", key)
    if cylinders < 2 or not t.entries("balance") or "balanced" not in one:
        raise t.fail(f"{why}: it goes with [[balance]] planes (the wheels) and a fraction "
                     "balanced", "engine", key)
    return load


def engine_speed(t: Tables, one: dict, metre: float, speed: Callable[[Tables, str], float],
                 optional: bool = False) -> float | None:
    """An engine's speed in rad/s: its ``speed``, or, as the books give a locomotive's, its
    ``road_speed`` (km/h) on driving wheels of ``wheel_diameter``: ω = v/(D/2). None where
    neither is given and the engine is ``optional`` about it: a locomotive whose balance
    masses (m·r, free of ω) and lift speed are asked, the speed being the unknown. ``speed``
    reads a table's own ``speed`` (in its [units]), as a rotor's is read."""
    if "speed" not in one and "road_speed" not in one:
        if optional:
            return None
        raise t.fail("[engine] needs speed = … (rpm with [units] speed = \"rpm\", else rad/s) "
                     "or road_speed = … (km/h) with wheel_diameter: its forces (N) and couples "
                     "(N·m) are m·r·ω²", "engine", None)
    if "road_speed" not in one:           # a wheel_diameter alone sizes the wheels (a lift)
        return speed(t, "engine")
    if "speed" in one:
        raise t.fail("a locomotive's speed is speed = …, or road_speed = … (km/h) with "
                     "wheel_diameter = …, not both", "engine", "road_speed")
    if "wheel_diameter" not in one:
        raise t.fail("road_speed (km/h) gives the cranks' speed on the driving wheels: give "
                     "their wheel_diameter with it", "engine", "road_speed")
    v = t.number(one, "road_speed", "engine", "the road speed")
    d = t.number(one, "wheel_diameter", "engine", "the wheels' diameter")
    if not (v > 0 and d > 0):
        key = "road_speed" if not v > 0 else "wheel_diameter"
        raise t.fail(f"the {key.replace('_', ' ')} must be positive, got "
                     f"{v if key == 'road_speed' else d:g}", "engine", key)
    return v / 3.6 / (d * metre / 2)
