"""Dyad rules that cut a joint from two loci already drawn.

* a point of a link already drawn: laid off along the line of two of its points, cut
  from two arcs about them, or squared off the link's axis;
* two arcs (a pin between two links, RRR): circle–circle;
* an arc and a guide (a pin on a slider, RRP): line–circle;
* two guides (a pin in a slot and on a slider): line–line.

An arc is a link's span about its one located point, or the radius of a curved slot or
of two circles in contact about its located centre. Where two loci cut twice the
point's branch chooses; where they miss, the error names the link that cannot reach.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .. import geometry as g
from .dyad_rules import dyad_rule
from .dyad_slots import known_guides
from ..errors import AssemblyError, DegenerateInput, NoIntersection
from ..joints import Arc
from ..narration import Phrase, Word, phrase

if TYPE_CHECKING:
    from .assembly import Assembler

__all__ = ["rigid_point", "two_arcs", "arc_and_guide", "two_guides"]


def _arc_why(a: Arc) -> Phrase:
    """Why a point keeps its distance: "the circles of links 3 and 2 touch: their centres
    R and C stay r3 + r2 apart"."""
    if not a.type.contact:
        return phrase("position.why_curved_slot", point=a.point, link=a.guide_link,
                      centre=a.centre)
    c = a.contact
    return phrase("position.why_circles_touch", i=c.circle.link, j=c.face.link, p=a.point,
                  q=a.centre, op="+" if c.side == "outside" else "−")


@dyad_rule("a point of a drawn link", 0)
def rigid_point(asm: Assembler) -> bool:
    """Locate a point of a link already drawn from the link's points already located."""
    for k in asm.m.links:
        if k.number == 1 or not asm.posed(k.number):
            continue
        for name in k.names:
            if name not in asm.known:
                _locate_on_link(asm, k.number, name)
                return True
    return False


def _locate_on_link(asm: Assembler, number: int, name: str) -> None:
    k = asm.m.link(number)
    on = [n for n in k.names if n in asm.known]
    px, py = k.local(name)
    if len(on) >= 2:
        a, b = on[0], on[1]
        (ax, ay), (bx, by) = k.local(a), k.local(b)
        ux, uy = bx - ax, by - ay
        cross = ux * (py - ay) - uy * (px - ax)
        if abs(cross) <= 1e-12 * (ux * ux + uy * uy):
            along = (ux * (px - ax) + uy * (py - ay)) / math.hypot(ux, uy)
            asm.found(name, "lay_off", asm.known[a], asm.known[b], length=along,
                      said=phrase("position.on_link_line", point=name, a=a, b=b,
                                  link=number, length=asm.length(abs(along))))
            return
        ra, rb = k.span(a, name), k.span(b, name)
        arc_a = asm.c.draw(f"arc:{name}@{a}", "swing_arc", asm.known[a], radius=ra,
                           label=f"arc {a}{name}")
        arc_b = asm.c.draw(f"arc:{name}@{b}", "swing_arc", asm.known[b], radius=rb,
                           label=f"arc {b}{name}")
        asm.found(name, "intersect_circles", arc_a, arc_b,
                  pick="left" if cross > 0 else "right",
                  said=phrase("position.rigid_point", point=name, link=number, a=a, b=b,
                              ra=asm.length(ra), rb=asm.length(rb)))
        return
    base = on[0]
    bx, by = k.local(base)
    du, dv = px - bx, py - by
    along = phrase("position.along_link", link=number, base=base, point=name,
                   length=asm.length(abs(du)))
    if dv == 0.0:
        asm.found(name, "lay_off", asm.known[base], asm.axes[number], length=du,
                  said=along)
        return
    foot = asm.c.draw(f"foot:{name}", "lay_off", asm.known[base], asm.axes[number],
                      length=du, phrase=along)
    perp = asm.c.draw(f"perp:{name}", "perpendicular_through", foot, asm.axes[number])
    asm.found(name, "lay_off", foot, perp, length=dv,
              said=phrase("position.square_off", length=asm.length(abs(dv)), point=name))


def _circles_of(asm: Assembler, name: str) -> list[tuple[int, str, float, Phrase]]:
    """The arcs ``name`` must lie on, as ``(link, centre, radius, why)``, lowest link first.

    An arc comes from a link not yet drawn with one point located (its span to
    ``name``), or from a curved slot or circle contact whose other end is located.
    """
    out = []
    for n in asm.m.links_at(name):
        if not asm.posed(n) and any(p in asm.known for p in asm.m.link(n).names):
            x = asm.one_known(n)
            r = asm.m.link(n).span(x, name)
            out.append((n, x, r, phrase("position.radius_span", a=x, b=name,
                                        length=asm.length(r))))
    for a in asm.m.pin_arcs:
        for here, there, k in ((a.point, a.centre, a.guide_link), (a.centre, a.point, a.link)):
            if here == name and there in asm.known:
                out.append((k, there, a.radius, phrase("position.radius_because",
                                                       length=asm.length(a.radius),
                                                       why=_arc_why(a))))
    return sorted(out, key=lambda c: c[:3])


