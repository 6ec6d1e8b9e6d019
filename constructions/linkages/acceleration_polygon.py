"""The acceleration polygon: relative accelerations and Coriolis, the lecture notes §2.10–2.11.

Every acceleration is drawn from one pole ``o_a``; the tip of A_X is ``x′``. The
polygon walks the mechanism as the velocity polygon did, and takes from it every
ω and every relative velocity, so each known component is drawn before the
unknown one:

* a point X of link c with a known point K: ``A_X = A_K + Aⁿ_X/K + Aᵗ_X/K``.
  From k′ lay off the normal component ω_c²·KX parallel to XK, pointing from X
  toward K; through its end draw the tangential component's line ⟂ KX, of
  unknown length.
* a block or pin on a frame guide (or any point of a link that slides on it
  without turning): the parallel to the guide through ``o_a``.
* coincident points on a slot of a moving link j (the notes' A2 and A4):
  ``A_A2 = A_A4 + Aᶜ + Aˢ``. From a4′ lay off the Coriolis component
  2ω_j·v_rel, its direction v_rel = V_A2/A4 turned 90° the way ω_j turns; through
  its end draw the parallel to the slot, the sliding acceleration of unknown
  length.

Two lines cross at the tip; images and translating links follow as in the
velocity polygon. α of each link is read off a tangential component,
α = Aᵗ_X/K / KX with the sense of Aᵗ_X/K about K.
"""

from __future__ import annotations

import math

from .. import asks as A
from .acceleration_slots import draw_curve, draw_slot
from .assembly_record import Assembly
from ..checks import Answer, vector_value
from .coincident import Node
from ..errors import TarsimError
from .joint_rules import rules_of
from ..narration import Number, Phrase, Quantity, Word, phrase
from .polygon import ACCELERATION, NOISE, Polygon, sense_of
from .polygon_readings import relative_normal
from .polygon_walk import PolygonWalk
from ..record import Derived, Panel, Ref, Role
from ..scales import nice
from .velocity_polygon import WORKED, drawn_velocity_polygon

__all__ = ["draw_acceleration_polygon", "drawn_acceleration_polygon",
           "answer"]


def draw_acceleration_polygon(asm: Assembly, vp: Polygon, scale: float | None = None, *,
                              pole: tuple[float, float] = (0.0, 0.0)) -> Polygon:
    """Draw the acceleration polygon of ``asm`` from its velocity polygon ``vp``.

    Parameters
    ----------
    asm : Assembly
        The mechanism drawn at one position, with the drive's ω and α (α is 0
        unless the file gives it).
    vp : Polygon
        The velocity polygon drawn on the same construction: it gives every ω and
        every sliding velocity.
    scale : float, optional
        Drawing metres per m/s². By default a 1, 2 or 5 × 10^k that makes the input
        pin's acceleration about half the mechanism's size.
    pole : (float, float)
        Where ``o_a`` stands in the acceleration panel (drawing metres).

    Returns
    -------
    Polygon

    Raises
    ------
    AssemblyError
        At a dead point (the two lines of a tip are parallel).
    TarsimError
        If the scale is not a positive number, a polygon is already drawn on this
        construction, or ``vp`` belongs to another construction.

    Examples
    --------
    A crank turning at a steady 2 rad/s: A_A is ω²·O2A = 12 toward O2.

    >>> import math
    >>> from tarsim.constructions.linkages.assembly import assemble
    >>> from tarsim.constructions.joints import Slide, SlideKind
    >>> from tarsim.constructions.model import Drive, Link, Mechanism
    >>> from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
    >>> m = Mechanism((Link(1, (("O2", (0, 0)),)), Link(2, (("O2", (0, 0)), ("A", (3, 0)))),
    ...                Link(3, (("A", (0, 0)), ("B", (8, 0)))), Link(4, (("B", (0, 0)),))),
    ...               Drive(2, math.pi / 2, omega=2.0),
    ...               (Slide(SlideKind.BLOCK, 4, "B", 1, (0, 0), (1, 0)),),
    ...               branches={"B": "forward"})
    >>> asm = assemble(m)
    >>> ap = draw_acceleration_polygon(asm, draw_velocity_polygon(asm, 1.0), 1.0)
    >>> tuple(round(v, 12) + 0.0 for v in ap.vector("A"))
    (0.0, -12.0)
    """
    if vp.construction is not asm:
        raise TarsimError("the velocity polygon belongs to another construction; draw both "
                          "on one assembly")
    if scale is None:
        accel = asm.mechanism.input_acceleration
        scale = 1.0 if accel == 0.0 else nice(asm.size / (2.0 * accel), up=False)
    if not (isinstance(scale, (int, float)) and math.isfinite(scale) and scale > 0.0):
        raise TarsimError(f"the acceleration scale must be a positive number, got {scale}")
    return _Polygon(asm, vp, float(scale), pole).run()


