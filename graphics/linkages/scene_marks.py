"""What a scene draws over the kinematic diagram, after it, each with its step numbers.

* the arrowhead of a swung arc, where the radius was swung to;
* readings: a dimension line with its length, clear of what is drawn; an angle's
  arc with its degrees;
* vectors, heavier for a result, their labels beside their shafts;
* points: a dot and one joined label for points that coincide ("I₁₃ ≡ I₃₄");
* a centre at infinity: a two-headed arrow across its guide, marked "I₁₄ → ∞";
* a point beyond the frame: its edge arrows' label, with its distance from the
  nearest pin;
* the numbers of each working line and arc.
"""

from __future__ import annotations

import math
from functools import partial
from typing import TYPE_CHECKING

from shapely.geometry import LineString
from shapely.geometry import Point as SPoint

from tarsim.constructions import geometry as g
from tarsim.constructions.linkages.centres import Centre
from tarsim.constructions.joints import SlideKind
from tarsim.constructions.measures import Angle, Dimension
from tarsim.constructions.narration import measure_words, numerals, words
from tarsim.constructions.record import Role, Step

from .diagram_slides import block_centre
from ..figure import Circle, Path
from .name_leaders import lead_last_to_shaft, place_led
from ..hiding import hidden
from .lanes import lanes, moved
from .scene_lines import DOT
from ..symbols import draw_arrow, draw_arrowhead, draw_dimension, draw_turning_arrow, unit
from ..typeset import subscript, typeset, typeset_span

if TYPE_CHECKING:
    from .scene import _Scene

__all__ = ["draw_arc_heads", "draw_measures", "plan_vectors", "draw_vectors", "draw_infinities",
           "draw_points", "draw_far", "number_lines"]

GRAZE = 0.5
"""Area (mm²) of a dimension line's clearance an obstacle may take and not be crossed."""
_INF_ARROW = 11.0   # each half of the arrow of a centre at infinity, mm


def draw_arc_heads(scene: _Scene) -> None:
    """Head each swung arc with an arrow where the radius was swung to, if on the page."""
    for step, pts, swung in scene.arcs:
        if swung and scene.clip_box.contains(SPoint(pts[-1])):
            d = unit((pts[-1][0] - pts[-2][0], pts[-1][1] - pts[-2][1]))
            with scene.fig.for_steps(step.id):
                draw_arrowhead(scene.fig, pts[-1], d, length=2.2, width=1.2)


def draw_measures(scene: _Scene) -> None:
    """Readings: a dimension line with its length, an angle's arc with its degrees.

    A dimension stands off its points on the side away from the mechanism, as
    near as it can be without crossing what is drawn. An angle's arc is thin, about
    the vertex, at the reach of the points it was read at; two angles read at one
    vertex (the slow and quick turns of a crank between its limit places) stand
    outside that circle at two radii, so each arc is told by its place, its degrees
    beside it. Its head shows the sense it was read in. Dimensions go first,
    so the degrees keep clear of them.
    """
    measures = [s for s in scene.steps if isinstance(s.output, (Dimension, Angle))]
    for step in sorted(measures, key=lambda s: isinstance(s.output, Angle)):
        out = step.output
        with scene.fig.for_steps(step.id):
            if isinstance(out, Dimension):
                _draw_dimension(scene, step, out)
                continue
            centre, radius = scene.angle_arc(step)
            at = draw_turning_arrow(scene.fig, centre, radius, out.start, out.sweep, "dimension")
            degrees = "" if "answers" in hidden() else f"{numerals(f'{out.degrees:.2f}')}°"
            text = f"{degrees} {words(step.label)}".strip()
            scene.label(text, at, [step], prefer=out.start + out.sweep / 2, gap=1.6, size=3.2)


