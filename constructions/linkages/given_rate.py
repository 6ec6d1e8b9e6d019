"""An input given by another member's motion, turned into the input link's ω and α.

Textbooks give "the piston moves at 3 m/s", "the crank pin moves at 2 m/s" or "the coupler
turns at 5 rad/s" at a crank angle. Velocities are linear in ω of the input, accelerations
in its α (for a given ω), so the input's rates follow from one provisional drawing: the
velocity polygon drawn at ω = 1 rad/s reads the member's speed per rad/s of the input, and
two acceleration polygons at that ω, with α = 0 and α = 1 rad/s², its acceleration per
rad/s². The construction converts so, by drawing; the analytic reference converts its own
way, by the vector-loop solver at the same provisional rates; each then solves with its
own ω and α, so a wrong conversion shows as a disagreement
(:mod:`.reference.given_rates`).
"""

from __future__ import annotations

import math

from .acceleration_polygon import draw_acceleration_polygon
from .assembly import assemble
from ..errors import InputError
from ..model import Mechanism
from ..narration import Phrase, Quantity, Word, phrase
from ..reference.given_rates import member_rate, with_input_rates
from .velocity_polygon import draw_velocity_polygon

__all__ = ["convert"]


def convert(m: Mechanism) -> tuple[Mechanism, Mechanism, Phrase]:
    """The mechanism with the input's ω and α as the drawing finds them, the same as the
    solver finds them, and a sentence that states the drawn conversion.

    Raises
    ------
    InputError
        If the member given does not move with the input at this position (its speed per
        rad/s of the input is nil), so no ω gives it.
    """
    g, d = m.given, m.drive
    per_w, per_w_ref = _rate(m, 1.0, 0.0), member_rate(m, 1.0, 0.0)
    if abs(per_w) <= 1e-12 * max(abs(per_w_ref), 1e-300) or per_w_ref == 0.0:
        raise InputError(f"{_what(g)} does not move with link {d.link} at this position, so "
                         f"no ω{d.link} gives it {_value(m, g)}; choose another member or "
                         "position", file=m.source or None)
    w, w_ref = g.value / per_w, g.value / per_w_ref
    a = a_ref = 0.0
    if g.second_given:
        base, base_ref = _rate(m, w, 0.0, second=True), member_rate(m, w_ref, 0.0, second=True)
        unit = _rate(m, w, 1.0, second=True) - base
        unit_ref = member_rate(m, w_ref, 1.0, second=True) - base_ref
        a, a_ref = (g.second - base) / unit, (g.second - base_ref) / unit_ref
    drawn = with_input_rates(m, w, a)
    what = (phrase("note.along_guide", point=g.target) if g.kind == "speed" else
            phrase("note.about_pivot", point=g.target, pivot=_pivot(m))
            if g.kind == "input_point" else _target(g))
    said = phrase("note.given_rate", what=what, value=_quantity(m, g.kind, g.value),
                  link=d.link, target=_target(g),
                  per=_quantity(m, g.kind, per_w), omega=Quantity(w, "rad", "/s", "rate"),
                  sense=phrase("note.sense", sense=Word("ccw" if w > 0 else "cw")) if w else None,
                  second=phrase("note.given_alpha", link=d.link,
                                alpha=Quantity(a, "rad", "/s²", "rate"))
                  if g.second_given else None)
    return drawn, with_input_rates(m, w_ref, a_ref), said


def _n(x: float) -> str:
    """A number as the notes set it: six figures, a true minus."""
    return f"{x:.6g}".replace("-", "−")


def _rate(m: Mechanism, w: float, a: float, *, second: bool = False) -> float:
    """The member's speed (or ω; with ``second``, its acceleration or α) as drawn with the
    input at ω = ``w``, α = ``a``."""
    asm = assemble(with_input_rates(m, w, a))
    vp = draw_velocity_polygon(asm)
    polygon = draw_acceleration_polygon(asm, vp) if second else vp
    g = m.given
    if g.kind == "omega":
        return polygon.rates[g.target]
    if g.kind == "input_point":        # along the circle about the pivot, k × OP / |OP|
        (px, py), (ox, oy) = asm.xy(g.target), asm.xy(_pivot(m))
        r = math.hypot(px - ox, py - oy)
        ux, uy = -(py - oy) / r, (px - ox) / r
    else:
        ux, uy = asm.guide(_guide(m)).direction
    x, y = polygon.vector(g.target)
    return x * ux + y * uy


def _pivot(m: Mechanism) -> str:
    """The input link's frame pivot, which a point of it turns about."""
    return next(n for n in m.link(m.drive.link).names if n in m.frame.names)


def _guide(m: Mechanism) -> int:
    """The index of the frame guide the given point runs on."""
    return next(i for i, s in enumerate(m.slides)
                if s.point == m.given.target and s.guide_link == 1)


def _what(g) -> str:
    return {"speed": f"V_{g.target} along its guide",
            "input_point": f"V_{g.target}"}.get(g.kind, f"ω{g.target}")


def _value(m: Mechanism, g) -> str:
    if g.kind != "omega":
        return f"{_n(g.value / m.units.metres)} {m.units.length}/s"
    return f"{_n(g.value)} rad/s"


def _target(g) -> str:
    """The member's rate by name: V_C, or ω3."""
    return f"ω{g.target}" if g.kind == "omega" else f"V_{g.target}"


def _quantity(m: Mechanism, kind: str, value: float) -> Quantity:
    """A speed (SI) in the file's units per second, or an ω in rad/s, as a note says it."""
    if kind != "omega":
        return Quantity(value / m.units.metres, m.units.length, "/s", "rate")
    return Quantity(value, "rad", "/s", "rate")