class _Polygon(PolygonWalk):
    kind = ACCELERATION

    def __init__(self, asm: Assembly, vp: Polygon, scale: float,
                 pole: tuple[float, float]):
        super().__init__(asm, scale, pole)
        self.vp = vp
        self.omegas = vp.rates
        self.normals: dict[tuple[Node, int], list[tuple[Node, Ref]]] = {}
        self.coriolis: dict[str, tuple[Ref, Ref, float]] = {}
        self.components: dict[str, Ref] = {}
        self.slides_drawn: list[tuple[Node, Node, Ref, float, str]] = []

    def run(self) -> Polygon:
        self.walk()
        return self.polygon(self.draw_results(), coriolis=self.coriolis,
                            components=self.components)

    def say(self, a: float) -> Quantity:
        """An acceleration as a step says it; rounding noise beside the input's own
        acceleration (a ram at rest in its stroke reads 1e-14 mm/s²) is said as 0."""
        floor = NOISE * self.m.input_acceleration
        return self.m.units.acceleration_said(0.0 if abs(a) <= floor else a)

    def velocity(self, n: Node) -> tuple[float, float]:
        return (0.0, 0.0) if self.zero(n) else self.vp.vector(self.name(n))

    def component(self, ref: Ref, start: Ref, end: Ref, label: str) -> None:
        """Draw a known or found component as an arrow (no sentence: the act before it said it)."""
        if math.dist(self.c.output(start).xy, self.c.output(end).xy) > 0.0:
            self.c.draw(ref, "join", start, end, label=label, panel=self.kind.panel, phrase=None)
            self.steps.append(ref)
            self.components[label] = ref

    # ----- the input ----------------------------------------------------------------
    def draw_input(self) -> None:
        d = self.m.drive
        o, x, r = self.input_arm()
        pivot, point = self.name(o), x.point
        X = self.name(x)
        line = self.space_line(o, x, d.link)
        radius = self.m.units.length_said(r)
        if self.m.rolling_input is not None:
            self.known[x] = self.draw_wheel_input(o, x, line, r)
            for n, (_, s) in self.rolls.items():
                self.known[n] = self.draw_rolling(n, s)
            return
        normal = self.act(
            f"ap:{X}:n", "lay_off", self.pole_ref, line, length=-d.omega ** 2 * r * self.scale,
            said=phrase("apolygon.input_normal", point=X, link=d.link, pivot=pivot, p=point,
                        omega=Number(abs(d.omega)), radius=radius,
                        accel=self.say(d.omega ** 2 * r)))
        self.component(f"ap:{X}:n:vec", self.pole_ref, normal, f"Aⁿ_{X}")
        given = phrase("apolygon.given" if d.alpha_given else "apolygon.not_given")
        if d.alpha == 0.0:
            tip = self.act(f"ap:tip:{X}", "mark", normal, label=self.tip_name(X),
                           said=phrase("apolygon.input_no_tangential", link=d.link, given=given,
                                       point=X, pivot=pivot, p=point, tip=self.tip_name(X)))
        else:
            perp = self.act(f"ap:{X}:t:perp", "perpendicular_through", normal, line,
                            said=phrase("apolygon.tangential_direction", pivot=pivot, p=point,
                                        point=X))
            sense = "ccw" if d.alpha > 0 else "cw"
            tip = self.act(
                f"ap:tip:{X}", "lay_off", normal, perp, length=d.alpha * r * self.scale,
                label=self.tip_name(X),
                said=phrase("apolygon.input_tangential", point=X, link=d.link, pivot=pivot,
                            p=point, alpha=Number(abs(d.alpha)), radius=radius,
                            accel=self.say(abs(d.alpha) * r), sense=Word(sense),
                            tip=self.tip_name(X)))
            self.component(f"ap:{X}:t:vec", normal, tip, f"Aᵗ_{X}")
        self.known[x] = tip
        for n, (_, s) in self.rolls.items():
            self.known[n] = self.draw_rolling(n, s)

    def draw_wheel_input(self, o: Node, x: Node, line: Ref, r: float) -> Ref:
        """The centre of the input wheel, rolling on a straight face, runs along it: its
        acceleration is α·r along the face, with nothing across it (a = α r)."""
        d = self.m.drive
        X, tip = self.name(x), self.tip_name(self.name(x))
        given = phrase("apolygon.given" if d.alpha_given else "apolygon.not_given")
        if d.alpha == 0.0:
            return self.act(f"ap:tip:{X}", "mark", self.pole_ref, label=tip,
                            said=phrase("apolygon.wheel_centre_still", link=d.link,
                                        given=given, point=X, tip=tip))
        perp = self.act(f"ap:{X}:t:perp", "perpendicular_through", self.pole_ref, line,
                        said=phrase("apolygon.wheel_centre_path", point=X, link=d.link,
                                    contact=self.name(o)))
        return self.act(
            f"ap:tip:{X}", "lay_off", self.pole_ref, perp, length=d.alpha * r * self.scale,
            label=tip, said=phrase("apolygon.wheel_centre", point=X, link=d.link,
                                   alpha=Number(abs(d.alpha)),
                                   radius=self.m.units.length_said(r),
                                   accel=self.say(abs(d.alpha) * r),
                                   sense=Word("ccw" if d.alpha > 0 else "cw"), tip=tip))

    def draw_rolling(self, n: Node, s) -> Ref:
        """The contact point of a wheel rolling on the ground: at rest, its acceleration is
        toward the wheel's centre, as the wheel's kind of contact gives it
        (:mod:`.polygon_joints`)."""
        P = self.name(n)
        line = self.space_line(n, Node(s.point), s.link)
        accel, said = rules_of(s).rolling(self, n, s)
        return self.act(f"ap:tip:{P}", "lay_off", self.pole_ref, line,
                        length=accel * self.scale, label=self.tip_name(P), said=said)

    # ----- the lines that carry a tip ---------------------------------------------
    def draw_locus(self, x: Node, locus: tuple) -> tuple[Ref, Phrase]:
        kind, X = locus[0], self.name(x)
        if kind == "rel":
            return self.draw_relative(x, *locus[1:])
        if kind in ("guide", "glide"):
            i = locus[1]
            why = (phrase("polygon.why_guide", point=X) if kind == "guide" else
                   phrase("polygon.why_glide", link=locus[2]))
            ref = self.act(f"ap:{X}:{kind}@{i}", "parallel_through", self.pole_ref,
                           self.asm.guides[i],
                           said=phrase("apolygon.parallel_guide", why=why, point=X))
            return ref, phrase("polygon.say_guide", pole="o_a")
        if kind == "curve":
            return draw_curve(self, x, *locus[1:])
        return draw_slot(self, x, *locus[1:])

    def draw_relative(self, x: Node, k: Node, c: int) -> tuple[Ref, Phrase]:
        """Aⁿ_X/K laid off from k′ toward K, then the line of Aᵗ_X/K ⟂ KX through it."""
        line = self.space_line(k, x, c)
        X, K = self.name(x), self.name(k)
        kx, xk = f"{k.point}{x.point}", f"{x.point}{k.point}"
        rel = X if self.zero(k) else f"{X}/{K}"
        w = self.omegas.get(c)
        if w is None:
            raise TarsimError(f"the velocity polygon gave no ω of link {c}, which A_{X} needs")
        r = math.dist(self.xy(k), self.xy(x))
        start = self.tip(k)
        if w == 0.0:
            ref = self.act(f"ap:{X}:t@{K}", "perpendicular_through", start, line,
                           said=phrase("apolygon.no_normal", link=c, rel=rel,
                                       tip=self.tip_label(k), line=kx))
            self.normals.setdefault((x, c), []).append((k, start))
            return ref, phrase("polygon.say_perpendicular", line=kx, tip=self.tip_label(k))
        end = self.act(
            f"ap:{X}:n@{K}", "lay_off", start, line, length=-w * w * r * self.scale,
            derived=Derived(relative_normal, (self.vp.reads.get(c, ()), self.point_ref(k),
                                              self.point_ref(x), self.scale)),
            said=phrase("apolygon.normal", tip=self.tip_label(k), rel=rel, link=c, line=kx,
                        omega=Number(abs(w)), length=self.m.units.length_said(r),
                        accel=self.say(w * w * r), back=xk, x=x.point, k=k.point))
        self.component(f"ap:{X}:n@{K}:vec", start, end, f"Aⁿ_{rel}")
        ref = self.act(f"ap:{X}:t@{K}", "perpendicular_through", end, line,
                       said=phrase("apolygon.tangential_line", line=kx, rel=rel))
        self.normals.setdefault((x, c), []).append((k, end))
        return ref, phrase("apolygon.say_tangential", line=kx, rel=rel)

    # ----- results ----------------------------------------------------------------
    def draw_results(self) -> dict[int, float]:
        """Draw A of every point from o_a and the found components; read α of every link.

        α of a link comes from a tangential component where one was drawn on it
        (α4 = Aᵗ_B / O4B), else from the relative acceleration of its two points
        (its part ⟂ the line joining them).
        """
        alphas: dict[int, float] = {}
        said: dict[Node, list[Phrase]] = {}
        later = []
        for (x, _), ends in self.normals.items():
            for k, end in ends:
                rel = self.name(x) if self.zero(k) else f"{self.name(x)}/{self.name(k)}"
                self.component(f"ap:{self.name(x)}:t@{self.name(k)}:vec", end, self.known[x],
                               f"Aᵗ_{rel}")
        for s_, c_, end, sign, label in self.slides_drawn:
            tip = self.known[s_] if sign > 0 else self.known[c_]
            self.component(f"ap:{self.name(s_)}:slide:vec", end, tip,
                           label if sign > 0 else f"−{label}")
        d = self.m.drive
        alphas[d.link] = d.alpha        # given (or taken as 0), not read back
        for k in self.m.links:
            c = k.number
            if c in (1, d.link):
                continue
            found = self.alpha_from_tangent(c)
            if found is None:
                pair = self.read_pair(c)
                if pair is None:
                    later.append(c)
                    continue
                found = self.alpha_from_pair(c, *pair)
            alpha, node, text = found
            alphas[c] = alpha
            said.setdefault(node, []).append(text)
        self.block_rates(alphas, later)
        drive = Node(self.m.link(self.m.drive.link).names[1])
        for n in self.nodes:
            if self.zero(n):
                continue
            X = self.name(n)
            then = said.get(n)
            self.act(f"ap:A:{X}", "join", self.pole_ref, self.known[n], label=f"A_{X}",
                     role=Role.GIVEN if n == drive else Role.RESULT,
                     said=phrase("apolygon.vector", tip=self.tip_name(X), point=X,
                                 accel=self.say(self.length(self.known[n])),
                                 then=phrase("then", sentences=tuple(then)) if then else None))
        return alphas

    def alpha_from_tangent(self, c: int) -> tuple[float, Node, str] | None:
        """α_c = Aᵗ_X/K / KX from the tangential component on link c, with its sense about K."""
        best = None
        for (x, cc), ends in self.normals.items():
            if cc != c:
                continue
            for k, end in ends:
                r = math.dist(self.xy(k), self.xy(x))
                key = (self.zero(k), r)
                if best is None or key > best[0]:
                    best = (key, x, k, end)
        if best is None:
            return None
        _, x, k, end = best
        (kx, ky), (xx, xy) = self.xy(k), self.xy(x)
        rx, ry = xx - kx, xy - ky
        ax, ay = self.vector(end, self.known[x])
        alpha = (rx * ay - ry * ax) / (rx * rx + ry * ry)
        self.spans[c] = math.hypot(rx, ry)
        rel = self.name(x) if self.zero(k) else f"{self.name(x)}/{self.name(k)}"
        return alpha, x, self.alpha_text(c, phrase("apolygon.what_tangential", rel=rel), k, x,
                                         math.hypot(ax, ay), alpha)

    def alpha_from_pair(self, c: int, p: Node, q: Node) -> tuple[float, Node, str]:
        (px, py), (qx, qy) = self.xy(p), self.xy(q)
        rx, ry = qx - px, qy - py
        ax, ay = self.vector(self.tip(p), self.tip(q))
        alpha = (rx * ay - ry * ax) / (rx * rx + ry * ry)
        r = self.spans[c] = math.hypot(rx, ry)
        rel = self.name(q) if self.zero(p) else f"{self.name(q)}/{self.name(p)}"
        return alpha, q, self.alpha_text(c, phrase("apolygon.what_part", rel=rel,
                                                   line=f"{p.point}{q.point}"), p, q,
                                         abs(alpha) * r, alpha)

    def alpha_text(self, c: int, what: Phrase, k: Node, x: Node, tangent: float,
                   alpha: float) -> Phrase:
        r = math.dist(self.xy(k), self.xy(x))
        sense = sense_of(alpha, math.hypot(self.m.drive.omega ** 2, self.m.drive.alpha))
        if sense == "at rest":          # rounding noise, said as none (not as 1e-17 rad/s²)
            sense, alpha = "no angular acceleration", 0.0
        return phrase("apolygon.alpha", link=c, what=what, line=f"{k.point}{x.point}",
                      accel=self.say(tangent), length=self.m.units.length_said(r),
                      alpha=Number(abs(alpha)), sense=Word(sense), about=k.point)