def _draw_dimension(scene: _Scene, step: Step, out: Dimension) -> None:
    a, b = scene.view(out.start.xy), scene.view(out.end.xy)
    u = unit((b[0] - a[0], b[1] - a[1]))
    n = (-u[1], u[0])
    mid = ((a[0] + b[0]) / 2 - scene.centre[0], (a[1] + b[1]) / 2 - scene.centre[1])
    lean = n[0] * mid[0] + n[1] * mid[1]
    if lean < 0 or (abs(lean) < 1e-9 and n[1] > 0):
        n = (-n[0], -n[1])

    def line_at(off, side):
        return [(a[0] + off * side[0], a[1] + off * side[1]),
                (b[0] + off * side[0], b[1] + off * side[1])]

    def crosses(off, side) -> bool:
        """Whether the dimension line at ``off`` crosses anything drawn, its ends apart:
        a span that ends on a line (a foot on the coupler) touches it at its end on
        either side, and a graze there is no crossing."""
        trim = min(3.0, math.dist(a, b) / 4)
        (x0, y0), (x1, y1) = line_at(off, side)
        inner = LineString([(x0 + trim * u[0], y0 + trim * u[1]),
                            (x1 - trim * u[0], y1 - trim * u[1])])
        return scene.placer.overlap(inner.buffer(2.5)) > GRAZE

    # The line and its reading stand outside the frame of the points: the page's
    # edge is no obstacle. The nearest offset that crosses nothing drawn is taken, on
    # the outer side if it has one, else on the inner (a perpendicular dropped from a
    # pivot has its link beside it on one side).
    page, scene.placer.page = scene.placer.page, None
    out_n = n
    offset, n = min(((off, side) for side in (out_n, (-out_n[0], -out_n[1]))
                     for off in (7.0, 11.0, 15.0, 19.0)),
                    key=lambda c: (crosses(*c), c[1] != out_n, c[0]))
    at = draw_dimension(scene.fig, a, b, n, offset)
    scene.placer.block_path(line_at(offset, n), 1.0)
    for end in (a, b):          # and its extension lines, out past the line
        scene.placer.block_path([end, (end[0] + (offset + 1.6) * n[0],
                                       end[1] + (offset + 1.6) * n[1])], 0.3)
    length = "" if "answers" in hidden() else measure_words(scene.m.units.length_drawn(out.length))
    text = f"{typeset_span(words(step.label))} {length}".strip()
    scene.label(text, at, [step], prefer=math.atan2(-n[1], n[0]), gap=1.0, size=3.4)
    scene.placer.page = page


def plan_vectors(scene: _Scene) -> None:
    """Give each vector its lane and take the room it will be drawn in.

    A vector that would lie along a link (a component laid off along the rod it
    belongs to) or along another vector is drawn in a lane beside it
    (:func:`.lanes.lanes`), true in length and direction, with a leader from each end
    to its point. Its shaft, head and leaders are taken before the mechanism's points are
    named, so a pin's name does not stand where the arrow moved to."""
    drawn = [s for s in scene.steps if isinstance(s.output, g.Segment)
             and s.id not in scene.off_page]
    ends = [(scene.view(s.output.start.xy), scene.view(s.output.end.xy)) for s in drawn]
    links = [(it.points[k], it.points[(k + 1) % len(it.points)]) for it in scene.fig.items
             if isinstance(it, Path) and it.style in ("link", "plate", "block")
             for k in range(len(it.points) - (0 if it.closed else 1))]
    lane = lanes(ends, [s.role is not Role.CONSTRUCTION for s in drawn], fixed=links)
    scene.vector_lanes = list(zip(drawn, ends, lane))
    for _, true, k in scene.vector_lanes:
        a, b = moved(true, k)
        if k and math.dist(a, b) >= 0.5:
            scene.placer.block_path([a, b], 1.6)
            scene.placer.block_head(b, a)
            for end, point in zip((a, b), true):
                if math.dist(end, point) > 0.5:
                    scene.placer.block_path([point, end], 0.3)


def draw_vectors(scene: _Scene) -> None:
    """Draw each vector on the page in its lane (:func:`plan_vectors`), heavier for a
    result, and name it beside its shaft: on its lane's side, if moved into one."""
    scene.placer.name_vectors(moved(seg, k) for s, seg, k in scene.vector_lanes if s.label)
    # Every arrow and leader first, then the names, each clear of them all.
    for step, seg, k in scene.vector_lanes:
        with scene.fig.for_steps(step.id):
            _draw_vector(scene, step, seg, k)
    for step, seg, k in scene.vector_lanes:
        with scene.fig.for_steps(step.id):
            _name_vector(scene, step, moved(seg, k), k)


def _draw_vector(scene: _Scene, step: Step, true, lane: int) -> None:
    a, b = moved(true, lane)
    if math.dist(a, b) < 0.5:
        return
    result = step.role is Role.RESULT
    draw_arrow(scene.fig, a, b, "vector_result" if result else "vector",
               head=3.2 if result else 2.8, width=1.6 if result else 1.4)
    for end, point in zip((a, b), true):
        if math.dist(end, point) > 0.5:
            scene.fig.add(Path((point, end), "leader"))


