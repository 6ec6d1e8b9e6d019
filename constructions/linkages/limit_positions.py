"""The limit positions of a crank-driven mechanism: its time ratio and its stroke.

The output reverses where the dyad driven by the crank stops turning the output
link, and the notes (000-part2 §2.2) draw those two positions by compass:

* a **slider-crank** or **crank-rocker**: crank and rod in line, extended (the
  rod's far end on an arc of radius AB + O2A about O2) and folded (AB − O2A);
* a **crank and slotted lever**: the lever tangent to the crank circle, where
  O2A ⟂ O4A; A is cut from the crank circle by the circle on O2O4 as diameter;
* a **Whitworth quick return** (the crank longer than O2O4, the lever turning right
  round): the lever and the rod it drives to the ram in line (:mod:`.limit_whitworth`).

The rest of the chain is then carried to each limit: a point of the lever or
rocker swings with it about its pivot, a ram pin in the lever's slot lies where
the lever's line cuts the ram's guide, and a rod's far end is cut from its guide
by an arc. The crank angles between the two limit positions give the time ratio
(slow stroke over quick stroke, at constant crank speed), the two places of the
output point give the stroke. Every act is recorded in the assembly's
construction, so the figure draws it and steps.md narrates it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .. import asks as A
from .assembly import assemble
from .assembly_record import Assembly, point_ref
from .limit_swing import SWING_WHY_NOT, swing_answer
from .limit_whitworth import secondary_rod, whitworth_pins
from ..checks import Answer, FigureSpec, time_ratio_value
from ..errors import InputError, NoIntersection, TarsimError
from ..model import Mechanism
from ..measures import measure_angle
from ..narration import Number, Phrase, Word, narrate, phrase
from ..record import Ref, Role

__all__ = ["LimitPositions", "draw_limit_positions", "limit_kind", "stroke_point",
           "drawn_limits", "answer", "askable", "WHY_NOT", "LIMITS"]

_PRIMES = ("′", "″")


@dataclass
class LimitPositions:
    """The two limit positions as drawn on the mechanism at its stated position."""

    assembly: Assembly
    """The mechanism at its stated position; its construction holds the steps below."""
    steps: list[Ref]
    kind: str
    """"slider-crank", "crank-rocker", "slotted lever" or "whitworth"."""
    crank_angles: tuple[float, float]
    """θ of the crank (rad) at the first and second limit, A′ and A″."""
    slow: float
    """Crank angle (rad) turned in the slow stroke, in the sense of ω."""
    quick: float
    point: str | None
    """The point whose stroke is measured (a block on a frame guide), if any."""
    stroke: float | None
    """|P′P″| in metres."""
    stroke_ref: Ref | None
    slow_from: int
    """Which limit (0 for ′, 1 for ″) the slow stroke starts from, turning with ω."""
    conditioning: float
    output: int | None = None
    """The lever or rocker the crank's dyad swings (None for a slider-crank)."""
    pivot: str | None = None
    """The lever's or rocker's frame pivot."""
    held: tuple[Ref, Ref] | None = None
    """Its point at each limit, which sets it there (None where it does not swing)."""

    @property
    def time_ratio(self) -> float:
        """Slow stroke over quick stroke: their crank angles at constant speed."""
        return self.slow / self.quick


def limit_kind(mech: Mechanism) -> str | None:
    """Which limit construction applies to ``mech``, or None if none does.

    The crank is the input; the dyad at its pin decides: a rod to a block on a
    frame guide (slider-crank), a rod to a rocker about a frame pivot
    (crank-rocker), or a block or pin in the slot of a lever about a frame pivot
    (slotted lever).
    """
    try:
        return _Dyad(mech).kind
    except InputError:
        return None


def stroke_point(mech: Mechanism) -> str | None:
    """The point whose stroke the limit positions measure: the last block on a frame guide."""
    on_frame = [s.point for s in mech.slides if s.guide_link == 1 and s.type.key == "block"]
    return on_frame[-1] if on_frame else None


