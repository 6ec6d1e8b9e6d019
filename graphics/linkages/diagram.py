"""The kinematic diagram: the mechanism at one position, in textbook style.

It draws what the assembly located (the construction's outputs), never
recomputing geometry: ground pivots with hatching, pins, bars and plates, slider
blocks on hatched guides, the input's θ and ω, link numbers, point labels, and a
scale bar that measures true on the printed page.

This module holds the diagram (what it knows of the mechanism on paper, and the
order it draws in) and the pin-jointed linkage: ground pivots, links and pins. The
rest is drawn by its siblings: :mod:`.diagram_slides` (blocks, guides, curved slots
and guides), :mod:`.diagram_contacts` (a cam's circle on a face or a roller, and P)
and :mod:`.diagram_labels` (the input's θ and ω, link numbers, point names), each
joint as its kind's symbol says (:mod:`.joint_symbols`). A
scene (:mod:`.scene`) is a diagram with a record's steps drawn on it.
"""

from __future__ import annotations

import math

from shapely.geometry import MultiPoint, Point as SPoint

from tarsim.constructions.linkages.assembly_record import Assembly
from tarsim.constructions.joints import Slide
from tarsim.constructions.model import Mechanism
from tarsim.constructions.scales import space_per_cm

from .diagram_contacts import contact, draw_contacts, pair
from .diagram_labels import draw_input, input_caption, label_links, label_points
from .diagram_slides import draw_blocks, draw_frame_guides, draw_track, track
from .joint_symbols import Drawn, symbol_of
from ..figure import Figure, Path, View
from ..drafts import label_placer
from ..paper_points import difference, farthest_pair
from ..scales import draw_caption
from ..symbols import PIN_RADIUS, draw_ground_pivot, draw_pin, unit

__all__ = ["draw_kinematic_diagram"]

_MARGIN = 8.0              # white round the drawing, mm


def draw_kinematic_diagram(record: Assembly, *, per_cm: float | None = None) -> Figure:
    """Draw the kinematic diagram of a mechanism from the record of its position.

    Everything drawn is read off the record: the points, guides and axes the
    assembly located, the contact points it marked. ``per_cm`` is the space scale
    (file units per paper cm) the solution chose; by default the one that fits the
    mechanism (:func:`~tarsim.constructions.scales.space_per_cm`).
    """
    return _Diagram(record, per_cm).draw()


class _Diagram:
    """A mechanism's position on paper: what the diagram knows, and the order it draws in."""

    def __init__(self, asm: Assembly, per_cm: float | None = None):
        self.asm = asm
        self.per_cm = per_cm or space_per_cm(asm)
        self.m: Mechanism = asm.mechanism
        self.world = {n: asm.xy(n) for n in self.m.point_names}
        self.contacts = [contact(self, i, s) for i, s in enumerate(self.m.slides)
                         if symbol_of(s).drawn is Drawn.FACE]
        self.pairs = [pair(self, a) for a in self.m.arcs if symbol_of(a).drawn is Drawn.CIRCLES]
        # A block on a curved guide carries the centre of curvature as its pin: a
        # kinematic stand-in, not a part of the block to draw.
        self.synthetic = {(a.link, a.centre) for a in self.m.arcs if a.type.stands_as_pin}

    def links_at(self, name: str) -> list[int]:
        """The links drawn at a point (a block's stand-in pin left out)."""
        return [k for k in self.m.links_at(name) if (k, name) not in self.synthetic]

    def names(self, number: int) -> list[str]:
        """The points drawn on a link (a block's stand-in pin left out)."""
        return [n for n in self.m.link(number).names if (number, n) not in self.synthetic]

    # ----- layout ------------------------------------------------------------------
    def layout(self) -> None:
        s = 10.0 / (self.per_cm * self.m.units.metres)   # paper mm per world metre
        self.view = View(s, (0.0, 0.0))
        self.fig = Figure(0.0, 0.0, title=self.m.name)
        self.placer = label_placer(self.fig)
        self.paper = {n: self.view(p) for n, p in self.world.items()}
        self.placer.name_points(self.paper.values())
        self.tracks = [track(self, a) for a in self.m.arcs if symbol_of(a).drawn is Drawn.TRACK]
        self.downs: dict[str, tuple[float, float]] = {}    # each ground pivot's support

    # ----- drawing ---------------------------------------------------------------------
    def draw(self) -> Figure:
        self.layout()
        draw_frame_guides(self)
        self.draw_ground_pivots()
        self.draw_links()
        draw_contacts(self)
        draw_blocks(self)
        self.draw_pins()
        draw_input(self)
        self.plan_marks()
        label_links(self)
        label_points(self)
        self.fit_page()
        return self.fig

    def plan_marks(self) -> None:
        """Take the room of what a figure draws over the mechanism after naming it (nothing
        here; a scene's vectors), so that the names keep clear of it."""

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
                        dirs.append(unit(difference(self.paper[other], at)))
                for s in self.m.slides:
                    if s.guide_link == k and s.point in self.paper:
                        dirs.append(unit(difference(self.paper[s.point], at)))
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
                    draw_track(self, t)
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
            a, b = farthest_pair(pts)
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
            d = unit(difference(end, other))
            return (end[0] + 2.0 * d[0], end[1] + 2.0 * d[1])

        return past(a, b), past(b, a)

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


# ----- small helpers ---------------------------------------------------------------------
def _is_slot(s: Slide) -> bool:
    """A slide drawn as a slot or guide; a contact's equivalent slide is drawn as profiles."""
    return symbol_of(s).drawn is Drawn.GUIDE


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
