"""What the kinematic diagram says: the input's θ and ω, link numbers and point names.

The input is stated twice: on the figure, as θ from a dashed reference along +x and
a turning arrow ω beside the crank, clear of every point the figure marks; and in
the caption's line (:func:`input_caption`). Each moving link's number stands by
its bar or inside its plate, the frame's past a pivot's hatching; each point's name
stands away from the mechanism's middle, and a contact's P off its common normal.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from shapely.geometry import MultiPoint

from tarsim.constructions.model import Mechanism
from tarsim.constructions.narration import significant, words

from .diagram_slides import block_centre, block_lift
from .joint_symbols import symbol_of
from .name_leaders import lead
from ..figure import Text, arc_points
from ..paper_points import centroid, difference, farthest_pair
from ..symbols import draw_turning_arrow, mark_angle, unit
from ..typeset import subscript

if TYPE_CHECKING:
    from .diagram import _Diagram

__all__ = ["input_caption", "draw_input", "label_links", "label_points"]


def input_caption(m: Mechanism) -> str:
    """The input's position and speed as a caption states them: "θ₂ = 60°,  ω₂ = 10 rad/s ccw"
    (six significant figures, a true minus)."""
    d, u = m.drive, m.units
    angle = (f"{significant(d.angle)} rad" if u.angle == "rad"
             else f"{significant(math.degrees(d.angle))}°")
    sub = subscript(str(d.link))
    params = f"θ{sub} = {angle.replace('-', '−')}"
    if d.omega:
        w = abs(d.omega) if u.angular_velocity == "rad/s" else abs(d.omega) * 60 / (2 * math.pi)
        sense = "ccw" if d.omega > 0 else "cw"
        params += f",  ω{sub} = {significant(w)} {u.angular_velocity} {words(sense)}"
    return params


def draw_input(diagram: _Diagram) -> None:
    """Mark the input's θ from a dashed reference along +x, and its ω as a turning arrow."""
    d = diagram.m.drive
    k = diagram.m.link(d.link)
    centre = diagram.paper[k.names[0]]
    theta = math.atan2(math.sin(d.angle), math.cos(d.angle))
    # θ: a dashed reference along +x and an arc up to the crank.
    ref_end = (centre[0] + 13.0, centre[1])
    diagram.fig.line(centre, ref_end, "reference")
    diagram.placer.block_segment(centre, ref_end, 0.3)
    mid = mark_angle(diagram.fig, centre, 8.0, 0.0, theta)
    diagram.placer.block_path(arc_points(centre, 8.0, 0.0, theta), 0.2)    # its name beside it
    half = theta / 2
    diagram.placer.place(f"θ{subscript(str(d.link))}", mid, prefer=half, gap=1.2, size=3.2)
    if d.omega == 0.0:
        return
    # ω: an arc arrow beside the crank, away from the θ mark and its reference line,
    # and clear of every point the figure marks (a centre that falls there keeps its
    # dot clear); its sense is ω's alone.
    first = (0.45, -1.65) if theta >= 0 else (-1.65, 0.45)
    lows = [theta + k for k in (*first, 1.9, -3.1, 3.35)]
    marks = diagram.marks() + [p for n, p in diagram.paper.items() if n != k.names[0]]

    def clearance(low: float) -> float:
        arc = [(centre[0] + 12.0 * math.cos(low + 1.2 * t / 8),
                centre[1] - 12.0 * math.sin(low + 1.2 * t / 8)) for t in range(9)]
        if (-low) % (2 * math.pi) <= 1.2:          # across the reference line
            return 0.0
        return min((math.dist(a, m) for a in arc for m in marks), default=math.inf)
    low = next((w for w in lows if clearance(w) >= 3.0), lows[0])
    start, sweep = (low, 1.2) if d.omega > 0 else (low + 1.2, -1.2)
    label_at = draw_turning_arrow(diagram.fig, centre, 12.0, start, sweep)
    diagram.placer.block_path(arc_points(centre, 12.0, start, sweep), 0.35)
    diagram.placer.place(f"ω{subscript(str(d.link))}", label_at,
                         prefer=start + sweep / 2, gap=1.4, size=3.2)


