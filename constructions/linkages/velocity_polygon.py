"""The velocity polygon: the relative-velocity method of the lecture notes §2.8, step for step.

Every velocity is drawn from one pole ``o_v``; the tip of the velocity of point X
is the lower-case ``x``. Each tip is found where two lines that carry it meet:

* a point of a link with a known point K: ``V_X = V_K + V_X/K`` with V_X/K ⟂ KX,
  so the line through ``k`` ⟂ KX (through ``o_v`` when K is a frame pivot);
* a block or pin on a frame guide: the parallel to the guide through ``o_v``;
* coincident points on a slot of a moving link (the notes' A2 and A4):
  ``V_A4 = V_A2 + V_A4/A2`` with V_A4/A2 along the slot, so the parallel to the
  slot through ``a2``; in a slot curved about K the sliding velocity is along
  the slot's tangent, so the line ⟂ KA through ``a2`` (K is the centre of
  curvature, a point of the slotted link: the notes §2.11);
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

from .. import asks as A
from .assembly_record import Assembly
from ..checks import Answer, FigureSpec, vector_value
from .coincident import Node
from ..errors import TarsimError
from .polygon import VELOCITY, Polygon, sense_of
from .polygon_walk import DEAD_POINT, PolygonWalk
from ..narration import Number, Phrase, Quantity, Word, phrase
from ..record import Panel, Ref, Role
from ..scales import nice

__all__ = ["draw_velocity_polygon", "DEAD_POINT", "WORKED",
           "wants_polygon", "drawn_velocity_polygon", "answer"]


def draw_velocity_polygon(asm: Assembly, scale: float | None = None, *,
                          pole: tuple[float, float] = (0.0, 0.0)) -> Polygon:
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
    Polygon
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
        (a rolling wheel).

    See Also
    --------
    constructions.velocity_by_components.velocity_by_components : one velocity by components.

    Examples
    --------
    A parallelogram four-bar at θ2 = 90°: the coupler translates, so b = a.

    >>> import math
    >>> from tarsim.constructions.linkages.assembly import assemble
    >>> from tarsim.constructions.model import Drive, Link, Mechanism
    >>> m = Mechanism((Link(1, (("O2", (0, 0)), ("O4", (4, 0)))),
    ...                Link(2, (("O2", (0, 0)), ("A", (3, 0)))),
    ...                Link(3, (("A", (0, 0)), ("B", (4, 0)))),
    ...                Link(4, (("O4", (0, 0)), ("B", (3, 0))))),
    ...               Drive(2, math.pi / 2, omega=1.0), branches={"B": "left"})
    >>> vp = draw_velocity_polygon(assemble(m), scale=1.0)
    >>> tuple(round(v, 12) + 0.0 for v in vp.vector("B"))
    (-3.0, 0.0)
    >>> round(vp.rates[3], 12) + 0.0, round(vp.rates[4], 12) + 0.0
    (0.0, 1.0)
    """
    if scale is None:
        speed = asm.mechanism.input_speed
        scale = 1.0 if speed == 0.0 else nice(asm.size / (2.0 * speed), up=False)
    if not (isinstance(scale, (int, float)) and math.isfinite(scale) and scale > 0.0):
        raise TarsimError(f"the velocity scale must be a positive number, got {scale}")
    return _Polygon(asm, float(scale), pole).run()


