"""The kinematic diagram: the mechanism at one position, in textbook style.

It draws what the assembly located (the construction's outputs), never
recomputing geometry: ground pivots with hatching, pins, bars and plates, slider
blocks on hatched guides, the input's θ and ω, link numbers, point labels, and a
scale bar that measures true on the printed page.

A contact of a circle on a flat face is assembled as its equivalent pin in a slot,
but drawn as what the student sees: the cam's circle, the follower's face and the
contact point P, where the assembly marked it. Two circles in contact (a roller
on a circular cam) are drawn as both circles and P on their line of centres.

A pin in a curved slot is drawn in a slot about its centre of curvature, carried
by its link's body; a block on a curved guide stands tangent to a hatched arc. The
block's pin at the centre of curvature, which the file reader adds to the block
(its kinematic equivalent), is not drawn: that centre is a bare dot.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from shapely.geometry import MultiPoint, Point as SPoint

from ..constructions.assembly import Assembly
from ..constructions.model import Arc, Mechanism, Slide, SlideKind
from ..constructions.narration import significant, words
from ..constructions.scales import face_ends, space_per_cm

from .figure import Circle, Figure, Path, Text, View, arc_points
from .labels import LabelPlacer, subscript
from .scales import draw_caption
from .symbols import (PIN_RADIUS, draw_block, draw_curved_guide, draw_curved_slot,
                      draw_ground_pivot, draw_guide, draw_hatched_arc, draw_pin, draw_turning_arrow,
                      mark_angle,
                      unit)

__all__ = ["draw_kinematic_diagram", "input_caption", "subscript"]

_MARGIN = 8.0              # white round the drawing, mm
_BLOCK = (9.0, 5.0)        # slider block on paper, mm
_DOT = 0.55                # a marked point (circle centre, contact point) on paper, mm
_FACE_MARGIN = 4.0         # a face runs this far (paper mm) past its own point, under a block
_SLOT_HALF = 20.0          # a curved slot runs this far (paper mm) either side of its middle
_SLOT_WIDTH = PIN_RADIUS + 0.35   # half its width, so the pin just fits


@dataclass(frozen=True, slots=True)
class _Contact:
    """A circle-on-face contact in world metres: what the diagram draws for it."""

    slide: Slide
    centre: tuple[float, float]
    radius: float
    point: tuple[float, float]        # P, the foot of the common normal
    away: tuple[float, float]         # unit normal from the circle across the face


@dataclass(frozen=True, slots=True)
class _Pair:
    """Two circles in contact, in world metres: both circles and P on their line of centres."""

    cam: tuple[float, float]
    cam_radius: float
    roller: tuple[float, float]
    roller_radius: float
    point: tuple[float, float]        # P
    normal: tuple[float, float]       # unit, from the cam's centre toward the roller's


@dataclass(frozen=True, slots=True)
class _Track:
    """A curved slot or guide on paper: an arc about its centre of curvature.

    ``root`` is where the carrying link's body meets it (None on the frame).
    """

    arc: Arc
    centre: tuple[float, float]
    radius: float                     # mm
    start: float                      # paper angle, rad, CCW as seen
    sweep: float
    root: tuple[float, float] | None


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


def draw_kinematic_diagram(record: Assembly, *, per_cm: float | None = None) -> Figure:
    """Draw the kinematic diagram of a mechanism from the record of its position.

    Everything drawn is read off the record: the points, guides and axes the
    assembly located, the contact points it marked. ``per_cm`` is the space scale
    (file units per paper cm) the solution chose; by default the one that fits the
    mechanism (:func:`~tarsim.constructions.scales.space_per_cm`).
    """
    return _Diagram(record, per_cm).draw()


class _Diagram:
    def __init__(self, asm: Assembly, per_cm: float | None = None):
        self.asm = asm
        self.per_cm = per_cm or space_per_cm(asm)
        self.m: Mechanism = asm.mechanism
        self.world = {n: asm.xy(n) for n in self.m.point_names}
        self.contacts = [self.contact(i, s) for i, s in enumerate(self.m.slides)
                         if s.contact is not None]
        self.pairs = [self.pair(a) for a in self.m.arcs if a.contact is not None]
        # A block on a curved guide carries the centre of curvature as its pin: a
        # kinematic stand-in, not a part of the block to draw.
        self.synthetic = {(a.link, a.centre) for a in self.m.arcs if a.kind is SlideKind.BLOCK}

    def links_at(self, name: str) -> list[int]:
        """The links drawn at a point (a block's stand-in pin left out)."""
        return [k for k in self.m.links_at(name) if (k, name) not in self.synthetic]

    def names(self, number: int) -> list[str]:
        """The points drawn on a link (a block's stand-in pin left out)."""
        return [n for n in self.m.link(number).names if (number, n) not in self.synthetic]

    def contact(self, index: int, s: Slide) -> _Contact:
        """Where a contact's circle, face and P lie: P as the assembly marked it."""
        c, r = self.world[s.point], s.contact.circle.radius
        ref = self.asm.contacts[s]
        p = self.asm.output(ref).xy
        d = unit(self.asm.guide(index).direction)
        away = unit(_sub(p, c)) if math.dist(p, c) > 0.0 else (-d[1], d[0])
        return _Contact(s, c, r, p, away)

    def face(self, k: _Contact, margin: float) -> tuple[tuple[float, float], tuple[float, float]]:
        """The face's ends as drawn: round P, and ``margin`` (m) round its own point."""
        return face_ends(self.asm, k.slide, self.asm.contacts[k.slide], margin)

    def pair(self, a: Arc) -> _Pair:
        """Where two touching circles and P lie: P as the assembly marked it, on their line
        of centres."""
        c, r = self.world[a.centre], self.world[a.point]
        cam, roller = a.contact.face.radius, a.contact.circle.radius
        n = unit(_sub(r, c)) if math.dist(r, c) > 0.0 else (1.0, 0.0)
        return _Pair(c, cam, r, roller, self.asm.output(self.asm.contacts[a]).xy, n)

    def track(self, a: Arc) -> _Track:
        """Lay out a curved slot or guide on paper about its centre of curvature.

        It is centred on its pin or block, where the figure shows it: on the frame as
        long as a straight guide, on a moving link a shorter slot. The link's body
        (a bar from its pivot) holds the slot at its middle, on the edge that faces
        the pivot; the centre of curvature is a point of the link's plane, not of its
        body, so the bar does not run to it.
        """
        c, p = self.paper[a.centre], self.paper[a.point]
        r = a.radius * self.view.scale
        at = _angle(c, p)
        if a.guide_link == 1:
            half = min(math.pi / 6, max(22.0, 0.5 * self.travel(a.point, _tangent(at))) / r)
            return _Track(a, c, r, at - half, 2 * half, None)
        half = min(math.pi / 6, _SLOT_HALF / r)
        w = _SLOT_WIDTH if a.kind is SlideKind.PIN else 0.0
        pivot = next((self.paper[n] for n in self.names(a.guide_link) if n != a.centre), c)
        root = min(((c[0] + e * math.cos(at), c[1] - e * math.sin(at)) for e in (r - w, r + w)),
                   key=lambda q: math.dist(q, pivot))
        return _Track(a, c, r, at - half, 2 * half, root)

    # ----- layout ------------------------------------------------------------------
    def layout(self) -> None:
        s = 10.0 / (self.per_cm * self.m.units.metres)   # paper mm per world metre
        self.view = View(s, (0.0, 0.0))
        self.fig = Figure(0.0, 0.0, title=self.m.name)
        self.placer = LabelPlacer(self.fig)
        self.paper = {n: self.view(p) for n, p in self.world.items()}
        self.placer.name_points(self.paper.values())
        self.tracks = [self.track(a) for a in self.m.arcs if a.contact is None]
        self.downs: dict[str, tuple[float, float]] = {}    # each ground pivot's support

    # ----- drawing ---------------------------------------------------------------------
    def draw(self) -> Figure:
        self.layout()
        self.draw_frame_guides()
        self.draw_ground_pivots()
        self.draw_links()
        self.draw_contacts()
        self.draw_blocks()
        self.draw_pins()
        self.draw_input()
        self.label_links()
        self.label_points()
        self.fit_page()
        return self.fig

    def fit_page(self) -> None:
        """Size the page to the drawing plus margins, and set the caption under it."""
        draw_caption(self.fig, self.m.name, [input_caption(self.m)], per_cm=self.per_cm,
                     unit=self.m.units.length, margin=_MARGIN)

    def slot_reach(self, number: int) -> list[tuple[float, float]]:
        """Paper points a link must reach: its own, what runs in its slot, its curved tracks.

        A curved track's centre is left out unless a link is pinned there.
        """
        bare = {t.arc.centre for t in self.tracks if t.arc.guide_link == number}
        pts = [self.paper[n] for n in self.names(number)
               if n not in bare or len(self.links_at(n)) > 1]
        pts += [self.paper[s.point] for s in self.m.slides
                if s.guide_link == number and _is_slot(s)]
        pts += [t.root for t in self.tracks if t.arc.guide_link == number]
        return pts

    def slotted(self, number: int) -> bool:
        """True if a pin or block runs in a slot of link ``number`` (a contact is no slot)."""
        return any(s.guide_link == number and _is_slot(s) for s in self.m.slides)

    def block_lift(self, s: Slide) -> tuple[tuple[float, float], float]:
        """How far (mm) a block is drawn off its point, and along which paper direction.

        A flat-faced follower's block point lies on its face; centred there, the
        block would cover the face and the cam. It is drawn standing on the face
        instead, as the follower's stem, which the rigid link allows.
        """
        d = unit(self.view.direction(self.asm.guide(self.m.slides.index(s)).direction))
        for k in self.contacts:
            if k.slide.guide_link != s.link or k.slide.contact.face.through != s.point:
                continue
            n = self.view.direction(k.away)
            along = d[0] * n[0] + d[1] * n[1]
            if abs(along) < 1e-6:
                break  # the face runs along the guide: nothing to stand on
            # Clear the face with the block's near corners, however the face is tilted.
            lift = _BLOCK[0] / 2 + _BLOCK[1] / 2 * math.sqrt(1.0 - along * along) / abs(along)
            return (d if along > 0 else (-d[0], -d[1])), lift
        return d, 0.0

    def block_centre(self, s: Slide) -> tuple[float, float]:
        """Where a block is drawn (see :meth:`block_lift`)."""
        (ux, uy), lift = self.block_lift(s)
        p = self.paper[s.point]
        return (p[0] + lift * ux, p[1] + lift * uy)

    def draw_contacts(self) -> None:
        """Draw each cam circle, its flat face or second circle, and P (dots, not pins).

        A face on the frame that a wheel rolls on is the ground: it is hatched.
        """
        for k in self.contacts:
            self.draw_circle(k.centre, k.radius)
            # Past its own point only if that is a bare dot (under a block), not a pivot.
            margin = _FACE_MARGIN if self.marked(k.slide.contact.face.through) else 0.0
            a, b = (self.view(e) for e in self.face(k, margin / self.view.scale))
            if k.slide.rolling and k.slide.guide_link == 1:
                self.placer.block(draw_guide(self.fig, a, b, self.view.direction(k.away)))
            else:
                self.fig.line(a, b, "link")
            self.placer.block_segment(a, b, 0.6)
            self.draw_dot(self.view(k.point))
            for n in (k.slide.point, k.slide.contact.face.through):
                if self.marked(n):
                    self.draw_dot(self.paper[n])
        for k, a in zip(self.pairs, [a for a in self.m.arcs if a.contact is not None]):
            self.draw_circle(k.cam, k.cam_radius)
            self.draw_circle(k.roller, k.roller_radius)
            self.draw_dot(self.view(k.point))
            if a.rolling and a.guide_link == 1:
                # The fixed circle a wheel rolls round is the ground: hatched on its far
                # side from the wheel, either way of the contact.
                c, p = self.view(k.cam), self.view(k.point)
                at = math.atan2(c[1] - p[1], p[0] - c[0])
                self.placer.block(draw_hatched_arc(
                    self.fig, c, k.cam_radius * self.view.scale, at - 0.7, 1.4,
                    inward=a.contact.side == "outside"))
        # A cam's centre and a centre of curvature are bare dots, unless a link is pinned there.
        for n in dict.fromkeys(a.centre for a in self.m.arcs):
            if self.marked(n):
                self.draw_dot(self.paper[n])

    def draw_circle(self, centre: tuple[float, float], radius: float) -> None:
        """A circular profile (world centre and radius) as a link outline."""
        c, r = self.view(centre), radius * self.view.scale
        self.fig.add(Circle(c, r, "link"))
        self.placer.block(SPoint(c).buffer(r + 0.6).difference(SPoint(c).buffer(r - 0.6)))

    def draw_dot(self, at: tuple[float, float]) -> None:
        """A marked point on paper that is not a joint: a small filled dot."""
        self.fig.add(Circle(at, _DOT, "arrowhead"))
        self.placer.block(SPoint(at).buffer(_DOT + 0.3))

    def draw_frame_guides(self) -> None:
        centre = _centroid([self.paper[n] for n in self.m.frame.names])
        for i, s in enumerate(self.m.slides):
            if s.guide_link != 1 or s.kind is not SlideKind.BLOCK:
                continue
            line = self.asm.guide(i)
            d = unit(self.view.direction(line.direction))
            n = (-d[1], d[0])
            p = self.block_centre(s)
            # The guide and its hatching lie on the side of the block no link leaves it by;
            # with links either way (or none), on the far side from the frame pivots.
            pin = self.paper[s.point]
            leave = sum(((q[0] - pin[0]) * n[0] + (q[1] - pin[1]) * n[1])
                        for k in self.links_at(s.point) if k != 1
                        for q in (self.paper[o] for o in self.names(k) if o != s.point))
            away = (p[0] - centre[0]) * n[0] + (p[1] - centre[1]) * n[1]
            if abs(leave) > 1.0:
                away = -leave
            side = n if away >= 0 else (-n[0], -n[1])
            off = _BLOCK[1] / 2
            half = max(22.0, 0.5 * self.travel(s.point, d))
            # A block standing on a face has its guide above the face only.
            u, lift = self.block_lift(s)
            lo, hi = (-half, half) if lift == 0.0 else (1.0 - _BLOCK[0] / 2, half + _BLOCK[0])
            if lift == 0.0:
                # The guide runs past every marked place of the block on it (a limit point).
                along = [(q[0] - p[0]) * u[0] + (q[1] - p[1]) * u[1] for q in self.marks()
                         if abs((q[0] - p[0]) * n[0] + (q[1] - p[1]) * n[1]) <= 0.5]
                lo, hi = min([lo] + [t - 8.0 for t in along]), max([hi] + [t + 8.0 for t in along])
            a = (p[0] + off * side[0] + lo * u[0], p[1] + off * side[1] + lo * u[1])
            b = (p[0] + off * side[0] + hi * u[0], p[1] + off * side[1] + hi * u[1])
            band = draw_guide(self.fig, a, b, side)
            self.placer.block(band.buffer(0.3))
            self.placer.block_segment(a, b)
        for t in self.tracks:
            if t.arc.guide_link == 1:
                self.draw_track(t)

    def draw_track(self, t: _Track) -> None:
        """A curved slot (an outline), or a guide: hatched on the frame, the link's arc if not.

        A frame guide is offset by half the block's height to the side away from the
        frame's other points, as a straight guide is.
        """
        a = t.arc
        if a.kind is SlideKind.PIN:
            style = "guide" if a.guide_link == 1 else "link"
            shape = draw_curved_slot(self.fig, t.centre, t.radius, t.start, t.sweep,
                                     _SLOT_WIDTH, style)
        elif a.guide_link == 1:
            others = [self.paper[n] for n in self.m.frame.names if n != a.centre]
            inside = math.dist(_centroid(others or [self.paper[a.point]]), t.centre) < t.radius
            side = 1.0 if inside else -1.0
            shape = draw_curved_guide(self.fig, t.centre, t.radius + side * _BLOCK[1] / 2,
                                      t.start, t.sweep, side)
        else:
            rim = arc_points(t.centre, t.radius, t.start, t.sweep)
            self.fig.add(Path(tuple(rim), "link"))
            shape = MultiPoint(rim).convex_hull
        self.placer.block(shape.buffer(0.5))

    def marks(self) -> list[tuple[float, float]]:
        """Paper points a figure marks beyond the mechanism's own (none here; a scene's)."""
        return []

    def rays_through(self, at: tuple[float, float]) -> list[tuple[float, float]]:
        """Paper directions, both ways, of the figure's lines through ``at`` beyond the
        mechanism's own (none here; a scene's)."""
        return []

    def travel(self, point: str, d: tuple[float, float]) -> float:
        """A guide long enough to look like a guide: the drawing's width along it."""
        ps = list(self.paper.values())
        proj = [q[0] * d[0] + q[1] * d[1] for q in ps]
        return 0.6 * (max(proj) - min(proj))

    def draw_ground_pivots(self) -> None:
        for name in self.m.frame.names:
            moving = [k for k in self.links_at(name) if k != 1]
            if not moving:
                continue
            at = self.paper[name]
            dirs = []
            for k in moving:
                for other in self.names(k):
                    if other != name:
                        dirs.append(unit(_sub(self.paper[other], at)))
                for s in self.m.slides:
                    if s.guide_link == k and s.point in self.paper:
                        dirs.append(unit(_sub(self.paper[s.point], at)))
            down = _clearest_direction(dirs, self.rays_through(at))
            self.downs[name] = down
            foot = draw_ground_pivot(self.fig, at, down)
            self.placer.block(foot)

    def draw_links(self) -> None:
        for k in self.m.links:
            if k.number == 1:
                continue
            for t in self.tracks:
                if t.arc.guide_link == k.number:
                    self.draw_track(t)
            slotted = self.slotted(k.number)
            pts = self.slot_reach(k.number)
            if len(pts) < 2:
                continue
            hull = MultiPoint(pts).convex_hull
            if hull.geom_type == "Polygon" and hull.area > 4.0 and not slotted:
                ring = tuple(hull.exterior.coords)[:-1]
                # The tint goes under the construction lines drawn before it; the outline
                # stays in its place.
                self.fig.add_under(Path(ring, "plate_fill", closed=True))
                self.fig.add(Path(ring, "plate", closed=True))
                self.placer.block(hull.buffer(0.5))
                continue
            a, b = _extremes(pts)
            if slotted:
                a, b = self.overhang(k.number, a, b)
            self.fig.line(a, b, "link")
            self.placer.block_segment(a, b, 0.6)

    def overhang(self, number: int, a, b):
        """Run a slotted lever between its farthest points, a little past a block at either
        end: a block behind the pivot keeps the bar running through the pivot to it."""
        names = self.m.link(number).names

        def past(end, other):
            if any(math.dist(end, self.paper[n]) < 1e-9 for n in names):
                return end
            d = unit(_sub(end, other))
            return (end[0] + 2.0 * d[0], end[1] + 2.0 * d[1])

        return past(a, b), past(b, a)

    def draw_blocks(self) -> None:
        for i, s in enumerate(self.m.slides):
            if s.kind is not SlideKind.BLOCK:
                continue
            d = unit(self.view.direction(self.asm.guide(i).direction))
            shape = draw_block(self.fig, self.block_centre(s), d, *_BLOCK)
            self.placer.block(shape)
        for t in self.tracks:
            if t.arc.kind is SlideKind.BLOCK:  # tangent to its arc, square to the radius
                at = self.paper[t.arc.point]
                self.placer.block(draw_block(self.fig, at, _tangent(_angle(t.centre, at)),
                                             *_BLOCK))

    def draw_pins(self) -> None:
        for name, at in self.paper.items():
            on = self.links_at(name)
            slid = (any(s.point == name and _is_slot(s) for s in self.m.slides)
                    or any(a.point == name for a in self.m.pin_arcs))
            if 1 in on or self.marked(name):
                continue  # drawn with its ground symbol, or as a dot
            if len(on) >= 2 or slid:
                draw_pin(self.fig, at)
                self.placer.block(SPoint(at).buffer(PIN_RADIUS + 0.4))

    def marked(self, name: str) -> bool:
        """True for a point drawn as a bare dot: a circle's or arc's centre, a face's point."""
        return len(self.links_at(name)) < 2 and (
            any(name in (k.slide.point, k.slide.contact.face.through) for k in self.contacts)
            or any(a.centre == name for a in self.m.arcs))

    def draw_input(self) -> None:
        d = self.m.drive
        k = self.m.link(d.link)
        centre = self.paper[k.names[0]]
        theta = math.atan2(math.sin(d.angle), math.cos(d.angle))
        # θ: a dashed reference along +x and an arc up to the crank.
        ref_end = (centre[0] + 13.0, centre[1])
        self.fig.line(centre, ref_end, "reference")
        self.placer.block_segment(centre, ref_end, 0.3)
        mid = mark_angle(self.fig, centre, 8.0, 0.0, theta)
        half = theta / 2
        self.placer.place(f"θ{subscript(str(d.link))}", mid, prefer=half, gap=1.2, size=3.2)
        if d.omega == 0.0:
            return
        # ω: an arc arrow beside the crank, away from the θ mark and its reference line,
        # and clear of every point the figure marks (a centre that falls there keeps its
        # dot clear); its sense is ω's alone.
        first = (0.45, -1.65) if theta >= 0 else (-1.65, 0.45)
        lows = [theta + k for k in (*first, 1.9, -3.1, 3.35)]
        marks = self.marks() + [p for n, p in self.paper.items() if n != k.names[0]]

        def clearance(low: float) -> float:
            arc = [(centre[0] + 12.0 * math.cos(low + 1.2 * t / 8),
                    centre[1] - 12.0 * math.sin(low + 1.2 * t / 8)) for t in range(9)]
            if (-low) % (2 * math.pi) <= 1.2:          # across the reference line
                return 0.0
            return min((math.dist(a, m) for a in arc for m in marks), default=math.inf)
        low = next((w for w in lows if clearance(w) >= 3.0), lows[0])
        start, sweep = (low, 1.2) if d.omega > 0 else (low + 1.2, -1.2)
        label_at = draw_turning_arrow(self.fig, centre, 12.0, start, sweep)
        self.placer.block_path(arc_points(centre, 12.0, start, sweep), 0.35)
        self.placer.place(f"ω{subscript(str(d.link))}", label_at,
                          prefer=start + sweep / 2, gap=1.4, size=3.2)

    def label_links(self) -> None:
        for k in self.m.links:
            if k.number == 1:
                continue
            slotted = self.slotted(k.number)
            pts = self.slot_reach(k.number)
            if len(pts) == 1:
                at, prefer = pts[0], math.pi / 2
                gap = 4.2
                lifted = [s for s in self.m.slides if s.link == k.number
                          and s.kind is SlideKind.BLOCK and self.block_lift(s)[1] > 0.0]
                if lifted:  # beside the block standing on the face, not under it
                    at, prefer = self.block_centre(lifted[0]), (math.pi, 0.0)
            else:
                hull = MultiPoint(pts).convex_hull
                if hull.geom_type == "Polygon" and hull.area > 4.0 and not slotted:
                    c = hull.centroid
                    self.fig.add(Text((c.x, c.y), str(k.number), 3.4, italic=False))
                    continue
                a, b = _extremes(pts)
                if slotted:
                    a, b = self.overhang(k.number, a, b)
                at = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
                      for t in (0.55, 0.4, 0.7, 0.25, 0.85)]
                dx, dy = unit(_sub(b, a))
                prefer = math.atan2(dx, dy)  # the paper normal (−dy, dx) as a paper angle
                gap = 1.6
            prefer = prefer if isinstance(prefer, tuple) else (prefer, prefer + math.pi)
            self.placer.place(str(k.number), at, prefer=prefer,
                              spread=math.pi / 4, gap=gap, size=3.4, italic=False)
        pivots = [n for n in self.m.frame.names if len(self.links_at(n)) > 1]
        if pivots:
            # Past the pivot's hatching, the way its support stands, away from its links.
            dx, dy = self.downs.get(pivots[0], (0.0, 1.0))
            self.placer.place("1", self.paper[pivots[0]], prefer=math.atan2(-dy, dx),
                              spread=math.pi / 2, gap=7.5, size=3.4, italic=False)
        elif self.m.frame.names:
            # No fixed pivot (a wheel rolling on the ground drives): under the ground's
            # hatching at the frame's first point.
            self.placer.place("1", self.paper[self.m.frame.names[0]], prefer=-math.pi / 2,
                              spread=math.pi / 2, gap=7.5, size=3.4, italic=False)

    def label_points(self) -> None:
        centre = _centroid(list(self.paper.values()))
        for name, at in self.paper.items():
            away = _sub(at, centre)
            prefer = math.atan2(-away[1], away[0]) if math.hypot(*away) > 1e-6 else math.pi / 4
            self.placer.place(subscript(name), at, prefer=prefer, gap=2.0, size=3.6, own=at)
        # P goes beside the contact, off the common normal that runs through it; between
        # two circles, out along the tangent in the gap that opens between them.
        for point, normal, spread, rings in (
                [(k.point, k.away, math.pi, (1.0, 1.6, 2.3)) for k in self.contacts]
                + [(k.point, k.normal, math.pi / 8, (1.0, 1.6, 2.3, 3.2, 4.2))
                   for k in self.pairs]):
            d = self.view.direction(normal)
            along = (-d[1], d[0])
            prefer = tuple(math.atan2(-v[1], v[0]) for v in (along, (-along[0], -along[1])))
            self.placer.place("P", self.view(point), prefer=prefer, spread=spread, gap=1.6,
                              size=3.6, rings=rings)


