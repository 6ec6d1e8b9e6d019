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
steps the same way.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

from shapely.geometry import Point as SPoint, box

from ..constructions import geometry as g
from ..constructions.errors import TarsimError
from ..constructions.model import Units
from ..constructions.record import Panel, Ref, Role, Slice, Step

from .figure import Circle, Figure, Path, View, arc_points, span_line
from .labels import LABEL, LabelPlacer, typeset
from .scales import draw_caption, nice_per_cm
from .symbols import draw_arrow, unit

__all__ = ["draw_polygon_panel", "POLYGON_BOX", "QUANTITIES"]

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
_ZERO = 0.05        # a vector shorter than this on paper (mm) is drawn as "= 0"
_HERE = 1e-6        # paper points closer than this (mm) are one
_TINY = 1.0         # a vector shorter than this (mm) is named as the point it nearly is:
                    # beside so short a shaft a name is as near every arrow from its pole
_NEAR = (1.0, 1.6, 2.4, 3.4, 4.6)   # a vector's label stays this many gaps from its shaft
_FARTHER = (6.0, 8.0, 11.0, 15.0)   # ...unless every spot there covers another label
_CROSSABLE = 0.02   # what covering a thin working line costs a label, against 1 for ink
_ON_LABEL = 0.05 * LABEL   # a tiny vector's name covers no more beside it (0.05 mm² of
                    # another label, 0.5 mm² of a line) before it stands off farther
_CROSSING = 20.0 * _CROSSABLE   # a point's name crosses this much (20 mm², two working
                    # lines under a label) before it stands off in a farther ring, where a
                    # reader would take it for another point's
_LANE = 3.0         # mm between collinear arrows drawn side by side (:func:`_lanes`)
_SHORT = 8.0        # mm: an arrow shorter than this may have its name round its ends
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
    tarsim.graphics.worked_page.compose_worked_page : a page of several panels.

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
    if not any(_finite_points(s) for s in steps):
        raise TarsimError(f"nothing to draw: no point or vector of the {panel} polygon is "
                          "among the steps asked for")
    return _PolygonPanel(steps, shown.numbers(panel), panel, float(scale), units,
                         per_cm, room).draw(title, notes)


# ----- what the steps put on paper ----------------------------------------------------------
def _finite_points(step: Step) -> list[tuple[float, float]]:
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


def _free_direction(at: tuple[float, float], rays: list[tuple[float, float]],
                    centre: tuple[float, float]) -> float:
    """Find the paper angle (rad, as :meth:`LabelPlacer.spot` takes it) for a point's label.

    ``rays`` are the paper directions of the lines and arrows leaving ``at``; a
    label in the middle of a wide gap between them reads clear of all. Of two
    gaps about as wide, the one opening away from the polygon's ``centre`` wins:
    inside, the vectors' labels need the room.
    """
    away = (at[0] - centre[0], at[1] - centre[1])
    outward = math.atan2(-away[1], away[0]) if math.hypot(*away) > 1e-6 else None
    if not rays:
        return math.pi / 4 if outward is None else outward
    angles = sorted({round(math.atan2(-dy, dx), 9) for dx, dy in rays})   # paper y runs down
    if len(angles) == 1:
        return angles[0] + math.pi
    gaps = [((angles[(k + 1) % len(angles)] - a) % (2 * math.pi), a)
            for k, a in enumerate(angles)]

    def score(gap: tuple[float, float]) -> float:
        width, start = gap
        lean = 0.0 if outward is None else math.cos(start + width / 2 - outward)
        return width * (1.0 + 0.5 * lean)

    width, start = max(gaps, key=score)
    return start + width / 2


