"""A drawn velocity or acceleration polygon: which polygon it is, its tips, and what it reads.

The walk (:mod:`.polygon_walk`) draws a polygon tip by tip; what it hands back is a
:class:`Polygon`: its pole, scale and tips, the rates it read, and the acts that read a
vector, a relative vector or a Coriolis component off it at its scale. Which polygon it
is, and how each names its parts, is its :class:`PolygonKind` (:data:`VELOCITY` or
:data:`ACCELERATION`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .. import geometry as g
from .assembly_record import Assembly
from ..errors import TarsimError
from ..narration import Quantity, phrase
from ..record import Construction, Panel, Ref, Role

__all__ = ["Polygon", "PolygonKind", "VELOCITY", "ACCELERATION", "NOISE", "sense_of"]

NOISE = 1e-12
"""A rate below this fraction of the input's is rounding, not motion: it is said as zero.

At a limit position ω of the lever comes out near 1e-17 of the input's; a sentence
giving it a sense would take the sense from noise.
"""


@dataclass(frozen=True)
class PolygonKind:
    """Which polygon: the velocity or the acceleration polygon, and how each names its parts."""

    panel: Panel
    noun: str
    symbol: str
    prefix: str
    pole: str
    prime: str
    unit: str


VELOCITY = PolygonKind(Panel.VELOCITY, "velocity", "V", "vp", "o_v", "", "/s")
"""The velocity polygon: pole o_v, tips b, vectors V_B."""

ACCELERATION = PolygonKind(Panel.ACCELERATION, "acceleration", "A", "ap", "o_a", "′", "/s²")
"""The acceleration polygon: pole o_a, tips b′, vectors A_B."""


@dataclass
class Polygon:
    """A drawn velocity or acceleration polygon: its pole, scale and tips, and what it reads.

    ``tips`` maps a point name (``"B"``), or a coincident point taken on a link
    (``"A4"``), to its tip step; frame points map to the pole. ``rates`` maps each
    moving link it could read to ω (rad/s), or α (rad/s²), counter-clockwise
    positive. ``steps`` are the polygon's steps in drawing order (all in its panel)
    and ``space_steps`` the lines of the space diagram they take directions from.
    ``coriolis`` maps the point of each slot to the (start, end, sign) of its
    Coriolis component 2ω_j × V_P/Pj, and ``components`` each drawn component's
    label ("Aⁿ_B/A") to its step (acceleration polygon).
    """

    kind: PolygonKind
    pole: Ref
    scale: float
    tips: dict[str, Ref]
    rates: dict[int, float]
    steps: list[Ref]
    space_steps: list[Ref] = field(default_factory=list)
    construction: Construction = field(default_factory=Construction, repr=False)
    aliases: dict[str, str] = field(default_factory=dict)
    coriolis: dict[str, tuple[Ref, Ref, float]] = field(default_factory=dict)
    components: dict[str, Ref] = field(default_factory=dict)
    spans: dict[int, float] = field(default_factory=dict)
    """The length (m) on the space diagram each rate was read over: ω = V_rel / span."""
    reads: dict[int, tuple] = field(default_factory=dict)
    """How each rate was read, by the steps it was read from
    (:func:`~.polygon_readings.rate`): what a replay reads again."""

    def vector(self, name: str) -> tuple[float, float]:
        """Read the velocity (or acceleration) of ``name`` off the polygon: the vector from the
        pole to its tip, in m/s (m/s²). ``name`` is a tip (``B``) or a point taken on a link
        that carries it (``A2`` for the crank pin A).

        Raises
        ------
        TarsimError
            If the polygon has no tip of that name.
        """
        return self.between(self.pole, self.tip(name))

    def tip(self, name: str) -> Ref:
        """The step of ``name``'s tip (``A2`` is the tip of the point A, taken on link 2).

        Raises
        ------
        TarsimError
            If the polygon has no tip of that name.
        """
        key = self.aliases.get(name, name)
        if key not in self.tips:
            raise TarsimError(f"the {self.kind.noun} polygon has no tip for {name}; it has "
                              f"{', '.join(self.tips)}")
        return self.tips[key]

    def draw_relative(self, name: str, of: str, units) -> Ref:
        """Join the tip of ``of`` to the tip of ``name``: the vector V_name/of (A_… in the
        acceleration polygon), drawn and narrated when an exercise asks for it. The
        step joins the polygon's ``steps``; its ref is returned.

        Raises
        ------
        TarsimError
            If the polygon has no tip for either name.
        """
        ref = f"{self.kind.prefix}:rel:{name}/{of}"
        c = self.construction
        if ref in c:
            return ref
        start, end = self.tip(of), self.tip(name)
        size = math.hypot(*self.between(start, end)) / units.metres
        symbol = f"{self.kind.symbol}_{name}/{of}"
        c.draw(ref, "join", start, end, label=symbol, role=Role.RESULT, panel=self.kind.panel,
               phrase=phrase("polygon.relative", a=c[start].label, b=c[end].label, symbol=symbol,
                             size=Quantity(size, units.length, self.kind.unit, "rate")))
        self.steps.append(ref)
        return ref

    def tips_on(self, link: int, mech) -> list[Ref]:
        """The tips of the points link ``link`` carries (``B``, or ``A4`` on a slot of link 4):
        what its ω or α is read from."""
        def on(key: str) -> bool:
            if key in mech.point_names:
                return link in mech.links_at(key) or any(s.point == key and s.link == link
                                                         for s in mech.slides)
            return key.endswith(str(link)) and key[:-len(str(link))] in mech.point_names
        return [r for key, r in self.tips.items() if on(key)]

    def extent(self) -> float:
        """The longest vector drawn from the pole (m/s, m/s²): each tip is drawn to a rounding
        of about eps times this, however short the vector read off it."""
        c = self.construction
        refs = [*self.tips.values(), *(end for _, end, _ in self.coriolis.values())]
        ends = [c.output(r) for r in refs]
        return max([math.hypot(*self.between(self.pole, r)) for r, p in zip(refs, ends)
                    if isinstance(p, g.Point) and not p.is_at_infinity] + [0.0])

    def conditioning(self, value: dict, scale: float, link: int | None = None) -> float:
        """The conditioning of ``value`` (results.json's shape: a vector, or link ``link``'s
        rate) read off the polygon, whose check measures it beside ``scale``.

        It is the polygon's :meth:`worst`, times the share of the polygon's extent the
        reading stands above: a short vector, or a rate over a short span, read off a large
        polygon keeps only that share of its digits.
        """
        size = max(abs(value["value"]), scale)
        if link is not None:
            size *= self.spans.get(link, 0.0)
        extent = self.extent()
        share = 1.0 if extent == 0.0 or size == 0.0 else min(1.0, size / extent)
        return self.worst() * share

    def worst(self) -> float:
        """The worst conditioning of the polygon's tips and of the points of the space diagram
        it takes its directions and images from. Every reading off it inherits it: the walk
        hands ω, α, sliding speeds and the space diagram's shape from tip to tip as numbers,
        not as drawn steps (a coupler point cut from nearly tangent arcs skews its image)."""
        c = self.construction
        space = c.points.values() if isinstance(c, Assembly) else ()
        return min(c[r].conditioning for r in (*self.tips.values(), *space))

    def between(self, start: Ref, end: Ref) -> tuple[float, float]:
        """The drawn vector ``start`` → ``end`` read at the polygon's scale."""
        (sx, sy), (ex, ey) = (self.construction.output(r).xy for r in (start, end))
        return (ex - sx) / self.scale, (ey - sy) / self.scale

    def coriolis_of(self, point: str) -> tuple[float, float]:
        """The Coriolis component 2ω_j × v_rel at slot point ``point`` (m/s²), as drawn.

        Raises
        ------
        TarsimError
            If no point of that name slides in a moving slot.
        """
        if point not in self.coriolis:
            raise TarsimError(f"no Coriolis component at {point}; the polygon has one at "
                              f"{', '.join(self.coriolis) or 'no point'}")
        start, end, sign = self.coriolis[point]
        x, y = self.between(start, end)
        return sign * x + 0.0, sign * y + 0.0


def sense_of(rate: float, scale: float) -> str:
    """"ccw", "cw", or "at rest" when ``rate`` is rounding noise beside ``scale``."""
    if abs(rate) <= NOISE * scale:
        return "at rest"
    return "ccw" if rate > 0 else "cw"
