"""The points a label may name on a drawing, each with what it is.

A reader takes a label to name a point the student marked: a dot, an arrow's tip, where
strokes meet, a slider block's middle. A stroke that just ends (a construction line run on
past its point) is the last thing a label names. The corners of an arrowhead, its shaft's
end inside it, the far ends of its V, and a block's corners are parts of a mark, never
points a label names.

How each :class:`Kind` is told, sizes in paper mm:

- **dot**: a circle; a closed curved stroke (a dot LibreOffice or GeoGebra draws in
  Béziers or arcs) at its middle; a round closed polygon of six corners or more, no wider
  than a block, that no shaft runs into.
- **tip**: an arrowhead's apex. A closed polygon within :data:`HEAD` that a longer stroke
  (its shaft) runs into, the apex on the shaft's line and ahead of its other corners; a
  triangle within :data:`_ALONE` with one clearly sharpest corner, alone; a barbed head
  (a dart) within :data:`_ALONE` by its shape, its shaft, if any, shorter than it (a
  short arrow's), ending inside it; two short strokes
  (a V's wings) meeting where a shaft ends and swept back along it; a stroke's end that
  carries a marker.
- **block**: the middle of a closed quadrilateral of square corners, no side longer than
  :data:`BLOCK` (a slider block), one stroke or four.
- **junction**: where strokes' ends meet within :data:`JOIN`: a polyline's or a
  polygon's corner; a stroke's end lying on another stroke.
- **end**: a stroke's end touching nothing.

:data:`PENALTY` is what :func:`.matching.match` adds to a label's distance from a point of
each kind: an end loses to any other mark up to that much farther.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum

from . import arrowheads
from .arrowheads import JOIN, extent, turn
from .drawing import Drawing, Outline

__all__ = ["Kind", "Mark", "marks", "touching", "PENALTY", "JOIN", "HEAD", "BLOCK"]

Vec = tuple[float, float]

HEAD = 12.0
"""The largest an arrowhead or a V's wing is (mm): a drafted arrowhead is 3–5 mm long,
GeoGebra's 17 px (4.5 mm) and, for its thickest vectors, 39 px (10.3 mm)."""

_ALONE = 6.0
"""The largest a polygon with no shaft is told an arrowhead by its shape alone (mm): a
polygon of a drawing is larger."""

OVERSHOOT = 10.0
"""The farthest (mm) a line drawn through a point runs on past it: its end there names
nothing. A centimetre, to within :data:`JOIN` (a line drawn a centimetre past is read
back a few micrometres longer or shorter)."""

BLOCK = 20.0
"""The longest side of a slider block (mm)."""

_SQUARE = math.radians(12.0)
"""How far from a right angle a block's corner may be."""

_WING = (math.radians(5.0), math.radians(60.0))
"""How far a V's wing sweeps back off its shaft's line."""

_FEW = 12
"""The most corners a closed polygon smaller than a block may have and be tried as an
arrowhead or a block; one of more is a dot if round, else a polygon."""

_CROWD = 12
"""The most strokes a place may join and be an arrow's V or a block's corner: more meet
only where a drawing heaps strokes."""


class Kind(StrEnum):
    """What a point a label may name is."""

    DOT = "dot"
    TIP = "tip"
    BLOCK = "block"
    JUNCTION = "junction"
    END = "end"


PENALTY = {Kind.DOT: 0.0, Kind.TIP: 0.0, Kind.BLOCK: 0.0, Kind.JUNCTION: 0.0, Kind.END: 2.0}
"""What pairing a label with a point of each kind costs beyond its distance (mm): a stroke's
bare end loses to a dot, a tip, a block or a junction up to 2 mm farther, more than a
construction line's end stands from the point it was drawn through (1.6 mm in a class's
drawings)."""

_PREFERRED = tuple(Kind)
"""Of marks at one place, the one kept: the first in this order."""


@dataclass(frozen=True, slots=True)
class Mark:
    """A point a label may name, what it is, and how many labels of one kind may name it:
    a tip one for each stroke ending there (two vectors drawn to one point are two tips),
    any other mark one (before marks at one place are one, the strokes each ends)."""

    at: Vec
    kind: Kind
    takes: int = 1