def _joined(names: list[tuple[str, str]]) -> tuple[str, str, str]:
    """One label for coincident points, "o_v ≡ b": text, subscript and tail.

    The pole, whose name has a true subscript, leads; the others follow it
    written out.
    """
    names = sorted(names, key=lambda name: not name[1])
    (text, sub), rest = names[0], names[1:]
    tail = "".join(f" ≡ {t}{s}" for t, s in rest)
    return (text, sub, tail) if sub else (text + tail, "", "")


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
        self.world = list(dict.fromkeys(p for s in steps for p in _finite_points(s)))
        xs, ys = zip(*self.world)
        # The yardstick of "lies on" and "coincides": the panel's reach from the origin.
        self.size = max(1.0, max(xs) - min(xs), max(ys) - min(ys),
                        max(math.hypot(*p) for p in self.world))
        self.per_cm = per_cm or _per_cm(self.world, scale, units, room)
        # Paper mm per drawing metre: 10 mm stands for per_cm file units per second.
        self.view = View(10.0 / (self.per_cm * units.metres * scale), (0.0, 0.0))
        self.fig = Figure(0.0, 0.0)
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
        self.label_points()
        self.label_vectors()
        self.number_lines()
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
        return [r for q, rays in self.rays.items() if math.dist(q, at) <= _HERE for r in rays]

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
        for _, ends in self.lines:
            self.fig.add(Path(ends, "working"))
            self.placer.block_path(ends, 0.3, weight=_CROSSABLE)

    def draw_circles(self) -> None:
        """Draw a circle (an arc swung in the polygon) as a whole compass circle."""
        for step in self.steps:
            if isinstance(step.output, g.Circle):
                c = self.view(step.output.centre.xy)
                pts = arc_points(c, step.output.radius * self.view.scale, 0.0, 2 * math.pi)
                self.fig.add(Path(tuple(pts), "compass"))
                self.placer.block_path(pts, 0.3)

    def vectors(self) -> list[tuple[Step, tuple[float, float], tuple[float, float]]]:
        """Each segment step with its paper tail and tip as drawn: in its lane
        (:func:`_lanes`), beside the points it joins if arrows overlap there."""
        return [(s, *self.drawn[s.id][:2]) for s in self.steps if s.id in self.drawn]

    def lay_vectors(self) -> None:
        """Give each vector its lane: collinear arrows that would cover one another are
        drawn side by side, each true in length and direction, a leader from each end it
        leaves to the point it stands for."""
        steps = [s for s in self.steps if isinstance(s.output, g.Segment)]
        ends = [(self.view(s.output.start.xy), self.view(s.output.end.xy)) for s in steps]
        lanes = _lanes(ends, [s.role is not Role.CONSTRUCTION for s in steps])
        self.drawn = {}
        for s, (a, b), lane in zip(steps, ends, lanes):
            n = (0.0, 0.0)
            if lane and math.dist(a, b) >= _ZERO:
                u = unit((b[0] - a[0], b[1] - a[1]))
                n = (-u[1] * lane * _LANE, u[0] * lane * _LANE)
            self.drawn[s.id] = ((a[0] + n[0], a[1] + n[1]), (b[0] + n[0], b[1] + n[1]), a, b)

    def draw_vectors(self) -> None:
        """Arrows with the head at the tip: absolute vectors heavy, components light; one
        moved into a lane of its own has a leader from each end to its point."""
        hidden = self.hidden()
        for step, a, b in self.vectors():
            if math.dist(a, b) < _ZERO:
                continue
            heavy = step.role is not Role.CONSTRUCTION
            if step.id not in hidden:
                draw_arrow(self.fig, a, b, "vector_result" if heavy else "vector",
                           **_HEAVY if heavy else _LIGHT)
                self.placer.block_path([a, b], 1.6 if heavy else 1.3)
            for end, true in zip((a, b), self.drawn[step.id][2:]):
                if math.dist(end, true) > _HERE:
                    self.fig.add(Path((true, end), "leader"))
                    self.placer.block_path([true, end], 0.3, weight=_CROSSABLE)
            self.add_rays(a, [b])
            self.add_rays(b, [a])

    def hidden(self) -> set[str]:
        """The vectors whose arrows the pole's dot would cover whole (A_C a quarter
        millimetre long from o_a), by id: not drawn, their tips dotted where no drawn arrow
        ends."""
        poles = [self.view(s.output.xy) for s in self.steps if s.role is Role.GIVEN
                 and isinstance(s.output, g.Point) and not s.output.is_at_infinity]
        return {s.id for s, a, b in self.vectors() if math.dist(a, b) >= _ZERO and any(
            _under_dot(a, b, pole, **_HEAVY if s.role is not Role.CONSTRUCTION else _LIGHT)
            for pole in poles)}

    def draw_dots(self) -> None:
        """Dot the pole, and any point no drawn arrow ends at."""
        hidden = self.hidden()
        ends = [q for s, a, b in self.vectors() if math.dist(a, b) >= _ZERO
                and s.id not in hidden for q in (a, b)]
        for step in self.steps:
            out = step.output
            if not isinstance(out, g.Point) or out.is_at_infinity:
                continue
            at = self.view(out.xy)
            if step.role is Role.GIVEN or not any(math.dist(at, e) <= _HERE for e in ends):
                self.fig.add(Circle(at, _DOT, "dot"))
                self.placer.block(SPoint(at).buffer(_DOT + 0.5))

    # ----- labels ----------------------------------------------------------------------------
    def numbered(self, steps: Iterable[Step]) -> list[int]:
        return [self.numbers[s.id] for s in steps if s.id in self.numbers]

    def label_points(self) -> None:
        """Each point's name and numbers; coincident points share one label ("o_v ≡ b")."""
        groups: list[list[Step]] = []
        for step in self.steps:
            out = step.output
            if not isinstance(out, g.Point) or out.is_at_infinity:
                continue
            grp = next((grp for grp in groups if self.coincide(grp[0].output.xy, out.xy)), None)
            if grp is None:
                groups.append([step])
            else:
                grp.append(step)
        self.placer.name_points(self.view(grp[0].output.xy) for grp in groups
                                if any(s.label for s in grp))
        # A reader takes a name for the nearest point marked: it stands nearer its own than
        # any arrow's tip, labelled or not, and the ends of arrows moved into lanes.
        hidden = self.hidden()
        self.placer.name_points(
            {end for s, a, b in self.vectors() if s.id not in hidden and math.dist(a, b) >= _ZERO
             for end, at in zip((a, b), self.drawn[s.id][2:])
             if end is b or math.dist(end, at) > _HERE})
        for grp in groups:
            at = self.view(grp[0].output.xy)
            names = list(dict.fromkeys(typeset(s.label) for s in grp if s.label))
            text, sub, tail = _joined(names) if names else ("", "", "")
            rays = self.rays_at(at)
            self.placer.place_numbered(text, at, self.numbered(grp), sub=sub, tail=tail,
                                       prefer=_free_direction(at, rays, self.centre), gap=1.0,
                                       size=3.8, farther=_FARTHER, crossing=_CROSSING,
                                       own=at if names else None, beside=True)

    def label_vectors(self) -> None:
        """Each vector's label beside its own stretch of shaft; a null one as "… = 0".

        The shortest go first: they have the least shaft to choose a place by. Arrows
        drawn one over another (V_A₂ and V_A₄ when the block does not slide) share one
        label, "V_A₂ = V_A₄"; one moved into a lane is labelled on its lane's side.
        """
        drawn = self.vectors()
        self.placer.name_vectors((a, b) for s, a, b in drawn
                                 if s.label and math.dist(a, b) >= _TINY)
        self.placer.name_points(_middle(a, b) for s, a, b in drawn
                                if s.label and _ZERO <= math.dist(a, b) < _TINY)
        twins: list[list[tuple[Step, tuple[float, float], tuple[float, float]]]] = []
        for v in drawn:
            same = next((t for t in twins if math.dist(t[0][1], v[1]) < _ZERO
                         and math.dist(t[0][2], v[2]) < _ZERO
                         and math.dist(v[1], v[2]) >= _ZERO), None)
            if same is None:
                twins.append([v])
            else:
                same.append(v)
        for group in sorted(twins, key=lambda t: math.dist(t[0][1], t[0][2])):
            step, a, b = group[0]
            names = list(dict.fromkeys(typeset(s.label) for s, _, _ in group if s.label))
            text, sub = names[0] if names else ("", "")
            numbers = self.numbered(s for s, _, _ in group)
            if math.dist(a, b) < _ZERO:
                rays = self.rays_at(a)
                self.placer.place_numbered(text, a, numbers, sub=sub,
                                           tail=" = 0" if text else "",
                                           prefer=_free_direction(a, rays, self.centre), gap=1.6,
                                           size=3.2)
                continue
            d = unit((b[0] - a[0], b[1] - a[1]))
            normal = math.atan2(d[0], d[1])       # the paper normal (−dy, dx) as a paper angle
            true_a = self.drawn[step.id][2]
            away = (a[0] + b[0]) / 2 - self.centre[0], (a[1] + b[1]) / 2 - self.centre[1]
            if math.dist(a, true_a) > _HERE:      # in a lane: its side is the lane's
                away = (a[0] - true_a[0], a[1] - true_a[1])
            if away[0] * math.cos(normal) - away[1] * math.sin(normal) < 0:
                normal += math.pi                  # the outer side of the polygon first
            others = [(p, q) for s, p, q in drawn if all(s is not t for t, _, _ in group)]
            anchors = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
                       for t in _own_stretch(a, b, others)]
            # A short arrow has little shaft to stand beside: its name may go round its ends.
            spread = math.pi / 3
            # So short an arrow is found by its name only beside it: farther rings only
            # where every spot beside it covers another label.
            dot = math.dist(a, b) < _TINY
            self.placer.place_numbered(text, anchors, numbers, sub=sub, also=tuple(names[1:]),
                                       prefer=(normal, normal + math.pi), spread=spread,
                                       gap=1.0, size=3.4, rings=_NEAR, farther=_FARTHER,
                                       crossing=_ON_LABEL if dot else 0.0,
                                       own=None if not text else _middle(a, b) if dot
                                       else (a, b))

    def number_lines(self) -> None:
        """Each line's numbers beside its middle, or the middle of the stretch no arrow covers.

        Its ends are where the tips and their numbers crowd, so a number there
        would be read as a point's.
        """
        arrows = [(p, q) for _, p, q in self.vectors() if math.dist(p, q) >= _ZERO]
        for steps, (a, b) in self.lines:
            d = unit((b[0] - a[0], b[1] - a[1]))
            normal = math.atan2(d[0], d[1])
            anchors = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
                       for t in _own_stretch(a, b, arrows)]
            self.placer.place_numbered("", anchors, self.numbered(steps),
                                       prefer=(normal, normal + math.pi), spread=math.pi / 4,
                                       gap=0.6, farther=_FARTHER)


