"""A linkage's answers in words: as steps.md's and the worked page's tables set them, and as
the terminal's check lines print them.

A quantity is in results.json's shape (SI); here it is said in the file's units and the
language being spoken, to the figures its place can be read to: six in steps.md, four
(:data:`DRAFTING`) on a drawing.
"""

from __future__ import annotations

import math

from tarsim.constructions.asks import (EFFORTS, MOMENTS, Distance, Equivalent,
                                       MechanicalAdvantage, Ratio, Rubbing, TransmissionAngle,
                                       parse_ask, symbol)
from tarsim.constructions.checks import Quantity
from tarsim.constructions.linkages.velocity_drawing import method_words
from tarsim.constructions.narration import numerals, speaking, words

from ..checked import check_line

__all__ = ["DRAFTING", "show", "overall_text", "answer_line"]

DRAFTING = 4
"""Significant figures of a number set on a figure: what a drawing can be read to."""


def overall_text(name: str, v: dict, units) -> str:
    """A whole-mechanism answer in the file's units, in the language spoken: "65 mm < AB <
    135 mm (crank-rocker)"."""
    def length(metres: float) -> str:
        return numerals(units.length_text(metres))

    if "class" in v and "low" in v:
        span, kind = name[len("range_"):], words(v["class"])
        if v["low"] == v["high"]:
            return words("{span} = {length} only ({kind})", span=span, length=length(v["low"]),
                         kind=kind)
        hi = "" if v["high"] is None else f" < {length(v['high'])}"
        return f"{length(v['low'])} < {span}{hi} ({kind})"
    if "here" in v:
        return words("{value} ({here} at this position)", value=numerals(str(v["value"])),
                     here=numerals(str(v["here"])))
    if "class" in v:
        return words(v["class"])
    if "point" in v:
        return length(v["value"])
    if "by_inspection" in v:
        return words("{value} ({inspection} by inspection, {kennedy} by Kennedy; {far} at "
                     "infinity)", value=numerals(str(v["value"])),
                     inspection=numerals(str(v["by_inspection"])),
                     kennedy=numerals(str(v["by_kennedy"])),
                     far=numerals(str(v.get("far_centres", 0))))
    if "crank_angle" in v:                              # A_P_zero, V_P_max: where in the turn
        def deg(x: float) -> str:
            return numerals(f"{x:.6g}°")

        where = words("{angle} from the dead centre (crank at {crank})",
                      angle=deg(v["value" if "zeros" in v else "angle"]),
                      crank=deg(v["crank_angle"]))
        if "zeros" in v:
            return where
        return words("{speed} at {where}", speed=numerals(
            f"{v['value'] / units.metres:.6g} {units.length}/s"), where=where)
    if name.startswith("swing_"):                       # a lever's swing, its inclination
        swing = numerals(f"{math.degrees(v['value']):.5g}°")
        if "inclination" not in v:
            return swing
        return words("{swing} ({tilt} from the line of centres)", swing=swing,
                     tilt=numerals(f"{math.degrees(v['inclination']):.5g}°"))
    if "slow_deg" in v:
        return numerals(f"{v['value']:.6g} ({v['slow_deg']:.5g}° / {v['quick_deg']:.5g}°)")
    return numerals(f"{v['value']}")


def _direction(x: float, y: float) -> float:
    """A vector's angle in degrees, (−180°, 180°]: a leftward vector reads 180° whatever the
    sign of its rounding-noise y, and a direction within 1e-9° of 0 reads 0."""
    deg = math.degrees(math.atan2(y, x))
    if deg <= -180.0 + 1e-9:
        return 180.0
    return 0.0 if abs(deg) < 1e-9 else deg