def _name_vector(scene: _Scene, step: Step, drawn, lane: int) -> None:
    a, b = drawn
    text, sub = typeset(step.label) if step.label else ("", "")
    if math.dist(a, b) < 0.5:
        scene.label(f"{text}{sub} = 0" if text else "", a, [step])
        return
    d = unit((b[0] - a[0], b[1] - a[1]))
    normal = math.atan2(d[0], d[1])     # the paper normal (dy, −dx) as a paper angle
    # Moved into a lane, (−dy, dx) a lane, it is named on that side, away from what it
    # was moved off, unless that side is taken.
    sides = (normal, normal + math.pi) if lane <= 0 else (normal + math.pi, normal)
    anchors = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
               for t in (0.6, 0.45, 0.75, 0.3, 0.9)]
    before = len(scene.fig.items)
    scene.label(text, anchors, [step], sub=sub, prefer=sides,
                spread=math.pi / 3, gap=1.2, size=3.6, own=(a, b) if text else None)
    lead_last_to_shaft(scene.fig, scene.placer, (a, b), before)


def draw_points(scene: _Scene) -> None:
    """Dots and labels; coincident points share one dot and one joined label."""
    groups: list[list[Step]] = []
    far = {s.id for s, _ in scene.far}
    for step in scene.steps:
        out = step.output
        if not isinstance(out, g.Point) or out.is_at_infinity or not step.draws \
                or step.id in far:
            continue
        for grp in groups:
            if scene.coincide(grp[0].output, out):
                grp.append(step)
                break
        else:
            groups.append([step])
    for grp in groups:
        p = grp[0].output.xy
        at = scene.view(p)
        pin = scene.is_pin(p)
        ids = tuple(s.id for s in grp)
        if not pin and not any(scene.coincide(grp[0].output, e) for e in scene.ends):
            scene.fig.add(Circle(at, DOT, "dot", steps=ids))
        names = list(dict.fromkeys(typeset(s.label)[0] for s in grp if s.label))
        away = (at[0] - scene.centre[0], at[1] - scene.centre[1])
        prefer = math.atan2(-away[1], away[0]) if math.hypot(*away) > 1e-6 else math.pi / 4
        with scene.fig.for_steps(*ids):
            place_led(scene.fig, scene.placer, at, partial(
                scene.label, " ≡ ".join(names), at, grp, prefer=prefer,
                gap=2.2 if pin else 1.2, own=at if names else None, beside=True))


def draw_infinities(scene: _Scene) -> None:
    """A centre at infinity: a two-headed arrow across its guide, marked "I₁₄ → ∞", clear
    of the vectors drawn (a velocity turned at a slider's block runs up beside it)."""
    infinite = [s for s in scene.steps if isinstance(s.output, g.Point)
                and s.output.is_at_infinity]
    if infinite:
        for _, true, k in scene.vector_lanes:
            if not k:       # one moved into a lane is taken already
                scene.placer.block_path(list(true), 1.0)
    for step in infinite:
        out = step.output
        at, along, clear = _infinity_anchor(scene, step)
        u = unit(scene.view.direction(out.direction))
        along = along or (-u[1], u[0])
        best = None
        for rank, off in enumerate((clear, -clear, clear + 5, -clear - 5, clear + 10,
                                    -clear - 10)):
            base = (at[0] + off * along[0], at[1] + off * along[1])
            a = (base[0] - _INF_ARROW * u[0], base[1] - _INF_ARROW * u[1])
            b = (base[0] + _INF_ARROW * u[0], base[1] + _INF_ARROW * u[1])
            cost = scene.placer.overlap(LineString([a, b]).buffer(1.0))
            if best is None or (cost, rank) < best[:2]:
                best = (cost, rank, base, a, b)
        _, _, base, a, b = best
        with scene.fig.for_steps(step.id):
            draw_arrow(scene.fig, base, b, "arrow", head=2.4, width=1.3)
            draw_arrow(scene.fig, base, a, "arrow", head=2.4, width=1.3)
            scene.placer.block_path([a, b], 1.6)
            text = (typeset(step.label)[0] + " → ∞") if step.label else "→ ∞"
            scene.label(text, [b, a], [step],
                        prefer=(math.atan2(-u[1], u[0]), math.atan2(u[1], -u[0])), gap=1.0)