def label_links(diagram: _Diagram) -> None:
    """Number each moving link by its bar, inside its plate or beside its block; then the frame."""
    for k in diagram.m.links:
        if k.number == 1:
            continue
        slotted = diagram.slotted(k.number)
        pts = diagram.slot_reach(k.number)
        if len(pts) == 1:
            at, prefer = pts[0], math.pi / 2
            gap = 4.2
            lifted = [s for s in diagram.m.slides if s.link == k.number
                      and symbol_of(s).block and block_lift(diagram, s)[1] > 0.0]
            if lifted:  # beside the block standing on the face, not under it
                at, prefer = block_centre(diagram, lifted[0]), (math.pi, 0.0)
        else:
            hull = MultiPoint(pts).convex_hull
            if hull.geom_type == "Polygon" and hull.area > 4.0 and not slotted:
                c = hull.centroid
                diagram.fig.add(Text((c.x, c.y), str(k.number), 3.4, italic=False))
                continue
            a, b = farthest_pair(pts)
            if slotted:
                a, b = diagram.overhang(k.number, a, b)
            at = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
                  for t in (0.55, 0.4, 0.7, 0.25, 0.85)]
            dx, dy = unit(difference(b, a))
            prefer = math.atan2(dx, dy)  # the paper normal (−dy, dx) as a paper angle
            gap = 1.6
        prefer = prefer if isinstance(prefer, tuple) else (prefer, prefer + math.pi)
        diagram.placer.place(str(k.number), at, prefer=prefer,
                             spread=math.pi / 4, gap=gap, size=3.4, italic=False)
    pivots = [n for n in diagram.m.frame.names if len(diagram.links_at(n)) > 1]
    if pivots:
        # Past the pivot's hatching, the way its support stands, away from its links.
        dx, dy = diagram.downs.get(pivots[0], (0.0, 1.0))
        diagram.placer.place("1", diagram.paper[pivots[0]], prefer=math.atan2(-dy, dx),
                             spread=math.pi / 2, gap=7.5, size=3.4, italic=False)
    elif diagram.m.frame.names:
        # No fixed pivot (a wheel rolling on the ground drives): under the ground's
        # hatching at the frame's first point.
        diagram.placer.place("1", diagram.paper[diagram.m.frame.names[0]],
                             prefer=-math.pi / 2, spread=math.pi / 2, gap=7.5, size=3.4,
                             italic=False)


def label_points(diagram: _Diagram) -> None:
    """Name each point away from the mechanism's middle, and each contact's P off its normal."""
    centre = centroid(list(diagram.paper.values()))
    for name, at in diagram.paper.items():
        away = difference(at, centre)
        prefer = math.atan2(-away[1], away[0]) if math.hypot(*away) > 1e-6 else math.pi / 4
        text = diagram.placer.place(subscript(name), at, prefer=prefer, gap=2.0, size=3.6,
                                    own=at)
        lead(diagram.fig, diagram.placer, at, text)
    # P goes beside the contact, off the common normal that runs through it; between
    # two circles, out along the tangent in the gap that opens between them.
    for point, normal, spread, rings in (
            [(k.point, k.away, math.pi, (1.0, 1.6, 2.3)) for k in diagram.contacts]
            + [(k.point, k.normal, math.pi / 8, (1.0, 1.6, 2.3, 3.2, 4.2))
               for k in diagram.pairs]):
        d = diagram.view.direction(normal)
        along = (-d[1], d[0])
        prefer = tuple(math.atan2(-v[1], v[0]) for v in (along, (-along[0], -along[1])))
        diagram.placer.place("P", diagram.view(point), prefer=prefer, spread=spread, gap=1.6,
                             size=3.6, rings=rings)
