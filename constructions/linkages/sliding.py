"""The sliding velocity and acceleration of a point along the slot of a moving link, read off
the polygons that draw them.

Where point P of link i runs in a straight slot of moving link j, the velocity polygon
closes V_Pi = V_Pj + V_Pi/Pj with V_Pi/Pj along the slot, and the acceleration polygon
A_Pi = A_Pj + Aᶜ + Aˢ with Aˢ, the sliding acceleration, along it too (notes §2.11).
``V_slide_P`` is that V_Pi/Pj and ``A_slide_P`` that Aˢ, each as drawn; the analytic
side takes them from the vector-loop solver's slide rates, the point's travel along the
guide seen from the guide link.
"""

from __future__ import annotations

from .. import asks as A
from .acceleration_polygon import answer as from_acceleration_polygon
from .acceleration_polygon import drawn_acceleration_polygon
from ..checks import Answer, vector_value
from ..errors import InputError
from ..joints import Slide
from ..model import Mechanism
from .velocity_polygon import answer as from_velocity_polygon

__all__ = ["answer_sliding", "slot_of", "sliding_askable"]


def slot_of(m: Mechanism, point: str) -> tuple[int, Slide]:
    """The straight slot of a moving link that ``point`` runs in, with its index among the
    mechanism's slides.

    Raises
    ------
    InputError
        If ``point`` runs in no straight slot of a moving link, naming those that do.
    """
    slots = [(i, s) for i, s in enumerate(m.slides) if s in m.slotted]
    for i, s in slots:
        if s.point == point:
            return i, s
    which = ", ".join(s.point for _, s in slots) or "none"
    raise InputError(f"point {point} runs in no straight slot of a moving link, so it has no "
                     f"sliding velocity of its own; the points that do: {which}")


def sliding_askable(m: Mechanism) -> set[str]:
    """``V_slide_P`` and ``A_slide_P`` of each point in a straight slot of a moving link."""
    return {f"{v}_slide_{s.point}" for s in m.slides if s in m.slotted for v in "VA"}


def answer_sliding(work, ask: A.Sliding) -> Answer:
    """V_Pi/Pj from the velocity polygon, or the sliding component Aˢ_Pi/Pj as the
    acceleration polygon draws it (0 where it draws none: the block is momentarily at
    constant sliding speed)."""
    _, s = slot_of(work.mechanism, ask.point)
    on, of = f"{ask.point}{s.link}", f"{ask.point}{s.guide_link}"
    if ask.letter == "V":
        found = from_velocity_polygon(work, A.Relative("V", on, of))
        return Answer(ask, found.value, found.conditioning, "velocity polygon (V_rel)",
                      refs=found.refs, arrows=found.arrows, figures=found.figures,
                      panel=found.panel)
    ap = drawn_acceleration_polygon(work)
    # The whole polygon answers through A_Pi (its conditioning, its figure); the sliding
    # component is the arrow it drew for Aˢ_Pi/Pj, or for −Aˢ_Pi/Pj from the other end.
    whole = from_acceleration_polygon(work, A.Acceleration(on))
    value, refs = vector_value(0.0, 0.0), ()
    for label, ref in ap.components.items():
        sign = -1.0 if label.startswith("−") else 1.0
        head, _, carried = label.lstrip("−").partition("/")
        # The slider's tip may be named on any link pinned at P (A2 for a block on the
        # crank pin A): the slot's own point names the component.
        if head.startswith("Aˢ_") and head[3:].rstrip("0123456789") == ask.point \
                and carried == of:
            x, y = ap.construction.output(ref).vector
            value, refs = vector_value(sign * x / ap.scale, sign * y / ap.scale), (ref,)
    return Answer(ask, value, whole.conditioning, "acceleration polygon (Aˢ)",
                  refs=refs + whole.refs, arrows=whole.arrows, figures=whole.figures,
                  panel=whole.panel)
