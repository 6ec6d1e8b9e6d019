"""Klein's construction: the velocity and acceleration of an in-line slider-crank's piston,
drawn on the mechanism itself (Khurmi, Theory of Machines, ch. 8).

With O the crank's pivot, C the crank pin and P the piston pin:

* **velocity**: produce the rod PC to meet at M the line through O square to the line
  of stroke. Triangle OCM has its sides square to those of the velocity triangle (V_C ⟂
  OC, V_PC ⟂ PC, V_P along the stroke), so it is that triangle turned through 90° at
  the scale 1/ω: V_P = ω·OM, turned a right angle with ω.
* **acceleration**: with centre C and radius CM draw a circle, and the circle on CP as
  diameter; the line KL through their two meeting points cuts CP at Q and the line of
  stroke at N. OCQN is the acceleration polygon, turned through 180° at the scale 1/ω²:
  a_P = ω²·NO, pointing from N toward O.

Both take the crank at constant speed (α = 0), as the construction does.
"""

from __future__ import annotations

from .. import asks as A
from ..checks import Answer, FigureSpec, vector_value
from ..errors import InputError
from ..model import Mechanism, slider_crank
from ..narration import phrase
from ..record import Kind, Role

__all__ = ["answer_klein", "klein_parts", "KLEIN_FIGURE"]

KLEIN_FIGURE = FigureSpec("klein", "Klein's construction", "Klein's construction")
"""The mechanism with the velocity triangle OCM and the acceleration diagram OCQN on it."""


def klein_parts(m: Mechanism) -> tuple[str, str, str, int]:
    """The crank's pivot O, the crank pin C, the piston pin P and the guide's slide index
    (:func:`~.model.slider_crank`).

    Raises
    ------
    InputError
        If the mechanism is no slider-crank whose crank drives a rod to a block on a frame
        guide.
    """
    parts = slider_crank(m)
    if parts is None:
        raise InputError("Klein's construction is drawn on a slider-crank: a crank, a rod and "
                         "a piston on a frame guide; this mechanism is not one")
    return parts


def answer_klein(work, ask) -> Answer:
    """The piston's velocity (V_P) or acceleration (A_P) by Klein's construction."""
    m, asm = work.mechanism, work.assembly
    o, c, p, i = klein_parts(m)
    if ask.point != p:
        raise InputError(f"Klein's construction finds the piston's motion, {p}'s, not "
                         f"{ask.point}'s; ask V_{p} or A_{p}")
    d = m.drive
    if isinstance(ask, A.Acceleration) and d.alpha != 0.0:
        raise InputError("Klein's construction takes the crank at constant speed; this one "
                         f"has α{d.link} = {d.alpha:g} rad/s²: use the acceleration polygon")
    stroke = asm.guides[i]
    off = abs(asm.output(stroke).signed_distance(asm.output(asm.points[o])))
    if off > 1e-9 * asm.size:
        raise InputError(f"Klein's construction is drawn on an in-line slider-crank; this "
                         f"stroke passes {m.units.length_text(off)} from {o}: use the polygons")
    ref = _draw(asm, o, c, p, stroke, acceleration=isinstance(ask, A.Acceleration))
    w = d.omega
    (ox, oy) = asm.xy(o)
    (x, y) = asm.output(ref).xy
    if isinstance(ask, A.Velocity):
        value = vector_value(-w * (y - oy), w * (x - ox))          # ω k × OM
        method = "Klein's construction (V = ω·OM)"
    else:
        value = vector_value(-w * w * (x - ox), -w * w * (y - oy))  # ω² NO
        method = "Klein's construction (a = ω²·NO)"
    cond = min(asm[r].conditioning for r in (ref, asm.points[c], asm.points[p]))
    refs = ("kl:OCM", ref) if isinstance(ask, A.Velocity) else ("kl:OCM", "kl:Q", "kl:NO")
    return Answer(ask, value, cond, method, refs=refs, figures=(KLEIN_FIGURE,))


def _draw(asm, o: str, c: str, p: str, stroke: str, *, acceleration: bool) -> str:
    """Draw Klein's lines once; return the ref of M (velocity) or of N (acceleration)."""
    if "kl:M" not in asm:
        po, pc, pp = asm.points[o], asm.points[c], asm.points[p]
        asm.draw("kl:OM", "perpendicular_through", po, stroke,
                 phrase=phrase("klein.square", o=o))
        asm.draw("kl:rod", "line_through", pp, pc, phrase=phrase("klein.produce", p=p, c=c))
        asm.draw("kl:M", "intersect_lines", "kl:OM", "kl:rod", label="M",
                 phrase=phrase("klein.m", o=o, c=c))
        asm.draw("kl:OCM", "join", po, "kl:M", kind=Kind.LINE, role=Role.RESULT,
                 phrase=phrase("klein.velocity", o=o, c=c, p=p))
    if not acceleration:
        return "kl:M"
    if "kl:N" not in asm:
        pc, pp = asm.points[c], asm.points[p]
        asm.draw("kl:c1", "circle_through", pc, "kl:M", phrase=phrase("klein.circle_cm", c=c))
        asm.draw("kl:mid", "midpoint", pc, pp)
        asm.draw("kl:c2", "circle_through", "kl:mid", pc,
                 phrase=phrase("klein.circle_cp", c=c, p=p))
        asm.draw("kl:K", "intersect_circles", "kl:c1", "kl:c2", pick="left", label="K")
        asm.draw("kl:L", "intersect_circles", "kl:c1", "kl:c2", pick="right", label="L",
                 phrase=phrase("klein.kl"))
        asm.draw("kl:KL", "line_through", "kl:K", "kl:L", phrase=phrase("klein.join_kl"))
        asm.draw("kl:Q", "intersect_lines", "kl:KL", "kl:rod", label="Q",
                 phrase=phrase("klein.q", c=c, p=p))
        asm.draw("kl:N", "intersect_lines", "kl:KL", stroke, label="N",
                 phrase=phrase("klein.acceleration", o=o, c=c, p=p))
        asm.draw("kl:NO", "join", "kl:N", asm.points[o], kind=Kind.LINE, role=Role.RESULT)
    return "kl:N"

