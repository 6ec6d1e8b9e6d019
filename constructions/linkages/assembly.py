"""Position by compass: assemble a mechanism one dyad at a time, recording every act.

The order is the student's: mark the frame, lay off the crank at θ2, then find each
joint from two things already drawn:

* two arcs (a pin between two links, RRR): circle–circle;
* an arc and a guide (a pin on a slider, RRP): line–circle;
* two guides (a pin in a slot and on a slider): line–line;
* a slot swung through a located block (the slotted lever, R-P-R): the line from
  the pivot through the block, or the tangent from the block to the offset circle;
* a point of a link already drawn: two arcs from two of its points.

Each of these is a dyad rule, registered with :func:`~.dyad_rules.dyad_rule` in
:data:`~.dyad_rules.DYAD_RULES`; each kind of joint names the rules that locate it in
:data:`~.joint_rules.JOINT_RULES`, and the pin's are :data:`~.joint_rules.PIN_RULES`. The
rules the mechanism's joints bring are tried in their order, the first that locates
something wins, and the walk starts again. When no rule can locate anything more the
mechanism needs a triad, and tarsim says so.

:class:`Assembler` holds what is drawn so far, the acts every rule shares (recording a
joint, choosing a branch, wording a length) and the walk. The rules live by the joints
they close: :mod:`.dyad_cuts` (arcs and guides), :mod:`.dyad_slots` (slots and blocks)
and :mod:`.dyad_rolling` (wheels that roll without slip). The record drawn into is
:class:`~.assembly_record.Assembly`.
"""

from __future__ import annotations

import math

from .. import geometry as g
from .assembly_record import Assembly, point_ref
from .dyad_rolling import roll_input
from .joint_rules import dyad_rules_for, rules_of
from ..errors import AssemblyError, BranchError
from ..joints import Arc, Slide
from ..model import Mechanism
from ..narration import Phrase, phrase
from ..record import VERBS, Kind, Ref, Role

__all__ = ["assemble", "Assembler", "input_ray", "ray_at"]


def input_ray(link: int) -> Ref:
    """The id of the given step that lays off the input's angle: the ray from its pivot."""
    return f"ray:{link}"


def ray_at(pivot: g.Point, angle: float) -> g.Line:
    """The ray from ``pivot`` at ``angle`` (rad) that the input's second point is laid off
    along: the one given of a position that moves when the input turns."""
    x, y = pivot.xy
    ux, uy = math.cos(angle), math.sin(angle)
    return g.Line(-uy, ux, uy * x - ux * y)


def assemble(mech: Mechanism) -> Assembly:
    """Locate every point of ``mech`` by recorded compass constructions.

    Raises
    ------
    AssemblyError
        If a dyad cannot close at this input angle, or no dyad order exists.
    """
    return Assembler(mech).run()


class Assembler:
    """A mechanism being drawn by compass: what is located so far, and the acts every dyad
    rule shares.

    ``known`` maps each located point to the step that locates it, ``guides`` each drawn
    slide (by its index in ``m.slides``) to its guide line and ``axes`` each drawn link to
    its axis; ``c`` is the record they are drawn into.
    """

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
        """Record the act ``verb`` that locates point ``name``, saying it with ``said``."""
        self.known[name] = self.c.draw(point_ref(name), verb, *inputs, label=name, phrase=said,
                                       kind=Kind.JOINT, role=Role.RESULT, **params)

    def posed(self, number: int) -> bool:
        """True if link ``number`` is drawn: two of its points located, or one and its axis."""
        if number == 1:
            return True
        k = self.m.link(number)
        return sum(n in self.known for n in k.names) >= 2 or (
            number in self.axes and any(n in self.known for n in k.names))

    def branch(self, point: str, default: str | None, choices: tuple[str, str],
               context: str) -> str | tuple[float, float]:
        """The branch ``point`` takes (``default`` where it names none), one of ``choices``
        or a near point; ``context`` says what the two positions are in an error."""
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
        """Mark the frame, lay off the input, then try the dyad rules until every point is
        located (and every slot drawn)."""
        self.mark_frame()
        self.lay_off_input()
        rules = dyad_rules_for(self.m)
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
        """Mark where each contact's profiles touch, P, as its kind does
        (:mod:`.contact_points`)."""
        out: dict[Slide | Arc, Ref] = {}
        for joints in (self.m.slides, self.m.arcs):
            for i, j in enumerate(joints):
                touch = rules_of(j).touch
                if touch is not None:
                    out[j] = touch(self, i, j)
        return out

    def mark_frame(self) -> None:
        """Give the frame's points and the guides fixed to the frame."""
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
        """Lay off the input's second point from its pivot at θ (or roll an input wheel)."""
        d = self.m.drive
        k = self.m.link(d.link)
        if self.m.rolling_input is not None:
            roll_input(self, self.m.rolling_input)
            return
        if len(k.names) < 2 or k.names[0] not in self.known:
            raise AssemblyError(f"the input {k.label} must turn about a frame point, listed "
                                "first among its points, and carry a second point", link=k.number)
        pivot, tip = k.names[0], k.names[1]
        ray = self.c.give(input_ray(d.link), ray_at(self.c.output(self.known[pivot]), d.angle),
                          label=f"θ{d.link}",
                          phrase=phrase("position.input_ray", pivot=pivot, link=d.link,
                                        angle=self.angle(d.angle)))
        self.found(tip, "lay_off", self.known[pivot], ray, length=k.span(pivot, tip),
                   said=phrase("position.input_point", pivot=pivot, point=tip,
                               radius=self.length(k.span(pivot, tip)), at=self.at_said()))
        self.axes[d.link] = self.c.draw(f"axis:{d.link}", "line_through", self.known[pivot],
                                        self.known[tip], label=f"link {d.link}", kind=Kind.GUIDE)

    # ----- helpers ---------------------------------------------------------------
    def slides_at(self, name: str) -> list[int]:
        """The indices of the slides whose sliding point is ``name``."""
        return [i for i, s in enumerate(self.m.slides) if s.point == name]

    def one_known(self, number: int) -> str:
        """The first of link ``number``'s points that is located."""
        return next(n for n in self.m.link(number).names if n in self.known)