def _infinity_anchor(scene: _Scene, step: Step):
    """Where a centre at infinity is drawn: beside its block, else on its line, else mid-page.

    Returns the paper point, the direction to step aside along (or None) and how far.
    """
    if isinstance(step.about, Centre):
        pair = step.about.pair
        for i, s in enumerate(scene.m.slides):
            if s.kind is SlideKind.BLOCK and tuple(sorted((s.link, s.guide_link))) == pair:
                at = block_centre(scene, s)
                return at, unit(scene.view.direction(scene.asm.guide(i).direction)), 7.5
    for r in step.inputs:
        line = scene.c.output(r)
        if isinstance(line, g.Line) and not line.is_at_infinity:
            on = [scene.paper[n] for n, p in scene.world.items() if scene.on_line(line, p)]
            if on:
                return min(on, key=lambda q: math.dist(q, scene.centre)), None, 6.0
    return scene.centre, None, 0.0


def draw_far(scene: _Scene) -> None:
    """Draw the edge arrows toward each far point, labelled with its distance from a pin."""
    for step, p, arrows in scene.edge_arrows:
        with scene.fig.for_steps(step.id):
            _draw_far(scene, step, p, arrows)


def _draw_far(scene: _Scene, step: Step, p: tuple[float, float], arrows: list) -> None:
    for tail, tip in arrows:
        draw_arrow(scene.fig, tail, tip, "edge_arrow", head=2.8, width=1.5)
    near, dist = min(((n, math.dist(p, q)) for n, q in scene.world.items()),
                     key=lambda nd: nd[1])
    name = typeset(step.label)[0] if step.label else words("a point")
    text = words("to {name}, {length} from {near}", name=name,
                 length=_length(dist, scene.m.units), near=subscript(near))
    # A vector drawn at the far point is off the page too: its number goes here.
    riders = [v for v in scene.steps if v.id in scene.off_page and scene.far_base(v) is step]
    tail, tip = arrows[0]
    ahead = math.atan2(tail[1] - tip[1], tip[0] - tail[0])
    # The label reads on from the arrow, past the page's frame if need be.
    page, scene.placer.page = scene.placer.page, None
    scene.label(text, [tip, tail], [step, *riders], prefer=(ahead, ahead + math.pi / 2,
                                                            ahead - math.pi / 2),
                gap=1.0, size=3.2, spread=math.pi / 2)
    # Every other line running to it ends in an arrow of its own: named too, so that no
    # arrow at the edge points nowhere and the named one is not taken for another line's.
    for tail, tip in arrows[1:] if step.label else ():
        ahead = math.atan2(tail[1] - tip[1], tip[0] - tail[0])
        scene.label(name, [tip, tail], [], prefer=(ahead, ahead + math.pi / 2,
                                                   ahead - math.pi / 2),
                    gap=1.0, size=3.2, spread=math.pi / 2, own=tip)
    scene.placer.page = page


def number_lines(scene: _Scene) -> None:
    """Each line's numbers beside it, toward its far end; each arc's beside its middle."""
    for steps, ends in scene.lines:
        if ends is None:
            continue
        a, b = sorted(ends, key=lambda e: math.dist(e, scene.centre))
        d = unit((b[0] - a[0], b[1] - a[1]))
        normal = math.atan2(d[0], d[1])
        anchors = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
                   for t in (0.92, 0.8, 0.68, 0.56, 0.44, 0.32, 0.2, 0.08)]
        with scene.fig.for_steps(*(s.id for s in steps)):
            scene.label("", anchors, steps, prefer=(normal, normal + math.pi),
                        spread=math.pi / 4, gap=0.6)
    numbered: set[str] = set()
    for step, pts, _ in scene.arcs:        # a circle drawn as traces is numbered once
        if step.id not in numbered:
            numbered.add(step.id)
            with scene.fig.for_steps(step.id):
                scene.label("", [pts[len(pts) // 2], pts[-1], pts[0]], [step], gap=0.6)


def _length(metres: float, units) -> str:
    value = metres / units.metres
    text = f"{value:.4g}" if value < 1e4 else f"{value:.0f}"
    return measure_words(f"{text} {units.length}")
