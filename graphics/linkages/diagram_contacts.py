"""Cam contacts on the kinematic diagram: a circle on a flat face, or two circles.

A contact of a circle on a flat face is assembled as its equivalent pin in a slot,
but drawn as what the student sees: the cam's circle, the follower's face and the
contact point P, where the assembly marked it. Two circles in contact (a roller
on a circular cam) are drawn as both circles and P on their line of centres.
Where each lies is read off the record once, when the diagram is made
(:func:`contact`, :func:`pair`); :func:`draw_contacts` draws them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from shapely.geometry import Point as SPoint

from tarsim.constructions.joints import Arc, Slide
from tarsim.constructions.scales import face_ends

from ..figure import Circle
from ..paper_points import difference
from ..symbols import draw_guide, draw_hatched_arc, unit
from .joint_symbols import Drawn, symbol_of

if TYPE_CHECKING:
    from .diagram import _Diagram

__all__ = ["contact", "pair", "draw_contacts"]

_DOT = 0.55                # a marked point (circle centre, contact point) on paper, mm
_FACE_MARGIN = 4.0         # a face runs this far (paper mm) past its own point, under a block


@dataclass(frozen=True, slots=True)
class _Contact:
    """A circle-on-face contact in world metres: what the diagram draws for it."""

    slide: Slide
    centre: tuple[float, float]
    radius: float
    point: tuple[float, float]        # P, the foot of the common normal
    away: tuple[float, float]         # unit normal from the circle across the face


@dataclass(frozen=True, slots=True)
class _Pair:
    """Two circles in contact, in world metres: both circles and P on their line of centres."""

    cam: tuple[float, float]
    cam_radius: float
    roller: tuple[float, float]
    roller_radius: float
    point: tuple[float, float]        # P
    normal: tuple[float, float]       # unit, from the cam's centre toward the roller's


def contact(diagram: _Diagram, index: int, s: Slide) -> _Contact:
    """Where a contact's circle, face and P lie: P as the assembly marked it."""
    c, r = diagram.world[s.point], s.contact.circle.radius
    ref = diagram.asm.contacts[s]
    p = diagram.asm.output(ref).xy
    d = unit(diagram.asm.guide(index).direction)
    away = unit(difference(p, c)) if math.dist(p, c) > 0.0 else (-d[1], d[0])
    return _Contact(s, c, r, p, away)


def _face(diagram: _Diagram, k: _Contact,
          margin: float) -> tuple[tuple[float, float], tuple[float, float]]:
    """The face's ends as drawn: round P, and ``margin`` (m) round its own point."""
    return face_ends(diagram.asm, k.slide, diagram.asm.contacts[k.slide], margin)


def pair(diagram: _Diagram, a: Arc) -> _Pair:
    """Where two touching circles and P lie: P as the assembly marked it, on their line
    of centres."""
    c, r = diagram.world[a.centre], diagram.world[a.point]
    cam, roller = a.contact.face.radius, a.contact.circle.radius
    n = unit(difference(r, c)) if math.dist(r, c) > 0.0 else (1.0, 0.0)
    return _Pair(c, cam, r, roller, diagram.asm.output(diagram.asm.contacts[a]).xy, n)


def draw_contacts(diagram: _Diagram) -> None:
    """Draw each cam circle, its flat face or second circle, and P (dots, not pins).

    A face on the frame that a wheel rolls on is the ground: it is hatched.
    """
    for k in diagram.contacts:
        _draw_circle(diagram, k.centre, k.radius)
        # Past its own point only if that is a bare dot (under a block), not a pivot.
        margin = _FACE_MARGIN if diagram.marked(k.slide.contact.face.through) else 0.0
        a, b = (diagram.view(e) for e in _face(diagram, k, margin / diagram.view.scale))
        if symbol_of(k.slide).ground and k.slide.guide_link == 1:
            diagram.placer.block(draw_guide(diagram.fig, a, b, diagram.view.direction(k.away)))
        else:
            diagram.fig.line(a, b, "link")
        diagram.placer.block_segment(a, b, 0.6)
        _draw_dot(diagram, diagram.view(k.point))
        for n in (k.slide.point, k.slide.contact.face.through):
            if diagram.marked(n):
                _draw_dot(diagram, diagram.paper[n])
    for k, a in zip(diagram.pairs, [a for a in diagram.m.arcs
                                    if symbol_of(a).drawn is Drawn.CIRCLES]):
        _draw_circle(diagram, k.cam, k.cam_radius)
        _draw_circle(diagram, k.roller, k.roller_radius)
        _draw_dot(diagram, diagram.view(k.point))
        if symbol_of(a).ground and a.guide_link == 1:
            # The fixed circle a wheel rolls round is the ground: hatched on its far
            # side from the wheel, either way of the contact.
            c, p = diagram.view(k.cam), diagram.view(k.point)
            at = math.atan2(c[1] - p[1], p[0] - c[0])
            diagram.placer.block(draw_hatched_arc(
                diagram.fig, c, k.cam_radius * diagram.view.scale, at - 0.7, 1.4,
                inward=a.contact.side == "outside"))
    # A cam's centre and a centre of curvature are bare dots, unless a link is pinned there.
    for n in dict.fromkeys(a.centre for a in diagram.m.arcs):
        if diagram.marked(n):
            _draw_dot(diagram, diagram.paper[n])


def _draw_circle(diagram: _Diagram, centre: tuple[float, float], radius: float) -> None:
    """A circular profile (world centre and radius) as a link outline."""
    c, r = diagram.view(centre), radius * diagram.view.scale
    diagram.fig.add(Circle(c, r, "link"))
    diagram.placer.block(SPoint(c).buffer(r + 0.6).difference(SPoint(c).buffer(r - 0.6)))


def _draw_dot(diagram: _Diagram, at: tuple[float, float]) -> None:
    """A marked point on paper that is not a joint: a small filled dot."""
    diagram.fig.add(Circle(at, _DOT, "arrowhead"))
    diagram.placer.block(SPoint(at).buffer(_DOT + 0.3))
