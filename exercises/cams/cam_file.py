"""Read a cam exercise (TOML with ``[cam]`` and ``[[segment]]`` tables).

The format is documented in docs/howto/cams.md. Angles are in degrees, lifts and radii in
the file's length unit, the cam's speed in rpm or rad/s. Every failure is one line naming
file:line: segments that do not add to 360°, a negative lift, a cam that does not come back
to its base circle, a law the diagram does not draw.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

from tarsim.constructions.cams.displacement import Segment
from tarsim.constructions.units import LENGTH_UNITS
from tarsim.constructions.reference.cam_laws import BLEND, LAWS
from tarsim.constructions.reference.cam_profile import Follower, arm_start, prime_radius
from ..file_numbers import file_number
from ..names import named_in, read_names, renamed_field
from ..table_file import SPEEDS, Tables
from .arc_cam_file import ARC_KINDS, base_key, eccentric_disc, parse_arc_cam
from .cam_settings import (CAM_KEYS, FOLLOWER_KEYS, FOLLOWER_KINDS, SEGMENT_KEYS, UNIT_KEYS,
                           book_follower, book_law, refuse_unknown)
from .segment_angles import degrees_per_second, refuse_untimed_speed, rest_angle, segment_angle

__all__ = ["CamExercise", "parse_cam"]

_ASK_KEYS = ("jerk", "at", "undercut")
_TOP = ("name", "names", "source", "description", "units", "cam", "follower", "segment", "ask")


@dataclass(frozen=True)
class CamExercise:
    """A cam and its follower's motion: the base circle (m), the cam's ω (rad/s, CCW +),
    the segments, and how the file states its units."""

    chapter: ClassVar[str] = "cams"

    id: str
    name: str
    source: str
    description: str
    base_radius: float
    omega: float
    segments: tuple[Segment, ...]
    length_unit: str = "mm"
    speed_unit: str = "rpm"
    follower: Follower = Follower()
    jerk: bool = False
    """The jerk is asked for: its diagram and each segment's peak."""
    at: tuple[float, ...] = ()
    """Cam angles (degrees from the first segment's start) the follower's motion is asked
    at."""
    names: tuple[tuple[str, str], ...] = ()
    """The cam's name in other languages (``[names]``, :mod:`.names`)."""
    pressure_limit: float | None = None
    """The greatest pressure angle allowed (rad), where the base circle is found from it."""
    undercut_asked: bool = False
    """The file asks whether the follower undercuts: the cam is solved and drawn even if it
    does, the trouble ringed, as --allow-undercut draws it."""
    curvature_limit: float | None = None
    """A flat face's profile's least radius of curvature allowed (m), where the base circle
    is found from it."""
    disc: tuple[float, float] | None = None
    """An eccentric disc's radius and eccentricity (the file's length unit), where the cam
    is one."""
    paper: str = "A4"
    """The sheet its figures are drawn for and set on (``graphics.paper.PAPERS``),
    as ``--paper`` sets it."""

    def named_in(self, lang: str) -> CamExercise:
        """The same exercise with the cam named in ``lang``, if its file does."""
        return named_in(self, lang)

    renamed = renamed_field

    @property
    def metre(self) -> float:
        """Metres in one of the file's length units."""
        return LENGTH_UNITS[self.length_unit]

    @property
    def sigma(self) -> float:
        """The cam's sense: +1 counter-clockwise."""
        return 1.0 if self.omega > 0 else -1.0


