"""What each kind of joint is to the compass methods, in one table: :data:`JOINT_RULES`.

A kind of joint (:mod:`~tarsim.constructions.joint_kinds`) brings to position by compass
the dyad rules that locate it, and, if it is a direct contact, where its profiles touch;
to the instant centres, its primary centre by inspection (or the common normal it lies
on); to the polygons, the line it puts a tip on, and for a wheel rolling on the ground
the acceleration of its contact point. Each method looks the joint's entry up by
``joint.type.key`` and takes what it needs, so a new kind of joint is one entry here
(and its functions, beside those of the kinds like it).

The pin, a point named on two links, is the mechanism's own joint: :data:`PIN_RULES`
are its dyad rules, and :mod:`.kennedy` marks its centre.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from . import contact_points, inspection, polygon_joints
from .dyad_cuts import arc_and_guide, rigid_point, two_arcs, two_guides
from .dyad_rolling import roll_round, roll_wheel
from .dyad_rules import DYAD_RULES, DyadRule
from .dyad_slots import slot_of_a_block, slot_through_block
from ..model import Mechanism

__all__ = ["JointRules", "JOINT_RULES", "PIN_RULES", "rules_of", "dyad_rules_for"]


@dataclass(frozen=True)
class JointRules:
    """A kind of joint as the compass methods see it.

    ``dyad_rules`` are the rules of position by compass that locate its point (see
    :mod:`.dyad_rules`); ``touch`` marks a contact's P (:mod:`.contact_points`);
    ``centre`` finds its primary centre by inspection, or the common normal the centre
    lies on (:mod:`.inspection`), in the round ``inspected`` (straight joints first, then
    a wheel's contact, then the curved joints' normals); ``pin`` says how the pin a kind
    stands as is a centre, for a kind with no equation of its own; ``locus`` is the line
    it puts a polygon's tip on and ``rolling`` the acceleration of a rolling wheel's
    contact point (:mod:`.polygon_joints`).
    """

    dyad_rules: tuple[Callable, ...]
    centre: Callable | None = None
    inspected: int = 1
    touch: Callable | None = None
    pin: Callable | None = None
    locus: Callable | None = None
    rolling: Callable | None = None


_STRAIGHT = (slot_through_block, slot_of_a_block, two_guides, arc_and_guide)
"""What locates a point on a straight guide or slot: the slot swung through its block, a
translating block's slot, two guides, or a guide and an arc."""

JOINT_RULES: dict[str, JointRules] = {
    "block": JointRules(_STRAIGHT, inspection.straight_block,
                        locus=polygon_joints.straight_locus),
    "slot": JointRules(_STRAIGHT, inspection.common_normal("slot"),
                       locus=polygon_joints.straight_locus),
    "face_contact": JointRules(_STRAIGHT, inspection.common_normal("contact"),
                               touch=contact_points.touch_face,
                               locus=polygon_joints.straight_locus),
    "rolling_on_face": JointRules((*_STRAIGHT, roll_wheel), inspection.rolling_on_face,
                                  touch=contact_points.touch_face,
                                  locus=polygon_joints.straight_locus,
                                  rolling=polygon_joints.rolling_on_face),
    "curved_slot": JointRules((two_arcs,), inspection.curved_slot, inspected=3,
                              locus=polygon_joints.curved_locus),
    "curved_block": JointRules((), pin=inspection.curved_block),
    "circle_contact": JointRules((two_arcs,), inspection.line_of_centres, inspected=3,
                                 touch=contact_points.touch_circle,
                                 locus=polygon_joints.curved_locus),
    "rolling_round": JointRules((two_arcs, roll_round), inspection.rolling_round, inspected=2,
                                touch=contact_points.touch_circle,
                                locus=polygon_joints.curved_locus,
                                rolling=polygon_joints.rolling_round),
}
"""Each kind of joint's rules, by the kind's key."""

PIN_RULES = (rigid_point, two_arcs)
"""The pin's dyad rules: a point of a link already drawn, or cut from two arcs (RRR)."""


def rules_of(joint) -> JointRules:
    """The entry of ``joint``'s kind."""
    return JOINT_RULES[joint.type.key]


def dyad_rules_for(mech: Mechanism) -> list[DyadRule]:
    """The dyad rules the walk tries on ``mech``, in their order (lower first, equal orders
    as they registered): the pin's, those of the kinds of joint it has, and any rule no
    kind names."""
    owned = set().union(*(r.dyad_rules for r in JOINT_RULES.values()))
    wanted = set(PIN_RULES).union(*(rules_of(j).dyad_rules for j in (*mech.slides, *mech.arcs)))
    return sorted((r for r in DYAD_RULES.values() if r.locate in wanted or r.locate not in owned),
                  key=lambda r: r.order)
