"""Position by compass: assemble a mechanism one dyad at a time, recording every act.

The order is the student's: mark the frame, lay off the crank at θ2, then find each
joint from two things already drawn:

* two arcs (a pin between two links, RRR): circle–circle;
* an arc and a guide (a pin on a slider, RRP): line–circle;
* two guides (a pin in a slot and on a slider): line–line;
* a slot swung through a located block (the slotted lever, R-P-R): the line from
  the pivot through the block, or the tangent from the block to the offset circle;
* a point of a link already drawn: two arcs from two of its points.

Each of these is a dyad rule, registered with :func:`dyad_rule` in
:data:`DYAD_RULES`: a new joint plugs in as one more rule. The rules are tried in
their order, the first that locates something wins, and the walk starts again.
When no rule can locate anything more the mechanism needs a triad, and tarsim
says so.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

from . import geometry as g
from .errors import AssemblyError, BranchError, DegenerateInput, NoIntersection, TarsimError
from .coincident import rolling_contacts
from .model import Arc, Mechanism, Slide, SlideKind
from .narration import Phrase, Word, phrase
from .record import VERBS, Construction, Kind, Ref, Role

__all__ = ["Assembly", "assemble", "point_ref", "DYAD_RULES", "dyad_rule", "MEETING"]

MEETING = 1e-7
"""A cut whose own conditioning (the sine of the angle it crosses at) is below this
touches within rounding: a tangency met through rounding keeps about √eps ≈ 1.5e-8."""

_CUTS = ("intersect_circles", "intersect_line_circle")
"""The acts that choose one of two places: where the two may coincide."""


@dataclass(frozen=True)
class DyadRule:
    """One way to locate a joint from what is drawn: ``locate`` draws it and returns True,
    or returns False; ``order`` is its place among the rules (lower is tried first)."""

    name: str
    order: int
    locate: Callable[[_Assembler], bool]


DYAD_RULES: dict[str, DyadRule] = {}
"""Every dyad rule of position by compass, by name."""


def dyad_rule(name: str, order: int):
    """Register a method of the assembler as the dyad rule ``name``, tried at ``order``."""
    def register(locate: Callable[[_Assembler], bool]) -> Callable[[_Assembler], bool]:
        DYAD_RULES[name] = DyadRule(name, order, locate)
        return locate
    return register


def _arc_why(a: Arc) -> Phrase:
    """Why a point keeps its distance: "the circles of links 3 and 2 touch: their centres
    R and C stay r3 + r2 apart"."""
    c = a.contact
    if c is None:
        return phrase("position.why_curved_slot", point=a.point, link=a.guide_link,
                      centre=a.centre)
    return phrase("position.why_circles_touch", i=c.circle.link, j=c.face.link, p=a.point,
                  q=a.centre, op="+" if c.side == "outside" else "−")


def point_ref(name: str) -> Ref:
    """The id of the step that locates point ``name``."""
    return f"P:{name}"


