"""Place labels where they touch neither each other nor the drawing.

Each label tries rings of candidate positions around its anchor, preferred direction
first, and takes the first that is clear; if none is, the one with the least weighted
ink under it. Placed labels become obstacles for the next. Candidates are priced on a
raster of the page (:mod:`.occupancy`), all of a label's at once; shapely keeps the
obstacles' exact shapes for the few callers that weigh a line or a shape of their own.
A label is held nearer what it names than any other named thing (:mod:`.label_nearness`);
its text is typeset, subscripts and all, by :mod:`.typeset`.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon, box
from shapely.geometry import Point as SPoint
from shapely.geometry.base import BaseGeometry
from shapely.strtree import STRtree

from .figure import Circle, Figure, Path, Text
from .label_nearness import (Owned, Shape, as_shape, box_distance, name_at, same_thing,
                             shape_ends)
from .occupancy import Occupancy
from .symbols import badge_radius, draw_badge

__all__ = ["LabelPlacer", "paper_angle"]


class LabelPlacer:
    """Collects obstacles on a page and places labels clear of them."""

    def __init__(self, fig: Figure):
        self.fig = fig
        self.obstacles: list[BaseGeometry] = []
        self.keys: list[object] = []
        self.weights: list[float] = []
        self._tree: STRtree | None = None
        self.ink = Occupancy()
        self.seen = 0                 # fig.items looked through for arrowheads
        self._drawn = 0               # and for lines, by block_drawn
        self.named: list[Shape] = []
        self._named_ends: dict[int, np.ndarray] = {}   # by kind, of ``named``
        self.clearance = 0.8
        # A page that is fitted to its content afterwards has no edge to avoid.
        self.page = box(1.0, 1.0, fig.width - 1.0, fig.height - 1.0) if fig.width else None

    def block(self, geom: BaseGeometry, key: object = None, weight: float = 1.0) -> None:
        """Mark an area (a link, a symbol, a placed label) as taken; ``key`` names it.

        ``weight`` prices covering it: below 1 for a thin working line a label may
        cross sooner than it would stray from its anchor or touch another label.
        """
        self.obstacles.append(geom)
        self.keys.append(key)
        self.weights.append(weight)
        self._tree = None
        self.ink.paint(geom, weight)

    def unblock(self, since: int) -> None:
        """Free the room of every obstacle blocked since there were ``since`` of them: a
        label taken back to be set again elsewhere."""
        for geom, weight in zip(self.obstacles[since:], self.weights[since:]):
            self.ink.paint(geom, -weight)
        del self.obstacles[since:], self.keys[since:], self.weights[since:]
        self._tree = None

    def name_points(self, points) -> None:
        """Register points that are (or will be) labelled on this page: a point's label must
        stand nearer its own point than any of these."""
        self.named += [(tuple(p),) for p in points]
        self._named_ends.clear()

    def name_vectors(self, vectors) -> None:
        """Register vectors, ``(tail, tip)``, that are (or will be) labelled on this page: a
        vector's label must stand nearer its own vector than any of these."""
        self.named += [(tuple(a), tuple(b)) for a, b in vectors]
        self._named_ends.clear()

    def block_head(self, tip: tuple[float, float], tail: tuple[float, float],
                   length: float = 3.2) -> None:
        """Mark the arrowhead an arrow from ``tail`` will end in at ``tip`` as a label's last
        resort (:data:`HEAD`), before the arrow is drawn."""
        n = math.dist(tip, tail)
        if n > 0.0:
            t = min(length, n) / n
            back = (tip[0] + t * (tail[0] - tip[0]), tip[1] + t * (tail[1] - tip[1]))
            self.block(LineString([tip, back]).buffer(1.2), weight=HEAD)

    def block_path(self, points, width: float = 0.4, weight: float = 1.0) -> None:
        """Mark a drawn polyline (with a little clearance) as taken."""
        if len(points) >= 2:
            self.block(LineString(points).buffer(width / 2 + 0.3, cap_style="flat"),
                       weight=weight)

    def block_segment(self, p: tuple[float, float], q: tuple[float, float],
                      width: float = 0.8) -> None:
        """Mark a drawn segment (with a little clearance) as taken."""
        self.block(LineString([p, q]).buffer(width / 2 + 0.3, cap_style="flat"))

    def overlap(self, geom: BaseGeometry, ignore: object = None) -> float:
        """Area of ``geom`` covered by obstacles (but those keyed ``ignore``) or off the page.

        Each obstacle's area counts times its weight.
        """
        return float(self.overlaps([geom], ignore)[0])

    def overlaps(self, shapes: list[BaseGeometry], ignore: object = None) -> np.ndarray:
        """:meth:`overlap` of each of ``shapes``, found together: one query of the tree and
        one pass of intersections for all the candidate spots of a label."""
        tree = self._tree_now()
        geoms = np.asarray(shapes, dtype=object)
        area = np.zeros(len(geoms))
        if self.page is not None:
            area += shapely.area(geoms) - shapely.area(shapely.intersection(geoms, self.page))
        if tree is not None and len(geoms):
            # Only shapes that truly meet an obstacle can share area with it.
            which, hit = tree.query(geoms, predicate="intersects")
            if ignore is not None:
                keep = np.array([self.keys[int(i)] != ignore for i in hit], dtype=bool)
                which, hit = which[keep], hit[keep]
            covered = shapely.area(shapely.intersection(
                geoms[which], np.asarray(self.obstacles, dtype=object)[hit]))
            # Summed per shape in the order the tree gives, as one shape at a time would.
            for k, h, a in zip(which.tolist(), hit.tolist(), covered.tolist()):
                area[k] += self.weights[h] * a
        return area

    def _tree_now(self) -> STRtree | None:
        if self._tree is None:
            self._tree = STRtree(self.obstacles) if self.obstacles else None
        return self._tree

    def clearest(self, shapes: list[BaseGeometry], ignore: object = None) -> int:
        """Index of the first of ``shapes`` clear of every obstacle, else of the least covered."""
        return _first_clear(self.overlaps(shapes, ignore))

    def spot(self, width: float, height: float,
             anchor: tuple[float, float] | list[tuple[float, float]], *,
             prefer: float | tuple[float, ...] = math.pi / 4, spread: float = math.pi,
             gap: float = 2.6, rings: tuple[float, ...] = (1.0, 1.6, 2.3),
             own: Owned | None = None,
             crossing: float = 0.0) -> tuple[tuple[float, float], float]:
        """Find the centre of a ``width`` × ``height`` box near ``anchor``; nothing is drawn.

        Directions are tried from each ``prefer`` angle (paper, rad) outwards, up to
        ``spread`` either side; the box's edge, not its centre, stands ``gap`` off
        the anchor. With ``own``, the name in the box stands nearer its point or vector
        than any other :meth:`named <name_points>` one, or else pays :data:`_ASTRAY`.
        Where no spot is clear, the nearest that covers no more than ``crossing`` (the
        weighted ink of thin lines a label may cross; first one that only touches them,
        :data:`_TOUCH`) is taken before the least covered.
        Returns the centre and the overlap left (0 when clear).
        """
        self._see_heads()
        prefers = prefer if isinstance(prefer, tuple) else (prefer,)
        anchors = np.asarray(anchor if isinstance(anchor, list) else [anchor], dtype=float)
        xy, ink = self._ring_costs(width / 2, height / 2, anchors, prefers, spread, gap,
                                   rings, 8)
        first = self._first_own(xy, ink, own)
        if first is None:
            # None clear: look again between the rings and the directions before settling
            # for the least covered.
            between = sorted({*rings, *((a + b) / 2 for a, b in zip(rings, rings[1:]))})
            xy, ink = self._ring_costs(width / 2, height / 2, anchors, prefers, spread, gap,
                                       between, 16)
            first = self._first_own(xy, ink, own)
            for most in (min(_TOUCH, crossing), crossing):
                if first is None and most > 0.0:
                    first = self._first_own(xy, ink, own, most)
        if first is not None:
            left = float(ink[first]) if ink[first] >= _NO_INK else 0.0
            return (float(xy[first, 0]), float(xy[first, 1])), left
        costs = ink.copy()
        if own is not None:
            # Straying costs _ASTRAY: a spot with that much more ink than the least cannot win.
            may = np.flatnonzero(ink <= ink.min() + _ASTRAY)
            costs[ink > ink.min() + _ASTRAY] = np.inf
            costs[may] += _ASTRAY * self._astray(xy[may], own)
        k = int(np.argmin(costs))
        return (float(xy[k, 0]), float(xy[k, 1])), float(costs[k])

    def _first_own(self, xy: np.ndarray, ink: np.ndarray, own: Owned | None,
                   crossing: float = 0.0) -> int | None:
        """The first spot clear of ink (or covering ``crossing`` at most) whose name stands
        nearer its own than any other (the nearness asked only of the clear ones), or None."""
        free = np.flatnonzero(ink < _NO_INK + crossing)
        if own is not None and len(free):
            free = free[~self._astray(xy[free], own)]
        return int(free[0]) if len(free) else None

    def _ring_costs(self, hw: float, hh: float, anchors: np.ndarray, prefers, spread: float,
                    gap: float, rings, steps: int) -> tuple[np.ndarray, np.ndarray]:
        """Candidate centres, ring by ring and for each anchor in turn, ``steps`` directions
        to a half turn from each preferred one, nearest first; and the ink under each."""
        turns = [(k + 1) // 2 * (1 if k % 2 else -1) * math.pi / steps for k in range(2 * steps)]
        angles = np.array([p + t for t in turns if abs(t) <= spread + 1e-9 for p in prefers])
        ux, uy = np.cos(angles), -np.sin(angles)
        # Push each box out until its edge, not its centre, is ``gap`` × ring away.
        edge = np.minimum(hw / np.maximum(np.abs(ux), 1e-9), hh / np.maximum(np.abs(uy), 1e-9))
        reach = gap * np.asarray(rings, dtype=float)[:, None, None] + edge
        xy = np.stack([anchors[None, :, None, 0] + reach * ux,
                       anchors[None, :, None, 1] + reach * uy], axis=-1).reshape(-1, 2)
        c = self.clearance
        # The box with its clearance about it, the corners rounded off: two crossed boxes.
        wide, tall, inner = self.costs(xy, (hw + c, hh), (hw, hh + c), (hw, hh))
        return xy, wide + tall - inner

    def _astray(self, xy: np.ndarray, own: Owned) -> np.ndarray:
        """Whether the name in each box centred at ``xy`` stands nearer another named thing
        of its kind (point or vector) than its own; those within half a millimetre of it are
        its own."""
        shape, hw, hh = own[0], own[3], own[4]
        out = np.zeros(len(xy), dtype=bool)
        named, pts = self._named_of_kind(len(shape))
        if not named:
            return out
        rival = np.array([not same_thing(r, shape) for r in named])
        centre, mine, _ = name_at(xy, own)
        # A rival can be nearer a box only if its bounding box is: test the pairs that may.
        lo, hi = pts.min(axis=1)[rival], pts.max(axis=1)[rival]
        gx = np.maximum(np.maximum(lo[None, :, 0] - centre[:, None, 0],
                                   centre[:, None, 0] - hi[None, :, 0]) - hw, 0.0)
        gy = np.maximum(np.maximum(lo[None, :, 1] - centre[:, None, 1],
                                   centre[:, None, 1] - hi[None, :, 1]) - hh, 0.0)
        may = np.hypot(gx, gy) < mine[:, None] - 1e-6
        boxes, rivals = np.flatnonzero(may.any(axis=1)), np.flatnonzero(may.any(axis=0))
        if not len(boxes):
            return out
        theirs = box_distance(centre[boxes], hw, hh, pts[rival][rivals]).min(axis=1)
        out[boxes] = theirs < mine[boxes] - 1e-6
        return out

    def _named_of_kind(self, size: int) -> tuple[list[Shape], np.ndarray]:
        """The named shapes of ``size`` points (1 a point, 2 a vector) and their ends (an
        array kept for all the labels placed till more are named)."""
        named = [r for r in self.named if len(r) == size]
        if size not in self._named_ends:
            self._named_ends[size] = shape_ends(named)
        return named, self._named_ends[size]

    def block_drawn(self) -> None:
        """Take the room of everything drawn on the figure since the last look: each line and
        outline with a little clearance, each dot or circle as a disc (an arc, drawn with
        its own path, the caller blocks). For a figure drawn first and named after, where
        every name must keep off every line."""
        self._see_heads()
        for it in self.fig.items[self._drawn:]:
            if isinstance(it, Path) and it.style not in _HEADS:
                if it.closed and len(it.points) >= 3:
                    self.block(Polygon(it.points).buffer(0.3))
                else:
                    self.block_path(it.points)
            elif isinstance(it, Circle):
                self.block(SPoint(it.centre).buffer(it.radius + 0.3))
        self._drawn = len(self.fig.items)

    def _see_heads(self) -> None:
        """Take the room of every arrowhead drawn since the last look, whoever drew it: a
        label may cover a line sooner than the head that tells the line's sense."""
        items = self.fig.items
        for it in items[self.seen:]:
            if isinstance(it, Path) and it.closed and it.style in _HEADS:
                self.block(Polygon(it.points).buffer(0.3), weight=HEAD)
        self.seen = len(items)

    def costs(self, xy: np.ndarray, *sizes: tuple[float, float]) -> np.ndarray:
        """Weighted ink (mm²) under boxes centred at ``xy``, and their area off the page: a
        row for each of ``sizes``, a box's half width and half height."""
        cost = self.ink.ink(xy, *sizes)
        if self.page is not None:
            x0, y0, x1, y1 = self.page.bounds
            for row, (hw, hh) in zip(cost, sizes):
                w = np.minimum(xy[:, 0] + hw, x1) - np.maximum(xy[:, 0] - hw, x0)
                h = np.minimum(xy[:, 1] + hh, y1) - np.maximum(xy[:, 1] - hh, y0)
                row += 4 * hw * hh - np.maximum(w, 0) * np.maximum(h, 0)
        return cost

    def place(self, text: str, anchor: tuple[float, float] | list[tuple[float, float]], *,
              prefer: float | tuple[float, ...] = math.pi / 4, spread: float = math.pi,
              gap: float = 2.6, size: float = 3.5, italic: bool = True,
              rings: tuple[float, ...] = (1.0, 1.6, 2.3), sub: str = "",
              own: Shape | tuple[float, float] | None = None) -> Text:
        """Put ``text`` (subscript ``sub``) near ``anchor``, or the first of several with room.

        Directions are tried from each ``prefer`` angle (paper, rad) outwards, up to
        ``spread`` either side. ``own`` is the point (or the vector, tail and tip) the text
        names, if it names one.
        """
        probe = Text((0.0, 0.0), text, size, "middle", italic, sub=sub)
        x0, y0, x1, y1 = probe.box()
        # The box of a subscripted label hangs below its centre line: aim the box.
        dy = (y0 + y1) / 2
        own = as_shape(own)
        owned = None if own is None else (own, 0.0, 0.0, (x1 - x0) / 2, (y1 - y0) / 2, 0.0)
        c, _ = self.spot(x1 - x0, y1 - y0, anchor, prefer=prefer, spread=spread, gap=gap,
                         rings=rings, own=owned)
        t = Text((c[0], c[1] - dy), text, size, "middle", italic, sub=sub, owner=own)
        self.block_label(t.box())
        self.fig.add(t)
        return t

    def place_numbered(self, text: str, anchor: tuple[float, float] | list[tuple[float, float]],
                       numbers: list[int], *, sub: str = "",
                       prefer: float | tuple[float, ...] = math.pi / 4, spread: float = math.pi,
                       gap: float = 1.4, size: float = 3.4, tail: str = "",
                       rings: tuple[float, ...] = (1.0, 1.6, 2.4, 3.4, 4.6, 6.0, 8.0),
                       farther: tuple[float, ...] = (), crossing: float = 0.0,
                       own: Shape | tuple[float, float] | None = None,
                       also: tuple[tuple[str, str], ...] = (),
                       beside: bool = False) -> tuple[float, float] | None:
        """Place a label followed by circled step numbers, as one unit clear of everything.

        Either part may be empty. ``tail`` follows the subscript on the baseline
        ("Aⁿ" sub "B/A" tail " = 0"). ``rings`` are the distances tried, in
        ``gap``s: fewer keep a label by its anchor at the cost of some overlap;
        ``farther`` rings are tried after them when none of theirs is clear (covers more
        than ``crossing``, the weighted ink of thin lines a label may cross), for a
        figure where covering a label is worse than standing a little off. ``own`` is the
        point (or the vector, tail and tip) the text names, if it names one. ``also`` are
        more names, text and subscript, of the same thing, each set after an equals sign
        ("V_A₂ = V_A₄": one arrow). ``beside``: the name stands next to what it names and
        its numbers beyond it, before it where the unit stands to the left ("②⑤ a₂"), as
        a reader takes a name for the point nearest it.
        Returns the unit's centre, or None if there was nothing to place.
        """
        if not text and not numbers:
            return None
        parts = [Text((0.0, 0.0), text, size, "middle", sub=sub, tail=tail)] if text else []
        parts += [Text((0.0, 0.0), f"= {more}", size, "middle", sub=more_sub)
                  for more, more_sub in also if text]
        t = parts[0] if parts else None
        x0, y0, x1, y1 = _row_box(parts) if parts else (0.0, 0.0, 0.0, 0.0)
        radii = [badge_radius(n) for n in numbers]
        w = (x1 - x0) + sum(2 * r + _SPACE for r in radii) - (0.0 if t else _SPACE)
        h = max(y1 - y0, 2 * max(radii, default=0.0))
        own = as_shape(own)
        owned = None
        if own is not None and t:
            # Only the first name is held to what it names: its box within the unit's, at
            # the unit's left end, or (beside) after the numbers where that stands it nearer.
            nx0, ny0, nx1, ny1 = t.box()
            owned = (own, ((nx1 - nx0) - w) / 2, (ny0 + ny1 - y0 - y1) / 2, (nx1 - nx0) / 2,
                     (ny1 - ny0) / 2, sum(2 * r + _SPACE for r in radii) if beside else 0.0)
        c, cost = self.spot(w, h, anchor, prefer=prefer, spread=spread, gap=gap, rings=rings,
                            own=owned, crossing=crossing)
        if cost > crossing and farther:
            c2, cost2 = self.spot(w, h, anchor, prefer=prefer, spread=spread, gap=gap,
                                  rings=farther, own=owned)
            if cost2 < cost:
                c = c2
        x = c[0] - w / 2
        numbers_first = owned is not None and bool(name_at(np.array([c]), owned)[2][0])
        if numbers_first:
            x = self._badges(numbers, radii, x, c[1])
        for k, part in enumerate(parts):
            px0, py0, px1, py1 = part.box()
            # the first name stands for the unit: it alone is held near what they name
            self.fig.add(replace(part, at=(x + (px1 - px0) / 2, c[1] - (y0 + y1) / 2),
                                 owner=own if k == 0 else None))
            x += (px1 - px0) + _SPACE
        if not numbers_first:
            self._badges(numbers, radii, x, c[1])
        self.block_label((c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2))
        return c

    def _badges(self, numbers: list[int], radii: list[float], x: float, y: float) -> float:
        """Draw circled ``numbers`` in a row from ``x``; return where the row ends."""
        for n, r in zip(numbers, radii):
            draw_badge(self.fig, (x + r, y), n)
            x += 2 * r + _SPACE
        return x

    def block_label(self, bounds: tuple[float, float, float, float]) -> None:
        """Mark a placed label's box ``(x0, y0, x1, y1)`` as taken, with room about it, at
        :data:`LABEL`'s price: as :meth:`place` marks its own, for a label its caller set at
        a :meth:`spot`."""
        self.block(box(*bounds).buffer(0.4), weight=LABEL)


def paper_angle(v: tuple[float, float]) -> float:
    """The direction of a paper vector (y down) as :meth:`LabelPlacer.spot` takes a
    ``prefer``: radians from the x axis, counter-clockwise as the page is read.

    >>> round(paper_angle((0.0, -1.0)), 4)           # up the page
    1.5708
    """
    return math.atan2(-v[1], v[0])


_ASTRAY = 100.0
"""What a spot costs (mm²) whose name stands nearer another named thing than its own."""

LABEL = 10.0
"""What covering a placed label costs, against 1 for a line: only where nothing else is left."""

HEAD = 10.0
"""What covering an arrowhead costs, against 1 for a line."""

_HEADS = ("arrowhead",)

_SPACE = 0.6
"""The space (mm) between the parts of a label set in a row: names, then circled numbers."""

_TOUCH = 0.05
"""Weighted ink (mm²) of a spot whose clearance only touches a line's: no ink is crossed."""

_NO_INK = 1e-6
"""Weighted ink (mm²) below which a spot is clear: a thousandth of the least a cell holds."""


def _row_box(parts: list[Text]) -> tuple[float, float, float, float]:
    """The box of texts set in a row, :data:`_SPACE` apart, each centred on one line."""
    boxes = [p.box() for p in parts]
    width = sum(b[2] - b[0] for b in boxes) + _SPACE * (len(boxes) - 1)
    return (0.0, min(b[1] for b in boxes), width, max(b[3] for b in boxes))


def _first_clear(costs: np.ndarray) -> int:
    """The first spot whose overlap is nil, else the first of the least overlap."""
    clear = np.flatnonzero(costs <= 1e-9)
    return int(clear[0]) if len(clear) else int(np.argmin(costs))
