"""What the velocity and the acceleration polygon share: the walk from tip to tip.

Both polygons find the same points in the same order, each as the crossing of two
lines that carry its tip (the notes §2.8 and §2.10); only what stands on those
lines differs. A line ⟂ KX through k is the velocity polygon's V_X/K, and in the
acceleration polygon the tangential component drawn from the end of the normal
one; a parallel to a slot is the sliding velocity, or the sliding acceleration
laid beyond the Coriolis component. So the planning (which tip follows from
which), the image rules (divide a side, share a tip) and the crossing with its
dead-point check live here, and each polygon says how it draws a line and what
it reads off at the end. What a joint gives the walk is its kind's entry
(:mod:`.polygon_joints`); the polygon it hands back is a :class:`~.polygon.Polygon`.
"""

from __future__ import annotations

import math
from itertools import combinations

from .. import geometry as g
from .assembly_record import Assembly
from .coincident import Node, Walk, rolling_contacts
from ..errors import DeadPoint, DegenerateInput, TarsimError
from .joint_rules import rules_of
from ..joints import Slide
from ..narration import Number, Phrase, Word, narrate, phrase
from .polygon import VELOCITY, Polygon, PolygonKind
from .polygon_readings import image_length, image_ratio
from ..record import Derived, Kind, Ref, Role

__all__ = ["PolygonWalk", "DEAD_POINT"]

DEAD_POINT = 1e-7
"""Sine of the crossing angle below which two lines of a tip count as parallel (a dead point).

At a toggle reached through rounding the two lines lean about ``sqrt(eps) ≈ 1.5e-8``
apart, so a smaller threshold would draw a dead point as a far, meaningless tip.
"""

