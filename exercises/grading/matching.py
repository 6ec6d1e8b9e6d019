"""Labels paired with the points they name on a drawing, as a reader pairs them: by all
the labels together, so crowded points are told apart."""

from __future__ import annotations

import math
from collections.abc import Callable

from .drawing import Drawing

__all__ = ["match", "REACH"]

REACH = 8.0
"""Paper (mm) a label may stand from the point it names."""

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
