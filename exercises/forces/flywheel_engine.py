"""A flywheel file's engine as the books give it rather than as a drawn diagram: by its power
and the coefficient of fluctuation of energy C_E (ΔE = C_E × the work done in a cycle), by
its strokes' works, each stroke's diagram a triangle, and as several cylinders whose
diagrams, each a cylinder's own, are set apart by their cranks and added.

A stroke's triangle stands on the stroke's base with its apex at mid-stroke, its height
2W/s (s the stroke's angle in rad), so that its area is the stroke's work W, as the books
draw a gas engine's compression and expansion. With ``power`` the works are ratios, scaled
so that they add to the work done in a cycle, P·t, t = cycle/ω the time a cycle takes (two
turns of a four-stroke engine). Each is turned into a table of points (or, for a formula,
a list of phases), so the diagram is then read, drawn and checked as any other.
"""

from __future__ import annotations

import math
from typing import Any

from ..table_file import Tables
from .flywheel_wheel import speeds
from .punch_file import read_power

__all__ = ["ENGINE_KEYS", "read_engine", "summed"]

ENGINE_KEYS = ("power", "energy_fluctuation", "strokes", "expansion_to_compression",
               "cylinders", "phases")
"""The [turning_moment] settings that give the engine as the books do, not as a diagram."""

_T = "turning_moment"


def _mean_speed(t: Tables, rad_s: float, key: str) -> float:
    """The mean speed (rad/s) ``[flywheel]`` gives: a power's work a cycle is P·cycle/ω."""
    fw = t.data.get("flywheel")
    got = speeds(t, fw, rad_s).get("speed") if isinstance(fw, dict) else None
    if got is None:
        raise t.fail(f"{key} needs the engine's mean speed for the time a cycle takes: give "
                     "[flywheel] speed = … (or its greatest and least speeds)", _T, key)
    return got


def read_engine(t: Tables, tm: dict, cycle_deg: float, rad_s: float) -> dict[str, Any]:
    """What the engine keys of ``[turning_moment]`` ``tm`` give, in SI: ``points`` (a table
    made of the strokes' triangles, or the cylinders' tables added), ``phases`` (each
    cylinder's lag, rad, for a formula), ``power`` (W), ``energy_coefficient`` (C_E given)
    and ``strokes`` (each stroke's work, J). The keys :func:`read_engine` does not handle
    (a formula, a table) are left to the caller, which reads them as usual."""
    out: dict[str, Any] = {}
    if "power" in tm:
        others = [k for k in ("torque", "points", "areas") if k in tm]
        if others:
            raise t.fail(f"power gives the work done in a cycle, for energy_fluctuation (C_E) "
                         f"or strokes; a diagram given by {others[0]} has its own mean: leave "
                         "power out", _T, "power")
        out["power"] = read_power(t, tm, _T, "the engine's power")
    if "energy_fluctuation" in tm:
        extra = [k for k in tm if k not in ("power", "energy_fluctuation", "cycle")]
        if "power" not in tm or extra:
            raise t.fail("energy_fluctuation (C_E) gives ΔE = C_E × the work done in a cycle: "
                         "give it with the engine's power alone (and the cycle, 720 for a "
                         "four-stroke engine)", _T, extra[0] if extra else "energy_fluctuation")
        ce = t.number(tm, "energy_fluctuation", _T, "the coefficient of fluctuation of energy")
        if not 0 < ce < 10:
            raise t.fail(f"C_E = ΔE/(work done in a cycle) is positive, got {ce:g}", _T,
                         "energy_fluctuation")
        _mean_speed(t, rad_s, "energy_fluctuation")
        return out | {"energy_coefficient": ce}
    if "strokes" in tm or "expansion_to_compression" in tm:
        out |= _strokes(t, tm, cycle_deg, rad_s, out.get("power"))
    elif "power" in tm:
        raise t.fail("power gives the work done in a cycle: give with it energy_fluctuation "
                     "(C_E) or the strokes' works, strokes = [0, -1, 3, 0]", _T, "power")
    if "cylinders" in tm or "phases" in tm:
        out["phases"] = _phases(t, tm, cycle_deg)
    return out


