"""An exercise: a mechanism file plus an ``[ask]`` table saying what to find and how.

::

    [ask]
    find = ["centres", "omega3", "omega4", "V_D"]     # what the exercise asks for
    methods = ["radius-rotation", "components"]       # how to find each velocity
    at = [{ angle = 90 }, { time = 2.34 }]            # optional: the positions to solve
    scale = ["1 cm = 4 cm", "1 cm = 50 mm/s"]         # optional: the scales stated

``find`` names quantities as results.json does: ``centres`` (all of them), a
single centre ``I24``, an angular velocity ``omega3``, a point's velocity ``V_D``,
an angular acceleration ``alpha4``, a point's acceleration ``A_B`` (``A_B4`` for
the point of link 4 under B, where B slides in a slot of link 4), a relative
velocity or acceleration ``V_B/A``, ``A_B/A``, and a Coriolis component
``A_cor_B``. ``methods`` are the velocity constructions, each drawn as its own
figure: ``radius-rotation``, ``parallel-line``, ``components``, ``polygon``
(relative velocities). Accelerations are always found by the polygon.
``at`` lists positions: an input ``angle`` (the file's angle unit), or a
``time`` in seconds after the ``[input]`` angle (θ = θ0 + ω t + α t²/2).
``scale`` is one statement or a list, each "1 cm = N unit" or "3 cm = 18 cm/s" (the
paper side in cm, mm or in) as the exercise words it: a length unit
states the space scale, ``unit/s`` the velocity scale, ``unit/s²`` (or ``/s^2``)
the acceleration scale; a scale not stated is chosen to fit the page. A file
without ``[ask]`` asks for every centre and the ω of every moving link.
"""

from __future__ import annotations

import difflib
import math
import re
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any, ClassVar
from pathlib import Path

from tarsim.constructions import asks as A
from tarsim.constructions import registry
from tarsim.constructions.errors import InputError
from tarsim.constructions.linkages.klein import klein_parts
from tarsim.constructions.loads import Loads
from tarsim.constructions.model import Drive, Mechanism
from tarsim.constructions.units import LENGTH_UNITS
from tarsim.constructions.narration import significant
from tarsim.constructions.scales import Stated

from ..forces.loads_file import LOAD_TABLES, pressures_per_position, read_loads
from ..names import named_in, read_names

if TYPE_CHECKING:
    from ..grading.drafting import Drafting
from ..file_numbers import RANGE, _float, arithmetic, in_range, radians_in_turn
from .mechanism_file import _Reader
from .mechanism_input import file_angle
from .travel_positions import TRAVEL_KEYS, crank_angle_at_travel, dead_centre_word
from ..toml_source import SourceMap, read_source, read_toml

__all__ = ["Exercise", "Position", "load_exercise", "parse_exercise", "asks_of"]

_ASK_KEYS = ("find", "methods", "at", "scale", "pins")
_NUMBER = r"([0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)"
_SCALE = re.compile(rf"^\s*{_NUMBER}\s*(cm|mm|in)\s*=\s*{_NUMBER}\s*(mm|cm|m|in|ft)"
                    r"\s*(/\s*s\s*(?:²|\^\s*2|2)?)?\s*$")
_PAPER_CM = {"cm": 1.0, "mm": 0.1, "in": 2.54}
_SCALE_UNITS = {**LENGTH_UNITS, "ft": 0.3048}
_SCALE_KINDS = {"": "space", "/s": "velocity", "/s2": "acceleration"}
@dataclass(frozen=True)
class Position:
    """One position an exercise is solved at: the input's state and how the file gave it."""

    drive: Drive
    label: str
    """As the figures and steps.md say it: "θ2 = 90°" or "t = 2.34 s (θ2 = −44.07°)"."""
    slug: str
    """As file names carry it: "theta2-90" or "t-2.34s"."""
    turned: tuple[float, str] | None = None
    """For a position by the piston's travel: the angle (rad) the crank has turned from
    the dead centre the travel is measured from, and that centre's name ("t.d.c.")."""


