"""Slides on the kinematic diagram: blocks on their guides, and curved slots and guides.

A block on the frame slides on a hatched guide drawn on the side no link leaves it
by; a flat-faced follower's block stands on its face, as the follower's stem
(:func:`block_lift`). A pin in a curved slot is drawn in a slot about its centre of
curvature, carried by its link's body; a block on a curved guide stands tangent to a
hatched arc. The block's pin at the centre of curvature, which the file reader adds
to the block (its kinematic equivalent), is not drawn: that centre is a bare dot.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from shapely.geometry import MultiPoint

from tarsim.constructions import geometry as g
from tarsim.constructions.joints import Arc, Slide

from ..figure import Path, arc_points
from ..paper_points import angle_about, centroid, tangent
from ..symbols import PIN_RADIUS, draw_block, draw_curved_guide, draw_curved_slot, draw_guide, unit
from .joint_symbols import Drawn, symbol_of

if TYPE_CHECKING:
    from .diagram import _Diagram

__all__ = ["track", "block_lift", "block_centre", "draw_frame_guides", "draw_track",
           "draw_blocks"]

_BLOCK = (9.0, 5.0)        # slider block on paper, mm
_SLOT_HALF = 20.0          # a curved slot runs this far (paper mm) either side of its middle
_SLOT_WIDTH = PIN_RADIUS + 0.35   # half its width, so the pin just fits


@dataclass(frozen=True, slots=True)
class _Track:
    """A curved slot or guide on paper: an arc about its centre of curvature.

    ``root`` is where the carrying link's body meets it (None on the frame).
    """

    arc: Arc
    centre: tuple[float, float]
    radius: float                     # mm
    start: float                      # paper angle, rad, CCW as seen
    sweep: float
    root: tuple[float, float] | None


def track(diagram: _Diagram, a: Arc) -> _Track:
    """Lay out a curved slot or guide on paper about its centre of curvature.

    It is centred on its pin or block, where the figure shows it: on the frame as
    long as a straight guide, on a moving link a shorter slot. The link's body
    (a bar from its pivot) holds the slot at its middle, on the edge that faces
    the pivot; the centre of curvature is a point of the link's plane, not of its
    body, so the bar does not run to it.
    """
    c, p = diagram.paper[a.centre], diagram.paper[a.point]
    r = a.radius * diagram.view.scale
    at = angle_about(c, p)
    if a.guide_link == 1:
        half = min(math.pi / 6, max(22.0, 0.5 * diagram.travel(a.point, tangent(at))) / r)
        return _Track(a, c, r, at - half, 2 * half, None)
    half = min(math.pi / 6, _SLOT_HALF / r)
    w = 0.0 if symbol_of(a).block else _SLOT_WIDTH
    pivot = next((diagram.paper[n] for n in diagram.names(a.guide_link) if n != a.centre), c)
    root = min(((c[0] + e * math.cos(at), c[1] - e * math.sin(at)) for e in (r - w, r + w)),
               key=lambda q: math.dist(q, pivot))
    return _Track(a, c, r, at - half, 2 * half, root)


def block_lift(diagram: _Diagram, s: Slide) -> tuple[tuple[float, float], float]:
    """How far (mm) a block is drawn off its point, and along which paper direction.

    A flat-faced follower's block point lies on its face; centred there, the
    block would cover the face and the cam. It is drawn standing on the face
    instead, as the follower's stem, which the rigid link allows. A block sliding on
    the ground a wheel rolls on stands on that ground, its point on the ground's line,
    so the ground is drawn once, at one height (:func:`_ground_under`).
    """
    d = unit(diagram.view.direction(diagram.asm.guide(diagram.m.slides.index(s)).direction))
    up = _ground_under(diagram, s)
    if up is not None:
        return up, _BLOCK[1] / 2
    for k in diagram.contacts:
        if k.slide.guide_link != s.link or k.slide.contact.face.through != s.point:
            continue
        n = diagram.view.direction(k.away)
        along = d[0] * n[0] + d[1] * n[1]
        if abs(along) < 1e-6:
            break  # the face runs along the guide: nothing to stand on
        # Clear the face with the block's near corners, however the face is tilted.
        lift = _BLOCK[0] / 2 + _BLOCK[1] / 2 * math.sqrt(1.0 - along * along) / abs(along)
        return (d if along > 0 else (-d[0], -d[1])), lift
    return d, 0.0


def _ground_under(diagram: _Diagram, s: Slide) -> tuple[float, float] | None:
    """The paper direction from the ground up to a block whose frame guide is the ground a
    wheel rolls on (the wheel-driven slider's B sliding on the floor the wheel rolls on),
    else None."""
    if s.guide_link != 1:
        return None
    line = diagram.asm.guide(diagram.m.slides.index(s))
    for k in diagram.contacts:
        if not (symbol_of(k.slide).ground and k.slide.guide_link == 1):
            continue
        face = diagram.asm.guide(diagram.m.slides.index(k.slide))
        (a, b), (c, e) = unit(line.direction), unit(face.direction)
        tol = 1e-9 * max(diagram.asm.size, 1e-300)
        if abs(a * e - b * c) <= 1e-9 and abs(line.signed_distance(g.Point(*k.point))) <= tol:
            n = diagram.view.direction(k.away)
            return (-n[0], -n[1])
    return None


def block_centre(diagram: _Diagram, s: Slide) -> tuple[float, float]:
    """Where a block is drawn (see :func:`block_lift`)."""
    (ux, uy), lift = block_lift(diagram, s)
    p = diagram.paper[s.point]
    return (p[0] + lift * ux, p[1] + lift * uy)


def draw_frame_guides(diagram: _Diagram) -> None:
    """Draw the hatched guide of each block on the frame, and the frame's curved tracks."""
    centre = centroid([diagram.paper[n] for n in diagram.m.frame.names])
    for i, s in enumerate(diagram.m.slides):
        if s.guide_link != 1 or not _on_guide(s):
            continue
        line = diagram.asm.guide(i)
        d = unit(diagram.view.direction(line.direction))
        n = (-d[1], d[0])
        p = block_centre(diagram, s)
        # The guide and its hatching lie on the side of the block no link leaves it by;
        # with links either way (or none), on the far side from the frame pivots.
        pin = diagram.paper[s.point]
        leave = sum(((q[0] - pin[0]) * n[0] + (q[1] - pin[1]) * n[1])
                    for k in diagram.links_at(s.point) if k != 1
                    for q in (diagram.paper[o] for o in diagram.names(k) if o != s.point))
        away = (p[0] - centre[0]) * n[0] + (p[1] - centre[1]) * n[1]
        if abs(leave) > 1.0:
            away = -leave
        side = n if away >= 0 else (-n[0], -n[1])
        off = _BLOCK[1] / 2
        half = max(22.0, 0.5 * diagram.travel(s.point, d))
        # A block standing on a face has its guide above the face only.
        u, lift = block_lift(diagram, s)
        up = _ground_under(diagram, s)
        if up is not None:      # standing on the ground: its guide is the ground's line
            side, u, lift = (-up[0], -up[1]), d, 0.0
        lo, hi = (-half, half) if lift == 0.0 else (1.0 - _BLOCK[0] / 2, half + _BLOCK[0])
        if lift == 0.0:
            # The guide runs past every marked place of the block on it (a limit point).
            along = [(q[0] - p[0]) * u[0] + (q[1] - p[1]) * u[1] for q in diagram.marks()
                     if abs((q[0] - p[0]) * n[0] + (q[1] - p[1]) * n[1]) <= 0.5]
            lo, hi = min([lo] + [t - 8.0 for t in along]), max([hi] + [t + 8.0 for t in along])
        a = (p[0] + off * side[0] + lo * u[0], p[1] + off * side[1] + lo * u[1])
        b = (p[0] + off * side[0] + hi * u[0], p[1] + off * side[1] + hi * u[1])
        band = draw_guide(diagram.fig, a, b, side)
        diagram.placer.block(band.buffer(0.3))
        diagram.placer.block_segment(a, b)
    for t in diagram.tracks:
        if t.arc.guide_link == 1:
            draw_track(diagram, t)


def draw_track(diagram: _Diagram, t: _Track) -> None:
    """A curved slot (an outline), or a guide: hatched on the frame, the link's arc if not.

    A frame guide is offset by half the block's height to the side away from the
    frame's other points, as a straight guide is.
    """
    a = t.arc
    if not symbol_of(a).block:
        style = "guide" if a.guide_link == 1 else "link"
        shape = draw_curved_slot(diagram.fig, t.centre, t.radius, t.start, t.sweep,
                                 _SLOT_WIDTH, style)
    elif a.guide_link == 1:
        others = [diagram.paper[n] for n in diagram.m.frame.names if n != a.centre]
        inside = math.dist(centroid(others or [diagram.paper[a.point]]), t.centre) < t.radius
        side = 1.0 if inside else -1.0
        shape = draw_curved_guide(diagram.fig, t.centre, t.radius + side * _BLOCK[1] / 2,
                                  t.start, t.sweep, side)
    else:
        rim = arc_points(t.centre, t.radius, t.start, t.sweep)
        diagram.fig.add(Path(tuple(rim), "link"))
        shape = MultiPoint(rim).convex_hull
    diagram.placer.block(shape.buffer(0.5))


def draw_blocks(diagram: _Diagram) -> None:
    """Draw each block: along its straight guide, or tangent to its curved one."""
    for i, s in enumerate(diagram.m.slides):
        if not _on_guide(s):
            continue
        d = unit(diagram.view.direction(diagram.asm.guide(i).direction))
        shape = draw_block(diagram.fig, block_centre(diagram, s), d, *_BLOCK)
        diagram.placer.block(shape)
    for t in diagram.tracks:
        if symbol_of(t.arc).block:  # tangent to its arc, square to the radius
            at = diagram.paper[t.arc.point]
            diagram.placer.block(draw_block(diagram.fig, at,
                                            tangent(angle_about(t.centre, at)), *_BLOCK))


def _on_guide(s: Slide) -> bool:
    """True for a block on a straight guide."""
    symbol = symbol_of(s)
    return symbol.block and symbol.drawn is Drawn.GUIDE
