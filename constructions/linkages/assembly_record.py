"""The record of a mechanism drawn at one position: :class:`Assembly`.

Position by compass (:func:`.assembly.assemble`) draws the mechanism into it; every
method then draws its own construction on top (the centres, the velocities, the
polygons), so one record holds the whole solution of a position and each figure is a
slice of it. Besides its steps it knows which step locates each point
(:func:`point_ref`), guide and axis, where each contact's profiles touch, and which
points stand at a change point (:attr:`Assembly.meetings`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .. import geometry as g
from .coincident import rolling_contacts
from ..joints import Arc, Slide
from ..model import Mechanism
from ..narration import phrase
from ..record import VERBS, Construction, Ref

__all__ = ["Assembly", "point_ref", "MEETING"]

MEETING = 1e-7
"""A cut whose own conditioning (the sine of the angle it crosses at) is below this
touches within rounding: a tangency met through rounding keeps about √eps ≈ 1.5e-8."""

_CUTS = ("intersect_circles", "intersect_line_circle")
"""The acts that choose one of two places: where the two may coincide."""


def point_ref(name: str) -> Ref:
    """The id of the step that locates point ``name``."""
    return f"P:{name}"


@dataclass
class Assembly(Construction):
    """The record of a mechanism drawn at one position: every drafting act, and which step
    locates each point, guide and axis.

    Position by compass draws the mechanism into it; every method then draws its own
    construction on top (the centres, the velocities, the polygons), so one record
    holds the whole solution of a position and each figure is a slice of it.
    """

    mechanism: Mechanism | None = None
    points: dict[str, Ref] = field(default_factory=dict)
    guides: dict[int, Ref] = field(default_factory=dict)
    axes: dict[int, Ref] = field(default_factory=dict)
    position_steps: frozenset[Ref] = frozenset()
    """The steps that located the mechanism: the kinematic diagram draws them, so a figure's
    slice stops there (:func:`~.record.slice`'s ``base``)."""
    contacts: dict[Slide | Arc, Ref] = field(default_factory=dict)
    """The contact point P of each joint that stands for a direct contact (a cam's circle
    on a flat face or on a roller): where the diagram draws the two profiles touching."""

    def input_arm(self) -> tuple[str, Ref, str, Ref]:
        """The input's centre of rotation and its known point, each by name and step, and the
        line from the one to the other: a crank's pivot and second point, along its axis;
        for a wheel rolling on the frame, its contact point (at rest at the instant) and
        its centre, joined here once."""
        m = self.mechanism
        d, s = m.drive, m.rolling_input
        k = m.link(d.link)
        if s is None:
            return k.names[0], self.points[k.names[0]], k.names[1], self.axes[d.link]
        contact = next(n for n, t in rolling_contacts(m).items() if t is s)
        ref = f"arm:{d.link}"
        if ref not in self:
            self.draw(ref, "line_through", self.contacts[s], self.points[s.point],
                      phrase=phrase("position.wheel_arm", contact=contact, point=s.point,
                                    link=d.link))
        return contact, self.contacts[s], s.point, ref

    def point(self, name: str) -> g.Point:
        """The located point ``name``."""
        return self.output(self.points[name])

    def xy(self, name: str) -> tuple[float, float]:
        """Cartesian coordinates (metres) of point ``name``."""
        return self.point(name).xy

    @property
    def size(self) -> float:
        """The mechanism's size at this position: its largest distance between two points (m).

        Tolerances for "the same point" or "on this line" are taken relative to it.
        """
        xy = [self.xy(n) for n in self.mechanism.point_names]
        return max([1e-300] + [math.dist(p, q) for p in xy for q in xy])

    def guide(self, index: int) -> g.Line:
        """The global line of slide ``index`` (``mechanism.slides[index]``)."""
        return self.output(self.guides[index])

    @property
    def meetings(self) -> tuple[str, ...]:
        """The points at a change point: where their two places coincide (their arcs, or arc
        and guide, only touch) and the linkage may go on in either assembly.

        Touching alone is a dead point of the input: the arc's centre C is driven across
        the line of the touch, so the input stops there. Both assemblies can move on only
        if C's motion runs along the touch, which, for C carried by a link pinned to the
        frame at P, is when P lies on the line of the touch (for a four-bar, all four
        pivots in line).
        """
        out = []
        for name in self.mechanism.point_names:
            step = self[self.points[name]]
            if step.verb in _CUTS:
                args = [self.output(r) for r in step.inputs]
                if (VERBS[step.verb](*args, **dict(step.params))[1] <= MEETING
                        and self._free_along_touch(name, step)):
                    out.append(name)
        return tuple(out)

    def _free_along_touch(self, name: str, step) -> bool:
        """True if a moving centre of an arc in ``step`` (the cut that found ``name``) runs
        along the line of the touch: a frame pivot of its link lies on that line."""
        m = self.mechanism
        loci = [self.output(r) for r in step.inputs]
        circles = [c for c in loci if isinstance(c, g.Circle)]
        if len(circles) == 2:
            line, _ = g.line_through(circles[0].centre, circles[1].centre)
        elif circles:
            guide = next(x for x in loci if isinstance(x, g.Line))
            line, _ = g.perpendicular_through(circles[0].centre, guide)
        for circle in circles:
            centre = next((n for n, r in self.points.items()
                           if n != name and self.output(r) == circle.centre), None)
            if centre is None or m.frame.carries(centre):
                continue
            pivots = [p for k in m.links_at(centre) if not m.link(k).carries(name)
                      for p in m.link(k).names if m.frame.carries(p)]
            if any(abs(line.signed_distance(self.output(self.points[p])))
                   <= MEETING * circle.radius for p in pivots):
                return True
        return False