def parse_cam(text: str, filename: str = "<string>", exercise_id: str = "cam",
              data: dict[str, Any] | None = None) -> CamExercise:
    """Parse a cam exercise from TOML text (:func:`tarsim.load` reads a file); ``data``, the
    tables already parsed from it, spares a second parse."""
    tables = Tables.read(text, filename, "cam", _TOP, {}, data)
    data, fail = tables.data, tables.fail
    if isinstance(data.get("units"), dict):
        refuse_unknown(data["units"], UNIT_KEYS, "[units]", fail, "units")
    length, speed = tables.units("mm", "rpm")
    metre = LENGTH_UNITS[length]
    cam = data.get("cam")
    if not isinstance(cam, dict):
        raise fail("[cam] gives the base circle and the cam's speed: base_radius = 40, "
                   "speed = 300, sense = \"cw\"", "cam")

    number = tables.number
    if "kind" in cam:                      # a cam of arcs, its motion from its outline
        if cam["kind"] not in ARC_KINDS:
            raise fail(f"a cam's kind is {' or '.join(ARC_KINDS)}, not {cam['kind']!r} (a cam "
                       "given by its follower's motion leaves kind out)", "cam", "kind")
        return parse_arc_cam(tables, exercise_id, _angles)
    refuse_unknown(cam, CAM_KEYS, "[cam]", fail, "cam")

    disc = _disc(cam, number, fail)
    base = _base(cam, disc, number, fail)
    refuse_untimed_speed(cam, data.get("segment"), fail)
    rate = number(cam, "speed", "cam", "the cam's speed")
    sense = cam.get("sense", "ccw")
    if sense not in ("cw", "ccw") or rate <= 0:
        raise fail("the cam turns at a positive speed, its sense cw or ccw", "cam", "sense")
    omega = rate * SPEEDS[speed] * (1 if sense == "ccw" else -1)
    follower = _follower(data.get("follower") or {}, None if base is None else base * metre,
                         metre, length, fail)
    if disc and follower.kind != "flat-faced":
        # Under a knife edge or a roller the disc drives a slider-crank: a cam of arcs that
        # is all nose.
        return eccentric_disc(tables, exercise_id, disc, follower, omega, _angles)
    segments = _disc_segments(disc, metre, data, fail) if disc else _segments(
        data, follower, metre, length, number, fail, degrees_per_second(rate, speed))
    if base is None:                       # found from the greatest pressure angle
        base = _least_base(segments, follower, omega, cam, metre, length, fail)
    ask = data.get("ask", {})
    takes = ("a cam's [ask] table takes jerk = true (its diagram and peaks), at = [40, 240] "
             "(the motion at those cam angles) and undercut = true (whether the follower "
             "undercuts, drawn even where it does); the displacement, velocity, acceleration "
             "and profile are always drawn")
    if isinstance(ask, dict):
        refuse_unknown(ask, _ASK_KEYS, "[ask]", fail, "ask", otherwise=takes)
    if not isinstance(ask, dict) or \
            not all(isinstance(ask.get(k, False), bool) for k in ("jerk", "undercut")):
        raise fail(takes, "ask")
    at = _angles(ask.get("at", []), fail)
    return CamExercise(exercise_id, str(data.get("name", exercise_id)),
                       str(data.get("source", "")), str(data.get("description", "")),
                       base * metre, omega, tuple(segments), length, speed, follower,
                       ask.get("jerk", False), at, read_names(data, tables.where, filename),
                       pressure_limit=math.radians(cam["pressure_angle"])
                       if "pressure_angle" in cam else None, disc=disc,
                       curvature_limit=cam["rho_min"] * metre if "rho_min" in cam else None,
                       undercut_asked=ask.get("undercut", False))


def _disc(cam: dict[str, Any], number, fail) -> tuple[float, float] | None:
    """An eccentric disc: its radius (or diameter) and eccentricity, in the file's unit."""
    if "disc_diameter" in cam and "disc_radius" in cam:
        raise fail("give the disc's radius or its diameter, not both", "cam", "disc_diameter")
    if not any(k in cam for k in ("disc_radius", "disc_diameter", "eccentricity")):
        return None
    key = "disc_diameter" if "disc_diameter" in cam else "disc_radius"
    if key not in cam or "eccentricity" not in cam:
        raise fail("an eccentric disc gives its radius (or disc_diameter) and its "
                   "eccentricity: disc_diameter = 80, eccentricity = 15", "cam",
                   "eccentricity" if key in cam else "disc_radius")
    size = number(cam, key, "cam", "the disc's " + key[5:])
    radius = size / 2 if key == "disc_diameter" else size
    e = number(cam, "eccentricity", "cam", "the eccentricity")
    if not 0 < e < radius < 1e6:
        raise fail(f"the eccentricity ({e:g}) must be more than 0 and less than the disc's "
                   f"radius ({radius:g}), or the shaft leaves the disc", "cam", "eccentricity")
    return radius, e


