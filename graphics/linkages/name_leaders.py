"""A leader from a point to its name, where the name had to stand off.

A reader takes a name for the point marked nearest it. Round a point where many lines
meet (a centre found by Kennedy's theorem, a pin that is also an instant centre) every
spot near it is crossed, and the placer sets the name clear of them farther off: a thin
line then leads from the point's mark to it, so that it is read for its own point and
not taken for a name in the white. A name within :data:`NEAR` of its mark needs none.
"""

from __future__ import annotations

import math

from shapely import get_coordinates
from shapely.geometry import LineString, MultiPoint, Polygon, box
from shapely.geometry import Point as SPoint
from shapely.ops import nearest_points, unary_union

from ..figure import Circle, Figure, Path, Text
from ..labels import LABEL, LabelPlacer
from ..symbols import unit

__all__ = ["NEAR", "lead", "mark_of", "place_led"]

NEAR = 3.5
"""Paper (mm) a point's name stands off its mark at most, unless a leader joins them: as far
as a mechanism's own names stand from their pins (two of their gaps and a little more)."""

_GAP = 0.4          # white between a leader's ends and the mark and the name it joins, mm
_TRIES = 48         # points round a name's box a leader may end at
_AGAIN = 3          # times a name no leader reaches is set again


def mark_of(fig: Figure, at: tuple[float, float]):
    """What marks the point ``at`` on ``fig``: its pin's circle or its dot, and a fixed
    pivot's triangle standing on it, past which its name stands (a shapely shape)."""
    parts = [SPoint(c.centre).buffer(c.radius) for c in fig.items if isinstance(c, Circle)
             and c.style in ("pin", "dot") and math.dist(c.centre, at) < 0.05]
    parts += [Polygon(p.points) for p in fig.items if isinstance(p, Path)
              and p.style == "ground" and p.closed and math.dist(p.points[0], at) < 0.05]
    return unary_union(parts) if parts else SPoint(at)


def place_led(fig: Figure, placer: LabelPlacer, at: tuple[float, float], place) -> None:
    """Name the point ``at`` by ``place()`` (which sets its name, the first text it adds
    that names a thing), with a leader where the name stands off (:func:`lead`). Where no
    leader reaches the name crossing no other (a centre's name set behind its pin's own),
    the name is taken back and set again with the white between it and its point shut to
    it, up to :data:`_AGAIN` times, so long as it covers no more than it did; else it stands
    where it was first set."""
    shut: list[int] = []
    first = None
    for again in range(_AGAIN + 2):
        items, taken = len(fig.items), len(placer.obstacles)
        place()
        name = next((t for t in fig.items[items:] if isinstance(t, Text)
                     and t.owner is not None), None)
        if name is None or again > _AGAIN:
            break
        covers = _covered(placer, taken, shut)
        first = covers if first is None else first
        if covers <= first + 1e-9 and lead(fig, placer, at, name):
            break
        del fig.items[items:]
        placer.seen, placer._drawn = min(placer.seen, items), min(placer._drawn, items)
        placer.unblock(taken)
        if again == _AGAIN:         # set where it was first, the white open again
            _open(placer, shut)
            shut = []
            continue
        shut.append(len(placer.obstacles))
        x0, y0, x1, y1 = name.box()
        placer.block(MultiPoint([at, (x0, y0), (x1, y0), (x0, y1), (x1, y1)]).convex_hull,
                     weight=LABEL)
    _open(placer, shut)


def _covered(placer: LabelPlacer, taken: int, shut: list[int]) -> float:
    """The weighted ink under what was blocked since ``taken`` obstacles (a name just set),
    of what was there before it, the white ``shut`` to it aside."""
    mine = placer.obstacles[taken:]
    return sum(w * m.intersection(o).area for m in mine
               for k, (o, w) in enumerate(zip(placer.obstacles[:taken], placer.weights))
               if k not in shut and m.intersects(o))


def _open(placer: LabelPlacer, shut: list[int]) -> None:
    """Take back the obstacles at ``shut`` (the white shut to a name while it was set)."""
    for k in reversed(shut):
        placer.ink.paint(placer.obstacles[k], -placer.weights[k])
        del placer.obstacles[k], placer.keys[k], placer.weights[k]
    placer._tree = None


def lead(fig: Figure, placer: LabelPlacer, at: tuple[float, float], name: Text) -> bool:
    """Draw a leader from the mark of the point ``at`` to its ``name`` if the name stands
    more than :data:`NEAR` off the mark; it runs from the mark's edge to the nearest point
    of the name's box that it reaches crossing no other name or arrowhead, and its room is
    taken. Returns whether the name stands by its point or is led to."""
    mark = mark_of(fig, at)
    edge = box(*name.box())
    if edge.distance(mark) <= NEAR:
        return True
    near = nearest_points(edge, SPoint(at))[0]
    ends = sorted({(near.x, near.y), *(edge.exterior.interpolate(k / _TRIES, normalized=True)
                                       .coords[0] for k in range(_TRIES))},
                  key=lambda e: math.dist(e, at))
    for to in ends:
        d = unit((to[0] - at[0], to[1] - at[1]))
        out = get_coordinates(mark.boundary.intersection(LineString([at, to])))
        rim = max((math.dist(at, q) for q in out.tolist()), default=0.0)
        start = (at[0] + (rim + _GAP) * d[0], at[1] + (rim + _GAP) * d[1])
        end = (to[0] - _GAP * d[0], to[1] - _GAP * d[1])
        if math.dist(start, end) > 0.5 and not _covers_label(
                placer, LineString([start, end]).buffer(0.15), edge):
            fig.add(Path((start, end), "plot_leader"))
            placer.block_path([start, end], 0.3)
            return True
    return False


def _covers_label(placer: LabelPlacer, shape, own) -> bool:
    """Whether ``shape`` covers a placed name or an arrowhead (what the placer prices at
    :data:`~..labels.LABEL` or more) past a graze, the name ``own`` (a box) aside."""
    if not placer.obstacles:
        return False
    taken = [placer.obstacles[k] for k in placer._tree_now().query(shape)
             if placer.weights[k] >= LABEL]
    return any(shape.intersection(t).area > 0.01 for t in taken
               if not t.contains(own.centroid))