def _lanes(ends: list[tuple[tuple[float, float], tuple[float, float]]],
           heavy: list[bool]) -> list[int]:
    """The lane of each arrow ``(tail, tip)``: 0 on its points, ±1, ±2 … :data:`_LANE` mm to
    either side.

    Two arrows on one carrier clash where they overlap, unless one lies within the other
    from a common tail and the same way (V_A₄ within V_B₄, both from o_v, a textbook's
    own drawing) or they are one and the same arrow; and where they meet head to head,
    their heads stacked on one point. A polygon that collapses onto a line
    (the crank-shaper's at θ₂ = 90°) has arrows running back over one another with heads
    meeting: each goes to the nearest lane where it clashes with none, the absolute
    vectors (``heavy``) and the longest placed first, so they keep to their points.

    >>> _lanes([((0, 0), (0, 90)), ((0, 90), (0, 24)), ((0, 0), (0, 30)), ((0, 31), (0, 0))],
    ...        [True, False, True, False])
    [0, 1, 0, -1]
    """
    def clash(i: int, j: int) -> bool:
        (a, b), (p, q) = ends[i], ends[j]
        n = math.dist(a, b)
        if n < _ZERO or math.dist(p, q) < _ZERO:
            return False
        d = ((b[0] - a[0]) / n, (b[1] - a[1]) / n)
        if any(abs((e[0] - a[0]) * d[1] - (e[1] - a[1]) * d[0]) > 0.05 for e in (p, q)):
            return False                                  # not on one carrier
        s, t = (((e[0] - a[0]) * d[0] + (e[1] - a[1]) * d[1]) for e in (p, q))
        if math.dist(b, q) < 0.05 and t < s:
            return True                                   # head to head: the heads meet
        if min(max(s, t), n) - max(min(s, t), 0.0) <= 0.5:
            return False                                  # end to end, or apart
        same_way = t > s
        if same_way and (abs(s) < 0.05 or (math.dist(a, p) < 0.05 and math.dist(b, q) < 0.05)):
            return False                                  # nested from one tail, or one arrow
        return True

    order = sorted(range(len(ends)), key=lambda i: (not heavy[i], -math.dist(*ends[i])))
    lane = [0] * len(ends)
    for k, i in enumerate(order):
        for candidate in (0, 1, -1, 2, -2, 3, -3, 4, -4):
            if not any(lane[j] == candidate and clash(i, j) for j in order[:k]):
                lane[i] = candidate
                break
    return lane