def _base(cam: dict[str, Any], disc, number, fail) -> float | None:
    """The base circle (the file's unit) as [cam] gives it: its radius, a disc's nearest
    point to the shaft, or None where the greatest pressure angle asks it found."""
    key = base_key(cam, fail)
    given = [k for k in (key, "pressure_angle", "rho_min") if k in cam] + (
        ["disc_radius"] if disc else [])
    if len(given) != 1:
        raise fail("[cam] gives the base circle one way: base_radius = 40 (or base_diameter "
                   "= 80), or pressure_angle "
                   "= 30 or (a flat face's) rho_min = 5 (the least base circle is found), or "
                   "an eccentric disc's disc_radius and eccentricity", "cam",
                   given[-1] if given else None)
    if disc:
        return disc[0] - disc[1]
    if "pressure_angle" in cam:
        limit = number(cam, "pressure_angle", "cam", "the greatest pressure angle")
        if not 0 < limit < 90:
            raise fail(f"the greatest pressure angle is between 0° and 90°, not {limit:g}°",
                       "cam", "pressure_angle")
        return None
    if "rho_min" in cam:
        rho = number(cam, "rho_min", "cam", "the least radius of curvature")
        if not 0 <= rho < 1e6:
            raise fail(f"the least radius of curvature is 0 (a point) or more, not {rho:g}",
                       "cam", "rho_min")
        return None
    base = number(cam, key, "cam", "the base " + key[5:])
    if not 0 < base < 1e6:
        raise fail(f"the base {key[5:]} must be positive, got {base:g}", "cam", key)
    return base / 2 if key == "base_diameter" else base


def _disc_segments(disc: tuple[float, float], metre: float, data: dict[str, Any], fail
                   ) -> list[Segment]:
    """An eccentric disc under a flat face: the face's lift above the disc's nearest point
    is e(1 − cos θ), simple harmonic up 2e over half a turn and down over the other."""
    if "segment" in data:
        raise fail("an eccentric disc makes its own motion (simple harmonic, up and down "
                   "2e over half a turn each): leave out the [[segment]] tables", "segment")
    lift = 2 * disc[1] * metre
    return [Segment("rise", math.pi, lift, "simple harmonic"),
            Segment("return", math.pi, lift, "simple harmonic")]


def _least_base(segments: list[Segment], follower: Follower, omega: float,
                cam: dict[str, Any], metre: float, unit: str, fail) -> float:
    """The least base circle (the file's unit) that holds the pressure angle to [cam]'s, or
    a flat face's profile's curvature to its rho_min."""
    from tarsim.constructions.cams.base_circle import least_base_radius, least_flat_base
    if "rho_min" in cam:
        if follower.kind != "flat-faced" or follower.oscillating:
            raise fail("rho_min sizes the base circle under a translating flat face (its "
                       "profile's radius r_b + y + y″); give a roller's or knife edge's "
                       "base_radius", "cam", "rho_min")
        base = least_flat_base(segments, cam["rho_min"] * metre)
        if not base > 0:
            raise fail(f"any base circle keeps this profile's radius of curvature over "
                       f"{cam['rho_min']:g} {unit}: give base_radius instead", "cam", "rho_min")
        return base / metre
    if follower.kind == "flat-faced":
        raise fail("a flat face square to its motion is pushed along it (its pressure angle "
                   "is 0): give its base_radius", "cam", "pressure_angle")
    limit = math.radians(cam["pressure_angle"])
    base = least_base_radius(segments, follower, math.copysign(1.0, omega), limit)
    if not base > 0:
        raise fail(f"any base circle keeps this follower's pressure angle under "
                   f"{cam['pressure_angle']:g}°: give base_radius instead", "cam",
                   "pressure_angle")
    return base / metre


