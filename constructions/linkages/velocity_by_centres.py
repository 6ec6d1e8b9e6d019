"""Velocities by instant centres: the radius-rotation and parallel-line constructions.

Both follow Hinkle's chapter 5 and the notes' 8-step line-of-centres procedure
(000-part2 §2.5, 004 §3–4):

* the known velocity (at a point of the input link) is carried to the *transfer
  point* I_ij, the centre common to the input link i and the link j that carries
  the asked point, along the line of centres I_1i–I_ij–I_1j (Kennedy): swing the
  known point onto the line about I_1i, lay off its speed there, draw the gauge
  line of link i from I_1i through the tip, and erect the perpendicular at I_ij;
* then, on link j, the asked point is reached
  - by **radius rotation**: swing it about I_1j onto the line of centres, cut the
    gauge line of link j with the perpendicular there, and rotate the velocity back;
  - by **parallel lines**: turn V_Iij through 90° onto its radius toward I_1j,
    draw through its tip the parallel to the line I_ij–D, cut the radius D–I_1j,
    and turn the piece cut off back through 90° the other way.

A link that translates (I_1j at infinity) moves as a whole: every point has the
transfer point's velocity.
"""

from __future__ import annotations

import math

from .. import geometry as g
from .assembly_record import Assembly
from .centre_answers import located
from .centres import Centres, pair_label
from ..errors import DegenerateInput, TarsimError
from ..narration import Quantity, phrase
from ..record import Derived, Kind, Ref, Role
from ..checks import Answer
from .velocity_drawing import (VelocityResult, answer, draw_input_velocity, vector_label,
                               velocity_result)

__all__ = ["velocity_by_radius_rotation", "velocity_by_parallel_lines", "METHODS",
           "answer_velocity"]


def velocity_by_radius_rotation(asm: Assembly, centres: Centres, point: str, *,
                                scale: float, link: int | None = None) -> VelocityResult:
    """Find V of ``point`` by rotating radii onto the line of centres (Hinkle Figs 5.1, 5.2,
    5.4)."""
    return _Method(asm, centres, "radius-rotation", "rr", scale).run(point, link)


def velocity_by_parallel_lines(asm: Assembly, centres: Centres, point: str, *,
                               scale: float, link: int | None = None) -> VelocityResult:
    """Find V of ``point`` by the parallel-line method (Hinkle Fig 5.3, notes §2.7)."""
    return _Method(asm, centres, "parallel-line", "pl", scale).run(point, link)


# ----- what the constructions read off their own drawing (:class:`~..record.Derived`), so
# that a replay at another position of the input (:mod:`..replay`) reads it again ---------
def known_length(output, centre: Ref, p: Ref, v: Ref) -> dict[str, float]:
    """The known speed ``v`` (a vector at ``p``) laid off signed: + if it turns
    counter-clockwise about ``centre``, − if clockwise, as read off the figure."""
    (cx, cy), (px, py) = output(centre).xy, output(p).xy
    vx, vy = output(v).vector
    sense = 1.0 if (px - cx) * vy - (py - cy) * vx >= 0 else -1.0
    return {"length": sense * output(v).length}


def speed_of(output, v: Ref) -> dict[str, float]:
    """The length of the vector ``v``, laid off again elsewhere."""
    return {"length": output(v).length}


def angle_back(output, centre: Ref, point: Ref, swung: Ref) -> dict[str, float]:
    """The angle that turns ``swung`` (the point swung onto the line of centres) back
    about ``centre`` to ``point``."""
    (cx, cy), (dx, dy), (ax, ay) = output(centre).xy, output(point).xy, output(swung).xy
    return {"angle": math.atan2(dy - cy, dx - cx) - math.atan2(ay - cy, ax - cx)}


def quarter_toward(output, t: Ref, centre: Ref, v: Ref) -> dict[str, float]:
    """The quarter turn that lays the velocity ``v`` at ``t`` onto its radius toward
    ``centre``."""
    (tx, ty), (cx, cy) = output(t).xy, output(centre).xy
    vx, vy = output(v).vector
    return {"angle": math.copysign(math.pi / 2, vx * (cy - ty) - vy * (cx - tx))}


def quarter_back(output, t: Ref, centre: Ref, v: Ref) -> dict[str, float]:
    """The quarter turn back the other way (:func:`quarter_toward`)."""
    return {"angle": -quarter_toward(output, t, centre, v)["angle"]}


