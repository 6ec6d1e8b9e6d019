"""A link's moment of inertia from a pendulum test, as the books give a connecting rod's:
"suspended from the gudgeon pin it makes 8 oscillations in 22 s".

Hung from a point P a distance h from its centre of mass G, a link swings as a compound
pendulum of period T = 2π·√((k² + h²)/(g·h)), k its radius of gyration about G; so
k² = g·h·T²/(4π²) − h² and I_G = m·k². The point of suspension is a point of the link (the
pin it hangs from) or [x, y] in the link's own frame; hung on a knife edge in a pin's
``bore`` (its diameter), it swings about the bore's top, half the bore farther from G. g
is 9.81 m/s² whether or not the file's weights are drawn, for the test was made on the
earth.
"""

from __future__ import annotations

import math
from typing import Any, Callable

from tarsim.constructions.loads import GRAVITY, pendulum_radius
from ..file_numbers import file_number

__all__ = ["OSCILLATION_KEYS", "pendulum_inertia"]

OSCILLATION_KEYS = ("count", "seconds", "period", "about", "bore")


def pendulum_inertia(raw: Any, link, mass: float, centre: tuple[float, float], metre: float,
                     fail: Callable[[str], Exception]
                     ) -> tuple[float, str, tuple[float, float, str, bool]]:
    """Link ``link``'s I about its centre ``centre`` (its own frame, m) from ``oscillations
    = { count = 8, seconds = 22, about = "P" }`` (or ``period = 2.75``, s), and the words
    that say how: k from the compound pendulum, I = m·k²; and the test (T s, h m, the
    point as named, whether on a knife edge in its bore) for its step.

    Raises
    ------
    InputError
        By ``fail``: a key it does not know, a count, time or period that is not positive,
        a point of suspension the link has not or at its centre, a period too short for a
        pendulum hung there (T < 2π·√(h/g), the least a body hung h from G swings in).
    """
    if not isinstance(raw, dict):
        raise fail("oscillations is a table: { count = 8, seconds = 22, about = \"P\" } "
                   "(or period = 2.75, s), the link swinging hung from its point P")
    unknown = [k for k in raw if k not in OSCILLATION_KEYS]
    if unknown:
        raise fail(f"unknown setting '{unknown[0]}' in oscillations; expected "
                   f"{', '.join(OSCILLATION_KEYS)}")

    def positive(key: str, what: str) -> float:
        try:
            v = file_number(raw.get(key), what)
        except ValueError as e:
            raise fail(str(e)) from None
        if not v > 0:
            raise fail(f"{what} must be positive, got {v:g}")
        return v

    if ("period" in raw) == ("count" in raw or "seconds" in raw):
        raise fail("give the oscillations as count and seconds (8 in 22 s) or their period "
                   "(s), one of them")
    if "period" in raw:
        period = positive("period", "the period of one oscillation (s)")
    else:
        period = positive("seconds", "the time the oscillations take (s)") / positive(
            "count", "the number of oscillations")
    about = raw.get("about")
    if isinstance(about, str):
        if not link.carries(about):
            raise fail(f"{link.label} has no point '{about}' to hang from; its points are "
                       f"{', '.join(link.names)}")
        point, said = link.local(about), about
    elif isinstance(about, list) and len(about) == 2:
        try:
            point = tuple(file_number(c, "a point of suspension's coordinate") * metre
                          for c in about)
        except ValueError as e:
            raise fail(str(e)) from None
        said = f"[{file_number(about[0], '')}, {file_number(about[1], '')}]"
    else:
        raise fail("about is the point the link hangs from: a point of it (\"P\", the "
                   "gudgeon pin) or [x, y] in its own frame")
    h = math.dist(point, centre)
    if "bore" in raw:
        if not isinstance(about, str):
            raise fail("bore is the diameter of the pin's bore the knife edge is in: hang it "
                       "about a point of the link, about = \"P\"")
        # the knife edge bears on the top of the bore, G hanging below the pin's centre
        h += positive("bore", "the bore's diameter") * metre / 2
    if not h > 0:
        raise fail(f"{link.label} hangs from its centre of mass at {said}: a pendulum swings "
                   "about a point off it")
    least = 2 * math.pi * math.sqrt(h / GRAVITY)
    k = pendulum_radius(period, h)
    if not k > 0:
        raise fail(f"a body hung {h / metre:g} from its centre swings in at least "
                   f"2π·√(h/g) = {least:.4g} s, but the period is {period:.4g} s")
    return mass * k * k, (f"k = √(g·h·T²/(4π²) − h²) = {k / metre:.6g}, hung from {said}, "
                          f"h = {h / metre:.6g}, T = {period:.6g} s"), (period, h, said,
                                                                         "bore" in raw)
