"""Read a punching press as the books give it (``[punch]``): the energy a hole takes (or the
energy per unit of sheared area, with the hole's diameter and the plate's thickness), how
often a hole is punched (``holes_per_hour``, ``holes_per_minute`` or the ``period`` in s; or
the motor's ``power``, a hole every E/P),
and how long the punching takes (``punching_time`` in s, or ``punching_fraction`` of the
period). Friction's share of the punching work (``losses = 0.2``: the motor and flywheel
give 1.2 times it) or the punch's ``efficiency`` (0.8: 1/0.8 times it) may be given, one
of them. Its flywheel is asked in ``[flywheel]`` as any other's."""

from __future__ import annotations

import math
import re
from typing import Any

from tarsim.constructions.errors import InputError
from tarsim.constructions.forces.flywheel import Punch
from ..file_numbers import file_number
from ..table_file import Tables
from .flywheel_wheel import read_length

__all__ = ["PUNCH_KEYS", "read_power", "read_punch"]

PUNCH_KEYS = ("energy", "energy_per_area", "hole", "plate", "holes_per_hour",
              "holes_per_minute", "period", "power", "punching_time", "punching_fraction",
              "losses", "efficiency")


def _one_of(t: Tables, p: dict, keys: tuple[str, ...], what: str) -> str:
    given = [k for k in keys if k in p]
    if len(given) != 1:
        raise t.fail(f"[punch] gives {what}: one of {', '.join(keys)}" +
                     (f", not {' and '.join(given)}" if given else ""), "punch",
                     given[1] if given else None)
    return given[0]


def read_punch(t: Tables, p: dict, metre: float) -> dict[str, Any]:
    """The punch's diagram as an exercise holds it: its two areas (the flywheel giving up
    E·(1 − t/T) while it punches and taking it back), and the :class:`Punch`. The hole and
    plate are in the file's length unit (``metre`` m), or text with their own ("30 mm").

    Raises
    ------
    InputError
        Naming file:line and what to fix.
    """
    def positive(key: str, what: str) -> float:
        v = t.number(p, key, "punch", what)
        if not v > 0:
            raise t.fail(f"{what} must be positive, got {v:g}", "punch", key)
        return v

    way = _one_of(t, p, ("energy", "energy_per_area"), "the energy a hole takes")
    if way == "energy":
        for k in ("hole", "plate"):
            if k in p:
                raise t.fail(f"{k} is for energy_per_area (J per unit of sheared area, π·d·t); "
                             "energy is a hole's already", "punch", k)
        energy = positive("energy", "a hole's energy (J)")
    else:
        missing = [k for k in ("hole", "plate") if k not in p]
        if missing:
            raise t.fail("energy_per_area needs the hole's diameter (hole = 38) and the "
                         "plate's thickness (plate = 32), in the file's length unit",
                         "punch", "energy_per_area")
        # J per (length unit)² times the sheared area π·d·t, in the file's unit as it is
        energy = (positive("energy_per_area", "the energy per unit of sheared area")
                  * math.pi
                  * read_length(t, p, "hole", "punch", "the hole's diameter", metre, metre)
                  * read_length(t, p, "plate", "punch", "the plate's thickness", metre, metre))
    supply, losses, efficiency = 1.0, None, None
    if "losses" in p and "efficiency" in p:
        raise t.fail("give the frictional losses (a share of the punching work, 0.2) or the "
                     "efficiency (0.8), not both", "punch", "efficiency")
    if "losses" in p:
        losses = t.number(p, "losses", "punch", "the losses' share of the punching work")
        if not 0 <= losses < 10:
            raise t.fail(f"losses is friction's share of the punching work (0.2 for 1/5), "
                         f"from 0 and below 10; got {losses:g}", "punch", "losses")
        supply = 1 + losses
    if "efficiency" in p:
        efficiency = t.number(p, "efficiency", "punch", "the punch's efficiency")
        if not 0.1 <= efficiency <= 1:
            raise t.fail(f"the efficiency is the punching work over the energy supplied, from "
                         f"0.1 to 1 (0.8, not 80); got {efficiency:g}", "punch", "efficiency")
        supply = 1 / efficiency
    rate = _one_of(t, p, ("holes_per_hour", "holes_per_minute", "period", "power"),
                   "how often it punches (or the motor's power: a hole every E/P)")
    if rate == "power":
        period = energy * supply / read_power(t, p)
    else:
        period = {"holes_per_hour": lambda v: 3600 / v, "holes_per_minute": lambda v: 60 / v,
                  "period": lambda v: v}[rate](positive(rate, "the punching rate"))
    part = _one_of(t, p, ("punching_time", "punching_fraction"), "how long a punching takes")
    time = positive(part, "the punching's time") * (period if part == "punching_fraction"
                                                     else 1.0)
    if not time < period:
        raise t.fail(f"a punching takes less than the {period:g} s between holes, got {time:g} s",
                     "punch", part)
    punch = Punch(energy, period, time, rate == "power", supply, losses, efficiency,
                  tuple((k, p[k]) for k in PUNCH_KEYS if k in p))
    return {"areas": (-punch.delta_e, punch.delta_e), "drawn_areas": (-punch.delta_e,
                                                                     punch.delta_e),
            "energy_scale": 1.0, "punch": punch}


POWERS = {"W": 1.0, "kW": 1e3, "MW": 1e6}
_POWER = re.compile(r"\s*(.+?)\s*(W|kW|MW)\s*")


def read_power(t: Tables, p: dict, table: str = "punch",
               what: str = "the motor's power") -> float:
    """``p``'s power in W: a number in [units] power (W unless it says "kW") or "3 kW"
    as the books write it."""
    raw = p["power"]
    m = _POWER.fullmatch(raw) if isinstance(raw, str) else None
    try:
        v = (file_number(m[1], what) * POWERS[m[2]] if m
             else t.number(p, "power", table, what)
             * POWERS[t.data.get("units", {}).get("power", "W")])
    except (InputError, ValueError):
        raise t.fail(f"{what} is a number in W or \"3 kW\"; got {raw!r:.40}",
                     table, "power") from None
    if not v > 0:
        raise t.fail(f"{what} must be positive, got {raw!r:.40}", table, "power")
    return v
