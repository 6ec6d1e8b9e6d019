"""Dyad rules for wheels that roll without slip, and an input that is such a wheel.

A wheel's angle follows from how far it has rolled: along a flat face, the distance its
centre stands from the start over its radius; round a circle, the angle its centre has
gone round times (R ± r)/r. Each rule draws the wheel's axis at that angle, and its
other points are laid off from the axis. :func:`roll_input` goes the other way for an
input wheel: its angle, given, lays off its centre along the face.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .. import geometry as g
from .dyad_rules import dyad_rule
from ..joints import Slide
from ..narration import Phrase, Word, phrase
from ..record import Kind

if TYPE_CHECKING:
    from .assembly import Assembler

__all__ = ["roll_input", "roll_wheel", "roll_round"]


def roll_input(asm: Assembler, s: Slide) -> None:
    """The input is a wheel rolling on the frame: its angle θ says how far it has rolled
    since its centre stood square over the face's ``through`` point (its axis then
    along the frame's x), so the centre is laid off σ·r·θ back along its path from
    there, and the wheel's axis drawn through it at θ."""
    d = asm.m.drive
    i = asm.m.slides.index(s)
    r = s.contact.circle.radius
    rolled = -s.contact.roll_sign * r * asm.theta
    start = asm.c.give(f"roll:{d.link}", g.Point(*s.through), label="", kind=Kind.POINT)
    asm.found(s.point, "lay_off", start, asm.guides[i], length=rolled,
              said=phrase("position.wheel_input", link=d.link, name=_link_name(asm, d.link),
                          point=s.point, face=s.contact.face.through,
                          turn=asm.angle(abs(asm.theta)),
                          sense=Word("counter-clockwise" if asm.theta > 0 else "clockwise"),
                          rolled=asm.length(abs(rolled)), radius=asm.length(r),
                          way=Word("forward" if rolled >= 0 else "back")))
    _wheel_axis(asm, d.link, asm.c.output(asm.known[s.point]).xy, asm.theta,
                phrase("position.wheel_axis", point=s.point, link=d.link,
                       angle=asm.angle(asm.theta)))


@dyad_rule("a wheel rolling without slip", 1)
def roll_wheel(asm: Assembler) -> bool:
    """Turn a wheel that rolls without slip through the distance rolled over its radius.

    Once the wheel's centre is drawn on its path (the face's parallel at the
    radius), the distance s it stands from the start (square over the face's
    ``through`` point) is measured with dividers along the face; the wheel has
    turned through s / r, clockwise when it rides on the left of the face.
    """
    for s in asm.m.slides:
        if not s.type.rolling or s.point not in asm.known or s.link in asm.axes:
            continue
        pose = _pose_of(asm, s.guide_link)
        if pose is None:
            continue
        phi, origin = pose
        c, sn = math.cos(phi), math.sin(phi)
        (tx, ty), (dx, dy) = s.through, s.direction
        gx, gy = origin[0] + c * tx - sn * ty, origin[1] + sn * tx + c * ty
        ux, uy = c * dx - sn * dy, sn * dx + c * dy
        px, py = asm.c.output(asm.known[s.point]).xy
        rolled = ux * (px - gx) + uy * (py - gy)
        r = s.contact.circle.radius
        turn = -rolled / (s.contact.roll_sign * r)
        wheel = phi + turn
        sense = "clockwise" if turn < 0 else "counter-clockwise"
        _wheel_axis(asm, s.link, (px, py), wheel, phrase(
            "position.wheel_rolls", link=s.link, name=_link_name(asm, s.link),
            point=s.point, rolled=asm.length(abs(rolled)), turn=asm.angle(abs(turn)),
            sense=Word(sense), radius=asm.length(r)))
        return True
    return False


@dyad_rule("a wheel rolling round a circle without slip", 1)
def roll_round(asm: Assembler) -> bool:
    """Turn a wheel that rolls round a circle through the arc rolled over its radius.

    Once the wheel's centre C is drawn, the angle β it has gone round the circle's
    centre K from the start (on K's +x) is measured with the protractor; the arc
    rolled, R·β, turns the wheel through R·β/r relative to the line KC, so through
    β·(R ± r)/r in all (+ outside the circle, − inside).
    """
    for a in asm.m.rolling_arcs:
        if a.point not in asm.known or a.centre not in asm.known or a.link in asm.axes:
            continue
        pose = _pose_of(asm, a.guide_link)
        if pose is None:
            continue
        phi, _ = pose
        (px, py), (kx, ky) = (asm.c.output(asm.known[n]).xy for n in (a.point, a.centre))
        beta = (math.atan2(py - ky, px - kx) - phi + math.pi) % math.tau - math.pi
        r = a.contact.circle.radius
        turn = a.roll_gain * beta / r
        wheel = phi + turn
        _wheel_axis(asm, a.link, (px, py), wheel, phrase(
            "position.wheel_rolls_round", link=a.link, name=_link_name(asm, a.link),
            point=a.point, centre=a.centre, beta=asm.angle(beta), turn=asm.angle(turn),
            ratio=Word("(R + r)/r" if a.contact.side == "outside" else "(r − R)/r"),
            big=asm.length(a.contact.face.radius), radius=asm.length(r)))
        return True
    return False


def _wheel_axis(asm: Assembler, link: int, at: tuple[float, float], angle: float,
                said: Phrase) -> None:
    """Draw a wheel's axis through its centre ``at``, at the ``angle`` rolling turned it
    to: the line its other points are laid off from."""
    x, y = at
    asm.axes[link] = asm.c.give(
        f"axis:{link}", g.Line(-math.sin(angle), math.cos(angle),
                               math.sin(angle) * x - math.cos(angle) * y),
        label=f"link {link}", kind=Kind.GUIDE, phrase=said)


def _link_name(asm: Assembler, number: int) -> Phrase | None:
    """A link's name as a step adds it after the number: " (wheel)"."""
    k = asm.m.link(number)
    return phrase("link_name", name=k.name) if k.name else None


def _pose_of(asm: Assembler, number: int) -> tuple[float, tuple[float, float]] | None:
    """(angle, origin) of a drawn link, or None if it is not drawn yet."""
    if number == 1:
        return 0.0, (0.0, 0.0)
    k = asm.m.link(number)
    if not asm.posed(number) or len(k.names) < 2 or not all(n in asm.known
                                                               for n in k.names[:2]):
        return None
    (ax, ay), (bx, by) = (asm.c.output(asm.known[n]).xy for n in k.names[:2])
    (lx, ly) = k.local(k.names[1])
    phi = math.atan2(by - ay, bx - ax) - math.atan2(ly, lx)
    return phi, (ax, ay)