def _segments(data: dict[str, Any], follower: Follower, metre: float, length: str, number,
              fail, turn: float) -> list[Segment]:
    """The [[segment]] tables in turn: each checked, its lift in m (an arm's swing as the arc
    at its end), its angle in degrees or its time at the cam's ``turn`` (degrees a second),
    and all of them a whole turn that brings the follower back. A setting no segment knows
    is refused first, before an angle missing for it is."""
    raw = data.get("segment")
    if not isinstance(raw, list) or not raw:
        raise fail("list the follower's motion as [[segment]] tables (kind, angle, lift, law)",
                   key="segment")
    for i, t in enumerate(raw):
        if isinstance(t, dict):
            refuse_unknown(t, SEGMENT_KEYS, f"[[segment]] {i + 1}", fail, "segment", i)
    segments, total, height = [], 0.0, 0.0
    rest = rest_angle(raw, turn, number, fail)
    for i, t in enumerate(raw):
        kind = t.get("kind") if isinstance(t, dict) else None
        if kind not in ("rise", "dwell", "return"):
            raise fail(f"a segment is a rise, a dwell or a return, not {kind!r}", "segment",
                       "kind", i)
        if kind == "dwell":
            _refuse_moving(t, fail, i)
        angle, time = (rest, None) if t.get("angle") == "rest" else \
            segment_angle(t, i, turn, number, fail)
        if not 0 < angle <= 360:
            timed = f" ({time:g} s at the cam's speed)" if time else ""
            raise fail(f"a segment's angle must be more than 0° and at most 360°, got "
                       f"{angle:g}°{timed}", "segment", "time" if time else "angle", i)
        lift, law, divisions, blend, split = 0.0, "", 6, BLEND, 0.5
        if kind != "dwell":
            lift = number(t, "lift", "segment", "a segment's lift", i)
            if lift < 0:
                raise fail(f"a negative lift ({lift:g} {length}): a {kind} gives the lift's "
                           "size, its kind the way", "segment", "lift", i)
            if follower.oscillating:               # the arm's swing, as the arc at its end
                lift = math.radians(lift) * follower.arm / metre
            law = book_law(t.get("law", "simple harmonic"))
            if law is None:
                raise fail(f"unknown law {t['law']!r}; the laws are {', '.join(LAWS)} (or as "
                           "the books say them: SHM, uniform acceleration and retardation, …)",
                           "segment", "law", i)
            modified = law == "modified uniform velocity"
            if "accelerating" in t or "acceleration_ratio" in t:
                split = _split(t, angle, law, number, fail, i)
            parts = t.get("divisions", 8 if modified else _parts(split))
            if isinstance(parts, bool) or not isinstance(parts, int) or not 2 <= parts <= 24:
                raise fail(f"a segment is divided into 2 to 24 equal parts, not {parts!r}",
                           "segment", "divisions", i)
            divisions = parts
            if law == "parabolic" and split == 0.5 and parts % 2:
                raise fail(f"a parabolic segment is divided into an even number of parts (the "
                           f"two halves alike), not {parts}", "segment", "divisions", i)
            if modified:
                blend = number(t, "blend", "segment", "the blend", i) if "blend" in t else BLEND
                if not (0 < blend <= 0.5 and abs(blend * parts - round(blend * parts)) < 1e-9
                        and round(blend * parts) >= 1):
                    raise fail(f"the blend at each end is a fraction of the segment up to ½ "
                               f"covering a whole number of its {parts} divisions, not "
                               f"{blend:g}", "segment", "blend", i)
            elif "blend" in t:
                raise fail("only a modified uniform velocity has a blend", "segment", "blend", i)
            if law == "parabolic" and not any(abs(split * n - round(split * n)) < 1e-9
                                               for n in range(2, 25)):
                key = "accelerating" if "accelerating" in t else "acceleration_ratio"
                raise fail(f"the acceleration ends {angle * split:.6g}° into the segment's "
                           f"{angle:g}°, on no division of 2 to 24 equal parts, where the "
                           f"diagram's construction ends it: give a {key} that does",
                           "segment", key, i)
            if law == "parabolic" and abs(split * parts - round(split * parts)) > 1e-9:
                raise fail(f"the acceleration must end on a division: {angle * split:g}° of "
                           f"{angle:g}° in {parts} equal parts does not; give divisions so "
                           "that it does", "segment", "divisions", i)
        total += angle
        height += lift if kind == "rise" else -lift
        if height < -1e-12 * max(lift, 1.0):
            raise fail(f"segment {i + 1} returns the follower below the base circle "
                       f"({height:g} {length})", "segment", "lift", i)
        segments.append(Segment(kind, math.radians(angle), lift * metre, law, divisions,
                                blend, split, time))
    if abs(total - 360.0) > 1e-9:
        raise fail(f"the segments add to {total:g}°, not 360°: the cam turns once",
                   key="segment")
    if abs(height) > 1e-9 * max(s.lift for s in segments):
        raise fail(f"the rises and returns leave the follower {height:g} {length} off the "
                   "base circle after a turn: they must balance", key="segment")
    return segments

