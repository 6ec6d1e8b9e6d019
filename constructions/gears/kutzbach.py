"""The velocity (Kutzbach) diagram of a planetary train, drawn by construction.

Along one radial line from the main axis every point of every member moves square to the
line, so each member's velocities along it lie on a straight line in a diagram of radius
(up) against velocity (across, counter-clockwise to the right), and its slope is the
member's ω. A member that turns about the main axis has its line through the axis O; the
fixed one's is the radial line itself. Two gears in mesh share the velocity of their pitch
point, and a planet's centre moves with the arm, at that planet's carrier radius (R, R′, …
where the arm carries planets at several). So, from the fixed member and the input, each
line is drawn through two points found before it, and every speed is read off as a slope,
Δv/Δr. A planet that drives is drawn through its pitch point with the fixed member, its
instant centre. Where no line can follow from the input's (the input and the fixed member
meet no common body), the diagram is drawn first for a trial speed of the arm and the
arm's true speed taken from the input's slope in it, as similar diagrams scale.

The diagram is drawn in drawing metres: radii true (in modules, a millimetre each, where no
gear gives its module), velocities at ``per`` drawing metres per m/s. It needs every mesh
to have a gear on the main axis: planets meshing with each other are refused in a line
(:func:`undrawable` says why). A pinion on a side shaft is off the radial line: the speed it
gives the main-axis gear it drives is carried by the tooth ratio, and the diagram starts
from that gear.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction

from .. import geometry as g
from ..errors import InputError
from ..narration import Number, Phrase, Word, phrase, significant
from ..record import Construction, Kind, Panel, Ref, Role
from ..units import LENGTH_UNITS
from ..scales import nice_per_cm
from .tabular import main_axis_train
from .train import GearTrain

__all__ = ["Kutzbach", "draw_kutzbach", "undrawable", "DRAWN"]

DRAWN = 4096 * 2.0 ** -52
"""The rounding a drawn length carries, relative to the drawing's size: a few thousand of
a float's, for some dozens of drafting acts each rounding their coordinates."""


@dataclass
class Kutzbach:
    """The drawn diagram: its record, the drawing metres per m/s, each body's line and the
    two points it was drawn through, the levels by radius name, and each member's ω read
    as a slope (rad/s)."""

    construction: Construction
    per: float
    metre: float
    """Drawing metres per unit of the train's sizes (1, or a millimetre a module)."""
    per_cm: float
    """The radius scale: the train's size unit (file length unit, or modules) per paper cm."""
    velocity_per_cm: float
    """The velocity scale: size units per second per paper cm."""
    unit: str
    """The size unit the scales state: the file's length unit, or "modules"."""
    stated: float
    """Drawing metres per unit the scales state."""
    lines: dict[tuple[int, ...], Ref] = field(default_factory=dict)
    through: dict[tuple[int, ...], tuple[Ref, Ref]] = field(default_factory=dict)
    levels: dict[str, Ref] = field(default_factory=dict)
    omegas: dict[int, float] = field(default_factory=dict)
    conditioning: dict[int, float] = field(default_factory=dict)
    """Each member's reading's conditioning: the span of radii its line was read across
    over the diagram's largest (1 for the fixed member, read as nil without a slope)."""

    def rounding(self, member: int, fastest: float) -> float:
        """What rounding leaves uncertain in ``member``'s ω read as a slope (rad/s): the
        drawing's velocities, of the ``fastest`` ω (rad/s) at the largest radius, rounded
        by :data:`DRAWN`, over the span of radii its line was read across."""
        return DRAWN * fastest / self.conditioning[member]

    def said(self, member: int) -> float:
        """``member``'s ω (rad/s) as the diagram says it: 0 where its slope is within the
        drawing's rounding of nil (a member at rest in a train whose others turn at
        1e28 rpm reads 1e12, the last bit of the fastest's coordinates)."""
        w = self.omegas[member]
        fastest = max(abs(v) for v in self.omegas.values())
        return 0.0 if abs(w) <= self.rounding(member, fastest) else w