class _Polygon(PolygonWalk):
    kind = VELOCITY

    def run(self) -> Polygon:
        self.walk()
        return self.polygon(self.draw_results())

    def say(self, v: float) -> Quantity:
        return self.m.units.speed_said(v)

    def draw_input(self) -> None:
        d = self.m.drive
        o, x, r = self.input_arm()
        pivot, point = self.name(o), x.point
        X = self.name(x)
        perp = self.act(f"vp:{X}:perp", "perpendicular_through", "vp:o_v", self.input_line(),
                        said=phrase("vpolygon.input_direction", pivot=pivot, p=point, point=X))
        sense = "ccw" if d.omega > 0 else "cw"
        self.known[x] = self.act(
            f"vp:tip:{X}", "lay_off", "vp:o_v", perp, length=d.omega * r * self.scale,
            label=X.lower(),
            said=phrase("vpolygon.input", tip=X.lower(), point=X, link=d.link, pivot=pivot,
                        p=point, omega=Number(abs(d.omega)),
                        radius=self.m.units.length_said(r), speed=self.say(self.m.input_speed),
                        sense=Word(sense)))

    def draw_locus(self, x: Node, locus: tuple) -> tuple[Ref, Phrase]:
        kind, X = locus[0], self.name(x)
        if kind == "rel":
            k, c = locus[1:]
            line = self.space_line(k, x, c)
            K, kx = self.name(k), f"{k.point}{x.point}"
            why = phrase("vpolygon.why_fixed" if self.zero(k) else "vpolygon.why_relative",
                         point=X, known=K)
            ref = self.act(f"vp:{X}:perp@{K}", "perpendicular_through", self.tip(k), line,
                           said=phrase("vpolygon.perpendicular", tip=self.tip_label(k), line=kx,
                                       why=why))
            return ref, phrase("polygon.say_perpendicular", line=kx, tip=self.tip_label(k))
        if kind in ("guide", "glide"):
            i = locus[1]
            why = (phrase("polygon.why_guide", point=X) if kind == "guide" else
                   phrase("polygon.why_glide", link=locus[2]))
            ref = self.act(f"vp:{X}:{kind}@{i}", "parallel_through", "vp:o_v", self.asm.guides[i],
                           said=phrase("vpolygon.parallel_guide", why=why, point=X))
            return ref, phrase("polygon.say_guide", pole="o_v")
        if kind == "curve":
            return self.draw_curve(x, *locus[1:])
        other, i = locus[1:]
        j = self.m.slides[i].guide_link
        ref = self.act(f"vp:{X}:slot@{i}", "parallel_through", self.tip(other), self.asm.guides[i],
                       said=phrase("vpolygon.slot", tip=self.tip_label(other), link=j, point=X,
                                   other=self.name(other)))
        return ref, phrase("polygon.say_slot", tip=self.tip_label(other))

    def draw_curve(self, x: Node, other: Node, i: int) -> tuple[Ref, Phrase]:
        """A pin in a curved slot about K slides along the slot's tangent, ⟂ KP."""
        a = self.m.pin_arcs[i]
        k, p = Node(a.centre), Node(a.point)
        line = self.space_line(k, p, a.guide_link)
        _, _, rel = self.curve_nodes(x, other)
        kp = f"{a.centre}{a.point}"
        X = self.name(x)
        ref = self.act(f"vp:{X}:curve@{i}", "perpendicular_through", self.tip(other), line,
                       said=phrase("vpolygon.curve", tip=self.tip_label(other), line=kp,
                                   point=a.point, centre=a.centre, rel=rel))
        return ref, phrase("polygon.say_perpendicular", line=kp, tip=self.tip_label(other))

    def draw_results(self) -> dict[int, float]:
        """Draw V of every point from o_v, and read ω of every link off the polygon.

        A link pivoted on the frame reads ω from an absolute velocity (ω4 = V_B / O4B),
        whose sentence says so; any other from a relative one drawn between two tips.
        """
        omegas: dict[int, float] = {}
        said: dict[Node, list[Phrase]] = {}
        relative = []
        later = []
        for k in self.m.links:
            c = k.number
            if c == 1:
                continue
            pair = self.read_pair(c)
            if pair is None:
                later.append(c)
                continue
            p, q = pair
            (px, py), (qx, qy) = self.xy(p), self.xy(q)
            (tpx, tpy), (tqx, tqy) = (self.c.output(self.tip(n)).xy for n in (p, q))
            rx, ry, vx, vy = qx - px, qy - py, (tqx - tpx) / self.scale, (tqy - tpy) / self.scale
            omega = (rx * vy - ry * vx) / (rx * rx + ry * ry)
            omegas[c] = omega
            self.spans[c] = math.hypot(rx, ry)
            self.reads[c] = (self.point_ref(p), self.point_ref(q), self.tip(p), self.tip(q),
                             self.scale)
            P, Q = self.name(p), self.name(q)
            rel = f"V_{Q}" if self.zero(p) else f"V_{Q}/{P}"
            side = f"o_v {Q.lower()}" if self.zero(p) else f"{P.lower()} {Q.lower()}"
            sense = sense_of(omega, abs(self.m.drive.omega))
            if sense == "at rest":
                omega = 0.0
            text = phrase("vpolygon.omega", link=c, rel=rel, line=f"{p.point}{q.point}",
                          side=side, speed=self.say(math.hypot(vx, vy)),
                          length=self.m.units.length_said(math.hypot(rx, ry)),
                          omega=Number(abs(omega)), sense=Word(sense), about=p.point)
            if self.zero(p):
                said.setdefault(q, []).append(text)
            else:
                relative.append((c, p, q, rel, text))
        drive = Node(self.m.link(self.m.drive.link).names[1])
        for n in self.nodes:
            if self.zero(n):
                continue
            X = self.name(n)
            then = said.get(n)
            self.act(f"vp:V:{X}", "join", "vp:o_v", self.known[n], label=f"V_{X}",
                     role=Role.GIVEN if n == drive else Role.RESULT,
                     said=phrase("vpolygon.vector", tip=X.lower(), point=X,
                                 speed=self.say(self.length(self.known[n])),
                                 then=phrase("then", sentences=tuple(then)) if then else None))
        for c, p, q, rel, text in relative:
            self.act(f"vp:omega:{c}", "join", self.tip(p), self.tip(q), label=rel,
                     role=Role.RESULT, said=phrase("vpolygon.relative", a=self.tip_label(p),
                                                   b=self.tip_label(q), rel=rel, omega=text))
        self.block_rates(omegas, later)
        return omegas