@dataclass(frozen=True)
class Exercise:
    """What to solve: the mechanism, the quantities asked, the velocity methods to draw.

    ``find`` holds the names as the file writes them ("centres", "omega4"), for a
    reader; ``asks`` the same parsed once, "centres" as every centre, each once.
    """

    chapter: ClassVar[str] = "linkages"
    id: str
    mechanism: Mechanism
    find: tuple[str, ...]
    methods: tuple[str, ...]
    positions: tuple[Position, ...] = ()
    """The positions to solve; empty means the [input] angle alone."""
    velocity_per_cm: float | None = None
    """The stated velocity scale, file length units per second per paper cm."""
    acceleration_per_cm: float | None = None
    """The stated acceleration scale, file length units per s² per paper cm."""
    asks: tuple[A.Ask, ...] = ()
    pins: tuple[tuple[str, float], ...] = ()
    """The pins' diameters (m) the exercise gives, for their rubbing velocities."""
    paper: str = "A4"
    """The sheet the figures are set on (``graphics.paper.PAPERS``): their scales are chosen
    to fill it."""
    loads: Loads | None = None
    loads_at: tuple[Loads, ...] = ()
    """The loads at each position, where a pressure is given per position (``loads`` the
    first's); empty where they are the same at every position."""
    lang: str = "en"
    """The language its steps are written in (``lang = "fa"`` in the file)."""
    names: tuple[tuple[str, str], ...] = ()
    """The mechanism's name in other languages (``[names] fa = "…"``), by language."""
    drafting: Drafting | None = None
    """How precisely a drawing of it is graded (:class:`~.grading.drafting.Drafting`), if
    its ``[grading]`` table says; the course's 0.5 mm and 0.5° otherwise."""
    """Masses, external forces and couples, for the force analysis; None if none given."""

    def __post_init__(self) -> None:
        if not self.asks:
            object.__setattr__(self, "asks", asks_of(self.find, self.mechanism, self.pins))

    def at(self, position: Position) -> Exercise:
        """The same exercise at one of its positions (and only that one)."""
        loads = (self.loads_at[self.positions.index(position)] if self.loads_at
                 else self.loads)
        return replace(self, mechanism=self.mechanism.with_drive(position.drive), positions=(),
                       loads=loads, loads_at=())

    def named_in(self, lang: str) -> Exercise:
        """The same exercise with its mechanism named in ``lang``, if its file does
        (:func:`~.names.named_in`)."""
        return named_in(self, lang)

    def renamed(self, name: str) -> Exercise:
        """The same exercise, its mechanism called ``name``."""
        return replace(self, mechanism=replace(self.mechanism, name=name))

    def asking(self, names: tuple[str, ...]) -> Exercise:
        """The same exercise asking only ``names``."""
        return replace(self, find=names, asks=asks_of(names, self.mechanism, self.pins))

    @property
    def position_asks(self) -> tuple[A.Ask, ...]:
        """What is asked at each position (centres, ω, V, A …)."""
        return tuple(a for a in self.asks if a.scope == "position")

    @property
    def without_motion(self) -> str | None:
        """Why the exercise cannot be solved with the input at rest (ω = 0): it asks for
        velocities or instant centres, which the input's turning defines; None if it can be
        or the input turns."""
        if self.mechanism.drive.omega != 0.0:
            return None
        moving = [a.name for a in self.position_asks
                  if isinstance(a, (A.Centre, A.AngularVelocity, A.Velocity))
                  or isinstance(a, A.Relative) and a.letter == "V"]
        if not moving:
            return None
        return (f"the exercise asks for {', '.join(moving[:3])}{' …' if len(moving) > 3 else ''}"
                " but the input does not turn (omega is 0 or not given); state the input's "
                "angular velocity in [input] omega")

    @property
    def mechanism_asks(self) -> tuple[A.Ask, ...]:
        """What is asked of the mechanism as a whole (results.json's top-level quantities)."""
        return tuple(a for a in self.asks if a.scope == "mechanism")

    @property
    def stated(self) -> dict[str, float]:
        """The velocity and acceleration scales the exercise states."""
        return {k: v for k, v in (("velocity", self.velocity_per_cm),
                                  ("acceleration", self.acceleration_per_cm)) if v is not None}


