"""Each kind of joint's symbol in the kinematic diagram, in one table: :data:`JOINT_SYMBOLS`.

Figures may not be imported by constructions, so the symbols are kept here, keyed by the
joint's kind (:mod:`tarsim.constructions.joint_kinds`). A symbol says what the diagram
draws for the joint, and its siblings draw it in their passes:

* a straight guide or slot (:class:`Drawn` ``GUIDE``): a hatched guide on the frame, a
  slot in a moving link's bar (:mod:`.diagram_slides`);
* a curved slot or guide (``TRACK``): an arc about its centre of curvature;
* a circle on a flat face (``FACE``) or two circles (``CIRCLES``): the profiles touching
  at P, as the student sees them (:mod:`.diagram_contacts`).

``block`` puts a slider block on the guide or track; ``ground`` hatches the profile the
wheel rolls on when it is the frame's. A new kind of joint drawn like one of these is one
entry; one drawn otherwise is a new :class:`Drawn` and its drawing in those modules.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

__all__ = ["Drawn", "JointSymbol", "JOINT_SYMBOLS", "symbol_of"]


class Drawn(StrEnum):
    """What the diagram draws for a joint."""

    GUIDE = "guide"
    """A straight guide (hatched, on the frame) or a slot in a moving link."""
    TRACK = "track"
    """A curved slot, or a curved guide, about its centre of curvature."""
    FACE = "face"
    """A circle on a flat face, touching at P."""
    CIRCLES = "circles"
    """Two circles, touching at P on their line of centres."""


@dataclass(frozen=True)
class JointSymbol:
    """How the diagram draws one kind of joint (see the module's docstring)."""

    drawn: Drawn
    block: bool = False
    ground: bool = False


JOINT_SYMBOLS: dict[str, JointSymbol] = {
    "block": JointSymbol(Drawn.GUIDE, block=True),
    "slot": JointSymbol(Drawn.GUIDE),
    "face_contact": JointSymbol(Drawn.FACE),
    "rolling_on_face": JointSymbol(Drawn.FACE, ground=True),
    "curved_slot": JointSymbol(Drawn.TRACK),
    "curved_block": JointSymbol(Drawn.TRACK, block=True),
    "circle_contact": JointSymbol(Drawn.CIRCLES),
    "rolling_round": JointSymbol(Drawn.CIRCLES, ground=True),
}
"""Each kind of joint's symbol, by the kind's key."""


def symbol_of(joint) -> JointSymbol:
    """The symbol of ``joint``'s kind."""
    return JOINT_SYMBOLS[joint.type.key]
