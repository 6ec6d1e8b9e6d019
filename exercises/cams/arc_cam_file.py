"""Read a cam made of arcs: ``[cam] kind = "circular arc"`` (under a flat face) or
``"tangent"`` (under a roller), given as the books give them.

A circular-arc cam gives its base radius, nose radius, lift and the angle of lift (the
cam's turn from the start of the lift to the apex), or its flank's radius in place of the
angle. A tangent cam gives its base radius and two of its nose radius, lift and angle of
lift, or the angle between its tangential faces, 180° − 2α, in place of the angle of lift:
its flanks' tangency to both circles fixes the third (d cos α = r₁ − r₂ with
d = r₁ + h − r₂). Every failure is one line at its place in the file.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

from tarsim.constructions.cams.arc_cam import ArcCam
from tarsim.constructions.units import LENGTH_UNITS
from ..file_numbers import file_number
from ..names import named_in, read_names, renamed_field
from ..table_file import SPEEDS
from .cam_settings import book_follower, refuse_unknown

__all__ = ["ArcCamExercise", "parse_arc_cam", "eccentric_disc", "ARC_KINDS"]

ARC_KINDS = {"circular arc": ("flat-faced", "roller", "knife-edge"),
             "tangent": ("roller", "knife-edge")}
"""Each cam of arcs and the followers the books set on it (the first unless said)."""

_CAM_KEYS = ("kind", "base_radius", "base_diameter", "nose_radius", "lift", "angle",
             "action_angle", "faces_angle", "flank_radius", "speed", "sense")


_FOLLOWER_KEYS = ("kind", "radius", "diameter", "mass", "motion", "offset")
"""A cam of arcs' [follower] (motion and offset only as the books set it: translating on a
line through the cam's centre)."""


@dataclass(frozen=True)
class ArcCamExercise:
    """A cam of arcs (m, rad) turning at ``omega`` (rad/s, CCW +), with the cam angles
    (degrees from the start of the lift) its motion is asked at."""

    chapter: ClassVar[str] = "cams"

    id: str
    name: str
    source: str
    description: str
    cam: ArcCam
    omega: float
    length_unit: str = "mm"
    speed_unit: str = "rpm"
    at: tuple[float, ...] = ()
    given: tuple[str, ...] = ()
    """Which of the cam's sizes the file gives (the rest are found)."""
    names: tuple[tuple[str, str], ...] = ()
    mass: float = 0.0
    """The follower's mass (kg), where the file gives it: the spring must hold it to the
    nose against its greatest retardation."""
    paper: str = "A4"
    """The sheet its figures are drawn for and set on (``graphics.paper.PAPERS``),
    as ``--paper`` sets it."""

    def named_in(self, lang: str) -> ArcCamExercise:
        """The same exercise with the cam named in ``lang``, if its file does."""
        return named_in(self, lang)

    renamed = renamed_field

    @property
    def metre(self) -> float:
        """Metres in one of the file's length units."""
        return LENGTH_UNITS[self.length_unit]


def parse_arc_cam(tables, exercise_id: str, angles) -> ArcCamExercise:
    """The cam of arcs in ``tables`` (already read; ``angles`` reads [ask] at)."""
    data, fail, number = tables.data, tables.fail, tables.number
    length, speed = tables.units("mm", "rpm")
    metre = LENGTH_UNITS[length]
    cam = data["cam"]
    kind = cam["kind"]
    refuse_unknown(cam, _CAM_KEYS, f"a {kind} cam's [cam]", fail, "cam")
    if "segment" in data:
        raise fail(f"a {kind} cam's motion comes from its arcs: leave out the [[segment]] "
                   "tables", "segment")

    def size(key: str, what: str) -> float:
        v = number(cam, key, "cam", what)
        if not 0 < v < 1e6:
            raise fail(f"{what} must be positive, got {v:g}", "cam", key)
        return v * metre

    key = base_key(cam, fail) or "base_radius"
    r1 = size(key, "the base " + key[5:]) / (2 if key == "base_diameter" else 1)
    rate = number(cam, "speed", "cam", "the cam's speed")
    sense = cam.get("sense", "ccw")
    if sense not in ("cw", "ccw") or rate <= 0:
        raise fail("the cam turns at a positive speed, its sense cw or ccw", "cam", "sense")
    omega = rate * SPEEDS[speed] * (1 if sense == "ccw" else -1)
    roller, flat = _follower(data.get("follower") or {}, kind, metre, fail)
    given = tuple(k for k in ("nose_radius", "lift", "angle", "action_angle", "faces_angle",
                              "flank_radius")
                  if k in cam)
    if kind == "tangent":
        if "flank_radius" in cam:          # read as nothing, it would leave another cam
            raise fail("a tangent cam's flanks are straight: flank_radius is a circular arc "
                       "cam's; leave it out", "cam", "flank_radius")
        shape = _tangent(cam, r1, size, number, fail)
    else:
        shape = _circular(cam, r1, size, number, fail)
    made = ArcCam(kind, r1, *shape, roller, flat)
    ask = data.get("ask", {})
    takes = (f"a {kind} cam's [ask] table takes at = [20, 75] (the motion at those cam angles "
             "from the start of the lift)")
    if isinstance(ask, dict):
        refuse_unknown(ask, ("at",), "[ask]", fail, "ask", otherwise=takes)
    if not isinstance(ask, dict):
        raise fail(takes, "ask")
    at = angles(ask.get("at", []), fail)
    top = math.degrees(2 * made.alpha)
    for v in at:
        if v > top + 1e-9:
            raise fail(f"the lift and the return take {top:.4g}° of this cam's turn: a cam angle "
                       f"asked at is at most that, not {v:g}°", "ask", "at")
    return ArcCamExercise(exercise_id, str(data.get("name", exercise_id)),
                          str(data.get("source", "")), str(data.get("description", "")),
                          made, omega, length, speed, at, given,
                          read_names(data, tables.where, tables.filename),
                          mass=_mass(data.get("follower") or {}, number, fail))


