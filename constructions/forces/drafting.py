"""The drafting every force polygon shares: a :class:`Drafter` that lays forces head to tail
at the force scale and closes a polygon on two lines of known direction, and the plane
statics the polygons are worked with (sums, moments about a point, a pin force named the
textbooks' way, the side a friction-leaned push comes from).

A friction-leaned push has two candidate lines, one for each side it may come from; the
side is the one whose line closes the polygon with a push from that same side, the check a
draftsman makes of the side assumed (:func:`push_side`, :func:`push_sides`).
"""

from __future__ import annotations

import math

from .. import geometry as g
from ..loads import leaning
from ..narration import Number, Quantity, Word, phrase
from ..record import Construction, Kind, Panel, Ref, Role

__all__ = ["Drafter", "as_named", "as_said", "friction_angle", "moment", "push_side",
           "push_sides", "vector_sum"]

Vec = tuple[float, float]


class Drafter:
    """Lays vectors head to tail in the FORCE panel at a force scale."""

    def __init__(self, c: Construction, scale: float):
        self.c, self.scale, self.count = c, scale, 0

    def vector(self, name: str, tip: Ref, f: Vec, said=None, label: str = "") -> Ref:
        """From ``tip`` lay off ``f`` (N): carried with dividers to the tip."""
        self.count += 1
        base = self.c.give(f"force:o:{self.count}", g.Point(0.0, 0.0), label="",
                           panel=Panel.FORCE)
        head = self.c.give(f"force:h:{self.count}", g.Point(f[0] * self.scale,
                                                            f[1] * self.scale),
                           label="", panel=Panel.FORCE)
        nxt = self.c.draw(f"force:{name}", "transfer", tip, base, head, panel=Panel.FORCE)
        self.c.draw(f"force:v:{name}", "join", tip, nxt, panel=Panel.FORCE, label=label,
                    phrase=said or phrase("force.lay", label=label or "the load",
                                          size=as_said(math.hypot(*f), "N")))
        return nxt

    def loads(self, link: int, tip: Ref, loads) -> Ref:
        """Lay off each load of ``link`` with a force, head to tail from ``tip``."""
        for n, (_, f, _, name) in enumerate(loads):
            if f != (0.0, 0.0):
                tip = self.vector(f"{link}:{n}", tip, f, label=name)
        return tip

    def square_to(self, through: Ref, direction: Vec, name: str) -> Ref:
        """The line through ``through`` square to a frame guide of ``direction``: the
        guide's push, which has no part along it."""
        guide = self.c.give(f"force:guide:{name}", g.Line(-direction[1], direction[0], 0.0),
                            label="", panel=Panel.FORCE)
        return self.c.draw(f"force:line:{name}", "perpendicular_through", through, guide,
                           kind=Kind.LINE, panel=Panel.FORCE)

    def leaning(self, through: Ref, guide: Vec, side: float, slip, name: str = "N",
                what=None) -> Ref:
        """The line through ``through`` of a frame guide's push with friction: square to
        the guide, leaned by the friction angle against the sliding, for a push from
        ``side``."""
        u = leaning((-guide[1], guide[0]), slip[1], slip[0], side)
        n = math.hypot(*u)
        raw = self.c.give(f"force:guide:{name}", g.Line(-u[1] / n, u[0] / n, 0.0), label="",
                          panel=Panel.FORCE)
        # A guide at rest pushes square to itself, as its resting step says.
        said = None if slip[1] == (0.0, 0.0) else phrase(
            "force.leaning", what=what or phrase("force.the_guide"), phi=friction_angle(slip),
            side=Word("the guide's left (a quarter turn counter-clockwise from its direction)"
                      if side > 0 else
                      "the guide's right (a quarter turn clockwise from its direction)"))
        return self.c.draw(f"force:line:{name}", "parallel_through", through, raw,
                           kind=Kind.LINE, panel=Panel.FORCE, phrase=said)

    def close(self, tip: Ref, far: Ref, start: Ref, near: Ref, said, far_name: str,
              near_name: str) -> tuple[Ref, Ref, Ref]:
        """Close a polygon from ``start`` to ``tip`` with two forces of known lines: a
        parallel to ``far`` through its end, to ``near`` through its start; returns where
        they cross and the two forces drawn."""
        n = self.count = self.count + 1
        along_end = self.c.draw(f"force:n:end{n}", "parallel_through", tip, far,
                                kind=Kind.LINE, panel=Panel.FORCE)
        along_start = self.c.draw(f"force:n:start{n}", "parallel_through", start, near,
                                  kind=Kind.LINE, panel=Panel.FORCE)
        cross = self.c.draw(f"force:X{n}", "intersect_lines", along_end, along_start,
                            label="x", panel=Panel.FORCE, phrase=said)
        return (cross, self.join(f"far{n}", tip, cross, label=far_name),
                self.join(f"near{n}", cross, start, label=near_name))

    def join(self, name: str, a: Ref, b: Ref, role: Role = Role.CONSTRUCTION,
             label: str = "") -> Ref:
        """Join ``a`` to ``b``: a force of the polygon drawn as the segment between them."""
        return self.c.draw(f"force:v:{name}", "join", a, b, panel=Panel.FORCE, role=role,
                           label=label)

    def read(self, seg: Ref) -> Vec:
        """The force (N) a drawn segment stands for, read back at the force scale."""
        s = self.c.output(seg)
        (ax, ay), (bx, by) = s.start.xy, s.end.xy
        return ((bx - ax) / self.scale, (by - ay) / self.scale)


