"""The scene's working lines: the lines and compass arcs of its steps, under the mechanism.

They are planned once the frame is known and before the diagram names its points,
and drawn first, so that every label keeps clear of them:

* a line spans the points that lie on it, running a little past a constructed
  point and stopping under a pin's circle; lines drawn by several steps are drawn
  once, in the most telling of their kinds (:data:`LINE_KINDS`), and numbered for
  each;
* a circle is the arc through the points on it that leaves out the widest gap, a
  compass trace through a lone point, or a trace through each point where the
  frame would cut the arc; a swing ends where the radius was swung to;
* a point beyond the frame gets an arrow at the page's edge on each line that runs
  to it, else from mid-page.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from shapely.geometry import LineString
from shapely.geometry import Point as SPoint

from tarsim.constructions import geometry as g
from tarsim.constructions.measures import Angle
from tarsim.constructions.record import Kind, Step

from ..figure import Path, arc_points, clip_line, ray_to_edge, span_line
from ..symbols import PIN_RADIUS, unit

if TYPE_CHECKING:
    from .scene import _Scene

__all__ = ["line_style", "LINE_KINDS", "SAME", "DOT", "plan_line", "plan_circle", "plan_far",
           "draw_working"]

LINE_KINDS = {
    Kind.KENNEDY_LINE: ("kennedy", "Kennedy line"),
    Kind.COMMON_NORMAL: ("normal", "common normal"),
    Kind.GAUGE_LINE: ("gauge", "gauge line"),
    Kind.LINE: ("working", "construction line"),
}
"""Each kind of line: its style and its name in the legend."""

_PRIORITY = (Kind.COMMON_NORMAL, Kind.GAUGE_LINE, Kind.KENNEDY_LINE, Kind.LINE)
"""Which kind shows when lines drawn by several steps coincide."""
_OVERHANG = 4.0     # a line runs this far past its last point, mm
_LONE = 12.0        # a line through one point runs this far either side, mm
_TRACE = 4.0        # a compass trace through one point runs this far either side, mm
DOT = 0.6           # a marked point, mm
SAME = 1e-9         # relative slack for "lies on" and "coincides"


def line_style(step: Step) -> str:
    """The style a line step is drawn in, by its kind: a guide or axis of the mechanism
    drawn as a working line, as any line the kinds do not name.

    Examples
    --------
    >>> from tarsim.constructions.record import Construction
    >>> c = Construction()
    >>> _ = c.give("l", g.Line(0.0, 1.0, 0.0), label="", kind=Kind.KENNEDY_LINE)
    >>> line_style(c["l"])
    'kennedy'
    """
    return LINE_KINDS.get(step.kind, LINE_KINDS[Kind.LINE])[0]


def plan_line(scene: _Scene, step: Step) -> None:
    """Span the points on the line, clipped to the frame; the same line again gains a number."""
    line: g.Line = step.output
    for steps, _ in scene.lines:
        other = steps[0].output
        if (abs(other.a * line.b - other.b * line.a) <= SAME
                and scene.on_line(other, line.anchor())):
            steps.append(step)
            return
    d = scene.view.direction(line.direction)
    # The paper line, measured from the foot of the frame's centre.
    a = scene.view(line.anchor())
    mid = ((scene.clip[0] + scene.clip[2]) / 2, (scene.clip[1] + scene.clip[3]) / 2)
    t_mid = (mid[0] - a[0]) * d[0] + (mid[1] - a[1]) * d[1]
    base = (a[0] + t_mid * d[0], a[1] + t_mid * d[1])
    # Past a constructed point the line runs on a little, to show the cut; at a
    # pin it stops under the pin's circle.
    stops = [(scene.view(p), PIN_RADIUS if scene.is_pin(p) else _OVERHANG)
             for _, p in scene.points if scene.on_line(line, p)]
    lo, hi = span_line(base, d, stops, _LONE)
    scene.lines.append(([step], clip_line(base, d, lo, hi, scene.clip)))


def _within(scene: _Scene, pts) -> bool:
    """True if every paper point lies in the frame's clip box."""
    x0, y0, x1, y1 = scene.clip
    return all(x0 <= x <= x1 and y0 <= y <= y1 for x, y in pts)


def _arc_of(scene: _Scene, step: Step) -> tuple[float, float, list[tuple[int, tuple]]]:
    """The arc a circle is drawn as, (start, sweep) in world angles, and the points it
    runs through: the whole circle through none, a compass trace through one (neither
    names its points), else the arc through them all that leaves out the widest gap."""
    circle: g.Circle = step.output
    cw = circle.centre.xy
    tol = SAME * max(scene.size, circle.radius, math.hypot(*cw))
    on = [(i, p) for i, p in scene.points if abs(math.dist(p, cw) - circle.radius) <= tol]
    angles = sorted({round(math.atan2(p[1] - cw[1], p[0] - cw[0]), 12) for _, p in on})
    if not angles:
        return 0.0, 2 * math.pi, []
    if len(angles) == 1:       # a compass trace through the one point
        half = min(_TRACE / (circle.radius * scene.view.scale), math.radians(20))
        return angles[0] - half, 2 * half, []
    gaps = [(angles[(k + 1) % len(angles)] - angles[k]) % (2 * math.pi)
            for k in range(len(angles))]
    k = max(range(len(gaps)), key=gaps.__getitem__)
    return angles[(k + 1) % len(angles)], 2 * math.pi - gaps[k], on