@dataclass(frozen=True)
class _Source:
    """A point a body's line may be drawn through, read off a body drawn before it: the
    pitch point of ``mesh`` (this body's gear, the drawn body's gear), or the centre of
    the planet body ``centre``, which it shares with the arm. ``level`` is its radius."""

    level: Fraction
    known: tuple[int, ...]
    mesh: tuple[int, int] | None = None
    centre: tuple[int, ...] | None = None


@dataclass(frozen=True)
class _Start:
    """The first line drawn after the fixed member's: ``member``'s, at ``omega`` (rad/s);
    through O for a member on the main axis, or through ``about``, the pitch point of a
    planet's gear with the fixed member's (its instant centre). ``trial``: the trial speed
    of ``member`` and the input's speed it gave, when ``omega`` was scaled from them."""

    member: int
    omega: float
    about: tuple[int, int] | None = None
    trial: tuple[float, float] | None = None


def carrier_radii(train: GearTrain) -> dict[tuple[int, ...], Fraction]:
    """Each planet body's carrier radius: its pitch radius off the first main-axis gear it
    meshes (the train's check holds every such mesh of one body to one radius)."""
    out: dict[tuple[int, ...], Fraction] = {}
    for body in train.bodies:
        if not train.carried(body[0]):
            continue
        for mesh in train.meshes:
            for p, c in ((mesh.a, mesh.b), (mesh.b, mesh.a)):
                if p in body and not train.carried(c) and body not in out:
                    rp, rc = train.pitch_radius(p), train.pitch_radius(c)
                    out[body] = rc - rp if mesh.internal else rc + rp
    return out


def _sources(train: GearTrain, body: tuple[int, ...], known, radii) -> list[_Source]:
    """The points ``body``'s line may be drawn through, given the bodies ``known`` drawn."""
    out = []
    for mesh in train.meshes:
        for a, b in ((mesh.a, mesh.b), (mesh.b, mesh.a)):
            if a in body and train.body(b) in known:
                main = b if train.carried(a) else a
                out.append(_Source(train.pitch_radius(main), train.body(b), mesh=(a, b)))
    arm = train.body(train.arm)
    if body in radii and arm in known:
        out.append(_Source(radii[body], arm, centre=body))
    if body == arm:
        out += [_Source(r, p, centre=p) for p, r in radii.items() if p in known]
    return out


def _enough(train: GearTrain, body, sources: list[_Source]) -> list[_Source]:
    """The sources a line is drawn through: one for a body about the main axis (its line
    runs through O), two at different radii for a planet; none if there are too few."""
    if not train.carried(body[0]):
        return sources[:1]
    for s in sources[1:]:
        if s.level != sources[0].level:
            return [sources[0], s]
    return []


def _reaches(train: GearTrain, known: set, radii) -> bool:
    """True if, from the bodies ``known``, every body's line can be drawn in turn."""
    known = set(known)
    grew = True
    while grew:
        grew = False
        for body in train.bodies:
            if body not in known and _enough(train, body, _sources(train, body, known, radii)):
                known.add(body)
                grew = True
    return len(known) == len(train.bodies)


def _plan(train: GearTrain, radii) -> tuple[int, tuple[int, int] | None, bool] | None:
    """The member whose line is drawn first, the planet's instant centre it is drawn
    through (or None: through O), and whether its speed needs a trial first; None if no
    start reaches every body."""
    fixed, drive = train.body(train.fixed), train.body(train.input_member)
    if not train.carried(train.input_member):
        about = None
    else:
        about = next(((a, b) for m in train.meshes for a, b in ((m.a, m.b), (m.b, m.a))
                      if a in drive and b in fixed), None)
    if (not train.carried(train.input_member) or about) and _reaches(
            train, {fixed, drive}, radii):
        return train.input_member, about, False
    for m in (train.arm, *(gear.number for gear in train.gears)):
        body = train.body(m)
        if not train.carried(m) and body != fixed and _reaches(train, {fixed, body}, radii):
            return m, None, True
    return None


