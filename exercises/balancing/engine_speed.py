"""The lines that say at what speed an engine's forces and couples are given: the speed as
the file's number was read (rad/s unless ``[units] speed`` says otherwise), the lift speed
found where a locomotive's file gives none, or none at all.

A locomotive's balance masses are m·r products, free of ω, and its lift speed
ω = √(P/(B·b)) follows from them and the dead load P: a book that asks both gives no speed,
and asks the swaying couple "at the speed found". Each force and couple is then given at
that speed, and the lines say so first.
"""

from __future__ import annotations

from dataclasses import replace

from tarsim.constructions.balancing.engine import engine_kinds
from tarsim.constructions.narration import numeral, words
from ..checked import Checked

__all__ = ["at_lift_tagged", "per_omega", "speed_lines"]


def per_omega(e):
    """The engine, turning at 1 rad/s where no speed is given: its forces are then its
    polygons' m·r (kg·m), what the checks compare free of ω."""
    return e if e.speed is not None else replace(e, speed=1.0)


def at_lift_tagged(q: dict[str, Checked], e) -> dict[str, Checked]:
    """results.json's quantities, each force and couple (N, N·m) marked ``at_lift_speed``
    (rad/s) where the engine's speed is the lift speed found, the file giving none."""
    if e is None or not e.at_lift:
        return q
    forces = {kind.replace(" ", "_") for kind in engine_kinds(e)}
    tag = "at_lift_speed" if e.dead_load is not None else "at_hammer_blow_speed"
    return {k: replace(c, value={**c.value, tag: e.speed})
            if k in forces or c.value.get("unit") in ("N", "N·m") else c for k, c in q.items()}


def speed_lines(ex) -> list[str]:
    """The line naming the speed an engine's forces are taken at, where it is not plain:
    read as rad/s by default, the lift speed found, or no speed at all."""
    e = ex.engine
    if e is None:
        return []
    if e.at_lift:
        road = words(", {road} km/h on the wheels", road=numeral(e.speed * e.wheel / 2 * 3.6)) \
            if e.wheel is not None else ""
        if e.dead_load is None:
            return [words("no speed is given: every force and couple below is at the speed "
                          "found where the hammer blow reaches the greatest allowed, ω = "
                          "{speed} rad/s", speed=numeral(e.speed)) + road]
        return [words("no speed is given: every force and couple below is at the lift speed "
                      "found, ω = {speed} rad/s", speed=numeral(e.speed)) + road]
    if e.speed is None and ex.open is not None:
        return [words("no speed is given: the masses and angles found need none (m·r); each "
                      "force and couple is given × ω² (kg·m, kg·m²), and none in N")]
    if e.speed is None:
        return [words("no speed is given: the balance masses need none (m·r); each force and "
                      "couple is given × ω² (kg·m, kg·m²), as a rotor's resultant is, and none "
                      "in N")]
    if ex.speed_default:
        return [words("ω = {speed} rad/s (read as rad/s; write [units] speed = \"rpm\" for rpm)",
                      speed=numeral(e.speed))]
    return []
