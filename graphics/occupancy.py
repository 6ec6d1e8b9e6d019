"""What a page has drawn on it, as a weighted raster, so that a label's spot is priced by
array look-ups instead of one polygon intersection per candidate.

Each obstacle adds its weight to the cells whose centres it covers: an even-odd scan of
its rings in numpy, done for all the obstacles that arrived since the last look. The ink
under a box is then the weighted area of the cells it covers, read from a summed-area
table of the few centimetres round the label being placed. One cell is a quarter
millimetre: the obstacles already carry 0.3 mm or more of clearance about their ink, so
a cell's error never lets a label onto a line.
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry.base import BaseGeometry

__all__ = ["Occupancy"]

CELL = 0.25
"""Side of a cell (mm)."""

PARTS = 1000
"""Parts a weight is kept in: a cell holds whole thousandths."""

_GROW = 40.0
"""How far (mm) the raster grows past whatever first falls outside it."""

_MOST = 700.0
"""The longest side (mm) the raster grows to: some 8 million cells, 60 MB."""


class Occupancy:
    """A raster of weights over the plane, grown as obstacles arrive.

    Weights are kept as whole thousandths, so the summed-area tables are exact integers
    (and summed in a third of the time of floats); obstacles are painted together when
    the ink is next asked for.

    >>> from shapely.geometry import box
    >>> occ = Occupancy()
    >>> occ.paint(box(0, 0, 10, 10), 2.0)
    >>> occ.ink(np.array([[5.0, 5.0], [20.0, 5.0]]), (1.0, 1.0), (2.0, 1.0))
    array([[ 8.,  0.],
           [16.,  0.]])
    """

    def __init__(self) -> None:
        self.grid = np.zeros((0, 0), dtype=np.int32)
        self.x0 = self.y0 = 0.0
        self._waiting: list[tuple[BaseGeometry, int]] = []

    def paint(self, geom: BaseGeometry, weight: float = 1.0) -> None:
        """Add ``weight`` (to a thousandth) to every cell whose centre lies inside ``geom``
        (a polygon or a collection of them; its holes stay clear)."""
        parts = round(weight * PARTS)
        if parts:
            self._waiting.append((geom, parts))

    def _paint_waiting(self) -> None:
        """Paint every waiting obstacle in one even-odd scan: each edge meets the rows whose
        centre lines it crosses (half-open in y, so a vertex on a line counts once); sorted
        by obstacle, row and x, the crossings pair into spans."""
        if not self._waiting:
            return
        geoms, parts = zip(*self._waiting)
        self._waiting = []
        polys, owner = shapely.get_parts(np.asarray(geoms, dtype=object), return_index=True)
        rings, of_poly = shapely.get_rings(polys, return_index=True)
        pts, ring = shapely.get_coordinates(rings, return_index=True)
        if len(pts) < 3:
            return
        for bounds in shapely.bounds(np.asarray(geoms, dtype=object)).tolist():
            if not math.isnan(bounds[0]):       # an empty shape has no bounds
                self._cover(*bounds)            # in order of arrival: the first kept, if any
        edge = ring[:-1] == ring[1:]           # no edge joins one ring to the next
        a, b = pts[:-1][edge], pts[1:][edge]
        whose = owner[of_poly[ring[:-1][edge]]]
        rows, cols = self.grid.shape
        r0 = np.clip(self._row(np.minimum(a[:, 1], b[:, 1])), 0, rows)
        r1 = np.clip(self._row(np.maximum(a[:, 1], b[:, 1])), 0, rows)
        n = np.maximum(r1 - r0, 0)
        e = np.repeat(np.arange(len(a)), n)
        r = r0[e] + np.arange(len(e)) - np.repeat(np.cumsum(n) - n, n)
        t = (self.y0 + (r + 0.5) * CELL - a[e, 1]) / (b[e, 1] - a[e, 1])
        x = a[e, 0] + t * (b[e, 0] - a[e, 0])
        order = np.lexsort((x, r, whose[e]))
        x, r, e = x[order], r[order], e[order]
        c0 = np.maximum(self._column(x[0::2]), 0)
        c1 = np.minimum(self._column(x[1::2]), cols)
        keep = c1 > c0
        r, c0, c1 = r[0::2][keep], c0[keep], c1[keep]
        weight = np.asarray(parts, dtype=np.int32)[whose[e[0::2][keep]]]
        # The cells of every span, as one run of flat indices; spans of two obstacles may
        # share cells, so the weights are added at, not assigned.
        length = c1 - c0
        first = r * cols + c0 - (np.cumsum(length) - length)
        np.add.at(self.grid.reshape(-1), np.repeat(first, length) + np.arange(length.sum()),
                  np.repeat(weight, length))

    def ink(self, xy: np.ndarray, *sizes: tuple[float, float]) -> np.ndarray:
        """The weighted area (mm²) under boxes centred at ``xy``: a row for each of ``sizes``,
        a box's half width and half height.

        Only the window the boxes span is summed: a label looks a few centimetres round.
        """
        self._paint_waiting()
        out = np.zeros((len(sizes), len(xy)))
        if not self.grid.size or not len(xy):
            return out
        hw = np.array([s[0] for s in sizes])[:, None]
        hh = np.array([s[1] for s in sizes])[:, None]
        r0, r1 = self._row(xy[:, 1] - hh), self._row(xy[:, 1] + hh)
        c0, c1 = self._column(xy[:, 0] - hw), self._column(xy[:, 0] + hw)
        rows, cols = self.grid.shape
        wr0, wr1 = max(int(r0.min()), 0), min(int(r1.max()), rows)
        wc0, wc1 = max(int(c0.min()), 0), min(int(c1.max()), cols)
        if wr1 <= wr0 or wc1 <= wc0:
            return out
        table = np.zeros((wr1 - wr0 + 1, wc1 - wc0 + 1), dtype=np.int64)
        np.cumsum(self.grid[wr0:wr1, wc0:wc1], axis=0, out=table[1:, 1:])
        np.cumsum(table[1:, 1:], axis=1, out=table[1:, 1:])
        r0, r1 = (np.minimum(np.maximum(r - wr0, 0), wr1 - wr0) for r in (r0, r1))
        c0, c1 = (np.minimum(np.maximum(c - wc0, 0), wc1 - wc0) for c in (c0, c1))
        parts = table[r1, c1] - table[r0, c1] - table[r1, c0] + table[r0, c0]
        return parts * (CELL * CELL) / PARTS

    def _row(self, y):
        """Index of the first row whose centre is at or past ``y``."""
        return np.ceil((np.asarray(y) - self.y0) / CELL - 0.5).astype(int)

    def _column(self, x):
        """Index of the first column whose centre is at or past ``x``."""
        return np.ceil((np.asarray(x) - self.x0) / CELL - 0.5).astype(int)

    def _cover(self, x0: float, y0: float, x1: float, y1: float) -> None:
        """Grow the raster until it holds the box given, with room to spare, but never past
        :data:`_MOST` a side (a point far off the page, an edge arrow's target, is no
        obstacle worth a gigabyte); its cells stay on one lattice (multiples of
        :data:`CELL`), so the old grid drops into the new."""
        rows, cols = self.grid.shape
        have_x = (self.x0, self.x0 + cols * CELL) if self.grid.size else None
        have_y = (self.y0, self.y0 + rows * CELL) if self.grid.size else None
        if have_x and x0 >= have_x[0] and x1 <= have_x[1] and y0 >= have_y[0] \
                and y1 <= have_y[1]:
            return
        nx0, nx1 = _span(x0, x1, have_x)
        ny0, ny1 = _span(y0, y1, have_y)
        if have_x and (nx0, nx1, ny0, ny1) == (*have_x, *have_y):
            return                      # at its most: what lies beyond is not kept
        grid = np.zeros((round((ny1 - ny0) / CELL), round((nx1 - nx0) / CELL)), dtype=np.int32)
        if self.grid.size:
            dr, dc = round((self.y0 - ny0) / CELL), round((self.x0 - nx0) / CELL)
            grid[dr:dr + rows, dc:dc + cols] = self.grid
        self.grid, self.x0, self.y0 = grid, nx0, ny0


def _span(lo: float, hi: float, have: tuple[float, float] | None) -> tuple[float, float]:
    """The extent along one axis that holds ``lo``–``hi`` and what the raster ``have``s,
    :data:`_GROW` to spare, on the lattice, at most :data:`_MOST` long (the part the raster
    has, or else the start of what is asked, kept)."""
    a, b = lo - _GROW, hi + _GROW
    if have is not None:
        # Rounded out to whole cells, a raster may already stand a cell past _MOST: it is
        # never cut down, or it would not drop into the new one.
        most = max(_MOST, have[1] - have[0])
        a, b = min(a, have[0]), max(b, have[1])
        if b - a > most:
            a = max(a, have[1] - most)
            b = min(b, a + most)
    elif b - a > _MOST:
        b = a + _MOST
    return CELL * math.floor(a / CELL), CELL * math.ceil(b / CELL)
