"""Dyad rules for slots: a slotted link swung through its block, and a block's slot.

* a slot swung through a located block (the slotted lever, R-P-R): the line from the
  pivot through the block, or the tangent from the block to the offset circle;
* the slot of a translating block (say the equivalent slot of a flat-faced follower):
  the block's guide turned by the slot's angle, through the located pin.

:func:`known_guides` gives the other rules the guides a point slides on, drawing the
slot of a moving link along its axis the first time it is asked for.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .. import geometry as g
from .assembly_record import MEETING
from .dyad_rules import dyad_rule
from ..errors import AssemblyError, BranchError, DegenerateInput, NoIntersection, TarsimError
from ..joints import Slide
from ..narration import phrase
from ..record import Kind, Ref

if TYPE_CHECKING:
    from .assembly import Assembler

__all__ = ["slot_through_block", "slot_of_a_block", "known_guides"]


@dyad_rule("a slot swung through its block (RPR)", 2)
def slot_through_block(asm: Assembler) -> bool:
    """Swing a slotted link about its one located point until its slot passes the block."""
    for i, s in enumerate(asm.m.slides):
        if i in asm.guides or s.point not in asm.known or asm.posed(s.guide_link):
            continue
        k = asm.m.link(s.guide_link)
        on = [n for n in k.names if n in asm.known]
        if len(on) != 1:
            continue
        _swing_slot(asm, i, s, on[0])
        return True
    return False


@dyad_rule("the slot of a translating block", 3)
def slot_of_a_block(asm: Assembler) -> bool:
    """Draw the slot of a translating block through its located pin, then the block.

    A block's own +x runs along its guide, so its slot (say the equivalent slot of a
    flat-faced follower) is the guide turned by the slot's angle, through the pin.
    The block's point lies on the parallel to the slot at its offset (the face),
    where that cuts the block's guide.
    """
    for i, s in enumerate(asm.m.slides):
        k = asm.m.link(s.guide_link)
        if i in asm.guides or k.number == 1 or s.point not in asm.known or len(k.names) != 1:
            continue
        j = next((j for j, b in enumerate(asm.m.slides) if b.link == k.number
                  and b.type.turns_with_guide and j in asm.guides), None)
        if j is None or k.names[0] in asm.known:
            continue
        guide, pin, name = asm.guides[j], asm.known[s.point], k.names[0]
        (tx, ty), (dx, dy) = s.through, s.direction
        if abs(dx) <= 1e-12:
            slot = asm.c.draw(f"guide:{i}", "perpendicular_through", pin, guide,
                              label=f"slot of link {k.number}", kind=Kind.GUIDE,
                              phrase=phrase("position.slot_square_to_guide", point=s.point,
                                            block=name, link=k.number))
        else:
            n = asm.c.draw(f"normal:{i}", "normal_direction", guide)
            turned = asm.c.draw(f"turn:{i}", "rotate_about", n, pin,
                                angle=math.atan2(dy, dx) - math.pi / 2)
            slot = asm.c.draw(f"guide:{i}", "line_through", pin, turned,
                              label=f"slot of link {k.number}", kind=Kind.GUIDE,
                              phrase=phrase("position.slot_at_angle", point=s.point,
                                            angle=asm.angle(math.atan2(dy, dx)),
                                            block=name, link=k.number))
        asm.guides[i] = slot
        px, py = k.local(name)
        # The block's point lies this far left of the slot; a drawn line may run the
        # other way (a perpendicular turns +90°, a direction has no sense).
        across = dx * (py - ty) - dy * (px - tx)
        (gx, gy), (sx, sy) = asm.c.output(guide).direction, asm.c.output(slot).direction
        if (gx * dx - gy * dy) * sx + (gy * dx + gx * dy) * sy < 0.0:
            across = -across
        line = slot
        if across != 0.0:
            perp = asm.c.draw(f"perp:{i}", "perpendicular_through", pin, slot)
            foot = asm.c.draw(f"foot:{i}", "lay_off", pin, perp, length=across)
            line = asm.c.draw(f"face:{i}", "parallel_through", foot, slot,
                              phrase=phrase("position.face_offset",
                                            length=asm.length(abs(across)), point=name))
        try:
            asm.found(name, "intersect_lines", line, guide,
                      said=phrase("position.cut_guide", point=name))
        except DegenerateInput:
            pass
        if name not in asm.known or asm.c.output(asm.known[name]).is_at_infinity:
            raise AssemblyError(f"the slot of {k.label} runs along its guide {asm.at()}, "
                                f"so {name} is not fixed", link=k.number, joint=name)
        asm.axes[k.number] = guide
        return True
    return False


def _swing_slot(asm: Assembler, i: int, s: Slide, pivot: str) -> None:
    k = asm.m.link(s.guide_link)
    qx, qy = k.local(pivot)
    (tx, ty), (dx, dy) = s.through, s.direction
    offset = dx * (ty - qy) - dy * (tx - qx)  # pivot lies this far right of the slot
    pick = asm.branch(s.point, "forward", ("forward", "backward"),
                      f"the block ahead of or behind the foot of {pivot} on the slot")
    if not isinstance(pick, str):
        raise BranchError(f"[assembly] {s.point}: give \"forward\" or \"backward\" for a "
                          "block in a swinging slot", joint=s.point)
    q, p = asm.known[pivot], asm.known[s.point]
    # Nearer than this (the analytic solver's SINGULAR_RCOND) the slot's direction is
    # rounding; an offset slot cannot come so near its pivot, and says so as it is drawn.
    if (abs(offset) <= 1e-12 * asm.size
            and g.distance(asm.c.output(q), asm.c.output(p)) <= MEETING * asm.size):
        raise AssemblyError(f"the block {s.point} sits on the pivot {pivot} {asm.at()}, so "
                            f"the slot of link {k.number} has no direction", link=k.number)
    name = f"slot of link {k.number}"
    if abs(offset) <= 1e-12 * asm.size:
        ends = (q, p) if pick == "forward" else (p, q)
        apart = g.distance(asm.c.output(q), asm.c.output(p)) / asm.size
        slot = asm.c.draw(f"guide:{i}", "line_through", *ends, label=name, kind=Kind.GUIDE,
                          spread=min(1.0, apart),
                          phrase=phrase("position.slot_through_block", link=k.number,
                                        pivot=pivot, point=s.point))
    else:
        slot = _tangent_slot(asm, i, s, pivot, offset, pick)
    asm.guides[i] = slot
    # The link's axis is the slot moved back onto its local origin.
    if abs(offset) <= 1e-12 * asm.size and k.names[0] == pivot and dx > 0:
        asm.axes[k.number] = slot
    else:
        asm.axes[k.number] = _axis_from_slot(asm, k.number, slot, s, pivot)


def _tangent_slot(asm: Assembler, i: int, s: Slide, pivot: str, offset: float,
                  pick: str) -> Ref:
    q, p = asm.known[pivot], asm.known[s.point]
    near = g.distance(asm.c.output(q), asm.c.output(p))
    if near == 0.0:               # no circle on O4A to cut: say it as a miss
        raise _too_near(asm, s.point, pivot, near, offset)
    mid = asm.c.draw(f"mid:{s.point}{pivot}", "midpoint", q, p,
                     phrase=phrase("position.bisect", a=pivot, b=s.point))
    thales = asm.c.draw(f"thales:{s.point}", "circle_through", mid, q,
                        phrase=phrase("position.circle_on_diameter", a=pivot, b=s.point))
    off = asm.c.draw(f"offset:{pivot}", "swing_arc", q, radius=abs(offset),
                     phrase=phrase("position.offset_arc", centre=pivot,
                                   radius=asm.length(abs(offset))))
    for side in ("left", "right"):
        try:
            t, _ = g.intersect_circles(asm.c.output(thales), asm.c.output(off), side)
        except NoIntersection:
            raise _too_near(asm, s.point, pivot, near, offset) from None
        ends = (t, asm.c.output(p)) if pick == "forward" else (asm.c.output(p), t)
        line, _ = g.line_through(*ends)
        if line.signed_distance(asm.c.output(q)) * offset < 0:
            foot = asm.c.draw(f"tangent:{s.point}", "intersect_circles", thales, off,
                              pick=side, phrase=phrase("position.foot_of_slot"))
            ordered = (foot, p) if pick == "forward" else (p, foot)
            return asm.c.draw(f"guide:{i}", "line_through", *ordered,
                              label=f"slot of link {s.guide_link}", kind=Kind.GUIDE,
                              phrase=phrase("position.slot_tangent", point=s.point))
    raise TarsimError(f"no tangent from {s.point} leaves {pivot} on the slot's side")


def _too_near(asm: Assembler, point: str, pivot: str, near: float,
              offset: float) -> AssemblyError:
    """An offset slot cannot pass its block: the block is nearer its pivot than the offset."""
    return AssemblyError(f"the block {point} comes within {asm.L(near)} of {pivot} "
                         f"{asm.at()}, closer than the slot's offset of "
                         f"{asm.L(abs(offset))}", joint=point)


def _axis_from_slot(asm: Assembler, number: int, slot: Ref, s: Slide, pivot: str) -> Ref:
    k = asm.m.link(number)
    dx, dy = s.direction
    if dy != 0.0 or dx < 0.0 or k.names[0] != pivot:
        raise AssemblyError(f"the slot of {k.label} must run along the link's axis, and the "
                            f"link must list its pivot {pivot} first", link=number)
    return asm.c.draw(f"axis:{number}", "parallel_through", asm.known[pivot], slot,
                      label=f"link {number}", kind=Kind.GUIDE)


def known_guides(asm: Assembler, name: str) -> list[int]:
    """The slides at point ``name`` whose guide is drawn, drawing a drawn link's slot first."""
    out = []
    for i in asm.slides_at(name):
        s = asm.m.slides[i]
        if i not in asm.guides and s.guide_link != 1 and asm.posed(s.guide_link):
            _place_slot(asm, i, s)
        if i in asm.guides:
            out.append(i)
    return out


