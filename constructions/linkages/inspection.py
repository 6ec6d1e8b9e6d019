"""The primary instant centre of each kind of joint, by inspection (notes 000-part1 §2.7).

A pin is the centre of the links it joins (:mod:`.kennedy` marks those). For the other
joints :data:`~.joint_rules.JOINT_RULES` names one of these per kind:

* a block on a straight guide: its centre is at infinity, perpendicular to the guide;
* a wheel rolling without slip: its centre is the contact point;
* a pin in a straight slot, or a circle on a face: no centre, but a locus, the common
  normal at the contact, on which the centre lies (rule 5);
* a pin in a curved slot, or two circles in contact: the line through the two centres
  of curvature is that normal;
* a block on a curved guide stands as its pin at the centre of curvature, and is said
  so (:func:`curved_block`).

Each takes the Kennedy walk (it records with its ``record`` and keeps ``out.loci``),
the joint's index among the mechanism's slides or arcs, and the joint.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .centres import Centre, centre_ref, pair_label
from ..joints import Arc, Slide
from ..narration import Phrase, Word, phrase
from ..record import Kind

if TYPE_CHECKING:
    from .kennedy import _Kennedy

__all__ = ["straight_block", "common_normal", "rolling_on_face", "rolling_round",
           "line_of_centres", "curved_slot", "curved_block"]


def on(link: int) -> Phrase:
    """"on the frame", or "on link 3"."""
    return phrase("on_frame") if link == 1 else phrase("on_link", link=link)


def straight_block(ken: _Kennedy, k: int, s: Slide) -> None:
    """A block on a straight guide: the centre at infinity, perpendicular to the guide."""
    i, j = sorted((s.link, s.guide_link))
    ken.record(Centre((i, j), centre_ref(i, j), "block"), "normal_direction",
               ken.asm.guides[k],
               said=phrase("centres.straight_block", point=s.point, link=s.link,
                           on=on(s.guide_link), centre=pair_label(i, j)))


def common_normal(what: str):
    """The common normal of a pin in a straight slot (``what`` "slot") or a circle on a face
    ("contact"): the perpendicular to the guide through the point, a locus of the centre."""
    def normal(ken: _Kennedy, k: int, s: Slide) -> None:
        i, j = sorted((s.link, s.guide_link))
        ref = ken.c.draw(f"N:{i}{j}:{k}", "perpendicular_through", ken.asm.points[s.point],
                         ken.asm.guides[k], kind=Kind.COMMON_NORMAL,
                         phrase=phrase("centres.common_normal", centre=pair_label(i, j),
                                       point=s.point, what=Word(what), link=s.guide_link))
        ken.out.loci.setdefault((i, j), []).append(ref)
    return normal


def rolling_on_face(ken: _Kennedy, k: int, s: Slide) -> None:
    """A wheel rolling without slip: the contact point is the centre (notes §2.7 (4))."""
    pair = tuple(sorted((s.link, s.guide_link)))
    face = s.contact.face
    line = ken.c.draw(f"face:{k}", "parallel_through", ken.asm.points[face.through],
                      ken.asm.guides[k],
                      phrase=phrase("centres.face", point=face.through, link=face.link,
                                    path_of=s.point))
    ken.record(Centre(pair, centre_ref(*pair), "rolling"), "project_onto",
               ken.asm.points[s.point], line,
               said=phrase("centres.rolling", link=s.link, on=s.guide_link, point=s.point,
                           centre=pair_label(*pair)))


def rolling_round(ken: _Kennedy, k: int, a: Arc) -> None:
    """A wheel rolling round a circle without slip: the contact point, R from the circle's
    centre along the line of centres, is the centre."""
    i, j = sorted((a.link, a.guide_link))
    ken.record(Centre((i, j), centre_ref(i, j), "rolling"), "lay_off",
               ken.asm.points[a.centre], ken.asm.points[a.point],
               length=a.contact.face.radius,
               said=phrase("centres.rolling_round", link=a.link, on=a.guide_link,
                           point=a.point, circle=a.centre,
                           radius=ken.m.units.length_said(a.contact.face.radius),
                           centre=pair_label(i, j)))


def line_of_centres(ken: _Kennedy, k: int, a: Arc) -> None:
    """Two circles in contact: the common normal is their line of centres, a locus of the
    centre."""
    _through_centres(ken, k, a, phrase("centres.line_of_centres"))


def curved_slot(ken: _Kennedy, k: int, a: Arc) -> None:
    """A pin in a curved slot: the common normal is the slot's radius through the pin."""
    _through_centres(ken, k, a, phrase("centres.curved_radius", link=a.guide_link))


def _through_centres(ken: _Kennedy, k: int, a: Arc, what: Phrase) -> None:
    i, j = sorted((a.link, a.guide_link))
    ref = ken.c.draw(f"N:{i}{j}:a{k}", "line_through", ken.asm.points[a.centre],
                     ken.asm.points[a.point], kind=Kind.COMMON_NORMAL,
                     phrase=phrase("centres.contact_normal", centre=pair_label(i, j),
                                   what=what, a=a.centre, b=a.point))
    ken.out.loci.setdefault((i, j), []).append(ref)


def curved_block(a: Arc, at: str, i: int, j: int) -> tuple[str, Phrase]:
    """How the pin a block on a curved guide stands as, at its centre of curvature ``at``,
    is found and said: the centre of curvature is the centre."""
    return "curved", phrase("centres.curved_block", point=a.point, link=a.link,
                            on=on(a.guide_link), at=at, centre=pair_label(i, j))