# ----- small helpers ---------------------------------------------------------------------
def _is_slot(s: Slide) -> bool:
    """A slide drawn as a slot or guide; a contact's equivalent slide is drawn as profiles."""
    return s.contact is None


def _sub(p, q):
    return (p[0] - q[0], p[1] - q[1])


def _angle(centre, p) -> float:
    """The paper angle (rad, CCW as seen) of ``p`` about ``centre``."""
    return math.atan2(centre[1] - p[1], p[0] - centre[0])


def _tangent(angle: float) -> tuple[float, float]:
    """The paper direction along a circle at ``angle``, the way the angle grows."""
    return (-math.sin(angle), -math.cos(angle))


def _centroid(pts):
    return (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))


def _extremes(pts):
    best = (0.0, pts[0], pts[-1])
    for i, p in enumerate(pts):
        for q in pts[i + 1:]:
            d = math.dist(p, q)
            if d > best[0]:
                best = (d, p, q)
    return best[1], best[2]


def _clearest_direction(dirs: list[tuple[float, float]],
                        lines: list[tuple[float, float]] = ()) -> tuple[float, float]:
    """The paper direction for a ground symbol: straight down unless a link is in the way.

    A link within 65° of a direction crosses the symbol's triangle or its hatched base
    (the base reaches about 60° either side of the symbol's axis), so the symbol turns
    to the first direction that clears every link by that much and every one of the
    figure's ``lines`` through the pivot (a Kennedy line, both ways) by 25°; failing one,
    the first that clears the links, or else the clearest.

    >>> _clearest_direction([(0.0, -1.0)])                         # a link straight up
    (0.0, 1.0)
    >>> _clearest_direction([(0.0, -1.0)], [(0.0, 1.0), (0.0, -1.0)])   # and a line through
    (0.7071, 0.7071)
    """
    candidates = [(0.0, 1.0), (0.7071, 0.7071), (-0.7071, 0.7071), (1.0, 0.0), (-1.0, 0.0),
                  (0.0, -1.0)]

    def angle(c, d):
        return math.acos(max(-1.0, min(1.0, c[0] * d[0] + c[1] * d[1])))
    for c in candidates:
        if all(angle(c, d) >= math.radians(65) for d in dirs) and \
                all(angle(c, d) >= math.radians(25) for d in lines):
            return c
    best = None
    for rank, c in enumerate(candidates):
        clear = min((math.acos(max(-1.0, min(1.0, c[0] * d[0] + c[1] * d[1]))) for d in dirs),
                    default=math.pi)
        score = clear - 0.05 * rank
        if clear >= math.radians(65):
            return c
        if best is None or score > best[0]:
            best = (score, c)
    return best[1]
