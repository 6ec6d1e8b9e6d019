"""The velocity (Kutzbach) diagram of a planetary train, drawn by construction.

Along one radial line from the main axis every point of every member moves square to the
line, so each member's velocities along it lie on a straight line in a diagram of radius
(up) against velocity (across, counter-clockwise to the right), and its slope is the
member's ω. A member that turns about the main axis has its line through the axis O; the
fixed one's is the radial line itself. Two gears in mesh share the velocity of their pitch
point, and a planet's centre moves with the arm. So, from the fixed member and the input,
each line is drawn through two points found before it, and every speed is read off as a
slope, Δv/Δr.

The diagram is drawn in drawing metres: radii true (in modules, a millimetre each, where no
gear gives its module), velocities at ``per`` drawing metres per m/s. It needs every mesh
to have a gear on the main axis; planets meshing with each other are refused in a line.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction

from .. import geometry as g
from ..errors import InputError
from ..narration import Number, Phrase, Word, phrase, significant
from ..record import Construction, Kind, Panel, Ref, Role
from ..model import LENGTH_UNITS
from ..scales import nice_per_cm
from .train import GearTrain

__all__ = ["Kutzbach", "draw_kutzbach"]


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


def draw_kutzbach(train: GearTrain, sizes: dict[int, Fraction]) -> Kutzbach:
    """Draw the diagram from the fixed member and the input's speed; read every ω off it.
    ``sizes`` (every member's speed, as the table found them) only chooses the velocity
    scale, so that the fastest pitch point fits: nothing is read from it.

    Raises
    ------
    InputError
        If a mesh joins two planets (it is off the radial line).
    """
    return _Diagram(train, sizes).run()


_ROOM = (90.0, 110.0)
"""Paper (mm) the diagram's velocities either side of the radial line, and its radii, fit."""


class _Diagram:
    def __init__(self, train: GearTrain, sizes: dict[int, Fraction]):
        self.t = train
        for mesh in train.meshes:
            if train.carried(mesh.a) and train.carried(mesh.b):
                raise InputError(f"the velocity diagram runs along one radial line, and "
                                 f"{train.gear(mesh.a).label} and {train.gear(mesh.b).label} "
                                 "are both planets, their mesh off it: the table alone solves "
                                 "this train", file=train.source or None)
        self.metre = 1.0 if train.sized else 1e-3
        self.arm_r = self._arm_radius()
        unit = train.units.length if train.sized else "modules"
        metres = 1.0 / LENGTH_UNITS[unit] if train.sized else 1.0   # size units per file unit
        radius = {m: float(train.pitch_radius(m)) for m in (gr.number for gr in train.gears)}
        if train.arm is not None:
            radius[train.arm] = float(self.arm_r)
        per = train.units.per_rad_s
        fastest = max(abs(float(sizes[m])) * per * r for m, r in radius.items()) * metres
        per_cm = nice_per_cm(max(radius.values()) * metres, _ROOM[1])
        per_cm_v = nice_per_cm(fastest, _ROOM[0])
        self.c = Construction()
        self.k = Kutzbach(self.c, per_cm / per_cm_v, self.metre, per_cm, per_cm_v, unit,
                          LENGTH_UNITS[unit] if train.sized else self.metre)

    def _arm_radius(self) -> Fraction:
        """Where the arm carries its planets: a planet's pitch radius off a main-axis gear's."""
        t = self.t
        for mesh in t.meshes:
            for p, c in ((mesh.a, mesh.b), (mesh.b, mesh.a)):
                if t.carried(p) and not t.carried(c):
                    rp, rc = t.pitch_radius(p), t.pitch_radius(c)
                    return rc - rp if mesh.internal else rc + rp
        raise InputError("no planet meshes with a gear on the main axis",
                         file=t.source or None)

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

    def run(self) -> Kutzbach:
        t, c = self.t, self.c
        c.give("kz:O", g.Point(0.0, 0.0), label="O", kind=Kind.POINT, panel=Panel.VELOCITY,
               phrase=phrase("kutzbach.radial"))
        c.give("kz:radial", g.Line(-1.0, 0.0, 0.0), label="", kind=Kind.GUIDE,
               panel=Panel.VELOCITY)
        c.give("kz:across", g.Line(0.0, 1.0, 0.0), label="", kind=Kind.LINE,
               panel=Panel.VELOCITY)
        fixed = t.body(t.fixed)
        self.k.lines[fixed] = "kz:radial"
        self.act("kz:fixed", "mark", "kz:O", said=phrase("kutzbach.fixed",
                                                        member=t.said(t.fixed, opening=True)))
        self.draw_input()
        while len(self.k.lines) < len(t.bodies):
            if not self.next_line():
                raise InputError("the velocity diagram cannot reach every member from the "
                                 "fixed one and the input", file=t.source or None)
        self.read()
        return self.k

    def level_of(self, m: int) -> tuple[str, Fraction]:
        """The radius a member's velocity is laid off at: a gear's pitch radius, or where the
        arm carries its planets."""
        if m == self.t.arm:
            return "R", self.arm_r
        return f"r{m}", self.t.pitch_radius(m)

    def draw_input(self) -> None:
        t, m = self.t, self.t.input_member
        w = float(t.input_speed) * t.units.per_rad_s
        name, size = self.level_of(m)
        r = float(size) * self.metre
        lvl = self.level(name, size, t.said(m))
        # The arm's velocity at R is the planets' centre's: it goes by that name, C.
        tip = self.act(f"kz:v:{m}", "lay_off", f"kz:r:{name}", lvl, length=w * r * self.k.per,
                       label="C" if m == t.arm else f"v{m}", said=phrase(
                           "kutzbach.input", member=t.said(m, opening=True), name=name,
                           omega=Number(abs(w)), radius=t.size_text(size),
                           sense=Word("ccw" if w > 0 else "cw")))
        self.through_origin(t.body(m), tip)

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
            points = self.points_on(body)
            if t.carried(body[0]) and len(points) >= 2:
                p, q = points[:2]
                ref = f"kz:line:{body[0]}"
                self.act(ref, "line_through", p, q, label=_names(body), said=phrase(
                    "kutzbach.planet_line", member=_names(body), p=self.c[p].label,
                    q=self.c[q].label))
                known[body] = ref
                self.k.through[body] = (p, q)
                return True
            if not t.carried(body[0]) and points:
                self.through_origin(body, points[0])
                return True
        return False

    def points_on(self, body) -> list[Ref]:
        """Points of ``body``'s line that lines already drawn give: the pitch points of its
        meshes with drawn bodies, and the planets' centre, which the arm and the planets
        share."""
        t, out = self.t, []
        for mesh in t.meshes:
            for a, b in ((mesh.a, mesh.b), (mesh.b, mesh.a)):
                if a not in body or t.body(b) not in self.k.lines:
                    continue
                main = b if t.carried(a) else a
                name = f"r{main}"
                lvl = self.level(name, t.pitch_radius(main), t.said(main))
                lo, hi = sorted((a, b))
                out.append(self.act(
                    f"kz:pitch:{lo}-{hi}", "intersect_lines", self.k.lines[t.body(b)], lvl,
                    label=f"P{lo}{hi}", said=phrase("kutzbach.pitch", a=t.said(a, opening=True),
                                                    b=t.said(b), name=name,
                                                    known=_names(t.body(b)))))
        if t.carried(body[0]) or t.arm in body:
            drawn = [b for b in self.k.lines if (t.arm in b) != (t.arm in body)
                     and (t.carried(b[0]) or t.arm in b)]
            if drawn:
                lvl = self.level("R", self.arm_r, phrase("kutzbach.planet_centres"))
                out.append(self.act("kz:centre", "intersect_lines", self.k.lines[drawn[0]], lvl,
                                    label="C", said=phrase("kutzbach.centre",
                                                           known=_names(drawn[0]))))
        return list(dict.fromkeys(out))

    def read(self) -> None:
        """Each member's ω: the slope of its body's line, Δv/Δr at the diagram's scales."""
        per = self.k.per
        for body, ref in self.k.lines.items():
            w = 0.0
            if ref != "kz:radial":
                p, q = (self.c.output(r).xy for r in self.k.through[body])
                w = (q[0] - p[0]) / per / (q[1] - p[1])
            for m in body:
                self.k.omegas[m] = w
            rate = w / self.t.units.per_rad_s
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