@dyad_rule("two arcs (RRR)", 6)
def two_arcs(asm: Assembler) -> bool:
    """Cut a point from two arcs about located centres (RRR): circle–circle."""
    for name in asm.m.point_names:
        if name in asm.known or asm.slides_at(name):
            continue
        circles = _circles_of(asm, name)
        if len(circles) < 2:
            continue
        (i, x, ri, why_i), (j, y, rj, why_j) = circles[:2]
        arc_i = asm.c.draw(f"arc:{name}@{x}", "swing_arc", asm.known[x], radius=ri,
                           label=f"arc {x}{name}",
                           phrase=phrase("position.swing_arc", centre=x, radius=why_i))
        arc_j = asm.c.draw(f"arc:{name}@{y}", "swing_arc", asm.known[y], radius=rj,
                           label=f"locus of {name}",
                           phrase=phrase("position.locus", centre=y, radius=why_j,
                                         point=name))
        pick = asm.branch(name, None, ("left", "right"), f"left or right of {x} → {y}")
        try:
            if not isinstance(pick, str):
                pick = asm.pick_near("intersect_circles", (arc_i, arc_j), ("left", "right"),
                                     pick)
            asm.found(name, "intersect_circles", arc_i, arc_j, pick=pick,
                      said=phrase("position.arcs_cut", point=name, pick=Word(pick), a=x,
                                  b=y))
        except NoIntersection:
            raise _cannot_reach(asm, name, i, x, ri, y, rj) from None
        except DegenerateInput:                   # x on y: the two arcs share a centre
            if ri != rj:
                raise _cannot_reach(asm, name, i, x, ri, y, rj) from None
            raise AssemblyError(
                f"{x} falls on {y} {asm.at()}, so the arcs of {name} about them "
                f"coincide and {name} is not fixed: a change point, where the linkage's "
                "branches meet", link=i, joint=name,
                angle_deg=math.degrees(asm.theta)) from None
        return True
    return False


def _cannot_reach(asm: Assembler, name: str, i: int, x: str, ri: float, y: str,
                  rj: float) -> AssemblyError:
    d = g.distance(asm.c.output(asm.known[x]), asm.c.output(asm.known[y]))
    if d > ri + rj:
        why = f"|{y}{x}| = {asm.L(d)} > {asm.L(ri)} + {asm.L(rj)}"
    else:
        why = f"|{y}{x}| = {asm.L(d)} < |{asm.L(ri)} − {asm.L(rj)}|"
    return AssemblyError(
        f"{asm.with_length(i, x + name, ri)} cannot reach the circle of "
        f"{name} about {y} {asm.at()}: {why}", link=i, joint=name,
        angle_deg=math.degrees(asm.theta))


@dyad_rule("an arc and a guide (RRP)", 5)
def arc_and_guide(asm: Assembler) -> bool:
    """Cut a point on its one drawn guide with an arc about a located centre (RRP)."""
    for name in asm.m.point_names:
        if name in asm.known:
            continue
        lines = known_guides(asm, name)
        circles = _circles_of(asm, name)
        if len(lines) != 1 or not circles:
            continue
        i, x, r, why = circles[0]
        arc = asm.c.draw(f"arc:{name}@{x}", "swing_arc", asm.known[x], radius=r,
                         label=f"arc {x}{name}",
                         phrase=phrase("position.swing_arc", centre=x, radius=why))
        guide = asm.guides[lines[0]]
        pick = asm.branch(name, None, ("forward", "backward"),
                          f"forward or backward along the guide of {name}")
        try:
            if not isinstance(pick, str):
                pick = asm.pick_near("intersect_line_circle", (guide, arc),
                                     ("forward", "backward"), pick)
            asm.found(name, "intersect_line_circle", guide, arc, pick=pick,
                      said=phrase("position.arc_cuts_guide", point=name, pick=Word(pick)))
        except NoIntersection as e:
            raise AssemblyError(
                f"{asm.with_length(i, x + name, r)} cannot reach the guide "
                f"of {name} {asm.at()}: it passes {asm.L(e.margin)} beyond the arc",
                link=i, joint=name, angle_deg=math.degrees(asm.theta)) from None
        return True
    return False


@dyad_rule("two guides (RPP)", 4)
def two_guides(asm: Assembler) -> bool:
    """Cut a point from the two drawn guides it slides on (RPP): line–line."""
    for name in asm.m.point_names:
        if name in asm.known:
            continue
        lines = known_guides(asm, name)
        if len(lines) < 2:
            continue
        try:
            asm.found(name, "intersect_lines", asm.guides[lines[0]], asm.guides[lines[1]],
                      said=phrase("position.two_guides", point=name))
        except DegenerateInput:
            raise AssemblyError(f"the two guides of {name} coincide {asm.at()}, so "
                                f"{name} is not fixed", joint=name) from None
        if asm.c.output(asm.known[name]).is_at_infinity:
            raise AssemblyError(f"the two guides of {name} are parallel {asm.at()}, so "
                                f"{name} is at infinity", joint=name)
        return True
    return False
