"""The force polygon of the dyad a crank drives (a four-bar's coupler and rocker, or a
slider-crank's rod and block), from the output back to the crank.

The pin force F_A at the coupler's outer pin A is split into its part square to AB, found
from the coupler's moments about the middle pin B (F_Aᵗ·AB = −ΣM_B), and its part along
AB, unknown. A rocker's pin at its frame pivot C is split the same way about B; a block's
guide pushes square to the guide. The dyad's force polygon lays every known load and the
two square parts head to tail; a line along AB through its start and a line along CB (or
square to the guide) through its end close it where they cross. The middle pin's force is
read off one link's own polygon, and a block's couple from its moments about B.

With no load on the output the coupler is a three-force member, and the course's
construction (the three forces meet in one point) is drawn instead, where its lines cross
squarely enough. A slider-crank's piston effort and the wall's thrust are read here too.
"""

from __future__ import annotations

import math
import sys

from .. import geometry as g
from ..errors import TarsimError
from ..loads import leaning, stroke_axis
from ..narration import phrase
from ..record import Kind, Panel
from .drafting import as_named, as_said, friction_angle, moment, push_side, vector_sum
from .groups import Dyad
from .result import Forces

__all__ = ["OBLIQUE", "dyad_polygon"]

Vec = tuple[float, float]


OBLIQUE = 10.0
"""How many times more obliquely than the split's the three-force construction's lines may
cross (a digit of the forces given up for the construction the course teaches for an
unloaded output): a couple that dwarfs the coupler's resultant throws X far off, where AX
and the output's line all but run together and the forces are lost to X's rounding."""


def dyad_polygon(c, draw, out: Forces, sh: Dyad, at, known, slip=None):
    """A four-bar's or slider-crank's dyad: returns the coupler's link, its pull on the
    crank at A, and the crank's pivot and pin. With no load on the output the coupler is a
    three-force member, solved by :func:`_concurrent` where its lines cross squarely enough;
    else by the tangential and normal split."""
    if not _carries(known[sh.j]):
        done = _concurrent(c, draw, out, sh, at, known[sh.i], slip)
        if done is not None:
            return done
    line_ab = c.draw("force:line:AB", "line_through", c.points[sh.a], c.points[sh.b],
                     kind=Kind.LINE, panel=Panel.FORCE)
    pole = c.give("force:S", g.Point(0.0, 0.0), label="", panel=Panel.FORCE)
    c.draw("force:say:dyad", "mark", pole, panel=Panel.FORCE, label=f"links {sh.i}, {sh.j}",
           phrase=phrase("force.dyad", i=sh.i, j=sh.j))
    tip = pole
    for k in (sh.i, sh.j):
        tip = draw.loads(k, tip, known[k])
    t_a = _square(at[sh.a], at[sh.b], known[sh.i])       # F_{d i}ᵗ on i at A
    tip = draw.vector(f"t:{sh.d}{sh.i}", tip, t_a, phrase(
        "force.tangential", name=f"F_{sh.d}{sh.i}", pin=sh.a, link=sh.i, about=sh.b),
        label=f"F_{sh.d}{sh.i}ᵗ")
    if sh.c is not None:
        t_c = _square(at[sh.c], at[sh.b], known[sh.j])   # F_{1 j}ᵗ on j at C
        tip = draw.vector(f"t:1{sh.j}", tip, t_c, phrase(
            "force.tangential", name=f"F_1{sh.j}", pin=sh.c, link=sh.j, about=sh.b),
            label=f"F_1{sh.j}ᵗ")
        far = c.draw("force:line:CB", "line_through", c.points[sh.c], c.points[sh.b],
                     kind=Kind.LINE, panel=Panel.FORCE)
    else:
        t_c = (0.0, 0.0)
        if slip is None:
            far = draw.square_to(pole, sh.guide, "N")
        else:
            laid = vector_sum([f for k in (sh.i, sh.j) for _, f, _, _ in known[k]] + [t_a])
            along_ab = (at[sh.b][0] - at[sh.a][0], at[sh.b][1] - at[sh.a][1])
            far = draw.leaning(pole, sh.guide, push_side(laid, sh.guide, slip, along_ab), slip)
    cross, end_vec, start_vec = draw.close(tip, far, pole, line_ab, phrase(
        "force.close", i=sh.i, j=sh.j), f"F_1{sh.j}" + ("ⁿ" if sh.c else ""),
        f"F_{sh.d}{sh.i}ⁿ")
    n_far, n_a = draw.read(end_vec), draw.read(start_vec)
    f_di = (t_a[0] + n_a[0], t_a[1] + n_a[1])
    joint_j = (t_c[0] + n_far[0], t_c[1] + n_far[1])
    out.joints[f"F_{min(sh.d, sh.i)}{max(sh.d, sh.i)}"] = as_named(f_di, sh.d < sh.i)
    out.joints[f"F_1{sh.j}"] = joint_j
    # The middle pin, from the output's own balance: F_ij = −(its loads + the frame's).
    loads_j = vector_sum(f for _, f, _, _ in known[sh.j])
    f_ij = (-(loads_j[0] + joint_j[0]), -(loads_j[1] + joint_j[1]))    # i on j
    out.joints[f"F_{min(sh.i, sh.j)}{max(sh.i, sh.j)}"] = as_named(f_ij, sh.i < sh.j)
    refs = (cross, end_vec, start_vec)
    out.refs = {name: refs for name in out.joints}
    if sh.c is None:
        # The block's couple from the guide: its moments about B vanish.
        out.couples[f"T_1{sh.j}"] = -moment(at[sh.b], known[sh.j])
        out.refs[f"T_1{sh.j}"] = refs
        _piston_effort(c, out, sh, at, known[sh.j], joint_j, refs)
    return sh.i, (-f_di[0], -f_di[1]), sh.o, sh.a


