"""Whose name a label reads as: the distance from a label's box to what a page names.

A reader takes a name for the point or vector marked nearest it, so the placer
(:class:`~.labels.LabelPlacer`) holds a label nearer what it names than any other
named thing of its kind. These are the shapes a label may name and the exact
distances from boxes to them, for all of a label's candidate spots at once.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["Shape", "Owned", "as_shape", "same_thing", "shape_ends", "box_distance", "name_at"]

Shape = tuple[tuple[float, float], ...]
"""A thing a label names, by its points: one for a point, tail and tip for a vector."""

Owned = tuple[Shape, float, float, float, float, float]
"""What a label names, and its name's box within the label: the box centre's offset from
the label's, along x and y, its half width and half height, and how much farther right
it stands when the label's other parts are set before it (0: they never are)."""


def as_shape(own) -> Shape | None:
    """A point ``(x, y)`` or a shape ``((x, y), …)`` as a shape."""
    if own is None:
        return None
    return (tuple(own),) if isinstance(own[0], (int, float)) else tuple(tuple(p) for p in own)


def same_thing(own: Shape, other: Shape) -> bool:
    """Whether ``other`` is no rival of ``own``: a point within half a millimetre of it, or
    a vector whose shaft holds all of its (one and the same arrow, or V_A₄ within V_B₄ from
    one pole: beside the shorter, a label is as near the longer)."""
    if len(own) == 1:
        return math.dist(own[0], other[0]) <= 0.5
    (ax, ay), (bx, by) = other
    n2 = (bx - ax) ** 2 + (by - ay) ** 2
    for px, py in own:
        t = 0.0 if n2 == 0.0 else min(max(((px - ax) * (bx - ax) + (py - ay) * (by - ay)) / n2,
                                          0.0), 1.0)
        if math.dist((px, py), (ax + t * (bx - ax), ay + t * (by - ay))) > 0.5:
            return False
    return True


def shape_ends(shapes: list[Shape]) -> np.ndarray:
    """Each shape as a segment, tail and tip, a row each (a point is a segment of no
    length)."""
    out = np.empty((len(shapes), 2, 2))
    for k, shape in enumerate(shapes):
        out[k] = shape[0], shape[-1]
    return out


def box_distance(centres: np.ndarray, hw: float, hh: float, ends: np.ndarray) -> np.ndarray:
    """Exact distance from each box (centre, half sizes) to each segment (:func:`shape_ends`): a
    row per box, a column per segment.

    Nil where the segment meets the box (their bounding boxes overlap and the box's
    corners are not all on one side of the segment's line); else the nearest of an end to
    the box and a corner to the segment, as for any two convex shapes apart.
    """
    cx, cy = centres[:, 0, None], centres[:, 1, None]
    ax, ay, bx, by = ends[None, :, 0, 0], ends[None, :, 0, 1], ends[None, :, 1, 0], \
        ends[None, :, 1, 1]

    def to_box(px, py):
        return np.hypot(np.maximum(np.abs(px - cx) - hw, 0.0),
                        np.maximum(np.abs(py - cy) - hh, 0.0))

    near = to_box(ax, ay)
    dx, dy = bx - ax, by - ay
    n2 = dx * dx + dy * dy
    if not n2.any():                              # points only
        return near
    near = np.minimum(near, to_box(bx, by))
    n2 = np.maximum(n2, 1e-300)
    for px, py in ((cx - hw, cy - hh), (cx - hw, cy + hh), (cx + hw, cy - hh),
                   (cx + hw, cy + hh)):
        t = np.clip(((px - ax) * dx + (py - ay) * dy) / n2, 0.0, 1.0)
        near = np.minimum(near, np.hypot(ax + t * dx - px, ay + t * dy - py))
    meets = (np.minimum(ax, bx) <= cx + hw) & (np.maximum(ax, bx) >= cx - hw) & \
        (np.minimum(ay, by) <= cy + hh) & (np.maximum(ay, by) >= cy - hh) & \
        (np.abs(dx * (cy - ay) - dy * (cx - ax)) <= hw * np.abs(dy) + hh * np.abs(dx))
    return np.where(meets, 0.0, near)


def name_at(xy: np.ndarray, own: Owned) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """For labels centred at ``xy``: where the name's box stands, how far it is from what
    it names, and whether it is set after the label's other parts, the nearer of its two
    places (:data:`Owned`)."""
    shape, dx, dy, hw, hh, shift = own
    ends = shape_ends([shape])
    centre = xy + (dx, dy)
    mine = box_distance(centre, hw, hh, ends)[:, 0]
    after = np.zeros(len(xy), dtype=bool)
    if shift:
        moved = centre + (shift, 0.0)
        theirs = box_distance(moved, hw, hh, ends)[:, 0]
        after = theirs < mine - 1e-6
        centre = np.where(after[:, None], moved, centre)
        mine = np.where(after, theirs, mine)
    return centre, mine, after