def base_key(cam: dict[str, Any], fail) -> str | None:
    """Which of ``base_radius`` and ``base_diameter`` [cam] gives its base circle by (the
    books give a cam's least diameter as often as its radius), None if neither; both are
    refused at the diameter's line."""
    if "base_radius" in cam and "base_diameter" in cam:
        raise fail("give the base circle's radius or its diameter, not both", "cam",
                   "base_diameter")
    return next((k for k in ("base_diameter", "base_radius") if k in cam), None)


def eccentric_disc(tables, exercise_id: str, disc: tuple[float, float], follower, omega: float,
                   angles) -> ArcCamExercise:
    """An eccentric disc (radius and eccentricity in the file's unit) under a knife edge or
    a roller on a line through the shaft: all nose, from its lowest place (r₂ − e from the
    shaft) through the apex at 180°."""
    data, fail = tables.data, tables.fail
    length, speed = tables.units("mm", "rpm")
    metre = LENGTH_UNITS[length]
    if follower.oscillating or follower.offset:
        raise fail("an eccentric disc is worked under a follower translating on a line "
                   "through the shaft", "follower", "offset" if follower.offset else "motion")
    if "segment" in data:
        raise fail("an eccentric disc makes its own motion: leave out the [[segment]] tables",
                   "segment")
    radius, e = disc[0] * metre, disc[1] * metre
    made = ArcCam("eccentric", radius - e, radius, 2 * e, math.pi, follower.radius)
    ask = data.get("ask", {})
    takes = ("an eccentric disc's [ask] table takes at = [30, 90] (the motion at those cam "
             "angles from its lowest place)")
    if isinstance(ask, dict):
        refuse_unknown(ask, ("at",), "[ask]", fail, "ask", otherwise=takes)
    if not isinstance(ask, dict):
        raise fail(takes, "ask")
    return ArcCamExercise(exercise_id, str(data.get("name", exercise_id)),
                          str(data.get("source", "")), str(data.get("description", "")),
                          made, omega, length, speed, angles(ask.get("at", []), fail),
                          ("disc_radius", "eccentricity"),
                          read_names(data, tables.where, tables.filename))


def _mass(t: dict[str, Any], number, fail) -> float:
    """The follower's mass (kg) and its parts', where [follower] gives it; 0 where not."""
    if "mass" not in t:
        return 0.0
    m = number(t, "mass", "follower", "the follower's mass")
    if not 0 < m < 1e9:
        raise fail(f"the follower's mass must be positive, got {m:g} kg", "follower", "mass")
    return m


def _follower(t: dict[str, Any], kind: str, metre: float, fail) -> tuple[float, bool]:
    """The follower the cam of ``kind`` drives: its roller's radius (m; 0 for a knife edge
    or a flat face) and whether it is a flat face."""
    allowed = ARC_KINDS[kind]
    refuse_unknown(t, _FOLLOWER_KEYS, "[follower]", fail, "follower")
    want = book_follower(t.get("kind", allowed[0]))
    if want not in allowed or t.get("motion", "translating") != "translating" or \
            t.get("offset", 0):
        raise fail(f"a {kind} cam is worked under a {' or '.join(allowed)} follower "
                   "translating on a line through the cam's centre", "follower", "kind")
    if want != "roller":
        size = next((k for k in ("radius", "diameter") if k in t), None)
        if size:
            raise fail(f"{size} is a roller's, not a {want} follower's: leave it out, or make "
                       "the follower a roller", "follower", size)
        return 0.0, want == "flat-faced"
    if ("radius" in t) == ("diameter" in t):
        raise fail("a roller follower gives its radius (radius = 15) or its diameter "
                   "(diameter = 30)", "follower", "radius")
    key = "radius" if "radius" in t else "diameter"
    try:
        r = file_number(t[key], "the roller's " + key) * metre / (1 if key == "radius" else 2)
    except ValueError as e:
        raise fail(str(e), "follower", key) from None
    if not r > 0:
        raise fail(f"the roller's {key} must be positive", "follower", key)
    return r, False


