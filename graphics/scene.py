"""A scene: the space diagram with a slice of its record drawn on it.

The kinematic diagram is drawn as :func:`~graphics.diagram.draw_kinematic_diagram`
draws it; each step of the scene is then drawn by what its output is, never by
recomputing geometry:

* a line is a thin working line spanning the points that lie on it, in a style
  that tells its kind (Kennedy line, common normal, gauge line, other);
* a circle is a compass arc through the points that lie on it, with an arrowhead
  where a radius was swung to;
* a segment is a vector arrow with its label and a true subscript;
* a point is a dot and its label; coincident points share one dot and one
  label ("I₁₃ ≡ I₃₄"); an instant centre at infinity is a two-headed arrow
  marked "I₁₄ → ∞" across its guide; a point beyond the page's frame is an
  arrow at the page's edge, on each line that runs to it, with its distance.

The page's frame is sized from the mechanism and takes in the scene's points up
to :data:`FRAME_CAP` mechanism extents (or :data:`FRAME_MIN` mm of paper); the
space scale is the kinematic diagram's, chosen with the velocity scale before
anything is drawn (:mod:`tarsim.constructions.scales`).

What the scene shows is a :class:`~tarsim.constructions.record.Slice` of the
record, and every step is styled by its :class:`~tarsim.constructions.record.Kind`
alone. Every step that draws something and is narrated, other than a given,
carries its number in a small circle: the slice's own numbering
(:meth:`~tarsim.constructions.record.Slice.numbered`), so a written solution
numbers its steps the same way.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

from shapely.geometry import LineString, box
from shapely.geometry import Point as SPoint

from ..constructions import geometry as g
from ..constructions.assembly import Assembly
from ..constructions.centres import Centre
from ..constructions.errors import TarsimError
from ..constructions.measures import Angle, Dimension
from ..constructions.model import SlideKind
from ..constructions.narration import measure_words, numerals, words
from ..constructions.record import Kind, Panel, Ref, Role, Slice, Step

from .diagram import _Diagram, input_caption
from .figure import (Circle, Figure, Path, View, arc_points, clip_line, ray_to_edge,
                     span_line)
from .labels import LabelPlacer, subscript, typeset, typeset_span
from .scales import draw_caption
from .symbols import (PIN_RADIUS, draw_arrow, draw_arrowhead, draw_dimension, draw_turning_arrow,
                      unit)

__all__ = ["draw_scene", "line_style", "FRAME_CAP", "FRAME_MIN", "LINE_KINDS"]

FRAME_CAP = 1.6
"""The page's frame grows to take in the scene's points up to this many mechanism extents..."""

FRAME_MIN = 190.0
"""...or this many millimetres of paper, whichever is more; beyond, a point is off the page."""

LINE_KINDS = {
    Kind.KENNEDY_LINE: ("kennedy", "Kennedy line"),
    Kind.COMMON_NORMAL: ("normal", "common normal"),
    Kind.GAUGE_LINE: ("gauge", "gauge line"),
    Kind.LINE: ("working", "construction line"),
}
"""Each kind of line: its style and its name in the legend."""

_PRIORITY = (Kind.COMMON_NORMAL, Kind.GAUGE_LINE, Kind.KENNEDY_LINE, Kind.LINE)
"""Which kind shows when lines drawn by several steps coincide."""
_MARGIN = 8.0       # white round the drawing, mm (as the kinematic diagram)
_REACH = 6.0        # mm a ground symbol reaches from its pivot: a line shorter past it is no ray
_EDGE = 9.0         # room between the frame's points and the clip edge, mm
_OVERHANG = 4.0     # a line runs this far past its last point, mm
_LONE = 12.0        # a line through one point runs this far either side, mm
_TRACE = 4.0        # a compass trace through one point runs this far either side, mm
_DOT = 0.6          # a marked point, mm
GRAZE = 0.5
"""Area (mm²) of a dimension line's clearance an obstacle may take and not be crossed."""
_INF_ARROW = 11.0   # each half of the arrow of a centre at infinity, mm
_SAME = 1e-9        # relative slack for "lies on" and "coincides"


# ----- the public functions -----------------------------------------------------------------
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


Overlay = Callable[[View, Figure, LabelPlacer],
                   Callable[[], tuple[tuple[str, float, str], list, list]]]