def asks_of(names, mech: Mechanism, pins=()) -> tuple[A.Ask, ...]:
    """Parse names into asks, once each: "centres" is every centre of ``mech``; a rubbing
    velocity takes its pin's diameter from ``pins`` ((point, metres) pairs).

    Raises
    ------
    InputError
        If a rubbing velocity is asked at a pin whose diameter is not given.
    """
    out: list[A.Ask] = []
    diameters = dict(pins)
    for name in names:
        if name == "centres":
            nums = sorted(mech.numbers)
            out += [A.Centre((a, b)) for i, a in enumerate(nums) for b in nums[i + 1:]]
            continue
        ask = A.parse_ask(name)
        if isinstance(ask, A.Rubbing):
            if ask.point not in diameters:
                raise InputError(f"{name} needs the diameter of pin {ask.point}: give it in "
                                 f"[ask] as pins = {{ {ask.point} = 20 }} (in the file's length "
                                 "unit)")
            ask = A.Rubbing(ask.point, diameters[ask.point])
        out.append(ask)
    return tuple(dict.fromkeys(out))


def load_exercise(path: str | Path, exercise_id: str | None = None) -> Exercise:
    """Read an exercise file (a mechanism file, optionally with ``[ask]``).

    Raises
    ------
    InputError
        Naming file:line and the field, with the closest valid name.
    """
    path = Path(path)
    return parse_exercise(read_source(path), str(path), exercise_id or path.stem)


def parse_exercise(text: str, filename: str = "<string>", exercise_id: str = "exercise",
                   data: dict[str, Any] | None = None) -> Exercise:
    """Parse an exercise from TOML text (see :func:`load_exercise`); ``data``, the tables
    already parsed from it (and taken apart here), spares a second parse."""
    data = read_toml(text, filename) if data is None else data
    where = SourceMap(text)
    ask = data.pop("ask", None)
    loading = {t: data.pop(t) for t in LOAD_TABLES if t in data}
    grading = data.pop("grading", None)
    lang = data.pop("lang", "en")
    if lang not in ("en", "fa"):
        raise InputError(f"lang is the language of the steps, en or fa; got {lang!r}",
                         file=filename, line=where.key("lang"))
    names = read_names(data, where, filename)
    data.pop("names", None)
    mech = _Reader(data, where, filename).mechanism()
    ex = _read_ask(ask, mech, where, filename, exercise_id)
    count = pressures_per_position(loading, where, filename, len(ex.positions))
    loads = read_loads(loading, mech, where, filename)
    if count:
        ex = replace(ex, loads_at=tuple(read_loads(loading, mech, where, filename, k)
                                        for k in range(count)))
    if loads is not None:
        ex = replace(ex, loads=loads)
    elif any(isinstance(a, (A.JointForce, A.DrivingTorque)) for a in ex.asks):
        raise InputError("forces are asked, but the file gives no loads: add [[mass]], "
                         "[[force]] or [[couple]] tables (see docs/howto/forces.md)", file=filename,
                         line=where.key("find", "ask") or where.header("ask"), key="ask.find")
    if grading is not None:
        from ..grading.drafting import read_drafting
        from ..table_file import Tables

        tables = Tables({"grading": grading}, where, filename,
                        {"grading": ("pen", "angle", "floor", "weights")})
        ex = replace(ex, drafting=read_drafting(grading, tables))
    if lang != "en":
        ex = replace(ex, lang=lang)
    if names:
        ex = replace(ex, names=names)
    if ask is not None and ex.without_motion:     # a bare mechanism file may still be drawn
        raise InputError(ex.without_motion, file=filename,
                         line=where.key("omega", "input") or where.header("input"), key="input")
    return ex