def _tangent(cam: dict[str, Any], r1: float, size, number, fail
             ) -> tuple[float, float, float]:
    """A tangent cam's nose radius, lift and angle of lift from the two the file gives."""
    alpha = _angle(cam, number, fail, faces=True)
    have = [k for k in ("nose_radius", "lift") if k in cam] + (["angle"] if alpha else [])
    if len(have) != 2:
        raise fail("a tangent cam gives two of nose_radius, lift and angle (the angle of "
                   "lift, or faces_angle between its flanks): its flanks' tangency fixes "
                   "the third", "cam", "kind")
    if alpha is None:
        r2, h = size("nose_radius", "the nose radius"), size("lift", "the lift")
        d = r1 + h - r2
        if not r2 < r1:
            raise fail("the nose is smaller than the base circle", "cam", "nose_radius")
        alpha = math.acos((r1 - r2) / d)
    elif "lift" in cam:
        h = size("lift", "the lift")
        d = h / (1 - math.cos(alpha))
        r2 = r1 + h - d
        if not r2 > 0:
            raise fail(f"a lift of {h:g} m over an angle of lift of {math.degrees(alpha):g}° "
                       "leaves no nose: give a smaller lift or a larger angle", "cam", "lift")
    else:
        r2 = size("nose_radius", "the nose radius")
        if not r2 < r1:
            raise fail("the nose is smaller than the base circle", "cam", "nose_radius")
        h = (r1 - r2) / math.cos(alpha) + r2 - r1
    return r2, h, alpha


def _circular(cam: dict[str, Any], r1: float, size, number, fail
              ) -> tuple[float, float, float]:
    """A circular-arc cam's nose radius, lift and angle of lift (from its flank's radius
    where the file gives that instead)."""
    for key in ("nose_radius", "lift"):
        if key not in cam:
            raise fail(f"a circular arc cam gives its base_radius, nose_radius, lift and "
                       f"angle of lift (or flank_radius): {key} is missing", "cam", "kind")
    r2, h = size("nose_radius", "the nose radius"), size("lift", "the lift")
    if not r2 < r1:
        raise fail("the nose is smaller than the base circle", "cam", "nose_radius")
    d = r1 + h - r2
    alpha = _angle(cam, number, fail, faces=False)
    if ("flank_radius" in cam) == (alpha is not None):
        raise fail("a circular arc cam gives its angle of lift or its flank_radius, one of "
                   "them", "cam", "angle")
    if alpha is None:
        big = size("flank_radius", "the flank's radius")
        c = ((big - r2) ** 2 - (big - r1) ** 2 - d * d) / (2 * (big - r1) * d)
        if not (big > r1 + h and -1 < c < 1):
            raise fail("a flank of that radius cannot touch both the base and the nose "
                       "circles", "cam", "flank_radius")
        alpha = math.acos(c)
    elif not r1 - r2 - d * math.cos(alpha) > 0:
        raise fail(f"an angle of lift of {math.degrees(alpha):g}° is too small for convex "
                   "arcs to join the base circle to the nose: give a larger angle or a "
                   "smaller lift", "cam", "angle")
    return r2, h, alpha


def _angle(cam: dict[str, Any], number, fail, *, faces: bool) -> float | None:
    """The angle of lift (rad) as given: ``angle``, or a tangent cam's ``faces_angle``."""
    given = [k for k in ("angle", "action_angle", "faces_angle") if k in cam]
    if len(given) > 1:
        raise fail(f"give one of the angle of lift, the angle of action and the faces' angle, "
                   f"not {' and '.join(given)}", "cam", given[-1])
    if "action_angle" in cam:              # the lift and the return: twice the angle of lift
        v = number(cam, "action_angle", "cam", "the angle of action")
        if not 0 < v < 360:
            raise fail(f"the angle of action is between 0° and 360°, not {v:g}°", "cam",
                       "action_angle")
        return math.radians(v / 2)
    if "faces_angle" in cam:
        if not faces:
            raise fail("only a tangent cam has straight faces", "cam", "faces_angle")
        v = number(cam, "faces_angle", "cam", "the angle between the faces")
        if not 0 < v < 180:
            raise fail(f"the angle between the faces is between 0° and 180°, not {v:g}°",
                       "cam", "faces_angle")
        return math.radians(90 - v / 2)
    if "angle" not in cam:
        return None
    v = number(cam, "angle", "cam", "the angle of lift")
    if not 0 < v < 180:
        raise fail(f"the angle of lift is between 0° and 180°, not {v:g}°", "cam", "angle")
    return math.radians(v)
