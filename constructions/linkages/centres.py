"""Instant centres as found: each centre and the rule that gave it, and the ω ratio they give.

A :class:`Centre` is one centre ``I_ij``, the step that locates it and how it was found
(by inspection, by Kennedy, or by the velocities when every Kennedy line coincides);
:class:`Centres` holds every centre of a position in order of discovery, and
:func:`omega_ratio` reads ``ω_j / ω_i`` off three of them. They are located in
:mod:`~tarsim.constructions.linkages.kennedy`, and answered as a method in
:mod:`~tarsim.constructions.linkages.centre_answers`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .. import geometry as g
from .assembly_record import Assembly
from ..errors import DegenerateInput
from ..narration import Number, Phrase, phrase
from ..record import Ref

__all__ = ["Centre", "Centres", "omega_ratio", "centre_ref", "pair_label", "ILL_CONDITIONED",
           "PRIMARY_RULES", "SAME"]

ILL_CONDITIONED = 1e-3
"""Conditioning below which a centre is reported as ill-conditioned."""

PRIMARY_RULES = ("pin", "block", "curved", "rolling")
"""The rules of inspection, as :attr:`Centre.rule` names them."""

SAME = 1e-9
"""Relative slack for "these two lines (or points) are the same"."""


def pair_label(i: int, j: int) -> str:
    """The centre's name as the notes write it: ``I13`` (lower number first)."""
    i, j = sorted((i, j))
    return f"I{i}{j}" if max(i, j) < 10 else f"I{i},{j}"


def centre_ref(i: int, j: int) -> Ref:
    """The id of the step that locates centre ``I_ij``."""
    i, j = sorted((i, j))
    return f"I:{i}{j}" if max(i, j) < 10 else f"I:{i},{j}"


@dataclass(frozen=True)
class Centre:
    """One instant centre and how it was found.

    ``rule`` is ``"pin"``, ``"block"`` (at infinity, perpendicular to a straight
    guide), ``"curved"`` (a block on a curved guide: the centre of curvature),
    ``"rolling"`` (the contact point of a wheel rolling without slip),
    ``"kennedy"``, or ``"velocities"`` (rule 2 on its one Kennedy line, where the
    two links' velocities agree, when every triangle gives that same line).
    ``lines`` are the refs of the two lines it was cut from, and ``triangles`` the
    third link of each triangle (``None`` for the common normal of a pin in a slot
    or a contact). ``order`` numbers the secondaries in discovery order (0 for a
    primary).
    """

    pair: tuple[int, int]
    ref: Ref
    rule: str
    lines: tuple[Ref, ...] = ()
    triangles: tuple[int | None, ...] = ()
    order: int = 0
    crossing: float = 1.0

    @property
    def label(self) -> str:
        """``I13``."""
        return pair_label(*self.pair)

    @property
    def primary(self) -> bool:
        """Found by inspection rather than by Kennedy's theorem."""
        return self.rule in PRIMARY_RULES


@dataclass
class Centres:
    """Every instant centre of an assembled mechanism, in order of discovery."""

    assembly: Assembly
    found: dict[tuple[int, int], Centre] = field(default_factory=dict)
    loci: dict[tuple[int, int], list[Ref]] = field(default_factory=dict)

    def centre(self, i: int, j: int) -> Centre:
        """The centre of links ``i`` and ``j`` (either order)."""
        return self.found[tuple(sorted((i, j)))]

    def point(self, i: int, j: int) -> g.Point:
        """Where ``I_ij`` is (possibly at infinity)."""
        return self.assembly.output(self.centre(i, j).ref)

    def conditioning(self, i: int, j: int) -> float:
        """The conditioning of ``I_ij``'s step, compounded along its construction."""
        return self.assembly[self.centre(i, j).ref].conditioning

    @property
    def links(self) -> tuple[int, ...]:
        """The link numbers, ascending."""
        return tuple(sorted(self.assembly.mechanism.numbers))

    @property
    def primaries(self) -> list[Centre]:
        """The centres found by inspection."""
        return [c for c in self.found.values() if c.primary]

    @property
    def secondaries(self) -> list[Centre]:
        """The centres found by Kennedy's theorem, in discovery order."""
        return sorted((c for c in self.found.values() if not c.primary), key=lambda c: c.order)

    def construction_refs(self) -> list[Ref]:
        """The refs of the whole construction in the order a student draws it: the centres by
        inspection, then for each centre found by Kennedy its two lines and the centre itself,
        in the order of discovery."""
        out = [c.ref for c in self.primaries]
        for c in self.secondaries:
            out += [r for r in c.lines if r not in out] + [c.ref]
        return out

    def warnings(self) -> list[Phrase]:
        """One line for each ill-conditioned centre, saying how the lines meet."""
        out = []
        for c in self.secondaries:
            if self.point(*c.pair).is_at_infinity:
                continue
            cond = self.conditioning(*c.pair)
            if cond < ILL_CONDITIONED:
                angle = math.degrees(math.asin(min(1.0, c.crossing)))
                out.append(phrase("note.ill_conditioned", centre=c.label,
                                  cond=Number(cond, ".2g"), angle=Number(angle, ".3g")))
        return out


def omega_ratio(centres: Centres, i: int, j: int) -> float:
    """``ω_j / ω_i`` from the centres: ``(I_ij − I_1i)/(I_ij − I_1j)`` along the line of centres.

    The ratio is negative (opposite senses) when I_ij lies between I_1i and I_1j.

    Raises
    ------
    DegenerateInput
        If ω_i is zero at this position (its link translates) or ω_j is unbounded
        (I_ij falls on I_1j).
    """
    if i == j:
        return 1.0
    p_ij, p_i, p_j = centres.point(i, j), centres.point(1, i), centres.point(1, j)
    if p_i.is_at_infinity:
        raise DegenerateInput(f"link {i} translates (I1{i} is at infinity), so ω{i} = 0 and "
                              f"no ratio to it exists")
    if p_j.is_at_infinity:
        return 0.0
    if p_ij.is_at_infinity:
        return 1.0
    (x, y), (xi, yi), (xj, yj) = p_ij.xy, p_i.xy, p_j.xy
    ux, uy = xj - xi, yj - yi
    if math.hypot(ux, uy) == 0.0:
        # I1i ≡ I1j: measure along the line from them to I_ij instead.
        ux, uy = x - xi, y - yi
    num = (x - xi) * ux + (y - yi) * uy
    den = (x - xj) * ux + (y - yj) * uy
    scale = max(abs(num), abs(den), 1e-300)
    if abs(den) <= 1e-12 * scale:
        raise DegenerateInput(f"{pair_label(i, j)} falls on {pair_label(1, j)}: ω{j} would be "
                              "unbounded at this position")
    return num / den