def _read_ask(ask, mech: Mechanism, where: SourceMap, filename: str, exercise_id: str) -> Exercise:
    def fail(message: str, key: str | None = None) -> InputError:
        line = where.key(key, "ask") if key else where.header("ask")
        return InputError(message, file=filename, line=line, key=f"ask.{key}" if key else "ask")

    if ask is None:
        moving = tuple(f"omega{n}" for n in sorted(mech.numbers) if n not in (1, mech.drive.link))
        return Exercise(exercise_id, mech, ("centres",) + moving, ("radius-rotation",))
    if not isinstance(ask, dict):
        raise fail("[ask] must be a table")
    for k in ask:
        if k not in _ASK_KEYS:
            close = _closest(k, _ASK_KEYS)
            hint = f"did you mean '{close}'?" if close else f"expected {' or '.join(_ASK_KEYS)}"
            raise fail(f"unknown setting '{k}' in [ask]; {hint}", k)
    find = ask.get("find")
    if not (isinstance(find, list) and find and all(isinstance(q, str) for q in find)):
        raise fail('[ask] needs find = [...], a list of quantities such as "centres", "I13", '
                   '"omega4", "V_D"', "find" if "find" in ask else None)
    valid = registry.askable(mech)
    for q in find:
        why = registry.why_not(q)
        if q not in valid and why is not None:
            raise fail(f"cannot find '{q}' for this mechanism: {why}", "find")
        if q not in valid:
            raise fail(f"cannot find '{q}' for this mechanism; {_find_hint(q, valid)}", "find")
    methods = ask.get("methods", ["radius-rotation"])
    if not (isinstance(methods, list) and methods and all(isinstance(m, str) for m in methods)):
        raise fail('methods must be a list such as ["radius-rotation", "components"]', "methods")
    for m in methods:
        if m not in registry.CHOSEN:
            close = _closest(m, registry.CHOSEN)
            hint = f"did you mean '{close}'?" if close else f"use {', '.join(registry.CHOSEN)}"
            raise fail(f"unknown velocity method '{m}'; {hint}", "methods")
    if "klein" in methods:
        try:
            klein_parts(mech)
        except InputError as e:
            raise fail(e.message, "methods") from None
    positions = _read_positions(ask.get("at"), mech, fail)
    scales = _read_scales(ask.get("scale", []), mech, fail)
    if "space" in scales:
        mech = replace(mech, scale=scales["space"])
    pins = _read_pins(ask.get("pins", {}), mech, fail)
    try:
        return Exercise(exercise_id, mech, tuple(dict.fromkeys(find)),
                        tuple(dict.fromkeys(methods)), positions, scales.get("velocity"),
                        scales.get("acceleration"), pins=pins)
    except InputError as e:
        raise fail(str(e), "find") from None


def _read_pins(given, mech: Mechanism, fail) -> tuple[tuple[str, float], ...]:
    """``pins = { B = 20 }``: each pin's diameter, in the file's length unit, as metres."""
    if not isinstance(given, dict):
        raise fail("pins must be a table of diameters such as { B = 20 }", "pins")
    out = []
    for point, d in given.items():
        if point not in mech.point_names:
            close = _closest(point, mech.point_names)
            hint = f"did you mean '{close}'?" if close else \
                f"the points are {', '.join(mech.point_names)}"
            raise fail(f"pins names '{point}', no point of the mechanism; {hint}", "pins")
        if isinstance(d, bool) or not isinstance(d, (int, float)) or not (
                math.isfinite(d) and d > 0):
            raise fail(f"the diameter of pin {point} must be a positive number, got {d!r:.40}",
                       "pins")
        out.append((point, float(d) * mech.units.metres))
    return tuple(out)


MOST_TURNED = 1e9
"""The largest input turn (rad) a time in ``at`` may give: a float holds an angle this large
to 1e-7 rad, so the turn's remainder, and so the position, is still the one meant."""


