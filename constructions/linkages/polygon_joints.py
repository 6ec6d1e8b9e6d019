"""What a joint gives the velocity and acceleration polygons, by its kind.

* Its **locus**: the line a joint puts a tip on (the notes §2.8, §2.11). A point on a
  straight guide of the frame moves along the guide (``guide``); a point in a straight
  slot of a moving link is two coincident points whose relative motion runs along the
  slot (``slot``); in a slot curved about K it runs square to KP (``curve``). Each
  polygon draws the line for the word (:meth:`~.polygon_walk.PolygonWalk.draw_locus`).
* For a wheel rolling on the ground, the **acceleration of its contact point**: at rest,
  but accelerating toward the wheel's centre.

:data:`~.joint_rules.JOINT_RULES` names the functions each kind takes.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .coincident import Node
from ..errors import TarsimError
from ..joints import Arc, Slide
from ..narration import Number, Phrase, Word, phrase

if TYPE_CHECKING:
    from .acceleration_polygon import _Polygon
    from .polygon_walk import PolygonWalk

__all__ = ["straight_locus", "curved_locus", "rolling_on_face", "rolling_round"]


def straight_locus(walk: PolygonWalk, x: Node, i: int, s: Slide, known) -> list:
    """The line slide ``i`` puts x's tip on: the guide's parallel through the pole for a point
    on a frame guide, the slot's through the other coincident point's tip in a moving one."""
    if s.point != x.point:
        return []
    if s.guide_link == 1:
        return [(("guide", i), walk.asm.guide(i).direction)] if x.link is None else []
    if x.link is None:
        other = Node(s.point, s.guide_link)
    elif x.link == s.guide_link:
        other = Node(s.point)
    else:
        return []
    if other != x and other in walk.nodes and walk.ready(other, known):
        if i not in walk.asm.guides:
            raise TarsimError(f"the slot of {s.label} was not drawn by the assembly")
        return [(("slot", other, i), walk.asm.guide(i).direction)]
    return []


def curved_locus(walk: PolygonWalk, x: Node, i: int, a: Arc, known) -> list:
    """The line arc ``i`` (of the mechanism's ``pin_arcs``) puts x's tip on: square to KP
    through the other point's tip (the centre K's for a slot of the frame)."""
    if a.guide_link == 1:      # a slot of the frame: P moves on the circle about K
        other = Node(a.centre) if x == Node(a.point) else None
    else:
        other = walk.partner(x, a.point, a.guide_link)
    if other is not None and walk.ready(other, known):
        return [(("curve", other, i), walk.normal(Node(a.centre), Node(a.point)))]
    return []


def rolling_on_face(ap: _Polygon, n: Node, s: Slide) -> tuple[float, Phrase]:
    """The contact point of a wheel rolling on a straight face of the ground: ω²·r toward
    the wheel's centre (the centre runs parallel to the ground, the rim point turns about
    it). Returns the acceleration and how it is said."""
    w, centre = ap.omegas[s.link], Node(s.point)
    P, r = ap.name(n), math.dist(ap.xy(n), ap.xy(centre))
    accel = w * w * r
    return accel, phrase("apolygon.rolling", point=P, link=s.link, centre=s.point,
                         omega=Number(abs(w)), radius=ap.m.units.length_said(r),
                         accel=ap.say(accel), tip=ap.tip_name(P))


def rolling_round(ap: _Polygon, n: Node, a: Arc) -> tuple[float, Phrase]:
    """The contact point of a wheel rolling round a fixed circle of radius R: the centre's
    own path curves, so ω²·r·R/(R ± r) toward the wheel's centre."""
    w, centre = ap.omegas[a.link], Node(a.point)
    P, r = ap.name(n), math.dist(ap.xy(n), ap.xy(centre))
    big = a.contact.face.radius
    accel = w * w * r * big / abs(a.roll_gain)
    return accel, phrase("apolygon.rolling_round", point=P, link=a.link, centre=a.point,
                         omega=Number(abs(w)), radius=ap.m.units.length_said(r),
                         big=ap.m.units.length_said(big),
                         op=Word("+" if a.contact.side == "outside" else "−"),
                         accel=ap.say(accel), tip=ap.tip_name(P))
