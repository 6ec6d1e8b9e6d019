"""Which mechanisms the force polygons draw, and how they see them: a crank driving a dyad
(a four-bar's coupler and rocker, a slider-crank's rod and block), or a crank driving a
slotted lever, with a ram riding in the same slot if it has one.

Every polygon is drawn for one of these two groups, so each is recognised once here, as a
small record of its links and points, and the rest of the analysis reads it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import TarsimError
from ..model import Mechanism
from .sliding import lever_gain

__all__ = ["NOT_DRAWN", "Dyad", "Lever", "gain", "group_of", "lever_span", "shape_of",
           "slotted_of"]


@dataclass(frozen=True)
class Dyad:
    """The mechanism as the dyad method sees it: driver d (pivot O, pin A to the coupler),
    coupler i (pins A and B), output j (pin B; pivot C, or a block on a frame guide)."""

    d: int
    i: int
    j: int
    o: str
    a: str
    b: str
    c: str | None
    guide: tuple[float, float] | None


@dataclass(frozen=True)
class Lever:
    """A slotted lever: crank d (pivot o, pin a) drives block b in the slot of lever l.

    The lever turns about p; a ram r may ride on a frame guide (direction ``guide``) with
    its pin q in the same slot."""

    d: int
    b: int
    l: int  # noqa: E741 - the lever, as the notes number it
    o: str
    a: str
    p: str
    r: int | None = None
    q: str | None = None
    guide: tuple[float, float] | None = None


NOT_DRAWN = ("the force polygons draw a four-bar, a slider-crank or a slotted lever only; this "
             "mechanism's forces are in the turning-moment diagram (tarsim sweep)")


def shape_of(mech: Mechanism) -> Dyad:
    """The driver and its dyad.

    Raises
    ------
    TarsimError
        If the mechanism is not a four-bar or a slider-crank.
    """
    why = NOT_DRAWN
    moving = [k.number for k in mech.links if k.number != 1]
    d = mech.drive.link
    if len(moving) != 3 or mech.arcs or any(s.type.contact for s in mech.slides):
        raise TarsimError(why)
    crank = mech.link(d)
    if len(crank.names) != 2 or mech.links_at(crank.names[0]) != tuple(sorted((1, d))):
        raise TarsimError(why)
    o, a = crank.names
    coupler = [n for n in mech.links_at(a) if n != d]
    if len(coupler) != 1:
        raise TarsimError(why)
    i = coupler[0]
    j = next(n for n in moving if n not in (d, i))
    # The coupler and the output may carry points of their own besides their pins (a
    # coupler point, a point a load acts at): the dyad's lines run through the pins alone.
    shared = [p for p in mech.link(i).names if p != a and j in mech.links_at(p)]
    if len(shared) != 1:
        raise TarsimError(why)
    b = shared[0]
    if not mech.slides:
        pivots = [p for p in mech.link(j).names if p != b and 1 in mech.links_at(p)]
        if len(pivots) != 1 or set(mech.links_at(pivots[0])) != {1, j}:
            raise TarsimError(why)
        return Dyad(d, i, j, o, a, b, pivots[0], None)
    (s,) = mech.slides if len(mech.slides) == 1 else (None,)
    if (s is None or s.type.key != "block" or s.guide_link != 1 or s.link != j
            or s.point != b or mech.link(j).names != (b,)):
        raise TarsimError(why)
    return Dyad(d, i, j, o, a, b, None, s.direction)


def slotted_of(mech: Mechanism) -> Lever:
    """The crank and the slotted lever it drives, with its ram if it has one.

    Raises
    ------
    TarsimError
        If the mechanism is not a slotted lever whose slot runs through its pivot.
    """
    d = mech.drive.link
    crank = mech.link(d)
    if mech.arcs or len(crank.names) != 2 or set(mech.links_at(crank.names[0])) != {1, d}:
        raise TarsimError(NOT_DRAWN)
    o, a = crank.names
    block = [s for s in mech.slides if s.point == a and s.type.key == "block"
             and s.guide_link != 1]
    if len(block) != 1 or mech.link(block[0].link).names != (a,):
        raise TarsimError(NOT_DRAWN)
    s = block[0]
    lever = mech.link(s.guide_link)
    # The lever turns about its first point; it may carry points of its own besides (a
    # point B of an inverted slider-crank), but no other joint.
    if (set(mech.links_at(lever.names[0])) != {1, lever.number} or s.through != (0.0, 0.0)
            or any(mech.links_at(p) != (lever.number,) for p in lever.names[1:])):
        raise TarsimError(NOT_DRAWN)
    rest = [k.number for k in mech.links if k.number not in (1, d, s.link, lever.number)]
    if not rest:
        if len(mech.slides) != 1:
            raise TarsimError(NOT_DRAWN)
        return Lever(d, s.link, lever.number, o, a, lever.names[0])
    ram = mech.link(rest[0]) if len(rest) == 1 else None
    if ram is None or len(ram.names) != 1 or len(mech.slides) != 3:
        raise TarsimError(NOT_DRAWN)
    q = ram.names[0]
    pin = [t for t in mech.slides if t.link == ram.number and t.point == q
           and t.type.key == "slot" and t.guide_link == lever.number
           and t.through == s.through and t.direction == s.direction]
    frame = [t for t in mech.slides if t.link == ram.number and t.point == q
             and t.type.key == "block" and t.guide_link == 1]
    if len(pin) != 1 or len(frame) != 1:
        raise TarsimError(NOT_DRAWN)
    return Lever(d, s.link, lever.number, o, a, lever.names[0], ram.number, q,
                 frame[0].direction)


def group_of(mech: Mechanism):
    """The group the crank drives: a dyad, or a slotted lever."""
    try:
        return shape_of(mech)
    except TarsimError:
        pass
    try:
        return slotted_of(mech)
    except TarsimError:
        raise TarsimError(NOT_DRAWN) from None


def gain(group, at, point: str) -> float:
    """What a slotted lever multiplies the rounding of a reading at ``point`` by
    (:func:`~.sliding.lever_gain`); 1 off a lever and at the crank's points."""
    if not isinstance(group, Lever) or point in (group.o, group.a):
        return 1.0
    return lever_gain(at, group.p, group.a, point)


def lever_span(group, at) -> tuple[int, float] | None:
    """A slotted lever and where its turning is read, |PA| from its pivot."""
    return (group.l, math.dist(at[group.p], at[group.a])) if isinstance(group, Lever) \
        else None
