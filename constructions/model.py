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

A **branch** says which of two assemblies to take for a point: ``left``/``right`` of
the line joining the two centres it is cut from, ``forward``/``backward`` along a
guide, or the solution nearest a point.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from functools import cached_property
from enum import StrEnum

from .errors import InputError
from .narration import Quantity, fixed, significant

__all__ = [
    "Units",
    "Link",
    "SlideKind",
    "Slide",
    "Profile",
    "Contact",
    "contact_slide",
    "contact_arc", "GivenRate", "slider_crank",
    "Arc",
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
        return f"{fixed(metres / self.metres, digits)} {self.length}"

    def length_drawn(self, metres: float) -> str:
        """A length (m) as a figure sets it, to drafting precision: four significant
        figures, in the file's unit ("679.1 mm")."""
        return f"{significant(metres / self.metres, 4)} {self.length}"

    def length_brief(self, metres: float) -> str:
        """A length (m) as an error message gives it: six significant figures, in the
        file's unit ("264.575 mm")."""
        return f"{significant(metres / self.metres)} {self.length}"

    def angle_brief(self, rad: float) -> str:
        """An angle (rad) as an error message gives it, in the file's angle unit, to six
        significant figures: "−100.335°", "1.0472 rad"."""
        if self.angle == "rad":
            return f"{significant(rad)} rad"
        return f"{significant(math.degrees(rad))}°"

    def length_said(self, metres: float) -> Quantity:
        """A length (m) as a step says it, in the file's unit: "250 mm"."""
        return Quantity(metres / self.metres, self.length)

    def speed_said(self, v: float) -> Quantity:
        """A speed (m/s) as a step says it: "406.712 mm/s"."""
        return Quantity(v / self.metres, self.length, "/s", "rate")

    def acceleration_said(self, a: float) -> Quantity:
        """An acceleration (m/s²) as a step says it: "535.64 mm/s²"."""
        return Quantity(a / self.metres, self.length, "/s²", "rate")

    def angle_said(self, rad: float) -> Quantity:
        """An angle (rad) as a step says it, in the file's angle unit: "60°" or "1.0472 rad"."""
        if self.angle == "rad":
            return Quantity(rad, "rad", style="fixed")
        return Quantity(math.degrees(rad), "°")


@dataclass(frozen=True, slots=True)
class Link:
    """A rigid link: its number and its points in local coordinates (metres)."""

    number: int
    points: tuple[tuple[str, tuple[float, float]], ...]
    name: str = ""
    _at: dict[str, tuple[float, float]] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        # Looked up by name once per point and per step: a dict keeps a link of many
        # points linear to read and to solve.
        object.__setattr__(self, "_at", dict(self.points))

    @property
    def names(self) -> tuple[str, ...]:
        """The link's point names, in file order."""
        return tuple(self._at)

    def local(self, point: str) -> tuple[float, float]:
        """Local coordinates of one of the link's points."""
        return self._at[point]

    def carries(self, point: str) -> bool:
        """Whether ``point`` is one of the link's points."""
        return point in self._at

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
    def label(self) -> str:
        """How messages name the joint."""
        return _joint_label(self, f"link {self.guide_link}")

    @property
    def rolling(self) -> bool:
        """True for a wheel rolling without slip on a face (see :class:`Contact`)."""
        return self.contact is not None and self.contact.rolling


def _joint_label(joint: Arc | Slide, on: str) -> str:
    """"block B of link 4 on link 1", or the contact's own name for a contact's equivalent."""
    if joint.contact is not None:
        return joint.contact.label
    what = "block" if joint.kind is SlideKind.BLOCK else "pin"
    return f"{what} {joint.point} of link {joint.link} on {on}"


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


@dataclass(frozen=True, slots=True)
class Drive:
    """The input: link ``link`` at axis angle ``angle`` (rad) turning at ω, α (CCW +)."""

    link: int
    angle: float
    omega: float = 0.0
    alpha: float = 0.0
    alpha_given: bool = True


@dataclass(frozen=True)
class GivenRate:
    """An input given, as textbooks often give it, by another member's motion than the
    input link's: the speed of ``target`` (a point on a frame guide, m/s along the guide's
    direction) or the ω of link ``target`` (rad/s, CCW +), with its rate of change
    (``second``: m/s², rad/s²) when ``second_given``. The input link's ω and α follow from
    it (:mod:`tarsim.exercises.given_rate`)."""

    kind: str
    target: str | int
    value: float
    second: float = 0.0
    second_given: bool = False


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
    arcs: tuple[Arc, ...] = ()
    scale: float | None = None
    """The space scale the exercise states, file length units per paper cm ("1 cm = 4 cm"
    is 4.0); None lets the figures choose."""
    given: GivenRate | None = None
    """The input's motion as the exercise gives it, when not as the input link's ω."""
    origin: tuple[float, float] = (0.0, 0.0)
    """Where the file's axes put this model's (0, 0), in metres: a file is read about its
    frame's first point, so that its numbers do not depend on how far from the file's origin
    it stands (:meth:`in_file_axes`)."""

    def __post_init__(self) -> None:
        numbers = [k.number for k in self.links]
        if 1 not in numbers:
            raise InputError("the mechanism has no frame (link 1)", file=self.source or None)
        if len(set(numbers)) != len(numbers):
            raise InputError("a link number is used twice", file=self.source or None)
        for a in self.rolling_arcs:
            arm = next((k for k in self.links if k.number not in (a.link, a.guide_link)
                        and a.point in k.names and a.centre in k.names), None)
            if arm is not None and not math.isclose(arm.span(a.point, a.centre), a.radius,
                                                    rel_tol=1e-9):
                raise InputError(f"link {arm.number} holds {a.point} and {a.centre} "
                                 f"{self.units.length_brief(arm.span(a.point, a.centre))} apart, "
                                 f"but the circles of the {a.contact.label} touch at "
                                 f"{self.units.length_brief(a.radius)}",
                                 file=self.source or None)

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
        return self._carriers.get(point, ())

    @cached_property
    def pin_pairs(self) -> tuple[tuple[str, int, int], ...]:
        """Every turning pair as its force is named, F_{lower}{other}: (point, the
        lowest-numbered link at the point, another link there)."""
        out = []
        for point in self.point_names:
            carriers = sorted(self.links_at(point))
            out += [(point, carriers[0], other) for other in carriers[1:]]
        return tuple(out)

    @cached_property
    def _carriers(self) -> dict[str, tuple[int, ...]]:
        out: dict[str, tuple[int, ...]] = {}
        for k in self.links:
            for n in k.names:
                out[n] = out.get(n, ()) + (k.number,)
        return out

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

        A pin on K links is K − 1 joints; a block and a rolling contact are one F1
        joint each; a pin in a straight or curved slot, a sliding-rolling contact,
        and a rolling contact of circles whose centres an arm holds (a gear pair), one
        F2 joint. A block on a curved guide is counted by its pin.
        """
        n = len(self.links)
        pins = sum(max(0, len(self.links_at(p)) - 1) for p in self.point_names)
        blocks = sum(1 for s in self.slides if s.kind is SlideKind.BLOCK or s.rolling)
        blocks += sum(1 for a in self.pin_arcs if a.rolling)
        f2 = sum(1 for s in self.slides if s.kind is SlideKind.PIN and not s.rolling)
        f2 += sum(1 for a in self.pin_arcs if not a.rolling)
        f2 += sum(1 for a in self.rolling_arcs if self.held(a))
        f1 = pins + blocks
        return 3 * (n - 1) - 2 * f1 - f2, n, f1, f2

    @property
    def pin_arcs(self) -> tuple[Arc, ...]:
        """The arcs that constrain a distance: a curved block is already its pin at the
        centre, and a wheel rolling on a circle whose centre an arm already holds at the
        distance the circles touch at adds only its no-slip (:meth:`held`)."""
        return tuple(a for a in self.arcs if a.kind is SlideKind.PIN and not self.held(a))

    @property
    def rolling_arcs(self) -> tuple[Arc, ...]:
        """Every wheel rolling on a circle, held by an arm or not."""
        return tuple(a for a in self.arcs if a.rolling)

    def held(self, a: Arc) -> bool:
        """True for a rolling contact of circles whose centres a third link (an arm, a
        planet carrier) carries both of: only its no-slip constrains, a higher pair."""
        return a.rolling and any(k.number not in (a.link, a.guide_link) and a.point in k.names
                                 and a.centre in k.names for k in self.links)

    @property
    def slotted(self) -> tuple[Slide | Arc, ...]:
        """The joints where a point runs in a slot, straight or curved, of a moving link that
        does not carry it: there the point has a coincident point on the slotted link, and
        a Coriolis component."""
        return tuple(s for s in (*self.slides, *self.pin_arcs)
                     if s.guide_link != 1 and s.point not in self.link(s.guide_link).names)

    @cached_property
    def rolling_input(self) -> Slide | None:
        """The rolling contact on the frame of an input that is a wheel, else None. Such a
        wheel turns, at the instant, about its contact point, and its angle says how far
        it has rolled; its centre is the point every method starts from."""
        return next((s for s in self.slides if s.rolling and s.guide_link == 1
                     and s.link == self.drive.link), None)

    @property
    def input_radius(self) -> float:
        """The radius r of the input's known point: the crank's length to its second point, or
        the rolling wheel's radius (centre to contact point)."""
        s = self.rolling_input
        if s is not None:
            return s.contact.circle.radius
        k = self.link(self.drive.link)
        return k.span(k.names[0], k.names[1])

    @property
    def input_speed(self) -> float:
        """|ω|·r of the input's known point: the velocity every method starts from."""
        return abs(self.drive.omega) * self.input_radius

    @property
    def input_acceleration(self) -> float:
        """r·√(ω⁴ + α²): the acceleration the polygon starts from (the crank pin's; for a
        rolling wheel, its contact point's and its centre's together)."""
        return math.hypot(self.drive.omega ** 2, self.drive.alpha) * self.input_radius

    def with_drive(self, drive: Drive) -> Mechanism:
        """Return the same mechanism at another input position."""
        return Mechanism(self.links, drive, self.slides, dict(self.branches), self.units,
                         self.name, self.source, self.arcs, self.scale, origin=self.origin)

    def moved(self, dx: float, dy: float) -> Mechanism:
        """Return the same mechanism moved by ``(dx, dy)`` (m) in its axes: the frame's
        points and guides and the points a branch is to be near; ``origin`` moves the other
        way, so :meth:`in_file_axes` still says where the file put each point.

        Examples
        --------
        >>> m = Mechanism((Link(1, (("O2", (0.0, 0.0)), ("O4", (0.5, 0.0)))),), Drive(1, 0.0))
        >>> far = m.moved(1024.0, 8.0)
        >>> far.frame.points, far.origin
        ((('O2', (1024.0, 8.0)), ('O4', (1024.5, 8.0))), (-1024.0, -8.0))
        >>> far.in_file_axes((1024.5, 8.0))
        (0.5, 0.0)
        """
        def moved(xy: tuple[float, float]) -> tuple[float, float]:
            return (xy[0] + dx + 0.0, xy[1] + dy + 0.0)

        frame = Link(1, tuple((n, moved(xy)) for n, xy in self.frame.points), self.frame.name)
        links = tuple(frame if k.number == 1 else k for k in self.links)
        slides = tuple(replace(s, through=moved(s.through)) if s.guide_link == 1 else s
                       for s in self.slides)
        branches = {n: b if isinstance(b, str) else moved(b) for n, b in self.branches.items()}
        return replace(self, links=links, slides=slides, branches=branches,
                       origin=(self.origin[0] - dx, self.origin[1] - dy))

    def in_file_axes(self, xy: tuple[float, float]) -> tuple[float, float]:
        """A point of this model, ``(x, y)`` in metres, in the axes of the file it was read
        from."""
        return (xy[0] + self.origin[0], xy[1] + self.origin[1])


def slider_crank(m: Mechanism) -> tuple[str, str, str, int] | None:
    """The parts of a slider-crank: the crank's pivot, the crank pin, the piston pin, and the
    index of the piston's frame guide among the slides; None if the input crank drives no
    two-point rod to a block on a frame guide. Klein's construction and the slider-crank's
    transmission angle are drawn on them."""
    d = m.drive.link
    crank = m.link(d)
    for i, s in enumerate(m.slides):
        if s.guide_link != 1 or s.kind is not SlideKind.BLOCK or s.contact is not None:
            continue
        for k in m.links:
            if k.number in (1, d, s.link) or s.point not in k.names or len(k.names) != 2:
                continue
            pin = next(n for n in k.names if n != s.point)
            if pin in crank.names and pin != crank.names[0]:
                return crank.names[0], pin, s.point, i
    return None