def show(v: dict, units, name: str = "", figures: int = 6) -> str:
    """A quantity in the file's units, for the results tables; ``name`` tells its kind.

    Numbers are set to ``figures`` significant figures (a figure's table takes 4, drafting
    precision; steps.md 6) with a true minus, and a coordinate that is rounding noise
    beside the other (a centre at (−3e−14, −500)) is set as 0. The words and digits are the
    language being spoken; units keep their symbols (m/s, N·m), as tables print them.
    """
    def _num(x: float, spec: str = ".6g") -> str:
        return numerals(_number(x, spec))

    s = units.metres
    spec = f".{figures}g"
    if "point" in v:
        x, y = _quiet_pair(v["point"])
        at = f"({_num(x / s, spec)}, {_num(y / s, spec)}) {units.length}"
        # a point with its speed: the least velocity along a link, and how far along it
        if "value" not in v:
            return at
        what = f"{_num(v['value'] / s, spec)} {units.length}/s"
        if "along" not in v:
            return words("{what} at {where}", what=what, where=at)
        return words("{what} at {where}, {along} from {point}", what=what, where=at,
                     along=f"{_num(v['along'] / s, spec)} {units.length}", point=v["from"])
    if "undefined" in v:
        return words("any point (no relative motion)")
    if v.get("at_infinity"):
        dx, dy = _quiet_pair(v["direction"])
        return words("at infinity, direction ({dx}, {dy})", dx=_num(dx, '.4f'), dy=_num(dy, '.4f'))
    def pointing(what: str) -> str:
        """``what`` and the way its vector points: none for a nil one, which points nowhere."""
        x, y = v["vector"]
        if x == 0.0 and y == 0.0:
            return what
        return words("{what} at {where}", what=what, where=f"{_num(_direction(x, y), '.4g')}°")

    if "vector" in v and name.startswith("F_"):        # a joint force, in newtons
        return pointing(f"{_num(v['value'], spec)} N")
    if name.startswith("T") and name[1:2] in "_0123456789" and name != "T":
        w = v["value"]                                  # a couple or the driving torque
        return f"{_num(w, spec)} N·m{_sense(w)}"
    if name == "rod_radius_of_gyration":                # a length about the rod's G
        return f"{_num(v['value'] / s, spec)} {units.length}"
    if name in EFFORTS:                                 # an engine's effort, signed
        unit = "N·m" if name in MOMENTS else "rad/s" if name == "reversal_speed" else \
            "rad/s²" if name == "flywheel_alpha" else "N"
        # a moment is signed as T2 is, CCW +, and says its sense the same way
        sense = _sense(v["value"]) if name in MOMENTS else ""
        if name == "reversal_speed":                    # a speed, with the books' rpm
            sense = f" ({_num(v['value'] * 60 / math.tau, spec)} rpm)"
        return f"{_num(v['value'], spec)} {unit}{sense}"
    if "vector" in v:
        per = "/s²" if name.startswith("A") else "/s"     # A_B, A_cor_B, An_B/A, A_slide_B
        return pointing(f"{_num(v['value'] / s, spec)} {units.length}{per}")
    w = v["value"]
    kind = type(parse_ask(name)) if name else None
    if kind in (Ratio, MechanicalAdvantage):
        return _num(w, spec)
    if kind in (Distance, Equivalent):
        return f"{_num(w / s, spec)} {units.length}"
    if kind is Rubbing:
        return f"{_num(w / s, spec)} {units.length}/s"
    if kind is TransmissionAngle:
        return f"{_num(math.degrees(w), spec)}°"
    return f"{_num(w, spec)} rad/s" + ("²" if name.startswith("alpha") else "") + _sense(w)


def _sense(w: float) -> str:
    """" (ccw)" or " (cw)" after a signed rate, in the language being spoken; "" for 0."""
    return f" ({words('ccw' if w > 0 else 'cw')})" if w else ""


def answer_line(name: str, q: Quantity, units, *, whole: bool = False) -> str:
    """One answer as ``solve`` prints it: the value with its unit and sense, then its check.
    ``whole`` marks an answer about the mechanism as a whole (DOF, time ratio, a range).

    >>> from types import SimpleNamespace as Q
    >>> from tarsim.constructions.units import Units
    >>> print(answer_line("omega3", Q(value={"value": -2.578}, rel_error=1.3e-16,
    ...                               tolerance=1e-9, method="velocity polygon"), Units("m")))
    ω3 = −2.578 rad/s (cw)               check ok 1.3e-16   velocity polygon
    """
    with speaking("en"):                    # the terminal's lines are English
        if not whole:
            answer = f"{symbol(name)} = {show(q.value, units, name)}"
        elif name.startswith("range_"):    # the text names the span: "65 mm < AB < 135 mm"
            answer = overall_text(name, q.value, units)
        else:
            label = {"dof": "DOF", "grashof": "Grashof class",
                     "n_centres": "instant centres"}.get(name, name.replace("_", " "))
            if name.endswith(("_zero", "_max")) and "crank_angle" in q.value:
                label = name[:-5] + " = 0 at" if name.endswith("_zero") else \
                    "greatest " + name[:-4] + " ="     # A_P = 0 at …, greatest V_P = …
                answer = f"{label} {overall_text(name, q.value, units)}"
            else:
                answer = f"{label} = {overall_text(name, q.value, units)}"
    return check_line(answer, width=36, passed=q.rel_error <= q.tolerance,
                      against=f"{q.rel_error:.1e}", method=method_words(q.method),
                      failed=f"check FAILED (tolerance {q.tolerance:.1e})")


def _quiet_pair(xy) -> tuple[float, float]:
    big = max(abs(xy[0]), abs(xy[1]))
    return tuple(0.0 if abs(c) <= 1e-9 * big else c for c in xy)


def _number(x: float, spec: str = ".6g") -> str:
    """``x`` as the tables print it: a true minus sign, and never "−0"."""
    text = format(x, spec)
    if text.startswith("-") and float(text) == 0.0:
        text = text[1:]
    return text.replace("-", "−")
