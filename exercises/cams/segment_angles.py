"""A segment's angle as a cam file gives it: in degrees, as the rest of the turn, or by the
time it takes, as the books give it ("rises 35 mm in 0.05 s" at 300 rpm).

A time t is turned into the cam's angle β = ωt at the cam's speed (at N rpm, β = 6Nt
degrees, exact in the file's own numbers); the segment keeps its time for the steps to say.
A segment gives its angle or its time, never both, and a time needs the cam's speed.
"""

from __future__ import annotations

import math
from typing import Any

__all__ = ["degrees_per_second", "segment_angle", "rest_angle", "refuse_untimed_speed"]


def degrees_per_second(rate: float, speed: str) -> float:
    """The cam's turn in degrees per second at ``rate`` in ``speed`` ("rpm" or "rad/s"):
    360/60 = 6 per rpm, exactly, so that 0.05 s at 300 rpm is 90° and not 90.00000000000001.

    >>> degrees_per_second(300, "rpm"), degrees_per_second(math.pi, "rad/s")
    (1800.0, 180.0)
    """
    return rate * 6.0 if speed == "rpm" else math.degrees(rate)


def segment_angle(t: dict[str, Any], i: int, turn: float, number, fail
                  ) -> tuple[float, float | None]:
    """The ``i``-th segment's angle (degrees) and the time it was given by (s, or None),
    the cam turning ``turn`` degrees a second.

    Raises
    ------
    InputError
        Through ``fail``: both an angle and a time, or a time not more than 0.
    """
    if "time" not in t:
        return number(t, "angle", "segment", "a segment's angle", i), None
    if "angle" in t:
        raise fail("a segment gives its angle or its time, not both: keep one", "segment",
                   "time", i)
    time = number(t, "time", "segment", "a segment's time", i)
    if time <= 0:
        raise fail(f"a segment's time must be more than 0 s, got {time:g} s", "segment",
                   "time", i)
    return time * turn, time


def rest_angle(raw: list, turn: float, number, fail) -> float:
    """The angle of the one segment whose angle is "rest" (as the books say "dwell for the
    rest of the revolution"): 360° less the others'; 0 where none is."""
    rests = [i for i, t in enumerate(raw) if isinstance(t, dict) and t.get("angle") == "rest"]
    if not rests:
        return 0.0
    if len(rests) > 1:
        raise fail("only one segment may take the rest of the turn", "segment", "angle",
                   rests[1])
    taken = sum(segment_angle(t, i, turn, number, fail)[0]
                for i, t in enumerate(raw) if i != rests[0] and isinstance(t, dict))
    if not taken < 360:
        raise fail(f"the other segments take {taken:g}°, leaving no rest of the turn",
                   "segment", "angle", rests[0])
    return 360.0 - taken


def refuse_untimed_speed(cam: dict[str, Any], raw: Any, fail) -> None:
    """Refuse, at the first segment given by its time, a cam that gives no speed to turn
    that time into an angle."""
    if "speed" in cam or not isinstance(raw, list):
        return
    for i, t in enumerate(raw):
        if isinstance(t, dict) and "time" in t:
            raise fail(f"segment {i + 1} is given by its time, and [cam] gives no speed to turn "
                       "it into an angle: give the cam's speed (speed = 300)", "segment",
                       "time", i)