def _angles(raw: Any, fail) -> tuple[float, ...]:
    """[ask] at: the cam angles (degrees, 0 to 360 from the first segment's start) the
    follower's motion is asked at, each once."""
    if not isinstance(raw, list) or not all(
            isinstance(v, (int, float)) and not isinstance(v, bool) for v in raw):
        raise fail("at lists cam angles in degrees from the start of the first segment: "
                   "at = [40, 240]", "ask", "at")
    for v in raw:
        if not 0 <= v <= 360:
            raise fail(f"a cam angle asked at is from 0° to 360°, not {v:g}°", "ask", "at")
    if len({f"{v:g}" for v in raw}) < len(raw):
        raise fail("a cam angle is asked at twice", "ask", "at")
    return tuple(float(v) for v in raw)


def _split(t: dict[str, Any], angle: float, law: str, number, fail, i: int) -> float:
    """A parabolic segment's accelerating fraction k: ``accelerating`` gives the degrees of
    uniform acceleration (from the segment's start), the retardation taking the rest, as
    the books split an outstroke unequally; or ``acceleration_ratio`` gives the book's
    "the acceleration is r times the retardation". The velocity is 2h/β where the parts
    meet, so the acceleration 2h/kβ² and the retardation 2h/(1 − k)β² stand in the ratio
    (1 − k)/k = r: k = 1/(1 + r)."""
    key = "accelerating" if "accelerating" in t else "acceleration_ratio"
    if law != "parabolic":
        raise fail(f"only a parabolic segment (uniform acceleration and retardation) is split "
                   f"by {key}", "segment", key, i)
    if key == "accelerating" and "acceleration_ratio" in t:
        raise fail("give the degrees of acceleration or the acceleration_ratio, not both",
                   "segment", "acceleration_ratio", i)
    if key == "acceleration_ratio":
        ratio = number(t, key, "segment", "the acceleration over the retardation", i)
        if not 1e-6 < ratio < 1e6:
            raise fail(f"the acceleration_ratio is the acceleration over the retardation, a "
                       f"positive number (2 where it is twice the retardation), not {ratio:g}",
                       "segment", key, i)
        return 1 / (1 + ratio)
    part = number(t, "accelerating", "segment", "the degrees of acceleration", i)
    if not 0 < part < angle:
        raise fail(f"the acceleration lasts part of the segment's {angle:g}°, more than 0° and "
                   f"less than all of it, not {part:g}°", "segment", "accelerating", i)
    return part / angle


def _refuse_moving(t: dict[str, Any], fail, i: int) -> None:
    """Refuse, at its line, a setting of motion in a dwell, which holds the follower still
    (a lift there would be dropped, the rest of the turn read without it)."""
    for k in t:
        if k not in ("kind", "angle", "time"):
            raise fail(f"a dwell holds the follower still: {k} is a rise's or a return's; "
                       "leave it out, or make the segment a rise or a return", "segment", k, i)


def _parts(split: float) -> int:
    """The fewest equal parts, six or more, that put a split on a division (six if none up
    to 24 does: the file then gives its divisions)."""
    return next((n for n in range(6, 25) if abs(split * n - round(split * n)) < 1e-9
                 and (split != 0.5 or n % 2 == 0)), 6)


