"""A rotor's out-of-balance force and couple, as the books ask them before any mass is
added ("find the out-of-balance force and couple at 600 rpm"): the force polygon of mᵢrᵢ and
the couple polygon of mᵢrᵢlᵢ (lᵢ from the reference plane) are laid head to tail as for a
balance (:mod:`.polygons`), and each closing side, from the last tip back to the pole, is
−R: the resultant left, turned through 180°. Times ω² it is the force (N) or couple (N·m).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .. import geometry as g
from ..narration import Word, phrase
from ..record import Construction, Kind, Panel, Ref
from .polygons import lay_polygon
from .rotor import Rotor

__all__ = ["Unbalance", "draw_unbalance"]


@dataclass
class Unbalance:
    """The drawn polygons: each one's tips from its pole, its closing side, and those that
    close on themselves (nothing left)."""

    construction: Construction
    about: float
    tips: dict[str, list[tuple[str, Ref]]] = field(default_factory=dict)
    closing: dict[str, Ref] = field(default_factory=dict)
    shut: set[str] = field(default_factory=set)

    def resultant(self, which: str) -> tuple[float, float]:
        """R, the resultant left (kg·m for the force, kg·m² for the couple): the closing
        side reversed; zero where the polygon closes on itself."""
        if which in self.shut:
            return (0.0, 0.0)
        seg = self.construction.output(self.closing[which])
        (sx, sy), (ex, ey) = seg.start.xy, seg.end.xy
        return (sx - ex, sy - ey)


def draw_unbalance(rotor: Rotor, about: float) -> Unbalance:
    """Draw the end view's radial lines, the force polygon and, with the masses in planes
    apart, the couple polygon about the plane at ``about``; close each."""
    c = Construction()
    out = Unbalance(c, about)
    c.give("O", g.Point(0.0, 0.0), label="O", phrase=phrase("balance.space"))
    radial = {}
    for m in rotor.masses:
        at = c.give(f"P{m.name}", g.Point(m.radius * math.cos(m.angle),
                                          m.radius * math.sin(m.angle)), label=m.name)
        radial[m.name] = c.draw(f"radial{m.name}", "line_through", "O", at, kind=Kind.LINE)
    kinds = [("force", "fp", Panel.FORCE, phrase("balance.force"),
              [(m.name, m.mass * m.radius, radial[m.name]) for m in rotor.masses],
              [m.mass * m.radius for m in rotor.masses])]
    if len({m.plane for m in rotor.masses}) > 1:
        kinds.append(("couple", "cp", Panel.COUPLE, phrase("balance.couple.about"),
                      [(m.name, m.mass * m.radius * (m.plane - about), radial[m.name])
                       for m in rotor.masses],
                      [m.mass * m.radius * (abs(m.plane) + abs(about)) for m in rotor.masses]))
    for which, tag, panel, said, vectors, reach in kinds:
        out.tips[which] = []
        out.closing[which], shut = lay_polygon(
            c, out.tips[which], tag, panel, vectors, said, Word(which), closing="balance.left",
            closed=phrase("balance.balanced", plane=Word(which)), reach=reach)
        if shut:
            out.shut.add(which)
    return out
