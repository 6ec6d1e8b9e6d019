"""Place labels where they touch neither each other nor the drawing (shapely boxes).

Each label tries a ring of candidate positions around its anchor, preferred
direction first, and takes the first that is clear; if none is, the one with the
least overlap. Placed labels become obstacles for the next.
"""

from __future__ import annotations

import math

from shapely.geometry import LineString, box
from shapely.geometry.base import BaseGeometry
from shapely.strtree import STRtree

from .figure import Figure, Text

__all__ = ["LabelPlacer"]


class LabelPlacer:
    """Collects obstacles on a page and places labels clear of them."""

    def __init__(self, fig: Figure):
        self.fig = fig
        self.obstacles: list[BaseGeometry] = []
        self._tree: STRtree | None = None
        self.clearance = 0.8
        # A page that is fitted to its content afterwards has no edge to avoid.
        self.page = box(1.0, 1.0, fig.width - 1.0, fig.height - 1.0) if fig.width else None

    def block(self, geom: BaseGeometry) -> None:
        """Mark an area (a link, a symbol, a placed label) as taken."""
        self.obstacles.append(geom)
        self._tree = None

    def block_segment(self, p: tuple[float, float], q: tuple[float, float], width: float = 0.8) -> None:
        """Mark a drawn segment (with a little clearance) as taken."""
        self.block(LineString([p, q]).buffer(width / 2 + 0.3, cap_style="flat"))

    def overlap(self, geom: BaseGeometry) -> float:
        """Area of ``geom`` covered by obstacles or off the page."""
        if self._tree is None:
            self._tree = STRtree(self.obstacles) if self.obstacles else None
        area = 0.0 if self.page is None else geom.area - geom.intersection(self.page).area
        if self._tree is not None:
            for i in self._tree.query(geom):
                area += geom.intersection(self.obstacles[int(i)]).area
        return area

    def place(self, text: str, anchor: tuple[float, float] | list[tuple[float, float]], *,
              prefer: float | tuple[float, ...] = math.pi / 4, spread: float = math.pi,
              gap: float = 2.6, size: float = 3.5, italic: bool = True,
              rings: tuple[float, ...] = (1.0, 1.6, 2.3)) -> Text:
        """Put ``text`` near ``anchor`` (or the first of several anchors that has room).

        Directions are tried from each ``prefer`` angle (paper, rad) outwards, up to
        ``spread`` either side.
        """
        prefers = prefer if isinstance(prefer, tuple) else (prefer,)
        turns = [(k + 1) // 2 * (1 if k % 2 else -1) * math.pi / 8 for k in range(16)]
        angles = [p + t for t in turns if abs(t) <= spread + 1e-9 for p in prefers]
        anchors = anchor if isinstance(anchor, list) else [anchor]
        probe = Text((0.0, 0.0), text, size, "middle", italic)
        x0, y0, x1, y1 = probe.box()
        hw, hh = (x1 - x0) / 2, (y1 - y0) / 2
        best: tuple[float, int, Text] | None = None
        order = 0
        for ring in rings:
            for base in anchors:
                for a in angles:
                    ux, uy = math.cos(a), -math.sin(a)
                    # Push the box out until its edge, not its centre, is ``gap`` away.
                    reach = gap * ring + min(hw / max(abs(ux), 1e-9), hh / max(abs(uy), 1e-9))
                    t = Text((base[0] + reach * ux, base[1] + reach * uy), text, size,
                             "middle", italic)
                    shape = box(*t.box())
                    cost = self.overlap(shape.buffer(self.clearance))
                    if cost <= 1e-9:
                        return self._commit(t, shape)
                    if best is None or (cost, order) < best[:2]:
                        best = (cost, order, t)
                    order += 1
        t = best[2]
        return self._commit(t, box(*t.box()))

    def _commit(self, t: Text, shape: BaseGeometry) -> Text:
        self.block(shape.buffer(0.4))
        self.fig.add(t)
        return t