def marks(drawing: Drawing) -> list[Mark]:
    """The points a label may name on ``drawing``, each once (marks within a micrometre
    are one, of the kind :data:`_PREFERRED` puts first).

    Examples
    --------
    A shaft with a filled arrowhead at (10, 0) and a stray line ending 1.6 mm away:

    >>> from tarsim.exercises.grading.drawing import Outline
    >>> d = Drawing(outlines=[Outline(((0.0, 0.0), (7.0, 0.0))),
    ...                       Outline(((10.0, 0.0), (7.0, 1.0), (7.0, -1.0)), closed=True),
    ...                       Outline(((11.6, 0.0), (11.6, 20.0)))])
    >>> [(m.at, str(m.kind)) for m in marks(d)]
    [((10.0, 0.0), 'tip'), ((0.0, 0.0), 'end'), ((11.6, 0.0), 'end'), ((11.6, 20.0), 'end')]
    """
    out = [Mark(c, Kind.DOT, 0) for c, _ in drawing.circles]
    web = _Web()
    heads = []
    # A drawing made of segments alone (built by hand, not read) is one stroke a segment.
    strokes = drawing.outlines or [Outline((a, b)) for a, b in drawing.segments]
    for o in strokes:
        corners, closed = _closed(o)
        if not closed:
            web.stroke(corners, False, o.marked)
            continue
        if o.curved:
            out.append(Mark(_middle(corners), Kind.DOT, 0))
            continue
        xs, ys = [p[0] for p in corners], [p[1] for p in corners]
        if math.hypot(max(xs) - min(xs), max(ys) - min(ys)) > 2.0 * BLOCK or \
                len(corners) > _FEW and not _round(corners):
            web.stroke(corners, True)        # a polygon of the drawing: its corners meet
            continue
        if len(corners) > _FEW:              # a small round polygon of many corners
            out.append(Mark(_middle(corners), Kind.DOT, 0))
            continue
        poly = _simplified(corners)
        sides = [math.dist(a, b) for a, b in zip(poly, poly[1:] + poly[:1])]
        if len(poly) == 4 and max(sides) <= BLOCK and _square(poly):
            out.append(Mark(_middle(poly), Kind.BLOCK, 0))
        elif extent(poly) <= HEAD:
            heads.append(poly)
        else:
            web.stroke(poly, True)
    for poly in heads:
        tip = web.head(poly)
        if tip is not None:
            out.append(tip)
        elif len(poly) >= 6 and _round(poly):
            out.append(Mark(_middle(poly), Kind.DOT, 0))
        else:
            web.stroke(poly, True)
    out += web.marks()
    return _distinct(_past_points(out, web.ends))


def _past_points(found: list[Mark], ends: dict[Vec, Vec]) -> list[Mark]:
    """``found`` without the ends of lines drawn through a tip, dot, block or junction and on
    past it (:data:`OVERSHOOT` at most), as a draughtsman draws a line through a point: the
    point is what the line names, not where the pen lifted."""
    strong = [m.at for m in found if m.kind is not Kind.END]
    if not strong or not ends:
        return found
    import numpy as np

    xy = np.array(strong, dtype=float)

    def past(m: Mark) -> bool:
        if m.kind is not Kind.END or m.at not in ends:
            return False
        near = xy[np.hypot(xy[:, 0] - m.at[0], xy[:, 1] - m.at[1]) <= OVERSHOOT + JOIN]
        return any(_on(tuple(p), m.at, ends[m.at]) for p in near)
    return [m for m in found if not past(m)]


def touching(drawing: Drawing, points: list[Vec]) -> list[bool]:
    """Whether each of ``points`` lies on one of ``drawing``'s segments (within
    :data:`JOIN`) away from that segment's ends: a stroke's end on another stroke is where
    the two meet."""
    import numpy as np

    if not points or not drawing.segments:
        return [False] * len(points)
    if len(points) * len(drawing.segments) <= 4096:         # too few for numpy to pay
        return [any(_on(p, a, b) for a, b in drawing.segments) for p in points]
    seg = np.array(drawing.segments, dtype=float)          # (n, 2, 2)
    a, b = seg[:, 0], seg[:, 1]
    d = b - a
    length2 = np.maximum((d * d).sum(axis=1), 1e-300)
    out = []
    chunk = max(1, 2_000_000 // len(seg))                   # points at a time
    xy = np.array(points, dtype=float)
    for k in range(0, len(xy), chunk):
        p = xy[k:k + chunk, None, :]                         # (m, 1, 2)
        t = np.clip(((p - a) * d).sum(axis=2) / length2, 0.0, 1.0)
        foot = a + t[..., None] * d - p
        off = np.hypot(foot[..., 0], foot[..., 1])
        away = np.minimum(np.hypot(*(p - a).transpose(2, 0, 1)),
                          np.hypot(*(p - b).transpose(2, 0, 1))) > JOIN
        out += np.any((off <= JOIN) & away, axis=1).tolist()
    return out


def _on(p: Vec, a: Vec, b: Vec) -> bool:
    """Whether ``p`` lies on the segment a–b (within :data:`JOIN`), away from its ends."""
    if math.dist(p, a) <= JOIN or math.dist(p, b) <= JOIN:
        return False
    d = (b[0] - a[0], b[1] - a[1])
    t = max(0.0, min(1.0, ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1])
                     / max(d[0] ** 2 + d[1] ** 2, 1e-300)))
    return math.dist(p, (a[0] + t * d[0], a[1] + t * d[1])) <= JOIN


