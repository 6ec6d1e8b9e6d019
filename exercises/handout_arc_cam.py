"""A cam of arcs' problem sheet (:mod:`.handout`): the cam as its file gives it (the base
circle, the lift to the apex, the nose or the angle of lift where given) with the follower
at the apex, at the scale the solution draws its outline at; its data and what is asked,
and no size or motion the construction finds."""

from __future__ import annotations

import math

from tarsim.constructions.narration import unit_words, words
from tarsim.graphics.figure import Figure
from tarsim.graphics.handout import Line, compose_handout, draw_statement

from .handout_text import math_text, number

__all__ = ["arc_cam_sheets"]

_ASKED = {
    "nose_distance": "the nose's distance OQ from the cam's centre",
    "nose_radius": "the nose's radius r₂",
    "angle_of_lift": "the angle of lift α",
    "flank_radius": "the flank's radius R",
    "flank_angle": "the cam's turn φ while the follower is on the flank",
    "a_lift_start": "the follower's acceleration at the beginning of the lift",
    "v_max": "the follower's greatest velocity",
    "a_flank_end": "its acceleration at the end of the flank",
    "a_nose_start": "its acceleration at the start of the nose",
    "a_apex": "its acceleration at the apex",
    "a_flank_max": "its greatest acceleration on the flank and on the nose",
}
"""How the sheet asks each result of a cam of arcs (by its key in results.json)."""

_GIVES = {"nose_radius": "nose_radius", "angle": "angle_of_lift",
          "action_angle": "angle_of_lift", "flank_radius": "flank_radius", "lift": "lift"}
"""The result a key of the file gives, so that it is not asked."""


def arc_cam_sheets(ex, sheet: tuple[float, float]) -> list[Figure]:
    """A cam of arcs' sheet: the cam as given, the data, and what is asked."""
    from tarsim.graphics.handout_cam import draw_given_arcs

    from .chapters import chapter_of

    sol = chapter_of(ex).solve(ex)
    drawing = draw_given_arcs(words("{name}: {what}", name=ex.name, what=words("the cam")),
                              ex.cam, ex.given, unit=ex.length_unit, metre=_metre(ex))
    asked = [k for k in sol.results["quantities"]]
    statement = draw_statement(_given_arcs(ex) + _asked_arcs(ex, asked))
    return compose_handout(words("{name}: {what}", name=ex.name, what=words("problem sheet")),
                           [drawing, statement], sheet=sheet)


def _metre(ex) -> float:
    from tarsim.constructions.units import LENGTH_UNITS

    return LENGTH_UNITS[ex.length_unit]


def _given_arcs(ex) -> list[Line]:
    """The cam as its file gives it: its kind, base circle, the sizes given, the follower,
    its speed and sense."""
    cam, metre, mm = ex.cam, _metre(ex), unit_words(ex.length_unit)

    def length(symbol: str, x: float) -> str:
        return math_text(f"{symbol} = {number(x / metre)}") + f" {mm}"

    out = [Line(words("Given"), heading=True),
           Line(words("a {kind} cam", kind=words(cam.kind))),
           Line(words("base circle radius {r}", r=length("r₁", cam.base)))]
    faces = 180 - 2 * math.degrees(cam.alpha)          # the faces lean α off the axis
    sizes = {"nose_radius": lambda: words("nose radius {r}", r=length("r₂", cam.nose)),
             "lift": lambda: words("lift {h}", h=length("h", cam.lift)),
             "angle": lambda: words("angle of lift {a}", a=math_text(
                 f"α = {number(math.degrees(cam.alpha))}°")),
             "action_angle": lambda: words("angle of action {a}", a=math_text(
                 f"{number(2 * math.degrees(cam.alpha))}°")),
             "faces_angle": lambda: words("the angle between the tangential faces {a}",
                                          a=math_text(f"{number(faces)}°")),
             "flank_radius": lambda: words("flank radius {r}", r=length("R",
                                                                      cam.flank_radius))}
    out += [Line(sizes[k]()) for k in ex.given if k in sizes]
    follower = ("flat-faced" if cam.flat else "roller" if cam.roller else "knife-edge")
    said = words("follower: {kind}", kind=words(follower))
    if cam.roller:
        said += words(", ") + words("roller radius {r}", r=length("r", cam.roller))
    out.append(Line(said + words(", ") + words("on a line through the cam's centre")))
    rpm = ex.speed_unit == "rpm"
    speed = abs(ex.omega) * 30 / math.pi if rpm else abs(ex.omega)
    out.append(Line(words("the cam turns at {speed}", speed=math_text(number(speed))
                          + f" {unit_words('rpm' if rpm else 'rad/s')} "
                          + words("cw" if ex.omega < 0 else "ccw"))))
    if ex.mass:
        out.append(Line(words("the follower's mass {m} kg", m=math_text(number(ex.mass)))))
    return out


def _asked_arcs(ex, keys: list[str]) -> list[Line]:
    """What is asked, each result once in the course's words; a size the file gives is not
    asked, and the motion at a cam angle is asked by the angle."""
    given = {_GIVES[k] for k in ex.given if k in _GIVES}
    if "faces_angle" in ex.given:
        given.add("angle_of_lift")
    out = [Line(words("Find"), heading=True)]
    out += [Line(words(_ASKED[k])) for k in keys
            if k in _ASKED and k not in given and k != "a_nose_max"]
    out += [Line(words("its lift, velocity and acceleration {theta} after the lift begins",
                       theta=math_text(f"{number(t)}°"))) for t in ex.at]
    return out
