"""Place labels where they touch neither each other nor the drawing (shapely boxes).

Each label tries a ring of candidate positions around its anchor, preferred
direction first, and takes the first that is clear; if none is, the one with the
least overlap. Placed labels become obstacles for the next.
"""

from __future__ import annotations

import math
import re

import numpy as np
import shapely
from shapely.geometry import LineString, box
from shapely.geometry.base import BaseGeometry
from shapely.strtree import STRtree

from .figure import Figure, Text
from .symbols import badge_radius, draw_badge

__all__ = ["LabelPlacer", "typeset", "typeset_span", "subscript"]


class LabelPlacer:
    """Collects obstacles on a page and places labels clear of them."""

    def __init__(self, fig: Figure):
        self.fig = fig
        self.obstacles: list[BaseGeometry] = []
        self.keys: list[object] = []
        self.weights: list[float] = []
        self._tree: STRtree | None = None
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

    def _first_free(self, xy: np.ndarray, hw: float, hh: float) -> int | None:
        """The first of the boxes centred at ``xy`` whose clearance lies on the page and at
        most touches an obstacle (an overlap of no area), or None.

        Told by predicates, far cheaper than measuring areas, and in two passes: a box grown
        by half the clearance lies inside the rounded one, so an obstacle it meets crosses
        that one's interior; only the spots it leaves free are built and tested whole.
        """
        tree = self._tree_now()
        spots = np.arange(len(xy))
        if tree is not None:
            m = self.clearance / 2
            inner = shapely.box(xy[:, 0] - hw - m, xy[:, 1] - hh - m, xy[:, 0] + hw + m,
                                xy[:, 1] + hh + m)
            crossed = np.zeros(len(xy), dtype=bool)
            crossed[tree.query(inner, predicate="intersects")[0]] = True
            spots = np.flatnonzero(~crossed)
        shapes = _rounded_boxes(xy[spots], hw, hh, self.clearance)
        clear = (np.ones(len(spots), dtype=bool) if self.page is None
                 else shapely.within(shapes, self.page))
        if tree is not None and len(spots):
            which, hit = tree.query(shapes, predicate="intersects")
            met = np.zeros(len(spots), dtype=bool)
            met[which] = True
            untouched = np.flatnonzero(clear & ~met)
            # Only the spots before the first untouched one may still win, by a touch.
            upto = int(untouched[0]) if len(untouched) else len(spots)
            near = which < upto
            which, hit = which[near], hit[near]
            crossed = ~shapely.touches(shapes[which],
                                       np.asarray(self.obstacles, dtype=object)[hit])
            clear[which[crossed]] = False
        first = np.flatnonzero(clear)
        return int(spots[first[0]]) if len(first) else None

    def clearest(self, shapes: list[BaseGeometry], ignore: object = None) -> int:
        """Index of the first of ``shapes`` clear of every obstacle, else of the least covered."""
        return _first_clear(self.overlaps(shapes, ignore))

    def spot(self, width: float, height: float,
             anchor: tuple[float, float] | list[tuple[float, float]], *,
             prefer: float | tuple[float, ...] = math.pi / 4, spread: float = math.pi,
             gap: float = 2.6, rings: tuple[float, ...] = (1.0, 1.6, 2.3)
             ) -> tuple[tuple[float, float], float]:
        """Find the centre of a ``width`` × ``height`` box near ``anchor``; nothing is drawn.

        Directions are tried from each ``prefer`` angle (paper, rad) outwards, up to
        ``spread`` either side; the box's edge, not its centre, stands ``gap`` off
        the anchor. Returns the centre and the overlap left (0 when clear).
        """
        prefers = prefer if isinstance(prefer, tuple) else (prefer,)
        turns = [(k + 1) // 2 * (1 if k % 2 else -1) * math.pi / 8 for k in range(16)]
        angles = [p + t for t in turns if abs(t) <= spread + 1e-9 for p in prefers]
        anchors = anchor if isinstance(anchor, list) else [anchor]
        hw, hh = width / 2, height / 2
        centres: list[tuple[float, float]] = []
        for ring in rings:            # a ring at a time: most labels find room in the first
            these = []
            for base in anchors:
                for a in angles:
                    ux, uy = math.cos(a), -math.sin(a)
                    # Push the box out until its edge, not its centre, is ``gap`` away.
                    reach = gap * ring + min(hw / max(abs(ux), 1e-9), hh / max(abs(uy), 1e-9))
                    these.append((base[0] + reach * ux, base[1] + reach * uy))
            xy = np.asarray(these)
            first = self._first_free(xy, hw, hh)
            if first is not None:
                return these[first], 0.0
            centres += these
        # No ring has room: the spot least covered, by area (the only costly measure).
        costs = self.overlaps(list(_rounded_boxes(np.asarray(centres), hw, hh, self.clearance)))
        k = int(np.argmin(costs))
        return centres[k], float(costs[k])

    def place(self, text: str, anchor: tuple[float, float] | list[tuple[float, float]], *,
              prefer: float | tuple[float, ...] = math.pi / 4, spread: float = math.pi,
              gap: float = 2.6, size: float = 3.5, italic: bool = True,
              rings: tuple[float, ...] = (1.0, 1.6, 2.3), sub: str = "") -> Text:
        """Put ``text`` (subscript ``sub``) near ``anchor``, or the first of several with room.

        Directions are tried from each ``prefer`` angle (paper, rad) outwards, up to
        ``spread`` either side.
        """
        probe = Text((0.0, 0.0), text, size, "middle", italic, sub=sub)
        x0, y0, x1, y1 = probe.box()
        # The box of a subscripted label hangs below its centre line: aim the box.
        dy = (y0 + y1) / 2
        c, _ = self.spot(x1 - x0, y1 - y0, anchor, prefer=prefer, spread=spread, gap=gap,
                         rings=rings)
        t = Text((c[0], c[1] - dy), text, size, "middle", italic, sub=sub)
        return self._commit(t, box(*t.box()))

    def place_numbered(self, text: str, anchor: tuple[float, float] | list[tuple[float, float]],
                       numbers: list[int], *, sub: str = "",
                       prefer: float | tuple[float, ...] = math.pi / 4, spread: float = math.pi,
                       gap: float = 1.4, size: float = 3.4, tail: str = "",
                       rings: tuple[float, ...] = (1.0, 1.6, 2.4, 3.4, 4.6, 6.0, 8.0),
                       farther: tuple[float, ...] = ()) -> tuple[float, float] | None:
        """Place a label followed by circled step numbers, as one unit clear of everything.

        Either part may be empty. ``tail`` follows the subscript on the baseline
        ("Aⁿ" sub "B/A" tail " = 0"). ``rings`` are the distances tried, in
        ``gap``s: fewer keep a label by its anchor at the cost of some overlap;
        ``farther`` rings are tried after them when none of theirs is clear, for a
        figure where covering a label is worse than standing a little off.
        Returns the unit's centre, or None if there was nothing to place.
        """
        if not text and not numbers:
            return None
        t = Text((0.0, 0.0), text, size, "middle", sub=sub, tail=tail) if text else None
        x0, y0, x1, y1 = t.box() if t else (0.0, 0.0, 0.0, 0.0)
        radii = [badge_radius(n) for n in numbers]
        w = (x1 - x0) + sum(2 * r + 0.6 for r in radii) - (0.0 if t else 0.6)
        h = max(y1 - y0, 2 * max(radii, default=0.0))
        c, cost = self.spot(w, h, anchor, prefer=prefer, spread=spread, gap=gap, rings=rings)
        if cost > 0.0 and farther:
            c2, cost2 = self.spot(w, h, anchor, prefer=prefer, spread=spread, gap=gap,
                                  rings=farther)
            if cost2 < cost:
                c = c2
        x = c[0] - w / 2
        if t:
            self.fig.add(Text((x + (x1 - x0) / 2, c[1] - (y0 + y1) / 2), text, size, "middle",
                              sub=sub, tail=tail))
            x += (x1 - x0) + 0.6
        for n, r in zip(numbers, radii):
            draw_badge(self.fig, (x + r, c[1]), n)
            x += 2 * r + 0.6
        self.block(box(c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2).buffer(0.4))
        return c

    def _commit(self, t: Text, shape: BaseGeometry) -> Text:
        self.block(shape.buffer(0.4))
        self.fig.add(t)
        return t


_SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
_TRAILING = re.compile(r"^(.*?[^\d,])([\d,]+)([′″]*)$")


def typeset(label: str) -> tuple[str, str]:
    """Split a recorded label into text and true subscript, as a textbook prints it.

    ``V_A`` is V with subscript A; digits that end a name become Unicode
    subscripts (``I13`` → I₁₃, ``ω2`` → ω₂), inside a subscript too
    (``V_I23`` → V with subscript I₂₃), before primes too (``a4′`` → a₄′, an
    acceleration tip), and on each side of a relative vector's slash
    (``A_A3/A4`` → A with subscript A₃/A₄).

    Examples
    --------
    >>> typeset("V_I23")
    ('V', 'I₂₃')
    >>> typeset("I13")
    ('I₁₃', '')
    >>> typeset("A_B/A")
    ('A', 'B/A')
    >>> typeset("Aᶜ_A3/A4"), typeset("a4′")
    (('Aᶜ', 'A₃/A₄'), ('a₄′', ''))
    """
    head, _, sub = label.partition("_")
    return _digits_down(head), "/".join(_digits_down(part) for part in sub.split("/"))


def subscript(name: str) -> str:
    """Write a name's trailing digits as subscripts, as a textbook prints them ("O2" → "O₂").

    >>> subscript("O24")
    'O₂₄'
    """
    head = name.rstrip("0123456789")
    return head + name[len(head):].translate(_SUBSCRIPT)


def typeset_span(label: str) -> str:
    """A span named by its end points, as a textbook prints it: each number that follows a
    letter becomes a subscript.

    >>> typeset_span("O2G"), typeset_span("AB + O2A"), typeset_span("stroke")
    ('O₂G', 'AB + O₂A', 'stroke')
    """
    return _NAMED.sub(lambda m: m.group(0).translate(_SUBSCRIPT), label)


_NAMED = re.compile(r"(?<=[A-Za-z])\d+")


def _digits_down(name: str) -> str:
    m = _TRAILING.match(name)
    if m is None or " " in name or not m.group(1).strip():
        return name
    return m.group(1) + m.group(2).translate(_SUBSCRIPT) + m.group(3)


def _rounded_boxes(xy: np.ndarray, hw: float, hh: float, clearance: float) -> np.ndarray:
    """The ``2hw`` × ``2hh`` boxes centred at ``xy`` with their clearance about them."""
    return shapely.buffer(shapely.box(xy[:, 0] - hw, xy[:, 1] - hh, xy[:, 0] + hw,
                                      xy[:, 1] + hh), clearance, quad_segs=16)


def _first_clear(costs: np.ndarray) -> int:
    """The first spot whose overlap is nil, else the first of the least overlap."""
    clear = np.flatnonzero(costs <= 1e-9)
    return int(clear[0]) if len(clear) else int(np.argmin(costs))
