"""A block's zero acceleration and greatest speed over a turn: ``A_P_zero`` and ``V_P_max``.

The crank is turned at a steady speed and the block's acceleration along its frame guide
scanned over the turn at once by the vectorised solver; each change of sign is narrowed
to the last bit by :func:`~.reference.limits.section_zero`, as ``tarsim sweep`` narrows
its zeros (:mod:`.reference.stroke_events` says where the angles are turned from). The
answers draw nothing: they stand in results.json's top-level quantities, checked against
the scalar solver's zeros found one position at a time.
"""

from __future__ import annotations

import math

import numpy as np

from .. import asks as A
from ..checks import Answer
from ..errors import AssemblyError
from ..model import Drive, Mechanism
from ..narration import narrate, phrase
from ..reference.limits import turn_zeros
from ..reference.stroke_events import StrokeEvents, stroke_events
from ..reference.turn import solve_turn
from .limit_positions import stroke_point

__all__ = ["answer_stroke_event", "stroke_event_askable", "event_value", "STROKE_EVENT_WHY_NOT",
           "turn_zeros_of"]

STROKE_EVENT_WHY_NOT = {A.StrokeEvent: "a zero acceleration and a greatest speed over the "
                                       "turn are of a block sliding on a frame guide, driven "
                                       "by a crank pivoted on the frame that turns fully "
                                       "(a piston, a ram)"}
"""Why a mechanism with no block on a frame guide has neither."""


def stroke_event_askable(mech: Mechanism) -> set[str]:
    """``A_P_zero`` and ``V_P_max`` of the block whose stroke the limit positions measure."""
    p = stroke_point(mech)
    crank = mech.link(mech.drive.link).names
    if p is None or "_" in p or not any(1 in mech.links_at(q) for q in crank):
        return set()                  # no block, or no crank turning about a frame pivot
    return {f"A_{p}_zero", f"V_{p}_max"}


def turn_zeros_of(mech: Mechanism, slide: int, start: float, sense: float) -> list[float]:
    """Where slide ``slide``'s acceleration is 0 over a turn from ``start``: the turn solved
    at once, each change of sign narrowed to neighbouring floats."""
    d = mech.drive

    def accelerations(angles: np.ndarray) -> np.ndarray:
        turn = solve_turn(mech.with_drive(Drive(d.link, d.angle, d.omega, 0.0)), angles)
        if not turn.ok.all():
            first = int(turn.ok.argmin())
            raise AssemblyError(f"the crank cannot turn fully: at θ{d.link} = "
                                f"{mech.units.angle_brief(float(angles[first]))} the "
                                "mechanism will not assemble").because(turn.refusal(first))
        return turn.slide_accelerations[slide]

    return turn_zeros(accelerations, start, sense)


def event_value(ev: StrokeEvents, ask: A.StrokeEvent) -> dict:
    """results.json's shape: angles in degrees turned from the dead centre (``crank_angle``
    the crank's own angle), the speed in m/s."""
    def deg(angle: float) -> float:
        return math.degrees(ev.turned(angle))

    if ask.letter == "A":
        first = ev.on_out_stroke[0] if ev.on_out_stroke else ev.zeros[0]
        return {"value": deg(first), "crank_angle": math.degrees(first) % 360.0,
                "zeros": [deg(z) for z in ev.zeros]}
    k = ev.fastest
    return {"value": ev.speeds[k], "angle": deg(ev.zeros[k]),
            "crank_angle": math.degrees(ev.zeros[k]) % 360.0}


def answer_stroke_event(work, ask: A.StrokeEvent) -> Answer:
    """The block's zero acceleration on the out-stroke, or its greatest speed and where."""
    ev = work.shared("stroke events", lambda: stroke_events(work.mechanism, ask.point,
                                                            turn_zeros_of))
    said = phrase("stroke.events")
    return Answer(ask, event_value(ev, ask), 1.0, narrate(said), said=said)