# ----- shapes ----------------------------------------------------------------------------------
def _closed(o: Outline) -> tuple[list[Vec], bool]:
    """``o``'s corners, and whether it closes (a stroke ending where it began, as a CAD
    program closes a polyline, does)."""
    corners = list(o.corners)
    if not o.closed and len(corners) > 3 and math.dist(corners[0], corners[-1]) <= JOIN:
        return corners[:-1], True
    return corners, o.closed


def _simplified(corners: list[Vec]) -> list[Vec]:
    """A closed polygon's corners, those where it does not turn (by under 2°) left out."""
    out = list(corners)
    changed = True
    while changed and len(out) > 3:
        changed = False
        for k in range(len(out)):
            a, b, c = out[k - 1], out[k], out[(k + 1) % len(out)]
            if abs(turn(a, b, c)) < math.radians(2.0) or math.dist(a, b) < 1e-6:
                del out[k]
                changed = True
                break
    return out


def _square(poly: list[Vec]) -> bool:
    """Whether a quadrilateral's corners are all right angles, within :data:`_SQUARE`."""
    return all(abs(abs(turn(poly[k - 1], poly[k], poly[(k + 1) % 4])) - math.pi / 2)
               <= _SQUARE for k in range(4))


def _round(points: list[Vec]) -> bool:
    """Whether ``points`` lie round their middle, none half as far again as another (a
    circle drawn as a polygon)."""
    c = _middle(points)
    r = [math.dist(c, p) for p in points]
    return min(r) > 0.0 and max(r) <= 1.5 * min(r)


def _middle(points: list[Vec]) -> Vec:
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    return ((min(xs) + max(xs)) / 2.0, (min(ys) + max(ys)) / 2.0)


def _distinct(found: list[Mark]) -> list[Mark]:
    """``found``, marks within a micrometre of one another one mark: the preferred kind,
    where the first of them stands (found on a grid of micrometre cells). A tip there
    takes a label for each stroke ending at it; any other mark, one."""
    same = 1e-6
    cells: dict[tuple[int, int], list[int]] = {}
    groups: list[list[Mark]] = []
    for m in found:
        kx, ky = math.floor(m.at[0] / same), math.floor(m.at[1] / same)
        twin = next((k for dx in (-1, 0, 1) for dy in (-1, 0, 1)
                     for k in cells.get((kx + dx, ky + dy), ())
                     if math.dist(groups[k][0].at, m.at) < same), None)
        if twin is None:
            cells.setdefault((kx, ky), []).append(len(groups))
            groups.append([m])
        else:
            groups[twin].append(m)
    out = []
    for group in groups:
        kind = min((m.kind for m in group), key=_PREFERRED.index)
        tip = any(m.kind is Kind.TIP for m in group)
        out.append(Mark(group[0].at, kind, max(1, sum(m.takes for m in group)) if tip else 1))
    return out


# ----- strokes and where they meet -------------------------------------------------------------
@dataclass
class _Place:
    """Where strokes' ends or corners meet: the first point there, and the strokes
    leaving it (each its far end and length)."""

    at: Vec
    leaving: list[tuple[Vec, float, int]]
    marked: bool = False
    part: bool = False
    tip: bool = False
    wings: int = 0


