"""The involute mesh of two spur gears, drawn by construction (exam text 001 ch. 4).

The two centres O2 and O3 stand the centre distance apart. By the law of gearing the pitch
point P divides O2O3 as the base radii (ω2/ω3 = O3P/O2P), which at the standard distance
puts it on both pitch circles. The line of action is the common internal tangent of the
base circles through P: each tangency point T is found by Thales' circle on OP. Its angle
to the common tangent of the pitch circles is the (working) pressure angle. The addendum
circles cut it where contact begins (A, on the driven gear's) and ends (B, on the
driver's): AB is the path of contact, AB / cos φ the arc of contact, and AB over the base
pitch the contact ratio. A contact end beyond its tangency point T is interference.

Each gear's tooth profile through P is traced as the end of a taut string unwound from its
base circle: the arc T S equal to PT is stepped back along the base circle, the arc from S
divided equally, and at each division the arc length laid off along the tangent; the points
so found are joined. Gear 2 drives, turning so that contact runs from A to B.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .. import geometry as g
from ..errors import InputError
from ..narration import (Number, Phrase, Word, counted, drawn_angle, drawn_length,
                         phrase)
from ..record import Construction, Kind, Panel, Ref
from .train import GearTrain

__all__ = ["Involute", "InvoluteMesh", "check_mesh", "draw_involute_mesh", "mesh_of",
           "least_teeth_drawn"]

_DIVISIONS = 8
"""Equal arcs the base circle is divided into between S and where the profile reaches the
addendum circle."""


@dataclass(frozen=True)
class Involute:
    """The mesh's data: the two gears, their pressure angle, addendum and dedendum (in
    modules) and the centre distance (m; None: the standard one)."""

    pinion: int
    wheel: int
    pressure_angle: float
    addendum: float = 1.0
    dedendum: float = 1.25
    centre_distance: float | None = None


@dataclass
class InvoluteMesh:
    """The drawn mesh: its record, the radii (m) of every circle by name, and what is read
    off it: the working pressure angle, the path and arc of contact, the base pitch, the
    contact ratio, and the gears whose tips reach past the other's tangency point (their
    addendum circles cut the line of action beyond it: interference)."""

    construction: Construction
    radii: dict[str, float] = field(default_factory=dict)
    profiles: dict[int, list[Ref]] = field(default_factory=dict)
    starts: dict[int, float] = field(default_factory=dict)
    """Each profile's start S on its base circle, as an angle about its centre (rad)."""
    centres: dict[int, tuple[float, float]] = field(default_factory=dict)
    pressure_angle: float = 0.0
    circular_pitch: float = 0.0
    path: float = 0.0
    arc: float = 0.0
    base_pitch: float = 0.0
    contact_ratio: float = 0.0
    interference: tuple[int, ...] = ()


def draw_involute_mesh(train: GearTrain, data: Involute) -> InvoluteMesh:
    """Draw the mesh of ``data.pinion`` (the driver) with ``data.wheel`` and read it.

    Raises
    ------
    InputError
        If either gear gives no module, the two do not mesh externally in ``train``, or
        they cannot mesh at the centre distance (see :func:`_check_distance`).
    """
    check_mesh(train, data)
    p, w = train.gear(data.pinion), train.gear(data.wheel)
    return mesh_of(float(p.module), (p.teeth, w.teeth), data, train.source)


def check_mesh(train: GearTrain, data: Involute) -> None:
    """Refuse a mesh that cannot be drawn: a gear with no module, a pair that does not mesh
    externally in ``train``, or one that cannot mesh at its centre distance.

    Raises
    ------
    InputError
        Naming the gears, in one line.
    """
    p, w = train.gear(data.pinion), train.gear(data.wheel)
    if p.module is None or w.module is None:
        raise InputError(f"the involute mesh is drawn to size: give {p.label} and {w.label} "
                         "their module", file=train.source or None)
    if not any({m.a, m.b} == {p.number, w.number} and not m.internal for m in train.meshes):
        raise InputError(f"{p.label} and {w.label} do not mesh externally in this train",
                         file=train.source or None)
    m = float(p.module)
    r2, r3 = m * p.teeth / 2, m * w.teeth / 2
    cos = math.cos(math.radians(data.pressure_angle))
    c = data.centre_distance if data.centre_distance is not None else r2 + r3
    _check_distance(data, (r2, r3), (r2 * cos, r3 * cos), m, c, train.source)