def _carries(loads) -> bool:
    """Whether any of ``loads`` is a force or a couple at all."""
    return any(f != (0.0, 0.0) or m != 0.0 for _, f, m, _ in loads)


def _square(pin: Vec, middle: Vec, loads) -> Vec:
    """The part of a pin force at ``pin`` square to pin → middle that holds the link's other
    loads about ``middle``: F ᵗ·|pin middle| balances their moment."""
    dx, dy = pin[0] - middle[0], pin[1] - middle[1]
    length = math.hypot(dx, dy)
    u = (-dy / length, dx / length)                # square to the line
    t = -moment(middle, loads) / (dx * u[1] - dy * u[0])
    return (t * u[0], t * u[1])


def _concurrent(c, draw, out: Forces, sh: Dyad, at, loads, slip=None):
    """The dyad when its output carries nothing: the output is a two-force member (a rocker
    pulls along CB; a massless block only across its guide), so the coupler holds three
    forces, its loads' resultant R, the output's push along that known line through B, and
    the crank's at A. Three forces in balance meet in one point: X, where R's line crosses
    the output's; the crank's force runs along AX. The coupler's polygon, R closed by a
    parallel to each line, gives both. Returns as :func:`dyad_polygon` does, or None when R is
    nothing, runs parallel to the output's line (X at infinity), or its lines cross
    :data:`OBLIQUE` times less squarely than the split's AB does with the output's line
    (:func:`_squareness`): the split then serves.
    """
    r = vector_sum(f for _, f, _, _ in loads)
    size = math.hypot(*r)
    if size == 0.0:
        return None
    # R's line: where R alone has the loads' moment about B; Q on it is the foot of the
    # loads' middle (a single load's own point).
    m_b = moment(at[sh.b], loads)
    on = (at[sh.b][0] + m_b * r[1] / size ** 2, at[sh.b][1] - m_b * r[0] / size ** 2)
    mid = vector_sum(p for p, f, _, _ in loads if f != (0.0, 0.0))
    count = sum(f != (0.0, 0.0) for _, f, _, _ in loads)
    mid = (mid[0] / count, mid[1] / count) if count else on
    t = ((mid[0] - on[0]) * r[0] + (mid[1] - on[1]) * r[1]) / size ** 2
    q = (on[0] + t * r[0], on[1] + t * r[1])
    if sh.c is not None:
        dx, dy = at[sh.b][0] - at[sh.c][0], at[sh.b][1] - at[sh.c][1]
    elif slip is None:
        dx, dy = -sh.guide[1], sh.guide[0]
    else:
        # The block's push leans against its sliding, on the side the coupler's balance
        # puts it: R and the push meet at X, the crank's force runs along AX.
        def balance_at(u):
            x_at = _crossing(q, r, at[sh.b], u)
            return None if x_at is None else (x_at[0] - at[sh.a][0], x_at[1] - at[sh.a][1])
        side = push_side(r, sh.guide, slip, None, balance_at)
        dx, dy = leaning((-sh.guide[1], sh.guide[0]), slip[1], slip[0], side)
    if abs(r[0] * dy - r[1] * dx) <= 1e-9 * size * math.hypot(dx, dy):
        return None
    split = abs(_sine((at[sh.b][0] - at[sh.a][0], at[sh.b][1] - at[sh.a][1]), (dx, dy)))
    if _squareness(at, sh, q, r, (dx, dy)) * OBLIQUE < split:
        return None
    qp = c.give("force:cc:Q", g.Point(*q), label="")
    along_r = c.give("force:cc:r", g.Line(-r[1] / size, r[0] / size, 0.0), label="",
                     panel=Panel.FORCE)
    line_r = c.draw("force:cc:lineR", "parallel_through", qp, along_r, kind=Kind.LINE,
                    phrase=phrase("force.resultant", i=sh.i, size=as_said(size, "N"), b=sh.b))
    if sh.c is not None:
        line_j = c.draw("force:cc:lineCB", "line_through", c.points[sh.c], c.points[sh.b],
                        kind=Kind.LINE, phrase=phrase("force.two_force", j=sh.j, c=sh.c,
                                                      b=sh.b))
    else:
        # The block's line: square to the guide, or leaned (dx, dy) with friction.
        push = c.give("force:cc:push", g.Line(-dy / math.hypot(dx, dy), dx / math.hypot(dx, dy),
                                              0.0), label="", panel=Panel.FORCE)
        line_j = c.draw("force:cc:lineN", "parallel_through", c.points[sh.b], push,
                        kind=Kind.LINE, phrase=phrase(
                            "force.massless_block" if slip is None else "force.leaning_block",
                            j=sh.j, b=sh.b, phi=friction_angle(slip)))
    x = c.draw("force:cc:X", "intersect_lines", line_r, line_j, label="X",
               phrase=phrase("force.concurrent", i=sh.i, a=sh.a))
    line_a = c.draw("force:cc:lineAX", "line_through", c.points[sh.a], x, kind=Kind.LINE)
    pole = c.give("force:S", g.Point(0.0, 0.0), label="", panel=Panel.FORCE)
    c.draw("force:say:three", "mark", pole, panel=Panel.FORCE, label=f"link {sh.i}",
           phrase=phrase("force.three", i=sh.i))
    tip = draw.loads(sh.i, pole, loads)
    cross, end_vec, start_vec = draw.close(tip, line_j, pole, line_a, phrase(
        "force.close_three", i=sh.i, j=sh.j, a=sh.a), f"F_{sh.j}{sh.i}", f"F_{sh.d}{sh.i}")
    f_ji, f_di = draw.read(end_vec), draw.read(start_vec)
    out.joints[f"F_{min(sh.d, sh.i)}{max(sh.d, sh.i)}"] = as_named(f_di, sh.d < sh.i)
    out.joints[f"F_{min(sh.i, sh.j)}{max(sh.i, sh.j)}"] = as_named((-f_ji[0], -f_ji[1]),
                                                                   sh.i < sh.j)
    out.joints[f"F_1{sh.j}"] = f_ji             # the frame holds the output against it
    refs = (x, cross, end_vec, start_vec)
    out.refs = {name: refs for name in out.joints}
    if sh.c is None:
        out.couples[f"T_1{sh.j}"] = 0.0          # every force on the block acts through B
        out.refs[f"T_1{sh.j}"] = refs
        _piston_effort(c, out, sh, at, [], f_ji, refs)
    return sh.i, (-f_di[0], -f_di[1]), sh.o, sh.a


