"""The acceleration polygon across a slot: the Coriolis component and the sliding one.

Where a point P of one link runs in a slot of link j, the acceleration polygon closes
``A_P = A_Pj + Aᶜ + Aˢ`` (the notes §2.11–2.12): the Coriolis component 2ω_j × v_rel,
then, in a straight slot, the sliding acceleration along the slot, and in a slot curved
about K, the relative path's normal component v_rel²/ρ toward K and its tangential one.
The acceleration polygon (:mod:`.acceleration_polygon`) draws the ``slot`` and ``curve``
loci its joints give it (:mod:`.polygon_joints`) with these.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .coincident import Node
from ..narration import Number, Phrase, Word, phrase
from .polygon import NOISE, sense_of
from .polygon_readings import coriolis_length, curve_normal_length
from ..record import Derived, Ref

if TYPE_CHECKING:
    from .acceleration_polygon import _Polygon

__all__ = ["draw_slot", "draw_curve", "draw_coriolis", "sliding", "sign", "signed", "reversed_"]


def draw_slot(ap: _Polygon, x: Node, other: Node, i: int) -> tuple[Ref, Phrase]:
    """Coriolis 2ω_j·v_rel laid off from the other point's tip, then the slot's parallel."""
    j = ap.m.slides[i].guide_link
    slider, carried, rel = ap.curve_nodes(x, other)
    guide = ap.asm.guides[i]
    end = draw_coriolis(ap, x, other, slider, carried, rel, j, ap.asm.guide(i).direction,
                        guide, None, ("guide", guide))
    ref = ap.act(f"ap:{ap.name(x)}:slot@{i}", "parallel_through", end, guide,
                 said=phrase("apolygon.slot", link=j, rel=rel))
    ap.slides_drawn.append((slider, carried, end, sign(x), f"Aˢ_{rel}"))
    return ref, phrase("apolygon.say_slot", component=signed("Aᶜ_" + rel, x))


def draw_curve(ap: _Polygon, x: Node, other: Node, i: int) -> tuple[Ref, Phrase]:
    """A pin P in a slot curved about K of link j (the notes §2.11–2.12).

    ``A_P = A_Pj + Aᶜ + Aⁿ + Aᵗ``: the Coriolis component 2ω_j × v_rel and the
    relative path's normal component v_rel²/ρ toward K both lie along KP, so both
    are laid off along it from the other point's tip; the tangential one, of
    unknown length, is the line ⟂ KP through their end.
    """
    a = ap.m.pin_arcs[i]
    j, K, Pn = a.guide_link, a.centre, a.point
    line = ap.space_line(Node(K), Node(Pn), j)
    slider, carried, rel = ap.curve_nodes(x, other)
    (kx, ky), (px, py) = ap.asm.xy(K), ap.asm.xy(Pn)
    e = math.hypot(px - kx, py - ky)
    tangent = (-(py - ky) / e, (px - kx) / e)            # KP turned +90°
    X, kp = ap.name(x), f"{K}{Pn}"
    first = ap.tip(other)
    along = ("curve", ap.asm.points[K], ap.asm.points[Pn])
    if j != 1:                                           # a frame slot does not turn
        first = draw_coriolis(ap, x, other, slider, carried, rel, j, tangent, None, (line, kp),
                              along)
    u = sliding(ap, slider, carried, tangent)
    normal = u * u / a.radius
    end = ap.act(
        f"ap:{X}:n@curve", "lay_off", first, line, length=-sign(x) * normal * ap.scale,
        derived=Derived(curve_normal_length, (_seen(ap, slider), _seen(ap, carried), along,
                                              a.radius, -sign(x), ap.scale)),
        said=phrase("apolygon.curve_normal", rel=rel,
                    speed=ap.m.units.speed_said(abs(u)),
                    radius=ap.m.units.length_said(a.radius), accel=ap.say(normal), p=Pn,
                    k=K, reversed=reversed_(x)))
    ap.component(f"ap:{X}:n@curve:vec", first, end, signed(f"Aⁿ_{rel}", x))
    ref = ap.act(f"ap:{X}:t@curve", "perpendicular_through", end, line,
                 said=phrase("apolygon.curve_tangent", line=kp, rel=rel))
    ap.slides_drawn.append((slider, carried, end, sign(x), f"Aᵗ_{rel}"))
    return ref, phrase("apolygon.say_tangential", line=kp, rel=rel)


def draw_coriolis(ap: _Polygon, x: Node, other: Node, slider: Node, carried: Node, rel: str,
                  j: int, tangent: tuple[float, float], slot: Ref | None,
                  normal_line: tuple[Ref, str] | None, tangent_by: tuple) -> Ref:
    """Lay off 2ω_j·v_rel from the other point's tip: v_rel turned 90° the way ω_j turns.

    v_rel runs along ``tangent``, so the component lies along the tangent turned
    +90°: the perpendicular to a straight ``slot`` (drawn here), or the line KP of a
    curved one (``normal_line``: the line, directed K → P, which is the turned
    tangent reversed, and its name). It is subtracted when the slot's own point
    is the one found. At an instant with no sliding or no turning the step says
    the component is zero. ``tangent_by`` gives the tangent by its steps, for a replay
    (:func:`~.polygon_readings.coriolis_length`).
    """
    X, tip, start = ap.name(x), ap.tip_label(other), ap.tip(other)
    w = ap.omegas[j]
    u = sliding(ap, slider, carried, tangent)
    still = sense_of(w, abs(ap.m.drive.omega)) == "at rest"
    stuck = abs(u) <= NOISE * ap.m.input_speed
    cor = 0.0 if still or stuck else 2.0 * w * u
    if cor == 0.0:
        why = (phrase("apolygon.still", link=j) if still else
               phrase("apolygon.stuck", rel=rel))
        end = ap.act(f"ap:{X}:cor", "mark", start,
                     said=phrase("apolygon.coriolis_zero", link=j, rel=rel, why=why))
    else:
        if slot is not None:
            along, turn = ap.act(
                f"ap:{X}:cor:perp", "perpendicular_through", start, slot,
                said=phrase("apolygon.coriolis_direction", tip=tip, link=j)), 1.0
            where = phrase("apolygon.along_it")
        else:
            (along, name), turn = normal_line, -1.0
            where = phrase("apolygon.from_along", tip=tip, line=name)
        end = ap.act(
            f"ap:{X}:cor", "lay_off", start, along,
            length=turn * sign(x) * cor * ap.scale,
            derived=Derived(coriolis_length, (
                ap.vp.reads.get(j, ()), _seen(ap, slider), _seen(ap, carried), tangent_by,
                turn * sign(x), ap.scale, abs(ap.m.drive.omega), NOISE * ap.m.input_speed)),
            said=phrase("apolygon.coriolis", where=where, rel=rel, link=j,
                        omega=Number(abs(w)), speed=ap.m.units.speed_said(abs(u)),
                        accel=ap.say(abs(cor)), sense=Word("ccw" if w > 0 else "cw"),
                        reversed=reversed_(x)))
        ap.component(f"ap:{X}:cor:vec", start, end, signed(f"Aᶜ_{rel}", x))
    ap.coriolis[slider.point] = (start, end, sign(x))
    return end


def sliding(ap: _Polygon, slider: Node, carried: Node, tangent: tuple[float, float]) -> float:
    """V_P/Pj along the slot's ``tangent``, from the velocity polygon."""
    (sx, sy), (cx, cy) = ap.velocity(slider), ap.velocity(carried)
    return (sx - cx) * tangent[0] + (sy - cy) * tangent[1]


def _seen(ap: _Polygon, n: Node) -> tuple[Ref | None, Ref, float]:
    """How ``n``'s velocity is read off the velocity polygon, by its steps
    (:func:`~.polygon_readings.velocity`): its tip (None: at rest), the pole, the scale."""
    vp = ap.vp
    return (None if ap.zero(n) else vp.tip(ap.name(n)), vp.pole, vp.scale)


def sign(x: Node) -> float:
    """+1 when the sliding point is found (A_P = A_Pj + …), −1 for the slot's point."""
    return 1.0 if x.link is None else -1.0


def signed(label: str, x: Node) -> str:
    """The component's label, "−" before it when the slot's own point is found."""
    return label if sign(x) > 0 else f"−{label}"


def reversed_(x: Node) -> Phrase | None:
    """", reversed, as it is subtracted" when the slot's own point is found."""
    return None if sign(x) > 0 else phrase("apolygon.reversed")