def _strokes(t: Tables, tm: dict, cycle_deg: float, rad_s: float,
             power: float | None) -> dict[str, Any]:
    """The strokes' works (J) and their triangles as a table of points."""
    if "strokes" in tm and "expansion_to_compression" in tm:
        raise t.fail("give the strokes' works, or expansion_to_compression, not both", _T,
                     "expansion_to_compression")
    if "torque" in tm or "points" in tm or "areas" in tm:
        raise t.fail("the strokes are the diagram: leave torque, points and areas out", _T,
                     "strokes" if "strokes" in tm else "expansion_to_compression")
    if "expansion_to_compression" in tm:
        ratio = t.number(tm, "expansion_to_compression", _T,
                         "the expansion stroke's work over the compression's")
        if not ratio > 1 or power is None:
            raise t.fail("expansion_to_compression (the expansion's work over the "
                         "compression's, more than 1) goes with the engine's power", _T,
                         "expansion_to_compression")
        # a four-stroke cycle: suction, compression, expansion, exhaust; a two-stroke's two
        raw = [0, -1, ratio, 0] if cycle_deg == 720 else [-1, ratio]
        if cycle_deg not in (360, 720):
            raise t.fail("expansion_to_compression is a two-stroke's cycle of 360° or a "
                         "four-stroke's of 720°; give other engines' strokes = […]", _T, "cycle")
        key = "expansion_to_compression"
    else:
        raw, key = tm["strokes"], "strokes"
        if not isinstance(raw, list) or not raw:
            raise t.fail("strokes lists each stroke's work in order (J, or ratios with the "
                         "power), the cycle shared equally, e.g. [0, -3000, 9000, 0]", _T, key)
    works = [t.number({"w": w}, "w", _T, f"stroke {i + 1}'s work") for i, w in enumerate(raw)]
    total = math.fsum(works)
    if not total > 0:
        raise t.fail(f"the strokes' works add to {total:g}: an engine does work over a cycle, "
                     "so the sum must be positive", _T, key)
    if power is not None:
        omega = _mean_speed(t, rad_s, key)
        cycle_work = power * math.radians(cycle_deg) / omega
        works = [w * cycle_work / total for w in works]
    span = math.radians(cycle_deg) / len(works)
    points = [(0.0, 0.0)]
    for i, w in enumerate(works):
        if w:
            points.append(((i + 0.5) * span, 2 * w / span))
        if i < len(works) - 1:
            points.append(((i + 1) * span, 0.0))
    return {"points": tuple(points), "strokes": tuple(works)}


def _phases(t: Tables, tm: dict, cycle_deg: float) -> tuple[float, ...]:
    """Each cylinder's lag (rad) behind the first, from ``cylinders`` (set equally over the
    cycle) or ``phases`` (degrees)."""
    if "cylinders" in tm and "phases" in tm:
        raise t.fail("give cylinders (set equally over the cycle) or phases (each cylinder's "
                     "lag, degrees), not both", _T, "phases")
    if "cylinders" in tm:
        n = tm["cylinders"]
        if not isinstance(n, int) or isinstance(n, bool) or not 1 <= n <= 24:
            raise t.fail(f"cylinders is how many, a whole number from 1 to 24, got {n!r:.20}",
                         _T, "cylinders")
        return tuple(math.radians(k * cycle_deg / n) for k in range(n))
    raw = tm["phases"]
    if not isinstance(raw, list) or not raw:
        raise t.fail("phases lists each cylinder's lag behind the first in degrees, "
                     "[0, 120, 240]", _T, "phases")
    out = [t.number({"p": p}, "p", _T, f"cylinder {i + 1}'s phase") for i, p in enumerate(raw)]
    return tuple(math.radians(p % cycle_deg) for p in out)


def summed(points: tuple[tuple[float, float], ...], torque, phases: tuple[float, ...],
           cycle: float) -> tuple[tuple[float, float], ...]:
    """One cylinder's table, ``torque`` its T(θ), added over the cylinders lagging by
    ``phases``: straight between its points, the sum is straight between every cylinder's
    points, so it is the table at all of them.

    >>> summed(((0.0, 1.0), (math.pi, -1.0)), math.cos, (0.0, math.pi), 2 * math.pi)
    ((0.0, 0.0), (3.141592653589793, 0.0))
    """
    angles: list[float] = []
    for a in sorted((p + lag) % cycle for p, _ in points for lag in phases):
        if not angles or a - angles[-1] > 1e-12 * cycle:
            angles.append(a)
    if cycle - angles[-1] <= 1e-12 * cycle and len(angles) > 1:
        angles.pop()                        # a cycle on: the first again
    return tuple((a, math.fsum(torque(a - lag) for lag in phases)) for a in angles)