def _crossing(p: Vec, u: Vec, q: Vec, w: Vec) -> Vec | None:
    """Where the line through ``p`` along ``u`` meets the one through ``q`` along ``w``."""
    det = u[0] * w[1] - u[1] * w[0]
    if abs(det) <= 1e-12 * math.hypot(*u) * math.hypot(*w):
        return None
    t = ((q[0] - p[0]) * w[1] - (q[1] - p[1]) * w[0]) / det
    return (p[0] + t * u[0], p[1] + t * u[1])


def _sine(u: Vec, w: Vec) -> float:
    """The sine of the angle from ``u`` to ``w``."""
    return (u[0] * w[1] - u[1] * w[0]) / (math.hypot(*u) * math.hypot(*w))


def _squareness(at, sh: Dyad, q: Vec, r: Vec, push: Vec) -> float:
    """How squarely the three-force construction's lines cross (the sine of the worse of its
    two crossings): R's line through ``q`` with the output's line (along ``push``) at X, and
    then AX with that line, which closes the polygon. X far beyond the mechanism (a couple
    that dwarfs the resultant throws R's line there) makes AX and the output's line nearly
    parallel: their difference, and every force, is then lost to the rounding of X."""
    x = _crossing(q, r, at[sh.b], push)
    if x is None:
        return 0.0
    ax = (x[0] - at[sh.a][0], x[1] - at[sh.a][1])
    return min(abs(_sine(r, push)), abs(_sine(ax, push)) if ax != (0.0, 0.0) else 0.0)


