"""The registry: every method tarsim draws, what it answers, and its analytic reference.

A solution walks it (:func:`~.methods.answer_all`). To add a method, write its
module (the construction and a ``construct(work, ask)`` that returns an
:class:`~.checks.Answer`), name its reference in :mod:`.expected`, and add one
:class:`~.methods.Method` here: see CONTRIBUTING.md.

The stages order a solution as the course does: centres, then angular
velocities from them, the velocities by the space diagram's methods (in the
order the exercise chooses them), the velocity polygon, the acceleration polygon;
and of the mechanism as a whole, its DOF, its Grashof class, its limit positions.
"""

from __future__ import annotations

from functools import partial

from . import asks as A
from . import expected
from .linkages.acceleration_parts import answer_part
from .linkages.acceleration_polygon import answer as from_acceleration_polygon
from .linkages.centre_answers import answer_centre, answer_count, answer_omega
from .linkages.limit_positions import WHY_NOT as LIMITS_WHY_NOT
from .linkages.limit_positions import answer as from_limits
from .linkages.limit_positions import askable as limits_askable
from .errors import TarsimError
from .methods import Method, Work
from .model import Mechanism
from .linkages.overall import GRASHOF_WHY_NOT, answer_grashof, answer_mobility, grashof_askable
from .linkages.equivalent import answer_equivalent, equivalent_askable
from .forces.answers import FORCES_WHY_NOT, answer as from_force_polygons, forces_askable
from .linkages.klein import answer_klein, klein_fits
from .linkages.positions import answer_position
from .linkages.readings import LEAST_WHY_NOT, MU_WHY_NOT, answer_reading, mu_askable
from .linkages.sliding import answer_sliding, sliding_askable
from .linkages.stroke_events import (STROKE_EVENT_WHY_NOT, answer_stroke_event,
                                     stroke_event_askable)
from .linkages.transmission import answer_omega as by_transmission, transmission_links
from .linkages.velocity_by_centres import answer_velocity as by_centres
from .linkages.velocity_by_components import answer_velocity as by_components
from .linkages.velocity_polygon import answer as from_velocity_polygon, wants_polygon

__all__ = ["METHODS", "CHOSEN", "askable", "why_not"]


_BY_CENTRES = ("radius-rotation", "parallel-line", "components")
"""The space diagram's velocity methods: choosing any of them draws the centres' ω too."""


def _transmission(work: Work, ask: A.AngularVelocity) -> bool:
    return ("line-of-transmission" in work.chosen
            and transmission_links(work.mechanism, ask.link) is not None)


def _velocity_polygon(work: Work, ask: A.Ask) -> bool:
    if isinstance(ask, A.Velocity):
        return "polygon" in work.chosen
    if isinstance(ask, A.Relative):
        return ask.letter == "V"
    return wants_polygon(work)


def _acceleration_polygon(work: Work, ask: A.Ask) -> bool:
    return not isinstance(ask, A.Relative) or ask.letter == "A"


def _velocity(name: str, construct) -> Method:
    return Method(name, {A.Velocity: expected.velocity}, construct, stage=2, chosen_by=(name,))


METHODS: tuple[Method, ...] = (
    Method("compass (assembly)", {A.Position: expected.position}, answer_position, stage=0),
    Method("instant centres", {A.Centre: expected.centre}, answer_centre, stage=0),
    Method("instant centres (ω ratio)", {A.AngularVelocity: expected.omega}, answer_omega,
           stage=1, chosen_by=_BY_CENTRES),
    _velocity("radius-rotation", partial(by_centres, method="radius-rotation")),
    _velocity("parallel-line", partial(by_centres, method="parallel-line")),
    _velocity("components", by_components),
    Method("klein", {A.Velocity: expected.velocity, A.Acceleration: expected.acceleration,
                     A.AngularVelocity: expected.omega, A.AngularAcceleration: expected.alpha},
           answer_klein, stage=2, chosen_by=("klein",), when=klein_fits),
    Method("velocity polygon", {A.AngularVelocity: expected.omega, A.Velocity: expected.velocity,
                                A.Relative: expected.relative},
           from_velocity_polygon, stage=3, chosen_by=("polygon",), when=_velocity_polygon),
    Method("line of transmission", {A.AngularVelocity: expected.omega}, by_transmission, stage=1,
           chosen_by=("line-of-transmission",), when=_transmission),
    Method("acceleration polygon", {A.AngularAcceleration: expected.alpha,
                                    A.Acceleration: expected.acceleration,
                                    A.Relative: expected.relative, A.Coriolis: expected.coriolis},
           from_acceleration_polygon, stage=4, when=_acceleration_polygon),
    Method("acceleration polygon (parts)", {A.AccelerationPart: expected.acceleration_part},
           answer_part, stage=4),
    Method("polygons (sliding)", {A.Sliding: expected.sliding}, answer_sliding, stage=4,
           askable=sliding_askable),
    Method("Grübler", {A.Mobility: expected.mobility}, answer_mobility, stage=5,
           askable=lambda mech: {"dof"}),
    Method("Grashof", {A.GrashofClass: expected.grashof, A.LengthRange: expected.length_range},
           answer_grashof, stage=6, askable=grashof_askable, why_not=GRASHOF_WHY_NOT),
    Method("limit positions", {A.TimeRatio: expected.time_ratio, A.Stroke: expected.stroke,
                               A.Swing: expected.swing},
           from_limits, stage=7, askable=limits_askable, why_not=LIMITS_WHY_NOT),
    Method("stroke events", {A.StrokeEvent: expected.stroke_event}, answer_stroke_event,
           stage=7, askable=stroke_event_askable, why_not=STROKE_EVENT_WHY_NOT),
    Method("circle diagram (count)", {A.CentreCount: expected.centre_count}, answer_count,
           stage=8),
    Method("equivalent linkage", {A.Equivalent: expected.equivalent}, answer_equivalent,
           stage=0, askable=equivalent_askable),
    Method("force polygons", {A.JointForce: expected.joint_force,
                              A.DrivingTorque: expected.driving_torque,
                              A.Effort: expected.effort},
           from_force_polygons, stage=9, askable=forces_askable, why_not=FORCES_WHY_NOT),
    Method("readings", {A.Ratio: expected.reading, A.MechanicalAdvantage: expected.reading,
                        A.Distance: expected.reading, A.TransmissionAngle: expected.reading,
                        A.LeastVelocity: expected.reading, A.Rubbing: expected.reading},
           answer_reading, stage=3, askable=mu_askable,
           why_not={**MU_WHY_NOT, **LEAST_WHY_NOT}),
)
"""Every method, in the order a solution takes them."""

CHOSEN: tuple[str, ...] = tuple(m.chosen_by[0] for m in METHODS
                                if m.chosen_by and len(m.chosen_by) == 1)
"""The names an exercise's ``[ask] methods`` chooses methods by."""


def askable(mech: Mechanism) -> set[str]:
    """Every name an exercise on ``mech`` may ask: its points' and links', and those of the
    methods that fit it as a whole."""
    out = A.ask_names(mech)
    for m in METHODS:
        if m.askable is not None:
            out |= m.askable(mech)
    return out


def why_not(name: str) -> str | None:
    """Why a mechanism may not be asked ``name`` (a time ratio of a mechanism with no limit
    construction), if a method says."""
    try:
        kind = type(A.parse_ask(name))
    except TarsimError:
        return None
    return next((m.why_not[kind] for m in METHODS if kind in m.why_not), None)
