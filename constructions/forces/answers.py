"""The force polygons as a method of the registry: the figures they are drawn in, the forces
an exercise may ask of a mechanism (and why not, where it may not), and each answer read off
the polygons with the conditioning of the acts it rests on.
"""

from __future__ import annotations

import math

from .. import asks as A
from ..linkages.acceleration_polygon import drawn_acceleration_polygon
from ..checks import Answer, FigureSpec, vector_value
from ..errors import TarsimError
from ..model import Mechanism
from ..record import Panel
from .equivalent import correction_couple, reversal_speed, rod_of
from .groups import Dyad, group_of
from .polygons import drawn_forces, inertia_torque
from .result import Forces
from .rounding import read_conditioning

__all__ = ["BODIES", "FORCES", "FORCES_WHY_NOT", "LOADS", "answer", "force_names",
           "forces_askable"]


FORCES = FigureSpec("forces", "Force polygons", "force polygons", kind="forces")
"""The figure the force polygons are drawn in."""

LOADS = FigureSpec("loads", "Loads", "space diagram with the loads", kind="loads")
"""The mechanism with every load and inertia force on it, at a force scale."""

BODIES = FigureSpec("free-bodies", "Free bodies", "free-body diagrams", kind="bodies")
"""Each link alone with every force on it."""


def force_names(mech: Mechanism) -> set[str]:
    """Every joint force, block couple and driving torque of ``mech``, as an exercise asks
    them: F_23 (of link 2 on link 3), T_14 (a block's couple from its guide), T2."""
    out = {f"T{mech.drive.link}"} | {f"F_{by}{on}" for _, by, on in mech.pin_pairs}
    for s in mech.slides:
        out.add(f"F_{s.guide_link}{s.link}")
        if s.type.turns_with_guide:                 # a block carries its guide's couple
            out.add(f"T_{s.guide_link}{s.link}")
    return out


FORCES_WHY_NOT = {kind: "the force polygons draw a four-bar, a slider-crank or a slotted lever, "
                        "naming its joints F_<by><on>, T_<guide><block> and T<input>"
                  for kind in (A.JointForce, A.DrivingTorque, A.Effort)}
"""Why a force is not askable: the mechanism is none the polygons draw, or has no such
joint. (The turning-moment diagram of ``tarsim sweep`` gives any mechanism's forces.)"""


def forces_askable(mech: Mechanism) -> set[str]:
    """The forces an exercise may ask of ``mech``, if the polygons draw it: its joints', the
    driving torque, the crank effort, its turning moment and the bearings' thrust, and a
    slider-crank's piston
    effort and wall thrust."""
    try:
        group = group_of(mech)
    except TarsimError:
        return set()
    out = force_names(mech) | {"crank_effort", "turning_moment", "bearing_thrust",
                               "flywheel_alpha"}
    if isinstance(group, Dyad) and group.guide is not None:
        out |= {"piston_effort", "wall_thrust", "inertia_force", "reversal_speed",
                "inertia_torque_reciprocating"}
        if rod_of(mech) is not None:
            out |= {"correction_couple", "rod_radius_of_gyration", "inertia_torque_rod"}
    return out


def _amplification(forces: Forces, size: float) -> float:
    """How many times the largest joint force outgrows the loads it comes from (1 at the
    least): a lever that multiplies its load so multiplies the rounding of everything drawn
    before it (a slot's direction through a block near its pivot), which no single act's
    conditioning sees."""
    loads = math.fsum(math.hypot(*f) + abs(m) / size for ls in forces.loads.values()
                      for _, f, m, _ in ls)
    biggest = max([math.hypot(*v) for v in forces.joints.values()] + [0.0])
    return max(1.0, biggest / loads) if loads > 0.0 else 1.0


def answer(work, ask) -> Answer:
    """A joint force, a block's couple or the driving torque, read off the force polygons.

    Its conditioning is the worst of the acts it rests on: the crossing that closes the
    dyad's polygon (or the lever's), whose forces every later polygon takes in as numbers,
    so the crank's answers inherit it; and the acceleration polygon the inertia loads are
    read off, both its worst act and what its rounding of each load, levered through the
    group, makes of this answer beside the loads' scale (:mod:`~.rounding`).
    """
    forces = drawn_forces(work)
    c = work.assembly
    read_as = ask               # whose rounding the answer carries
    if isinstance(ask, A.DrivingTorque):
        value = {"value": forces.torque}
    elif isinstance(ask, A.Effort) and ask.word == "correction_couple":
        # the rod's α off the acceleration polygon, with its mass split between its pins
        rod = rod_of(work.mechanism)[0]
        alpha = drawn_acceleration_polygon(work).rates.get(rod, 0.0)
        value = {"value": correction_couple(work.mechanism, work.loads, alpha)}
    elif isinstance(ask, A.Effort) and ask.word == "reversal_speed":
        value = {"value": reversal_speed(work.mechanism, forces.efforts["piston_effort"],
                                         forces.efforts["inertia_force"])}
    elif isinstance(ask, A.Effort) and ask.word.startswith("inertia_torque_"):
        # one part's inertia loads alone through the same polygons: the piston, or the rod
        part = group_of(work.mechanism).j if ask.word.endswith("reciprocating") \
            else rod_of(work.mechanism)[0]
        if work.loads.mass_of(part) is None:
            raise TarsimError(f"{ask.word} is the turning moment of link {part}'s inertia "
                              f"loads alone: give link {part} a [[mass]]")
        value = {"value": inertia_torque(work, part)}
        read_as = A.Effort("turning_moment")    # the turning moment's rounding
    elif isinstance(ask, A.Effort) and ask.word == "rod_radius_of_gyration":
        m = work.loads.mass_of(rod_of(work.mechanism)[0])
        if m is None or m.inertia == 0.0:
            raise TarsimError("rod_radius_of_gyration is the connecting rod's √(I/m) about G: "
                              "give the rod a [[mass]] with its inertia (or a pendulum test)")
        value = {"value": math.sqrt(m.inertia / m.mass)}
    elif isinstance(ask, A.Effort) and ask.word == "flywheel_alpha":
        if "flywheel_alpha" not in forces.efforts:
            raise TarsimError("flywheel_alpha is (T − T_mean)/I: give [forces] flywheel = 136.8 "
                              "(kg·m²) and the engine's power = 22000 (W) or its mean_torque "
                              "(N·m)")
        value = {"value": forces.efforts[ask.word]}
        read_as = A.Effort("turning_moment")    # T's rounding over a given I and T_mean
    elif isinstance(ask, A.Effort):
        value = {"value": forces.efforts[ask.word]}
    elif ask.letter == "T":
        value = {"value": forces.couples[ask.name]}
    else:
        value = vector_value(*forces.joints[ask.name])
    cond = min([c[r].conditioning for refs in forces.refs.values() for r in refs] + [1.0])
    if work.has("acceleration polygon"):
        cond *= drawn_acceleration_polygon(work).worst()
    cond = min(cond / _amplification(forces, work.assembly.size),
               read_conditioning(work, forces, read_as))
    return Answer(ask, value, cond, "force polygons", refs=forces.every,
                  figures=(LOADS, FORCES, BODIES), panel=Panel.FORCE)
