"""The kinds of joint besides the pin, each declared once: what makes a joint of the model
one kind or another, and the facts about it every layer asks.

A joint of the model is a :class:`~.joints.Slide` (a point kept on a straight line of
another link) or an :class:`~.joints.Arc` (a point kept at a distance from a point of
another link), with its :class:`SlideKind` and, for a direct contact, its
:class:`~.joints.Contact`. Those fields together make its **kind**, ``joint.type``: a
block on a straight guide, a pin in a straight slot, a circle on a flat face, a wheel
rolling on one, a pin in a curved slot, a block on a curved guide, two circles in
contact, a wheel rolling round a circle. The pin, a point named on two links, is the
mechanism's own joint and no entry here.

A kind declares the facts the model answers with (how many equations it adds, whether
its link turns with its guide, how a message names it). What each layer *does* with a
joint is kept in one table per layer keyed by :attr:`JointKind.key`, because the layers
may not share code (the reference imports no method, and constructions no figure):

* :data:`~tarsim.constructions.linkages.joint_rules.JOINT_RULES`: its dyad rules, its
  contact point, its primary instant centre and its locus in the polygons;
* :data:`~tarsim.constructions.reference.joint_equations.JOINT_EQUATIONS`: its rows of
  the loop equations and its closed-form act;
* :data:`~tarsim.graphics.linkages.joint_symbols.JOINT_SYMBOLS`: its symbol in the
  kinematic diagram.

A new kind of joint is one entry in :data:`JOINT_KINDS` and one in each table
(``tests/test_joint_kinds.py`` holds every table to the same keys).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

__all__ = ["SlideKind", "JointKind", "JOINT_KINDS", "kind_of"]


class SlideKind(StrEnum):
    """A prismatic block, or a pin running in a slot."""

    BLOCK = "block"
    PIN = "pin"


@dataclass(frozen=True)
class JointKind:
    """One kind of joint: the fields that make it, and what the model answers of it.

    ``shape`` is ``"line"`` for a :class:`~.joints.Slide` and ``"circle"`` for an
    :class:`~.joints.Arc`; with ``slide``, ``contact`` (it is the equivalent of a direct
    contact) and ``rolling`` (without slip) it is the signature :func:`kind_of` reads a
    joint's kind by. ``constraints`` is the number of loop equations it adds (two make it
    a lower pair in Grübler's count, one a higher pair; none for a block on a curved
    guide, which stands as the pin at its centre of curvature). ``turns_with_guide``: its
    link keeps its angle to the guide's, so it also carries a couple. ``noun`` is how a
    message names its point ("block B of link 4 on link 1").
    """

    key: str
    shape: str
    slide: SlideKind
    contact: bool
    rolling: bool
    constraints: int
    turns_with_guide: bool
    noun: str

    @property
    def stands_as_pin(self) -> bool:
        """True for a kind with no equation of its own: the pin the reader gave it stands."""
        return self.constraints == 0


JOINT_KINDS: dict[str, JointKind] = {k.key: k for k in (
    JointKind("block", "line", SlideKind.BLOCK, False, False, 2, True, "block"),
    JointKind("slot", "line", SlideKind.PIN, False, False, 1, False, "pin"),
    JointKind("face_contact", "line", SlideKind.PIN, True, False, 1, False, "contact"),
    JointKind("rolling_on_face", "line", SlideKind.PIN, True, True, 2, False, "contact"),
    JointKind("curved_slot", "circle", SlideKind.PIN, False, False, 1, False, "pin"),
    JointKind("curved_block", "circle", SlideKind.BLOCK, False, False, 0, False, "block"),
    JointKind("circle_contact", "circle", SlideKind.PIN, True, False, 1, False, "contact"),
    JointKind("rolling_round", "circle", SlideKind.PIN, True, True, 2, False, "contact"),
)}
"""Every kind of joint besides the pin, by key."""

_BY_FIELDS = {(k.shape, k.slide, k.contact, k.rolling): k for k in JOINT_KINDS.values()}


def kind_of(shape: str, slide: SlideKind, contact: bool, rolling: bool) -> JointKind:
    """The kind of a joint with these fields.

    Examples
    --------
    >>> kind_of("line", SlideKind.BLOCK, False, False).key
    'block'
    >>> kind_of("circle", SlideKind.PIN, True, True).constraints
    2
    """
    return _BY_FIELDS[shape, slide, contact, rolling]
