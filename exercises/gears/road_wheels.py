"""A car's differential as the books pose it: ``[road]`` gives the car's speed round a
curve, the curve's mean radius, the track and the road wheels' diameter, and names the two
members that carry the road wheels; their two speeds are the differential's two given
speeds.

On a curve of mean radius R the car turns about the curve's centre at v/R, so a road wheel
whose path has radius R ± t/2 rolls at v·(R ± t/2)/R and turns at that over its own radius
r: ω = v·(R ± t/2)/(R·r). Read by :class:`~.train_file._Reader` through
:class:`~.train_inputs.InputTables`, whose ``fail``, ``exact``, ``integer`` and ``known``
it uses.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from math import pi
from typing import Any

from tarsim.constructions.gears.train import SpeedUnits
from tarsim.constructions.narration import Phrase, Word, phrase, significant
from tarsim.constructions.units import LENGTH_UNITS

__all__ = ["ROAD_KEYS", "RoadTables", "wheel_speed"]

_KEYS = ("road_speed", "curve_radius", "track", "wheel_diameter", "outer", "inner", "sense")
ROAD_KEYS = _KEYS[:-1]
"""The road's own settings (``sense`` is an input's too): found in ``[input]``, they are
sent to ``[road]``."""
_FIGURES = 10
"""An rpm speed, v/(2π·r) turns a second, has π in it, and a gear train's numbers are exact
fractions: it is taken at ten significant figures, far below the four a book states."""


def wheel_speed(road_speed: Fraction, curve_radius: Fraction, side: Fraction,
                wheel_radius: Fraction) -> Fraction:
    """The road wheel's speed (rad/s) whose path is ``side`` (m) off the car's centre line,
    + out and − in, on a curve of mean ``curve_radius`` (m) at ``road_speed`` (m/s):
    ω = v·(R + side)/(R·r).

    >>> wheel_speed(Fraction(15), Fraction(30), Fraction(3, 4), Fraction(3, 8))
    Fraction(41, 1)
    """
    return road_speed * (curve_radius + side) / (curve_radius * wheel_radius)


@dataclass(frozen=True)
class _Road:
    """The road's data, each in SI (m/s, m) exactly, and the lengths as the file gives them."""

    kmh: Fraction
    radius: Fraction
    track: Fraction
    wheel: Fraction
    metre: Fraction


class RoadTables:
    """The reader's part for ``[road]``."""

    def road(self, units: SpeedUnits) -> tuple[int, Fraction, tuple[int, Fraction]]:
        """The two road wheels' members and speeds, in ``units.speed`` and the sense the
        file gives (ccw where none): the outer first, as (member, speed, (member,
        speed)), the form two ``[[input]]`` tables give; ``road_said`` gets the steps."""
        t = self.data["road"]
        if not isinstance(t, dict):
            raise self.fail("[road] must be a table: road_speed = 54 (km/h), curve_radius, "
                            "track, wheel_diameter, outer = 3, inner = 4", "road")
        if "input" in self.data:
            raise self.fail("[road] gives the two road wheels' speeds: leave out [input] "
                            "(or give the two speeds in [[input]] and no [road])", "input")
        self.known(t, _KEYS, "road")
        for k in _KEYS[:-1]:
            if k not in t:
                raise self.fail(f"{k} is missing: road_speed (km/h); curve_radius, "
                                f"track, wheel_diameter ({units.length}); outer and inner, "
                                "the members carrying the road wheels", "road")
        data = {k: self.exact(t[k], f"the road's {k}", "road", k) for k in _KEYS[:4]}
        for k, v in data.items():
            if v <= 0:
                raise self.fail(f"the road's {k} must be positive, got {float(v):g}", "road", k)
        outer = self.integer(t["outer"], "the outer wheel's member", "road", "outer")
        inner = self.integer(t["inner"], "the inner wheel's member", "road", "inner")
        if outer == inner:
            raise self.fail(f"outer and inner are both member {outer}: name the two members "
                            "that carry the road wheels (the two axle gears)", "road", "inner")
        if data["curve_radius"] <= data["track"] / 2:
            unit = units.length
            raise self.fail(f"a curve radius of {float(data['curve_radius']):g} {unit} is not "
                            f"more than half the track ({float(data['track'] / 2):g} {unit}): "
                            "the inner wheel would not go round; give the mean radius",
                            "road", "curve_radius")
        sense = t.get("sense", "ccw")
        if sense not in ("cw", "ccw"):
            raise self.fail(f"unknown sense '{sense}'; use cw or ccw", "road", "sense")
        road = _Road(data["road_speed"], data["curve_radius"], data["track"],
                     data["wheel_diameter"], Fraction(str(LENGTH_UNITS[units.length])))
        speeds = [self._wheel(road, units, side, sense) for side in (1, -1)]
        self.road_said = [_said_car(road, units),
                          *(_said_wheel(n, side, road, units, w, sense)
                            for n, side, w in ((outer, 1, speeds[0]), (inner, -1, speeds[1])))]
        return outer, speeds[0], (inner, speeds[1])

    @staticmethod
    def _wheel(road: _Road, units: SpeedUnits, side: int, sense: str) -> Fraction:
        """One wheel's speed in ``units.speed``, signed by ``sense``."""
        w = wheel_speed(road.kmh * Fraction(5, 18), road.radius, side * road.track / 2,
                        road.wheel / 2 * road.metre)
        if units.speed == "rpm":
            w = Fraction(f"{float(w) * 30 / pi:.{_FIGURES}g}")
        return w if sense == "ccw" else -w


def _said_car(road: _Road, units: SpeedUnits) -> Phrase:
    """The car's step: its speed in m/s and its wheels' radius in m."""
    return phrase("gears.road_car", kmh=_text(road.kmh), v=_text(road.kmh * Fraction(5, 18)),
                  R=_text(road.radius), t=_text(road.track), d=_text(road.wheel),
                  unit=units.length, r=_text(road.wheel / 2 * road.metre))


def _said_wheel(n: int, side: int, road: _Road, units: SpeedUnits, w: Fraction,
                sense: str) -> Phrase:
    """A wheel's step: its path's radius and its speed, as the given speed it becomes."""
    path = road.radius + side * road.track / 2
    return phrase("gears.road_outer" if side > 0 else "gears.road_inner", n=n,
                  path=_text(path), unit=units.length, w=_text(abs(w)), speed=units.speed,
                  sense=Word(sense), about="≈ " if units.speed == "rpm" else "= ")


def _text(v: Any) -> str:
    """A number of the road's as steps.md states it, at six significant figures (15, 0.375,
    391.521)."""
    return significant(float(v))
