"""The given speeds and loads of a gear-train file: ``[input]`` (or two ``[[input]]``
tables, or a car's ``[road]``, :mod:`.road_wheels`), the input's torque or power, and the
train's efficiency; read by
:class:`~.train_file._Reader`, whose ``fail``, ``integer``, ``exact`` and ``known`` they
use."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from tarsim.constructions.gears.train import SpeedUnits
from .road_wheels import ROAD_KEYS, RoadTables

__all__ = ["InputTables"]

_POWERS = {"W": 1, "kW": 1000}
"""The power units a file may state, in W."""


class InputTables(RoadTables):
    """The reader's part for the given speeds and loads."""

    def inputs(self, units: SpeedUnits) -> tuple[int, Fraction | None,
                                                 tuple[int, Fraction] | None]:
        """The given speeds: ``[input]``, or two ``[[input]]`` tables where no member is
        fixed (the arm and a gear both turning; a sun and a ring both driven). The first
        is the input (its torque or power, if any); the second, if any, as (member,
        speed). A ``[road]`` gives the two road wheels' as the two."""
        if "road" in self.data:
            given = self.road(units)
            self.data["input"] = {}             # no load: the wheels' speeds alone
            return given
        raw = self.data.get("input")
        if isinstance(raw, list):
            if not 1 <= len(raw) <= 2:
                raise self.fail(f"{len(raw)} [[input]] tables: a train takes one given speed "
                                "with a fixed member, or two with none", "input", index=2)
            if len(raw) == 2:
                self.data["input"] = raw[0]     # the input's load is read from the first
                member, speed = self.input(units, raw[0], 0)
                other, more = self.input(units, raw[1], 1)
                if speed is None or more is None:
                    raise self.fail("two [[input]] tables each give a speed: speed = …",
                                    "input", index=int(more is None))
                for k in ("torque", "power"):
                    if k in raw[1]:
                        raise self.fail(f"give the {k} on the first [[input]], the driver",
                                        "input", k, 1)
                return member, speed, (other, more)
            self.data["input"] = raw = raw[0]
        return (*self.input(units, raw), None)

    def input(self, units: SpeedUnits, t: Any, index: int = 0
              ) -> tuple[int, Fraction | None]:
        """The member whose speed is given (any member but the fixed one, the output's
        shaft too), and its speed, CCW-positive; None where no speed is given (a file that
        asks only ratios or torques needs none)."""
        road = [k for k in t if k in ROAD_KEYS] if isinstance(t, dict) else []
        if road:
            raise self.fail(f"{road[0]} is the road's: give a car on a curve as [road] "
                            "(road_speed, curve_radius, track, wheel_diameter, outer, inner) "
                            "in place of [input]", "input", road[0], index)
        if not isinstance(t, dict) or "member" not in t:
            raise self.fail("give the driving member and its speed: member = 2, "
                            f"speed = 80 ({units.speed}), sense = \"cw\"", "input",
                            index=index)
        member = self.integer(t["member"], "the input member", "input", "member", index)
        if "speed" not in t:
            self.known(t, ("member", "speed", "sense", "torque", "power"), "input", index)
            return member, None
        speed = self.exact(t["speed"], "the input speed", "input", "speed", index)
        sense = t.get("sense", "ccw")
        if sense not in ("cw", "ccw"):
            raise self.fail(f"unknown sense '{sense}'; use cw or ccw", "input", "sense", index)
        if speed == 0 and index == 0:
            raise self.fail("the input speed is 0: nothing turns", "input", "speed")
        for k in t:
            if k not in ("member", "speed", "sense", "torque", "power"):
                raise self.fail(f"unknown input setting '{k}'; expected member, speed, sense, "
                                "torque (N·m) or power (W)", "input", k, index)
        return member, speed if sense == "ccw" else -speed

    def load(self, speed_given: bool = True) -> tuple[Fraction | None, Fraction | None]:
        """The input's torque (N·m) or power (W), if given: one of them, positive."""
        t = self.data["input"]
        given = [k for k in ("torque", "power") if k in t]
        if len(given) > 1:
            raise self.fail("give the input's torque or its power, not both", "input", "power")
        if not given:
            return None, None
        if given[0] == "power" and not speed_given:
            raise self.fail("the input's power gives its torque through its speed: give "
                            "speed = … in [input] too", "input", "power")
        v = self.exact(t[given[0]], f"the input {given[0]}", "input", given[0])
        if v <= 0:
            raise self.fail(f"the input {given[0]} must be positive: it drives the train "
                            "(its sense is the input's)", "input", given[0])
        units = self.data.get("units") or {}
        per = _POWERS.get(units.get("power", "W"), 1) if isinstance(units, dict) else 1
        return (v, None) if given[0] == "torque" else (None, v * per)

    def efficiency(self) -> Fraction:
        """The train's efficiency, 0 < η ≤ 1 (1, no losses, where none is given)."""
        if "efficiency" not in self.data:
            return Fraction(1)
        eta = self.exact(self.data["efficiency"], "the efficiency", "", "efficiency")
        if not 0 < eta <= 1:
            hint = f" (a percentage? write {float(eta) / 100:g})" if 1 < eta <= 100 else ""
            raise self.fail(f"an efficiency of {_shown(self.data['efficiency'])} is not one: "
                            f"give it as a fraction, 0 < efficiency ≤ 1{hint}", key="efficiency")
        return eta


def _shown(v: Any) -> str:
    """A value the file gave, as a refusal quotes it: a long integer short (1e+07)."""
    if isinstance(v, int) and not isinstance(v, bool) and abs(v) >= 1_000_000:
        digits = str(abs(v))
        return f"{'-' if v < 0 else ''}{digits[0]}.{digits[1:3]}e+{len(digits) - 1:02d}"
    return f"'{v!r}'" if isinstance(v, float) else repr(v)     # a float quoted as written
