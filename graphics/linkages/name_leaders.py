"""A leader from a point or a vector to its name, where the name had to stand off.

A reader takes a name for the point (or the arrow) marked nearest it. Round a point
where many lines meet (a centre found by Kennedy's theorem, a pin that is also an instant
centre), or among a polygon's short arrows crowded at one end, every spot near it is
crossed, and the name is set clear of them farther off: a thin line then leads from the
point's mark (or the arrow's shaft) to it, so that it is read for its own and not taken
for a name in the white or for the arrow it stands by. A name within :data:`NEAR` of its
own, nearer it than any other named thing, needs none.

:func:`place_led` sets a name as its caller would, and where that spot covers ink or no
leader reaches it, sets it again in the first clear spot, wherever it is, and leads to it.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from shapely import get_coordinates
from shapely.geometry import LineString, MultiPoint, Polygon, box
from shapely.geometry import Point as SPoint
from shapely.ops import nearest_points, unary_union

from ..figure import Circle, Figure, Path, Text
from ..label_nearness import as_shape
from ..labels import LABEL, LabelPlacer
from ..symbols import unit

__all__ = ["NEAR", "lead", "mark_of", "place_led"]

NEAR = 3.5
"""Paper (mm) a point's name stands off its mark at most, unless a leader joins them: as far
as a mechanism's own names stand from their pins (two of their gaps and a little more)."""

CLEAN = 0.0
"""What a name may lie over (mm², past a graze) and still stand where it was set: nothing but
the lines it may cross (``crossable``); not another label, an arrowhead, a shaft or a link."""

_GAP = 0.4          # white between a leader's ends and the mark and the name it joins, mm
_TRIES = 48         # points round a name's box a leader may end at
_AGAIN = 3          # times a name is set again, the white it stood in shut to it
_SHAFT = 0.8        # an arrow's half width, its head's, mm: a vector's mark about its shaft
_THIN = 0.5         # what a leader may cross uncounted: a polygon's working lines (0.02)
_AROUND = 1.5       # mm: an arrowhead this near a point's mark or a shaft is by it
_GRAZE = 0.05       # mm²: a name sharing no more than this with a thing only touches it


def mark_of(fig: Figure, at: tuple[float, float]):
    """What marks the point ``at`` on ``fig``: its pin's circle or its dot, and a fixed
    pivot's triangle standing on it, past which its name stands (a shapely shape)."""
    parts = [SPoint(c.centre).buffer(c.radius) for c in fig.items if isinstance(c, Circle)
             and c.style in ("pin", "dot") and math.dist(c.centre, at) < 0.05]
    parts += [Polygon(p.points) for p in fig.items if isinstance(p, Path)
              and p.style == "ground" and p.closed and math.dist(p.points[0], at) < 0.05]
    return unary_union(parts) if parts else SPoint(at)


def place_led(fig: Figure, placer: LabelPlacer, own, place, *,
              keep_near: bool = False, crossable: tuple[str, ...] = ("hatch",)) -> None:
    """Name ``own``, a point or a vector (tail and tip), by ``place(**kw)``, which sets the
    name (the first text it adds) as its caller sets it, with a leader where it stands off
    (:func:`lead`).

    Where that spot covers more than :data:`CLEAN` (no spot beside its own was clear: a
    shaft or a name lies under it) or no leader reaches it crossing no other name, it is
    taken back and set again in the first clear spot, near or far, the white it stood in
    shut to it, its nearness to its own waived, ``place(own=None)``: a leader then joins it
    to its own, even where it stands as near another (``keep_near``: only where its first
    spot covered ink; a polygon's tip, clear but unled, keeps its nearness). Up to
    :data:`_AGAIN` times, so long as it covers no more than :data:`CLEAN` or less than it
    first did, and, where it first stood clear, no more than :data:`NEAR` farther off; else
    it stands where it was first set.
    """
    shape = as_shape(own)
    shut: list[int] = []
    first = None
    for again in range(_AGAIN + 2):
        items, taken = len(fig.items), len(placer.obstacles)
        if again > _AGAIN:          # none better: where it was first set, the white open
            _open(placer, shut)
            shut = []
            place()
            name = _name(fig, items)
            if name is not None:
                lead(fig, placer, shape, name)
            return
        waive = again and not (keep_near and first[0] <= CLEAN)
        place() if not waive else place(own=None)
        name = _name(fig, items)
        if name is None or len(placer.obstacles) == taken:  # a draft's placer keeps no ink
            break
        if waive:
            name = _own(fig, name, shape)
        covers, off = _covered(fig, items, crossable), _off(fig, shape, name)
        first = (covers, off) if first is None else first
        # Set again, it must stand clearer than it first did; and where it first stood clear
        # (only no leader reached it), not much farther off.
        ok = covers <= CLEAN if not again else \
            (covers <= CLEAN or covers < first[0] - 1e-9) \
            and (first[0] > CLEAN or off <= first[1] + NEAR)
        if ok and lead(fig, placer, shape, name, always=bool(again) and _astray(placer, name)):
            break
        del fig.items[items:]
        placer.seen, placer._drawn = min(placer.seen, items), min(placer._drawn, items)
        placer.unblock(taken)
        shut.append(len(placer.obstacles))
        x0, y0, x1, y1 = name.box()
        placer.block(MultiPoint([*_marked(fig, shape)[1], (x0, y0), (x1, y0), (x0, y1),
                                 (x1, y1)]).convex_hull, weight=LABEL)
    _open(placer, shut)


