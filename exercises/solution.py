"""A worked solution: run the constructions an exercise asks for and check every number.

Each asked quantity is found graphically (its construction is recorded), read
off the drawing, and put beside the independent analytic value with the relative
error and the tolerance its conditioning allows. Nothing here draws (only the
velocity scale is the scene's choice): the figures and files are made from a
:class:`Solution` by :mod:`exercises.solution_files`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from constructions import analytic
from constructions.analytic_centres import centre_error, instant_centre, mechanism_size, tolerance
from constructions.assembly import Assembly, assemble
from constructions.centres import Centres, locate_centres, omega_ratio, pair_label
from constructions.errors import DegenerateInput, TarsimError
from constructions.velocity_by_centres import METHODS as CENTRE_METHODS
from constructions.record import Ref
from constructions.velocity_drawing import VelocityResult
from graphics.scene import choose_velocity_scale

from .exercise_file import Exercise

__all__ = ["Quantity", "Solution", "solve_exercise"]


@dataclass(frozen=True)
class Quantity:
    """One asked quantity: by construction, by the analytic solver, and how far apart.

    ``value`` and ``reference`` are in results.json's shape (SI units).
    """

    name: str
    value: dict[str, Any]
    reference: dict[str, Any]
    rel_error: float
    tolerance: float
    conditioning: float
    method: str
    alternatives: dict[str, Quantity] = field(default_factory=dict)

    @property
    def passed(self) -> bool:
        """Whether the construction agrees with the reference within its tolerance."""
        return self.rel_error <= self.tolerance and all(
            q.passed for q in self.alternatives.values())


@dataclass
class Solution:
    """Everything one position of an exercise produced."""

    exercise: Exercise
    assembly: Assembly
    kinematics: analytic.Kinematics
    centres: Centres | None
    velocities: list[VelocityResult]
    quantities: dict[str, Quantity]
    velocity_scale: float | None
    notes: list[str]
    position_steps: frozenset[Ref]
    """The steps that located the mechanism; a figure's own steps are the others."""

    @property
    def failures(self) -> list[Quantity]:
        """Quantities whose construction disagrees with the reference."""
        return [q for q in self.quantities.values() if not q.passed]


def solve_exercise(ex: Exercise, velocity_scale: float | None = None) -> Solution:
    """Solve ``ex`` at its stated position.

    ``velocity_scale`` (drawing metres per m/s) fixes how long velocity vectors
    are drawn; by default it is the scene's nice scale for the input velocity.

    Raises
    ------
    TarsimError
        If the mechanism cannot be assembled, is singular at this position, or a
        construction breaks down; the message says which and where.
    """
    mech = ex.mechanism
    if mech.drive.omega == 0.0 and (ex.omegas or ex.velocities):
        raise TarsimError("the exercise asks for velocities but [input] gives no omega; "
                          "state the input's angular velocity")
    asm = assemble(mech)
    position_steps = frozenset(asm.construction.steps)
    kin = analytic.solve(mech)
    size = mechanism_size(kin)
    quantities: dict[str, Quantity] = {}
    notes: list[str] = []
    cs = None
    if ex.centres or ex.omegas or ex.velocities:
        cs = locate_centres(asm)
        notes += cs.warnings()
    for pair in ex.centres:
        quantities[pair_label(*pair)] = _centre(cs, kin, pair, size)
    for n in ex.omegas:
        quantities[f"omega{n}"] = _omega(cs, kin, n)
    scale = velocity_scale
    if scale is None and ex.velocities:
        scale = choose_velocity_scale(asm, mech.input_speed)
    results: list[VelocityResult] = []
    for p in ex.velocities:
        found = []
        for method in ex.methods:
            r = _velocity(asm, cs, p, method, scale)
            results.append(r)
            found.append(_velocity_quantity(asm, kin, r))
        first, rest = found[0], found[1:]
        quantities[f"V_{p}"] = _with_alternatives(first, {q.method: q for q in rest})
    return Solution(ex, asm, kin, cs, results, quantities, scale if results else None, notes,
                    position_steps)