def _read_positions(at, mech: Mechanism, fail) -> tuple[Position, ...]:
    """``at = [{ angle = 90 }, { time = 2.34 }]``: each a Position of the input."""
    if at is None:
        return ()
    shape = 'at must be a list of positions such as [{ angle = 90 }, { time = 2.34 }]'
    if not (isinstance(at, list) and at and all(isinstance(p, dict) for p in at)):
        raise fail(shape, "at")
    d = mech.drive
    deg = mech.units.angle != "rad"
    out = []
    for p in at:
        loads = [k for k in p if k in ("pressure", "force", "resist")]
        if loads:
            raise fail(f"a {loads[0]} that changes with the position is a list in its "
                       f"[[force]], one per position in at: {loads[0]} = [first's, second's, …]",
                       "at")
        if len(p) != 1 or next(iter(p)) not in ("angle", "time", *TRAVEL_KEYS):
            raise fail("each position in at gives one of angle, time, stroke (the share of "
                       f"the stroke the piston has travelled) or travel, got {p}", "at")
        (key, value), = p.items()
        exact = arithmetic(value, pi=True) if isinstance(value, str) else None
        if exact is not None:
            value = _float(exact)
        if key in TRAVEL_KEYS:
            out.append(_by_travel(mech, key, value, deg, fail))
            continue
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise fail(f"{key} in at must be a number, got {value!r:.40}", "at")
        if key == "time" and mech.given is not None:
            raise fail("a time in at needs the input's own ω to turn it through; this input is "
                       "given by another member's motion, so give the positions as angles",
                       "at")
        if not (in_range(_float(value)) if key == "time" else math.isfinite(_float(value))):
            want = RANGE if key == "time" else "finite"
            raise fail(f"{key} in at must be a number {want}, got {value!r:.40}", "at")
        if key == "angle":          # turned as [input]'s: from +x, or from its dead centre
            angle = file_angle(mech.angle_from, value, mech.units.angle)
            drive = replace(d, angle=angle)
            label = f"θ{d.link} = {_angle_text(angle, deg)}"
            if mech.angle_from is not None:
                label = (f"{_angle_text(radians_in_turn(value, mech.units.angle), deg)} from "
                         f"the {mech.angle_from[2]}, " + label)
            slug = f"theta{d.link}-{value:g}"
        else:
            turned = d.omega * value + 0.5 * d.alpha * value * value
            omega = d.omega + d.alpha * value
            if not abs(turned) <= MOST_TURNED:
                raise fail(f"at t = {significant(value)} s the input has turned "
                           f"{significant(turned, 3)} rad, past the {significant(MOST_TURNED)} "
                           "rad within which a float keeps its angle to 1e-7 rad; give an "
                           "earlier time", "at")
            if not in_range(omega):
                raise fail(f"at t = {significant(value)} s the input's ω = "
                           f"{significant(omega, 3)} rad/s is out of the range tarsim takes "
                           f"({RANGE})", "at")
            angle = math.fmod(d.angle + turned, math.tau)
            drive = replace(d, angle=angle, omega=omega)
            label = f"t = {value:g} s (θ{d.link} = {_angle_text(angle, deg)})"
            slug = f"t-{value:g}s"
        out.append(Position(drive, label, slug))
    slugs = [p.slug for p in out]
    if len(set(slugs)) != len(slugs):
        raise fail("at lists the same position twice", "at")
    return tuple(out)