# ----- as a method of the registry -------------------------------------------------------------
WORKED = FigureSpec("worked", "Worked solution", "worked solution", kind="polygons")
"""The worked page: the space diagram, the polygons and the results table."""


def wants_polygon(work) -> bool:
    """True if the exercise draws the velocity polygon: chosen, or needed for what it asks."""
    return "polygon" in work.chosen or bool(work.asked(
        (A.Relative, A.AngularAcceleration, A.Acceleration, A.Coriolis)))


def drawn_velocity_polygon(work) -> Polygon:
    """The position's velocity polygon, drawn once."""
    return work.shared("velocity polygon", lambda: draw_velocity_polygon(work.assembly))


def answer(work, ask) -> Answer:
    """ω, V or a relative velocity read off the velocity polygon."""
    vp = drawn_velocity_polygon(work)
    m, c = work.mechanism, work.assembly
    link = None
    if isinstance(ask, A.AngularVelocity):
        w = vp.rates.get(ask.link)
        if w is None:
            raise TarsimError(f"{ask.name} could not be read off the polygon")
        value, refs, link = {"value": w}, tuple(vp.tips_on(ask.link, m)) or (vp.pole,), ask.link
    elif isinstance(ask, A.Relative):
        ref = vp.draw_relative(ask.point, ask.of, m.units)
        value, refs = vector_value(*vp.between(*c[ref].inputs)), (ref,)
    else:
        value, refs = vector_value(*vp.vector(ask.point)), (vp.tip(ask.point),)
    return Answer(ask, value, vp.conditioning(value, work.scale_of(ask), link),
                  "velocity polygon", refs=refs, arrows=tuple(vp.steps),
                  figures=(WORKED,), panel=Panel.VELOCITY)