def _own_stretch(a: tuple[float, float], b: tuple[float, float],
                 others: list[tuple[tuple[float, float], tuple[float, float]]]) -> list[float]:
    """Where along ``a → b`` (fractions, best first) its label can name it alone.

    Vectors drawn along one line overlap (V_A₄ within V_B₄, both from o_v): the
    longer one's label goes on the stretch no other arrow covers, so each label
    sits by its own arrow. An arrow wholly covered takes its middle.
    """
    length = math.dist(a, b)
    d = ((b[0] - a[0]) / length, (b[1] - a[1]) / length)
    covered = []
    for p, q in others:
        # Another arrow on the same carrier: both its ends within a hair of a → b's line.
        if all(abs((e[0] - a[0]) * d[1] - (e[1] - a[1]) * d[0]) < 0.05 for e in (p, q)):
            s, t = sorted(((e[0] - a[0]) * d[0] + (e[1] - a[1]) * d[1]) / length for e in (p, q))
            covered.append((s, t))
    free = [(0.0, 1.0)]
    for s, t in covered:
        free = [piece for lo, hi in free
                for piece in ((lo, min(hi, s)), (max(lo, t), hi)) if piece[1] - piece[0] > 1e-9]
    lo, hi = max(free, key=lambda f: f[1] - f[0], default=(0.0, 1.0))
    if (hi - lo) * length < 6.0:
        lo, hi = 0.0, 1.0
    mid = (lo + hi) / 2
    return [mid + k * (hi - lo) for k in (0.0, -0.15, 0.15, -0.3, 0.3, -0.4, 0.4)]


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


def _middle(a: tuple[float, float], b: tuple[float, float]) -> tuple[float, float]:
    return (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
