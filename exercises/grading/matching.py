"""Labels paired with the points they name on a drawing, as a reader pairs them: by all
the labels together, so crowded points are told apart."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from .drawing import Drawing

__all__ = ["match", "Frame", "rounded", "REACH", "LEAST_CONDITIONING"]

REACH = 8.0
"""Paper (mm) a label may stand from the point it names."""

LEAST_CONDITIONING = 0.05
"""The least conditioning slack is given for: an item no drawing can place better than this
is graded at twenty pens."""

Vec = tuple[float, float]


def match(drawing: Drawing, read: Callable[[str], object | None],
          unmatched: list[str] | None = None) -> dict[object, Vec]:
    """Each label's point, the label read by ``read`` (None for a label that names no
    point): the line ends and dots within :data:`REACH` of its letters, each point taken
    once by each kind of thing (a key's first part), in the pairing whose distances add to
    the least (nearest pairs first, then any two labels' points swapped while that shortens
    the sum). The labels left with no point are added to ``unmatched``."""
    points = drawing.ends() + [c for c, _ in drawing.circles]
    unique: list[Vec] = []
    for p in points:
        if not any(math.dist(p, q) < 1e-6 for q in unique):
            unique.append(p)
    labels = [(key, label) for label in drawing.labels
              if (key := read(label.text)) is not None]
    near = {i: {j: d for j, p in enumerate(unique) if (d := _to_letters(p, label)) <= REACH}
            for i, (_, label) in enumerate(labels)}
    pairs = sorted((d, i, j) for i, js in near.items() for j, d in js.items())
    taken: dict[int, int] = {}
    for _, i, j in pairs:
        if i not in taken and (_kind(labels[i][0]), j) not in {
                (_kind(labels[m][0]), n) for m, n in taken.items()}:
            taken[i] = j
    improved = True
    while improved:
        improved = False
        for i in list(taken):
            for k in list(taken):
                a, b = taken[i], taken[k]
                if i < k and _kind(labels[i][0]) == _kind(labels[k][0]) and \
                        b in near[i] and a in near[k] and \
                        near[i][b] + near[k][a] < near[i][a] + near[k][b] - 1e-9:
                    taken[i], taken[k] = b, a
                    improved = True
    out: dict[object, Vec] = {}
    for i, j in taken.items():
        out.setdefault(labels[i][0], unique[j])
    if unmatched is not None:               # a label by no point it could name
        unmatched += [label.text for i, (_, label) in enumerate(labels) if i not in taken]
    return out


def _kind(key) -> object:
    """What a label names a point of: a key's first part (one point may be both a pin and
    the instant centre at it, but not two tips of one polygon)."""
    return key[0] if isinstance(key, tuple) else None


def _to_letters(p: Vec, label) -> float:
    """How far point ``p`` stands from a label's letters: a box from its anchor (the
    baseline's start) about as wide as its letters and as tall as a capital."""
    x0, x1 = label.at[0], label.at[0] + 2.0 * len(label.text)
    y0, y1 = label.at[1] - 3.5, label.at[1]
    dx = max(x0 - p[0], 0.0, p[0] - x1)
    dy = max(y0 - p[1], 0.0, p[1] - y1)
    return math.hypot(dx, dy)


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
