"""A leader from a point to its name, where the name had to stand off.

A reader takes a name for the point marked nearest it. Round a point where many lines
meet (a centre found by Kennedy's theorem, a pin that is also an instant centre) every
spot near it is crossed, and the placer sets the name clear of them farther off: a thin
line then leads from the point's mark to it, so that it is read for its own point and
not taken for a name in the white. A name within :data:`NEAR` of its mark needs none.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from shapely import get_coordinates
from shapely.geometry import LineString, MultiPoint, Polygon, box
from shapely.geometry import Point as SPoint
from shapely.ops import nearest_points, unary_union

from ..figure import Circle, Figure, Path, Text
from ..labels import LABEL, LabelPlacer
from ..symbols import unit

__all__ = ["NEAR", "lead", "lead_last_to_shaft", "lead_to_shaft", "mark_of", "place_led"]

NEAR = 3.5
"""Paper (mm) a point's name stands off its mark at most, unless a leader joins them: as far
as a mechanism's own names stand from their pins (two of their gaps and a little more)."""

_GAP = 0.4          # white between a leader's ends and the mark and the name it joins, mm
_TRIES = 48         # points round a name's box a leader may end at
_AGAIN = 3          # times a name no leader reaches is set again
_HEAD = 3.0         # mm of an arrow's shaft by its head, from which no leader starts
_STARTS = 12        # points along a shaft a leader to its name may start from


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
    return _led(fig, placer, at, mark, edge)


def lead_to_shaft(fig: Figure, placer: LabelPlacer, shaft: tuple[tuple[float, float], ...],
                  name: Text, avoid: Sequence = (), claimed: Sequence = ()) -> bool:
    """Draw a leader to an arrow's ``name`` standing more than :data:`NEAR` off its
    ``shaft`` (tail, tip), from the shaft's point nearest the name, short of its head (a
    leader from the head would be read for the tip's); as :func:`lead` does for a point,
    crossing none of the shapes ``avoid`` either (the name's own step numbers), its ends
    in none of ``claimed``."""
    line, edge = LineString(shaft), box(*name.box())
    if edge.distance(line) <= NEAR:
        return True
    # From the shaft's point nearest the name, else from the next nearest one a leader
    # reaches past the heads and names crowding there.
    reach = max(line.length - _HEAD, 0.0)
    along = {min(line.project(edge.centroid), reach),
             *(reach * k / _STARTS for k in range(_STARTS + 1))}
    starts = sorted((line.interpolate(t).coords[0] for t in along),
                    key=lambda p: edge.distance(SPoint(p)))
    return any(_led(fig, placer, at, SPoint(at), edge, avoid, claimed) for at in starts)


def lead_last_to_shaft(fig: Figure, placer: LabelPlacer, shaft: tuple[tuple[float, float], ...],
                       since: int) -> None:
    """Lead to its arrow the name of ``shaft`` set among ``fig``'s items from ``since`` on
    (:func:`lead_to_shaft`), where one was set: the first text there that names a thing."""
    name = next((t for t in fig.items[since:] if isinstance(t, Text) and t.owner), None)
    if name is not None:    # past its own step numbers and the names after it ("= A_A₂")
        own = [SPoint(c.centre).buffer(c.radius) for c in fig.items[since:]
               if isinstance(c, Circle)]
        own += [box(*t.box()) for t in fig.items[since:] if isinstance(t, Text) and t is not name]
        lead_to_shaft(fig, placer, shaft, name, avoid=own, claimed=_claims(fig))


def _claims(fig: Figure) -> list:
    """Round each point's name on ``fig``, the white nearer it than its own point: a
    leader ending there would be taken for the point that name names (a reader, and the
    grader, take a name for the mark nearest it)."""
    out = []
    for t in fig.items:
        if isinstance(t, Text) and t.owner is not None and len(t.owner) == 1 \
                and isinstance(t.owner[0], tuple):
            name = box(*t.box())
            out.append(name.buffer(name.distance(SPoint(t.owner[0]))))
    return out


def _led(fig: Figure, placer: LabelPlacer, at: tuple[float, float], mark, edge,
         avoid: Sequence = (), claimed: Sequence = ()) -> bool:
    """A leader from ``mark`` (about ``at``) to the nearest point of the box ``edge`` it
    reaches crossing no other name or arrowhead, nor a shape of ``avoid``, its ends in
    none of ``claimed`` (:func:`lead`); whether one was drawn."""
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
        stroke = LineString([start, end]).buffer(0.15)
        # (not along its own name's edge either, where it would be read as underlining)
        if math.dist(start, end) > 0.5 and not stroke.intersects(edge) \
                and not _covers_label(placer, stroke, edge) \
                and not any(stroke.intersects(a) for a in avoid) \
                and not any(c.contains(SPoint(e)) for c in claimed for e in (start, end)):
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
