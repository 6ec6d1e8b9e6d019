"""The crank's force polygon, drawn last: the pull of the group it drives and the crank's
own loads close on the frame's force at its pivot, and the moments about the pivot give
the driving torque. The push on the crank pin splits along the crank and square to it, the
crank effort, whose moment about the pivot is the turning moment.
"""

from __future__ import annotations

import math

from .. import geometry as g
from ..checks import NOISE, quiet
from ..loads import crank_tangent
from ..narration import phrase
from ..record import Kind, Panel, Ref, Role
from .drafting import as_said, moment
from .result import Forces

__all__ = ["crank_polygon"]

Vec = tuple[float, float]


def crank_polygon(c, draw, out: Forces, d: int, i: int, f_id: Vec, o: str, a: str, at, known):
    """The crank's polygon, to the right of the rest and clear of it: its loads and the pull
    ``f_id`` of link ``i`` at ``a``, closed by the frame's force at ``o``; its moments about
    ``o`` give the driving torque."""
    drawn = [s.output.xy for s in c if s.panel is Panel.FORCE and isinstance(s.output, g.Point)
             and not s.output.is_at_infinity and not s.id.startswith(("force:o:", "force:h:"))]
    chain = [(0.0, 0.0)]
    for f in [f for _, f, _, _ in known[d]] + [f_id]:
        chain.append((chain[-1][0] + f[0] * out.scale, chain[-1][1] + f[1] * out.scale))
    right = max(x for x, _ in drawn) - min(x for x, _ in chain) + 0.03
    start = c.give("force:S2", g.Point(right, 0.0), label="", panel=Panel.FORCE)
    c.draw("force:say:driver", "mark", start, panel=Panel.FORCE, label=f"link {d}",
           phrase=phrase("force.driver", d=d, i=i, o=o))
    tip = draw.loads(d, start, known[d])
    pulled = tip
    tip = draw.vector(f"{i}on{d}", tip, f_id, label=f"F_{i}{d}")
    _crank_effort(c, draw, out, pulled, tip, f"F_{i}{d}", o, a, at)
    closing = draw.join("frame", tip, start, role=Role.RESULT, label=f"F_1{d}")
    out.joints[f"F_1{d}"] = draw.read(closing)
    out.refs[f"F_1{d}"] = (closing,)
    arm = (at[a][0] - at[o][0], at[a][1] - at[o][1])
    torque = -(moment(at[o], known[d]) + arm[0] * f_id[1] - arm[1] * f_id[0])
    out.torque = torque
    arm_size = math.hypot(*arm)
    said = c.draw("force:say:torque", "mark", start, panel=Panel.FORCE, phrase=phrase(
        "force.torque", d=d, o=o,
        torque=as_said(quiet(torque, 0.08 / out.scale * arm_size), "N·m", ".6g")))
    out.refs[f"T{d}"] = (closing, said)


def _crank_effort(c, draw, out: Forces, tail: Ref, head: Ref, name: str, o: str, a: str,
                  at) -> None:
    """Split the push on the crank pin (drawn from ``tail`` to ``head``) along the crank and
    square to it: through its tail a parallel to the crank, through its head a parallel to
    the crank circle's tangent at the pin; they cross where the radial part ends and the
    tangential part, the crank effort, begins. Its moment about the pivot, effort × crank,
    is the turning moment; the radial part, read toward the shaft, is the thrust on the
    shaft's bearings."""
    t = crank_tangent(at[o], at[a])
    (tx, ty), (hx, hy) = c.output(tail).xy, c.output(head).xy
    push = math.hypot(hx - tx, hy - ty)
    if abs((hx - tx) * t[1] - (hy - ty) * t[0]) <= NOISE * push:
        # Square to the crank already: all of it is crank effort, nothing to split off.
        cross, part, key = head, None, "force.effort_square"
        pushed, radial = ((hx - tx) / draw.scale, (hy - ty) / draw.scale), (0.0, 0.0)
    else:
        crank = c.draw("force:line:crank", "line_through", c.points[o], c.points[a],
                       kind=Kind.LINE, panel=Panel.FORCE)
        tangent = c.draw("force:line:tangent", "perpendicular_through", c.points[a], crank,
                         kind=Kind.LINE, panel=Panel.FORCE)
        radial = c.draw("force:n:radial", "parallel_through", tail, crank, kind=Kind.LINE,
                        panel=Panel.FORCE)
        square = c.draw("force:n:tangential", "parallel_through", head, tangent,
                        kind=Kind.LINE, panel=Panel.FORCE)
        cross = c.draw("force:X:effort", "intersect_lines", radial, square, label="t",
                       panel=Panel.FORCE)
        radial = draw.read(draw.join("radial", tail, cross, label="F_R"))
        part = draw.join("effort", cross, head, label="F_T")
        pushed, key = draw.read(part), "force.effort"
    effort = pushed[0] * t[0] + pushed[1] * t[1]
    r = math.dist(at[o], at[a])
    out.efforts["crank_effort"], out.efforts["turning_moment"] = effort, effort * r
    # the radial part read toward the shaft (the tangent turned a quarter back: pin → pivot)
    bearing = radial[1] * t[0] - radial[0] * t[1]
    out.efforts["bearing_thrust"] = bearing
    loads = 0.08 / draw.scale                    # the largest load, to the rounding of it
    said = c.draw("force:say:effort", "mark", cross, panel=Panel.FORCE, phrase=phrase(
        key, name=name, o=o, a=a, effort=as_said(quiet(effort, loads), "N", ".6g"),
        moment=as_said(quiet(effort * r, loads * r), "N·m", ".6g"),
        radial=as_said(quiet(bearing, loads), "N", ".6g")))
    out.refs["crank_effort"] = out.refs["turning_moment"] = out.refs["bearing_thrust"] = tuple(
        r for r in (cross, part, said) if r is not None)
