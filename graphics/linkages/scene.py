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

This module holds the scene itself: its frame, what it asks of the diagram (the
points it marks, the lines through a pivot) and its caption. The working lines
and arcs under the mechanism are planned and drawn by :mod:`.scene_lines`; the
vectors, points, readings and numbers over it by :mod:`.scene_marks`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

from shapely.geometry import box
from shapely.ops import unary_union

from tarsim.constructions import geometry as g
from tarsim.constructions.linkages.assembly_record import Assembly
from tarsim.constructions.linkages.centres import Centre
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.measures import Angle, Dimension
from tarsim.constructions.record import Kind, Panel, Ref, Slice, Step

from .diagram import _Diagram
from .diagram_labels import input_caption
from ..figure import Circle, Figure, Path, View
from ..labels import LabelPlacer
from ..paper_points import centroid
from ..scales import draw_caption
from .scene_lines import LINE_KINDS, SAME, draw_working, plan_circle, plan_far, plan_line
from .scene_marks import (draw_arc_heads, draw_far, draw_infinities, draw_measures, draw_points,
                          draw_vectors, number_lines, plan_vectors)

__all__ = ["draw_scene", "FRAME_CAP", "FRAME_MIN"]

FRAME_CAP = 1.6
"""The page's frame grows to take in the scene's points up to this many mechanism extents..."""

FRAME_MIN = 190.0
"""...or this many millimetres of paper, whichever is more; beyond, a point is off the page."""

_MARGIN = 8.0       # white round the drawing, mm (as the kinematic diagram)
_REACH = 6.0        # mm a ground symbol reaches from its pivot: a line shorter past it is no ray
_EDGE = 9.0         # room between the frame's points and the clip edge, mm


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
        :class:`~tarsim.constructions.linkages.assembly.Assembly`). Its space-panel steps are
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
        self.vector_lanes: list[tuple[Step, tuple, int]] = []   # by plan_marks

    # ----- planning, before the diagram places its own labels ------------------------------
    def layout(self) -> None:
        super().layout()
        self.fig.views[Panel.SPACE.value] = self.view
        xy = list(self.world.values())
        self.size = self.asm.size
        self.centre = centroid(list(self.paper.values()))
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
                plan_line(self, step)
            elif isinstance(step.output, g.Circle):
                plan_circle(self, step)
        plan_far(self)
        draw_working(self)
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
        return math.dist(p.xy, q.xy) <= SAME * max(self.size, p.size(), q.size())

    def on_line(self, line: g.Line, p: tuple[float, float]) -> bool:
        return abs(line.signed_distance(g.Point(*p))) <= SAME * max(self.size, math.hypot(*p))

    def is_pin(self, p: tuple[float, float]) -> bool:
        return any(math.dist(p, q) <= SAME * max(self.size, math.hypot(*p))
                   for q in self.world.values())

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

    def plan_marks(self) -> None:
        """Put each vector in its lane, beside a link it would lie along, and take its room
        before the mechanism's points are named. A wheel drawn past the frame of the points
        (its rim reaches beyond its pins) is page too: a label may stand beside it."""
        wheels = [box(c.centre[0] - c.radius, c.centre[1] - c.radius, c.centre[0] + c.radius,
                      c.centre[1] + c.radius) for c in self.fig.items
                  if isinstance(c, Circle) and c.style == "link"]
        if wheels:
            self.placer.page = unary_union([self.clip_box, *wheels]).envelope.buffer(
                4.0, join_style="mitre")
        plan_vectors(self)

    # ----- over the diagram, then the caption ---------------------------------------------
    def fit_page(self) -> None:
        # The diagram's θ and ω marks take room its placer was not told of.
        for it in self.fig.items:
            if isinstance(it, Path) and it.style in ("arrow", "arrowhead", "dimension"):
                self.placer.block_path(list(it.points) + ([it.points[0]] if it.closed else []),
                                       0.4)
        draw_arc_heads(self)
        draw_measures(self)
        draw_vectors(self)
        draw_infinities(self)
        draw_points(self)
        draw_far(self)
        number_lines(self)
        self.over = self.namer() if self.namer else None
        self.caption()

    def label(self, text: str, anchor, steps: Sequence[Step] = (), **kw) -> None:
        """A label with the circled numbers of its steps that need one, placed as one."""
        numbers = [self.numbers[s.id] for s in steps if s.id in self.numbers
                   and _needs_number(s)]
        self.placer.place_numbered(text, anchor, numbers, **kw)

    def angle_arc(self, step: Step) -> tuple[tuple[float, float], float]:
        """Centre and radius (paper) of an angle's arc: at the reach of its points, or, for two
        angles read at one vertex, outside that circle at two radii."""
        out = step.output
        twins = [s for s in self.steps if isinstance(s.output, Angle)
                 and s.output.vertex.xy == out.vertex.xy]
        ring = 1.0 if len(twins) < 2 else 1.24 - 0.12 * twins.index(step)
        return self.view(out.vertex.xy), out.reach * self.view.scale * ring

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
def _needs_number(s: Step) -> bool:
    """Whether a step's circled number helps a reader find it on the figure: a Kennedy line
    is found by the two centres it joins and a centre found by inspection (a pin, a
    block's guide, a contact) by the mechanism, so neither is numbered there (steps.md
    numbers every step); a centre found by Kennedy's theorem keeps the number of the step
    it was found at, as the order it was found in.

    >>> from types import SimpleNamespace as N
    >>> _needs_number(N(kind=Kind.KENNEDY_LINE, about=None)), _needs_number(
    ...     N(kind=Kind.LINE, about=None))
    (False, True)
    """
    if s.kind is Kind.KENNEDY_LINE:
        return False
    return not (isinstance(s.about, Centre) and s.about.order == 0)


def _finite_points(s: Step) -> list[tuple[float, float]]:
    """The finite points a step puts on the page (a mechanism point is the diagram's)."""
    out = s.output
    if isinstance(out, g.Point) and not out.is_at_infinity and s.kind is not Kind.JOINT:
        return [out.xy]
    if isinstance(out, (g.Segment, Dimension)):
        return [out.start.xy, out.end.xy]
    return []
