"""Points as the velocity methods walk them: a joint, or a coincident point on a link.

A pin in a slot is two points at one place, A2 on the crank and A4 on the lever
(the notes' coincident-point notation). The component method and the velocity
polygon both find velocities point by point in these terms, so both take this
mixin for who carries a point and which links translate.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..joints import Arc, Slide
from ..model import Mechanism

__all__ = ["Node", "Walk", "taken", "rolling_contacts"]


@dataclass(frozen=True)
class Node:
    """A velocity to find: of point ``point`` itself, or of it taken on link ``link``."""

    point: str
    link: int | None = None

    @property
    def tag(self) -> str:
        """A ref-safe id: ``A`` or ``A@4``."""
        return self.point if self.link is None else f"{self.point}@{self.link}"

    @property
    def name(self) -> str:
        """The textbook name: ``A`` or ``A4``."""
        return self.point if self.link is None else f"{self.point}{self.link}"


class Walk:
    """What a point-by-point velocity method asks of the mechanism.

    The class using it sets ``m`` (the :class:`Mechanism`) and ``nodes`` (every
    :class:`Node` it may find).
    """

    m: Mechanism
    nodes: list[Node]

    def carriers(self, n: Node) -> tuple[int, ...]:
        """The links ``n`` is a point of (a block's point is carried by the block)."""
        if n.link is not None:
            return (n.link,)
        at = set(self.m.links_at(n.point)) | {s.link for s in self.m.slides if s.point == n.point}
        return tuple(sorted(at))

    def zero(self, n: Node) -> bool:
        """True for a point of the frame: its velocity is zero."""
        return 1 in self.carriers(n)

    def members(self, c: int) -> list[Node]:
        """Every node fixed to link ``c``: its points, its blocks' points, its coincident points."""
        out = [Node(p) for p in self.m.link(c).names]
        out += [Node(s.point) for s in self.m.slides if s.link == c]
        return list(dict.fromkeys(out + [n for n in self.nodes if n.link == c]))

    def frame_guide(self, c: int) -> int | None:
        """The slide index if link ``c`` is a block on a frame guide (so it translates)."""
        return next((i for i, s in enumerate(self.m.slides) if s.link == c and s.guide_link == 1
                     and s.type.turns_with_guide), None)


def taken(m: Mechanism, name: str) -> tuple[int, str]:
    """The link a named point is taken on, and the point: ``B`` on its first moving carrier,
    ``A4`` as point A taken on link 4 (a coincident point under a slot).

    Examples
    --------
    >>> from tarsim.constructions.model import Drive, Link
    >>> m = Mechanism((Link(1, (("O", (0, 0)),)), Link(2, (("O", (0, 0)), ("A", (1, 0))))),
    ...               Drive(2, 0.0))
    >>> taken(m, "A"), taken(m, "A2")
    ((2, 'A'), (2, 'A'))
    """
    if name in m.point_names:
        carriers = [c for c in m.links_at(name) if c != 1] + \
                   [s.link for s in m.slides if s.point == name]
        return (carriers[0] if carriers else 1), name
    i = len(name.rstrip("0123456789"))
    return int(name[i:]), name[:i]


def rolling_contacts(m: Mechanism) -> dict[str, Slide | Arc]:
    """Each wheel rolling on the ground or on a fixed circle, by the name its contact point
    goes by: P, or P4 (the wheel's link) where the mechanism has a P of its own or more than
    one wheel. At the instant it is the wheel's point at rest, the centre the wheel turns
    about."""
    wheels = [s for s in (*m.slides, *m.arcs) if s.type.rolling and s.guide_link == 1]
    plain = len(wheels) == 1 and "P" not in m.point_names
    return {("P" if plain else f"P{s.link}"): s for s in wheels}