class _Method:
    def __init__(self, asm: Assembly, centres: Centres, method: str, prefix: str, scale: float):
        self.asm, self.cs, self.method, self.scale = asm, centres, method, scale
        self.c = asm
        self.m = asm.mechanism
        self.prefix = prefix

    # ----- bookkeeping ------------------------------------------------------------
    def draw(self, name: str, verb: str, *inputs: Ref, **kw) -> Ref:
        ref = f"{self.prefix}:{self.point}:{name}"
        return self.c.draw(ref, verb, *inputs, **kw)

    def centre(self, i: int, j: int) -> Ref:
        return self.cs.centre(i, j).ref

    def is_infinite(self, ref: Ref) -> bool:
        return self.c.output(ref).is_at_infinity

    def speed(self, start: Ref, tip: Ref) -> Quantity:
        """The speed a vector from ``start`` to ``tip`` stands for, read at the scale."""
        length = g.distance(self.c.output(start), self.c.output(tip))
        return self.m.units.speed_said(length / self.scale)

    # ----- the run --------------------------------------------------------------
    def run(self, point: str, link: int | None) -> VelocityResult:
        self.point = point
        self.turned: list[Ref] = []       # the velocities the parallel lines turn through 90°
        d = self.m.drive.link
        known, v_known = draw_input_velocity(self.asm, self.scale)
        j = self.carrier(point, link)
        carried = (v_known,)
        try:
            if j == d:
                v = self.on_link(j, self.asm.points[known], v_known, point,
                                 transfer_label=known)
            else:
                t, v_t = self.transfer(d, j, known, v_known)
                carried = tuple(dict.fromkeys((v_known, v_t)))
                v = self.on_link(j, t, v_t, point, transfer_label=pair_label(d, j))
        except DegenerateInput as e:
            raise TarsimError(f"the {self.method} construction of V_{point} breaks down at this "
                              f"position: {e}") from None
        return velocity_result(self.asm, self.method, point, j, v, self.scale,
                               (*carried, *self.turned))

    def carrier(self, point: str, link: int | None) -> int:
        """The link to take ``point`` on: the input's, else one whose transfer centre is a pin."""
        links = [k for k in self.m.links_at(point) if k != 1]
        if not links:
            slides = [s.link for s in self.m.slides if s.point == point]
            links = slides
        if link is not None:
            if link not in links:
                raise TarsimError(f"point {point} is not on link {link}; it is on "
                                  f"{', '.join(f'link {k}' for k in links) or 'the frame only'}")
            return link
        if not links:
            raise TarsimError(f"point {point} is on the frame: its velocity is zero")
        d = self.m.drive.link
        if d in links:
            return d

        def cost(k: int) -> tuple:
            return (self.is_infinite(self.centre(1, k)), not self.cs.centre(d, k).primary, k)
        return min(links, key=cost)

    def transfer(self, i: int, j: int, known: str, v_known: Ref) -> tuple[Ref, Ref]:
        """Carry the known velocity on link i to the transfer point I_ij (notes §2.5, steps 1–4)."""
        i1, ij = self.centre(1, i), self.centre(i, j)
        lab_i1, lab_ij = pair_label(1, i), pair_label(i, j)
        if self.same(ij, self.asm.points[known]):
            return ij, v_known  # the known point is the transfer point (a pin)
        if self.is_infinite(ij):
            return self.equal_omega(i, j, known, v_known)
        loc = self.draw("loc", "line_through", i1, ij,
                        phrase=phrase("velocity.line_of_centres", a=lab_i1, b=lab_ij,
                                      c=pair_label(1, j)))
        tip = self.gauge_tip(i1, loc, known, v_known, lab_i1, i)
        perp = self.draw("perp:t", "perpendicular_through", ij, loc,
                         phrase=phrase("velocity.erect_perpendicular", at=lab_ij))
        t_tip = self.draw("tip:t", "intersect_lines", perp, tip,
                          phrase=phrase("velocity.meets_gauge_at_tip", link=i, centre=lab_ij))
        v_t = self.draw("V:t", "join", ij, t_tip, label=vector_label(self.named(i, j)),
                        phrase=phrase("velocity.transfer_point", centre=lab_ij,
                                      speed=self.speed(ij, t_tip), i=i, j=j))
        return ij, v_t

    def named(self, i: int, j: int) -> str:
        """What the transfer point I_ij is called on the figure: the pin's own name where
        links i and j are pinned there (V_A, not V_I23, for the pin A), else the centre's."""
        if self.cs.centre(i, j).rule == "pin":
            shared = [n for n in self.m.link(i).names if n in self.m.link(j).names]
            if len(shared) == 1:
                return shared[0]
        return pair_label(i, j)

    def equal_omega(self, i: int, j: int, known: str, v_known: Ref) -> tuple[Ref, Ref]:
        """Carry the known velocity to link j when I_ij is at infinity (notes §2.5): the two
        links turn with one ω, so their gauge lines have one slope. On the line through
        I_1i and I_1j, draw link i's gauge line as usual, link j's through I_1j parallel to
        it, and read the velocity of I_1i taken as a point of link j. Returns that point
        and its velocity, for link j's own construction to go on from.

        Raises
        ------
        DegenerateInput
            If link j translates too, or its centre I_1j falls on I_1i.
        """
        i1, j1 = self.centre(1, i), self.centre(1, j)
        lab_i1, lab_j1, lab_ij = pair_label(1, i), pair_label(1, j), pair_label(i, j)
        if self.is_infinite(j1) or self.same(i1, j1):
            raise DegenerateInput(f"{lab_ij} is at infinity and {lab_j1} gives no line with "
                                  f"{lab_i1}: no line carries link {j}'s ω")
        loc = self.draw("loc", "line_through", i1, j1,
                        phrase=phrase("velocity.equal_omega_line", centre=lab_ij, i=i, j=j,
                                      a=lab_i1, b=lab_j1))
        gauge_i = self.gauge_tip(i1, loc, known, v_known, lab_i1, i)
        gauge_j = self.draw("gauge:eq", "parallel_through", j1, gauge_i,
                            label=f"gauge line of link {j}", kind=Kind.GAUGE_LINE,
                            phrase=phrase("velocity.equal_omega_gauge", centre=lab_j1, i=i, j=j))
        perp = self.draw("perp:eq", "perpendicular_through", i1, loc)
        tip = self.draw("tip:eq", "intersect_lines", perp, gauge_j,
                        phrase=phrase("velocity.equal_omega_point", at=lab_i1, j=j,
                                      speed=self.speed_to(i1, perp, gauge_j)))
        return i1, self.draw("V:eq", "join", i1, tip, label=vector_label(lab_i1))

    def speed_to(self, at: Ref, perp: Ref, gauge: Ref) -> Quantity:
        """The speed the perpendicular at ``at`` cuts off on ``gauge``, read before it is drawn
        (for the sentence that draws it)."""
        p = g.intersect_lines(self.c.output(perp), self.c.output(gauge))[0]
        return self.m.units.speed_said(g.distance(self.c.output(at), p) / self.scale)

    def gauge_tip(self, centre: Ref, loc: Ref, known: str, v_known: Ref, lab_c: str,
                  link: int) -> Ref:
        """Swing ``known`` onto the line of centres, lay off its speed there, draw the gauge
        line."""
        p = self.asm.points[known]
        arc = self.draw("arc:k", "circle_through", centre, p, kind=Kind.SWING,
                        phrase=phrase("velocity.swing_onto_line", centre=lab_c, point=known))
        at = self.draw("rot:k", "intersect_line_circle", loc, arc, pick="forward",
                       label=f"{known}′")
        perp = self.draw("perp:k", "perpendicular_through", at, loc)
        tip = self.draw("tip:k", "lay_off", at, perp,
                        derived=Derived(known_length, (centre, p, v_known)),
                        **known_length(self.c.output, centre, p, v_known),
                        phrase=phrase("velocity.lay_off_known", point=known,
                                      speed=self.speed(*self.c[v_known].inputs)))
        return self.draw("gauge:i", "line_through", centre, tip, label=f"gauge line of link {link}",
                         kind=Kind.GAUGE_LINE,
                         phrase=phrase("velocity.gauge_line", link=link, centre=lab_c))

    # ----- on link j ---------------------------------------------------------------
    def on_link(self, j: int, t: Ref, v_t: Ref, point: str, transfer_label: str) -> Ref:
        target = self.asm.points[point]
        j1 = self.centre(1, j)
        label = vector_label(point)
        if self.is_infinite(j1):
            along = self.draw("dir", "line_through", t, self.tip_of(v_t))
            par = self.draw("par", "parallel_through", target, along)
            tip = self.draw("tip", "lay_off", target, par, derived=Derived(speed_of, (v_t,)),
                            **speed_of(self.c.output, v_t),
                            phrase=phrase("velocity.translates", link=j, centre=pair_label(1, j),
                                          known=transfer_label, point=point))
            return self.result(point, tip, label)
        if g.distance(self.c.output(target), self.c.output(j1)) <= 1e-12 * self.asm.size:
            at_rest = self.draw("rest", "mark", target,
                                phrase=phrase("velocity.at_rest", point=point,
                                              centre=pair_label(1, j), link=j))
            return self.result(point, at_rest, label)
        if self.method == "radius-rotation":
            return self.rotate_radius(j, j1, t, v_t, point, target, label)
        return self.draw_parallels(j, j1, t, v_t, point, target, label)

    def name_of(self, ref: Ref) -> str:
        """How the text names a drawn point: its label ("I23"), or a point name ("A")."""
        step = self.c[ref]
        at = step.inputs[0] if step.verb == "mark" else ref   # a pin named as a centre
        names = [n for n, r in self.asm.points.items() if r == at]
        label = self.c[ref].label
        return f"{label} ({names[0]})" if names and label and label != names[0] else (
            label or (names[0] if names else ref))

    def same(self, a: Ref, b: Ref) -> bool:
        """True if the points ``a`` and ``b`` coincide to the drawing's rounding (relative to
        its size, so a mechanism a micrometre across is judged as one a metre across)."""
        p, q = self.c.output(a), self.c.output(b)
        if p.is_at_infinity or q.is_at_infinity:
            return False
        return math.dist(p.xy, q.xy) <= 1e-12 * self.asm.size

    def tip_of(self, v: Ref) -> Ref:
        """The ref of a vector's tip point (the input of its ``join``)."""
        return self.c[v].inputs[1]

    def rotate_radius(self, j, j1, t, v_t, point, target, label) -> Ref:
        lab = pair_label(1, j)
        if self.same(t, target):
            return v_t
        loc = self.draw("loc:j", "line_through", j1, t,
                        phrase=phrase("velocity.line_of_centres_of_link", link=j, a=lab,
                                      b=self.name_of(t)))
        gauge = self.draw("gauge:j", "line_through", j1, self.tip_of(v_t),
                          label=f"gauge line of link {j}", kind=Kind.GAUGE_LINE,
                          phrase=phrase("velocity.gauge_line_known", link=j, centre=lab))
        arc = self.draw("arc:d", "circle_through", j1, target, kind=Kind.SWING,
                        phrase=phrase("velocity.swing_onto_line", centre=lab, point=point))
        at = self.draw("rot:d", "intersect_line_circle", loc, arc, pick="forward",
                       label=f"{point}′")
        perp = self.draw("perp:d", "perpendicular_through", at, loc,
                         phrase=phrase("velocity.erect_perpendicular", at=f"{point}′"))
        tip = self.draw("tip:d", "intersect_lines", perp, gauge,
                        phrase=phrase("velocity.meets_gauge_length", link=j, point=point))
        tip_back = self.draw("back", "rotate_about", tip, j1,
                             derived=Derived(angle_back, (j1, target, at)),
                             **angle_back(self.c.output, j1, target, at),
                             phrase=phrase("velocity.rotate_back", centre=lab, point=point))
        return self.result(point, tip_back, label)

    def draw_parallels(self, j, j1, t, v_t, point, target, label) -> Ref:
        lab = pair_label(1, j)
        if self.same(t, target):
            return v_t
        # Turn the known velocity itself about its point, so the answer rests on it and
        # inherits its conditioning. Its length laid off as a bare number would drop the
        # transfer's, which is where the digits go when I_ij stands close to I_1i (a short
        # crank beside a long frame: I25 0.031 mm from O2 in a drawing 100 mm across).
        turned = self.draw("turn:t", "rotate_about", self.tip_of(v_t), t,
                           derived=Derived(quarter_toward, (t, j1, v_t)),
                           **quarter_toward(self.c.output, t, j1, v_t),
                           phrase=phrase("velocity.turn_known", centre=lab))
        self.turned.append(self.draw("turned:t", "join", t, turned,
                                     phrase=phrase("velocity.turned_arrow")))
        side = self.draw("td", "line_through", t, target,
                         phrase=phrase("velocity.join", a=self.name_of(t), b=point))
        par = self.draw("par", "parallel_through", turned, side,
                        phrase=phrase("velocity.parallel_through_turned"))
        radius = self.draw("rad", "line_through", target, j1,
                           phrase=phrase("velocity.radius", point=point, centre=lab))
        cut = self.draw("cut", "intersect_lines", par, radius,
                        phrase=phrase("velocity.parallel_cuts_radius", point=point))
        self.turned.append(self.draw("turned", "join", target, cut,
                                     phrase=phrase("velocity.turned_found", point=point)))
        # The known velocity was turned onto its radius by ±90°; turn back the other way.
        tip = self.draw("back", "rotate_about", cut, target,
                        derived=Derived(quarter_back, (t, j1, v_t)),
                        **quarter_back(self.c.output, t, j1, v_t),
                        phrase=phrase("velocity.turn_back", point=point, centre=lab))
        return self.result(point, tip, label)

    def result(self, point: str, tip: Ref, label: str) -> Ref:
        at = self.asm.points[point]
        return self.draw("V", "join", at, tip, label=label, role=Role.RESULT,
                         phrase=phrase("velocity.result", point=point, speed=self.speed(at, tip)))




METHODS = {
    "radius-rotation": velocity_by_radius_rotation,
    "parallel-line": velocity_by_parallel_lines,
}
"""The centre-based velocity methods, by the name an exercise file uses."""


def answer_velocity(work, ask, method: str) -> Answer:
    """V of the asked point by ``method`` through the position's centres (the registry's)."""
    result = METHODS[method](work.assembly, located(work), ask.point, scale=work.scales.vector)
    return answer(work, ask, result)