"""Draws over a diagram, on paper by its view, before the diagram names its points (so
that they keep clear of it), and returns what names it after them, with the diagram's own
label placer, and then gives the second scale it drew at (name, per cm, unit), the legend
entries (style, words) and the notes it adds."""


def draw_scene(shown: Slice, *, title: str | None = None,
               velocity_scale: float | None = None, notes: Sequence[str] = (),
               per_cm: float | None = None, velocity_stated: float | None = None,
               overlay: Overlay | None = None) -> Figure:
    """Draw the kinematic diagram of a position's record with the steps of a slice of it.

    Parameters
    ----------
    shown
        What the figure shows: a slice of a position's record (an
        :class:`~tarsim.constructions.assembly.Assembly`). Its space-panel steps are
        drawn over the mechanism, in its order, and numbered as it numbers them.
    title
        The caption's heading; the mechanism's name when None.
    velocity_scale
        Drawing metres per m/s of the velocity vectors among the steps; the
        caption then states it as "Velocity scale 1 cm = N unit/s".
    notes
        Short lines printed under the caption (warnings, remarks).
    per_cm
        The space scale (file units per paper cm), as the solution chose it; by
        default the kinematic diagram's own.
    velocity_stated
        The velocity scale the exercise states (file units/s per paper cm, a
        :class:`~tarsim.constructions.scales.Stated`): the caption words it as the
        exercise does when the vectors are drawn at it.
    overlay
        What is drawn over the diagram at a scale of its own (the loads on the links at a
        force scale), before the caption, which states that scale.

    Raises
    ------
    TarsimError
        If the slice is not of a mechanism's record.
    """
    if not isinstance(shown.construction, Assembly):
        raise TarsimError("a scene is a slice of a mechanism's record (an assembly)")
    scene = _Scene(shown, title, velocity_scale, notes, per_cm, velocity_stated)
    scene.overlay = overlay
    return scene.draw()


# ----- what a step draws --------------------------------------------------------------------
def _segment_ends(steps: list[Step]) -> list[g.Point]:
    return [p for s in steps if isinstance(s.output, g.Segment)
            for p in (s.output.start, s.output.end)]


