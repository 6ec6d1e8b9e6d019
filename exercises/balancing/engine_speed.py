"""The lines that say at what speed an engine's forces and couples are given: the speed as
the file's number was read (rad/s unless ``[units] speed`` says otherwise), the lift speed
found where a locomotive's file gives none, or none at all.

A locomotive's balance masses are m·r products, free of ω, and its lift speed
ω = √(P/(B·b)) follows from them and the dead load P: a book that asks both gives no speed,
and asks the swaying couple "at the speed found". Each force and couple is then given at
that speed, and the lines say so first.
"""

from __future__ import annotations

from tarsim.constructions.narration import numeral, words

__all__ = ["speed_lines"]


def speed_lines(ex) -> list[str]:
    """The line naming the speed an engine's forces are taken at, where it is not plain:
    read as rad/s by default, the lift speed found, or no speed at all."""
    e = ex.engine
    if e is None:
        return []
    if e.at_lift:
        road = words(", {road} km/h on the wheels", road=numeral(e.speed * e.wheel / 2 * 3.6)) \
            if e.wheel is not None else ""
        return [words("no speed is given: every force and couple below is at the lift speed "
                      "found, ω = {speed} rad/s", speed=numeral(e.speed)) + road]
    if e.speed is None:
        return [words("no speed is given: the balance masses need none (m·r); each force and "
                      "couple is given × ω² (kg·m, kg·m²), as a rotor's resultant is, and none "
                      "in N")]
    if ex.speed_default:
        return [words("ω = {speed} rad/s (read as rad/s; write [units] speed = \"rpm\" for rpm)",
                      speed=numeral(e.speed))]
    return []