def mesh_of(module: float, teeth: tuple[float, float], data: Involute, source: str = "",
            *, profiles: bool = True) -> InvoluteMesh:
    """Draw the mesh of two gears of ``teeth`` (a gear of no whole number of teeth is
    drawn all the same, as the least-teeth search needs) at ``module`` (m)."""
    m = module
    r2, r3 = m * teeth[0] / 2, m * teeth[1] / 2
    phi = math.radians(data.pressure_angle)
    rb2, rb3 = r2 * math.cos(phi), r3 * math.cos(phi)
    c = data.centre_distance if data.centre_distance is not None else r2 + r3
    _check_distance(data, (r2, r3), (rb2, rb3), m, c, source)
    out = InvoluteMesh(Construction())
    _Drafting(out, teeth, data, m, (r2, r3), (rb2, rb3), c).run(profiles)
    return out


def _check_distance(data: Involute, pitch: tuple[float, float], base: tuple[float, float],
                    m: float, c: float, source: str) -> None:
    """Refuse a pair that cannot mesh at centre distance ``c``: a gear whose root circle
    falls inside its centre, base circles that overlap (no line of action), tips that
    strike the other gear's root circle, addendum circles that do not reach each other, or
    that overlap off the line of action (a path of contact of no length)."""
    (r2, r3), (rb2, rb3) = pitch, base
    add, ded = data.addendum * m, data.dedendum * m
    ra, rf = (r2 + add, r3 + add), (r2 - ded, r3 - ded)
    numbers = (data.pinion, data.wheel)

    def mm(x: float) -> str:
        return f"{x * 1e3:.6g} mm"

    def fail(message: str) -> InputError:
        return InputError(f"gears {numbers[0]} and {numbers[1]} {message}; the pitch circles "
                          f"need {mm(r2 + r3)}", file=source or None)

    for k in (0, 1):
        if rf[k] <= 0:
            raise InputError(f"gear {numbers[k]} has too few teeth for its dedendum: its pitch "
                             f"radius {mm(pitch[k])} is no more than the dedendum {mm(ded)}",
                             file=source or None)
    if not c > rb2 + rb3:
        raise fail(f"have no line of action: the centre distance {mm(c)} leaves their base "
                   f"circles ({mm(2 * rb2)} and {mm(2 * rb3)} across) overlapping")
    for k in (0, 1):             # touching is clear; below a rounding of the sizes, a jam
        if c < (ra[k] + rf[1 - k]) * (1 - 1e-12):
            raise fail(f"jam: at a centre distance of {mm(c)} the tips of gear {numbers[k]} "
                       f"strike the root circle of gear {numbers[1 - k]}, which needs "
                       f"{mm(ra[k] + rf[1 - k])}")
    if c >= ra[0] + ra[1]:
        raise fail(f"do not touch: the centre distance is {mm(c)}, and their addendum circles "
                   f"reach only {mm(ra[0] + ra[1])}")
    # The line of action's length inside both addendum circles, as the path of contact.
    reach = math.sqrt(ra[0] ** 2 - rb2 ** 2) + math.sqrt(ra[1] ** 2 - rb3 ** 2)
    widest = math.hypot(rb2 + rb3, reach)
    if c >= widest:
        raise fail(f"overlap only off the line of action: at a centre distance of {mm(c)} "
                   f"their teeth never touch; it must stay below {mm(widest)}")


def least_teeth_drawn(module: float, ratio: float, data: Involute, most: int = 400) -> int:
    """The fewest teeth the pinion may have, the wheel ``ratio`` times as many, for no
    interference: the mesh drawn again with one tooth more until neither gear's tips reach
    past the other's tangency point."""
    for n in range(4, most + 1):
        trial = Involute(data.pinion, data.wheel, data.pressure_angle, data.addendum,
                         data.dedendum)
        if not mesh_of(module, (n, n * ratio), trial, profiles=False).interference:
            return n
    raise InputError(f"no pinion of up to {most} teeth clears interference at this ratio")