def plan_circle(scene: _Scene, step: Step) -> None:
    """An arc through the points on the circle; a swing ends in an arrow at its new place."""
    circle: g.Circle = step.output
    cw = circle.centre.xy
    c, r = scene.view(cw), circle.radius * scene.view.scale
    start, sweep, on = _arc_of(scene, step)
    if on and step.kind is not Kind.SWING and not _within(scene, arc_points(c, r, start, sweep)):
        # An arc the frame would cut (Klein's circle on the rod) is drawn as a draftsman
        # draws it: a compass trace through each point on it, and no more.
        half = min(_TRACE / r, math.radians(20))
        for _, p in on:
            at = math.atan2(p[1] - cw[1], p[0] - cw[0])
            scene.arcs.append((step, arc_points(c, r, at - half, 2 * half), False))
        return
    swung = step.kind is Kind.SWING and bool(on)
    if swung:
        # The swung-to end is the point located last that is neither a pin nor a
        # vector's end; the arc runs to it.
        def rank(ip):
            i, p = ip
            return -1 if i < 0 or scene.is_pin(p) or not isinstance(
                scene.steps[i].output, g.Point) else i
        last = max(on, key=rank)[1]
        if abs(math.remainder(math.atan2(last[1] - cw[1], last[0] - cw[0]) - start,
                              2 * math.pi)) < 1e-9:
            start, sweep = start + sweep, -sweep
    scene.arcs.append((step, arc_points(c, r, start, sweep), swung))


def plan_far(scene: _Scene) -> None:
    """Arrows at the page's edge toward each far point: on its lines, else from mid-page."""
    scene.edge_arrows: list[tuple[Step, tuple[float, float], list[tuple]]] = []
    for step, p in scene.far:
        q = scene.view(p)
        arrows = []
        for steps, ends in scene.lines:
            if ends is None or not scene.on_line(steps[0].output, p):
                continue
            end = min(ends, key=lambda e: math.dist(e, q))
            u = unit((q[0] - end[0], q[1] - end[1]))
            arrows.append(((end[0] - 7.0 * u[0], end[1] - 7.0 * u[1]), end))
        if not arrows:
            mid = ((scene.clip[0] + scene.clip[2]) / 2, (scene.clip[1] + scene.clip[3]) / 2)
            u = unit((q[0] - mid[0], q[1] - mid[1]))
            tip = ray_to_edge(mid, u, scene.clip)
            arrows.append(((tip[0] - 9.0 * u[0], tip[1] - 9.0 * u[1]), tip))
        arrows.sort(key=lambda a: math.dist(a[1], q))
        scene.edge_arrows.append((step, p, arrows))


def draw_working(scene: _Scene) -> None:
    """Lines and arcs go in first, under the mechanism; the labels will keep clear."""
    for steps, ends in scene.lines:
        # Lines drawn over one another show as the most telling of their kinds.
        kind = min((st.kind if st.kind in LINE_KINDS else Kind.LINE for st in steps),
                   key=_PRIORITY.index)
        if ends is not None:
            scene.kinds += [kind] if kind not in scene.kinds else []
            scene.fig.add(Path(ends, LINE_KINDS[kind][0], steps=tuple(s.id for s in steps)))
            scene.placer.block_path(ends, 0.3)
    for step, pts, _ in scene.arcs:
        for part in _clipped(scene, pts):
            scene.fig.add(Path(tuple(part), "compass", steps=(step.id,)))
            scene.placer.block_path(part, 0.3)
    # Vectors, dots, angles' arcs and edge arrows are drawn on top later; their room is
    # taken now (a point past the frame is an edge arrow, not a dot).
    far = {s.id for s, _ in scene.far}
    for step in scene.steps:
        out = step.output
        if isinstance(out, Angle):
            centre, radius = scene.angle_arc(step)
            scene.placer.block_path(arc_points(centre, radius, out.start, out.sweep), 0.4)
        if isinstance(out, g.Segment) and out.length > 0:
            scene.placer.block_path([scene.view(out.start.xy), scene.view(out.end.xy)], 1.0)
        elif isinstance(out, g.Point) and not out.is_at_infinity and step.draws \
                and step.id not in far:
            scene.placer.block(SPoint(scene.view(out.xy)).buffer(DOT + 0.6))
    for _, _, arrows in scene.edge_arrows:
        for tail, tip in arrows:
            scene.placer.block_path([tail, tip], 1.6)


def _clipped(scene: _Scene, pts: list[tuple[float, float]]) -> list[list[tuple[float, float]]]:
    """The parts of a paper polyline inside the frame."""
    cut = LineString(pts).intersection(scene.clip_box)
    return [list(p.coords) for p in getattr(cut, "geoms", [cut])
            if isinstance(p, LineString) and not p.is_empty and p.length > 0.2]