def draw_limit_positions(drawn: Mechanism | Assembly) -> LimitPositions:
    """Draw both limit positions on the mechanism as drawn at its stated position (see the
    module); a mechanism not yet drawn is assembled first.

    Raises
    ------
    InputError
        If the crank's dyad is none of the three kinds, or the crank cannot turn
        fully (no limit positions for it to pass).
    TarsimError
        If an arc misses its line (the mechanism cannot reach a limit position).
    """
    return _Limits(drawn if isinstance(drawn, Assembly) else assemble(drawn)).run()


class _Dyad:
    """The crank and the dyad at its pin, read off the mechanism."""

    def __init__(self, mech: Mechanism):
        self.m = mech
        d = mech.drive.link
        crank = mech.link(d)
        if mech.rolling_input is not None:
            raise InputError(f"the input link {d} is a wheel rolling on the frame, not a crank "
                             "about a frame pivot: each turn carries it along, so the linkage "
                             "never comes back to a limit position")
        if len(crank.names) < 2:
            raise InputError(f"the input link {d} carries no pin to drive a dyad")
        self.crank, self.o2, self.a = d, crank.names[0], crank.names[1]
        self.r = crank.span(self.o2, self.a)
        lever = [s for s in mech.slides if s.point == self.a and s.guide_link != 1
                 and not s.type.contact and _pivot(mech, s.guide_link)]
        rods = [(k, b) for k in mech.links_at(self.a) if k not in (1, d)
                for b in mech.link(k).names if b != self.a]        # a rod may carry more
        if lever:
            self.kind, self.out = "slotted lever", lever[0].guide_link
            self.o4 = _pivot(mech, self.out)
            k, s = mech.link(self.out), lever[0]
            px, py = k.local(self.o4)
            (tx, ty), (dx, dy) = s.through, s.direction
            reach = max(1e-300, math.hypot(px, py), self.r)
            if abs(dx * (py - ty) - dy * (px - tx)) > 1e-9 * reach:
                raise InputError(f"the slot of link {self.out} does not run through its pivot "
                                 f"{self.o4}; the lever's limit positions are drawn for a slot "
                                 "through the pivot")
            centres = math.dist(mech.link(1).local(self.o2), mech.link(1).local(self.o4))
            if self.r >= centres:
                self.rod2 = secondary_rod(mech, self.out, self.o4, self.a)
                if self.rod2 is None:
                    raise InputError(
                        f"the crank {self.o2}{self.a} is no shorter than {self.o2}{self.o4}, so "
                        "the lever turns a full revolution with it (a Whitworth quick return): "
                        "it has no limit positions of its own, and no rod from it drives a "
                        "block on a frame guide")
                self.kind = "whitworth"
            return
        for k, b in rods:
            self.rod, self.b, self.rod_length = k, b, mech.link(k).span(self.a, b)
            guide = [i for i, s in enumerate(mech.slides) if s.point == b and s.guide_link == 1
                     and s.type.key == "block"]
            rocker = [n for n in mech.links_at(b) if n not in (1, k) and _pivot(mech, n)]
            if guide:
                self.kind, self.guide = "slider-crank", guide[0]
                return
            if rocker:
                self.kind, self.out = "crank-rocker", rocker[0]
                self.o4 = _pivot(mech, self.out)
                return
        raise InputError(
            "the time ratio and stroke are drawn for a slider-crank, a crank-rocker or a "
            f"crank and slotted lever; the dyad at the crank's pin {self.a} is none of these")


def _pivot(mech: Mechanism, number: int) -> str | None:
    """The frame point link ``number`` turns about, if it is pinned to the frame."""
    if number == 1:
        return None
    return next((n for n in mech.link(number).names if 1 in mech.links_at(n)), None)


