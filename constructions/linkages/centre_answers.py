"""Instant centres as a method of the registry: a centre, how many there are, and ω read off them.

Every centre of a position is located once (:func:`located`) and shared by the answers
drawn on it: an instant centre, the circle diagram's count, and an angular velocity by
the ratio of the centres' distances.
"""

from __future__ import annotations

import math

from .. import asks as A
from .. import geometry as g
from .centres import SAME, Centres, omega_ratio, pair_label
from ..checks import Answer, FigureSpec
from ..errors import DegenerateInput, TarsimError
from .kennedy import locate_centres
from ..record import Ref

__all__ = ["located", "answer_centre", "answer_count", "answer_omega", "ratio_by_centres",
           "CENTRES_FIGURE", "ASKED_FIGURE", "OMEGA_FIGURE", "CIRCLE_FIGURE"]


def _spread(cs: Centres, i: int, j: int) -> float:
    """How far I_ij stands from I_1j beside the mechanism's size: the ratio's denominator is
    that distance, and each centre is only known to the rounding of the whole drawing."""
    p_ij, p_j = cs.point(i, j), cs.point(1, j)
    if p_ij.is_at_infinity or p_j.is_at_infinity:
        return 1.0
    asm = cs.assembly
    size = max(math.hypot(*asm.output(r).xy) for r in asm.points.values())
    size = max(size, *(abs(c) for c in (*p_ij.xy, *p_j.xy)), 1e-300)
    return min(1.0, g.distance(p_ij, p_j) / size)


_RULE_WORDS = {"pin": "inspection (pin)", "block": "inspection (block on a straight guide)",
               "curved": "inspection (block on a curved guide: centre of curvature)",
               "rolling": "inspection (rolling contact: the contact point)",
               "kennedy": "Kennedy (circle diagram)",
               "velocities": "Kennedy line and velocity ratio"}


def located(work) -> Centres:
    """Every centre of the work's position, located once; ill-conditioned ones are noted."""
    def make() -> Centres:
        cs = locate_centres(work.assembly)
        for warning in cs.warnings():
            work.note(warning)
        return cs
    return work.shared("centres", make)


def answer_centre(work, ask: A.Centre) -> Answer:
    """An instant centre, drawn on the centres figure and the circle diagram."""
    cs = located(work)
    c, p = cs.centre(*ask.pair), cs.point(*ask.pair)
    value = ({"at_infinity": True, "direction": list(p.direction)} if p.is_at_infinity
             else {"point": list(p.xy)})
    every = sum(isinstance(a, A.Centre) for a in work.asks) >= len(cs.found)
    return Answer(ask, value, cs.conditioning(*ask.pair), _RULE_WORDS[c.rule], refs=(c.ref,),
                  figures=(CENTRES_FIGURE if every else ASKED_FIGURE, CIRCLE_FIGURE), found=p,
                  holds_always=c.primary)


def answer_count(work, ask: A.CentreCount) -> Answer:
    """How many centres the circle diagram holds: n(n − 1)/2 chords, those drawn solid by
    inspection, the rest dashed by Kennedy's theorem; and how many of them lie at infinity
    at this position (a block's on a straight guide, two links that translate together)."""
    cs = located(work)
    n = len(cs.links)
    total, inspected = len(cs.found), len(cs.primaries)
    far = sum(cs.point(*pair).is_at_infinity for pair in cs.found)
    return Answer(ask, {"value": total, "by_inspection": inspected,
                        "by_kennedy": total - inspected, "far_centres": far}, 1.0,
                  f"circle diagram, n(n − 1)/2 with n = {n}",
                  refs=tuple(cs.construction_refs()))


def answer_omega(work, ask: A.AngularVelocity) -> Answer:
    """ω of a link from the centres: ω_n / ω_d = (I_dn − I_1d) / (I_dn − I_1n) on their line."""
    cs = located(work)
    d = work.mechanism.drive
    n = ask.link
    if n == d.link:
        return Answer(ask, {"value": d.omega}, 1.0, "given", refs=(cs.centre(1, d.link).ref,),
                      figures=(OMEGA_FIGURE,))
    ratio, cond, refs = ratio_by_centres(work, d.link, n)
    return Answer(ask, {"value": ratio * d.omega + 0.0}, cond, "instant centres (ω ratio)",
                  refs=refs, figures=(OMEGA_FIGURE,))


def ratio_by_centres(work, i: int, j: int) -> tuple[float, float, tuple[Ref, ...]]:
    """ω_j / ω_i read off the centres I_1i, I_1j and I_ij on their line, with its
    conditioning and the centres' refs.

    Raises
    ------
    TarsimError
        If the ratio does not exist here (link i translates, ω_j is unbounded), or I_ij and
        I_1j fall together, so the ratio of their distances is lost to rounding.
    """
    cs = located(work)
    try:
        ratio = omega_ratio(cs, i, j)
    except DegenerateInput as e:
        raise TarsimError(f"ω{j} from the instant centres: {e}") from None
    pairs = [(1, i), (1, j), tuple(sorted((i, j)))]
    cond = min(cs.conditioning(*pair) for pair in pairs) * _spread(cs, i, j)
    if cond < SAME:
        raise TarsimError(f"ω{j} from the instant centres: {pair_label(i, j)} and "
                          f"{pair_label(1, j)} fall together at this position, so the ratio "
                          f"of their distances is lost to rounding; find ω{j} by the velocity "
                          "polygon")
    return ratio, cond, tuple(cs.centre(*pair).ref for pair in pairs)


CENTRES_FIGURE = FigureSpec("centres", "Instant centres", "instant centres", notes=True)
ASKED_FIGURE = FigureSpec("centres", "The instant centres asked", "the instant centres asked",
                          notes=True)
"""The centres figure when only some centres are asked: it shows those and the centres they
are found from (10 of the 15 of velocity-homework-292, for I15 and I25), not every one."""
OMEGA_FIGURE = FigureSpec("centres", "Centres for the angular velocities",
                          "centres for the angular velocities", notes=True)
CIRCLE_FIGURE = FigureSpec("circle-diagram", "Circle diagram", kind="circle diagram")