# ----- as a method of the registry -------------------------------------------------------------
def drawn_acceleration_polygon(work) -> Polygon:
    """The position's acceleration polygon, drawn once on its velocity polygon; an α of the
    input not given is noted as taken as 0."""
    def make() -> Polygon:
        d = work.mechanism.drive
        if not d.alpha_given:
            work.note(phrase("note.alpha_not_given", link=d.link), Panel.ACCELERATION)
        return draw_acceleration_polygon(work.assembly, drawn_velocity_polygon(work))
    return work.shared("acceleration polygon", make)


def answer(work, ask) -> Answer:
    """α, A, a relative acceleration or a Coriolis component read off the acceleration polygon.

    Every tip of the velocity polygon is part of the answer: the acceleration polygon
    takes each ω and sliding velocity from it.
    """
    ap = drawn_acceleration_polygon(work)
    velocities = tuple(drawn_velocity_polygon(work).tips.values())
    m, c = work.mechanism, work.assembly
    arrows = tuple(drawn_velocity_polygon(work).steps) + tuple(ap.steps)
    if isinstance(ask, A.AngularAcceleration):
        a = ap.rates.get(ask.link)
        if a is None:
            raise TarsimError(f"{ask.name} could not be read off the polygon")
        value, refs = {"value": a}, tuple(ap.tips_on(ask.link, m))
        method = "acceleration polygon"
    elif isinstance(ask, A.Relative):
        ref = ap.draw_relative(ask.point, ask.of, m.units)
        value = vector_value(*ap.between(*c[ref].inputs))
        refs, method = (ref,), "acceleration polygon"
    elif isinstance(ask, A.Coriolis):
        end = ap.coriolis[ask.point][1]
        value, refs = vector_value(*ap.coriolis_of(ask.point)), (end,)
        method = "acceleration polygon (2ω×v_rel)"
    else:
        tip = ap.tip(ask.point)
        value, refs = vector_value(*ap.vector(ask.point)), (tip,)
        method = "acceleration polygon"
    # The walk takes ω and sliding speeds from the velocity polygon, and hands α from tip to
    # tip, as numbers: every reading inherits the worst of both polygons, compounded (near a
    # toggle each polygon divides by the same small sine, so an acceleration by its square).
    link = ask.link if isinstance(ask, A.AngularAcceleration) else None
    cond = ap.conditioning(value, work.scale_of(ask), link) * drawn_velocity_polygon(work).worst()
    return Answer(ask, value, cond, method, refs=refs + velocities, arrows=arrows,
                  figures=(WORKED,), panel=Panel.ACCELERATION)