def _piston_effort(c, out: Forces, sh: Dyad, at, loads, wall: Vec, refs) -> None:
    """A slider-crank's piston effort, its loads along the stroke (laid off head to tail in
    the polygon, so their sum runs from its start to the end of the piston's part), and the
    wall's thrust, the guide's push the polygon closed on.

    Raises
    ------
    TarsimError
        Where the piston stands level with the crank's pivot along the stroke (to the
        rounding of the drawing): "toward the crank" has no sense there.
    """
    (ox, oy), (bx, by) = at[sh.o], at[sh.b]
    size = max(math.dist(at[sh.o], p) for p in at.values())
    if abs((ox - bx) * sh.guide[0] + (oy - by) * sh.guide[1]) <= 64 * sys.float_info.epsilon * size:
        m = c.mechanism
        raise TarsimError(f"piston_effort at θ{m.drive.link} = "
                          f"{m.units.angle_brief(m.drive.angle)}: the piston {sh.b} stands level "
                          f"with the crank's pivot {sh.o} along its stroke, so 'toward the crank' "
                          f"has no sense; ask F_{sh.i}{sh.j} and F_1{sh.j}")
    u = stroke_axis(at[sh.o], at[sh.b], sh.guide)
    piston = vector_sum(f for _, f, _, _ in loads)
    out.efforts["piston_effort"] = piston[0] * u[0] + piston[1] * u[1]
    out.efforts["wall_thrust"] = abs(-wall[0] * sh.guide[1] + wall[1] * sh.guide[0])
    # the reciprocating parts' m·a toward the crank, which the piston effort loses
    fi = next((f for _, f, _, name in loads if name == f"Fi{sh.j}"), (0.0, 0.0))
    out.efforts["inertia_force"] = -(fi[0] * u[0] + fi[1] * u[1])
    said = c.draw("force:say:piston", "mark", refs[0], panel=Panel.FORCE, phrase=phrase(
        "force.piston", j=sh.j, effort=as_said(out.efforts["piston_effort"], "N", ".6g"),
        thrust=as_said(out.efforts["wall_thrust"], "N", ".6g"),
        inertia=as_said(out.efforts["inertia_force"], "N", ".6g")))
    out.refs["piston_effort"] = out.refs["wall_thrust"] = out.refs["inertia_force"] = (
        *refs, said)