def _place_slot(asm: Assembler, i: int, s: Slide) -> None:
    """Draw the slot of an already-drawn moving link."""
    number = s.guide_link
    axis = _axis_of(asm, number)
    k = asm.m.link(number)
    ox, oy = k.local(k.names[0])
    ty, (dx, dy) = s.through[1], s.direction
    if abs(dy) > 0.0 or dx < 0:
        raise AssemblyError(f"the slot of {k.label} must run along the link's axis",
                            link=number)
    off = ty - oy
    if off == 0.0:
        asm.guides[i] = axis
        return
    base = asm.c.draw(f"slotfoot:{i}", "perpendicular_through", asm.known[k.names[0]], axis)
    at = asm.c.draw(f"slotpt:{i}", "lay_off", asm.known[k.names[0]], base, length=off)
    asm.guides[i] = asm.c.draw(f"guide:{i}", "parallel_through", at, axis,
                               label=f"slot of link {number}", kind=Kind.GUIDE)


def _axis_of(asm: Assembler, number: int) -> Ref:
    """The oriented axis line of a drawn link (through its first point)."""
    if number in asm.axes:
        return asm.axes[number]
    k = asm.m.link(number)
    if len(k.names) >= 2 and all(n in asm.known for n in k.names[:2]):
        asm.axes[number] = asm.c.draw(f"axis:{number}", "line_through",
                                      asm.known[k.names[0]], asm.known[k.names[1]],
                                      label=f"link {number}", kind=Kind.GUIDE)
        return asm.axes[number]
    for i, s in enumerate(asm.m.slides):
        if s.link == number and s.type.turns_with_guide and i in asm.guides:
            asm.axes[number] = asm.guides[i]
            return asm.guides[i]
    raise AssemblyError(f"{asm.m.link(number).label} has no direction: give it two points "
                        "or a slide", link=number)
