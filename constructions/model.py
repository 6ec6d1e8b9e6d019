"""The mechanism model: links, pins, sliders and the input, in SI units.

This is the only thing the compass constructions and the analytic solver share.

A **link** is a rigid body numbered as in the textbooks (the frame is link 1). It
carries named points in *local* coordinates: its first point at the origin and its
second on the +x axis (its *axis*). The frame's points are global coordinates. A
point named on several links is a **pin** joining them (K links at one pin count as
K − 1 joints).

A **slide** puts a point of one link on a straight line fixed in another: the guide
of a slider or the slot of a slotted lever. ``BLOCK`` is a prismatic pair (the
sliding link turns with the guide); ``PIN`` is a pin in a slot (it turns freely, a
two-freedom joint).

A **contact** is direct (sliding-rolling) contact of a circular profile on a flat
face: a cam's circle on a flat-faced follower, or a roller on a flat cam face.
Kinematically it is exactly a pin at the circle's centre running in a slot of the
face's link, parallel to the face and offset from it by the radius (the
equivalent linkage, lecture notes §2.13); :func:`contact_slide` builds that slide,
so assembly and the analytic solver see only a ``PIN`` slide.

A **branch** says which of two assemblies to take for a point: ``left``/``right`` of
the line joining the two centres it is cut from, ``forward``/``backward`` along a
guide, or the solution nearest a point.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from enum import StrEnum

from .errors import InputError

__all__ = [
    "Units",
    "Link",
    "SlideKind",
    "Slide",
    "Profile",
    "Contact",
    "contact_slide",
    "Drive",
    "Mechanism",
    "LENGTH_UNITS",
]

LENGTH_UNITS = {"mm": 1e-3, "cm": 1e-2, "m": 1.0, "in": 0.0254}
"""Length units a file may state, with their size in metres."""


@dataclass(frozen=True, slots=True)
class Units:
    """How the source file states its numbers; figures and text speak in these."""

    length: str = "mm"
    angle: str = "deg"
    angular_velocity: str = "rad/s"

    @property
    def metres(self) -> float:
        """Size of one length unit in metres."""
        return LENGTH_UNITS[self.length]

    def length_text(self, metres: float, digits: int = 4) -> str:
        """Format a length given in metres in the file's unit ("250 mm")."""
        return f"{_fmt(metres / self.metres, digits)} {self.length}"


def _fmt(value: float, digits: int) -> str:
    text = f"{value:.{digits}f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


@dataclass(frozen=True, slots=True)
class Link:
    """A rigid link: its number and its points in local coordinates (metres)."""

    number: int
    points: tuple[tuple[str, tuple[float, float]], ...]
    name: str = ""

    @property
    def names(self) -> tuple[str, ...]:
        """The link's point names, in file order."""
        return tuple(n for n, _ in self.points)

    def local(self, point: str) -> tuple[float, float]:
        """Local coordinates of one of the link's points."""
        for n, xy in self.points:
            if n == point:
                return xy
        raise KeyError(point)

    def span(self, p: str, q: str) -> float:
        """Distance between two of the link's points."""
        (px, py), (qx, qy) = self.local(p), self.local(q)
        return math.hypot(qx - px, qy - py)

    @property
    def label(self) -> str:
        """How messages name the link: "link 3" or "link 3 (coupler)"."""
        return f"link {self.number}" + (f" ({self.name})" if self.name else "")


class SlideKind(StrEnum):
    """A prismatic block, or a pin running in a slot."""

    BLOCK = "block"
    PIN = "pin"


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
    """Direct contact of a circular profile on a flat face.

    ``side`` is ``"left"`` or ``"right"``: the side of the face's direction on
    which the circle lies, so that the equivalent slot is offset to that side.
    """

    circle: Profile
    face: Profile
    side: str

    @property
    def label(self) -> str:
        """How messages name the contact: "contact of link 2 on link 3"."""
        return f"contact of link {self.circle.link} on link {self.face.link}"


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
    def label(self) -> str:
        """How messages name the joint."""
        what = "block" if self.kind is SlideKind.BLOCK else "pin"
        return f"{what} {self.point} of link {self.link} on link {self.guide_link}"


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


@dataclass(frozen=True, slots=True)
class Drive:
    """The input: link ``link`` at axis angle ``angle`` (rad) turning at ω, α (CCW +)."""

    link: int
    angle: float
    omega: float = 0.0
    alpha: float = 0.0
    alpha_given: bool = True


@dataclass(frozen=True)
class Mechanism:
    """A planar mechanism at one input position, in SI units.

    ``branches`` maps a point name to ``"left"``, ``"right"``, ``"forward"``,
    ``"backward"`` or an ``(x, y)`` point (metres) the solution should be nearest.
    """

    links: tuple[Link, ...]
    drive: Drive
    slides: tuple[Slide, ...] = ()
    branches: dict[str, str | tuple[float, float]] = field(default_factory=dict)
    units: Units = Units()
    name: str = ""
    source: str = ""

    def __post_init__(self) -> None:
        numbers = [k.number for k in self.links]
        if 1 not in numbers:
            raise InputError("the mechanism has no frame (link 1)", file=self.source or None)
        if len(set(numbers)) != len(numbers):
            raise InputError("a link number is used twice", file=self.source or None)

    def link(self, number: int) -> Link:
        """Return link ``number``."""
        for k in self.links:
            if k.number == number:
                return k
        raise InputError(f"there is no link {number}; the links are "
                         f"{', '.join(str(n) for n in sorted(self.numbers))}",
                         file=self.source or None)

    @property
    def numbers(self) -> tuple[int, ...]:
        """All link numbers, frame included."""
        return tuple(k.number for k in self.links)

    @property
    def frame(self) -> Link:
        """Link 1."""
        return self.link(1)

    def links_at(self, point: str) -> tuple[int, ...]:
        """Numbers of the links that carry ``point`` (two or more make a pin)."""
        return tuple(k.number for k in self.links if point in k.names)

    @property
    def point_names(self) -> tuple[str, ...]:
        """Every point name, each once, in file order."""
        seen: dict[str, None] = {}
        for k in self.links:
            for n in k.names:
                seen.setdefault(n, None)
        for s in self.slides:
            seen.setdefault(s.point, None)
        return tuple(seen)

    def mobility(self) -> tuple[int, int, int, int]:
        """Grübler's count: ``(dof, n, F1, F2)`` with DOF = 3(n − 1) − 2·F1 − F2.

        A pin on K links is K − 1 joints; a block is one F1 joint, a pin in a slot
        one F2 joint.
        """
        n = len(self.links)
        pins = sum(max(0, len(self.links_at(p)) - 1) for p in self.point_names)
        blocks = sum(1 for s in self.slides if s.kind is SlideKind.BLOCK)
        f2 = sum(1 for s in self.slides if s.kind is SlideKind.PIN)
        f1 = pins + blocks
        return 3 * (n - 1) - 2 * f1 - f2, n, f1, f2

    @property
    def input_speed(self) -> float:
        """|ω|·r of the input link's second point: the known velocity every method starts from."""
        k = self.link(self.drive.link)
        return abs(self.drive.omega) * k.span(k.names[0], k.names[1])

    def with_drive(self, drive: Drive) -> Mechanism:
        """Return the same mechanism at another input position."""
        return Mechanism(self.links, drive, self.slides, dict(self.branches), self.units,
                         self.name, self.source)