def undrawable(train: GearTrain) -> str | None:
    """Why ``train`` has no velocity diagram (an ordinary train, planets meshing each other,
    a gear on an axis of its own, no line to start from), or None if it has one."""
    two = train.fixed is None and train.second is not None
    if not train.planetary or (train.fixed is None and not two) or (
            train.fixed is not None and train.arm in train.body(train.fixed)):
        return "an ordinary train has no velocity diagram: its axes stand still"
    if train.fixed in train.off_axis:
        return "the fixed member turns on a side shaft, off the radial line"
    if any(mesh.bevel for mesh in train.meshes):
        return ("a bevel gear turns about an axis square to the main axis, off the plane of "
                "the velocity diagram: the table alone solves this train")
    if train.off_axis:                    # the diagram draws the main axis and the planets
        train = main_axis_train(train, [])[0]
    if two and any(train.carried(m) for m in (train.input_member, train.second[0])):
        return ("a given speed is a planet's, and its line needs a point at rest: the table "
                "alone solves this train")
    if not two and train.carried(train.fixed):
        return f"the fixed member {train.fixed} is carried by the arm: the arm cannot turn"
    if train.uncoaxial(sized_too=True):     # the diagram lays radii off in modules
        return ("a planet's meshes stand at different radii in modules (its gears differ in "
                "module, or are corrected): the table alone solves this train")
    for mesh in train.meshes:
        a, b = train.gear(mesh.a).label, train.gear(mesh.b).label
        if train.carried(mesh.a) and train.carried(mesh.b):
            return (f"the velocity diagram runs along one radial line, and {a} and {b} are "
                    "both planets, their mesh off it: the table alone solves this train")
        if not (train.carried(mesh.a) or train.carried(mesh.b)):
            return (f"the velocity diagram runs along one radial line, and {a} and {b} both "
                    "turn on fixed axes, one off the main axis: the table alone solves "
                    "this train")
    radii = carrier_radii(train)
    if (two and not _reaches(train, {train.body(train.input_member),
                                     train.body(train.second[0])}, radii)) or (
            not two and _plan(train, radii) is None):
        return ("the velocity diagram cannot reach every member from the fixed one and "
                "the input: the table alone solves this train")
    return None


def draw_kutzbach(train: GearTrain, sizes: dict[int, Fraction]) -> Kutzbach:
    """Draw the diagram from the fixed member and the input's speed; read every ω off it.
    ``sizes`` (every member's speed, as the table found them) only chooses the velocity
    scale, so that the fastest pitch point fits: nothing is read from it.

    Raises
    ------
    InputError
        If the train has no diagram (see :func:`undrawable`).
    """
    why = undrawable(train)
    if why is not None:
        raise InputError(why, file=train.source or None)
    side: list[Phrase] = []               # gears on side shafts drive a main-axis gear
    if train.off_axis:
        train = main_axis_train(train, side)[0]
    radii = carrier_radii(train)
    w = float(train.input_speed) * train.units.per_rad_s
    if train.fixed is None:       # two given speeds: two lines through O, the rest from them
        m2, w2 = train.second[0], float(train.second[1]) * train.units.per_rad_s
        return _Diagram(train, sizes, radii, _Start(train.input_member, w), side,
                        _Start(m2, w2)).run()
    member, about, trial = _plan(train, radii)
    if not trial:
        return _Diagram(train, sizes, radii, _Start(member, w, about), side).run()
    # Drawn first at a trial speed of ``member``: every velocity scales with it, so the
    # input's slope in the trial gives the true speed.
    read = _Diagram(train, sizes, radii, _Start(member, w)).run().omegas[train.input_member]
    if read == 0:
        raise InputError(f"the input, {train.label(train.input_member)}, stands still "
                         "whatever the arm does: it cannot drive the train",
                         file=train.source or None)
    start = _Start(member, w * w / read, trial=(w, read))
    return _Diagram(train, sizes, radii, start, side).run()


_ROOM = (90.0, 110.0)
"""Paper (mm) the diagram's velocities either side of the radial line, and its radii, fit."""