@dataclass
class Assembly(Construction):
    """The record of a mechanism drawn at one position: every drafting act, and which step
    locates each point, guide and axis.

    Position by compass draws the mechanism into it; every method then draws its own
    construction on top (the centres, the velocities, the polygons), so one record
    holds the whole solution of a position and each figure is a slice of it.
    """

    mechanism: Mechanism | None = None
    points: dict[str, Ref] = field(default_factory=dict)
    guides: dict[int, Ref] = field(default_factory=dict)
    axes: dict[int, Ref] = field(default_factory=dict)
    position_steps: frozenset[Ref] = frozenset()
    """The steps that located the mechanism: the kinematic diagram draws them, so a figure's
    slice stops there (:func:`~.record.slice`'s ``base``)."""
    contacts: dict[Slide | Arc, Ref] = field(default_factory=dict)
    """The contact point P of each joint that stands for a direct contact (a cam's circle
    on a flat face or on a roller): where the diagram draws the two profiles touching."""

    def input_arm(self) -> tuple[str, Ref, str, Ref]:
        """The input's centre of rotation and its known point, each by name and step, and the
        line from the one to the other: a crank's pivot and second point, along its axis;
        for a wheel rolling on the frame, its contact point (at rest at the instant) and
        its centre, joined here once."""
        m = self.mechanism
        d, s = m.drive, m.rolling_input
        k = m.link(d.link)
        if s is None:
            return k.names[0], self.points[k.names[0]], k.names[1], self.axes[d.link]
        contact = next(n for n, t in rolling_contacts(m).items() if t is s)
        ref = f"arm:{d.link}"
        if ref not in self:
            self.draw(ref, "line_through", self.contacts[s], self.points[s.point],
                      phrase=phrase("position.wheel_arm", contact=contact, point=s.point,
                                    link=d.link))
        return contact, self.contacts[s], s.point, ref

    def point(self, name: str) -> g.Point:
        """The located point ``name``."""
        return self.output(self.points[name])

    def xy(self, name: str) -> tuple[float, float]:
        """Cartesian coordinates (metres) of point ``name``."""
        return self.point(name).xy

    @property
    def size(self) -> float:
        """The mechanism's size at this position: its largest distance between two points (m).

        Tolerances for "the same point" or "on this line" are taken relative to it.
        """
        xy = [self.xy(n) for n in self.mechanism.point_names]
        return max([1e-300] + [math.dist(p, q) for p in xy for q in xy])

    def guide(self, index: int) -> g.Line:
        """The global line of slide ``index`` (``mechanism.slides[index]``)."""
        return self.output(self.guides[index])

    @property
    def meetings(self) -> tuple[str, ...]:
        """The points at a change point: where their two places coincide (their arcs, or arc
        and guide, only touch) and the linkage may go on in either assembly.

        Touching alone is a dead point of the input: the arc's centre C is driven across
        the line of the touch, so the input stops there. Both assemblies can move on only
        if C's motion runs along the touch, which, for C carried by a link pinned to the
        frame at P, is when P lies on the line of the touch (for a four-bar, all four
        pivots in line).
        """
        out = []
        for name in self.mechanism.point_names:
            step = self[self.points[name]]
            if step.verb in _CUTS:
                args = [self.output(r) for r in step.inputs]
                if (VERBS[step.verb](*args, **dict(step.params))[1] <= MEETING
                        and self._free_along_touch(name, step)):
                    out.append(name)
        return tuple(out)

    def _free_along_touch(self, name: str, step) -> bool:
        """True if a moving centre of an arc in ``step`` (the cut that found ``name``) runs
        along the line of the touch: a frame pivot of its link lies on that line."""
        m = self.mechanism
        loci = [self.output(r) for r in step.inputs]
        circles = [c for c in loci if isinstance(c, g.Circle)]
        if len(circles) == 2:
            line, _ = g.line_through(circles[0].centre, circles[1].centre)
        elif circles:
            guide = next(x for x in loci if isinstance(x, g.Line))
            line, _ = g.perpendicular_through(circles[0].centre, guide)
        for circle in circles:
            centre = next((n for n, r in self.points.items()
                           if n != name and self.output(r) == circle.centre), None)
            if centre is None or m.frame.carries(centre):
                continue
            pivots = [p for k in m.links_at(centre) if not m.link(k).carries(name)
                      for p in m.link(k).names if m.frame.carries(p)]
            if any(abs(line.signed_distance(self.output(self.points[p])))
                   <= MEETING * circle.radius for p in pivots):
                return True
        return False


def assemble(mech: Mechanism) -> Assembly:
    """Locate every point of ``mech`` by recorded compass constructions.

    Raises
    ------
    AssemblyError
        If a dyad cannot close at this input angle, or no dyad order exists.
    """
    return _Assembler(mech).run()


