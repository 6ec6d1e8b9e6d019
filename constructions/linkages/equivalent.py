"""The equivalent linkage of a direct contact, drawn (notes part 2 §2.13).

A circle touching a second circle keeps its centre a fixed distance from the other's
(r₁ + r₂ outside, r₂ − r₁ inside): the pair moves, at the instant, as a link joining the
two centres of curvature. A circle on a flat face keeps its centre a radius from the face:
as a block at that centre running in a slot parallel to the face. tarsim solves contacts
that way already; ``equiv_R`` (R the circle's centre) draws it, dashed, over the contact
pair, and reads the equivalent link's length (or the slot's offset) off the drawing.
"""

from __future__ import annotations

import math

from .. import asks as A
from ..checks import Answer, FigureSpec
from ..errors import InputError
from ..model import Mechanism
from ..narration import phrase
from ..record import Kind

__all__ = ["answer_equivalent", "contact_at", "equivalent_askable", "EQUIVALENT_FIGURE"]

EQUIVALENT_FIGURE = FigureSpec("equivalent-linkage", "Equivalent linkage", "equivalent linkage")
"""The contact pair with its centres of curvature and the equivalent link, dashed."""


def contact_at(m: Mechanism, point: str):
    """The contact whose circle has its centre at ``point``: an arc (circle on circle) or a
    slide (circle on a face), with its index among the mechanism's slides for a face.

    Raises
    ------
    InputError
        If no contact's circle is centred there, naming those that are.
    """
    for a in m.arcs:
        if a.type.contact and a.point == point:
            return a, None
    for i, s in enumerate(m.slides):
        if s.type.contact and s.point == point:
            return s, i
    centres = [j.point for j in (*m.arcs, *m.slides) if j.type.contact]
    raise InputError(f"no contact has its circle centred at {point}; the contacts' circles are "
                     f"centred at {', '.join(centres) or 'none (no [[contact]])'}")


def equivalent_askable(m: Mechanism) -> set[str]:
    """``equiv_R`` for each contact's circle centre R."""
    return {f"equiv_{j.point}" for j in (*m.arcs, *m.slides) if j.type.contact}


def answer_equivalent(work, ask: A.Equivalent) -> Answer:
    """Draw the equivalent link (or slot) of the contact at ``ask.point`` and read its length
    (or offset)."""
    m, asm = work.mechanism, work.assembly
    joint, index = contact_at(m, ask.point)
    c = joint.contact
    key = f"eq:{ask.point}"
    if index is None:
        other = joint.centre
        if key not in asm:
            asm.draw(f"{key}:a", "mark", asm.points[ask.point],
                     phrase=phrase("equivalent.centres", a=ask.point, b=other, i=joint.link,
                                   j=joint.guide_link))
            asm.draw(key, "line_through", asm.points[ask.point], asm.points[other],
                     kind=Kind.LINE,
                     phrase=phrase("equivalent.link", a=ask.point, b=other,
                                   length=m.units.length_text(joint.radius),
                                   how="r₁ + r₂" if c.side == "outside" else "r₂ − r₁"))
        value = {"value": math.dist(asm.xy(ask.point), asm.xy(other))}
        refs = (f"{key}:a", key)
    else:
        if key not in asm:
            asm.draw(key, "parallel_through", asm.points[ask.point], asm.guides[index],
                     kind=Kind.LINE,
                     phrase=phrase("equivalent.slot", a=ask.point, i=joint.link,
                                   j=joint.guide_link,
                                   r=m.units.length_text(c.circle.radius)))
        face = asm.output(asm.points[c.face.through])
        line = asm.output(key)
        value = {"value": abs(line.signed_distance(face))}
        refs = (key,)
    cond = asm[asm.points[ask.point]].conditioning
    return Answer(ask, value, cond, "equivalent linkage (notes §2.13)", refs=refs,
                  figures=(EQUIVALENT_FIGURE,))