def _by_travel(mech: Mechanism, key: str, value, deg: bool, fail) -> Position:
    """``{ stroke = "1/4" }`` or ``{ travel = 75 }``: the crank where the piston has moved
    that share of its stroke (or that length) from the inner dead centre."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not (
            math.isfinite(value) and value >= 0):
        what = "a share of the stroke, 0 to 1 (\"1/4\")" if key == "stroke" else \
            f"a length in {mech.units.length}, not below 0"
        raise fail(f"{key} in at is {what}, got {value!r:.40}", "at")
    if key == "stroke" and value > 1:
        raise fail(f"stroke in at is the share of the stroke travelled, 0 to 1 (\"1/4\"), "
                   f"got {value:g}", "at")
    d = mech.drive
    try:
        angle, moved, _, turned = crank_angle_at_travel(
            mech, share=value if key == "stroke" else None,
            travel=value * mech.units.metres if key == "travel" else None)
    except ValueError as e:
        raise fail(str(e), "at") from None
    shown = f"{value:g} of the stroke" if key == "stroke" else ""
    centre = dead_centre_word(mech)
    label = (f"{significant(moved / mech.units.metres)} {mech.units.length} from the {centre}"
             f"{' (' + shown + ')' if shown else ''}, the crank {_angle_text(turned, deg)} past "
             f"it, θ{d.link} = {_angle_text(angle, deg)}")
    return Position(replace(d, angle=angle), label, f"{key}-{value:g}", (turned, centre))


def _read_scales(given, mech: Mechanism, fail) -> dict[str, float]:
    """``scale = ["7 cm = 500 mm", "3 cm = 18 cm/s", "1 cm = 2 m/s²"]``: the scales the
    exercise states, by kind (space, velocity, acceleration), in file length units (per s,
    per s²) per paper cm. The unit says the kind, so the order is free."""
    shape = ('scale must read like "1 cm = 4 cm", "3 cm = 18 cm/s" or "1 in = 1 ft/s²" '
             '(positive amounts; paper in cm, mm or in; lengths in mm, cm, m, in or ft), '
             'or be a list of these')
    texts = [given] if isinstance(given, str) else given
    if not isinstance(texts, list):
        raise fail(f"{shape}, got {given!r}", "scale")
    out: dict[str, float] = {}
    for text in texts:
        m = _SCALE.match(text) if isinstance(text, str) else None
        if m is None or float(m.group(1)) <= 0.0 or float(m.group(3)) <= 0.0:
            raise fail(f"{shape}, got {text!r}", "scale")
        paper = float(m.group(1)) * _PAPER_CM[m.group(2)]
        amount, unit, per = float(m.group(3)), m.group(4), m.group(5)
        kind = _SCALE_KINDS[re.sub(r"[\s^]", "", per or "").replace("²", "2")]
        if kind in out:
            raise fail(f"scale states the {kind} scale twice", "scale")
        per_cm = amount * _SCALE_UNITS[unit] / mech.units.metres / paper
        tail = {"space": "", "velocity": "/s", "acceleration": "/s²"}[kind]
        out[kind] = Stated(per_cm, paper=f"{float(m.group(1)):g} {m.group(2)}", paper_cm=paper,
                           amount=amount, unit=unit + tail)
        _fits(kind, text, out[kind], mech, fail)
    return out


def _fits(kind: str, text: str, per_cm: float, mech: Mechanism, fail) -> None:
    """Refuse a stated velocity or acceleration scale that draws the input's (ω r, or
    |α r, ω² r|) shorter than a micrometre or longer than ten kilometres: no figure holds
    it, and its arrows are lost to rounding beside the mechanism."""
    size = {"velocity": mech.input_speed, "acceleration": mech.input_acceleration,
            "space": 0.0}[kind] / mech.units.metres
    if size == 0.0 or 1e-4 <= size / per_cm <= 1e6:
        return
    raise fail(f"the {kind} scale {text!r} draws the input's {kind}, {significant(size)} "
               f"{mech.units.length}/s{'²' if kind == 'acceleration' else ''}, "
               f"{significant(size / per_cm)} cm long; state one that draws it a few cm long",
               "scale")


def _angle_text(angle: float, deg: bool) -> str:
    return (f"{math.degrees(angle):.6g}°" if deg else f"{angle:.6g} rad").replace("-", "−")


def _find_hint(q: str, valid: set[str]) -> str:
    """What to ask instead of ``q``: the valid name nearest it; else the kinematic names,
    and the forces this mechanism answers as :data:`~tarsim.constructions.asks.EFFORTS`
    registers them; and a rod's equivalent system where ``q`` is near a [rod] file's ask."""
    from ..forces.rod_file import ROD_ASKS

    close = _closest(q, sorted(valid))
    if close:
        return f"did you mean '{close}'?"
    forces = [e for e in A.EFFORTS if e in valid]
    also = f"; or a force it answers: {', '.join(forces)}" if forces else ""
    if difflib.get_close_matches(q, ROD_ASKS, n=1, cutoff=0.5):
        return (f"a connecting rod given alone is a [rod] file (tarsim new rod), which asks "
                f"{', '.join(ROD_ASKS)}{also}")
    return ('use "centres", "I<i><j>", "omega<n>", "alpha<n>", "V_<point>", "A_<point>", '
            '"V_<point>/<point>", "A_cor_<point>", "dof", "grashof", "range_<XY>", '
            f'"time_ratio" or "stroke"{also}')


def _closest(got: str, valid) -> str | None:
    """The valid name nearest ``got``: a spelling neighbour, or one it abbreviates."""
    close = difflib.get_close_matches(got, list(valid), n=1)
    if close:
        return close[0]
    return next((v for v in valid if got and v.startswith(got)), None)