class _Assembler:
    def __init__(self, mech: Mechanism):
        self.m = mech
        self.c = Assembly(mechanism=mech)
        self.known: dict[str, Ref] = {}
        self.axes: dict[int, Ref] = {}
        self.guides: dict[int, Ref] = {}
        self.theta = mech.drive.angle
        self.size = max([1e-9] + [math.hypot(*xy) for _, xy in mech.frame.points]
                        + [k.span(a, b) for k in mech.links for a in k.names for b in k.names])

    # ----- wording -------------------------------------------------------------
    def L(self, metres: float) -> str:
        """A length as an error message writes it."""
        return self.m.units.length_brief(metres)

    def length(self, metres: float):
        """A length as a step says it."""
        return self.m.units.length_said(metres)

    def angle(self, rad: float):
        """An angle as a step says it."""
        return self.m.units.angle_said(rad)

    def at(self) -> str:
        """The input position, as an error message writes it: "at θ2 = 60°"."""
        return f"at θ{self.m.drive.link} = {self.m.units.angle_brief(self.theta)}"

    def at_said(self) -> Phrase:
        """The input position, as a step says it: "at θ2 = 60°"."""
        return phrase("position.at", link=self.m.drive.link, angle=self.angle(self.theta))

    def with_length(self, number: int, span: str, metres: float) -> str:
        """Name a link with the length that matters: "link 3 (coupler, AB = 250 mm)"."""
        k = self.m.link(number)
        named = f"{k.name}, " if k.name else ""
        return f"link {number} ({named}{span} = {self.L(metres)})"

    # ----- bookkeeping ---------------------------------------------------------
    def found(self, name: str, verb: str, *inputs: Ref, said: Phrase, **params) -> None:
        self.known[name] = self.c.draw(point_ref(name), verb, *inputs, label=name, phrase=said,
                                       kind=Kind.JOINT, role=Role.RESULT, **params)

    def posed(self, number: int) -> bool:
        if number == 1:
            return True
        k = self.m.link(number)
        return sum(n in self.known for n in k.names) >= 2 or (
            number in self.axes and any(n in self.known for n in k.names))

    def branch(self, point: str, default: str | None, choices: tuple[str, str],
               context: str) -> str | tuple[float, float]:
        b = self.m.branches.get(point, default)
        if b is None:
            raise BranchError(
                f"point {point} has two positions ({context}); choose one in [assembly]: "
                f'{point} = "{choices[0]}" or "{choices[1]}"', joint=point)
        if isinstance(b, str) and b not in choices:
            raise BranchError(f"[assembly] {point} = \"{b}\" does not apply here ({context}); "
                                f'use "{choices[0]}" or "{choices[1]}"', joint=point)
        return b

    def pick_near(self, verb: str, inputs: tuple[Ref, ...], choices: tuple[str, str],
                  near: tuple[float, float]) -> str:
        """Turn a near-point branch into the explicit pick it means."""
        args = [self.c.output(r) for r in inputs]
        best = None
        for pick in choices:
            p, _ = VERBS[verb](*args, pick=pick)
            d = math.dist(p.xy, near)
            if best is None or d < best[0]:
                best = (d, pick)
        return best[1]

    # ----- the run -------------------------------------------------------------
    def run(self) -> Assembly:
        self.mark_frame()
        self.lay_off_input()
        rules = sorted(DYAD_RULES.values(), key=lambda r: r.order)
        wanted = [n for n in self.m.point_names]
        while any(n not in self.known for n in wanted):
            if not any(rule.locate(self) for rule in rules):
                missing = ", ".join(n for n in wanted if n not in self.known)
                raise AssemblyError(
                    f"no dyad locates {missing}: this mechanism needs a triad, which tarsim "
                    "cannot yet construct by compass")
        # A slot that fixes no point (a lever with only its pivot) is still drawn: the
        # instant centres and the polygons need its direction.
        while len(self.guides) < len(self.m.slides) and any(rule.locate(self) for rule in rules):
            pass
        self.c.contacts = self.touch()
        self.c.points, self.c.guides, self.c.axes = self.known, self.guides, self.axes
        self.c.position_steps = frozenset(self.c.steps)
        return self.c

    def touch(self) -> dict[Slide | Arc, Ref]:
        """Mark where each contact's profiles touch, P.

        On a flat face P is the foot of the circle's centre, since the common normal
        runs through the centre square to the face; between two circles it is on
        their line of centres, on the cam's rim toward the roller (on its far side
        only for a cam inside a larger roller).
        """
        out: dict[Slide | Arc, Ref] = {}
        for i, s in enumerate(self.m.slides):
            if s.contact is not None:
                face = self.c.draw(f"profile:face:{i}", "parallel_through",
                                   self.known[s.contact.face.through], self.guides[i],
                                   kind=Kind.GUIDE, label=f"face of link {s.contact.face.link}")
                out[s] = self.c.draw(f"contact:{i}", "project_onto", self.known[s.point], face,
                                     label="P", kind=Kind.CONTACT)
        for k, a in enumerate(self.m.arcs):
            if a.contact is None:
                continue
            cam, roller = a.contact.face.radius, a.contact.circle.radius
            reach = -cam if a.contact.side == "inside" and roller > cam else cam
            c, r = self.known[a.centre], self.known[a.point]
            if g.distance(self.c.output(c), self.c.output(r)) == 0.0:   # concentric: any rim point
                x, y = self.c.output(c).xy
                out[a] = self.c.give(f"contact:a{k}", g.Point(x + reach, y), label="P",
                                     kind=Kind.CONTACT)
            else:
                out[a] = self.c.draw(f"contact:a{k}", "lay_off", c, r, length=reach, label="P",
                                     kind=Kind.CONTACT)
        return out

    def mark_frame(self) -> None:
        for name, (x, y) in self.m.frame.points:
            self.known[name] = self.c.give(
                point_ref(name), g.Point(x, y), label=name, kind=Kind.JOINT,
                phrase=phrase("position.frame_point", point=name, x=self.length(x),
                              y=self.length(y)))
        for i, s in enumerate(self.m.slides):
            if s.guide_link == 1:
                (tx, ty), (dx, dy) = s.through, s.direction
                line, _ = g.line_through(g.Point(tx, ty), g.Point(dx, dy, 0.0))
                if (line.direction[0] * dx + line.direction[1] * dy) < 0:
                    line = g.Line(-line.a, -line.b, -line.c)
                self.guides[i] = self.c.give(
                    f"guide:{i}", line, label=f"guide of {s.point}", kind=Kind.GUIDE,
                    phrase=phrase("position.frame_guide", point=s.point,
                                  angle=self.angle(math.atan2(dy, dx))))

    def lay_off_input(self) -> None:
        d = self.m.drive
        k = self.m.link(d.link)
        if self.m.rolling_input is not None:
            self.roll_input(self.m.rolling_input)
            return
        if len(k.names) < 2 or k.names[0] not in self.known:
            raise AssemblyError(f"the input {k.label} must turn about a frame point, listed "
                                "first among its points, and carry a second point", link=k.number)
        pivot, tip = k.names[0], k.names[1]
        x, y = self.c.output(self.known[pivot]).xy
        ux, uy = math.cos(d.angle), math.sin(d.angle)
        ray = self.c.give(f"ray:{d.link}", g.Line(-uy, ux, uy * x - ux * y),
                          label=f"θ{d.link}",
                          phrase=phrase("position.input_ray", pivot=pivot, link=d.link,
                                        angle=self.angle(d.angle)))
        self.found(tip, "lay_off", self.known[pivot], ray, length=k.span(pivot, tip),
                   said=phrase("position.input_point", pivot=pivot, point=tip,
                               radius=self.length(k.span(pivot, tip)), at=self.at_said()))
        self.axes[d.link] = self.c.draw(f"axis:{d.link}", "line_through", self.known[pivot],
                                        self.known[tip], label=f"link {d.link}", kind=Kind.GUIDE)

    def roll_input(self, s: Slide) -> None:
        """The input is a wheel rolling on the frame: its angle θ says how far it has rolled
        since its centre stood square over the face's ``through`` point (its axis then
        along the frame's x), so the centre is laid off σ·r·θ back along its path from
        there, and the wheel's axis drawn through it at θ."""
        d = self.m.drive
        i = self.m.slides.index(s)
        r = s.contact.circle.radius
        rolled = -s.contact.roll_sign * r * self.theta
        start = self.c.give(f"roll:{d.link}", g.Point(*s.through), label="", kind=Kind.POINT)
        self.found(s.point, "lay_off", start, self.guides[i], length=rolled,
                   said=phrase("position.wheel_input", link=d.link, name=self.link_name(d.link),
                               point=s.point, face=s.contact.face.through,
                               turn=self.angle(abs(self.theta)),
                               sense=Word("counter-clockwise" if self.theta > 0 else "clockwise"),
                               rolled=self.length(abs(rolled)), radius=self.length(r),
                               way=Word("forward" if rolled >= 0 else "back")))
        self.wheel_axis(d.link, self.c.output(self.known[s.point]).xy, self.theta,
                        phrase("position.wheel_axis", point=s.point, link=d.link,
                               angle=self.angle(self.theta)))

    # ----- rules: each locates something and returns True, or returns False -----
    @dyad_rule("a point of a drawn link", 0)
    def rigid_point(self) -> bool:
        for k in self.m.links:
            if k.number == 1 or not self.posed(k.number):
                continue
            for name in k.names:
                if name not in self.known:
                    self.locate_on_link(k.number, name)
                    return True
        return False

    def locate_on_link(self, number: int, name: str) -> None:
        k = self.m.link(number)
        on = [n for n in k.names if n in self.known]
        px, py = k.local(name)
        if len(on) >= 2:
            a, b = on[0], on[1]
            (ax, ay), (bx, by) = k.local(a), k.local(b)
            ux, uy = bx - ax, by - ay
            cross = ux * (py - ay) - uy * (px - ax)
            if abs(cross) <= 1e-12 * (ux * ux + uy * uy):
                along = (ux * (px - ax) + uy * (py - ay)) / math.hypot(ux, uy)
                self.found(name, "lay_off", self.known[a], self.known[b], length=along,
                           said=phrase("position.on_link_line", point=name, a=a, b=b,
                                       link=number, length=self.length(abs(along))))
                return
            ra, rb = k.span(a, name), k.span(b, name)
            arc_a = self.c.draw(f"arc:{name}@{a}", "swing_arc", self.known[a], radius=ra,
                                label=f"arc {a}{name}")
            arc_b = self.c.draw(f"arc:{name}@{b}", "swing_arc", self.known[b], radius=rb,
                                label=f"arc {b}{name}")
            self.found(name, "intersect_circles", arc_a, arc_b,
                       pick="left" if cross > 0 else "right",
                       said=phrase("position.rigid_point", point=name, link=number, a=a, b=b,
                                   ra=self.length(ra), rb=self.length(rb)))
            return
        base = on[0]
        bx, by = k.local(base)
        du, dv = px - bx, py - by
        along = phrase("position.along_link", link=number, base=base, point=name,
                       length=self.length(abs(du)))
        if dv == 0.0:
            self.found(name, "lay_off", self.known[base], self.axes[number], length=du,
                       said=along)
            return
        foot = self.c.draw(f"foot:{name}", "lay_off", self.known[base], self.axes[number],
                           length=du, phrase=along)
        perp = self.c.draw(f"perp:{name}", "perpendicular_through", foot, self.axes[number])
        self.found(name, "lay_off", foot, perp, length=dv,
                   said=phrase("position.square_off", length=self.length(abs(dv)), point=name))

    def circles_of(self, name: str) -> list[tuple[int, str, float, Phrase]]:
        """The arcs ``name`` must lie on, as ``(link, centre, radius, why)``, lowest link first.

        An arc comes from a link not yet drawn with one point located (its span to
        ``name``), or from a curved slot or circle contact whose other end is located.
        """
        out = []
        for n in self.m.links_at(name):
            if not self.posed(n) and any(p in self.known for p in self.m.link(n).names):
                x = self.one_known(n)
                r = self.m.link(n).span(x, name)
                out.append((n, x, r, phrase("position.radius_span", a=x, b=name,
                                            length=self.length(r))))
        for a in self.m.pin_arcs:
            for here, there, k in ((a.point, a.centre, a.guide_link), (a.centre, a.point, a.link)):
                if here == name and there in self.known:
                    out.append((k, there, a.radius, phrase("position.radius_because",
                                                           length=self.length(a.radius),
                                                           why=_arc_why(a))))
        return sorted(out, key=lambda c: c[:3])

    @dyad_rule("two arcs (RRR)", 6)
    def two_arcs(self) -> bool:
        for name in self.m.point_names:
            if name in self.known or self.slides_at(name):
                continue
            circles = self.circles_of(name)
            if len(circles) < 2:
                continue
            (i, x, ri, why_i), (j, y, rj, why_j) = circles[:2]
            arc_i = self.c.draw(f"arc:{name}@{x}", "swing_arc", self.known[x], radius=ri,
                                label=f"arc {x}{name}",
                                phrase=phrase("position.swing_arc", centre=x, radius=why_i))
            arc_j = self.c.draw(f"arc:{name}@{y}", "swing_arc", self.known[y], radius=rj,
                                label=f"locus of {name}",
                                phrase=phrase("position.locus", centre=y, radius=why_j,
                                              point=name))
            pick = self.branch(name, None, ("left", "right"), f"left or right of {x} → {y}")
            try:
                if not isinstance(pick, str):
                    pick = self.pick_near("intersect_circles", (arc_i, arc_j), ("left", "right"),
                                          pick)
                self.found(name, "intersect_circles", arc_i, arc_j, pick=pick,
                           said=phrase("position.arcs_cut", point=name, pick=Word(pick), a=x,
                                       b=y))
            except NoIntersection:
                raise self.cannot_reach(name, i, x, ri, y, rj) from None
            except DegenerateInput:                   # x on y: the two arcs share a centre
                if ri != rj:
                    raise self.cannot_reach(name, i, x, ri, y, rj) from None
                raise AssemblyError(
                    f"{x} falls on {y} {self.at()}, so the arcs of {name} about them "
                    f"coincide and {name} is not fixed: a change point, where the linkage's "
                    "branches meet", link=i, joint=name,
                    angle_deg=math.degrees(self.theta)) from None
            return True
        return False

    def cannot_reach(self, name: str, i: int, x: str, ri: float, y: str,
                     rj: float) -> AssemblyError:
        d = g.distance(self.c.output(self.known[x]), self.c.output(self.known[y]))
        if d > ri + rj:
            why = f"|{y}{x}| = {self.L(d)} > {self.L(ri)} + {self.L(rj)}"
        else:
            why = f"|{y}{x}| = {self.L(d)} < |{self.L(ri)} − {self.L(rj)}|"
        return AssemblyError(
            f"{self.with_length(i, x + name, ri)} cannot reach the circle of "
            f"{name} about {y} {self.at()}: {why}", link=i, joint=name,
            angle_deg=math.degrees(self.theta))

    @dyad_rule("an arc and a guide (RRP)", 5)
    def arc_and_guide(self) -> bool:
        for name in self.m.point_names:
            if name in self.known:
                continue
            lines = self.known_guides(name)
            circles = self.circles_of(name)
            if len(lines) != 1 or not circles:
                continue
            i, x, r, why = circles[0]
            arc = self.c.draw(f"arc:{name}@{x}", "swing_arc", self.known[x], radius=r,
                              label=f"arc {x}{name}",
                              phrase=phrase("position.swing_arc", centre=x, radius=why))
            guide = self.guides[lines[0]]
            pick = self.branch(name, None, ("forward", "backward"),
                               f"forward or backward along the guide of {name}")
            try:
                if not isinstance(pick, str):
                    pick = self.pick_near("intersect_line_circle", (guide, arc),
                                          ("forward", "backward"), pick)
                self.found(name, "intersect_line_circle", guide, arc, pick=pick,
                           said=phrase("position.arc_cuts_guide", point=name, pick=Word(pick)))
            except NoIntersection as e:
                raise AssemblyError(
                    f"{self.with_length(i, x + name, r)} cannot reach the guide "
                    f"of {name} {self.at()}: it passes {self.L(e.margin)} beyond the arc",
                    link=i, joint=name, angle_deg=math.degrees(self.theta)) from None
            return True
        return False

    @dyad_rule("two guides (RPP)", 4)
    def two_guides(self) -> bool:
        for name in self.m.point_names:
            if name in self.known:
                continue
            lines = self.known_guides(name)
            if len(lines) < 2:
                continue
            try:
                self.found(name, "intersect_lines", self.guides[lines[0]], self.guides[lines[1]],
                           said=phrase("position.two_guides", point=name))
            except DegenerateInput:
                raise AssemblyError(f"the two guides of {name} coincide {self.at()}, so "
                                    f"{name} is not fixed", joint=name) from None
            if self.c.output(self.known[name]).is_at_infinity:
                raise AssemblyError(f"the two guides of {name} are parallel {self.at()}, so "
                                    f"{name} is at infinity", joint=name)
            return True
        return False

    @dyad_rule("a wheel rolling without slip", 1)
    def roll_wheel(self) -> bool:
        """Turn a wheel that rolls without slip through the distance rolled over its radius.

        Once the wheel's centre is drawn on its path (the face's parallel at the
        radius), the distance s it stands from the start (square over the face's
        ``through`` point) is measured with dividers along the face; the wheel has
        turned through s / r, clockwise when it rides on the left of the face.
        """
        for s in self.m.slides:
            if not s.rolling or s.point not in self.known or s.link in self.axes:
                continue
            pose = self.pose_of(s.guide_link)
            if pose is None:
                continue
            phi, origin = pose
            c, sn = math.cos(phi), math.sin(phi)
            (tx, ty), (dx, dy) = s.through, s.direction
            gx, gy = origin[0] + c * tx - sn * ty, origin[1] + sn * tx + c * ty
            ux, uy = c * dx - sn * dy, sn * dx + c * dy
            px, py = self.c.output(self.known[s.point]).xy
            rolled = ux * (px - gx) + uy * (py - gy)
            r = s.contact.circle.radius
            turn = -rolled / (s.contact.roll_sign * r)
            wheel = phi + turn
            sense = "clockwise" if turn < 0 else "counter-clockwise"
            self.wheel_axis(s.link, (px, py), wheel, phrase(
                "position.wheel_rolls", link=s.link, name=self.link_name(s.link),
                point=s.point, rolled=self.length(abs(rolled)), turn=self.angle(abs(turn)),
                sense=Word(sense), radius=self.length(r)))
            return True
        return False

    @dyad_rule("a wheel rolling round a circle without slip", 1)
    def roll_round(self) -> bool:
        """Turn a wheel that rolls round a circle through the arc rolled over its radius.

        Once the wheel's centre C is drawn, the angle β it has gone round the circle's
        centre K from the start (on K's +x) is measured with the protractor; the arc
        rolled, R·β, turns the wheel through R·β/r relative to the line KC, so through
        β·(R ± r)/r in all (+ outside the circle, − inside).
        """
        for a in self.m.rolling_arcs:
            if a.point not in self.known or a.centre not in self.known or a.link in self.axes:
                continue
            pose = self.pose_of(a.guide_link)
            if pose is None:
                continue
            phi, _ = pose
            (px, py), (kx, ky) = (self.c.output(self.known[n]).xy for n in (a.point, a.centre))
            beta = (math.atan2(py - ky, px - kx) - phi + math.pi) % math.tau - math.pi
            r = a.contact.circle.radius
            turn = a.roll_gain * beta / r
            wheel = phi + turn
            self.wheel_axis(a.link, (px, py), wheel, phrase(
                "position.wheel_rolls_round", link=a.link, name=self.link_name(a.link),
                point=a.point, centre=a.centre, beta=self.angle(beta), turn=self.angle(turn),
                ratio=Word("(R + r)/r" if a.contact.side == "outside" else "(r − R)/r"),
                big=self.length(a.contact.face.radius), radius=self.length(r)))
            return True
        return False

    def wheel_axis(self, link: int, at: tuple[float, float], angle: float,
                   said: Phrase) -> None:
        """Draw a wheel's axis through its centre ``at``, at the ``angle`` rolling turned it
        to: the line its other points are laid off from."""
        x, y = at
        self.axes[link] = self.c.give(
            f"axis:{link}", g.Line(-math.sin(angle), math.cos(angle),
                                   math.sin(angle) * x - math.cos(angle) * y),
            label=f"link {link}", kind=Kind.GUIDE, phrase=said)

    def link_name(self, number: int) -> Phrase | None:
        """A link's name as a step adds it after the number: " (wheel)"."""
        k = self.m.link(number)
        return phrase("link_name", name=k.name) if k.name else None

    def pose_of(self, number: int) -> tuple[float, tuple[float, float]] | None:
        """(angle, origin) of a drawn link, or None if it is not drawn yet."""
        if number == 1:
            return 0.0, (0.0, 0.0)
        k = self.m.link(number)
        if not self.posed(number) or len(k.names) < 2 or not all(n in self.known
                                                                   for n in k.names[:2]):
            return None
        (ax, ay), (bx, by) = (self.c.output(self.known[n]).xy for n in k.names[:2])
        (lx, ly) = k.local(k.names[1])
        phi = math.atan2(by - ay, bx - ax) - math.atan2(ly, lx)
        return phi, (ax, ay)

    @dyad_rule("a slot swung through its block (RPR)", 2)
    def slot_through_block(self) -> bool:
        for i, s in enumerate(self.m.slides):
            if i in self.guides or s.point not in self.known or self.posed(s.guide_link):
                continue
            k = self.m.link(s.guide_link)
            on = [n for n in k.names if n in self.known]
            if len(on) != 1:
                continue
            self.swing_slot(i, s, on[0])
            return True
        return False

    @dyad_rule("the slot of a translating block", 3)
    def slot_of_a_block(self) -> bool:
        """Draw the slot of a translating block through its located pin, then the block.

        A block's own +x runs along its guide, so its slot (say the equivalent slot of a
        flat-faced follower) is the guide turned by the slot's angle, through the pin.
        The block's point lies on the parallel to the slot at its offset (the face),
        where that cuts the block's guide.
        """
        for i, s in enumerate(self.m.slides):
            k = self.m.link(s.guide_link)
            if i in self.guides or k.number == 1 or s.point not in self.known or len(k.names) != 1:
                continue
            j = next((j for j, b in enumerate(self.m.slides) if b.link == k.number
                      and b.kind is SlideKind.BLOCK and j in self.guides), None)
            if j is None or k.names[0] in self.known:
                continue
            guide, pin, name = self.guides[j], self.known[s.point], k.names[0]
            (tx, ty), (dx, dy) = s.through, s.direction
            if abs(dx) <= 1e-12:
                slot = self.c.draw(f"guide:{i}", "perpendicular_through", pin, guide,
                                   label=f"slot of link {k.number}", kind=Kind.GUIDE,
                                   phrase=phrase("position.slot_square_to_guide", point=s.point,
                                                 block=name, link=k.number))
            else:
                n = self.c.draw(f"normal:{i}", "normal_direction", guide)
                turned = self.c.draw(f"turn:{i}", "rotate_about", n, pin,
                                     angle=math.atan2(dy, dx) - math.pi / 2)
                slot = self.c.draw(f"guide:{i}", "line_through", pin, turned,
                                   label=f"slot of link {k.number}", kind=Kind.GUIDE,
                                   phrase=phrase("position.slot_at_angle", point=s.point,
                                                 angle=self.angle(math.atan2(dy, dx)),
                                                 block=name, link=k.number))
            self.guides[i] = slot
            px, py = k.local(name)
            # The block's point lies this far left of the slot; a drawn line may run the
            # other way (a perpendicular turns +90°, a direction has no sense).
            across = dx * (py - ty) - dy * (px - tx)
            (gx, gy), (sx, sy) = self.c.output(guide).direction, self.c.output(slot).direction
            if (gx * dx - gy * dy) * sx + (gy * dx + gx * dy) * sy < 0.0:
                across = -across
            line = slot
            if across != 0.0:
                perp = self.c.draw(f"perp:{i}", "perpendicular_through", pin, slot)
                foot = self.c.draw(f"foot:{i}", "lay_off", pin, perp, length=across)
                line = self.c.draw(f"face:{i}", "parallel_through", foot, slot,
                                   phrase=phrase("position.face_offset",
                                                 length=self.length(abs(across)), point=name))
            try:
                self.found(name, "intersect_lines", line, guide,
                           said=phrase("position.cut_guide", point=name))
            except DegenerateInput:
                pass
            if name not in self.known or self.c.output(self.known[name]).is_at_infinity:
                raise AssemblyError(f"the slot of {k.label} runs along its guide {self.at()}, "
                                    f"so {name} is not fixed", link=k.number, joint=name)
            self.axes[k.number] = guide
            return True
        return False

    def swing_slot(self, i: int, s: Slide, pivot: str) -> None:
        k = self.m.link(s.guide_link)
        qx, qy = k.local(pivot)
        (tx, ty), (dx, dy) = s.through, s.direction
        offset = dx * (ty - qy) - dy * (tx - qx)  # pivot lies this far right of the slot
        pick = self.branch(s.point, "forward", ("forward", "backward"),
                           f"the block ahead of or behind the foot of {pivot} on the slot")
        if not isinstance(pick, str):
            raise BranchError(f"[assembly] {s.point}: give \"forward\" or \"backward\" for a "
                              "block in a swinging slot", joint=s.point)
        q, p = self.known[pivot], self.known[s.point]
        # Nearer than this (the analytic solver's SINGULAR_RCOND) the slot's direction is
        # rounding; an offset slot cannot come so near its pivot, and says so as it is drawn.
        if (abs(offset) <= 1e-12 * self.size
                and g.distance(self.c.output(q), self.c.output(p)) <= MEETING * self.size):
            raise AssemblyError(f"the block {s.point} sits on the pivot {pivot} {self.at()}, so "
                                f"the slot of link {k.number} has no direction", link=k.number)
        name = f"slot of link {k.number}"
        if abs(offset) <= 1e-12 * self.size:
            ends = (q, p) if pick == "forward" else (p, q)
            apart = g.distance(self.c.output(q), self.c.output(p)) / self.size
            slot = self.c.draw(f"guide:{i}", "line_through", *ends, label=name, kind=Kind.GUIDE,
                               spread=min(1.0, apart),
                               phrase=phrase("position.slot_through_block", link=k.number,
                                             pivot=pivot, point=s.point))
        else:
            slot = self.tangent_slot(i, s, pivot, offset, pick)
        self.guides[i] = slot
        # The link's axis is the slot moved back onto its local origin.
        if abs(offset) <= 1e-12 * self.size and k.names[0] == pivot and dx > 0:
            self.axes[k.number] = slot
        else:
            self.axes[k.number] = self.axis_from_slot(k.number, slot, s, pivot)

    def tangent_slot(self, i: int, s: Slide, pivot: str, offset: float, pick: str) -> Ref:
        q, p = self.known[pivot], self.known[s.point]
        near = g.distance(self.c.output(q), self.c.output(p))
        if near == 0.0:               # no circle on O4A to cut: say it as a miss
            raise self.too_near(s.point, pivot, near, offset)
        mid = self.c.draw(f"mid:{s.point}{pivot}", "midpoint", q, p,
                          phrase=phrase("position.bisect", a=pivot, b=s.point))
        thales = self.c.draw(f"thales:{s.point}", "circle_through", mid, q,
                             phrase=phrase("position.circle_on_diameter", a=pivot, b=s.point))
        off = self.c.draw(f"offset:{pivot}", "swing_arc", q, radius=abs(offset),
                          phrase=phrase("position.offset_arc", centre=pivot,
                                        radius=self.length(abs(offset))))
        for side in ("left", "right"):
            try:
                t, _ = g.intersect_circles(self.c.output(thales), self.c.output(off), side)
            except NoIntersection:
                raise self.too_near(s.point, pivot, near, offset) from None
            ends = (t, self.c.output(p)) if pick == "forward" else (self.c.output(p), t)
            line, _ = g.line_through(*ends)
            if line.signed_distance(self.c.output(q)) * offset < 0:
                foot = self.c.draw(f"tangent:{s.point}", "intersect_circles", thales, off,
                                   pick=side, phrase=phrase("position.foot_of_slot"))
                ordered = (foot, p) if pick == "forward" else (p, foot)
                return self.c.draw(f"guide:{i}", "line_through", *ordered,
                                   label=f"slot of link {s.guide_link}", kind=Kind.GUIDE,
                                   phrase=phrase("position.slot_tangent", point=s.point))
        raise TarsimError(f"no tangent from {s.point} leaves {pivot} on the slot's side")

    def too_near(self, point: str, pivot: str, near: float, offset: float) -> AssemblyError:
        """An offset slot cannot pass its block: the block is nearer its pivot than the offset."""
        return AssemblyError(f"the block {point} comes within {self.L(near)} of {pivot} "
                             f"{self.at()}, closer than the slot's offset of "
                             f"{self.L(abs(offset))}", joint=point)

    def axis_from_slot(self, number: int, slot: Ref, s: Slide, pivot: str) -> Ref:
        k = self.m.link(number)
        dx, dy = s.direction
        if dy != 0.0 or dx < 0.0 or k.names[0] != pivot:
            raise AssemblyError(f"the slot of {k.label} must run along the link's axis, and the "
                                f"link must list its pivot {pivot} first", link=number)
        return self.c.draw(f"axis:{number}", "parallel_through", self.known[pivot], slot,
                           label=f"link {number}", kind=Kind.GUIDE)

    # ----- helpers ---------------------------------------------------------------
    def slides_at(self, name: str) -> list[int]:
        return [i for i, s in enumerate(self.m.slides) if s.point == name]

    def known_guides(self, name: str) -> list[int]:
        out = []
        for i in self.slides_at(name):
            s = self.m.slides[i]
            if i not in self.guides and s.guide_link != 1 and self.posed(s.guide_link):
                self.place_slot(i, s)
            if i in self.guides:
                out.append(i)
        return out

    def place_slot(self, i: int, s: Slide) -> None:
        """Draw the slot of an already-drawn moving link."""
        number = s.guide_link
        axis = self.axis_of(number)
        k = self.m.link(number)
        ox, oy = k.local(k.names[0])
        ty, (dx, dy) = s.through[1], s.direction
        if abs(dy) > 0.0 or dx < 0:
            raise AssemblyError(f"the slot of {k.label} must run along the link's axis",
                                link=number)
        off = ty - oy
        if off == 0.0:
            self.guides[i] = axis
            return
        base = self.c.draw(f"slotfoot:{i}", "perpendicular_through", self.known[k.names[0]], axis)
        at = self.c.draw(f"slotpt:{i}", "lay_off", self.known[k.names[0]], base, length=off)
        self.guides[i] = self.c.draw(f"guide:{i}", "parallel_through", at, axis,
                                     label=f"slot of link {number}", kind=Kind.GUIDE)

    def axis_of(self, number: int) -> Ref:
        """The oriented axis line of a drawn link (through its first point)."""
        if number in self.axes:
            return self.axes[number]
        k = self.m.link(number)
        if len(k.names) >= 2 and all(n in self.known for n in k.names[:2]):
            self.axes[number] = self.c.draw(f"axis:{number}", "line_through",
                                            self.known[k.names[0]], self.known[k.names[1]],
                                            label=f"link {number}", kind=Kind.GUIDE)
            return self.axes[number]
        for i, s in enumerate(self.m.slides):
            if s.link == number and s.kind is SlideKind.BLOCK and i in self.guides:
                self.axes[number] = self.guides[i]
                return self.guides[i]
        raise AssemblyError(f"{self.m.link(number).label} has no direction: give it two points "
                            "or a slide", link=number)

    def one_known(self, number: int) -> str:
        return next(n for n in self.m.link(number).names if n in self.known)