_ON_LINE = 1e-9  # relative sine below which three points count as collinear
_APART = 1e-12   # relative distance below which two points count as one
class PolygonWalk(Walk):
    """One polygon drawn point by point from its pole; subclasses draw the lines.

    A subclass sets ``kind`` (:data:`VELOCITY` or :data:`ACCELERATION`, which names
    its steps, pole and tips) and provides ``draw_input``, ``draw_locus`` and
    ``draw_results``.
    """

    kind: PolygonKind

    def polygon(self, rates: dict[int, float], **parts) -> Polygon:
        """The drawn polygon, with the rates it read and any further parts (Coriolis)."""
        tips, aliases = self.tips()
        return Polygon(self.kind, self.pole_ref, self.scale, tips, rates, self.steps,
                       self.space_steps, self.c, aliases, spans=self.spans, reads=self.reads,
                       **parts)

    def __init__(self, asm: Assembly, scale: float, pole: tuple[float, float]):
        self.asm, self.m, self.c, self.scale = asm, asm.mechanism, asm, scale
        m = self.m
        moving = [s for s in (*m.slides, *m.arcs) if s.guide_link != 1 and s.type.rolling]
        if moving:
            raise TarsimError(f"the {self.kind.noun} polygon does not yet handle the "
                              f"{moving[0].label}, on a moving face; use radius-rotation or "
                              "parallel-line")
        if self.pole_ref in self.c:
            article = "an" if self.kind.noun[0] in "aeiou" else "a"
            raise TarsimError(f"this construction already holds {article} {self.kind.noun} "
                              "polygon; assemble the mechanism again to draw another")
        self.pole_xy = (float(pole[0]), float(pole[1]))
        self.size = asm.size
        self.spans: dict[int, float] = {}
        self.reads: dict[int, tuple] = {}
        nodes = [Node(n) for n in m.point_names]
        nodes += [Node(s.point, s.guide_link) for s in m.slotted]
        # A wheel rolling on the ground touches it at its instant centre: a point of the
        # wheel at rest, though not without acceleration (ω² r toward the wheel's centre).
        self.rolls: dict[Node, tuple[Ref, Slide]] = {
            Node(name, s.link): (asm.contacts[s], s) for name, s in rolling_contacts(m).items()}
        nodes += list(self.rolls)
        self.nodes = list(dict.fromkeys(nodes))
        self.known: dict[Node, Ref] = {}
        self.steps: list[Ref] = []
        self.space_steps: list[Ref] = []

    def input_arm(self) -> tuple[Node, Node, float]:
        """The input's centre of rotation and its known point, and the distance between: a
        crank's pivot and second point; a rolling wheel's contact point (at rest at the
        instant) and its centre."""
        d = self.m.drive
        s = self.m.rolling_input
        if s is None:
            k = self.m.link(d.link)
            return Node(k.names[0]), Node(k.names[1]), k.span(k.names[0], k.names[1])
        contact = next(n for n, (_, t) in self.rolls.items() if t is s)
        return contact, Node(s.point), s.contact.circle.radius

    def input_line(self) -> Ref:
        """The space-diagram line from the input's centre of rotation to its known point: the
        crank's axis, or the line joining a rolling wheel's contact point to its centre."""
        o, x, _ = self.input_arm()
        if self.m.rolling_input is None:
            return self.asm.axes[self.m.drive.link]
        return self.space_line(o, x, self.m.drive.link)

    @property
    def pole_ref(self) -> Ref:
        """The step of the pole."""
        return f"{self.kind.prefix}:{self.kind.pole}"

    # ----- the mechanism as the polygon sees it -----------------------------------
    def name(self, n: Node) -> str:
        """The textbook name: B, or A2 and A4 where a slot makes A two points; P for the
        point of a rolling wheel on the ground."""
        if n in self.rolls:
            return n.point
        if n.link is not None:
            return f"{n.point}{n.link}"
        if any(k.point == n.point and k.link is not None for k in self.nodes):
            moving = [c for c in self.carriers(n) if c != 1]
            return f"{n.point}{moving[0]}" if moving else n.point
        return n.point

    def tip_name(self, name: str) -> str:
        """The tip of point ``name`` in this polygon: b, or b′."""
        return name.lower() + self.kind.prime

    def tip_label(self, n: Node) -> str:
        """How the polygon names the tip of ``n``: its letter, or the pole for a fixed point."""
        return self.kind.pole if self.zero(n) else self.tip_name(self.name(n))

    def xy(self, n: Node) -> tuple[float, float]:
        """Where the point ``n`` stands in the space diagram."""
        return self.c.output(self.point_ref(n)).xy

    def point_ref(self, n: Node) -> Ref:
        """The step that put ``n`` on the space diagram: its joint, or a wheel's contact."""
        return self.rolls[n][0] if n in self.rolls else self.asm.points[n.point]

    def zero(self, n: Node) -> bool:
        """True for a point at rest: of the frame; or, in the velocity polygon, a rolling
        wheel's contact point."""
        if n in self.rolls:
            return self.kind is VELOCITY
        return super().zero(n)

    def apart(self, a: Node, b: Node) -> bool:
        """True if the two points are not one."""
        return math.dist(self.xy(a), self.xy(b)) > _APART * self.size

    def normal(self, a: Node, b: Node) -> tuple[float, float]:
        """The unit normal to ``ab``, turned +90° from it."""
        (ax, ay), (bx, by) = self.xy(a), self.xy(b)
        d = math.hypot(bx - ax, by - ay)
        return (ay - by) / d, (bx - ax) / d

    def ready(self, n: Node, known) -> bool:
        """True if the tip of ``n`` is drawn, or is the pole."""
        return n in known or self.zero(n)

    def tip(self, n: Node) -> Ref:
        """The step of the tip of ``n`` (the pole for a fixed point)."""
        return self.pole_ref if self.zero(n) else self.known[n]

    def length(self, ref: Ref) -> float:
        """The drawn vector o → ``ref`` in m/s (or m/s²)."""
        return math.dist(self.c.output(ref).xy, self.pole_xy) / self.scale

    def vector(self, start: Ref, end: Ref) -> tuple[float, float]:
        """The drawn vector ``start`` → ``end`` in m/s (or m/s²)."""
        (sx, sy), (ex, ey) = (self.c.output(r).xy for r in (start, end))
        return (ex - sx) / self.scale, (ey - sy) / self.scale

    # ----- planning: which tip follows from which ---------------------------------
    def loci(self, x: Node, known) -> list[tuple[tuple, tuple[float, float]]]:
        """Lines known to carry the tip of x, with their directions in space."""
        out = []
        for c in self.carriers(x):
            out += [(("rel", k, c), self.normal(k, x)) for k in self.members(c)
                    if k != x and self.ready(k, known) and self.apart(k, x)]
            i = self.frame_guide(c)
            if i is not None and not (x.link is None and self.m.slides[i].point == x.point):
                out.append((("glide", i, c), self.asm.guide(i).direction))
        for joints in (self.m.slides, self.m.pin_arcs):      # as each kind's locus gives it
            for i, j in enumerate(joints):
                out += rules_of(j).locus(self, x, i, j, known)
        return list(dict.fromkeys(out))

    def curve_nodes(self, x: Node, other: Node) -> tuple[Node, Node, str]:
        """Of the two points a curved slot makes, (the sliding point P, the slot's point Pj)
        and the relative motion's name: "A2/A4", or "A" on a slot of the frame."""
        slider, carried = (x, other) if x.link is None else (other, x)
        P = self.name(slider)
        return slider, carried, P if self.zero(carried) else f"{P}/{self.name(carried)}"

    def partner(self, x: Node, point: str, j: int) -> Node | None:
        """The other of the two coincident points a joint of ``point`` on link j makes."""
        if x.point != point or j == 1:
            return None
        other = Node(point, j) if x.link is None else Node(point) if x.link == j else None
        return other if other is not None and other != x and other in self.nodes else None

    def rules(self, x: Node, known) -> list[tuple[str, tuple, float]]:
        """Every way to find x's tip, as (kind, args, quality), the crossing-free ones first."""
        whole, cross = [], []
        for c in self.carriers(x):
            # A point standing on a known point of its link is that point (a rim point on the
            # contact of a rolling wheel): one tip, however the link moves.
            whole += [("coincide", (c, k), 1.0) for k in self.members(c)
                      if k != x and self.ready(k, known) and not self.apart(k, x)
                      and k in self.rolls]
            if self.frame_guide(c) is not None:
                whole += [("translate", (c, k), 1.0) for k in self.members(c)
                          if k != x and k in known and not self.zero(k)]
            ready = [k for k in self.members(c)
                     if k != x and self.ready(k, known) and self.apart(k, x)]
            for a, b in combinations(ready, 2):
                if not (self.zero(a) and self.zero(b)) and self.apart(a, b) and \
                        self.collinear(a, b, x):
                    whole.append(("divide", (c, a, b), 1.0))
        for (l1, d1), (l2, d2) in combinations(self.loci(x, known), 2):
            cross.append(("cross", (l1, l2), abs(d1[0] * d2[1] - d1[1] * d2[0])))
        return whole + cross

    def collinear(self, a: Node, b: Node, x: Node) -> bool:
        """True if ``x`` lies on the line ``ab``."""
        pa, pb, px = (g.Point(*self.xy(n)) for n in (a, b, x))
        return abs(g.side_of(px, pa, pb)) <= _ON_LINE * g.distance(pa, pb) * g.distance(pa, px)

    # ----- the walk ---------------------------------------------------------------
    def walk(self) -> None:
        """Set the pole, draw the input, then every other tip, the best-crossing first."""
        self.c.give(self.pole_ref, g.Point(*self.pole_xy), label=self.kind.pole,
                    panel=self.kind.panel, kind=Kind.POLE,
                    phrase=phrase("polygon.pole", noun=Word(self.kind.noun), pole=self.kind.pole))
        self.steps.append(self.pole_ref)
        self.draw_input()
        while True:
            todo = [n for n in self.nodes if n not in self.known and not self.zero(n)]
            if not todo:
                return
            best = None
            for n in todo:
                for rule in self.rules(n, self.known):
                    if best is None or rule[2] > best[1][2]:
                        best = (n, rule)
            if best is None:
                names = ", ".join(n.point if n.link is None else f"{n.point} on link {n.link}"
                                  for n in todo)
                raise TarsimError(f"the {self.kind.noun} polygon cannot reach {names}: no link "
                                  "carrying it has two known points or a known direction")
            x, (kind, args, _) = best
            self.known[x] = getattr(self, f"draw_{kind}")(x, *args)

    def tips(self) -> tuple[dict[str, Ref], dict[str, str]]:
        """Every tip by name, and the names a carrying link gives a pin (A2 for A)."""
        tips = {n.point if n.link is None else self.name(n): self.tip(n) for n in self.nodes}
        aliases = {}
        for n in self.nodes:
            if n.link is None:
                for c in self.carriers(n):
                    alias = f"{n.point}{c}"
                    if c != 1 and alias not in tips:
                        aliases[alias] = n.point
        return tips, aliases

    def act(self, ref: Ref, verb: str, *inputs: Ref, said: Phrase | None, label: str = "",
            role: Role = Role.CONSTRUCTION, derived: Derived | None = None, **params) -> Ref:
        """Do one drafting act in the polygon's panel and count it among its steps."""
        self.c.draw(ref, verb, *inputs, label=label, phrase=said, role=role,
                    panel=self.kind.panel, derived=derived, **params)
        self.steps.append(ref)
        return ref

    def space_line(self, k: Node, x: Node, c: int) -> Ref:
        """The space-diagram line KX of link c, directed K → X, drawn once for both polygons."""
        ref = f"vp:line:{k.point}-{x.point}"
        if ref not in self.c:
            self.c.draw(ref, "line_through", self.point_ref(k), self.point_ref(x),
                        phrase=phrase("polygon.space_line", a=k.point, b=x.point, link=c))
        if ref not in self.space_steps:
            self.space_steps.append(ref)
        return ref

    # ----- the acts both polygons share ---------------------------------------------
    def draw_cross(self, x: Node, first: tuple, second: tuple) -> Ref:
        """Find the tip of ``x`` where two lines that carry it meet, or say it is a dead point."""
        (l1, say1), (l2, say2) = (self.draw_locus(x, lo) for lo in (first, second))
        X = self.name(x)
        xl = self.tip_name(X)
        d = self.m.drive
        dead = (f"dead point at θ{d.link} = {self.m.units.angle_brief(d.angle)}: "
                f"{narrate(say1)} and {narrate(say2)} are parallel, so {self.kind.symbol}_{X} is "
                "undefined; move the input off it")
        try:
            tip = self.act(f"{self.kind.prefix}:tip:{X}", "intersect_lines", l1, l2, label=xl,
                           said=phrase("polygon.lines_meet", tip=xl, pole=self.kind.pole,
                                       symbol=self.kind.symbol, point=X))
        except DegenerateInput:
            raise DeadPoint(dead, joint=x.point, angle_deg=math.degrees(d.angle)) from None
        step = self.c[tip]
        (a1, b1), (a2, b2) = (self.c.output(r).normal for r in (l1, l2))
        if step.output.is_at_infinity or abs(a1 * b2 - b1 * a2) < DEAD_POINT:
            raise DeadPoint(dead, joint=x.point, angle_deg=math.degrees(d.angle))
        return tip

    def draw_divide(self, x: Node, c: int, a: Node, b: Node) -> Ref:
        """X on line AB of link c: x divides ab as X divides AB (the image)."""
        spots = (self.point_ref(a), self.point_ref(b), self.point_ref(x))
        ratio = image_ratio(self.c.output, *spots)
        X = self.name(x)
        xl, al, bl = self.tip_name(X), self.tip_label(a), self.tip_label(b)
        ta, tb = self.tip(a), self.tip(b)
        side = math.dist(self.c.output(ta).xy, self.c.output(tb).xy)
        why = phrase("polygon.image_why", x=x.point, a=a.point, b=b.point, link=c, tip=xl,
                     ta=al, tb=bl, ratio=Number(ratio), noun=Word(self.kind.noun))
        ref = f"{self.kind.prefix}:tip:{X}"
        if side == 0.0:
            return self.act(ref, "mark", ta, label=xl,
                            said=phrase("polygon.image_collapsed", why=why, ta=al, tb=bl, tip=xl))
        return self.act(ref, "lay_off", ta, tb, length=ratio * side, label=xl,
                        derived=Derived(image_length, (ta, tb, *spots)),
                        said=phrase("polygon.image_lay_off", why=why, ta=al, tip=xl,
                                    ratio=Number(ratio), tb=bl))

    def draw_translate(self, x: Node, c: int, k: Node) -> Ref:
        """A point of a link that slides without turning has the tip of the point ``k`` of it."""
        X, K = self.name(x), self.name(k)
        s = self.kind.symbol
        return self.act(f"{self.kind.prefix}:tip:{X}", "mark", self.tip(k), label=self.tip_name(X),
                        said=phrase("polygon.translate", link=c, symbol=s, point=X, known=K,
                                    tip=self.tip_name(X), known_tip=self.tip_name(K)))

    def draw_coincide(self, x: Node, c: int, k: Node) -> Ref:
        """A point of link c that stands, at the instant, on its known point ``k``."""
        X, K = self.name(x), self.name(k)
        return self.act(f"{self.kind.prefix}:tip:{X}", "mark", self.tip(k),
                        label=self.tip_name(X),
                        said=phrase("polygon.coincide", link=c, point=X, known=K,
                                    symbol=self.kind.symbol, tip=self.tip_name(X),
                                    known_tip=self.tip_label(k)))

    def read_pair(self, c: int) -> tuple[Node, Node] | None:
        """The two points of link c its ω or α is read from: a fixed pivot and the farthest point,
        else the two farthest; the fixed one (if any) first."""
        nodes = [n for n in self.members(c) if n in self.known or self.zero(n)]
        pairs = [(a, b) for a, b in combinations(nodes, 2)
                 if not (self.zero(a) and self.zero(b)) and self.apart(a, b)]
        if not pairs:
            return None
        p, q = max(pairs, key=lambda p: (self.zero(p[0]) or self.zero(p[1]),
                                         math.dist(self.xy(p[0]), self.xy(p[1]))))
        return (q, p) if self.zero(q) else (p, q)

    def block_rates(self, rates: dict[int, float], later: list[int]) -> None:
        """A one-point block turns with its guide (or not at all on the frame): fill its rate."""
        while later:
            for c in later:
                s = next((s for s in self.m.slides if s.link == c and s.type.turns_with_guide
                          and (s.guide_link == 1 or s.guide_link in rates)), None)
                if s is not None:
                    rates[c] = 0.0 if s.guide_link == 1 else rates[s.guide_link]
                    self.reads[c] = self.reads.get(s.guide_link, ())
                    later.remove(c)
                    break
            else:
                return
