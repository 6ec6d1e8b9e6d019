"""An in-line engine's primary and secondary forces and couples, by their polygons.

Each cylinder's reciprocating mass m (its own, where they differ) at crank radius r gives
a primary force m·ω²·r·cos θ along the line of stroke: the x-component of a vector m·r·ω²
turning with the crank. Its
secondary force m·ω²·r·cos 2θ / n is the component of one turning at twice the speed, a
crank at 2θ of size m·r/n (the direct crank). So the primary forces cancel at every angle
when the vectors m·r along the cranks close their polygon, and the primary couples when
m·r·lᵢ do (lᵢ from the reference plane, a vector reversed where lᵢ < 0); the secondary
ones likewise with the cranks at 2θᵢ. Each polygon is drawn as the rotor's are, and its
closing side, if any, is what is left unbalanced.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .. import geometry as g
from ..narration import Word, phrase
from ..record import Construction, Kind, Panel, Ref
from .polygons import lay_polygon
from .rotor import Engine

__all__ = ["EnginePolygons", "draw_engine", "engine_kinds"]

KINDS = ("primary force", "primary couple", "secondary force", "secondary couple")


@dataclass
class EnginePolygons:
    """The four polygons' records: tips in order and closing sides, by kind."""

    construction: Construction
    tips: dict[str, list[tuple[str, Ref]]] = field(default_factory=dict)
    closing: dict[str, Ref] = field(default_factory=dict)
    balanced: set[str] = field(default_factory=set)
    """The kinds whose polygon closes on itself (to rounding): nothing is left of them."""

    def left(self, kind: str) -> float:
        """What the closing side leaves unbalanced (kg·m, or kg·m² for a couple): zero for a
        polygon that closes on itself."""
        if kind in self.balanced:
            return 0.0
        seg = self.construction.output(self.closing[kind])
        return math.dist(seg.start.xy, seg.end.xy)


def engine_kinds(e: Engine) -> tuple[str, ...]:
    """The polygons an engine's data ask for: the secondary ones only with a rod given."""
    return KINDS if e.rod is not None else KINDS[:2]


def draw_engine(e: Engine, reference: float | None = None) -> EnginePolygons:
    """Draw the cranks and their doubled directions in the end view, then the four
    polygons; couples about the plane at ``reference`` (default: the engine's central
    plane, midway between its end cylinders, about which the textbooks take them)."""
    ref = (min(e.planes) + max(e.planes)) / 2 if reference is None else reference
    c = Construction()
    out = EnginePolygons(c)
    o = c.give("O", g.Point(0.0, 0.0), label="O", phrase=phrase("balance.cranks"))
    lines = {}
    for i, theta in enumerate(e.cranks, start=1):
        for kind, angle in (("1", theta), ("2", 2 * theta)):
            at = c.give(f"C{kind}{i}", g.Point(math.cos(angle), math.sin(angle)), label="")
            lines[kind, i] = c.draw(f"crank{kind}{i}", "line_through", o, at, kind=Kind.LINE)
    n = None if e.rod is None else e.rod / e.crank
    for k, kind in enumerate(engine_kinds(e)):
        order = "1" if kind.startswith("primary") else "2"
        sizes = [m * e.crank / (1.0 if order == "1" else n) for m in e.each]
        vectors = [(str(i), size * ((p - ref) if kind.endswith("couple") else 1.0),
                    lines[order, i]) for i, (p, size) in enumerate(zip(e.planes, sizes), start=1)]
        tag = f"e{k}"
        out.tips[kind] = []
        panel = Panel.COUPLE if kind.endswith("couple") else Panel.FORCE
        # A couple's arm p − ref rounds at the size of the planes it is taken between.
        reach = [size * ((abs(p) + abs(ref)) if kind.endswith("couple") else 1.0)
                 for p, size in zip(e.planes, sizes)]
        out.closing[kind], shut = lay_polygon(
            c, out.tips[kind], tag, panel, vectors,
            phrase("balance.engine", kind=Word(kind), order="θᵢ" if order == "1" else "2θᵢ"),
            Word(kind), closing="balance.left",
            closed=phrase("balance.balanced", plane=Word(kind)), reach=reach)
        if shut:
            out.balanced.add(kind)
    return out