def lead(fig: Figure, placer: LabelPlacer, own, name: Text, always: bool = False) -> bool:
    """Draw a leader from the mark of ``own``, a point or a vector (tail and tip), to its
    ``name`` if the name stands more than :data:`NEAR` off it (or ``always``), and take its
    room. It runs from the mark's edge to a point of the name's box, crossing no other name,
    step number or arrowhead: of those, the one that crosses the fewest shafts and lines
    (a thin working line of a polygon aside), then the shortest. Returns whether the name
    stands by what it names or is led to."""
    shape = as_shape(own)
    mark, starts = _marked(fig, shape)
    edge = box(*name.box())
    if edge.distance(mark) <= NEAR and not always:
        return True
    if len(shape) == 2:     # and from the shaft's point nearest the name, short of its head
        shaft = LineString(shape)
        t = min(shaft.project(edge.centroid), max(shaft.length - 3.0, 0.0))
        starts = [shaft.interpolate(t).coords[0], *starts]
    # Its own step numbers too: a leader to a name runs past them, not through.
    badges = [SPoint(c.centre).buffer(c.radius + 0.2) for c in fig.items
              if isinstance(c, Circle) and c.style == "badge"]
    # The heads of the arrows that meet where it starts are its mark's: it leaves past them.
    heads = {tuple(round(v, 6) for v in Polygon(p.points).buffer(0.3).bounds)
             for p in fig.items if isinstance(p, Path) and p.style == "arrowhead"
             and mark.distance(Polygon(p.points)) < _AROUND}
    rim = edge.exterior
    ends = [rim.interpolate(k / _TRIES, normalized=True).coords[0] for k in range(_TRIES)]
    best = None
    for at in starts:
        for to in (nearest_points(edge, SPoint(at))[0].coords[0], *ends):
            d = unit((to[0] - at[0], to[1] - at[1]))
            out = get_coordinates(mark.boundary.intersection(LineString([at, to])))
            reach = max((math.dist(at, q) for q in out.tolist()), default=0.0)
            start = (at[0] + (reach + _GAP) * d[0], at[1] + (reach + _GAP) * d[1])
            end = (to[0] - _GAP * d[0], to[1] - _GAP * d[1])
            length = math.dist(start, end)
            if length <= 0.5 or (best is not None and length >= best[0][1]
                                 and best[0][0] == 0):
                continue
            line = LineString([start, end]).buffer(0.15)
            if line.intersection(edge).area > 0.01 or any(line.intersects(b) for b in badges):
                continue        # through its own name, or a step number
            crossed = _crossed(placer, line, edge, at, heads)
            if crossed is not None and (best is None or (crossed, length) < best[0]):
                best = ((crossed, length), (start, end))
    if best is None:
        return False
    fig.add(Path(best[1], "plot_leader"))
    placer.block_path(list(best[1]), 0.3, weight=LABEL)    # as a name's: kept clear
    return True


