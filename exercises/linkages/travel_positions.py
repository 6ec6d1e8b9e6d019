"""A position given as the books give an engine's: by the piston's travel from the inner
dead centre ("when the piston has moved one-fourth of its stroke"), as ``at = [{ stroke =
"1/4" }]`` or ``at = [{ travel = 75 }]``.

The crank angle is found as the draftsman finds it, from the dead centres: the piston's two
reversals (:func:`~tarsim.constructions.reference.limits.limit_reference`) bound the
out-stroke, the inner one the piston's place farthest from the crank's pivot (the crank
pointing at the piston, the books' i.d.c. and a vertical engine's t.d.c.); along the
out-stroke, turning with ω, the travel grows from 0 to the stroke, and the angle where it is
the one asked is narrowed to the last bit. Every construction then starts from that angle,
so the number asked at the position is drawn and checked as at any other angle.
"""

from __future__ import annotations

import math

import numpy as np

from tarsim.constructions.errors import TarsimError
from tarsim.constructions.linkages.limit_positions import limit_kind, stroke_point
from tarsim.constructions.model import Drive, Mechanism
from tarsim.constructions.reference.limits import limit_reference, section_zero
from tarsim.constructions.reference.solver import solve_positions
from tarsim.constructions.reference.turn import solve_turn

__all__ = ["TRAVEL_KEYS", "crank_angle_at_travel", "dead_centre_word"]

TRAVEL_KEYS = ("stroke", "travel")
"""``at``'s keys for a position by the piston's travel: a share of the stroke, or a length."""


def crank_angle_at_travel(mech: Mechanism, *, share: float | None = None,
                          travel: float | None = None) -> tuple[float, float, float, float]:
    """The crank angle (rad) on the out-stroke where the piston has travelled ``share`` of
    its stroke (or ``travel`` metres) from the inner dead centre; with the travel and the
    stroke (m), and the angle (rad) the crank has turned from the inner dead centre, as the
    books ask it ("the angle turned by the crank from the t.d.c.").

    Raises
    ------
    ValueError
        Saying what is wrong (not a slider-crank, a travel past the stroke), for the
        caller to place at its file:line.
    """
    if limit_kind(mech) != "slider-crank":
        raise ValueError("a position by the piston's travel needs a crank driving a block on "
                         "a frame guide through a rod (a slider-crank); give its angle")
    point = stroke_point(mech)
    slide = next(i for i, s in enumerate(mech.slides) if s.point == point and s.guide_link == 1)
    d = mech.drive
    try:
        reversals = limit_reference(mech, point=point)
    except TarsimError as e:
        raise ValueError(f"the piston {point} has no dead centres to travel from: {e}") from None
    stroke = reversals.stroke
    wanted = share * stroke if share is not None else travel
    if not 0.0 <= wanted <= stroke * (1 + 1e-12):
        raise ValueError(f"a travel of {wanted / mech.units.metres:.6g} {mech.units.length} "
                         f"is past the piston's stroke, {stroke / mech.units.metres:.6g} "
                         f"{mech.units.length}")
    pivot = mech.link(d.link).names[0]

    def from_pivot(theta: float) -> float:
        at = solve_positions(mech.with_drive(Drive(d.link, theta, d.omega, d.alpha)))
        return math.dist(at[point], at[pivot])

    outer, inner = sorted(reversals.crank_angles, key=from_pivot)    # inner: the farthest
    sense = 1.0 if d.omega >= 0 else -1.0
    span = (sense * (outer - inner)) % math.tau

    def place(thetas) -> np.ndarray:
        return solve_turn(mech, np.asarray(thetas)).slide_positions[slide]

    start = float(place([inner])[0])

    def short(thetas) -> np.ndarray:          # travel so far less the travel wanted
        return np.abs(place(thetas) - start) - wanted

    if wanted <= 0.0:
        return inner % math.tau, wanted, stroke, 0.0
    if wanted >= stroke:
        return outer % math.tau, wanted, stroke, span
    theta = section_zero(short, inner, inner + sense * span, -wanted)
    return theta % math.tau, wanted, stroke, (sense * (theta - inner)) % math.tau


def dead_centre_word(mech: Mechanism) -> str:
    """How the books name the dead centre a piston's travel starts from: the top dead centre
    of a vertical engine (its line of stroke within a degree of upright), else the inner."""
    point = stroke_point(mech)
    slide = next(s for s in mech.slides if s.point == point and s.guide_link == 1)
    return "t.d.c." if abs(slide.direction[0]) < math.sin(math.radians(1)) else "i.d.c."
