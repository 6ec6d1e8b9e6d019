"""The joints of the mechanism model besides pins: slides, arcs and direct contacts.

A **slide** puts a point of one link on a straight line fixed in another: the guide
of a slider or the slot of a slotted lever. ``BLOCK`` is a prismatic pair (the
sliding link turns with the guide); ``PIN`` is a pin in a slot (it turns freely, a
two-freedom joint).

An **arc** keeps a point of one link at a fixed distance from a point of another:
a pin in a curved slot (the slot's centre of curvature is the second point), or
two circles in contact, whose centres stay the sum (or difference) of the radii
apart. A *block* on a curved guide turns with the radius of the guide, so it is
exactly a pin at the centre of curvature (notes 000-part1 §2.7 (3b)): the file
reader gives the block that point, and the arc only tells figures and the centre
rule what the pin stands for.

A **contact** is direct (sliding-rolling) contact of a circular profile on a flat
face or on another circle: a cam's circle on a flat-faced follower, a roller on a
flat cam face, or a roller on a circular cam. Kinematically it is exactly a pin at
the circle's centre running in a slot of the other link: for a face, the parallel
to the face offset by the radius; for a circle, the circle through the roller's
centre about the cam's centre (the equivalent linkage, lecture notes §2.13).
:func:`contact_slide` and :func:`contact_arc` build those, so assembly and the
analytic solver see only a ``PIN`` slide or an arc. A **rolling** contact (a
wheel on a flat face, without slip) adds one more constraint: the distance rolled
along the face equals the arc turned on the wheel.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from .joint_kinds import JointKind, SlideKind, kind_of

if TYPE_CHECKING:
    from .model import Link

__all__ = ["SlideKind", "Slide", "Arc", "Profile", "Contact", "contact_slide", "contact_arc"]


@dataclass(frozen=True, slots=True)
class Profile:
    """A working surface of link ``link``: a circular arc or a flat face.

    A circle is ``centre`` (a point name of the link) and ``radius`` (m, > 0); a
    flat face is ``through`` (a point name of the link lying on the face) and
    ``angle``, the face's direction in the link's local frame (rad, CCW +). The
    common normal at a contact runs through the centre and square to the face,
    which is all the kinematics needs of either.
    """

    link: int
    centre: str | None = None
    radius: float | None = None
    through: str | None = None
    angle: float | None = None

    @property
    def is_circle(self) -> bool:
        """True for a circular profile (it has a centre)."""
        return self.centre is not None


@dataclass(frozen=True, slots=True)
class Contact:
    """Direct contact of a circular profile on a flat face or on a second circle.

    For a face, ``side`` is ``"left"`` or ``"right"``: the side of the face's
    direction on which the circle lies, so that the equivalent slot is offset to
    that side. For two circles it is ``"outside"`` (they touch externally: a roller
    on a cam) or ``"inside"`` (the first circle runs inside the second).
    ``rolling`` says the circle rolls on the face or circle without slip, which makes
    the contact point the two links' instant centre.

    The convention that fixes a rolling wheel's angle: the wheel's points are given
    as they are when its centre stands square over the face's ``through`` point (on a
    circle: on the +x axis of the circle's link from its centre) with its local axis
    along the x axis of the face's link (the frame's +x). The wheel turns by the
    distance rolled over its radius from there.
    """

    circle: Profile
    face: Profile
    side: str
    rolling: bool = False

    @property
    def label(self) -> str:
        """How messages name the contact: "contact of link 2 on link 3"."""
        what = "rolling contact" if self.rolling else "contact"
        return f"{what} of link {self.circle.link} on link {self.face.link}"

    @property
    def roll_sign(self) -> float:
        """σ in the no-slip condition s + σ·r·(φ_wheel − φ_face) = 0.

        A wheel on the left of the face's direction turns clockwise as it rolls
        forward (σ = +1); on the right, counter-clockwise (σ = −1).
        """
        return 1.0 if self.side == "left" else -1.0


@dataclass(frozen=True, slots=True)
class Arc:
    """Point ``point`` of link ``link`` stays ``radius`` from point ``centre`` of ``guide_link``.

    ``kind`` is ``PIN`` for a pin in a curved slot or two circles in contact (a
    two-freedom joint), and ``BLOCK`` for a block on a curved guide, which the
    reader has already turned into a pin at ``centre`` (so it adds no constraint of
    its own). ``contact`` is set when the arc is the equivalent of a circle-on-circle
    :class:`Contact`; ``side`` says on which side of a curved block's axis the
    centre of curvature lies.
    """

    kind: SlideKind
    link: int
    point: str
    guide_link: int
    centre: str
    radius: float
    contact: Contact | None = None
    side: str = "left"

    @property
    def type(self) -> JointKind:
        """The joint's kind (:mod:`~.joint_kinds`): a curved slot, a curved block, two circles
        in contact or a wheel rolling round a circle."""
        return kind_of("circle", self.kind, self.contact is not None, self.rolling)

    @property
    def label(self) -> str:
        """How messages name the joint."""
        return _joint_label(self, f"the curved guide of link {self.guide_link}")

    @property
    def rolling(self) -> bool:
        """True for a wheel rolling without slip on a circle (see :class:`Contact`)."""
        return self.contact is not None and self.contact.rolling

    @property
    def roll_gain(self) -> float:
        """The gain k in the no-slip condition r·(φ_wheel − φ_guide) = k·β, β the angle
        the wheel's centre has gone round the circle's from the guide's +x: r + R rolling
        outside the circle, r − R inside it (a coin rolled round an equal coin turns twice)."""
        r, big = self.contact.circle.radius, self.contact.face.radius
        return r + big if self.contact.side == "outside" else r - big


@dataclass(frozen=True, slots=True)
class Slide:
    """Point ``point`` of link ``link`` runs on a straight line fixed in link ``guide_link``.

    The line passes through ``through`` with unit ``direction``, both in the guide
    link's local coordinates (global ones for the frame). ``contact`` is set when
    the slide is the equivalent of a circle-on-face :class:`Contact` (see
    :func:`contact_slide`), so that figures draw the profiles, not a slot.
    """

    kind: SlideKind
    link: int
    point: str
    guide_link: int
    through: tuple[float, float]
    direction: tuple[float, float]
    contact: Contact | None = None

    @property
    def type(self) -> JointKind:
        """The joint's kind (:mod:`~.joint_kinds`): a block or a pin in a slot, a circle on a
        face or a wheel rolling on one."""
        return kind_of("line", self.kind, self.contact is not None, self.rolling)

    @property
    def label(self) -> str:
        """How messages name the joint."""
        return _joint_label(self, f"link {self.guide_link}")

    @property
    def rolling(self) -> bool:
        """True for a wheel rolling without slip on a face (see :class:`Contact`)."""
        return self.contact is not None and self.contact.rolling


def _joint_label(joint: Arc | Slide, on: str) -> str:
    """"block B of link 4 on link 1", or the contact's own name for a contact's equivalent."""
    if joint.type.contact:
        return joint.contact.label
    return f"{joint.type.noun} {joint.point} of link {joint.link} on {on}"


def contact_slide(contact: Contact, face_link: Link) -> Slide:
    """Replace a circle-on-face contact by its equivalent pin in a slot.

    The circle's centre keeps a constant distance, the radius, from the face, so
    it runs on the parallel to the face offset by the radius towards the circle:
    a ``PIN`` slide of the centre in that line, fixed in the face's link.

    Parameters
    ----------
    contact : Contact
        The contact; its face's ``through`` point must be a point of ``face_link``.
    face_link : Link
        The link that carries the flat face (local coordinates, metres).

    Returns
    -------
    Slide
        ``PIN`` slide of ``contact.circle.centre`` on ``face_link``, with ``contact``
        set.

    Examples
    --------
    A circle of radius 1 below a face along +x through the origin of the frame:

    >>> from tarsim.constructions.model import Link
    >>> c = Contact(Profile(2, centre="C", radius=1.0), Profile(1, through="O", angle=0.0),
    ...             "right")
    >>> s = contact_slide(c, Link(1, (("O", (0.0, 0.0)),)))
    >>> s.point, s.guide_link, s.through, s.direction
    ('C', 1, (0.0, -1.0), (1.0, 0.0))
    """
    circle, face = contact.circle, contact.face
    d = (math.cos(face.angle), math.sin(face.angle))
    r = circle.radius if contact.side == "left" else -circle.radius
    x, y = face_link.local(face.through)
    return Slide(SlideKind.PIN, circle.link, circle.centre, face.link,
                 (x - r * d[1], y + r * d[0]), d, contact)


def contact_arc(contact: Contact) -> Arc:
    """Replace a circle-on-circle contact by its equivalent arc.

    The first circle's centre stays r1 + r2 (``outside``) or |r2 − r1| (``inside``)
    from the second's: a ``PIN`` arc of the first centre about the second.

    Examples
    --------
    >>> c = Contact(Profile(3, centre="R", radius=10.0), Profile(2, centre="C", radius=40.0),
    ...             "outside")
    >>> a = contact_arc(c)
    >>> a.point, a.guide_link, a.centre, a.radius
    ('R', 2, 'C', 50.0)
    """
    first, second = contact.circle, contact.face
    radius = (first.radius + second.radius if contact.side == "outside"
              else abs(second.radius - first.radius))
    return Arc(SlideKind.PIN, first.link, first.centre, second.link, second.centre, radius,
               contact)