class _Diagram:
    def __init__(self, train: GearTrain, sizes: dict[int, Fraction], radii, start: _Start,
                 side: list[Phrase] = (), second: _Start | None = None):
        self.t, self.radii, self.start, self.side = train, radii, start, side
        self.second = second
        """The second given member's start, where no member is fixed."""
        self.metre = 1.0 if train.sized else 1e-3
        distinct = list(dict.fromkeys(radii.values()))
        self.arm_r = distinct[0]
        self.named = {r: ("R" + "′" * k, "C" + "′" * k, "kz:centre" + (f":{k}" if k else ""))
                      for k, r in enumerate(distinct)}
        unit = train.units.length if train.sized else "modules"
        metres = 1.0 / LENGTH_UNITS[unit] if train.sized else 1.0   # size units per file unit
        radius = {m: float(train.pitch_radius(m)) for m in (gr.number for gr in train.gears)}
        if train.arm is not None:
            radius[train.arm] = float(max(distinct))
        per = train.units.per_rad_s
        fastest = max(abs(float(sizes[m])) * per * r for m, r in radius.items()) * metres
        per_cm = nice_per_cm(max(radius.values()) * metres, _ROOM[1])
        per_cm_v = nice_per_cm(fastest, _ROOM[0])
        self.c = Construction()
        self.k = Kutzbach(self.c, per_cm / per_cm_v, self.metre, per_cm, per_cm_v, unit,
                          LENGTH_UNITS[unit] if train.sized else self.metre)

    # ----- drafting -----------------------------------------------------------------------
    def act(self, ref: Ref, verb: str, *inputs: Ref, said, label: str = "",
            kind: Kind | None = None, role: Role = Role.CONSTRUCTION, **params) -> Ref:
        """One drafting act in the diagram's panel, once whoever asks for it."""
        if ref not in self.c:
            self.c.draw(ref, verb, *inputs, label=label, phrase=said, kind=kind, role=role,
                        panel=Panel.VELOCITY, **params)
        return ref

    def level(self, name: str, size: Fraction, what: Phrase) -> Ref:
        """The level of radius ``size`` (the train's sizes), marked on the radial line."""
        ref = f"kz:level:{name}"
        if ref not in self.c:
            mark = self.act(f"kz:r:{name}", "lay_off", "kz:O", "kz:radial",
                            length=float(size) * self.metre, label=name,
                            said=phrase("kutzbach.radius", name=name, what=what,
                                        radius=self.t.size_text(size)))
            self.act(ref, "parallel_through", mark, "kz:across", kind=Kind.LINE, said=None)
            self.k.levels[name] = ref
        return ref

    def carrier_level(self, size: Fraction) -> tuple[str, Ref]:
        """The level where the arm carries planets at radius ``size``, and its name."""
        name = self.named[size][0]
        if len(self.named) == 1:
            what = phrase("kutzbach.planet_centres")
        else:
            what = phrase("kutzbach.planet_centre", member=", ".join(
                _names(b) for b, r in self.radii.items() if r == size))
        return name, self.level(name, size, what)

    def run(self) -> Kutzbach:
        t, c = self.t, self.c
        c.give("kz:O", g.Point(0.0, 0.0), label="O", kind=Kind.POINT, panel=Panel.VELOCITY,
               phrase=phrase("kutzbach.radial"))
        c.give("kz:radial", g.Line(-1.0, 0.0, 0.0), label="", kind=Kind.GUIDE,
               panel=Panel.VELOCITY)
        c.give("kz:across", g.Line(0.0, 1.0, 0.0), label="", kind=Kind.LINE,
               panel=Panel.VELOCITY)
        if self.second is None:
            self.k.lines[t.body(t.fixed)] = "kz:radial"
            self.act("kz:fixed", "mark", "kz:O", said=phrase(
                "kutzbach.fixed", member=t.said(t.fixed, opening=True)))
        else:
            self.act("kz:two", "mark", "kz:O", said=phrase(
                "kutzbach.two_given", a=t.said(self.start.member),
                b=t.said(self.second.member)))
        for k, said in enumerate(self.side):      # off the radial line: by the tooth ratios
            self.act(f"kz:side:{k}", "mark", "kz:O", said=said)
        if self.start.about is None:
            self.draw_start(self.start)
        else:
            self.draw_planet_start()
        if self.second is not None:
            self.draw_start(self.second)
        while len(self.k.lines) < len(t.bodies):
            if not self.next_line():
                raise InputError("the velocity diagram cannot reach every member from the "
                                 "fixed one and the input", file=t.source or None)
        self.read()
        return self.k

    def level_of(self, m: int) -> tuple[str, Fraction]:
        """The radius a member's velocity is laid off at: a gear's pitch radius, or where the
        arm carries its (first) planets."""
        if m == self.t.arm:
            return "R", self.arm_r
        return f"r{m}", self.t.pitch_radius(m)

    def draw_start(self, s: _Start) -> None:
        """A start member's velocity laid off at its radius, and its line through O."""
        t = self.t
        m, w = s.member, s.omega
        if s.trial is not None:
            per = t.units.per_rad_s
            self.act("kz:trial", "mark", "kz:O", said=phrase(
                "kutzbach.trial", member=t.said(m), trial=Number(abs(s.trial[0]), ".4g"),
                drive=t.said(t.input_member), read=Number(abs(s.trial[1]), ".4g"),
                given=Number(abs(t.input_speed * per), ".4g"), omega=Number(abs(w), ".4g"),
                sense=Word("ccw" if w > 0 else "cw"), trial_sense=Word(
                    "ccw" if s.trial[0] > 0 else "cw"), read_sense=Word(
                    "ccw" if s.trial[1] > 0 else "cw")))
        name, size = self.level_of(m)
        r = float(size) * self.metre
        lvl = (self.carrier_level(size)[1] if m == t.arm and len(self.named) > 1
               else self.level(name, size, t.said(m)))
        # The arm's velocity at R is the planets' centre's: it goes by that name, C.
        tip = self.act(f"kz:v:{m}", "lay_off", f"kz:r:{name}", lvl, length=w * r * self.k.per,
                       label="C" if m == t.arm else f"v{m}", said=phrase(
                           "kutzbach.input", member=t.said(m, opening=True), name=name,
                           omega=Number(abs(w)), radius=t.size_text(size),
                           sense=Word("ccw" if w > 0 else "cw")))
        self.through_origin(t.body(m), tip)

    def draw_planet_start(self) -> None:
        """A driving planet: its centre's velocity about its pitch point with the fixed
        member (at rest, its instant centre), and its line through the two."""
        t, s = self.t, self.start
        a, b = s.about
        body = t.body(s.member)
        pitch = self.pitch(a, b)
        size = self.radii[body]
        name, lvl = self.carrier_level(size)
        label, ref = self.named[size][1:]
        held = t.pitch_radius(b)
        tip = self.act(ref, "lay_off", f"kz:r:{name}", lvl,
                       length=s.omega * float(size - held) * self.metre * self.k.per,
                       label=label, said=phrase(
                           "kutzbach.input_planet", member=t.said(s.member, opening=True),
                           omega=Number(abs(s.omega)), sense=Word("ccw" if s.omega > 0
                                                                  else "cw"),
                           pitch=self.c[pitch].label, name=name, point=label,
                           level=f"r{b}"))
        self.draw_planet(body, pitch, tip)

    def draw_planet(self, body, p: Ref, q: Ref) -> None:
        ref = f"kz:line:{body[0]}"
        self.act(ref, "line_through", p, q, label=_names(body), said=phrase(
            "kutzbach.planet_line", member=_names(body), p=self.c[p].label,
            q=self.c[q].label))
        self.k.lines[body] = ref
        self.k.through[body] = (p, q)

    def through_origin(self, body, point: Ref) -> None:
        ref = f"kz:line:{body[0]}"
        self.act(ref, "line_through", "kz:O", point, label=_names(body), said=phrase(
            "kutzbach.main_line", member=_names(body), point=self.c[point].label))
        self.k.lines[body] = ref
        self.k.through[body] = ("kz:O", point)

    def next_line(self) -> bool:
        """Draw one more body's line from what is drawn; False if none can be."""
        t, known = self.t, self.k.lines
        for body in t.bodies:
            if body in known:
                continue
            chosen = _enough(t, body, _sources(t, body, known, self.radii))
            if not chosen:
                continue
            points = [self.point(s) for s in chosen]
            if t.carried(body[0]):
                self.draw_planet(body, *points)
            else:
                self.through_origin(body, points[0])
            return True
        return False

    def point(self, s: _Source) -> Ref:
        """Draw the point ``s`` on the line of the body it is read from."""
        if s.mesh is not None:
            return self.pitch(*s.mesh)
        size = self.radii[s.centre]
        name, lvl = self.carrier_level(size)
        label, ref = self.named[size][1:]
        if len(self.named) == 1:
            said = phrase("kutzbach.centre", known=_names(s.known))
        else:
            said = phrase("kutzbach.centre_at", point=label, name=name,
                          member=_names(s.centre), known=_names(s.known))
        return self.act(ref, "intersect_lines", self.k.lines[s.known], lvl, label=label,
                        said=said)

    def pitch(self, a: int, b: int) -> Ref:
        """The pitch point of gear ``a`` with gear ``b``, whose body's line is drawn: where
        that line crosses the level of the main-axis gear's pitch radius."""
        t = self.t
        main = b if t.carried(a) else a
        name = f"r{main}"
        lvl = self.level(name, t.pitch_radius(main), t.said(main))
        lo, hi = sorted((a, b))
        return self.act(
            f"kz:pitch:{lo}-{hi}", "intersect_lines", self.k.lines[t.body(b)], lvl,
            label=f"P{lo}{hi}", said=phrase("kutzbach.pitch", a=t.said(a, opening=True),
                                            b=t.said(b), name=name, known=_names(t.body(b))))

    def read(self) -> None:
        """Each member's ω: the slope of its body's line, Δv/Δr at the diagram's scales,
        said as nil where it is within the drawing's rounding of it."""
        per, k = self.k.per, self.k
        top = max(abs(self.c.output(r).xy[1]) for pair in k.through.values() for r in pair)
        for body, ref in k.lines.items():
            w, span = 0.0, top
            if ref != "kz:radial":
                p, q = (self.c.output(r).xy for r in k.through[body])
                w, span = (q[0] - p[0]) / per / (q[1] - p[1]), abs(q[1] - p[1])
            for m in body:
                k.omegas[m], k.conditioning[m] = w, span / top
        for body, ref in k.lines.items():
            w = k.said(body[0])
            rate = w / self.t.units.per_rad_s
            if not self.t.speed_given:         # drawn for the input at 1: a ratio
                i = self.t.input_member
                self.c.draw(f"kz:read:{body[0]}", "mark", self.k.through[body][-1]
                            if ref != "kz:radial" else "kz:O", panel=Panel.VELOCITY,
                            role=Role.RESULT, phrase=phrase(
                                "kutzbach.read_ratio", member=_names(body), i=i,
                                omega=Number(abs(w)), unit=self.t.units.speed,
                                sense=phrase("gears.sense", sense=Word("ccw" if w > 0 else
                                                                       "cw")) if w else None,
                                ratio=significant(w / k.said(i))))
                continue
            self.c.draw(f"kz:read:{body[0]}", "mark", self.k.through[body][-1]
                        if ref != "kz:radial" else "kz:O", panel=Panel.VELOCITY,
                        role=Role.RESULT, phrase=phrase(
                            "kutzbach.read", member=_names(body), omega=Number(abs(w)),
                            speed=f"{significant(abs(rate))} {self.t.units.speed}",
                            sense=phrase("gears.sense", sense=Word("ccw" if w > 0 else "cw"))
                            if w else None))


def _names(body) -> str:
    """A body as the diagram names its line: "3", or "3–4" for gears on one shaft."""
    return "–".join(str(m) for m in body)
