"""The limit positions of a Whitworth quick return: the crank longer than the distance
between the fixed centres, so the slotted lever turns right round with it, and its end
drives a ram through a rod.

The lever's own motion never reverses; the ram does, where lever and rod lie in line
(the dead centres of the slider-crank the lever, the rod and the ram make): extended, the
ram cut from its line of stroke by an arc of radius rod + lever about the lever's pivot;
folded, by an arc of rod − lever. The lever's end lies on the line from the pivot to
each (toward it, or beyond the pivot), and the crank pin where that line, the slot,
cuts the crank circle, on the side of the pivot the drawn position shows (the pin never
passes the pivot, which lies within its circle). The crank angles between the two pins
give the time ratio, the ram's two places the stroke (Khurmi, Theory of Machines, §5.9).
"""

from __future__ import annotations

from ..errors import InputError, NoIntersection
from ..narration import Word, narrate, phrase
from ..record import Ref

__all__ = ["secondary_rod", "whitworth_pins"]

_PRIMES = ("′", "″")


def secondary_rod(mech, out: int, o4: str, pin: str):
    """The rod from a point X of lever ``out`` to a block C on a frame guide: (rod link, X,
    C, the guide's slide index), or None."""
    for x in mech.link(out).names:
        if x in (o4, pin):
            continue
        for k in mech.links_at(x):
            rod = mech.link(k)
            if k in (1, out) or len(rod.names) != 2:
                continue
            c = next(n for n in rod.names if n != x)
            guide = next((i for i, s in enumerate(mech.slides) if s.point == c
                          and s.guide_link == 1 and s.type.key == "block"), None)
            if guide is not None:
                return k, x, c, guide
    return None


def whitworth_pins(lim) -> tuple[tuple[Ref, Ref], tuple[Ref, Ref]]:
    """Draw both limit positions (see the module) on ``lim`` (a ``_Limits``): the crank pins
    A′, A″ and the ram's places C′, C″."""
    m, o2, o4, a = lim.m, lim.o2, lim.o4, lim.a
    k, x, c, guide = lim.rod2
    lever, rod = m.link(lim.out).span(o4, x), m.link(k).span(x, c)
    if rod <= lever:
        raise InputError(f"the rod {x}{c} (link {k}, {lim.L(rod)}) is not longer than the lever "
                         f"{o4}{x} ({lim.L(lever)}): the lever cannot turn right round")
    path = lim.asm.guides[guide]
    pick = lim.along(c, o4, path)
    (ox, oy), (ax, ay), (xx, xy) = (lim.asm.xy(n) for n in (o4, a, x))
    slot_side = "forward" if (ax - ox) * (xx - ox) + (ay - oy) * (xy - oy) > 0.0 else "backward"
    lim.act("crank-circle", "circle_through", lim.P(o2), lim.P(a), label="crank circle",
            said=phrase("limits.crank_circle", pivot=o2, pin=a, radius=lim.length(lim.r)))
    pins, rams = [], []
    for i, (length, how) in enumerate(((rod + lever, "extended"), (rod - lever, "folded"))):
        mark = _PRIMES[i]
        spoken = phrase("limits.span_sum" if i == 0 else "limits.span_difference", a=x, b=c,
                        pivot=o4)
        arc = lim.act(f"arc{i}", "swing_arc", lim.P(o4), radius=length,
                      label=f"arc {x}{c} {'+' if i == 0 else '−'} {o4}{x}")
        said = phrase("limits.lever_in_line", pivot=o4, span=spoken, radius=lim.length(length),
                      path=phrase("limits.path_of", point=c), point=f"{c}{mark}",
                      how=Word(how))
        try:
            end = lim.act(f"{c}{i}", "intersect_line_circle", path, arc, pick=pick,
                          label=f"{c}{mark}", result=True, said=said)
        except NoIntersection as e:
            raise InputError(
                f"lever and rod cannot lie in line, {how}: the arc of radius {lim.L(length)} "
                f"about {o4} misses {narrate(phrase('limits.path_of', point=c))} by "
                f"{lim.L(e.margin)}, so the ram never reverses there") from None
        lim.act(f"line{i}", "line_through", lim.P(o4), end, label=f"{o4}{c}{mark}")
        xp = lim.act(f"{x}{i}", "lay_off", lim.P(o4), end, length=lever if i == 0 else -lever,
                     label=f"{x}{mark}",
                     said=phrase("limits.lever_along" if i == 0 else "limits.lever_beyond",
                                 pivot=o4, point=f"{c}{mark}", end=f"{x}{mark}", x=x,
                                 radius=lim.length(lever)))
        slot = lim.act(f"lever{i}", "line_through", lim.P(o4), xp, label=f"{o4}{x}{mark}")
        pins.append(lim.act(f"{a}{i}", "intersect_line_circle", slot, "limit:crank-circle",
                            pick=slot_side, label=f"{a}{mark}", result=True,
                            said=phrase("limits.slot_cuts_crank", pivot=o4, end=f"{x}{mark}",
                                        pin=f"{a}{mark}")))
        lim.act(f"rod{i}", "line_through", xp, end, label=f"{x}{mark}{c}{mark}",
                said=phrase("limits.rod", a=f"{x}{mark}", b=f"{c}{mark}", link=k))
        rams.append(end)
    return (pins[0], pins[1]), (rams[0], rams[1])
