"""The velocity polygon: the relative-velocity method of the lecture notes §2.8, step for step.

Every velocity is drawn from one pole ``o_v``; the tip of the velocity of point X
is the lower-case ``x``. Each tip is found where two lines that carry it meet:

* a point of a link with a known point K: ``V_X = V_K + V_X/K`` with V_X/K ⟂ KX,
  so the line through ``k`` ⟂ KX (through ``o_v`` when K is a frame pivot);
* a block or pin on a frame guide: the parallel to the guide through ``o_v``;
* coincident points on a slot of a moving link (the notes' A2 and A4):
  ``V_A4 = V_A2 + V_A4/A2`` with V_A4/A2 along the slot, so the parallel to the
  slot through ``a2``;
* any point of a link that slides on a frame guide without turning: the
  parallel to the guide through ``o_v``.

Two further acts need no crossing: the velocity image of a point on the line of
two known points divides their polygon side in the same ratio, and every point
of a translating link has the same tip. A third point of a link whose two points
have tips gets its tip from the two perpendiculars, so triangle abc is the
velocity image of ABC. ω of each link is read off the polygon: ω = V_X/K / KX,
with the sense of V_X/K about K (counter-clockwise positive).

Every act is a ``vp:`` step in the velocity panel; the space lines the
perpendiculars are taken from (``KX``) are ``vp:line:`` steps in the space panel.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from itertools import combinations

from . import geometry as g
from .assembly import Assembly
from .coincident import Node, Walk
from .errors import AssemblyError, DegenerateInput, TarsimError
from .model import SlideKind
from .record import Construction, Panel, Ref, Role
from .velocity_drawing import speed_text

__all__ = ["VelocityPolygon", "draw_velocity_polygon", "nice_scale", "DEAD_POINT"]

DEAD_POINT = 1e-7
"""Sine of the crossing angle below which two lines of a tip count as parallel (a dead point).

