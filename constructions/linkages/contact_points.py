"""Where a contact's profiles touch, P, marked once the position is drawn.

A direct contact is assembled as its equivalent (a pin in a slot parallel to the face,
or a link joining two centres of curvature), but the diagram draws the profiles
touching and the centres take their common normal through P. Each kind of contact
marks its P here (:data:`~.joint_rules.JOINT_RULES` names which): on a flat face, the
foot of the circle's centre, since the common normal runs through the centre square to
the face; between two circles, on their line of centres, on the cam's rim toward the
roller (on its far side only for a cam inside a larger roller).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .. import geometry as g
from ..joints import Arc, Slide
from ..record import Kind, Ref

if TYPE_CHECKING:
    from .assembly import Assembler

__all__ = ["touch_face", "touch_circle"]


def touch_face(asm: Assembler, i: int, s: Slide) -> Ref:
    """P of a circle on a flat face (slide ``i``): the foot of the circle's centre on the face
    drawn through its own point parallel to the slot."""
    face = asm.c.draw(f"profile:face:{i}", "parallel_through",
                      asm.known[s.contact.face.through], asm.guides[i],
                      kind=Kind.GUIDE, label=f"face of link {s.contact.face.link}")
    return asm.c.draw(f"contact:{i}", "project_onto", asm.known[s.point], face,
                      label="P", kind=Kind.CONTACT)


def touch_circle(asm: Assembler, k: int, a: Arc) -> Ref:
    """P of two circles in contact (arc ``k``): the cam's radius laid off from its centre
    toward the roller's; any rim point where the centres coincide."""
    cam, roller = a.contact.face.radius, a.contact.circle.radius
    reach = -cam if a.contact.side == "inside" and roller > cam else cam
    c, r = asm.known[a.centre], asm.known[a.point]
    if g.distance(asm.c.output(c), asm.c.output(r)) == 0.0:   # concentric: any rim point
        x, y = asm.c.output(c).xy
        return asm.c.give(f"contact:a{k}", g.Point(x + reach, y), label="P", kind=Kind.CONTACT)
    return asm.c.draw(f"contact:a{k}", "lay_off", c, r, length=reach, label="P",
                      kind=Kind.CONTACT)