def _crossed(placer: LabelPlacer, shape, own, at, heads=frozenset()) -> int | None:
    """How many shafts and lines ``shape`` (a leader about to be drawn from by ``at`` to the
    name ``own``, a box) crosses, what passes through ``at`` and the arrowheads by it
    (``heads``, by their bounds) aside; None where it covers a placed name or another
    arrowhead (what the placer prices at :data:`~..labels.LABEL` or more) past a graze."""
    if not placer.obstacles:
        return 0
    here, centre = SPoint(at), own.centroid
    crossed = 0
    for k in placer._tree_now().query(shape):
        o, w = placer.obstacles[k], placer.weights[k]
        if w < _THIN or o.contains(here) or o.contains(centre) \
                or tuple(round(v, 6) for v in o.bounds) in heads \
                or shape.intersection(o).area <= 0.01:
            continue
        if w >= LABEL:
            return None
        crossed += 1
    return crossed


def _name(fig: Figure, since: int) -> Text | None:
    """The name a label set since ``since`` items: its first text that is no step number."""
    badges = {c.centre for c in fig.items[since:] if isinstance(c, Circle)
              and c.style == "badge"}
    return next((t for t in fig.items[since:] if isinstance(t, Text) and t.text.strip()
                 and t.at not in badges), None)


def _own(fig: Figure, name: Text, shape) -> Text:
    """``name``, set with its nearness waived, told again what it names."""
    k = next(i for i in range(len(fig.items) - 1, -1, -1) if fig.items[i] is name)
    fig.items[k] = replace(name, owner=shape)
    return fig.items[k]


def _marked(fig: Figure, shape):
    """The mark of a point (:func:`mark_of`) or a vector's shaft, and the points a leader
    may start from: the point, or along the shaft from its middle out."""
    if len(shape) == 1:
        return mark_of(fig, shape[0]), [shape[0]]
    line = LineString(shape)
    return line.buffer(_SHAFT), [line.interpolate(t, normalized=True).coords[0]
                                 for t in (0.5, 0.35, 0.65, 0.2, 0.8)]


def _off(fig: Figure, shape, name: Text) -> float:
    """How far (mm) ``name`` stands off the mark of what it names."""
    return box(*name.box()).distance(_marked(fig, shape)[0])


def _astray(placer: LabelPlacer, name: Text) -> bool:
    """Whether ``name`` stands nearer another named point or vector than its own."""
    x0, y0, x1, y1 = name.box()
    owned = (name.owner, 0.0, 0.0, (x1 - x0) / 2, (y1 - y0) / 2, 0.0)
    return bool(placer._astray(np.array([[(x0 + x1) / 2, (y0 + y1) / 2]]), owned)[0])


def _covered(fig: Figure, since: int, crossable: tuple[str, ...]) -> float:
    """The area (mm²) by which the label set since ``since`` items (its name and step
    numbers) lies over what was drawn before it: another label, an arrowhead, or a line
    of a style not ``crossable`` (a polygon's names may cross its thin working lines, a
    space diagram's a ground's hatching), each past a graze."""
    new, old = fig.items[since:], fig.items[:since]
    mine = _marks_of_labels(new)
    if not mine:
        return 0.0
    x0 = min(m.bounds[0] for m in mine) - 1.0
    y0 = min(m.bounds[1] for m in mine) - 1.0
    x1 = max(m.bounds[2] for m in mine) + 1.0
    y1 = max(m.bounds[3] for m in mine) + 1.0
    near = box(x0, y0, x1, y1)
    drawn = _marks_of_labels(old) + [
        Polygon(p.points) if p.closed else LineString(p.points).buffer(0.1)
        for p in old if isinstance(p, Path) and len(p.points) >= 2
        and (p.style == "arrowhead" or (not p.closed and p.style not in crossable))]
    total = 0.0
    for d in drawn:
        if d.intersects(near):
            for m in mine:
                area = m.intersection(d).area
                total += area if area > _GRAZE else 0.0
    return total


def _marks_of_labels(items) -> list:
    """The boxes of the texts among ``items`` and the discs of their step numbers."""
    discs = [c for c in items if isinstance(c, Circle) and c.style == "badge"]
    centres = {c.centre for c in discs}
    return [box(*t.box()) for t in items if isinstance(t, Text) and t.text.strip()
            and t.at not in centres] + [SPoint(c.centre).buffer(c.radius) for c in discs]


def _open(placer: LabelPlacer, shut: list[int]) -> None:
    """Take back the obstacles at ``shut`` (the white shut to a name while it was set)."""
    for k in reversed(shut):
        placer.ink.paint(placer.obstacles[k], -placer.weights[k])
        del placer.obstacles[k], placer.keys[k], placer.weights[k]
    placer._tree = None
