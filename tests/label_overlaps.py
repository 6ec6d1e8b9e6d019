"""Count what a figure's labels cover, geometrically, from its primitives.

A label is a text's box or a step-number badge. Three counts, each a number of pairs
whose shared area is more than :data:`GRAZE` (mm²), so a label that only touches what it
names is not counted:

- ``label-label``: two labels over one another;
- ``label-arrowhead``: a label over an arrowhead (a small closed, filled polygon);
- ``label-line``: a label over a drawn line (any open path), counted once per label.

tests/test_label_overlaps.py holds every bundled figure to the counts recorded in
tests/data/label_overlaps.json: none may rise. ``python tests/label_overlaps.py``
prints the counts of every bundled figure as that file records them.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from shapely import STRtree
from shapely.geometry import LineString, Point, Polygon, box

from tarsim.graphics.figure import Circle, Figure, Path as Stroke, Text

GRAZE = 0.05
"""Shared area (mm²) above which a label covers something, not merely touches it."""

KINDS = ("label-label", "label-arrowhead", "label-line")
RECORD = Path(__file__).parent / "data" / "label_overlaps.json"


def labels(fig: Figure) -> list:
    """The text boxes and badge discs of ``fig``; a badge's own number is the badge."""
    badges = [c for c in fig.items if isinstance(c, Circle) and c.style == "badge"]
    centres = {c.centre for c in badges}
    out = [box(*t.box()) for t in fig.items
           if isinstance(t, Text) and t.text.strip() and t.at not in centres]
    return out + [Point(c.centre).buffer(c.radius) for c in badges]


def arrowheads(fig: Figure) -> list:
    """The small closed polygons an arrow ends in."""
    return [Polygon(p.points) for p in fig.items if isinstance(p, Stroke) and p.closed
            and len(p.points) in (3, 4) and Polygon(p.points).area < 6.0]


def lines(fig: Figure) -> list:
    """Every open polyline drawn."""
    return [LineString(p.points).buffer(0.1) for p in fig.items
            if isinstance(p, Stroke) and not p.closed and len(p.points) >= 2]


def count(fig: Figure) -> dict[str, int]:
    """The three counts of ``fig``."""
    marks = labels(fig)
    out = dict.fromkeys(KINDS, 0)
    tree = STRtree(marks) if marks else None
    if tree is not None:
        for i, j in zip(*tree.query(marks)):
            if i < j and marks[i].intersection(marks[j]).area > GRAZE:
                out["label-label"] += 1
    for kind, things in (("label-arrowhead", arrowheads(fig)), ("label-line", lines(fig))):
        if not things or not marks:
            continue
        found = STRtree(things)
        for m in marks:
            hits = [k for k in found.query(m) if m.intersection(things[k]).area > GRAZE]
            out[kind] += len(hits) if kind == "label-arrowhead" else bool(hits)
    return out


def strays(fig: Figure, tol: float = 0.05) -> list[tuple[str, tuple, tuple]]:
    """Each label that stands nearer another named thing of its kind than its own (by more
    than ``tol`` mm, its box to the point, or to the vector's shaft): (name, its own, the
    nearer one). A label's own is its text's ``owner``: a point, or a vector's tail and tip;
    two within half a millimetre of one another are one, and a vector within another's
    shaft (V_A₄ within V_B₄ from one pole) has no rival in it."""
    named = [t for t in fig.items if isinstance(t, Text) and t.owner is not None]
    shapes = {t.owner for t in named}

    def geometry(shape):
        return Point(shape[0]) if len(shape) == 1 else LineString(shape)

    def holds(other, own):
        """``other`` is ``own``, or (a vector) its shaft holds all of ``own``'s."""
        return all(geometry(other).distance(Point(p)) <= 0.5 for p in own)
    out = []
    for t in named:
        b = box(*t.box())
        mine = b.distance(geometry(t.owner))
        for other in shapes:
            if len(other) == len(t.owner) and not holds(other, t.owner) and \
                    b.distance(geometry(other)) < mine - tol:
                out.append((t.text + t.sub, t.owner, other))
                break
    return out


def bundled_counts() -> dict[str, dict[str, int]]:
    """``{"<exercise>/<figure stem>": counts}`` for every bundled exercise's figures, of
    every chapter."""
    from tarsim import load, solve
    from tarsim.exercises.catalog import everything

    return {f"{name}/{stem}": count(fig) for name in everything()
            for stem, fig in solve(load(name)).figures.items()}


if __name__ == "__main__":
    json.dump(bundled_counts(), sys.stdout, indent=1, sort_keys=True)
    print()
