"""The force polygons of a slotted lever driven by a crank (a crank shaper, a Whitworth
quick return), with its ram if it has one, in the order the unknowns allow: the ram, the
block's couple, the slot's push from the lever's moments, then the block's and the lever's
polygons.
"""

from __future__ import annotations

import math

from .. import geometry as g
from ..loads import leaning
from ..narration import phrase
from ..record import Kind, Panel, Role
from .drafting import as_named, as_said, moment, push_sides, vector_sum
from .groups import Lever
from .result import Forces

__all__ = ["lever_polygons"]

Vec = tuple[float, float]


def lever_polygons(c, draw, out: Forces, lv: Lever, at, known, slip=None):
    """The slotted lever's group, in the order its unknowns allow.

    1. the ram: its loads closed by the slot's push and the guide's, each square to its
       line, crossing; its guide couple from its moments about its pin;
    2. the block's couple from the slot, from the block's moments about A;
    3. the slot's push on the block, from the lever's moments about its pivot;
    4. the block's polygon closed by the crank's force on it, the lever's by its pivot's.

    Returns the block's link, its pull on the crank at A, and the crank's pivot and pin.
    """
    slot = c.draw("force:line:slot", "line_through", c.points[lv.p], c.points[lv.a],
                  kind=Kind.LINE, panel=Panel.FORCE)
    u = _unit((at[lv.a][0] - at[lv.p][0], at[lv.a][1] - at[lv.p][1]))
    n = (-u[1], u[0])                                    # square to the slot
    f_rl = (0.0, 0.0)
    origin = c.give("force:S", g.Point(0.0, 0.0), label="", panel=Panel.FORCE)
    refs: list[str] = []
    if lv.r is not None:
        c.draw("force:say:ram", "mark", origin, panel=Panel.FORCE, label=f"link {lv.r}",
               phrase=phrase("force.ram", r=lv.r, l=lv.l))
        tip = draw.loads(lv.r, origin, known[lv.r])
        if slip is None or slip[1]["guide"] == slip[1]["pin"] == (0.0, 0.0):
            guide = draw.square_to(origin, lv.guide, "N")
            across = c.draw("force:line:slotN", "perpendicular_through", origin, slot,
                            kind=Kind.LINE, panel=Panel.FORCE)
        else:
            mu, sliding = slip
            laid = vector_sum(f for _, f, _, _ in known[lv.r])
            s_guide, s_slot = push_sides(laid, (lv.guide, sliding["guide"]),
                                         (u, sliding["pin"]), mu)
            guide = draw.leaning(origin, lv.guide, s_guide, (mu, sliding["guide"]),
                                 what=phrase("force.the_frame_guide"))
            across = draw.leaning(origin, u, s_slot, (mu, sliding["pin"]), "slotN",
                                  what=phrase("force.the_slot", link=lv.l))
        cross, end_vec, start_vec = draw.close(tip, guide, origin, across, phrase(
            "force.ram_close", r=lv.r, l=lv.l), f"F_1{lv.r}", f"F_{lv.l}{lv.r}")
        n_guide, n_slot = draw.read(end_vec), draw.read(start_vec)
        out.joints[f"F_1{lv.r}"] = n_guide
        out.joints[f"F_{lv.l}{lv.r}"] = n_slot
        out.couples[f"T_1{lv.r}"] = -moment(at[lv.q], known[lv.r])
        f_rl = (-n_slot[0], -n_slot[1])                  # the ram's pin on the lever
        refs += [cross, end_vec, start_vec]
    # The block: its couple from the slot (the slot's push and the crank's pin both at A).
    t_lb = -moment(at[lv.a], known[lv.b])
    out.couples[f"T_{lv.l}{lv.b}"] = t_lb
    # The lever's moments about its pivot give the slot's push ν·n on the block.
    pa = (at[lv.a][0] - at[lv.p][0], at[lv.a][1] - at[lv.p][1])
    ram_moment = 0.0
    if lv.r is not None:
        pq = (at[lv.q][0] - at[lv.p][0], at[lv.q][1] - at[lv.p][1])
        ram_moment = pq[0] * f_rl[1] - pq[1] * f_rl[0]
    nu = (moment(at[lv.p], known[lv.l]) + ram_moment - t_lb) / (pa[0] * n[1] - pa[1] * n[0])
    n_lb = (nu * n[0], nu * n[1])
    if slip is not None:
        # Friction along the slot acts on the slot's line, through the pivot: it leaves the
        # lever's moments, and so ν, as they were, and leans the push against the sliding.
        lean = leaning(n, slip[1]["block"], slip[0], 1.0 if nu >= 0.0 else -1.0)
        n_lb = (nu * lean[0], nu * lean[1])
    out.joints[f"F_{lv.l}{lv.b}"] = n_lb
    # The block's polygon: its loads and the slot's push, closed by the crank's force.
    low = min([s.output.xy[1] for s in c if s.panel is Panel.FORCE
               and isinstance(s.output, g.Point) and not s.id.startswith(("force:o:",
                                                                          "force:h:"))]
              + [0.0])
    start_b = c.give("force:Sb", g.Point(0.0, low - 0.03), label="", panel=Panel.FORCE)
    c.draw("force:say:block", "mark", start_b, panel=Panel.FORCE, label=f"link {lv.b}",
           phrase=phrase(
        "force.block", b=lv.b, l=lv.l, p=lv.p, nu=as_said(abs(nu), "N")))
    tip = draw.loads(lv.b, start_b, known[lv.b])
    tip = draw.vector(f"{lv.l}on{lv.b}", tip, n_lb, label=f"F_{lv.l}{lv.b}")
    closing_b = draw.join("crank", tip, start_b, role=Role.RESULT, label=f"F_{lv.d}{lv.b}")
    f_db = draw.read(closing_b)
    out.joints[f"F_{min(lv.d, lv.b)}{max(lv.d, lv.b)}"] = as_named(f_db, lv.d < lv.b)
    # The lever's polygon: its loads, the block's and the ram's pushes, closed at its pivot,
    # below the block's.
    low = min(s.output.xy[1] for s in c if s.panel is Panel.FORCE
              and isinstance(s.output, g.Point) and not s.id.startswith(("force:o:",
                                                                         "force:h:")))
    start_l = c.give("force:Sl", g.Point(0.0, low - 0.03), label="", panel=Panel.FORCE)
    c.draw("force:say:lever", "mark", start_l, panel=Panel.FORCE, label=f"link {lv.l}",
           phrase=phrase("force.lever", l=lv.l, p=lv.p))
    tip = draw.loads(lv.l, start_l, known[lv.l])
    tip = draw.vector(f"{lv.b}on{lv.l}", tip, (-n_lb[0], -n_lb[1]), label=f"F_{lv.b}{lv.l}")
    if lv.r is not None:
        tip = draw.vector(f"{lv.r}on{lv.l}", tip, f_rl, label=f"F_{lv.r}{lv.l}")
    closing_l = draw.join("pivot", tip, start_l, role=Role.RESULT, label=f"F_1{lv.l}")
    out.joints[f"F_1{lv.l}"] = draw.read(closing_l)
    refs += [closing_b, closing_l]
    for name in list(out.joints) + list(out.couples):
        out.refs[name] = tuple(refs)
    return lv.b, (-f_db[0], -f_db[1]), lv.o, lv.a


def _unit(v: Vec) -> Vec:
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n)
