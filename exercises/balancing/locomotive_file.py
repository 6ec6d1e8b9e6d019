"""A locomotive's file: its driving wheels' diameter and dead load, and the engine's speed
as the books give it, ``speed``, a ``road_speed`` (km/h) on wheels of ``wheel_diameter``,
or none where the speed is the unknown (the balance masses need none, and a dead load gives
the lift speed). Every failure is one line naming file:line."""

from __future__ import annotations

from collections.abc import Callable

from ..table_file import Tables

__all__ = ["engine_speed", "read_wheel"]


def read_wheel(t: Tables, one: dict, metre: float, cylinders: int
               ) -> tuple[float | None, float | None]:
    """A locomotive's wheel diameter (m) and the dead load on each driving wheel (N), where
    the file gives them; the load only where balance masses in the wheels strike the rails."""
    wheel = t.number(one, "wheel_diameter", "engine", "the wheels' diameter") * metre \
        if "wheel_diameter" in one else None
    if "dead_load" not in one:
        return wheel, None
    load = t.number(one, "dead_load", "engine", "the dead load on a wheel")
    if not load > 0:
        raise t.fail(f"the dead load on a wheel must be positive, got {load:g} N", "engine",
                     "dead_load")
    if cylinders < 2 or not t.entries("balance") or "balanced" not in one:
        raise t.fail("dead_load is what a hammer blow lifts a wheel against: it goes with "
                     "[[balance]] planes (the wheels) and a fraction balanced", "engine",
                     "dead_load")
    return wheel, load


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