At a toggle reached through rounding the two lines lean about ``sqrt(eps) ≈ 1.5e-8``
apart, so a smaller threshold would draw a dead point as a far, meaningless tip.
"""

_ON_LINE = 1e-9  # relative sine below which three points count as collinear
_APART = 1e-12   # relative distance below which two points count as one


@dataclass
class VelocityPolygon:
    """A drawn velocity polygon: its pole, scale, tips and the ω read off it.

    ``tips`` maps a point name (``"B"``), or a coincident point taken on a link
    (``"A4"``), to its tip step; frame points map to the pole. ``omegas`` maps each
    moving link it could read to ω (rad/s, counter-clockwise positive). ``steps``
    are the polygon's steps in drawing order (all in the velocity panel) and
    ``space_steps`` the lines of the space diagram they take directions from.
    """

    pole: Ref
    scale: float
    tips: dict[str, Ref]
    omegas: dict[int, float]
    steps: list[Ref]
    space_steps: list[Ref] = field(default_factory=list)
    construction: Construction = field(default_factory=Construction, repr=False)
    aliases: dict[str, str] = field(default_factory=dict)

    def velocity(self, name: str) -> tuple[float, float]:
        """Read the velocity of ``name`` (m/s) off the polygon: the vector o_v → its tip.

        ``name`` is a key of ``tips`` or a point taken on a link that carries it
        (``"A2"`` for the crank pin A).

        Raises
        ------
        TarsimError
            If the polygon has no tip of that name.
        """
        key = self.aliases.get(name, name)
        if key not in self.tips:
            raise TarsimError(f"the velocity polygon has no tip for {name}; it has "
                              f"{', '.join(self.tips)}")
        (px, py), (tx, ty) = (self.construction.output(r).xy for r in (self.pole, self.tips[key]))
        return (tx - px) / self.scale, (ty - py) / self.scale


def nice_scale(raw: float) -> float:
    """The largest 1, 2 or 5 × 10^k not above ``raw``.

    Examples
    --------
    >>> nice_scale(0.037), nice_scale(4.0), nice_scale(1.0)
    (0.02, 2.0, 1.0)
    """
    k = math.floor(math.log10(raw))
    for m in (5.0, 2.0, 1.0):
        if m * 10.0 ** k <= raw * (1 + 1e-12):
            return m * 10.0 ** k
    return 10.0 ** k


def draw_velocity_polygon(asm: Assembly, scale: float | None = None, *,
                          pole: tuple[float, float] = (0.0, 0.0)) -> VelocityPolygon:
    """Draw the velocity polygon of ``asm`` by relative velocities, from the input outward.

    Parameters
    ----------
    asm : Assembly
        The mechanism drawn at one position, with the drive's ω.
    scale : float, optional
        Drawing metres per m/s. By default a 1, 2 or 5 × 10^k that makes the input
        velocity about half the mechanism's size.
    pole : (float, float)
        Where ``o_v`` stands in the velocity panel (drawing metres).

    Returns
    -------
    VelocityPolygon
        The pole, the tips of every point (and coincident point on a slot), ω of
        every link it can read, and the steps drawn.

    Raises
    ------
    AssemblyError
        At a dead point: the two lines of a tip are parallel, so the velocities
        and ω are undefined there.
    TarsimError
        If a polygon is already drawn on this construction, the scale is not a
        positive number, or the mechanism has a joint the polygon does not handle
        (a curved slot, a circle contact, a rolling wheel).

    See Also
    --------
    constructions.velocity_by_components.velocity_by_components : one velocity by components.

    Examples
    --------
    A parallelogram four-bar at θ2 = 90°: the coupler translates, so b = a.

    >>> import math
    >>> from constructions.assembly import assemble
    >>> from constructions.model import Drive, Link, Mechanism
    >>> m = Mechanism((Link(1, (("O2", (0, 0)), ("O4", (4, 0)))),
    ...                Link(2, (("O2", (0, 0)), ("A", (3, 0)))),
    ...                Link(3, (("A", (0, 0)), ("B", (4, 0)))),
    ...                Link(4, (("O4", (0, 0)), ("B", (3, 0))))),
    ...               Drive(2, math.pi / 2, omega=1.0), branches={"B": "left"})
    >>> vp = draw_velocity_polygon(assemble(m), scale=1.0)
    >>> tuple(round(v, 12) + 0.0 for v in vp.velocity("B"))
    (-3.0, 0.0)
    >>> round(vp.omegas[3], 12) + 0.0, round(vp.omegas[4], 12) + 0.0
    (0.0, 1.0)
    """
    if scale is None:
        speed = asm.mechanism.input_speed
        scale = 1.0 if speed == 0.0 else nice_scale(asm.size / (2.0 * speed))
    if not (isinstance(scale, (int, float)) and math.isfinite(scale) and scale > 0.0):
        raise TarsimError(f"the velocity scale must be a positive number, got {scale}")
    if "vp:o_v" in asm.construction:
        raise TarsimError("this construction already holds a velocity polygon; assemble the "
                          "mechanism again to draw another")
    return _Polygon(asm, float(scale), pole).run()


class _Polygon(Walk):
    def __init__(self, asm: Assembly, scale: float, pole: tuple[float, float]):
        self.asm, self.m, self.c, self.scale = asm, asm.mechanism, asm.construction, scale
        m = self.m
        if m.pin_arcs:
            a = m.pin_arcs[0]
            raise TarsimError(f"the velocity polygon does not yet handle the {a.label} (a curved "
                              "slot or circle contact); use radius-rotation or parallel-line")
        if any(s.rolling for s in m.slides):
            s = next(s for s in m.slides if s.rolling)
            raise TarsimError(f"the velocity polygon does not yet handle the {s.label}; use "
                              "radius-rotation or parallel-line")
        self.pole_xy = (float(pole[0]), float(pole[1]))
        self.size = asm.size
        nodes = [Node(n) for n in m.point_names]
        nodes += [Node(s.point, s.guide_link) for s in m.slides
                  if s.guide_link != 1 and s.point not in m.link(s.guide_link).names]
        self.nodes = list(dict.fromkeys(nodes))
        self.known: dict[Node, Ref] = {}
        self.steps: list[Ref] = []
        self.space_steps: list[Ref] = []

    # ----- the mechanism as the polygon sees it -----------------------------------
    def name(self, n: Node) -> str:
        """The textbook name: B, or A2 and A4 where a slot makes A two points."""
        if n.link is not None:
            return f"{n.point}{n.link}"
        if any(k.point == n.point and k.link is not None for k in self.nodes):
            moving = [c for c in self.carriers(n) if c != 1]
            return f"{n.point}{moving[0]}" if moving else n.point
        return n.point

    def tip_label(self, n: Node) -> str:
        return "o_v" if self.zero(n) else self.name(n).lower()

    def xy(self, n: Node) -> tuple[float, float]:
        return self.asm.xy(n.point)

    def apart(self, a: Node, b: Node) -> bool:
        return math.dist(self.xy(a), self.xy(b)) > _APART * self.size

    def normal(self, a: Node, b: Node) -> tuple[float, float]:
        (ax, ay), (bx, by) = self.xy(a), self.xy(b)
        d = math.hypot(bx - ax, by - ay)
        return (ay - by) / d, (bx - ax) / d

    def ready(self, n: Node, known) -> bool:
        return n in known or self.zero(n)

    def tip(self, n: Node) -> Ref:
        return "vp:o_v" if self.zero(n) else self.known[n]

    def speed(self, ref: Ref) -> float:
        return math.dist(self.c.output(ref).xy, self.pole_xy) / self.scale

    def say(self, v: float) -> str:
        return speed_text(v, self.m.units)

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
        for i, s in enumerate(self.m.slides):
            if s.point != x.point:
                continue
            if s.guide_link == 1:
                if x.link is None:
                    out.append((("guide", i), self.asm.guide(i).direction))
                continue
            if x.link is None:
                other = Node(s.point, s.guide_link)
            elif x.link == s.guide_link:
                other = Node(s.point)
            else:
                continue
            if other != x and other in self.nodes and self.ready(other, known):
                if i not in self.asm.guides:
                    raise TarsimError(f"the slot of {s.label} was not drawn by the assembly")
                out.append((("slot", other, i), self.asm.guide(i).direction))
        return list(dict.fromkeys(out))

    def rules(self, x: Node, known) -> list[tuple[str, tuple, float]]:
        """Every way to find x's tip, as (kind, args, quality), the crossing-free ones first."""
        whole, cross = [], []
        for c in self.carriers(x):
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
        pa, pb, px = (g.Point(*self.xy(n)) for n in (a, b, x))
        return abs(g.side_of(px, pa, pb)) <= _ON_LINE * g.distance(pa, pb) * g.distance(pa, px)

    # ----- the run ----------------------------------------------------------------
    def run(self) -> VelocityPolygon:
        self.c.give("vp:o_v", g.Point(*self.pole_xy), label="o_v", panel=Panel.VELOCITY,
                    sentence="Choose the velocity pole o_v: every vector drawn from it is an "
                             "absolute velocity.")
        self.steps.append("vp:o_v")
        self.draw_input()
        while True:
            todo = [n for n in self.nodes if n not in self.known and not self.zero(n)]
            if not todo:
                break
            best = None
            for n in todo:
                for rule in self.rules(n, self.known):
                    if best is None or rule[2] > best[1][2]:
                        best = (n, rule)
            if best is None:
                names = ", ".join(self.name(n) for n in todo)
                raise TarsimError(f"the velocity polygon cannot reach {names}: no link carrying "
                                  "it has two known velocities or a known direction")
            x, (kind, args, quality) = best
            self.known[x] = getattr(self, f"draw_{kind}")(x, *args)
        omegas = self.draw_results()
        tips = {n.point if n.link is None else self.name(n): self.tip(n) for n in self.nodes}
        aliases = {}
        for n in self.nodes:
            if n.link is None:
                for c in self.carriers(n):
                    alias = f"{n.point}{c}"
                    if c != 1 and alias not in tips:
                        aliases[alias] = n.point
        return VelocityPolygon("vp:o_v", self.scale, tips, omegas, self.steps,
                               self.space_steps, self.c, aliases)

    def act(self, ref: Ref, verb: str, *inputs: Ref, sentence: str, label: str = "",
            role: Role = Role.CONSTRUCTION, **params) -> Ref:
        self.c.draw(ref, verb, *inputs, label=label, sentence=sentence, role=role,
                    panel=Panel.VELOCITY, **params)
        self.steps.append(ref)
        return ref

    def space_line(self, k: Node, x: Node, c: int) -> Ref:
        """The space-diagram line KX of link c, drawn once."""
        ref = f"vp:line:{k.point}-{x.point}"
        if ref not in self.c:
            self.c.draw(ref, "line_through", self.asm.points[k.point], self.asm.points[x.point],
                        sentence=f"Draw line {k.point}{x.point} of link {c}.")
            self.space_steps.append(ref)
        return ref

    def draw_input(self) -> None:
        d = self.m.drive
        k = self.m.link(d.link)
        pivot, point = k.names[0], k.names[1]
        x = Node(point)
        r = k.span(pivot, point)
        X = self.name(x)
        perp = self.act(f"vp:{X}:perp", "perpendicular_through", "vp:o_v", self.asm.axes[d.link],
                        sentence=f"Through o_v draw a line ⟂ {pivot}{point} (the direction of "
                                 f"V_{X}).")
        sense = "ccw" if d.omega > 0 else "cw"
        self.known[x] = self.act(
            f"vp:tip:{X}", "lay_off", "vp:o_v", perp, length=d.omega * r * self.scale,
            label=X.lower(),
            sentence=f"From o_v lay off o_v {X.lower()} = V_{X} = ω{d.link}·{pivot}{point} = "
                     f"{abs(d.omega):.6g} rad/s × {self.m.units.length_text(r)} = "
                     f"{self.say(self.m.input_speed)} ⟂ {pivot}{point}, in the sense of "
                     f"ω{d.link} ({sense}).")

    # ----- the acts ---------------------------------------------------------------
    def draw_locus(self, x: Node, locus: tuple) -> tuple[Ref, str]:
        kind, X = locus[0], self.name(x)
        if kind == "rel":
            k, c = locus[1:]
            line = self.space_line(k, x, c)
            K, kx = self.name(k), f"{k.point}{x.point}"
            if self.zero(k):
                why = f"V_{X}, as {K} is fixed"
            else:
                why = f"V_{X}/{K}"
            ref = self.act(f"vp:{X}:perp@{K}", "perpendicular_through", self.tip(k), line,
                           sentence=f"Through {self.tip_label(k)} draw a line ⟂ {kx} (the "
                                    f"direction of {why}).")
            return ref, f"the line ⟂ {kx} through {self.tip_label(k)}"
        if kind in ("guide", "glide"):
            i = locus[1]
            why = (f"the guide of {X}" if kind == "guide" else
                   f"the guide of link {locus[2]}, which slides on it without turning")
            ref = self.act(f"vp:{X}:{kind}@{i}", "parallel_through", "vp:o_v", self.asm.guides[i],
                           sentence=f"Through o_v draw the parallel to {why} (the direction of "
                                    f"V_{X}).")
            return ref, "the parallel to the guide through o_v"
        other, i = locus[1:]
        O, j = self.name(other), self.m.slides[i].guide_link
        ref = self.act(f"vp:{X}:slot@{i}", "parallel_through", self.tip(other), self.asm.guides[i],
                       sentence=f"Through {self.tip_label(other)} draw the parallel to the slot "
                                f"of link {j} (the direction of V_{X}/{O}, the sliding "
                                "velocity).")
        return ref, f"the parallel to the slot through {self.tip_label(other)}"

    def draw_cross(self, x: Node, first: tuple, second: tuple) -> Ref:
        (l1, say1), (l2, say2) = (self.draw_locus(x, lo) for lo in (first, second))
        X = self.name(x)
        d = self.m.drive
        dead = (f"dead point at θ{d.link} = {math.degrees(d.angle):.6g}°: {say1} and {say2} "
                f"are parallel, so V_{X} and ω are undefined; move the input off it")
        try:
            tip = self.act(f"vp:tip:{X}", "intersect_lines", l1, l2, label=X.lower(),
                           sentence=f"The two lines meet at {X.lower()}: o_v {X.lower()} = V_{X}.")
        except DegenerateInput:
            raise AssemblyError(dead, joint=x.point,
                                angle_deg=math.degrees(d.angle)) from None
        step = self.c[tip]
        (a1, b1), (a2, b2) = (self.c.output(r).normal for r in (l1, l2))
        if step.output.is_at_infinity or abs(a1 * b2 - b1 * a2) < DEAD_POINT:
            raise AssemblyError(dead, joint=x.point, angle_deg=math.degrees(d.angle))
        return tip

    def draw_divide(self, x: Node, c: int, a: Node, b: Node) -> Ref:
        """X on line AB of link c: x divides ab as X divides AB (the velocity image)."""
        (ax, ay), (bx, by), (px, py) = self.xy(a), self.xy(b), self.xy(x)
        ratio = ((px - ax) * (bx - ax) + (py - ay) * (by - ay)) / ((bx - ax) ** 2 + (by - ay) ** 2)
        X = self.name(x)
        xl, al, bl = X.lower(), self.tip_label(a), self.tip_label(b)
        ta, tb = self.tip(a), self.tip(b)
        side = math.dist(self.c.output(ta).xy, self.c.output(tb).xy)
        why = (f"{x.point} lies on line {a.point}{b.point} of link {c}, so {xl} lies on "
               f"{al} {bl} with {al} {xl} : {al} {bl} = {a.point}{x.point} : "
               f"{a.point}{b.point} = {ratio:.6g} (the velocity image)")
        if side == 0.0:
            return self.act(f"vp:tip:{X}", "mark", ta, label=xl,
                            sentence=f"{why}; {al} {bl} has no length, so {xl} is at {al}.")
        return self.act(f"vp:tip:{X}", "lay_off", ta, tb, length=ratio * side, label=xl,
                        sentence=f"{why}: lay off {al} {xl} = {ratio:.6g} × {al} {bl} "
                                 f"along {al} {bl}.")

    def draw_translate(self, x: Node, c: int, k: Node) -> Ref:
        X, K = self.name(x), self.name(k)
        return self.act(f"vp:tip:{X}", "mark", self.tip(k), label=X.lower(),
                        sentence=f"Link {c} slides on a frame guide without turning, so V_{X} = "
                                 f"V_{K}: {X.lower()} is at {K.lower()}.")

    # ----- results ----------------------------------------------------------------
    def draw_results(self) -> dict[int, float]:
        """Draw V of every point from o_v, and read ω of every link off the polygon.

        A link pivoted on the frame reads ω from an absolute velocity (ω4 = V_B / O4B),
        whose sentence says so; any other from a relative one drawn between two tips.
        """
        omegas: dict[int, float] = {}
        said: dict[Node, list[str]] = {}
        relative = []
        later = []
        for k in self.m.links:
            c = k.number
            if c == 1:
                continue
            pair = self.omega_pair(c)
            if pair is None:
                later.append(c)
                continue
            p, q = pair if self.zero(pair[0]) or not self.zero(pair[1]) else pair[::-1]
            (px, py), (qx, qy) = self.xy(p), self.xy(q)
            (tpx, tpy), (tqx, tqy) = (self.c.output(self.tip(n)).xy for n in (p, q))
            rx, ry, vx, vy = qx - px, qy - py, (tqx - tpx) / self.scale, (tqy - tpy) / self.scale
            omega = (rx * vy - ry * vx) / (rx * rx + ry * ry)
            omegas[c] = omega
            P, Q = self.name(p), self.name(q)
            rel = f"V_{Q}" if self.zero(p) else f"V_{Q}/{P}"
            side = f"o_v {Q.lower()}" if self.zero(p) else f"{P.lower()} {Q.lower()}"
            sense = "ccw" if omega > 0 else "cw" if omega < 0 else "at rest"
            text = (f"ω{c} = {rel} / {p.point}{q.point} = {side} / {p.point}{q.point} = "
                    f"{self.say(math.hypot(vx, vy))} ÷ "
                    f"{self.m.units.length_text(math.hypot(rx, ry))} = {abs(omega):.6g} rad/s "
                    f"({sense}: the sense of {rel} about {p.point}).")
            if self.zero(p):
                said.setdefault(q, []).append(text)
            else:
                relative.append((c, p, q, rel, text))
        drive = Node(self.m.link(self.m.drive.link).names[1])
        for n in self.nodes:
            if self.zero(n):
                continue
            X = self.name(n)
            self.act(f"vp:V:{X}", "join", "vp:o_v", self.known[n], label=f"V_{X}",
                     role=Role.GIVEN if n == drive else Role.RESULT,
                     sentence=" ".join([f"o_v {X.lower()} = V_{X} = "
                                        f"{self.say(self.speed(self.known[n]))}."]
                                       + said.get(n, [])))
        for c, p, q, rel, text in relative:
            self.act(f"vp:omega:{c}", "join", self.tip(p), self.tip(q), label=rel,
                     role=Role.RESULT, sentence=f"{self.tip_label(p)} {self.tip_label(q)} is "
                                                f"{rel}. {text}")
        while later:  # one-point blocks turn with their guide, or not at all on the frame
            for c in later:
                s = next((s for s in self.m.slides if s.link == c and s.kind is SlideKind.BLOCK
                          and (s.guide_link == 1 or s.guide_link in omegas)), None)
                if s is not None:
                    omegas[c] = 0.0 if s.guide_link == 1 else omegas[s.guide_link]
                    later.remove(c)
                    break
            else:
                break
        return omegas

    def omega_pair(self, c: int) -> tuple[Node, Node] | None:
        nodes = [n for n in self.members(c) if n in self.known or self.zero(n)]
        pairs = [(a, b) for a, b in combinations(nodes, 2)
                 if not (self.zero(a) and self.zero(b)) and self.apart(a, b)]
        if not pairs:
            return None
        # The textbook's pair: a fixed pivot and the farthest point, else the two farthest.
        return max(pairs, key=lambda p: (self.zero(p[0]) or self.zero(p[1]),
                                         math.dist(self.xy(p[0]), self.xy(p[1]))))