class _Drafting:
    def __init__(self, out: InvoluteMesh, teeth: tuple[float, float], data: Involute, m: float,
                 pitch: tuple[float, float], base: tuple[float, float], c: float):
        self.out, self.teeth, self.d, self.c = out, teeth, data, out.construction
        self.m, self.pitch, self.base, self.distance = m, pitch, base, c
        self.n = (data.pinion, data.wheel)

    def act(self, ref: Ref, verb: str, *inputs: Ref, said=None, label: str = "",
            kind: Kind | None = None, **params) -> Ref:
        self.c.draw(ref, verb, *inputs, label=label, phrase=said, kind=kind,
                    panel=Panel.SPACE, **params)
        return ref


    def run(self, profiles: bool = True) -> None:
        c, (a, b) = self.c, self.n
        (r2, r3), (rb2, rb3), dist = self.pitch, self.base, self.distance
        out = self.out
        c.give("O2", g.Point(0.0, 0.0), label=f"O{a}", kind=Kind.JOINT,
               phrase=phrase("involute.centres", a=a, b=b, distance=drawn_length(dist)))
        c.give("O3", g.Point(dist, 0.0), label=f"O{b}", kind=Kind.JOINT)
        out.centres = {a: (0.0, 0.0), b: (dist, 0.0)}
        self.act("centres", "line_through", "O2", "O3", kind=Kind.GUIDE, said=None)
        # The pitch point divides O2O3 as the base radii (the law of gearing).
        share = dist * rb2 / (rb2 + rb3)
        self.act("P", "lay_off", "O2", "O3", length=share, label="P", kind=Kind.CENTRE,
                 said=phrase("involute.pitch_point", a=a, b=b, o2p=drawn_length(share),
                             na=f"{self.teeth[0]:g}", nb=f"{self.teeth[1]:g}"))
        for ref, centre, radius, name in (("pitch2", "O2", r2, _circle("pitch", a)),
                                          ("pitch3", "O3", r3, _circle("pitch", b)),
                                          ("base2", "O2", rb2, _circle("base", a)),
                                          ("base3", "O3", rb3, _circle("base", b))):
            self.act(ref, "swing_arc", centre, radius=radius, kind=Kind.ARC,
                     said=phrase("involute.circle", name=name, radius=drawn_length(radius)))
            out.radii[ref] = radius
        # Thales: the tangency point of the line of action on each base circle.
        for k, (centre, base) in enumerate((("O2", "base2"), ("O3", "base3")), start=2):
            mid = self.act(f"M{k}", "midpoint", centre, "P", said=None)
            thales = self.act(f"thales{k}", "circle_through", mid, centre, kind=Kind.ARC,
                              said=phrase("involute.thales", centre=self.c[centre].label))
            self.act(f"T{k}", "intersect_circles", thales, base, pick="left",
                     label=f"T{self.n[k - 2]}", said=phrase(
                         "involute.tangent_point", point=f"T{self.n[k - 2]}",
                         base=_circle("base", self.n[k - 2])))
        self.act("action", "line_through", "T2", "T3", kind=Kind.GUIDE,
                 said=phrase("involute.line_of_action", a=a, b=b))
        # The common tangent of the pitch circles at P: O3 swung a right angle about P.
        self.act("U", "rotate_about", "O3", "P", angle=math.pi / 2, said=None)
        self.act("tangent", "line_through", "P", "U", kind=Kind.LINE,
                 said=phrase("involute.common_tangent"))
        angle = self.act("phi", "measure_angle", "P", "U", "T3", turn=-1.0, label="φ")
        out.pressure_angle = math.radians(self.c.output(angle).degrees)
        # Addendum and dedendum circles; where contact begins and ends.
        add, ded = self.d.addendum * self.m, self.d.dedendum * self.m
        for ref, centre, radius, name in (("addendum2", "O2", r2 + add, _circle("addendum", a)),
                                          ("addendum3", "O3", r3 + add, _circle("addendum", b)),
                                          ("root2", "O2", r2 - ded, _circle("root", a)),
                                          ("root3", "O3", r3 - ded, _circle("root", b))):
            self.act(ref, "swing_arc", centre, radius=radius, kind=Kind.ARC,
                     said=phrase("involute.circle", name=name, radius=drawn_length(radius)))
            out.radii[ref] = radius
        self.act("A", "intersect_line_circle", "action", "addendum3", pick="backward",
                 label="A", said=phrase("involute.start", b=b))
        self.act("B", "intersect_line_circle", "action", "addendum2", pick="forward",
                 label="B", said=phrase("involute.end", a=a))
        path = g.distance(self.c.output("A"), self.c.output("B"))
        out.path = path
        out.arc = path / math.cos(out.pressure_angle)
        out.base_pitch = 2 * math.pi * rb2 / self.teeth[0]
        # The circular pitch: P stepped one tooth round the pitch circle of the pinion.
        self.act("P1", "rotate_about", "P", "O2", angle=2 * math.pi / self.teeth[0], label="P′",
                 said=phrase("involute.circular_pitch", a=a, teeth=f"{self.teeth[0]:g}"))
        out.circular_pitch = r2 * 2 * math.pi / self.teeth[0]
        out.contact_ratio = path / out.base_pitch
        self.act("AB", "measure", "A", "B", label="path of contact", kind=Kind.DIMENSION,
                 said=phrase("involute.path", path=drawn_length(path),
                             arc=drawn_length(out.arc), pitch=drawn_length(out.base_pitch),
                             ratio=Number(out.contact_ratio, ".4g"),
                             angle=drawn_angle(out.pressure_angle)))
        # A tip reaches past the other gear's tangency point when its contact end lies
        # farther from its own gear's tangency point than that one: B beyond T3 measured
        # from T2, A beyond T2 from T3 (from P, an end on the far side of P would pass).
        out.interference = tuple(
            n for n, end, t, own in ((a, "B", "T3", "T2"), (b, "A", "T2", "T3"))
            if g.distance(self.c.output(own), self.c.output(end))
            > g.distance(self.c.output(own), self.c.output(t)) * (1 + 1e-12))
        for n, t, centre, rb, radius in ((a, "T2", "O2", rb2, r2 + add),
                                         (b, "T3", "O3", rb3, r3 + add)):
            if profiles:
                self.profile(n, t, centre, rb, radius)

    def profile(self, n: int, t: Ref, centre: Ref, rb: float, tip: float) -> None:
        """Gear ``n``'s tooth through P: the string unwound from its base circle."""
        k = 2 if centre == "O2" else 3
        pt = g.distance(self.c.output("P"), self.c.output(t))
        # Step the arc TS = PT back along the base circle: S, where the string starts.
        s = self.act(f"S{k}", "rotate_about", t, centre, angle=pt / rb, label=f"S{n}",
                     said=phrase("involute.start_point", gear=n, point=f"S{n}",
                                 t=self.c[t].label, length=drawn_length(pt)))
        sx, sy = self.c.output(s).xy
        ox, oy = self.c.output(centre).xy
        self.out.starts[n] = math.atan2(sy - oy, sx - ox)
        reach = math.sqrt(tip * tip - rb * rb) / rb          # the roll angle at the tip
        step = reach / _DIVISIONS
        points = [s]
        for i in range(1, _DIVISIONS + 1):
            d = self.act(f"D{k}:{i}", "rotate_about", s, centre, angle=-i * step, said=None)
            out = self.act(f"E{k}:{i}", "lay_off", d, centre, length=-rb * i * step, said=None)
            points.append(self.act(f"X{k}:{i}", "rotate_about", out, d, angle=math.pi / 2,
                                   said=None))
        self.c.draw(f"profile{k}", "mark", points[-1], panel=Panel.SPACE, phrase=phrase(
            "involute.profile", gear=n, point=f"S{n}", divisions=counted(_DIVISIONS),
            arc=drawn_angle(step)))
        self.out.profiles[n] = points


def _circle(kind: str, gear) -> Phrase:
    """"pitch circle of 2", for each language to say its own way."""
    return phrase("involute.circle_of", circle=Word(f"{kind} circle"), gear=gear)
