"""Velocity and acceleration polygons drawn as textbook figures, on their own true scale.

A polygon panel is drawn from the recorded steps of one panel (the velocity or
the acceleration polygon), by what each step's output is, never by recomputing
geometry:

* the pole is a small dot labelled o_v or o_a, with a true subscript;
* a line is a thin working line spanning the points of the panel that lie on it
  (tips and the ends of vectors), running a few millimetres past the last;
* a segment is a vector arrow, heavier for an absolute velocity or acceleration
  (a result, or the given input) than for a component, its label (``V_B/A``,
  ``Aⁿ_B/A``) set beside it; a vector of no length is written "Aⁿ_B/A = 0" beside
  its point instead of drawn;
* a tip is its lower-case letter in italic (b, a₄, b′), set in the widest gap
  between the lines and arrows that meet there, its step numbers beyond it, and
  nearer it than any other arrow's tip (labelled or not), as a reader takes a name
  for the point marked nearest it; it may cross a thin working line rather than
  stand off where it would name another;
* an arrow the pole's dot would cover whole is not drawn (its tip is dotted where no
  other arrow marks it).

The panel has its own nice scale, "1 cm = N mm/s" (or mm/s²) with N = 1, 2 or
5 × 10^k in the file's length unit, chosen so the polygon fills about
:data:`POLYGON_BOX` of paper; the statement is true, so a vector of v m/s
measures v / N cm. Each narrated step carries its circled number, the slice's
own numbering for the panel
(:meth:`~tarsim.constructions.record.Slice.numbered`), so steps.md numbers its
steps the same way. The names are set by :mod:`.polygon_labels`, once everything
is drawn.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from shapely.geometry import Point as SPoint, box

from tarsim.constructions import geometry as g
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.units import Units
from tarsim.constructions.record import Panel, Ref, Role, Slice, Step

from ..figure import Circle, Figure, Path, View, arc_points, span_line
from ..labels import LabelPlacer
from .lanes import lanes, moved
from .polygon_labels import CROSSABLE, HERE, ZERO, label_points, label_vectors, number_lines
from ..scales import draw_caption, nice_per_cm
from ..symbols import draw_arrow, unit

__all__ = ["draw_polygon_panel", "POLYGON_BOX", "QUANTITIES", "finite_points"]

POLYGON_BOX = (120.0, 110.0)
"""The paper (mm, wide × high) a polygon is scaled to fill, at most."""

QUANTITIES = {Panel.VELOCITY: ("Velocity", "/s"), Panel.ACCELERATION: ("Acceleration", "/s²")}
"""What each polygon panel draws, and the time part of its unit."""

_MARGIN = 8.0       # white round the drawing, mm
_OVERHANG = 4.0     # a working line runs this far past its last point, mm
_LONE = 10.0        # a line through one point runs this far either side, mm
_DOT = 1.0          # the pole's dot's radius, mm: it shows among the result arrows met there
_ROOM = 16.0        # labels stay within this much of the polygon, mm
_SAME = 1e-9        # relative slack for "lies on" and "coincides"
_HEAVY = {"head": 3.2, "width": 1.6}    # an absolute vector's arrowhead, mm
_LIGHT = {"head": 2.8, "width": 1.4}    # a component's


# ----- the public function ----------------------------------------------------------------
def draw_polygon_panel(shown: Slice, *, panel: Panel, scale: float, units: Units, title: str,
                       notes: Sequence[str] = (), per_cm: float | None = None,
                       room: tuple[float, float] = POLYGON_BOX) -> Figure:
    """Draw the steps of a velocity or acceleration polygon that ``shown`` holds as a figure.

    Parameters
    ----------
    shown
        A slice of the record; its steps in ``panel`` are drawn in its order and
        numbered as it numbers them (those of other panels are left out, so a
        whole figure's slice can be passed).
    panel
        ``Panel.VELOCITY`` or ``Panel.ACCELERATION``; it also names the quantity
        in the scale statement and its unit (mm/s or mm/s²).
    scale
        Drawing metres per m/s (per m/s² for accelerations): the scale the
        construction laid its vectors off at.
    units
        The file's units; the scale is stated in its length unit.
    title
        The caption's heading.
    notes
        Short lines printed under the caption.
    per_cm
        The scale to draw at, file length units per second (per s²) per paper
        cm, when the exercise states one; by default the nice scale that fits
        :data:`POLYGON_BOX`.
    room
        The paper (mm, wide × high) the polygon is fitted to when no scale is stated.

    Returns
    -------
    Figure
        The polygon on paper with its caption, scale statement and scale bar.

    Raises
    ------
    TarsimError
        If ``panel`` is not a polygon panel, ``scale`` is not a positive number,
        or no point of the panel is among the steps shown.

    See Also
    --------
    tarsim.constructions.record.Slice.numbered : the circled numbers, for a steps.md writer.
    tarsim.graphics.linkages.worked_page.compose_worked_page : a page of several panels.

    Examples
    --------
    V_B of 50 mm/s on a 3-4-5 triangle, laid off at 1 drawing metre per m/s:

    >>> from tarsim.constructions.record import Construction, slice
    >>> c = Construction()
    >>> _ = c.give("vp:o_v", g.Point(0, 0), label="o_v", panel=Panel.VELOCITY)
    >>> _ = c.give("vp:tip:B", g.Point(0.03, 0.04), label="b", panel=Panel.VELOCITY)
    >>> _ = c.draw("vp:V:B", "join", "vp:o_v", "vp:tip:B", label="V_B", role=Role.RESULT,
    ...            panel=Panel.VELOCITY)
    >>> fig = draw_polygon_panel(slice(c, ["vp:V:B"]), panel=Panel.VELOCITY,
    ...                          scale=1.0, units=Units("mm"), title="V_B")
    >>> [t.text for t in fig.items if getattr(t, "text", "").startswith("Velocity")]
    ['Velocity scale 1 cm = 5 mm/s']
    >>> shaft = next(p for p in fig.items if getattr(p, "style", "") == "vector_result")
    >>> head = next(p for p in fig.items if getattr(p, "style", "") == "arrowhead")
    >>> round(math.dist(shaft.points[0], head.points[0]), 9)    # 50 mm/s at 5 mm/s per cm
    100.0
    """
    if panel not in QUANTITIES:
        raise TarsimError(f"'{panel}' is not a polygon panel; choose "
                          f"{' or '.join(str(p) for p in QUANTITIES)}")
    if not (isinstance(scale, (int, float)) and math.isfinite(scale) and scale > 0.0):
        raise TarsimError(f"a polygon's scale must be a positive number, got {scale}")
    if per_cm is not None and not (math.isfinite(per_cm) and per_cm > 0.0):
        raise TarsimError(f"a stated polygon scale must be a positive number, got {per_cm}")
    steps = shown.steps(panel)
    if not any(finite_points(s) for s in steps):
        raise TarsimError(f"nothing to draw: no point or vector of the {panel} polygon is "
                          "among the steps asked for")
    return _PolygonPanel(steps, shown.numbers(panel), panel, float(scale), units,
                         per_cm, room).draw(title, notes)


# ----- what the steps put on paper ----------------------------------------------------------
def finite_points(step: Step) -> list[tuple[float, float]]:
    """Return the finite points a step marks: a point, or the two ends of a vector."""
    out = step.output
    if isinstance(out, g.Point):
        return [] if out.is_at_infinity else [out.xy]
    if isinstance(out, g.Segment):
        return [out.start.xy, out.end.xy]
    return []


def _per_cm(points: list[tuple[float, float]], scale: float, units: Units,
            box: tuple[float, float] = POLYGON_BOX) -> float:
    """Choose the nice N of "1 cm = N unit/s" that fits the polygon in ``box`` (mm).

    ``points`` are in drawing metres. A polygon of no extent (everything at
    rest) fits any scale; 1 is stated.
    """
    to_units = 1.0 / (scale * units.metres)        # drawing metres → file units per second
    fits = []
    for k, room in enumerate(box):
        extent = (max(p[k] for p in points) - min(p[k] for p in points)) * to_units
        if extent > 0.0:
            fits.append(nice_per_cm(extent, room))
    return max(fits, default=1.0)


# ----- the figure ----------------------------------------------------------------------------
class _PolygonPanel:
    """Working lines first, then the arrows and the pole over them, then every label."""

    def __init__(self, steps: list[Step], numbers: dict[Ref, int], panel: Panel, scale: float,
                 units: Units, per_cm: float | None = None,
                 room: tuple[float, float] = POLYGON_BOX):
        self.steps = steps
        self.numbers = numbers
        self.panel = panel
        self.scale = scale
        self.units = units
        self.world = list(dict.fromkeys(p for s in steps for p in finite_points(s)))
        xs, ys = zip(*self.world)
        # The yardstick of "lies on" and "coincides": the panel's reach from the origin.
        self.size = max(1.0, max(xs) - min(xs), max(ys) - min(ys),
                        max(math.hypot(*p) for p in self.world))
        self.per_cm = per_cm or _per_cm(self.world, scale, units, room)
        # Paper mm per drawing metre: 10 mm stands for per_cm file units per second.
        self.view = View(10.0 / (self.per_cm * units.metres * scale), (0.0, 0.0))
        self.fig = Figure(0.0, 0.0, views={panel.value: self.view})
        self.placer = LabelPlacer(self.fig)
        self.paper = [self.view(p) for p in self.world]
        self.centre = (sum(p[0] for p in self.paper) / len(self.paper),
                       sum(p[1] for p in self.paper) / len(self.paper))
        self.lines: list[tuple[list[Step], tuple[tuple[float, float], tuple[float, float]]]] = []
        self.rays: dict[tuple[float, float], list[tuple[float, float]]] = {}

    def draw(self, title: str, notes: Sequence[str]) -> Figure:
        for step in self.steps:
            if isinstance(step.output, g.Line) and not step.output.is_at_infinity:
                self.plan_line(step)
        self.lay_vectors()
        # Labels stay within _ROOM of what is drawn: the points, and arrows moved into lanes.
        xs, ys = zip(*self.paper, *(p for a, b, *_ in self.drawn.values() for p in (a, b)))
        self.placer.page = box(min(xs) - _ROOM, min(ys) - _ROOM, max(xs) + _ROOM, max(ys) + _ROOM)
        self.draw_lines()
        self.draw_circles()
        self.draw_vectors()
        self.draw_dots()
        label_points(self)
        label_vectors(self)
        number_lines(self)
        quantity, per_time = QUANTITIES[self.panel]
        draw_caption(self.fig, title, [], per_cm=self.per_cm, unit=self.units.length + per_time,
                     notes=notes, margin=_MARGIN, scale_name=f"{quantity} scale")
        return self.fig

    # ----- planning ---------------------------------------------------------------------------
    def on_line(self, line: g.Line, p: tuple[float, float]) -> bool:
        return abs(line.signed_distance(g.Point(*p))) <= _SAME * self.size

    def coincide(self, p: tuple[float, float], q: tuple[float, float]) -> bool:
        """Tell whether two points of the panel (drawing metres) are one."""
        return math.dist(p, q) <= _SAME * self.size

    def rays_at(self, at: tuple[float, float]) -> list[tuple[float, float]]:
        return [r for q, rays in self.rays.items() if math.dist(q, at) <= HERE for r in rays]

    def plan_line(self, step: Step) -> None:
        """Span the panel's points on the line; a line drawn again only gains a number."""
        line: g.Line = step.output
        for steps, _ in self.lines:
            other = steps[0].output
            if abs(other.a * line.b - other.b * line.a) <= _SAME and \
                    self.on_line(other, line.anchor()):
                steps.append(step)
                return
        d = self.view.direction(line.direction)
        # Measured from the foot of the polygon's centre, so the numbers stay small.
        a = self.view(line.anchor())
        t = (self.centre[0] - a[0]) * d[0] + (self.centre[1] - a[1]) * d[1]
        base = (a[0] + t * d[0], a[1] + t * d[1])
        stops = [(q, _OVERHANG) for p, q in zip(self.world, self.paper) if self.on_line(line, p)]
        lo, hi = span_line(base, d, stops, _LONE)
        ends = ((base[0] + lo * d[0], base[1] + lo * d[1]),
                (base[0] + hi * d[0], base[1] + hi * d[1]))
        self.lines.append(([step], ends))
        for p, q in zip(self.world, self.paper):
            if self.on_line(line, p):
                self.add_rays(q, ends)

    def add_rays(self, at: tuple[float, float], ends) -> None:
        """Note the directions a drawn line or arrow leaves ``at`` in, for its label."""
        for e in ends:
            if math.dist(e, at) > 0.5:
                self.rays.setdefault(at, []).append(unit((e[0] - at[0], e[1] - at[1])))

    # ----- drawing -------------------------------------------------------------------------
    def draw_lines(self) -> None:
        for steps, ends in self.lines:
            self.fig.add(Path(ends, "working", steps=tuple(s.id for s in steps)))
            self.placer.block_path(ends, 0.3, weight=CROSSABLE)

    def draw_circles(self) -> None:
        """Draw a circle (an arc swung in the polygon) as a whole compass circle."""
        for step in self.steps:
            if isinstance(step.output, g.Circle):
                c = self.view(step.output.centre.xy)
                pts = arc_points(c, step.output.radius * self.view.scale, 0.0, 2 * math.pi)
                self.fig.add(Path(tuple(pts), "compass", steps=(step.id,)))
                self.placer.block_path(pts, 0.3)

    def vectors(self) -> list[tuple[Step, tuple[float, float], tuple[float, float]]]:
        """Each segment step with its paper tail and tip as drawn: in its lane
        (:func:`.lanes.lanes`), beside the points it joins if arrows overlap there."""
        return [(s, *self.drawn[s.id][:2]) for s in self.steps if s.id in self.drawn]

    def lay_vectors(self) -> None:
        """Give each vector its lane: arrows that would cover one another (collinear, or a
        short one along a longer) are drawn side by side, each true in length and
        direction, a leader from each end it leaves to the point it stands for."""
        steps = [s for s in self.steps if isinstance(s.output, g.Segment)]
        ends = [(self.view(s.output.start.xy), self.view(s.output.end.xy)) for s in steps]
        drawn_in = lanes(ends, [s.role is not Role.CONSTRUCTION for s in steps])
        self.drawn = {s.id: (*moved(seg, lane), *seg)
                      for s, seg, lane in zip(steps, ends, drawn_in)}

    def draw_vectors(self) -> None:
        """Arrows with the head at the tip: absolute vectors heavy, components light; one
        moved into a lane of its own has a leader from each end to its point."""
        hidden = self.hidden()
        for step, a, b in self.vectors():
            if math.dist(a, b) < ZERO:
                continue
            with self.fig.for_steps(step.id):
                self.draw_vector(step, a, b, step.id in hidden)

    def draw_vector(self, step: Step, a: tuple[float, float], b: tuple[float, float],
                    hidden: bool) -> None:
        """One arrow, unless the pole's dot hides it, and its leaders out of its lane."""
        heavy = step.role is not Role.CONSTRUCTION
        if not hidden:
            draw_arrow(self.fig, a, b, "vector_result" if heavy else "vector",
                       **_HEAVY if heavy else _LIGHT)
            self.placer.block_path([a, b], 1.6 if heavy else 1.3)
        for end, true in zip((a, b), self.drawn[step.id][2:]):
            if math.dist(end, true) > HERE:
                self.fig.add(Path((true, end), "leader"))
                self.placer.block_path([true, end], 0.3, weight=CROSSABLE)
        self.add_rays(a, [b])
        self.add_rays(b, [a])

    def hidden(self) -> set[str]:
        """The vectors whose arrows the pole's dot would cover whole (A_C a quarter
        millimetre long from o_a), by id: not drawn, their tips dotted where no drawn arrow
        ends."""
        poles = [self.view(s.output.xy) for s in self.steps if s.role is Role.GIVEN
                 and isinstance(s.output, g.Point) and not s.output.is_at_infinity]
        return {s.id for s, a, b in self.vectors() if math.dist(a, b) >= ZERO and any(
            _under_dot(a, b, pole, **_HEAVY if s.role is not Role.CONSTRUCTION else _LIGHT)
            for pole in poles)}

    def draw_dots(self) -> None:
        """Dot the pole, and any point no drawn arrow ends at."""
        hidden = self.hidden()
        ends = [q for s, a, b in self.vectors() if math.dist(a, b) >= ZERO
                and s.id not in hidden for q in (a, b)]
        for step in self.steps:
            out = step.output
            if not isinstance(out, g.Point) or out.is_at_infinity:
                continue
            at = self.view(out.xy)
            if step.role is Role.GIVEN or not any(math.dist(at, e) <= HERE for e in ends):
                self.fig.add(Circle(at, _DOT, "dot", steps=(step.id,)))
                self.placer.block(SPoint(at).buffer(_DOT + 0.5))


def _under_dot(a: tuple[float, float], b: tuple[float, float], dot: tuple[float, float], *,
               head: float, width: float) -> bool:
    """Whether the arrow from ``a`` to ``b`` (its head ``head`` long at most, ``width``
    wide, as :func:`.symbols.draw_arrow` draws it) lies wholly within the dot at ``dot``.

    >>> _under_dot((0.0, 0.0), (0.25, 0.0), (0.0, 0.0), head=3.2, width=1.6)
    True
    >>> _under_dot((0.0, 0.0), (1.5, 0.0), (0.0, 0.0), head=3.2, width=1.6)
    False
    """
    n = math.dist(a, b)
    u = ((b[0] - a[0]) / n, (b[1] - a[1]) / n)
    base = (b[0] - min(head, n) * u[0], b[1] - min(head, n) * u[1])
    wings = [(base[0] - k * width / 2 * u[1], base[1] + k * width / 2 * u[0]) for k in (1, -1)]
    return all(math.dist(p, dot) <= _DOT for p in (a, b, *wings))