def _velocity(asm, cs, point, method, scale) -> VelocityResult:
    if method in CENTRE_METHODS:
        return CENTRE_METHODS[method](asm, cs, point, scale=scale)
    from constructions.velocity_by_components import velocity_by_components
    return velocity_by_components(asm, point, scale=scale)


def _centre(cs: Centres, kin, pair, size) -> Quantity:
    p = cs.point(*pair)
    cond = cs.conditioning(*pair)
    if p.is_at_infinity:
        value = {"at_infinity": True, "direction": list(p.direction)}
    else:
        value = {"point": list(p.xy)}
    c = cs.centre(*pair)
    method = {"pin": "inspection (pin)", "block": "inspection (block on a straight guide)",
              "curved": "inspection (block on a curved guide: centre of curvature)",
              "rolling": "inspection (rolling contact: the contact point)",
              "kennedy": "Kennedy (circle diagram)",
              "velocities": "Kennedy line and velocity ratio"}[c.rule]
    try:
        ref = instant_centre(kin, *pair)
    except DegenerateInput as e:
        if not c.primary:
            raise TarsimError(f"{pair_label(*pair)} has no analytic reference here: {e}") from None
        # A joint's own centre holds at every instant, even one with no relative
        # motion (a block momentarily at rest in its slot), where any point would do.
        return Quantity(pair_label(*pair), value, {"undefined": str(e)}, 0.0, tolerance(1.0),
                        cond, method)
    reference = ({"at_infinity": True, "direction": list(ref.direction)} if ref.is_at_infinity
                 else {"point": list(ref.point)})
    # A direction is judged by angle alone, so its tolerance does not grow with distance.
    # The reference's own rounding (large when ω_i ≈ ω_j) is added to the tolerance.
    tol = tolerance(1.0 if p.is_at_infinity else cond) + ref.rounding
    return Quantity(pair_label(*pair), value, reference, centre_error(p, ref, size), tol, cond,
                    method)


def _omega(cs: Centres, kin, n: int) -> Quantity:
    m = cs.assembly.mechanism
    d = m.drive
    if n == d.link:
        return Quantity(f"omega{n}", {"value": d.omega}, {"value": kin.omegas[n]}, 0.0,
                        tolerance(1.0), 1.0, "given")
    try:
        ratio = omega_ratio(cs, d.link, n)
    except DegenerateInput as e:
        raise TarsimError(f"ω{n} from the instant centres: {e}") from None
    w = ratio * d.omega + 0.0
    ref = kin.omegas[n]
    cond = min(cs.conditioning(1, n), cs.conditioning(d.link, n), cs.conditioning(1, d.link))
    err = abs(w - ref) / abs(d.omega)
    return Quantity(f"omega{n}", {"value": w}, {"value": ref}, err, tolerance(cond), cond,
                    "instant centres (ω ratio)")


def _velocity_quantity(asm, kin, r: VelocityResult) -> Quantity:
    m = asm.mechanism
    vx, vy = r.value(asm.construction)
    rx, ry = analytic.point_velocity(kin, m, r.link, r.point)
    # Relative to the input speed too, so a point at rest (dead centre) has a scale.
    err = math.hypot(vx - rx, vy - ry) / max(math.hypot(rx, ry), m.input_speed)
    cond = asm.construction[r.vector].conditioning
    return Quantity(f"V_{r.point}", _vector(vx, vy), _vector(rx, ry), err, tolerance(cond),
                    cond, r.method)


def _vector(x: float, y: float) -> dict[str, Any]:
    return {"value": math.hypot(x, y), "vector": [x + 0.0, y + 0.0]}


def _with_alternatives(q: Quantity, alternatives: dict[str, Quantity]) -> Quantity:
    return Quantity(q.name, q.value, q.reference, q.rel_error, q.tolerance, q.conditioning,
                    q.method, alternatives)