def as_said(value: float, unit: str, spec: str = ".4g") -> tuple[Number, str]:
    """A number and its unit as a step says them, the number in the language's digits."""
    return (Number(value, spec), unit)


def friction_angle(slip):
    """φ = atan μ as a step says it."""
    return None if slip is None else Quantity(math.degrees(math.atan(slip[0])), "°",
                                              style="rate")


def vector_sum(vectors) -> Vec:
    """The sum of ``vectors``, each coordinate summed exactly (math.fsum)."""
    vs = list(vectors)
    return (math.fsum(v[0] for v in vs), math.fsum(v[1] for v in vs))


def moment(about: Vec, loads) -> float:
    """Σ (p − about) × F + Σ M of ``loads`` (where, force, couple, name)."""
    return math.fsum((p[0] - about[0]) * f[1] - (p[1] - about[1]) * f[0] + m
                     for p, f, m, _ in loads)


def as_named(f: Vec, forward: bool) -> Vec:
    """A pin force named F_lo hi (of the lower-numbered link on the higher): ``f`` is of the
    first-named link on the second when ``forward``, else turned round."""
    return f if forward else (-f[0], -f[1])


def push_side(laid: Vec, guide: Vec, slip, other: Vec | None, other_at=None) -> float:
    """Which side a guide's push comes from when friction leans it: the side whose leaned
    line, with the polygon's other closing line (along ``other``, or ``other_at(u)`` for a
    line that hangs on u), closes the ``laid`` loads with a push from that same side — the
    check a draftsman makes of the side assumed. The frictionless side when neither holds
    (a push of nothing)."""
    mu, sliding = slip
    normal = (-guide[1], guide[0])
    for side in (1.0, -1.0):
        u = leaning(normal, sliding, mu, side)
        w = other if other_at is None else other_at(u)
        parts = None if w is None else _closing(laid, u, w)
        if parts is not None and parts[0] * side >= 0.0:
            return side
    return 1.0


def push_sides(laid: Vec, first, second, mu: float) -> tuple[float, float]:
    """The sides two leaning pushes come from, each (guide direction, unit sliding): the
    pair whose leaned lines close the ``laid`` loads with pushes from those same sides
    (both square to their guides, the first pair, when none holds)."""
    n1, n2 = (-first[0][1], first[0][0]), (-second[0][1], second[0][0])
    for s1 in (1.0, -1.0):
        for s2 in (1.0, -1.0):
            parts = _closing(laid, leaning(n1, first[1], mu, s1),
                             leaning(n2, second[1], mu, s2))
            if parts is not None and parts[0] * s1 >= 0.0 and parts[1] * s2 >= 0.0:
                return s1, s2
    return 1.0, 1.0


def _closing(laid: Vec, u: Vec, w: Vec) -> tuple[float, float] | None:
    """The multiples a, b with laid + a·u + b·w = 0: what two lines of known direction close
    a polygon with; None when they run parallel."""
    det = u[0] * w[1] - u[1] * w[0]
    if det == 0.0:
        return None
    return ((-laid[0] * w[1] + laid[1] * w[0]) / det, (-u[0] * laid[1] + u[1] * laid[0]) / det)
