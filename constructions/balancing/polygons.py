"""Balancing by the force and couple polygons, drawn as 001 ch. 7 draws them.

The space diagram's end view gives each mass's radial line from the shaft's centre O.
The force polygon lays the mass–radius products mᵢrᵢ head to tail, each parallel to its
mass's radial line (ω² is common, so it is left out, as the notes' step 2 says); the side
that closes the polygon, from the last tip back to the start, is the balancing mass–radius
product, the resultant turned through 180° (steps 4–5). For two planes A and B (the
reference-plane method), the couple polygon first lays mᵢrᵢlᵢ the same way, lᵢ from A, a
vector reversed where lᵢ < 0; its closing side is (m r l)_B, so (m r)_B is it over l_B,
and the force polygon then takes (m r)_B in with the masses, its closing side (m r)_A.

Both polygons are drawn in kg·m (kg·m² for the couples) as drawing units; the figures
give them a scale.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field

from .. import geometry as g
from ..narration import phrase
from ..record import Construction, Kind, Panel, Ref, Role
from .rotor import Rotor

__all__ = ["Balance", "ROUNDING", "draw_balance", "lay_polygon", "rounding"]

ROUNDING = 8.0 * sys.float_info.epsilon
"""What laying off one vector may leave of rounding, relative to the polygon's perimeter: a
tip is rounded by an ulp or two of the running sum, and its direction (a cosine and a sine
of an angle converted from degrees) by as much again. Random stars of 2 to 8 equal vectors,
which close exactly, leave gaps up to 2·n·ε·Σ|vᵢ|; this allows four times that."""


def rounding(sizes) -> float:
    """The largest gap a polygon of vectors of ``sizes`` leaves by rounding alone: a gap no
    bigger is a polygon that closes on itself.

    A vector made by a difference rounds at the size of what it was made from: a couple
    m·r·(z − a) at m·r·(|z| + |a|), so that is the size to give for it."""
    sizes = [abs(s) for s in sizes]
    return ROUNDING * (len(sizes) + 1) * math.fsum(sizes)


@dataclass
class Balance:
    """The drawn balance: the record, each polygon's tips in order (name, tip), and each
    balancing plane's mass–radius product as drawn (the closing sides)."""

    construction: Construction
    force: list[tuple[str, Ref]] = field(default_factory=list)
    couple: list[tuple[str, Ref]] = field(default_factory=list)
    closing: dict[str, Ref] = field(default_factory=dict)
    """Each balancing plane's closing side, a vector step: (m r) in kg·m for the force
    polygon's, (m r l) in kg·m² for the couple polygon's."""
    radial: dict[str, Ref] = field(default_factory=dict)
    none: set[str] = field(default_factory=set)
    """The balancing planes that need no mass: their polygon closes on itself (to rounding),
    so their product is zero and has no angle."""

    def vector(self, ref: Ref) -> tuple[float, float]:
        """A drawn segment as a vector in the polygon's units."""
        seg = self.construction.output(ref)
        (sx, sy), (ex, ey) = seg.start.xy, seg.end.xy
        return (ex - sx, ey - sy)

    def product(self, plane: str) -> tuple[float, float]:
        """The balancing mass–radius product (kg·m) found for ``plane``: zero for a plane that
        needs no mass."""
        if plane in self.none:
            return (0.0, 0.0)
        return self.vector(self.closing[plane])