class _Web:
    """The strokes that are not shapes of their own, met at their places."""

    def __init__(self):
        self.places: list[_Place] = []
        self.cells: dict[tuple[int, int], list[int]] = {}
        self.near: dict[tuple[int, int], list[int]] = {}          # 2 mm cells, for heads
        self.ends: dict[Vec, Vec] = {}         # a lone end, and where its stroke runs to

    def place(self, p: Vec) -> int:
        """The place at ``p``, made if no place stands within :data:`JOIN`."""
        kx, ky = math.floor(p[0] / JOIN), math.floor(p[1] / JOIN)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for k in self.cells.get((kx + dx, ky + dy), ()):
                    if math.dist(self.places[k].at, p) <= JOIN:
                        return k
        self.cells.setdefault((kx, ky), []).append(len(self.places))
        self.near.setdefault((math.floor(p[0] / 2.0), math.floor(p[1] / 2.0)), []).append(
            len(self.places))
        self.places.append(_Place(p, []))
        return len(self.places) - 1

    def stroke(self, corners: list[Vec], closed: bool,
               marked: tuple[bool, bool] = (False, False)) -> None:
        """Add a stroke through ``corners``, closing back to its start if ``closed``."""
        ring = corners + corners[:1] if closed else corners
        ids = [self.place(p) for p in ring]
        for (i, a), (j, b) in zip(zip(ids, ring), zip(ids[1:], ring[1:])):
            if i != j:
                length = math.dist(a, b)
                self.places[i].leaving.append((self.places[j].at, length, j))
                self.places[j].leaving.append((self.places[i].at, length, i))
        if ids and not closed:
            self.places[ids[0]].marked |= marked[0]
            self.places[ids[-1]].marked |= marked[1]

    def head(self, poly: list[Vec]) -> Mark | None:
        """The tip at the apex of the arrowhead ``poly`` is, if it is one: the corner ahead
        along the shaft that runs into it (a stroke longer than the head, ending in or on
        it), on the shaft's line; failing a shaft, a triangle's one clearly sharpest
        corner, or a dart's apex (:func:`.arrowheads.barbed`). The shaft's end is then part
        of the arrow; where it reaches the apex, the tip takes a label for each stroke
        ending there with it."""
        size = extent(poly)
        xs, ys = [p[0] for p in poly], [p[1] for p in poly]
        inside = [self.places[k] for cx in range(math.floor((min(xs) - JOIN) / 2.0),
                                                 math.floor((max(xs) + JOIN) / 2.0) + 1)
                  for cy in range(math.floor((min(ys) - JOIN) / 2.0),
                                  math.floor((max(ys) + JOIN) / 2.0) + 1)
                  for k in self.near.get((cx, cy), ())
                  if arrowheads.within(self.places[k].at, poly)]
        tip = None
        for q in inside:
            for far, length, _ in q.leaving:
                apex = arrowheads.apex(poly, far, q.at, size) if length >= size else None
                if apex is not None:
                    q.part = True
                    tip = Mark(apex, Kind.TIP, len(q.leaving)
                               if math.dist(q.at, apex) <= JOIN else 1)
                    break
            if tip is not None:
                break
        if tip is None and size <= _ALONE:
            apex = arrowheads.sharpest(poly) if len(poly) == 3 else arrowheads.barbed(poly)
            tip = None if apex is None else Mark(apex, Kind.TIP)
        if tip is not None:
            # A shaft shorter than the head ends inside it, behind the apex.
            for q in inside:
                if len(q.leaving) == 1 and math.dist(q.at, tip.at) > JOIN:
                    q.part = True
        return tip

    def marks(self) -> list[Mark]:
        """The tips, blocks, junctions and ends where the strokes meet, their arrowheads'
        wings and blocks' corners left out."""
        out = []
        for place in self.places:
            _v_tip(place, self.places)
        out += self._blocks()
        for place in self.places:
            arriving = len(place.leaving) - place.wings
            if place.tip or place.marked:
                out.append(Mark(place.at, Kind.TIP, max(arriving, 1)))
            elif not place.part and place.leaving:
                out.append(Mark(place.at, Kind.JUNCTION if len(place.leaving) > 1
                                else Kind.END, len(place.leaving)))
                if len(place.leaving) == 1:
                    self.ends[place.at] = place.leaving[0][0]
        return out

    def _blocks(self) -> list[Mark]:
        """Slider blocks drawn as four strokes: places joined by short sides round a
        rectangle. Their corners are parts of them, unless another stroke meets there."""
        short = [{j for _, length, j in p.leaving if length <= BLOCK} for p in self.places]
        seen, out = set(), []
        for a, ends in enumerate(short):
            if not 2 <= len(ends) <= _CROWD:
                continue
            for b in ends:
                for d in ends:
                    if b >= d:
                        continue
                    for c in (short[b] & short[d]) - {a}:
                        corners = (a, b, c, d)
                        key = frozenset(corners)
                        poly = [self.places[k].at for k in corners]
                        if key in seen or not _square(poly):
                            continue
                        seen.add(key)
                        out.append(Mark(_middle(poly), Kind.BLOCK, 0))
                        for k in corners:
                            if len(self.places[k].leaving) == 2:
                                self.places[k].part = True
        return out


def _v_tip(place: _Place, places: list[_Place]) -> None:
    """Mark ``place`` a tip if two short strokes leave it swept back on either side of a
    longer one (an arrowhead drawn as a V), and the wings' far ends parts of it."""
    if not 3 <= len(place.leaving) <= _CROWD:
        return
    for far, length, _ in place.leaving:
        shaft = math.atan2(far[1] - place.at[1], far[0] - place.at[0])
        sides: dict[int, list[int]] = {1: [], -1: []}
        for wing_far, wing, k in place.leaving:
            if wing > HEAD or wing * 1.5 > length:
                continue
            off = math.remainder(math.atan2(wing_far[1] - place.at[1],
                                            wing_far[0] - place.at[0]) - shaft, math.tau)
            if _WING[0] <= abs(off) <= _WING[1]:
                sides[1 if off > 0 else -1].append(k)
        if sides[1] and sides[-1]:
            place.tip, place.wings = True, len(sides[1]) + len(sides[-1])
            for k in sides[1] + sides[-1]:
                if len(places[k].leaving) == 1:
                    places[k].part = True
            return
