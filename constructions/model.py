"""The mechanism model: links, pins and the input, with the joints between them, in SI units.

This is the only thing the compass constructions and the analytic solver share.

A **link** is a rigid body numbered as in the textbooks (the frame is link 1). It
carries named points in *local* coordinates: its first point at the origin and its
second on the +x axis (its *axis*). The frame's points are global coordinates. A
point named on several links is a **pin** joining them (K links at one pin count as
K − 1 joints).

The other joints, a **slide**, an **arc** and a **contact**, are in
:mod:`~tarsim.constructions.joints`, and their kinds in :mod:`~tarsim.constructions.joint_kinds`;
the units the file states its numbers in are in
:mod:`~tarsim.constructions.units`.

A **branch** says which of two assemblies to take for a point: ``left``/``right`` of
the line joining the two centres it is cut from, ``forward``/``backward`` along a
guide, or the solution nearest a point.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from functools import cached_property

from .errors import InputError
from .joints import Arc, Slide
from .units import Units

__all__ = ["Link", "Drive", "GivenRate", "Mechanism", "slider_crank"]


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
    input link's: the speed of ``target`` (kind "speed": a point on a frame guide, m/s along
    the guide's direction; kind "input_point": a point of the input link, m/s along its
    circle about the frame pivot, CCW +) or the ω of link ``target`` (kind "omega": rad/s,
    CCW +), with its rate of change (``second``: m/s², rad/s²; of a point of the input
    link, its tangential part) when ``second_given``. The input link's ω and α follow from
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
    angle_from: tuple[float, float, str] | None = None
    """The dead centre the file turns its input angles from, where [input] names one
    ("t.d.c."): its direction (degrees from +x), the sense the crank turns (+1 CCW, −1 CW) and
    its name, so that every angle of the file (its [ask] at, --angle) is read as [input]'s."""

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

        A pin on K links is K − 1 joints; every other joint is an F1 joint if it adds two
        equations (a block, a rolling contact) and an F2 joint if it adds one (a pin in a
        straight or curved slot, a sliding-rolling contact, a rolling contact of circles
        whose centres an arm holds: a gear pair). A block on a curved guide is counted by
        its pin (:meth:`constraints`).
        """
        n = len(self.links)
        pins = sum(max(0, len(self.links_at(p)) - 1) for p in self.point_names)
        counts = [self.constraints(j) for j in (*self.slides, *self.arcs)]
        f1, f2 = pins + counts.count(2), counts.count(1)
        return 3 * (n - 1) - 2 * f1 - f2, n, f1, f2

    def constraints(self, joint: Slide | Arc) -> int:
        """How many loop equations ``joint`` adds: its kind's, less the distance an arm
        already holds for a wheel rolling round a circle (:meth:`held`)."""
        return joint.type.constraints - (1 if self.held(joint) else 0)

    @property
    def pin_arcs(self) -> tuple[Arc, ...]:
        """The arcs that constrain a distance: a curved block is already its pin at the
        centre, and a wheel rolling on a circle whose centre an arm already holds at the
        distance the circles touch at adds only its no-slip (:meth:`held`)."""
        return tuple(a for a in self.arcs if not a.type.stands_as_pin and not self.held(a))

    @property
    def rolling_arcs(self) -> tuple[Arc, ...]:
        """Every wheel rolling on a circle, held by an arm or not."""
        return tuple(a for a in self.arcs if a.type.rolling)

    def held(self, joint: Slide | Arc) -> bool:
        """True for a rolling contact of circles whose centres a third link (an arm, a
        planet carrier) carries both of: only its no-slip constrains, a higher pair."""
        return joint in self._held

    @cached_property
    def _held(self) -> tuple[Arc, ...]:
        """The wheels rolling round a circle that an arm holds (:meth:`held`)."""
        return tuple(a for a in self.rolling_arcs if any(
            k.number not in (a.link, a.guide_link) and a.point in k.names
            and a.centre in k.names for k in self.links))

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
        return next((s for s in self.slides if s.type.rolling and s.guide_link == 1
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
    rod (which may carry other points) to a block on a frame guide. Klein's construction
    and the slider-crank's transmission angle are drawn on them."""
    d = m.drive.link
    crank = m.link(d)
    for i, s in enumerate(m.slides):
        if s.guide_link != 1 or s.type.key != "block":
            continue
        for k in m.links:
            if k.number in (1, d, s.link) or s.point not in k.names:
                continue
            pins = [n for n in k.names if n != s.point and n in crank.names[1:]]
            if pins:
                return crank.names[0], pins[0], s.point, i
    return None
