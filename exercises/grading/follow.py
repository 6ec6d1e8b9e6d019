"""Follow-through: a tip drawn rightly from an earlier wrong one.

A polygon is a chain of drafting acts (:mod:`tarsim.constructions.record`): each tip is cut
from lines drawn through tips found before it. When a student draws one tip wrong, every
tip after it is built on the wrong one, and a course marks those by what the student did
with them, not by where the true tips lie. So the acts are done again (:func:`replayed`),
each tip the student drew wrong taken where the student drew it, and a later tip that
lands where the redone acts put it "follows from an earlier error".
"""

from __future__ import annotations

import math

from tarsim.constructions import geometry as g
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.record import VERBS

__all__ = ["Replay", "unplace", "reversed_coriolis"]

Vec = tuple[float, float]


def unplace(frame, p: Vec) -> Vec:
    """The world vector (from ``frame.origin``) that ``frame`` puts at paper point ``p``: the
    inverse of ``frame.place``."""
    c, s = math.cos(frame.turn), math.sin(frame.turn)
    dx, dy = p[0] - frame.at[0], p[1] - frame.at[1]
    u, v = c * dx + s * dy, -s * dx + c * dy
    return (frame.origin[0] + u / frame.scale, frame.origin[1] - v / (frame.hand * frame.scale))


class Replay:
    """A polygon's acts redone in drawing order, with the tips a student drew wrong moved to
    where they were drawn.

    ``polygon`` is tarsim's drawn polygon (:class:`~tarsim.constructions.linkages.polygon_walk.
    Polygon`), ``frame`` how the sheet lays its vectors (SI, from the pole) on paper.
    """

    def __init__(self, polygon, frame):
        self.polygon, self.frame = polygon, frame
        c = polygon.construction
        self.order = {ref: k for k, ref in enumerate(c.steps)}
        self.pole = c.output(polygon.pole).xy
        self.moved: dict[str, object] = {}
        self._rests: dict[str, bool] = {}

    def tips_in_order(self, names: dict[str, str]) -> list[str]:
        """``names`` (a label's tip → the polygon's tip key) in the order they were drawn."""
        return sorted(names, key=lambda n: self.order.get(self.polygon.tip(names[n]), 0))

    def move(self, key: str, paper: Vec) -> None:
        """Take the tip ``key`` where the student drew it, at ``paper``."""
        w = unplace(self.frame, paper)
        s = self.polygon.scale
        self.moved[self.polygon.tip(key)] = g.Point(self.pole[0] + w[0] * s,
                                                   self.pole[1] + w[1] * s)
        self._rests = {}

    def reverse(self, start: str, end: str) -> None:
        """Draw the vector of steps ``start`` → ``end`` (a Coriolis component) the other
        way."""
        c = self.polygon.construction
        (sx, sy), (ex, ey) = c.output(start).xy, c.output(end).xy
        self.moved[end] = g.Point(2.0 * sx - ex, 2.0 * sy - ey)
        self._rests = {}

    def directly(self, key: str) -> bool:
        """True if the tip ``key`` rests on a moved step through no other tip: the first
        tip a moved step changes."""
        c, tip = self.polygon.construction, self.polygon.tip(key)
        tips = set(self.polygon.tips.values()) - {tip}
        seen, stack = set(), [tip]
        while stack:
            r = stack.pop()
            if r in self.moved:
                return True
            if r not in seen and r not in tips:
                seen.add(r)
                stack.extend(c[r].inputs)
        return False

    def where(self, key: str) -> Vec | None:
        """Where the redone acts put the tip ``key`` on paper; None if no tip it rests on
        was moved, or the acts cannot be done again from the moved tips (two lines that no
        longer cross)."""
        if not self.moved:
            return None
        c = self.polygon.construction
        target = self.polygon.tip(key)
        done: dict[str, object] = {}

        def output(ref: str):
            if ref in self.moved:
                return self.moved[ref]
            if ref in done:
                return done[ref]
            step = c[ref]
            if step.verb == "given" or not self._rests_on_moved(ref):
                return step.output
            inputs = [output(r) for r in step.inputs]
            params = dict(step.params)
            if step.verb == "lay_off" and isinstance(inputs[1], g.Point):
                params["length"] *= _stretch(c, step, inputs)
            done[ref] = VERBS[step.verb](*inputs, **params)[0]
            return done[ref]
        if not self._rests_on_moved(target):
            return None
        try:
            p = output(target)
        except (TarsimError, ArithmeticError, ValueError):
            return None
        if not isinstance(p, g.Point) or p.is_at_infinity:
            return None
        s = self.polygon.scale
        return self.frame.place(((p.xy[0] - self.pole[0]) / s, (p.xy[1] - self.pole[1]) / s))

    def _rests_on_moved(self, ref: str) -> bool:
        """True if a moved tip is among the acts ``ref`` was drawn from."""
        if ref not in self._rests:
            self._rests[ref] = ref in self.moved or any(
                self._rests_on_moved(r) for r in self.polygon.construction[ref].inputs)
        return self._rests[ref]


def _stretch(c, step, inputs) -> float:
    """How much a length laid off from a point towards another grows when those points are
    redrawn: a tip laid off towards a tip is its image (the point of a link on the line
    of two others), so it keeps its share of their distance."""
    old = [c.output(r) for r in step.inputs]
    before = math.dist(old[0].xy, old[1].xy)
    after = math.dist(inputs[0].xy, inputs[1].xy)
    return after / before if before > 0.0 else 1.0


def reversed_coriolis(polygon, frame, keys: dict[str, str]) -> dict[str, tuple[Vec, str]]:
    """For each tip a Coriolis component is drawn into directly, where it lands with that
    component drawn the other way, and the component's point: the classic error."""
    out = {}
    for point, (start, end, _) in polygon.coriolis.items():
        replay = Replay(polygon, frame)
        replay.reverse(start, end)
        for name, key in keys.items():
            if replay.directly(key):
                at = replay.where(key)
                if at is not None:
                    out[name] = (at, point)
    return out