class _Limits(_Dyad):
    def __init__(self, asm: Assembly):
        super().__init__(asm.mechanism)
        self.asm = asm
        self.c = self.asm
        self.steps: list[Ref] = []
        self.cond = 1.0
        self.cancel = 1.0

    def L(self, metres: float) -> str:
        """A length as an error message writes it."""
        return self.m.units.length_brief(metres)

    def length(self, metres: float):
        """A length as a step says it."""
        return self.m.units.length_said(metres)

    def P(self, name: str) -> Ref:
        return point_ref(name)

    def act(self, ref: str, verb: str, *inputs: Ref, label: str = "", said: Phrase | None = None,
            result: bool = False, **params) -> Ref:
        """Record one act."""
        self.c.draw(f"limit:{ref}", verb, *inputs, label=label, phrase=said,
                    role=Role.RESULT if result else Role.CONSTRUCTION, **params)
        self.steps.append(f"limit:{ref}")
        self.cond = min(self.cond, self.c[f"limit:{ref}"].conditioning)
        return f"limit:{ref}"

    def xy(self, ref: Ref) -> tuple[float, float]:
        return self.c.output(ref).xy

    # A dyad keeps its assembly round the revolution: its far end never crosses the line of
    # its two centres (that would be a dead point, which a turning crank does not meet). So
    # each cut at a limit takes the side the drawn position shows, whatever angle it is
    # drawn at, rather than the cut nearer the drawn point.
    def side(self, point: str, a: str, b: str) -> str:
        """"left" or "right": the side of ``a`` → ``b`` that ``point`` is drawn on."""
        (ax, ay), (bx, by), (px, py) = (self.asm.xy(n) for n in (a, b, point))
        return "left" if (bx - ax) * (py - ay) - (by - ay) * (px - ax) > 0.0 else "right"

    def along(self, point: str, base: str, guide: Ref) -> str:
        """"forward" or "backward": where ``point`` is drawn from ``base`` along ``guide``."""
        tx, ty = self.c.output(guide).direction
        (bx, by), (px, py) = self.asm.xy(base), self.asm.xy(point)
        return "forward" if (px - bx) * tx + (py - by) * ty > 0.0 else "backward"

    # ----- the run ------------------------------------------------------------------------
    def run(self) -> LimitPositions:
        rams = None
        if self.kind == "slotted lever":
            pins = self.tangent_lever()
        elif self.kind == "whitworth":
            pins, rams = whitworth_pins(self)
        else:
            pins = self.rod_in_line()
        angles = tuple(math.atan2(*_sub(self.xy(p), self.xy(self.P(self.o2)))[::-1]) for p in pins)
        slow_from, slow, quick = self.crank_angles(pins)
        point, stroke, stroke_ref = self.carry_output(rams)
        swings = self.kind in ("crank-rocker", "slotted lever")
        return LimitPositions(self.asm, self.steps, self.kind, angles, slow, quick, point,
                              stroke, stroke_ref, slow_from, self.cond * self.cancel,
                              None if self.kind == "slider-crank" else self.out,
                              self.o4 if swings else None,
                              (f"limit:{self.held}0", f"limit:{self.held}1") if swings else None)

    def crank_angles(self, pins: tuple[Ref, Ref]) -> tuple[int, float, float]:
        """Measure at O2 the two angles the crank turns, with ω, between its limit positions.

        Returns the limit (0 for ′, 1 for ″) the slow stroke starts from, and the slow
        and quick angles (rad).
        """
        o2, d = self.o2, self.m.drive
        names = [self.c[p].label for p in pins]
        if self.kind in ("slotted lever", "whitworth"):
            for i, pin in enumerate(pins):
                self.act(f"crank{i}", "line_through", self.P(o2), pin, label=f"{o2}{names[i]}",
                         said=(phrase("limits.join_cranks", pivot=o2, a=names[0], b=names[1])
                               if i == 0 else None))
        sense = 1.0 if d.omega >= 0 else -1.0
        centre, *ends = (self.c.output(p) for p in (self.P(o2), *pins))

        def turned(a: int) -> float:
            return measure_angle(centre, ends[a], ends[1 - a], turn=sense)[0].degrees

        slow_from = 0 if turned(0) >= 180.0 else 1
        way = "ccw" if sense > 0 else "cw"
        out = []
        for stroke, a in (("slow", slow_from), ("quick", 1 - slow_from)):
            b = 1 - a
            ref = self.act(stroke, "measure_angle", self.P(o2), pins[a], pins[b], turn=sense,
                           label=stroke, result=True,
                           said=phrase("limits.measure", a=names[a], pivot=o2, b=names[b],
                                       sense=Word(way), link=d.link,
                                       degrees=Number(turned(a), ".2f"), stroke=Word(stroke)))
            out.append(abs(self.c.output(ref).sweep))
        return slow_from, out[0], out[1]

    def rod_in_line(self) -> tuple[Ref, Ref]:
        """Crank and rod in line: B on arcs of AB ± O2A about O2, A on the line O2B."""
        o2, a, b = self.o2, self.a, self.b
        r, rod = self.r, self.rod_length
        if rod <= r:
            raise InputError(f"the rod {a}{b} (link {self.rod}, {self.L(rod)}) is not longer "
                             f"than the crank {o2}{a} (link {self.m.drive.link}, {self.L(r)}): "
                             "the crank cannot turn fully")
        # The folded radius AB − O2A carries the rounding of both lengths: relative to itself
        # it is (AB + O2A) / (AB − O2A) times as uncertain, which a rod barely longer than
        # its crank makes large.
        # Its error then passes through the cut of that arc with B's path, so the two
        # compound: a product, not the lesser.
        self.cancel = (rod - r) / (rod + r)
        pins = []
        for i, (length, how) in enumerate(((rod + r, "extended"), (rod - r, "folded"))):
            mark = _PRIMES[i]
            span = f"{a}{b} {'+' if i == 0 else '−'} {o2}{a}"
            spoken = phrase("limits.span_sum" if i == 0 else "limits.span_difference", a=a, b=b,
                            pivot=o2)
            arc = self.act(f"arc{i}", "swing_arc", self.P(o2), radius=length,
                           label=f"arc {span}")
            where = self.path_of_b(arc, b + mark, i, length)
            said = phrase("limits.in_line", pivot=o2, span=spoken, radius=self.length(length),
                          path=where[1], point=f"{b}{mark}", how=Word(how))
            try:
                bp = self.act(f"{b}{i}", where[0], *where[2], label=f"{b}{mark}",
                              said=said, pick=where[3])
            except NoIntersection as e:
                raise InputError(
                    f"crank and rod cannot lie in line, {how}: the arc of radius {span} = "
                    f"{self.L(length)} about {o2} misses {narrate(where[1])} by "
                    f"{self.L(e.margin)}, so "
                    f"{b} never reverses there and there is no limit position to draw") from None
            self.act(f"line{i}", "line_through", self.P(o2), bp, label=f"{o2}{b}{mark}")
            ap = self.act(f"{a}{i}", "lay_off", self.P(o2), bp, length=r if i == 0 else -r,
                          label=f"{a}{mark}", result=True,
                          said=phrase("limits.crank_along" if i == 0 else "limits.crank_beyond",
                                      pivot=o2, point=f"{b}{mark}", pin=f"{a}{mark}", crank=a,
                                      radius=self.length(r)))
            pins.append(ap)
        return pins[0], pins[1]

    def path_of_b(self, arc: Ref, name: str, i: int, length: float):
        """(verb, words, inputs, pick) for cutting B's path with the arc about O2.

        With the crank in line, A lies on O2B, so B is on the same side of O2 → O4 (or
        as far along the guide from O2's foot) as it is drawn from A → O4 (from A).
        """
        if self.kind == "slider-crank":
            guide = self.asm.guides[self.guide]
            return ("intersect_line_circle", phrase("limits.path_of", point=self.b),
                    (guide, arc), self.along(self.b, self.a, guide))
        o4 = self.o4
        rocker = self.act(f"rocker-arc{i}", "swing_arc", self.P(o4),
                          radius=self.m.link(self.out).span(o4, self.b),
                          label=f"arc {o4}{self.b}")
        return ("intersect_circles", phrase("limits.arc_about", point=self.b, centre=o4),
                (arc, rocker), self.side(self.b, self.a, o4))

    def tangent_lever(self) -> tuple[Ref, Ref]:
        """The lever tangent to the crank circle: the circle on O2O4 cuts it at A′, A″."""
        o2, o4, a = self.o2, self.o4, self.a
        mid = self.act("mid", "midpoint", self.P(o2), self.P(o4), label="M",
                       said=phrase("limits.bisect", a=o2, b=o4))
        self.act("thales", "circle_through", mid, self.P(o2), label=f"circle on {o2}{o4}",
                 said=phrase("limits.thales", a=o2, b=o4))
        self.act("crank-circle", "circle_through", self.P(o2), self.P(a), label="crank circle",
                 said=phrase("limits.crank_circle", pivot=o2, pin=a, radius=self.length(self.r)))
        pins = [self.act(f"{a}{i}", "intersect_circles", "limit:crank-circle", "limit:thales",
                         pick=pick, label=f"{a}{_PRIMES[i]}", result=True,
                         said=(phrase("limits.tangent_cuts", pin=a, a=o2, b=o4) if i == 0 else
                               phrase("limits.second_cut", pin=a)))
                for i, pick in enumerate(("left", "right"))]
        for i, ap in enumerate(pins):
            self.act(f"lever{i}", "line_through", self.P(o4), ap, label=f"{o4}{a}{_PRIMES[i]}",
                     said=phrase("limits.lever", pivot=o4, pin=f"{a}{_PRIMES[i]}",
                                 which=Word("first" if i == 0 else "second")))
        return pins[0], pins[1]

    # ----- the output at each limit ----------------------------------------------------
    def carry_output(self, rams: tuple[Ref, Ref] | None = None):
        """Carry the chain to the stroke point at each limit; its two places give the stroke
        (a Whitworth's ram, drawn with its limits, at ``rams``)."""
        target = stroke_point(self.m)
        if target is None:
            return None, None, None
        if rams is not None:
            target, ends = self.rod2[2], list(rams)
        elif self.kind == "slider-crank":
            if target != self.b:
                return None, None, None
            ends = [f"limit:{self.b}0", f"limit:{self.b}1"]
        else:
            ends = [self.carry(target, i) for i in range(2)]
            if None in ends:
                return None, None, None
        length = math.dist(self.xy(ends[0]), self.xy(ends[1]))
        ref = self.act("stroke", "measure", ends[1], ends[0], label="stroke", result=True,
                       said=phrase("limits.stroke", point=target, length=self.length(length)))
        return target, length, ref

    @property
    def held(self) -> str:
        """The point whose limit place sets the lever or rocker: A in its slot, or B."""
        return self.a if self.kind == "slotted lever" else self.b

    def carry(self, name: str, i: int) -> Ref | None:
        """Place ``name`` at limit ``i`` of the lever or rocker, or None if tarsim cannot."""
        mark = _PRIMES[i]
        out, o4, held = self.out, self.o4, self.held
        lever_line = (f"limit:lever{i}" if self.kind == "slotted lever"
                      else self.act(f"rocker{i}", "line_through", self.P(o4), f"limit:{held}{i}",
                                    label=f"{o4}{held}{mark}"))
        guide = next((j for j, s in enumerate(self.m.slides) if s.point == name
                      and s.guide_link == 1), None)
        slot = any(s.point == name and s.guide_link == out for s in self.m.slides)
        if slot and guide is not None:
            return self.act(f"{name}{i}", "intersect_lines", lever_line, self.asm.guides[guide],
                            label=f"{name}{mark}", result=True,
                            said=phrase("limits.produce_lever", pivot=o4, held=f"{held}{mark}",
                                        point=name, end=f"{name}{mark}"))
        # A rod from a point X of the lever to the block's pin.
        for k in self.m.links_at(name):
            rod = self.m.link(k)
            if k == 1 or len(rod.names) != 2 or guide is None:
                continue
            x = next(n for n in rod.names if n != name)
            if out not in self.m.links_at(x):
                continue
            xp = self.swing(x, i)
            arc = self.act(f"arc-{name}{i}", "swing_arc", xp, radius=rod.span(x, name),
                           label=f"arc {x}{mark}{name}{mark}")
            path = self.asm.guides[guide]
            end = self.act(f"{name}{i}", "intersect_line_circle", path, arc,
                           label=f"{name}{mark}", result=True, pick=self.along(name, x, path),
                           said=phrase("limits.rod_cuts_path", x=f"{x}{mark}", span=f"{x}{name}",
                                       radius=self.length(rod.span(x, name)), point=name,
                                       end=f"{name}{mark}"))
            self.act(f"rod-{name}{i}", "line_through", xp, end, label=f"{x}{mark}{name}{mark}",
                     said=phrase("limits.rod", a=f"{x}{mark}", b=f"{name}{mark}", link=k))
            return end
        return None

    def swing(self, x: str, i: int) -> Ref:
        """Point ``x`` of the lever or rocker, swung about its pivot into limit ``i``."""
        mark = _PRIMES[i]
        o4, held = self.o4, self.held
        if x == held:
            return f"limit:{held}{i}"
        here = _sub(self.asm.xy(held), self.asm.xy(o4))
        there = _sub(self.xy(f"limit:{held}{i}"), self.asm.xy(o4))
        turn = math.atan2(there[1], there[0]) - math.atan2(here[1], here[0])
        return self.act(f"{x}{i}", "rotate_about", self.P(x), self.P(o4), angle=turn,
                        label=f"{x}{mark}",
                        said=phrase("limits.swing", pivot=o4, point=x, held=held,
                                    held_there=f"{held}{mark}", there=f"{x}{mark}"))