# ----- the figure ------------------------------------------------------------------------------
class _Scene(_Diagram):
    """The kinematic diagram, then the scene's layers: working lines under it, marks over it."""

    def __init__(self, shown: Slice, title: str | None, velocity_scale: float | None,
                 notes: Sequence[str], per_cm: float | None,
                 velocity_stated: float | None = None):
        super().__init__(shown.construction, per_cm)
        self.velocity_stated = velocity_stated
        self.steps = shown.steps(Panel.SPACE)
        steps = self.steps
        self.title = title
        self.velocity_scale = velocity_scale
        self.notes = tuple(notes)
        self.c = self.asm
        self.numbers = shown.numbers(Panel.SPACE)
        self.ends = _segment_ends(steps)
        self.kinds: list[str] = []
        self.overlay: Overlay | None = None
        self.namer = self.over = None

    # ----- planning, before the diagram places its own labels ------------------------------
    def layout(self) -> None:
        super().layout()
        xy = list(self.world.values())
        self.size = self.asm.size
        self.centre = _mid(list(self.paper.values()))
        self.points = [(-1, p) for p in xy] + [(i, p) for i, s in enumerate(self.steps)
                                               for p in _finite_points(s)]
        self.plan_frame()
        self.placer.name_points(self.view(s.output.xy) for s in self.steps
                                if isinstance(s.output, g.Point) and not s.output.is_at_infinity
                                and s.draws and s.label)
        # Each drawn line: the steps that drew it (coincident lines are drawn once) and its ends.
        self.lines: list[tuple[list[Step], tuple | None]] = []
        self.arcs: list[tuple[Step, list[tuple[float, float]], bool]] = []
        for step in self.steps:
            if isinstance(step.output, g.Line) and not step.output.is_at_infinity:
                self.plan_line(step)
            elif isinstance(step.output, g.Circle):
                self.plan_circle(step)
        self.plan_far()
        self.draw_working()
        self.namer = self.overlay(self.view, self.fig, self.placer) if self.overlay else None

    def plan_frame(self) -> None:
        """The frame: the mechanism, grown to take in the scene's points up to the cap."""
        xs = [p[0] for p in self.world.values()]
        ys = [p[1] for p in self.world.values()]
        b = [min(xs), min(ys), max(xs), max(ys)]
        extent = max(b[2] - b[0], b[3] - b[1], 1e-9)
        cap = max(FRAME_CAP * extent, FRAME_MIN / self.view.scale)

        def beyond(p):
            return max(b[0] - p[0], p[0] - b[2], b[1] - p[1], p[1] - b[3])

        self.far: list[tuple[Step, tuple[float, float]]] = []
        self.off_page: set[Ref] = set()
        # Each step's points grow the frame together: a vector fits whole or not at all,
        # since one cut at the frame would misstate its length. One that does not fit
        # (drawn at a far centre) is left out; the centre's edge arrow says where it is.
        steps = [(i, [p for j, p in self.points if j == i]) for i in range(len(self.steps))]
        for i, pts in sorted((ip for ip in steps if ip[1]),
                             key=lambda ip: max(beyond(p) for p in ip[1])):
            grown = [min([b[0]] + [p[0] for p in pts]), min([b[1]] + [p[1] for p in pts]),
                     max([b[2]] + [p[0] for p in pts]), max([b[3]] + [p[1] for p in pts])]
            if max(grown[2] - grown[0], grown[3] - grown[1]) <= cap * (1 + 1e-12):
                b = grown
            elif isinstance(self.steps[i].output, g.Point):
                self.far.append((self.steps[i], pts[0]))
            else:
                self.off_page.add(self.steps[i].id)
        for i, step in enumerate(self.steps):     # only a vector at a far centre stays off
            if step.id in self.off_page and self.far_base(step) is None:
                self.off_page.discard(step.id)
                pts = [p for j, p in self.points if j == i]
                b = [min([b[0]] + [p[0] for p in pts]), min([b[1]] + [p[1] for p in pts]),
                     max([b[2]] + [p[0] for p in pts]), max([b[3]] + [p[1] for p in pts])]
        # A flat mechanism (all its pins in a line) still gets room for its labels.
        least = 0.4 * extent
        for lo, hi in ((0, 2), (1, 3)):
            grow = max(0.0, least - (b[hi] - b[lo])) / 2
            b[lo], b[hi] = b[lo] - grow, b[hi] + grow
        (x0, y0), (x1, y1) = self.view((b[0], b[3])), self.view((b[2], b[1]))
        self.clip = (x0 - _EDGE, y0 - _EDGE, x1 + _EDGE, y1 + _EDGE)
        self.clip_box = box(*self.clip)
        # Labels stay on the page the frame makes, or just about.
        self.placer.page = self.clip_box.buffer(4.0, join_style="mitre")

    def far_base(self, step: Step) -> Step | None:
        """The far point a vector is drawn from, if it starts at one."""
        return next((f for f, _ in self.far if self.coincide(f.output, step.output.start)), None)

    def coincide(self, p: g.Point, q: g.Point) -> bool:
        """True if ``p`` and ``q`` are one point to the rounding of the drawing: relative to
        its size, so a mechanism a micrometre across is judged as one a metre across."""
        if p.is_at_infinity or q.is_at_infinity:
            return False
        return math.dist(p.xy, q.xy) <= _SAME * max(self.size, p.size(), q.size())

    def on_line(self, line: g.Line, p: tuple[float, float]) -> bool:
        return abs(line.signed_distance(g.Point(*p))) <= _SAME * max(self.size, math.hypot(*p))

    def is_pin(self, p: tuple[float, float]) -> bool:
        return any(math.dist(p, q) <= _SAME * max(self.size, math.hypot(*p))
                   for q in self.world.values())

    def plan_line(self, step: Step) -> None:
        """Span the points on the line, clipped to the frame; the same line again gains a number."""
        line: g.Line = step.output
        for steps, _ in self.lines:
            other = steps[0].output
            if (abs(other.a * line.b - other.b * line.a) <= _SAME
                    and self.on_line(other, line.anchor())):
                steps.append(step)
                return
        d = self.view.direction(line.direction)
        # The paper line, measured from the foot of the frame's centre.
        a = self.view(line.anchor())
        mid = ((self.clip[0] + self.clip[2]) / 2, (self.clip[1] + self.clip[3]) / 2)
        t_mid = (mid[0] - a[0]) * d[0] + (mid[1] - a[1]) * d[1]
        base = (a[0] + t_mid * d[0], a[1] + t_mid * d[1])
        # Past a constructed point the line runs on a little, to show the cut; at a
        # pin it stops under the pin's circle.
        stops = [(self.view(p), PIN_RADIUS if self.is_pin(p) else _OVERHANG)
                 for _, p in self.points if self.on_line(line, p)]
        lo, hi = span_line(base, d, stops, _LONE)
        self.lines.append(([step], clip_line(base, d, lo, hi, self.clip)))

    def within(self, pts) -> bool:
        """True if every paper point lies in the frame's clip box."""
        x0, y0, x1, y1 = self.clip
        return all(x0 <= x <= x1 and y0 <= y <= y1 for x, y in pts)

    def arc_of(self, step: Step) -> tuple[float, float, list[tuple[int, tuple]]]:
        """The arc a circle is drawn as, (start, sweep) in world angles, and the points it
        runs through: the whole circle through none, a compass trace through one (neither
        names its points), else the arc through them all that leaves out the widest gap."""
        circle: g.Circle = step.output
        cw = circle.centre.xy
        tol = _SAME * max(self.size, circle.radius, math.hypot(*cw))
        on = [(i, p) for i, p in self.points if abs(math.dist(p, cw) - circle.radius) <= tol]
        angles = sorted({round(math.atan2(p[1] - cw[1], p[0] - cw[0]), 12) for _, p in on})
        if not angles:
            return 0.0, 2 * math.pi, []
        if len(angles) == 1:       # a compass trace through the one point
            half = min(_TRACE / (circle.radius * self.view.scale), math.radians(20))
            return angles[0] - half, 2 * half, []
        gaps = [(angles[(k + 1) % len(angles)] - angles[k]) % (2 * math.pi)
                for k in range(len(angles))]
        k = max(range(len(gaps)), key=gaps.__getitem__)
        return angles[(k + 1) % len(angles)], 2 * math.pi - gaps[k], on

    def plan_circle(self, step: Step) -> None:
        """An arc through the points on the circle; a swing ends in an arrow at its new place."""
        circle: g.Circle = step.output
        cw = circle.centre.xy
        c, r = self.view(cw), circle.radius * self.view.scale
        start, sweep, on = self.arc_of(step)
        if on and step.kind is not Kind.SWING and not self.within(arc_points(c, r, start, sweep)):
            # An arc the frame would cut (Klein's circle on the rod) is drawn as a draftsman
            # draws it: a compass trace through each point on it, and no more.
            half = min(_TRACE / r, math.radians(20))
            for _, p in on:
                at = math.atan2(p[1] - cw[1], p[0] - cw[0])
                self.arcs.append((step, arc_points(c, r, at - half, 2 * half), False))
            return
        swung = step.kind is Kind.SWING and bool(on)
        if swung:
            # The swung-to end is the point located last that is neither a pin nor a
            # vector's end; the arc runs to it.
            def rank(ip):
                i, p = ip
                return -1 if i < 0 or self.is_pin(p) or not isinstance(
                    self.steps[i].output, g.Point) else i
            last = max(on, key=rank)[1]
            if abs(math.remainder(math.atan2(last[1] - cw[1], last[0] - cw[0]) - start,
                                  2 * math.pi)) < 1e-9:
                start, sweep = start + sweep, -sweep
        self.arcs.append((step, arc_points(c, r, start, sweep), swung))

    def plan_far(self) -> None:
        """Arrows at the page's edge toward each far point: on its lines, else from mid-page."""
        self.edge_arrows: list[tuple[Step, tuple[float, float], list[tuple]]] = []
        for step, p in self.far:
            q = self.view(p)
            arrows = []
            for steps, ends in self.lines:
                if ends is None or not self.on_line(steps[0].output, p):
                    continue
                end = min(ends, key=lambda e: math.dist(e, q))
                u = unit((q[0] - end[0], q[1] - end[1]))
                arrows.append(((end[0] - 7.0 * u[0], end[1] - 7.0 * u[1]), end))
            if not arrows:
                mid = ((self.clip[0] + self.clip[2]) / 2, (self.clip[1] + self.clip[3]) / 2)
                u = unit((q[0] - mid[0], q[1] - mid[1]))
                tip = ray_to_edge(mid, u, self.clip)
                arrows.append(((tip[0] - 9.0 * u[0], tip[1] - 9.0 * u[1]), tip))
            arrows.sort(key=lambda a: math.dist(a[1], q))
            self.edge_arrows.append((step, p, arrows))

    def draw_working(self) -> None:
        """Lines and arcs go in first, under the mechanism; the labels will keep clear."""
        for steps, ends in self.lines:
            # Lines drawn over one another show as the most telling of their kinds.
            kind = min((st.kind if st.kind in LINE_KINDS else Kind.LINE for st in steps),
                       key=_PRIORITY.index)
            if ends is not None:
                self.kinds += [kind] if kind not in self.kinds else []
                self.fig.add(Path(ends, LINE_KINDS[kind][0]))
                self.placer.block_path(ends, 0.3)
        for _, pts, _ in self.arcs:
            for part in self.clipped(pts):
                self.fig.add(Path(tuple(part), "compass"))
                self.placer.block_path(part, 0.3)
        # Vectors, dots, angles' arcs and edge arrows are drawn on top later; their room is
        # taken now (a point past the frame is an edge arrow, not a dot).
        far = {s.id for s, _ in self.far}
        for step in self.steps:
            out = step.output
            if isinstance(out, Angle):
                centre, radius = self.angle_arc(step)
                self.placer.block_path(arc_points(centre, radius, out.start, out.sweep), 0.4)
            if isinstance(out, g.Segment) and out.length > 0:
                self.placer.block_path([self.view(out.start.xy), self.view(out.end.xy)], 1.0)
            elif isinstance(out, g.Point) and not out.is_at_infinity and step.draws \
                    and step.id not in far:
                self.placer.block(SPoint(self.view(out.xy)).buffer(_DOT + 0.6))
        for _, _, arrows in self.edge_arrows:
            for tail, tip in arrows:
                self.placer.block_path([tail, tip], 1.6)

    def rays_through(self, at: tuple[float, float]) -> list[tuple[float, float]]:
        """The directions the scene's lines leave ``at`` in, each way a line runs on past it
        by more than a symbol's reach (a line's short overhang past its end is no ray)."""
        out = []
        for _, ends in self.lines:
            if ends is None:
                continue
            (x0, y0), (x1, y1) = ends
            n = math.hypot(x1 - x0, y1 - y0)
            if n > 0 and abs((at[0] - x0) * (y1 - y0) - (at[1] - y0) * (x1 - x0)) / n < 0.5:
                out += [((x - at[0]) / n, (y - at[1]) / n) for x, y in ends
                        if math.hypot(x - at[0], y - at[1]) > _REACH]
        return [(dx / math.hypot(dx, dy), dy / math.hypot(dx, dy)) for dx, dy in out]

    def marks(self) -> list[tuple[float, float]]:
        """The points the scene's steps mark, on paper: a guide runs past those on it."""
        return [self.view(s.output.xy) for s in self.steps if isinstance(s.output, g.Point)
                and not s.output.is_at_infinity and s.draws]

    def clipped(self, pts: list[tuple[float, float]]) -> list[list[tuple[float, float]]]:
        """The parts of a paper polyline inside the frame."""
        cut = LineString(pts).intersection(self.clip_box)
        return [list(p.coords) for p in getattr(cut, "geoms", [cut])
                if isinstance(p, LineString) and not p.is_empty and p.length > 0.2]

    # ----- over the diagram, then the caption ---------------------------------------------
    def fit_page(self) -> None:
        # The diagram's θ and ω marks take room its placer was not told of.
        for it in self.fig.items:
            if isinstance(it, Path) and it.style in ("arrow", "arrowhead", "dimension"):
                self.placer.block_path(list(it.points) + ([it.points[0]] if it.closed else []),
                                       0.4)
        self.draw_arc_heads()
        self.draw_measures()
        self.draw_vectors()
        self.draw_infinities()
        self.draw_points()
        self.draw_far()
        self.number_lines()
        self.over = self.namer() if self.namer else None
        self.caption()

    def label(self, text: str, anchor, steps: Sequence[Step] = (), **kw) -> None:
        """A label with the circled numbers of its steps, placed as one."""
        numbers = [self.numbers[s.id] for s in steps if s.id in self.numbers]
        self.placer.place_numbered(text, anchor, numbers, **kw)

    def draw_arc_heads(self) -> None:
        for _, pts, swung in self.arcs:
            if swung and self.clip_box.contains(SPoint(pts[-1])):
                d = unit((pts[-1][0] - pts[-2][0], pts[-1][1] - pts[-2][1]))
                draw_arrowhead(self.fig, pts[-1], d, length=2.2, width=1.2)

    def draw_measures(self) -> None:
        """Readings: a dimension line with its length, an angle's arc with its degrees.

        A dimension stands off its points on the side away from the mechanism, as
        near as it can be without crossing what is drawn. An angle's arc is thin, about
        the vertex, at the reach of the points it was read at; two angles read at one
        vertex (the slow and quick turns of a crank between its limit places) stand
        outside that circle at two radii, so each arc is told by its place, its degrees
        beside it. Its head shows the sense it was read in. Dimensions go first,
        so the degrees keep clear of them.
        """
        measures = [s for s in self.steps if isinstance(s.output, (Dimension, Angle))]
        for step in sorted(measures, key=lambda s: isinstance(s.output, Angle)):
            out = step.output
            if isinstance(out, Dimension):
                self.draw_dimension(step, out)
                continue
            centre, radius = self.angle_arc(step)
            at = draw_turning_arrow(self.fig, centre, radius, out.start, out.sweep, "dimension")
            text = f"{numerals(f'{out.degrees:.2f}')}° {words(step.label)}".strip()
            self.label(text, at, [step], prefer=out.start + out.sweep / 2, gap=1.6, size=3.2)

    def angle_arc(self, step: Step) -> tuple[tuple[float, float], float]:
        """Centre and radius (paper) of an angle's arc: at the reach of its points, or, for two
        angles read at one vertex, outside that circle at two radii."""
        out = step.output
        twins = [s for s in self.steps if isinstance(s.output, Angle)
                 and s.output.vertex.xy == out.vertex.xy]
        ring = 1.0 if len(twins) < 2 else 1.24 - 0.12 * twins.index(step)
        return self.view(out.vertex.xy), out.reach * self.view.scale * ring

    def draw_dimension(self, step: Step, out: Dimension) -> None:
        a, b = self.view(out.start.xy), self.view(out.end.xy)
        u = unit((b[0] - a[0], b[1] - a[1]))
        n = (-u[1], u[0])
        mid = ((a[0] + b[0]) / 2 - self.centre[0], (a[1] + b[1]) / 2 - self.centre[1])
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
            return self.placer.overlap(inner.buffer(2.5)) > GRAZE

        # The line and its reading stand outside the frame of the points: the page's
        # edge is no obstacle. The nearest offset that crosses nothing drawn is taken, on
        # the outer side if it has one, else on the inner (a perpendicular dropped from a
        # pivot has its link beside it on one side).
        page, self.placer.page = self.placer.page, None
        out_n = n
        offset, n = min(((off, side) for side in (out_n, (-out_n[0], -out_n[1]))
                         for off in (7.0, 11.0, 15.0, 19.0)),
                        key=lambda c: (crosses(*c), c[1] != out_n, c[0]))
        at = draw_dimension(self.fig, a, b, n, offset)
        self.placer.block_path(line_at(offset, n), 1.0)
        for end in (a, b):          # and its extension lines, out past the line
            self.placer.block_path([end, (end[0] + (offset + 1.6) * n[0],
                                          end[1] + (offset + 1.6) * n[1])], 0.3)
        text = (f"{typeset_span(words(step.label))} "
                f"{measure_words(self.m.units.length_drawn(out.length))}").strip()
        self.label(text, at, [step], prefer=math.atan2(-n[1], n[0]), gap=1.0, size=3.4)
        self.placer.page = page

    def draw_vectors(self) -> None:
        drawn = [s for s in self.steps if isinstance(s.output, g.Segment)
                 and s.id not in self.off_page]
        self.placer.name_vectors((self.view(s.output.start.xy), self.view(s.output.end.xy))
                                 for s in drawn if s.label)
        for step in drawn:
            out = step.output
            a, b = self.view(out.start.xy), self.view(out.end.xy)
            text, sub = typeset(step.label) if step.label else ("", "")
            if math.dist(a, b) < 0.5:
                self.label(f"{text}{sub} = 0" if text else "", a, [step])
                continue
            result = step.role is Role.RESULT
            draw_arrow(self.fig, a, b, "vector_result" if result else "vector",
                       head=3.2 if result else 2.8, width=1.6 if result else 1.4)
            d = unit((b[0] - a[0], b[1] - a[1]))
            normal = math.atan2(d[0], d[1])     # the paper normal (−dy, dx) as a paper angle
            anchors = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
                       for t in (0.6, 0.45, 0.75, 0.3, 0.9)]
            self.label(text, anchors, [step], sub=sub, prefer=(normal, normal + math.pi),
                       spread=math.pi / 3, gap=1.2, size=3.6, own=(a, b) if text else None)

    def draw_points(self) -> None:
        """Dots and labels; coincident points share one dot and one joined label."""
        groups: list[list[Step]] = []
        far = {s.id for s, _ in self.far}
        for step in self.steps:
            out = step.output
            if not isinstance(out, g.Point) or out.is_at_infinity or not step.draws \
                    or step.id in far:
                continue
            for grp in groups:
                if self.coincide(grp[0].output, out):
                    grp.append(step)
                    break
            else:
                groups.append([step])
        for grp in groups:
            p = grp[0].output.xy
            at = self.view(p)
            pin = self.is_pin(p)
            if not pin and not any(self.coincide(grp[0].output, e) for e in self.ends):
                self.fig.add(Circle(at, _DOT, "dot"))
            names = list(dict.fromkeys(typeset(s.label)[0] for s in grp if s.label))
            away = (at[0] - self.centre[0], at[1] - self.centre[1])
            prefer = math.atan2(-away[1], away[0]) if math.hypot(*away) > 1e-6 else math.pi / 4
            self.label(" ≡ ".join(names), at, grp, prefer=prefer, gap=2.2 if pin else 1.2,
                       own=at if names else None)

    def draw_infinities(self) -> None:
        """A centre at infinity: a two-headed arrow across its guide, marked "I₁₄ → ∞"."""
        for step in self.steps:
            out = step.output
            if not isinstance(out, g.Point) or not out.is_at_infinity:
                continue
            at, along, clear = self.infinity_anchor(step)
            u = unit(self.view.direction(out.direction))
            along = along or (-u[1], u[0])
            best = None
            for rank, off in enumerate((clear, -clear, clear + 5, -clear - 5, clear + 10,
                                        -clear - 10)):
                base = (at[0] + off * along[0], at[1] + off * along[1])
                a = (base[0] - _INF_ARROW * u[0], base[1] - _INF_ARROW * u[1])
                b = (base[0] + _INF_ARROW * u[0], base[1] + _INF_ARROW * u[1])
                cost = self.placer.overlap(LineString([a, b]).buffer(1.0))
                if best is None or (cost, rank) < best[:2]:
                    best = (cost, rank, base, a, b)
            _, _, base, a, b = best
            draw_arrow(self.fig, base, b, "arrow", head=2.4, width=1.3)
            draw_arrow(self.fig, base, a, "arrow", head=2.4, width=1.3)
            self.placer.block_path([a, b], 1.6)
            text = (typeset(step.label)[0] + " → ∞") if step.label else "→ ∞"
            self.label(text, [b, a], [step],
                       prefer=(math.atan2(-u[1], u[0]), math.atan2(u[1], -u[0])), gap=1.0)

    def infinity_anchor(self, step: Step):
        """Where a centre at infinity is drawn: beside its block, else on its line, else mid-page.

        Returns the paper point, the direction to step aside along (or None) and how far.
        """
        if isinstance(step.about, Centre):
            pair = step.about.pair
            for i, s in enumerate(self.m.slides):
                if s.kind is SlideKind.BLOCK and tuple(sorted((s.link, s.guide_link))) == pair:
                    at = (self.block_centre(s) if hasattr(self, "block_centre")
                          else self.paper[s.point])
                    return at, unit(self.view.direction(self.asm.guide(i).direction)), 7.5
        for r in step.inputs:
            line = self.c.output(r)
            if isinstance(line, g.Line) and not line.is_at_infinity:
                on = [self.paper[n] for n, p in self.world.items() if self.on_line(line, p)]
                if on:
                    return min(on, key=lambda q: math.dist(q, self.centre)), None, 6.0
        return self.centre, None, 0.0

    def draw_far(self) -> None:
        for step, p, arrows in self.edge_arrows:
            for tail, tip in arrows:
                draw_arrow(self.fig, tail, tip, "edge_arrow", head=2.8, width=1.5)
            near, dist = min(((n, math.dist(p, q)) for n, q in self.world.items()),
                             key=lambda nd: nd[1])
            name = typeset(step.label)[0] if step.label else words("a point")
            text = words("to {name}, {length} from {near}", name=name,
                         length=_length(dist, self.m.units), near=subscript(near))
            # A vector drawn at the far point is off the page too: its number goes here.
            riders = [v for v in self.steps if v.id in self.off_page and self.far_base(v) is step]
            tail, tip = arrows[0]
            ahead = math.atan2(tail[1] - tip[1], tip[0] - tail[0])
            # The label reads on from the arrow, past the page's frame if need be.
            page, self.placer.page = self.placer.page, None
            self.label(text, [tip, tail], [step, *riders], prefer=(ahead, ahead + math.pi / 2,
                                                          ahead - math.pi / 2),
                       gap=1.0, size=3.2, spread=math.pi / 2)
            self.placer.page = page

    def number_lines(self) -> None:
        """Each line's numbers beside it, toward its far end; each arc's beside its middle."""
        for steps, ends in self.lines:
            if ends is None:
                continue
            a, b = sorted(ends, key=lambda e: math.dist(e, self.centre))
            d = unit((b[0] - a[0], b[1] - a[1]))
            normal = math.atan2(d[0], d[1])
            anchors = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
                       for t in (0.92, 0.8, 0.68, 0.56, 0.44, 0.32, 0.2, 0.08)]
            self.label("", anchors, steps, prefer=(normal, normal + math.pi),
                       spread=math.pi / 4, gap=0.6)
        numbered: set[str] = set()
        for step, pts, _ in self.arcs:        # a circle drawn as traces is numbered once
            if step.id not in numbered:
                numbered.add(step.id)
                self.label("", [pts[len(pts) // 2], pts[-1], pts[0]], [step], gap=0.6)

    def caption(self) -> None:
        """The diagram's caption, with the velocity scale, a legend of lines and the notes."""
        u = self.m.units
        lines, second = [input_caption(self.m)], None
        if self.velocity_scale:
            # A vector is velocity_scale × view scale paper mm per m/s: state 1 cm in unit/s.
            per_cm = 10.0 / (self.velocity_scale * self.view.scale) / u.metres
            stated = self.velocity_stated
            if stated is not None and abs(per_cm - stated) <= 1e-9 * stated:
                per_cm = stated           # drawn at the stated scale: worded as stated
            second = ("Velocity scale", per_cm, u.length + "/s")
        legend = [LINE_KINDS[k] for k in LINE_KINDS if k in self.kinds]
        if legend == [LINE_KINDS[Kind.LINE]]:
            legend = []           # plain construction lines need no key
        if self.over is not None:
            second = second or self.over[0]
            legend += self.over[1]
        draw_caption(self.fig, self.title or self.m.name, lines, per_cm=self.per_cm,
                     unit=u.length, legend=legend, margin=_MARGIN, second=second,
                     notes=self.notes + tuple(self.over[2] if self.over else ()))


# ----- small helpers ---------------------------------------------------------------------------
def _finite_points(s: Step) -> list[tuple[float, float]]:
    """The finite points a step puts on the page (a mechanism point is the diagram's)."""
    out = s.output
    if isinstance(out, g.Point) and not out.is_at_infinity and s.kind is not Kind.JOINT:
        return [out.xy]
    if isinstance(out, (g.Segment, Dimension)):
        return [out.start.xy, out.end.xy]
    return []


def _mid(pts):
    return (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))


def _length(metres: float, units) -> str:
    value = metres / units.metres
    text = f"{value:.4g}" if value < 1e4 else f"{value:.0f}"
    return measure_words(f"{text} {units.length}")