def _follower(t: dict[str, Any], base: float | None, metre: float, unit: str, fail
              ) -> Follower:
    """The [follower] table: its kind, roller radius, and a translating line's offset or an
    oscillating arm's pivot and length (the file's length unit, from the cam centre)."""
    refuse_unknown(t, FOLLOWER_KEYS, "[follower]", fail, "follower")
    kind, how = book_follower(t.get("kind", "knife-edge")), t.get("motion", "translating")
    if kind is None:
        raise fail(f"a follower is {', '.join(FOLLOWER_KINDS)} (or as the books say them: "
                   f"knife edge, flat-face, flat, mushroom), not {t['kind']!r}", "follower",
                   "kind")
    if how not in ("translating", "oscillating"):
        raise fail(f"a follower is translating or oscillating, not {how!r}", "follower",
                   "motion")
    _refuse_unused(t, kind, how, fail)

    def size(key: str, what: str) -> float:
        try:
            return file_number(t.get(key, 0), what) * metre
        except ValueError as e:
            raise fail(str(e), "follower", key) from None

    if "diameter" in t and "radius" in t:
        raise fail("give the roller's radius or its diameter, not both", "follower",
                   "diameter")
    # The books give a roller by its diameter as often as by its radius.
    radius = size("diameter", "the roller's diameter") / 2 if "diameter" in t else \
        size("radius", "the roller's radius")
    if kind == "roller" and not radius > 0:
        raise fail("a roller follower gives its radius (radius = 10) or its diameter "
                   "(diameter = 20)", "follower", "diameter" if "diameter" in t else "radius")
    if how == "translating":
        offset = size("offset", "the follower's offset")
        # A base circle found from the pressure angle clears the offset by its s₀.
        reach = math.inf if base is None else prime_radius(base, Follower(kind, radius))
        if abs(offset) >= reach:
            raise fail(f"an offset of {abs(offset) / metre:g} {unit} puts the follower's line "
                       f"clear of the prime circle ({reach / metre:g} {unit})", "follower",
                       "offset")
        return Follower(kind, radius, offset)
    if kind == "flat-faced":
        raise fail("an oscillating flat face is not laid out yet: use a roller or a knife "
                   "edge on the arm", "follower", "kind")
    if base is None:
        raise fail("the least base circle for a pressure angle is found for a translating "
                   "follower: give an oscillating one's base_radius", "follower", "motion")
    pivot = t.get("pivot")
    if not isinstance(pivot, list) or len(pivot) != 2:
        raise fail("an oscillating follower gives its pivot from the cam centre: "
                   "pivot = [70, 0]", "follower", "pivot")
    try:
        at = tuple(file_number(v, "the pivot's coordinate") * metre for v in pivot)
    except ValueError as e:
        raise fail(str(e), "follower", "pivot") from None
    f = Follower(kind, radius, 0.0, at, size("arm", "the arm's length"))
    if not f.arm > 0:
        raise fail("an oscillating follower gives its arm's length: arm = 50", "follower",
                   "arm")
    d, r = math.hypot(*f.pivot), prime_radius(base, f)
    if not abs(d - f.arm) < r < d + f.arm:
        raise fail(f"an arm of {f.arm / metre:g} {unit} on a pivot {d / metre:g} {unit} from "
                   f"the cam centre cannot reach the prime circle ({r / metre:g} {unit})",
                   "follower", "arm")
    try:
        arm_start(base, f)
    except ValueError as e:
        raise fail(str(e), "follower", "pivot") from None
    return f


def _refuse_unused(t: dict[str, Any], kind: str, how: str, fail) -> None:
    """Refuse, at its line, a [follower] setting this follower has no use for: a size on a
    follower with no roller, a pivot or arm on one that does not swing, an offset on one
    that does (each would be dropped and another follower's cam solved)."""
    unused = {"radius": kind != "roller", "diameter": kind != "roller",
              "pivot": how != "oscillating", "arm": how != "oscillating",
              "offset": how == "oscillating"}
    for k in t:
        if unused.get(k):
            whose = ("a roller's" if k in ("radius", "diameter") else
                     "a translating follower's" if k == "offset" else
                     'an oscillating follower\'s (motion = "oscillating")')
            raise fail(f"{k} is {whose}, not a {how} {kind} follower's: leave it out, or "
                       "give the follower it belongs to", "follower", k)