def _sub(p, q) -> tuple[float, float]:
    return (p[0] - q[0], p[1] - q[1])


# ----- as a method of the registry -------------------------------------------------------------
LIMITS = FigureSpec("limits", "Limit positions", "limit positions", kind="limits")
"""The figure of both limit positions: the crank's angles and the stroke."""

WHY_NOT = {
    A.TimeRatio: "its crank drives no slider-crank, crank-rocker or slotted lever (a wheel "
                 "rolling on the frame is no crank), so it has no limit positions to draw",
    A.Stroke: "the stroke is measured on a block that slides on a frame guide, driven through "
              "the limit positions, and this mechanism has none",
    A.Swing: SWING_WHY_NOT.format(k="<k>"),
}
"""Why a mechanism the limit construction does not fit has no time ratio or stroke."""


def askable(mech: Mechanism) -> set[str]:
    """The time ratio where the construction fits the crank's dyad, the stroke where it also
    drives a block on a frame guide."""
    try:
        dyad = _Dyad(mech)
    except InputError:
        return set()
    swing = {f"swing_{dyad.out}"} if dyad.kind in ("crank-rocker", "slotted lever") else set()
    return {"time_ratio"} | swing | ({"stroke"} if stroke_point(mech) is not None else set())


def drawn_limits(work) -> LimitPositions:
    """Both limit positions, drawn once on the mechanism at its stated position."""
    return work.shared("limits", lambda: draw_limit_positions(work.assembly))


def answer(work, ask) -> Answer:
    """The time ratio, the stroke or a lever's swing, read off the limit positions."""
    lp = drawn_limits(work)
    if isinstance(ask, A.Swing):
        return swing_answer(work, ask, lp, LIMITS)
    how = {"slotted lever": "lever tangent to the crank circle",
           "whitworth": "lever and rod in line"}.get(lp.kind, "crank and rod in line")
    method = f"limit positions by compass ({how})"
    if isinstance(ask, A.TimeRatio):
        if min(lp.slow, lp.quick) <= 0.0:
            theta = work.mechanism.units.angle_brief(lp.crank_angles[0])
            raise TarsimError(f"both limit positions fall at θ{work.mechanism.drive.link} = "
                              f"{theta}: the crank turns through no angle between "
                              "them, so there is no time ratio (the linkage's branches meet "
                              "there, a change point)")
        value = time_ratio_value(lp.slow, lp.quick)
    else:
        if lp.stroke is None:
            raise InputError(WHY_NOT[A.Stroke])
        value = {"value": lp.stroke, "point": lp.point}
    return Answer(ask, value, lp.conditioning, method, refs=tuple(lp.steps), figures=(LIMITS,))
