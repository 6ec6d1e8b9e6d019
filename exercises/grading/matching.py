"""Labels paired with the points they name on a drawing, as a reader pairs them: by all
the labels together, so crowded points are told apart, and each to a point a student
marks (:mod:`.marks`) before a bare stroke's end."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from tarsim.constructions.errors import InputError
from .drawing import Drawing, advance
from .marks import PENALTY, Kind, Mark, marks, touching

__all__ = ["match", "Frame", "rounded", "REACH", "NEAREST", "MAX_NAMES", "LEAST_CONDITIONING"]

REACH = 8.0
"""Paper (mm) a label may stand from the point it names."""

NEAREST = 16
"""How many of the points nearest a label it may be paired with: more than stand within
:data:`REACH` of any label on a drawing a reader can read."""

MAX_NAMES = 500
"""The most labels naming a point a drawing may have."""

LEAST_CONDITIONING = 0.05
"""The least conditioning slack is given for: an item no drawing can place better than this
is graded at twenty pens."""

Vec = tuple[float, float]


def match(drawing: Drawing, read: Callable[[str], object | None],
          unmatched: list[str] | None = None,
          penalty: dict[Kind, float] | None = None) -> dict[object, Vec]:
    """Each label's point, the label read by ``read`` (None for a label that names no
    point): of the points a label may name (:func:`.marks.marks`: dots, arrows' tips,
    junctions, blocks' middles, strokes' ends) within :data:`REACH` of its letters (the
    :data:`NEAREST` nearest), each point taken by each kind of thing (a key's first part)
    once, or a tip once for each stroke ending there (:attr:`.marks.Mark.takes`), in the
    pairing whose costs add to the least (nearest pairs first, then any two
    labels' points swapped while that lowers the sum). A pair costs its distance and the
    point's :data:`.marks.PENALTY` (or ``penalty``'s, for a drawing whose points are drawn
    as one kind: a space diagram's pins as circles), so a bare stroke's end loses to a mark
    a little farther. The labels left with no point are added to ``unmatched``.

    Raises
    ------
    InputError
        If more than :data:`MAX_NAMES` labels name a point.
    """
    labels = [(key, label) for label in drawing.labels
              if (key := read(label.text)) is not None]
    if len(labels) > MAX_NAMES:
        raise InputError(f"{len(labels):,} labels name a point, more than a drawing has (at "
                         f"most {MAX_NAMES}); a page of polygons names some dozens",
                         file=drawing.source)
    found = marks(drawing) if labels else []
    kinds = [_kind(key) for key, _ in labels]
    near = _near([m.at for m in found], [label for _, label in labels])
    # A bare end a label could take may lie on another stroke: where the two meet.
    ends = sorted({j for js in near.values() for j in js if found[j].kind is Kind.END})
    for j, meets in zip(ends, touching(drawing, [found[j].at for j in ends])):
        if meets:
            found[j] = Mark(found[j].at, Kind.JUNCTION)
    penalty = penalty or PENALTY
    cost = {i: {j: d + penalty[found[j].kind] for j, d in js.items()} for i, js in near.items()}
    pairs = sorted((c, i, j) for i, js in cost.items() for j, c in js.items())
    taken: dict[int, int] = {}
    holders: dict[tuple[object, int], list[int]] = {}   # (kind, point): the labels on it
    for _, i, j in pairs:
        on = holders.setdefault((kinds[i], j), [])
        if i not in taken and len(on) < found[j].takes:
            taken[i] = j
            on.append(i)
    order = {i: n for n, i in enumerate(taken)}
    improved = True
    while improved:
        improved = False
        for i in list(taken):
            # Only a label holding one of i's points can be swapped with i: visit those, in
            # the order the labels were paired.
            mates = sorted({m for j in cost[i] for m in holders.get((kinds[i], j), ())
                            if m > i}, key=order.get)
            for k in mates:
                a, b = taken[i], taken[k]
                if a != b and b in cost[i] and a in cost[k] and \
                        cost[i][b] + cost[k][a] < cost[i][a] + cost[k][b] - 1e-9:
                    taken[i], taken[k] = b, a
                    holders[kinds[i], a][holders[kinds[i], a].index(i)] = k
                    holders[kinds[i], b][holders[kinds[i], b].index(k)] = i
                    improved = True
    _share(cost, taken, holders, kinds, found)
    out: dict[object, Vec] = {}
    for i, j in taken.items():
        out.setdefault(labels[i][0], found[j].at)
    if unmatched is not None:               # a label by no point it could name
        unmatched += [label.text for i, (_, label) in enumerate(labels) if i not in taken]
    return out


SHARE = 1.5
"""What a label pays (mm) to share a tip or a dot another label of its kind names: two
tips drawn as one (b ≡ b4 at a dead point, one stroke and two labels), or two centres at
one pin (I13 and I14 at O4 with the crank upright), are named so, where the label's own
nearest mark is that much farther."""


def _share(cost, taken: dict[int, int], holders, kinds, found: list[Mark]) -> None:
    """Move each label to a tip or dot already named, where sharing it costs less than the
    point it holds (or none): :data:`SHARE` more than its distance."""
    for i, js in cost.items():
        here = cost[i][taken[i]] if i in taken else math.inf
        best = min(((c + SHARE, j) for j, c in js.items() if j != taken.get(i)
                    and found[j].kind in (Kind.TIP, Kind.DOT)
                    and holders.get((kinds[i], j))), default=None)
        if best is not None and best[0] < here:
            if i in taken:
                holders[kinds[i], taken[i]].remove(i)
            taken[i] = best[1]
            holders[kinds[i], best[1]].append(i)


def _near(points: list[Vec], labels: list) -> dict[int, dict[int, float]]:
    """For each label, the :data:`NEAREST` points within :data:`REACH` of its letters, and
    how far each is."""
    import numpy as np

    if not points:
        return {i: {} for i in range(len(labels))}
    xy = np.array(points, dtype=float)
    by_x = np.argsort(xy[:, 0], kind="stable")
    xs = xy[by_x, 0]
    out = {}
    for i, label in enumerate(labels):
        x0, x1, y0, y1 = _letters(label)
        lo = int(np.searchsorted(xs, x0 - REACH, side="left"))
        hi = int(np.searchsorted(xs, x1 + REACH, side="right"))
        idx = by_x[lo:hi]
        p = xy[idx]
        d = np.hypot(np.maximum(np.maximum(x0 - p[:, 0], 0.0), p[:, 0] - x1),
                     np.maximum(np.maximum(y0 - p[:, 1], 0.0), p[:, 1] - y1))
        keep = np.flatnonzero(d <= REACH)
        if len(keep) > NEAREST:
            keep = keep[np.lexsort((idx[keep], d[keep]))[:NEAREST]]
        out[i] = {int(idx[k]): float(d[k]) for k in keep}
    return out


def _kind(key) -> object:
    """What a label names a point of: a key's first part (one point may be both a pin and
    the instant centre at it, but not two tips of one polygon)."""
    return key[0] if isinstance(key, tuple) else None


def _letters(label) -> tuple[float, float, float, float]:
    """A label's letters as a box (x0, x1, y0, y1): from its anchor (the baseline's start)
    about as wide as its letters and as tall as a capital (0.8 of its size, taken between
    1 and 10 mm: letters drawn smaller or larger still name the point by them)."""
    size = min(max(label.size, 1.0), 10.0)
    return (label.at[0], label.at[0] + advance(label.text) * size,
            label.at[1] - 0.8 * size, label.at[1])


@dataclass(frozen=True)
class Frame:
    """How a drawing sets the world on its paper: world ``origin`` at paper ``at``, turned
    by ``turn``, ``scale`` paper mm a world unit, of either ``hand`` (1: as drawn with y up,
    paper's y down; −1: mirrored)."""

    scale: float
    turn: float
    hand: float
    origin: Vec = (0.0, 0.0)
    at: Vec = (0.0, 0.0)

    @classmethod
    def fitted(cls, world: Vec, paper: Vec, hand: float, scale: float | None = None,
               origin: Vec = (0.0, 0.0), at: Vec = (0.0, 0.0)) -> Frame:
        """The frame that lays the world vector ``world`` along the paper vector ``paper``
        (at their length ratio unless ``scale`` is given), from ``origin`` to ``at``."""
        ex, ey = world[0], -hand * world[1]
        turn = math.atan2(paper[1], paper[0]) - math.atan2(ey, ex)
        return cls(scale or math.hypot(*paper) / math.hypot(*world), turn, hand, origin, at)

    def place(self, x: Vec) -> Vec:
        """Where the world point (or, from the origin, vector) ``x`` stands on paper."""
        v = ((x[0] - self.origin[0]) * self.scale, -self.hand * (x[1] - self.origin[1])
             * self.scale)
        c, s = math.cos(self.turn), math.sin(self.turn)
        return (self.at[0] + c * v[0] - s * v[1], self.at[1] + s * v[0] + c * v[1])


def rounded(p: Vec) -> list[float]:
    """A paper point as grade.json gives it, to a thousandth of a millimetre."""
    return [round(p[0], 3), round(p[1], 3)]