def draw_balance(rotor: Rotor) -> Balance:
    """Draw the end view's radial lines, then the couple polygon (two planes) and the force
    polygon, and close them.

    A polygon that closes on itself (its gap within :func:`rounding`) leaves its plane no
    mass to add: the couple polygon when the masses' couples about A cancel (all of them in
    plane A, say), the force polygon when their forces and B's do. That plane's product is
    zero, and the force polygon then lays no vector for B.

    Raises
    ------
    ValueError
        For no balancing plane, or more than two.
    """
    planes = rotor.planes
    if not 1 <= len(planes) <= 2:
        raise ValueError("balancing takes one plane (static) or two (dynamic)")
    c = Construction()
    out = Balance(c)
    o = c.give("O", g.Point(0.0, 0.0), label="O", phrase=phrase("balance.space"))
    for m in rotor.masses:
        at = c.give(f"P{m.name}", g.Point(m.radius * math.cos(m.angle),
                                          m.radius * math.sin(m.angle)), label=m.name)
        out.radial[m.name] = c.draw(f"radial{m.name}", "line_through", o, at, kind=Kind.LINE)
    extra: list[tuple[str, float, Ref]] = []
    if len(planes) == 2:
        a, b = planes
        arms = [(m.name, m.mass * m.radius * (m.plane - a.position), out.radial[m.name])
                for m in rotor.masses]
        point = all(size == 0.0 for _, size, _ in arms)
        closing, closed = lay_polygon(
            c, out.couple, "cp", Panel.COUPLE, arms,
            phrase("balance.couple", a=a.name, b=b.name), b.name,
            closed=phrase("balance.point", a=a.name, plane=b.name) if point else None,
            reach=[m.mass * m.radius * (abs(m.plane) + abs(a.position))
                   for m in rotor.masses])
        out.closing[f"{b.name}·l"] = closing
        if closed:
            out.none.add(b.name)
            out.closing[b.name] = closing
        else:
            lever = b.position - a.position
            # (m r)_B along the couple polygon's closing side, its length over l_B.
            line = c.draw("cp:dir", "line_through", *_ends(c, closing), kind=Kind.LINE,
                          panel=Panel.COUPLE)
            size = math.hypot(*out.vector(closing)) / lever
            extra.append((b.name, size, line))
        target = a
    else:
        target = planes[0]
    products = [(m.name, m.mass * m.radius, out.radial[m.name]) for m in rotor.masses]
    closing, closed = lay_polygon(c, out.force, "fp", Panel.FORCE, products + extra,
                                  phrase("balance.force", plane=target.name), target.name)
    out.closing[target.name] = closing
    if closed:
        out.none.add(target.name)
    if extra:
        out.closing[extra[0][0]] = f"fp:v:{extra[0][0]}"   # (m r)_B as the force polygon drew it
    return out


def _ends(c: Construction, seg: Ref) -> tuple[Ref, Ref]:
    step = c[seg]
    return step.inputs[0], step.inputs[1]


def lay_polygon(c: Construction, tips: list[tuple[str, Ref]], tag: str, panel: Panel,
                vectors: list[tuple[str, float, Ref]], said, plane,
                closing: str = "balance.close", closed=None,
                reach: list[float] | None = None) -> tuple[Ref, bool]:
    """Lay ``vectors`` (name, signed size, the line it is parallel to) head to tail from a
    pole, and close the polygon back to it: the closing side is ``plane``'s balancing
    vector (or, for an engine, what is left unbalanced).

    Returns the closing side, and whether the polygon closes on itself (its last tip back
    on its pole to the :func:`rounding` of the vectors, or of ``reach``, the sizes they
    were made from): then its step says so, as ``closed`` says it if given, and there is no
    side to draw."""
    pole = c.give(f"{tag}:o", g.Point(0.0, 0.0), label="o", panel=panel, phrase=said)
    tip = pole
    for name, size, line in vectors:
        along = c.draw(f"{tag}:par:{name}", "parallel_through", tip, line, kind=Kind.LINE,
                       panel=panel)
        nxt = c.draw(f"{tag}:tip:{name}", "lay_off", tip, along, length=size, label=name,
                     panel=panel)
        c.draw(f"{tag}:v:{name}", "join", tip, nxt, panel=panel)
        tips.append((name, nxt))
        tip = nxt
    gap = math.hypot(*c.output(tip).xy)
    shut = gap <= rounding([size for _, size, _ in vectors] if reach is None else reach)
    if shut:
        said = closed or phrase("balance.closed", plane=plane)
    else:
        said = phrase(closing, plane=plane)
    return c.draw(f"{tag}:close", "join", tip, pole, panel=panel, role=Role.RESULT,
                  phrase=said), shut
