"""Velocities by components: the lecture notes' §2.6 and Hinkle's §5-8, step for step.

Two points of a rigid link have equal velocity components along the line joining
them. From the input velocity the method walks the mechanism link by link and
finds each new velocity's tip where two of its loci meet, or by a whole
construction of the notes:

* case 1: V_K′ (along KX) laid off at X; the perpendicular to KX at its tip meets
  the path of X (⟂ the radius from a frame pivot, or a frame guide);
* case 2: two such perpendiculars meet at the tip of V_X (not the vector sum!);
* case 3: X on line AB: the line through the tips of V_A″ and V_B″ (⟂ AB) gives
  V_X″; V_X′ = V_A′; V_X = V_X′ + V_X″ by the parallelogram;
* slot (Hinkle Fig. 5.8): V_Pi − V_Pj lies along the slot, so the parallel to the
  slot through one tip meets the other's path;
* translation (Hinkle Fig. 5.9): all points of a block on a frame guide share V.

A node is a velocity: of a point itself (on every link that lists it) or of the
coincident point of another link (``V_A4``: A taken on link 4). The method plans
which node follows from which, as a student surveys the figure, then draws only
what the asked point rests on. Every act is a ``cm:`` step, named by what it is,
so a second call on the same construction reuses what the first one drew.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from itertools import combinations

from .. import geometry as g
from .assembly_record import Assembly
from .coincident import Node, Walk, rolling_contacts
from ..errors import DegenerateInput, TarsimError
from ..narration import Capitalized, Phrase, narrate, phrase
from ..record import Kind, Ref, Role
from ..checks import Answer
from .velocity_drawing import VelocityResult, answer, draw_input_velocity, velocity_result

__all__ = ["velocity_by_components", "answer_velocity"]

WELL_CROSSED = 0.1
"""Sine of the crossing angle (about 6°) from which a pair of loci is taken at once."""

_ON_LINE = 1e-9  # relative sine below which three points count as collinear (case 3)


@dataclass(frozen=True)
class _Rule:
    """How a node is found: ``cross`` two loci, ``case3`` or ``translate``."""

    kind: str
    args: tuple
    needs: tuple[Node, ...]
    quality: float


def velocity_by_components(asm: Assembly, point: str, *, scale: float,
                           link: int | None = None) -> VelocityResult:
    """Find the velocity of ``point`` by resolving known velocities into components.

    Parameters
    ----------
    asm : Assembly
        The mechanism drawn at one position, with the drive's ω.
    point : str
        The point asked for.
    scale : float
        Drawing metres per m/s of the velocity vectors.
    link : int, optional
        The link the point is taken on; a link that does not list the point gives
        its coincident point (``V_A4``). By default, the point itself.

    Returns
    -------
    VelocityResult
        Method ``"components"``; ``vector`` is the ``V_<point>`` result step and
        ``steps`` every step the answer rests on, the input vector first.

    Raises
    ------
    TarsimError
        If no case of the method reaches the point, or the construction
        degenerates (two loci of a tip are parallel, at a dead point).

    See Also
    --------
    constructions.velocity_drawing.draw_input_velocity : the vector it starts from.

    Examples
    --------
    A parallelogram four-bar at θ2 = 90°: the coupler translates, so V_B = V_A.

    >>> import math
    >>> from tarsim.constructions.linkages.assembly import assemble
    >>> from tarsim.constructions.model import Drive, Link, Mechanism
    >>> m = Mechanism((Link(1, (("O2", (0, 0)), ("O4", (4, 0)))),
    ...                Link(2, (("O2", (0, 0)), ("A", (3, 0)))),
    ...                Link(3, (("A", (0, 0)), ("B", (4, 0)))),
    ...                Link(4, (("O4", (0, 0)), ("B", (3, 0))))),
    ...               Drive(2, math.pi / 2, omega=1.0), branches={"B": "left"})
    >>> asm = assemble(m)
    >>> r = velocity_by_components(asm, "B", scale=1.0)
    >>> tuple(round(v, 12) + 0.0 for v in r.value(asm))
    (-3.0, 0.0)
    >>> from tarsim.constructions.narration import narrate
    >>> narrate(asm["cm:B:path@O4"])
    'At B draw the perpendicular to O4B: the path of B.'
    """
    if not (math.isfinite(scale) and scale > 0.0):
        raise TarsimError(f"the velocity scale must be a positive number, got {scale}")
    m = asm.mechanism
    if point not in m.point_names:
        raise TarsimError(f"there is no point {point}; the points are {', '.join(m.point_names)}")
    if link is not None:
        m.link(link)
    target = Node(point, None if link is None or point in m.link(link).names else link)
    return _Components(asm, scale, target).run()


class _Components(Walk):
    def __init__(self, asm: Assembly, scale: float, target: Node):
        self.asm, self.c, self.m, self.scale, self.target = (
            asm, asm, asm.mechanism, scale, target)
        start, vec = draw_input_velocity(asm, scale)
        drawn, want = self.c.output(vec).length, self.m.input_speed
        if abs(drawn - want * scale) > 1e-9 * drawn:
            raise TarsimError(f"this construction's velocities are drawn at {drawn / want:.6g} "
                              f"m per m/s, not {scale:.6g}; use that scale")
        self.given = vec
        nodes = [Node(n) for n in self.m.point_names] + [
            Node(s.point, s.guide_link) for s in self.m.slides
            if s.guide_link != 1 and s.point not in self.m.link(s.guide_link).names]
        self.nodes = list(dict.fromkeys(nodes + [target]))
        # A wheel rolling on the ground turns, at the instant, about its contact point P:
        # a pivot of the wheel as a frame pin is of its link.
        self.contacts = {name: (asm.contacts[s], s.link)
                         for name, s in rolling_contacts(self.m).items()}
        self.known: dict[Node, Ref] = {Node(start): self.c[vec].inputs[1]}
        self.known |= {n: f"cm:{n.tag}:tip" for n in self.nodes  # drawn by a previous call
                       if f"cm:{n.tag}:tip" in self.c and n not in self.known}

    # ----- the mechanism as the method sees it ------------------------------------
    def normal_to(self, a: Node | str, b: Node) -> tuple[float, float] | None:
        """The unit normal to line ab (the direction of a component locus), if a ≠ b."""
        (ax, ay), (bx, by) = (self.c.output(self.at(n)).xy for n in (a, b))
        d = math.hypot(bx - ax, by - ay)
        big = max(1.0, abs(ax), abs(ay), abs(bx), abs(by))
        return None if d <= 1e-12 * big else ((ay - by) / d, (bx - ax) / d)

    def zero(self, n: Node) -> bool:
        """True for a point at rest: of the frame, or a rolling wheel's contact point."""
        return n.point in self.contacts or super().zero(n)

    def collinear(self, a: Node, b: Node, x: Node) -> bool:
        pa, pb, px = (self.c.output(self.at(n)) for n in (a, b, x))
        ab, ax, bx = g.distance(pa, pb), g.distance(pa, px), g.distance(pb, px)
        return min(ab, ax, bx) > 0.0 and abs(g.side_of(px, pa, pb)) <= _ON_LINE * ab * ax

    # ----- planning: which velocity follows from which ----------------------------
    def loci(self, x: Node, known) -> list[tuple[tuple, tuple[float, float]]]:
        """Lines known to carry the tip of V_x, in the notes' order: components, slot, path."""
        comp, slot, path = [], [], []
        for c in self.carriers(x):
            comp += [(("component", k, c), self.normal_to(k, x)) for k in self.members(c)
                     if k != x and k in known and not self.zero(k) and self.normal_to(k, x)]
            pivots = [o for o in self.m.link(c).names if o in self.m.frame.names]
            pivots += [o for o, (_, wheel) in self.contacts.items() if wheel == c]
            path += [(("path", o, c), self.normal_to(o, x)) for o in pivots
                     if self.normal_to(o, x)]
            i = self.frame_guide(c)
            if i is not None and self.m.slides[i].point != x.point:
                path.append((("glide", i, c), self.asm.guide(i).direction))
        for i, s in enumerate(self.m.slides):
            if s.point == x.point and s.guide_link == 1 and x.link is None:
                path.append((("guide", i), self.asm.guide(i).direction))
            elif s.point == x.point and s.guide_link != 1 and x.link in (None, s.guide_link):
                other = Node(s.point, s.guide_link if x.link is None else None)
                if other in known:
                    slot.append((("slide", other, i), self.asm.guide(i).direction))
        return comp + slot + path

    def rules(self, x: Node, known) -> list[_Rule]:
        """Every way to find V_x from what is known, in the order a student would try them."""
        whole, cross, case3 = [], [], []
        for c in self.carriers(x):
            ready = [k for k in self.members(c) if k != x and (k in known or self.zero(k))]
            rest = [Node(o) for o, (_, wheel) in self.contacts.items() if wheel == c]
            whole += [_Rule("rest", (c, k), (), 1.0) for k in rest
                      if self.normal_to(k, x) is None]       # x stands on the contact
            ready += rest
            if self.frame_guide(c) is not None:
                whole += [_Rule("translate", (c, k), (k,), 1.0) for k in ready if not self.zero(k)]
            case3 += [_Rule("case3", (c, a, b), (a, b), 1.0) for a, b in combinations(ready, 2)
                      if not (self.zero(a) and self.zero(b)) and self.collinear(a, b, x)]
        for (l1, d1), (l2, d2) in combinations(self.loci(x, known), 2):
            needs = tuple(lo[1] for lo in (l1, l2) if lo[0] in ("component", "slide"))
            cross.append(_Rule("cross", (l1, l2), needs, abs(d1[0] * d2[1] - d1[1] * d2[0])))
        return whole + cross + case3

    def plan(self) -> list[tuple[Node, _Rule]]:
        """Survey the figure in rounds from what is known, then keep what the target needs.

        Each round finds every node that follows well-crossed from the last round's
        knowns (so each takes the shortest route), or else the one best-crossed node.
        """
        known, chosen = set(self.known), {}
        while self.target not in known and not self.zero(self.target):
            found, best = {}, None
            for n in (n for n in self.nodes if n not in known and not self.zero(n)):
                rules = self.rules(n, known)
                r = next((r for r in rules if r.quality >= WELL_CROSSED), None)
                if r is not None:
                    found[n] = r
                elif rules and (best is None or max(q.quality for q in rules) > best[1].quality):
                    best = (n, max(rules, key=lambda q: q.quality))
            if not found and best is None:
                x = self.target
                on = "" if x.link is None else f" as a point of link {x.link}"
                hint = ("; across a curved slot, a circle contact or a rolling wheel use "
                        "radius-rotation or parallel-line"
                        if self.m.arcs or any(s.type.rolling for s in self.m.slides) else "")
                raise TarsimError(f"the component method cannot reach {x.point}{on}: no link "
                                  f"carrying it has two known velocities or a known path{hint}")
            found = found or dict([best])
            known |= found.keys()
            chosen |= found
        need, stack = set(), [self.target]
        while stack:
            n = stack.pop()
            if n in chosen and n not in need:
                need.add(n)
                stack.extend(chosen[n].needs)
        return [(n, r) for n, r in chosen.items() if n in need]

    # ----- drafting ---------------------------------------------------------------
    def act(self, ref: Ref, verb: str, *inputs: Ref, said: Phrase | None, label: str = "",
            role: Role = Role.CONSTRUCTION, **params) -> Ref:
        """Do one drafting act, or reuse it if this construction already holds it."""
        if ref not in self.c:
            self.c.draw(ref, verb, *inputs, label=label, phrase=said, role=role, **params)
        return ref

    def at(self, n: Node | str) -> Ref:
        name = n.point if isinstance(n, Node) else n
        return self.contacts[name][0] if name in self.contacts else self.asm.points[name]

    def tip(self, n: Node) -> Ref:
        return self.at(n) if self.zero(n) else self.known[n]

    def run(self) -> VelocityResult:
        x = self.target
        try:
            for n, rule in self.plan():
                self.known[n] = getattr(self, f"draw_{rule.kind}")(n, *rule.args)
                if n != x and f"cm:V:{n.tag}:result" not in self.c:
                    self.draw_arrow(n, f"cm:V:{n.tag}", Role.CONSTRUCTION)
            vector = self.draw_arrow(x, f"cm:V:{x.tag}:result", Role.RESULT)
        except DegenerateInput as e:
            d = self.m.drive
            raise TarsimError(f"the component method cannot find V_{x.name} at θ{d.link} = "
                              f"{self.m.units.angle_brief(d.angle)}: {e}") from None
        link = x.link if x.link is not None else next((c for c in self.carriers(x) if c != 1), 1)
        # The method's arrows on this construction, whichever call drew them: a velocity
        # found for an earlier point is a known one here.
        arrows = tuple(s.id for s in self.c if s.id.startswith("cm:") and s.kind is Kind.VECTOR)
        return velocity_result(self.asm, "components", x.point, link, vector, self.scale,
                               (self.given,), arrows)

    def draw_arrow(self, x: Node, ref: Ref, role: Role) -> Ref:
        speed = math.dist(*(self.c.output(r).xy for r in (self.at(x), self.tip(x)))) / self.scale
        return self.act(ref, "join", self.at(x), self.tip(x), label=f"V_{x.name}", role=role,
                        said=phrase("components.arrow", point=x.name,
                                    speed=self.m.units.speed_said(speed)))

    def draw_line(self, p: Node | str, q: Node, said: Phrase) -> Ref:
        """Draw the line through two points, once per construction whoever needs it."""
        p = p.point if isinstance(p, Node) else p
        return self.act(f"cm:line:{p}-{q.point}", "line_through", self.at(p), self.at(q),
                        said=said)

    def transfer_along(self, x: Node, k: Node, line: Ref, kx: str,
                       mark: str = "′") -> tuple[Ref, str]:
        """Project V_k onto ``line`` and lay the component off at x; return its tip and
        what the component at x is called."""
        t, on, K, X = f"cm:{x.tag}:", line.removeprefix("cm:line:"), k.name, x.name
        vk = self.component_name(f"cm:{k.tag}:arrow@{on}", f"V_{K}′", kx)
        vx = self.component_name(f"{t}along-arrow@{k.tag}", f"V_{X}{mark}", kx)
        foot = self.act(f"cm:{k.tag}:foot@{on}", "project_onto", self.tip(k), line,
                        said=phrase("components.project_along", point=K, line=kx, component=vk))
        self.act(f"cm:{k.tag}:arrow@{on}", "join", self.at(k), foot, label=vk,
                 said=phrase("components.draw_component_along", component=vk, point=K, line=kx))
        along = self.act(f"{t}along@{k.tag}", "transfer", self.at(x), self.at(k), foot,
                         said=phrase("components.dividers", a=vx, b=vk, point=X, line=kx))
        self.act(f"{t}along-arrow@{k.tag}", "join", self.at(x), along, label=vx,
                 said=phrase("components.equal_components", a=vx, b=vk))
        return along, vx

    def component_name(self, ref: Ref, name: str, line: str) -> str:
        """``name`` ("V_A′"), or "V_A′(AE)" if another component of the construction already
        goes by it: one figure may hold V_A's components along AB and along AE."""
        if ref in self.c:
            return self.c[ref].label
        if name.endswith(")") or not any(st.label == name for st in self.c):
            return name
        return f"{name}({line})"

    def draw_locus(self, x: Node, locus: tuple, mark: str) -> tuple[Ref, Phrase]:
        """Draw one line carrying the tip of V_x; return it and how the text names it."""
        kind, t, X = locus[0], f"cm:{x.tag}:", x.name
        if kind == "component":
            (k, c), kx = locus[1:], f"{locus[1].name}{X}"
            line = self.draw_line(k, x, phrase("components.line_of_link", line=kx, link=c))
            along, vx = self.transfer_along(x, k, line, kx, mark)
            perp = self.act(f"{t}perp@{k.tag}", "perpendicular_through", along, line,
                            said=phrase("components.perpendicular_from_tip", component=vx,
                                        line=kx))
            return perp, phrase("components.say_perpendicular", line=kx, component=vx)
        if kind == "path":
            o, c = locus[1:]
            radius = self.draw_line(o, x, phrase("components.radius", pivot=o, point=X, link=c))
            path = self.act(f"{t}path@{o}", "perpendicular_through", self.at(x), radius,
                            said=phrase("components.path", point=X, pivot=o))
            return path, phrase("components.say_path", point=X, pivot=o)
        if kind == "guide":
            return self.asm.guides[locus[1]], phrase("components.say_guide", point=X)
        if kind == "glide":
            i, c = locus[1:]
            glide = self.act(f"{t}glide@{i}", "parallel_through", self.at(x), self.asm.guides[i],
                             said=phrase("components.glide", link=c, point=X))
            return glide, phrase("components.say_glide", point=X, link=c)
        (other, i), p = locus[1:], self.m.slides[locus[2]].point
        j = self.m.slides[i].guide_link
        slide = self.act(f"{t}slide@{i}", "parallel_through", self.tip(other), self.asm.guides[i],
                         said=phrase("components.slot_parallel", other=other.name, link=j,
                                     point=p))
        return slide, phrase("components.say_slot", link=j, other=other.name)

    def draw_cross(self, x: Node, first: tuple, second: tuple) -> Ref:
        """Cases 1 and 2 and the slot: two loci of the tip meet at it."""
        both = first[0] == second[0] == "component"
        (l1, say1), (l2, say2) = (self.draw_locus(x, lo, f"′({lo[1].name}{x.name})" if both
                                                  else "′") for lo in (first, second))
        note = phrase("components.not_vector_sum") if both else None
        tip = self.act(f"cm:{x.tag}:tip", "intersect_lines", l1, l2,
                       said=phrase("components.loci_meet", first=Capitalized(say1), second=say2,
                                   point=x.name, note=note))
        if self.c.output(tip).is_at_infinity:
            raise DegenerateInput(f"{narrate(say1)} and {narrate(say2)} are parallel (a dead "
                                  "point)")
        return tip

    def component_normal(self, k: Node, ab: Ref, ab_name: str) -> Ref:
        """The tip of V_k″, the component of V_k ⟂ AB (k itself when k is at rest)."""
        if self.zero(k):
            return self.at(k)
        on, K = ab.removeprefix("cm:line:"), k.name
        n = self.act(f"cm:{k.tag}:normal@{on}", "perpendicular_through", self.at(k), ab,
                     said=phrase("components.perpendicular_at", point=K, line=ab_name))
        vk = self.component_name(f"cm:{k.tag}:narrow@{on}", f"V_{K}″", ab_name)
        tip = self.act(f"cm:{k.tag}:ncomp@{on}", "project_onto", self.tip(k), n,
                       said=phrase("components.project_normal", point=K, component=vk,
                                   line=ab_name))
        self.act(f"cm:{k.tag}:narrow@{on}", "join", self.at(k), tip, label=vk,
                 said=phrase("components.draw_component", component=vk, point=K))
        return tip

    def draw_case3(self, x: Node, c: int, a: Node, b: Node) -> Ref:
        """Case 3: X on line AB, from the components ⟂ AB and the one along it."""
        t, X, ab_name = f"cm:{x.tag}:", x.name, f"{a.name}{b.name}"
        ab = self.draw_line(a, b, phrase("components.line_carries", line=ab_name, link=c,
                                         point=X))
        ta, tb = (self.component_normal(k, ab, ab_name) for k in (a, b))
        rest = a if self.zero(a) else b
        through = (phrase("components.through_rest_and_tip", rest=rest.name,
                          other=(b if rest == a else a).name)
                   if self.zero(rest) else phrase("components.through_tips", a=a.name, b=b.name))
        gauge = self.act(f"{t}gauge", "line_through", ta, tb,
                         said=phrase("components.gauge_through", through=through))
        nx = self.act(f"{t}normal@{x.tag}", "perpendicular_through", self.at(x), ab,
                      said=phrase("components.perpendicular_at", point=X, line=ab_name))
        nx_name = self.component_name(f"{t}narrow@{x.tag}", f"V_{X}″", ab_name)
        tx = self.act(f"{t}ncomp", "intersect_lines", gauge, nx,
                      said=phrase("components.cuts_gauge", component=nx_name, point=X,
                                  line=ab_name))
        self.act(f"{t}narrow@{x.tag}", "join", self.at(x), tx, label=nx_name,
                 said=phrase("components.draw_component", component=nx_name, point=X))
        if self.zero(rest):  # V_X′ = 0: X turns about the fixed pivot, as on Hinkle's gauge line
            return self.act(f"{t}tip", "mark", tx,
                            said=phrase("components.rest_gives", point=X, rest=rest.name,
                                        component=nx_name))
        along, vx = self.transfer_along(x, a, ab, ab_name)
        l1 = self.act(f"{t}pgram′", "perpendicular_through", along, ab,
                      said=phrase("components.pgram_first", a=vx, b=nx_name, line=ab_name))
        l2 = self.act(f"{t}pgram″", "parallel_through", tx, ab,
                      said=phrase("components.pgram_second", a=nx_name, b=vx, line=ab_name))
        return self.act(f"{t}tip", "intersect_lines", l1, l2,
                        said=phrase("components.pgram_meet", point=X, a=vx, b=nx_name))

    def draw_rest(self, x: Node, c: int, k: Node) -> Ref:
        """A point of a rolling wheel standing, at the instant, on its contact point is that
        point: at rest."""
        return self.act(f"cm:{x.tag}:tip", "mark", self.at(x),
                        said=phrase("components.on_contact", point=x.name, rest=k.name, link=c))

    def draw_translate(self, x: Node, c: int, k: Node) -> Ref:
        """Hinkle Fig. 5.9: a block on a frame guide translates, so V_x = V_k."""
        K, X = k.name, x.name
        return self.act(f"cm:{x.tag}:tip", "transfer", self.at(x), self.at(k), self.tip(k),
                        said=phrase("components.translate", link=c, known=K, point=X))


def answer_velocity(work, ask) -> Answer:
    """V of the asked point by components (the registry's)."""
    return answer(work, ask, velocity_by_components(work.assembly, ask.point,
                                                    scale=work.scales.vector))
