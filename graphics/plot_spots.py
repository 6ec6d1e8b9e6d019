"""Where a plot's words may go: a label's candidate boxes priced against the curves, the
frame and the words already set, and the leader from a mark to a label set off its circle.

Plain geometry in paper millimetres on numpy arrays, for :mod:`.plot`'s marks and tags;
nothing here draws.
"""

from __future__ import annotations

import numpy as np

__all__ = ["MARK_R", "RINGS", "WAYS", "leaders", "through_marks", "crossed", "segments",
           "overlaps"]

Point = tuple[float, float]
Box = tuple[float, float, float, float]

MARK_R = 1.1
"""The radius of a mark's open circle, mm."""


def leaders(x: float, y: float, boxes: np.ndarray,
             ring: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The leader each of ``boxes`` would be drawn with, from the circle at (x, y) to the
    box's nearest point (a gap short of it): the starts and the ends, a row each; NaN for a
    box on the first ring, or one too near to need a leader."""
    ex = np.clip(x, boxes[:, 0], boxes[:, 2])
    ey = np.clip(y, boxes[:, 1], boxes[:, 3])
    d = np.hypot(ex - x, ey - y)
    led = (ring > 1.0) & (d > MARK_R + 0.3)
    ux, uy = (ex - x) / np.where(led, d, 1.0), (ey - y) / np.where(led, d, 1.0)
    start = np.stack([x + ux * MARK_R, y + uy * MARK_R], axis=1)
    end = np.stack([ex - ux * 0.3, ey - uy * 0.3], axis=1)
    start[~led] = end[~led] = np.nan
    return start, end


def through_marks(a: np.ndarray, b: np.ndarray, others: list[Point]) -> np.ndarray:
    """1 for each leader (from ``a`` to ``b``, a row each; NaN for none) that passes
    within a gap of the circle of any of ``others``, else 0."""
    if not others:
        return np.zeros(len(a))
    o = np.asarray(others, dtype=float)[None, :, :]
    d = (b - a)[:, None, :]
    n2 = np.maximum((d * d).sum(axis=2), 1e-12)
    t = np.clip(((o - a[:, None, :]) * d).sum(axis=2) / n2, 0.0, 1.0)
    near = np.hypot(*np.moveaxis(a[:, None, :] + t[..., None] * d - o, 2, 0))
    return (np.nan_to_num(near, nan=np.inf) < MARK_R + 0.3).any(axis=1).astype(float)


def crossed(a: np.ndarray, b: np.ndarray, segments) -> np.ndarray:
    """Whether each segment ab (a row each; NaN for none) crosses a curve's segment."""
    p, q, _ = segments
    if not len(p):
        return np.zeros(len(a))

    def side(o, u, v):          # the sign of (u − o) × (v − o), for every pair
        return np.sign((u[..., 0] - o[..., 0]) * (v[..., 1] - o[..., 1])
                       - (u[..., 1] - o[..., 1]) * (v[..., 0] - o[..., 0]))

    a, b = a[:, None, :], b[:, None, :]
    cross = (side(a, b, p[None]) * side(a, b, q[None]) < 0) \
        & (side(p[None], q[None], a) * side(p[None], q[None], b) < 0)
    return cross.any(axis=1).astype(float)


RINGS = (1.0, 1.8, 2.6, 3.6, 4.8, 6.2)
"""How far out a mark's label is tried, in steps of the circle's radius and a gap."""

WAYS = ((0.0, -1.0), (1.0, -0.8), (1.0, 0.8), (0.0, 1.0), (-1.0, -0.8), (-1.0, 0.8),
         (1.0, 0.0), (-1.0, 0.0))
"""The directions a mark's label is tried in, on each ring, first preferred first."""


def segments(runs: list[tuple[Point, ...]]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The curves' segments: their starts, their ends (a row each) and the run of each."""
    p = [r[:-1] for r in runs if len(r) > 1]
    q = [r[1:] for r in runs if len(r) > 1]
    if not p:
        return np.empty((0, 2)), np.empty((0, 2)), np.empty(0, dtype=int)
    which = np.repeat(np.arange(len(p)), [len(r) for r in p])
    return np.concatenate(p), np.concatenate(q), which


def overlaps(boxes: np.ndarray, taken: list[Box], segments, frame: Box) -> np.ndarray:
    """How badly each of ``boxes`` collides: 10 past the frame's edge, 5 for each placed box
    it meets, and 1 for each curve it crosses."""
    b0, b1, b2, b3 = boxes.T
    cost = 10.0 * ((b0 < frame[0]) | (b1 < frame[1]) | (b2 > frame[2]) | (b3 > frame[3]))
    if taken:
        t = np.asarray(taken)
        cost += 5.0 * ((b0[:, None] < t[:, 2]) & (t[:, 0] < b2[:, None])
                       & (b1[:, None] < t[:, 3]) & (t[:, 1] < b3[:, None])).sum(axis=1)
    p, q, which = segments
    # Only the segments whose bounds meet those of all the boxes can meet one.
    near = ~_apart(p, q, b0.min(), b1.min(), b2.max(), b3.max())
    if near.any():
        hits, of = _segments_hit(p[near], q[near], boxes), which[near]
        for run in np.unique(of):
            cost += hits[:, of == run].any(axis=1)
    return cost


def _apart(p: np.ndarray, q: np.ndarray, x0, y0, x1, y1) -> np.ndarray:
    """Whether each segment pq lies wholly to one side of the box x0 y0 x1 y1 (or of each
    box, their bounds given as columns)."""
    return ((np.maximum(p[:, 0], q[:, 0]) < x0) | (np.minimum(p[:, 0], q[:, 0]) > x1)
            | (np.maximum(p[:, 1], q[:, 1]) < y0) | (np.minimum(p[:, 1], q[:, 1]) > y1))


def _segments_hit(p: np.ndarray, q: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """Whether each segment pq meets each box (a row per box), by Liang–Barsky clipping."""
    lo = np.zeros((len(boxes), len(p)))
    hi = np.ones((len(boxes), len(p)))
    meets = ~_apart(p, q, *(boxes[:, k, None] for k in range(4)))
    for k in (0, 1):
        d = q[:, k] - p[:, k]
        flat = np.abs(d) < 1e-12           # along the other axis: inside its band, or not
        meets &= ~flat | ((boxes[:, k, None] <= p[:, k]) & (p[:, k] <= boxes[:, k + 2, None]))
        d = np.where(flat, 1.0, d)
        t0, t1 = (boxes[:, k, None] - p[:, k]) / d, (boxes[:, k + 2, None] - p[:, k]) / d
        lo = np.where(flat, lo, np.maximum(lo, np.minimum(t0, t1)))
        hi = np.where(flat, hi, np.minimum(hi, np.maximum(t0, t1)))
    return meets & (lo <= hi)
