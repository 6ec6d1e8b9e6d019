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

from ..constructions.reference import solver
from ..constructions.reference.centres import centre_error, instant_centre, mechanism_size, tolerance
from ..constructions.assembly import Assembly, assemble
from ..constructions.centres import Centres, locate_centres, omega_ratio, pair_label
from ..constructions.errors import DegenerateInput, TarsimError
from ..constructions.polygon_walk import NOISE
from ..constructions.acceleration_polygon import AccelerationPolygon, draw_acceleration_polygon
from ..constructions.velocity_by_centres import METHODS as CENTRE_METHODS
from ..constructions.velocity_polygon import VelocityPolygon, draw_velocity_polygon
from ..constructions.record import Ref
from ..constructions.velocity_drawing import VelocityResult
from ..graphics.scene import choose_velocity_scale, velocity_scale_for

from .exercise_file import Exercise, Position

__all__ = ["Quantity", "Solution", "solve_exercise", "solve_positions"]


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
    kinematics: solver.Kinematics
    centres: Centres | None
    velocities: list[VelocityResult]
    quantities: dict[str, Quantity]
    velocity_scale: float | None
    notes: list[str]
    position_steps: frozenset[Ref]
    """The steps that located the mechanism; a figure's own steps are the others."""
    velocity_polygon: VelocityPolygon | None = None
    acceleration_polygon: AccelerationPolygon | None = None
    position: Position | None = None
    """Which of the exercise's positions this is (None: the file's [input] angle)."""

    @property
    def failures(self) -> list[Quantity]:
        """Quantities whose construction disagrees with the reference."""
        return [q for q in self.quantities.values() if not q.passed]


def solve_positions(ex: Exercise) -> list[Solution]:
    """Solve ``ex`` at each of its positions (or at its [input] angle if it lists none).

    Raises
    ------
    TarsimError
        As :func:`solve_exercise`, with the position named.
    """
    if not ex.positions:
        return [solve_exercise(ex)]
    out = []
    for p in ex.positions:
        try:
            sol = solve_exercise(ex.at(p))
        except TarsimError as e:
            raise type(e)(f"at {p.label}: {e}") from None
        sol.position = p
        out.append(sol)
    return out


def solve_exercise(ex: Exercise, velocity_scale: float | None = None) -> Solution:
    """Solve ``ex`` at its stated position.

    ``velocity_scale`` (drawing metres per m/s) fixes how long velocity vectors
    are drawn; by default it is the exercise's stated scale, or else the scene's
    nice scale for the input velocity.

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
    kin = solver.solve(mech)
    size = mechanism_size(kin)
    quantities: dict[str, Quantity] = {}
    notes: list[str] = []
    cs = None
    drawn = [m_ for m_ in ex.methods if m_ != "polygon"]   # the polygon is drawn once, below
    if ex.centres or ((ex.omegas or ex.velocities) and drawn):
        cs = locate_centres(asm)
        notes += cs.warnings()
    for pair in ex.centres:
        quantities[pair_label(*pair)] = _centre(cs, kin, pair, size)
    for n in ex.omegas if drawn else ():
        quantities[f"omega{n}"] = _omega(cs, kin, n)
    scale = velocity_scale
    if scale is None and ex.velocities and drawn:
        scale = (velocity_scale_for(asm, ex.velocity_per_cm) if ex.velocity_per_cm
                 else choose_velocity_scale(asm, mech.input_speed))
    results: list[VelocityResult] = []
    for p in ex.velocities if drawn else ():
        found = []
        for method in drawn:
            r = _velocity(asm, cs, p, method, scale)
            results.append(r)
            found.append(_velocity_quantity(asm, kin, r))
        first, rest = found[0], found[1:]
        quantities[f"V_{p}"] = _with_alternatives(first, {q.method: q for q in rest})
    vp = ap = None
    if ex.wants_polygon:
        vp, ap = _polygons(asm, ex.wants_accelerations)
        _polygon_quantities(ex, asm, kin, vp, ap, quantities)
        if ap is not None and not mech.drive.alpha_given:
            notes.append(f"α{mech.drive.link} is not given, so it is taken as 0.")
    return Solution(ex, asm, kin, cs, results, quantities, scale if results else None, notes,
                    position_steps, vp, ap)


def _polygons(asm, accelerations: bool) -> tuple[VelocityPolygon, AccelerationPolygon | None]:
    vp = draw_velocity_polygon(asm)
    return vp, (draw_acceleration_polygon(asm, vp) if accelerations else None)


def _polygon_quantities(ex: Exercise, asm, kin, vp: VelocityPolygon,
                        ap: AccelerationPolygon | None, quantities: dict) -> None:
    """Every quantity read off the polygons, beside its analytic value.

    An ω already found from the centres gets the polygon's as an alternative;
    with ``polygon`` the only method, the polygon's is the answer.
    """
    m = asm.mechanism
    c = asm.construction
    d = m.drive
    v_scale = m.input_speed
    a_scale = m.input_acceleration
    only = ex.methods == ("polygon",)
    for n in ex.omegas:
        q = _scalar(f"omega{n}", vp.omegas.get(n), kin.omegas[n], abs(d.omega),
                    _worst(c, vp.tips.values()), "velocity polygon")
        if only or f"omega{n}" not in quantities:
            quantities[f"omega{n}"] = q
        else:
            first = quantities[f"omega{n}"]
            quantities[f"omega{n}"] = _with_alternatives(first, {**first.alternatives,
                                                                 "velocity polygon": q})
    if "polygon" in ex.methods:
        for p in ex.velocities:
            link, point = _taken(m, p)
            q = _vector_quantity(f"V_{p}", vp.velocity(p),
                                 solver.point_velocity(kin, m, link, point), v_scale,
                                 _cond(c, vp.tip(p)), "velocity polygon")
            first = quantities.get(f"V_{p}")
            quantities[f"V_{p}"] = q if first is None or only else _with_alternatives(
                first, {**first.alternatives, "velocity polygon": q})
    for name in ex.relatives:
        kind, pair = name.split("_", 1)
        p, r = pair.split("/")
        poly, ref_of, scale = ((vp, solver.point_velocity, v_scale) if kind == "V" else
                               (ap, solver.point_acceleration, a_scale))
        # The answer is the arrow drawn from r's tip to p's, read at the polygon's scale.
        drawn = poly.between(*c[poly.draw_relative(p, r, m.units)].inputs)
        (ax, ay), (bx, by) = (ref_of(kin, m, *_taken(m, n)) for n in (p, r))
        cond = min(_cond(c, poly.tip(n)) for n in (p, r))
        quantities[name] = _vector_quantity(name, drawn, (ax - bx, ay - by), scale,
                                            cond, f"{'velocity' if kind == 'V' else 'acceleration'}"
                                                  " polygon")
    if ap is None:
        return
    for n in ex.alphas:
        quantities[f"alpha{n}"] = _scalar(f"alpha{n}", ap.alphas.get(n), kin.alphas[n],
                                          math.hypot(d.omega ** 2, d.alpha),
                                          _worst(c, ap.tips.values()), "acceleration polygon")
    for p in ex.accelerations:
        link, point = _taken(m, p)
        quantities[f"A_{p}"] = _vector_quantity(
            f"A_{p}", ap.acceleration(p), solver.point_acceleration(kin, m, link, point),
            a_scale, _cond(c, ap.tip(p)), "acceleration polygon")
    for p in ex.coriolis:
        quantities[f"A_cor_{p}"] = _vector_quantity(
            f"A_cor_{p}", ap.coriolis_of(p), _coriolis(kin, m, p), a_scale,
            _cond(c, ap.coriolis[p][1]), "acceleration polygon (2ω×v_rel)")


def _coriolis(kin, m, point: str) -> tuple[float, float]:
    """The analytic 2ω_j × (V_P − V_Pj) at the slot (straight or curved) ``point`` runs in."""
    joint = next(s for s in (*m.slides, *m.pin_arcs) if s.point == point and s.guide_link != 1
                 and point not in m.link(s.guide_link).names)
    j = joint.guide_link
    (px, py), (qx, qy) = (solver.point_velocity(kin, m, k, point) for k in (joint.link, j))
    w = kin.omegas[j]
    return -2.0 * w * (py - qy), 2.0 * w * (px - qx)


def _taken(m, name: str) -> tuple[int, str]:
    """The link a named point is taken on, and the point: ``B`` on its first moving carrier,
    ``A4`` as point A taken on link 4 (a coincident point under a slot)."""
    if name in m.point_names:
        carriers = [c for c in m.links_at(name) if c != 1] + \
                   [s.link for s in m.slides if s.point == name]
        return (carriers[0] if carriers else 1), name
    i = len(name.rstrip("0123456789"))
    return int(name[i:]), name[:i]


def _cond(c, ref) -> float:
    return c[ref].conditioning


def _worst(c, refs) -> float:
    """The worst conditioning of a polygon's tips: an ω or α read off it inherits it."""
    return min(c[r].conditioning for r in refs)


def _scalar(name: str, value: float | None, ref: float, scale: float, cond: float,
            method: str) -> Quantity:
    if value is None:
        raise TarsimError(f"{name} could not be read off the polygon")
    err = abs(value - ref) / max(abs(ref), scale, 1e-300)
    value, ref = (_quiet(v, scale) for v in (value, ref))
    return Quantity(name, {"value": value}, {"value": ref}, err, tolerance(cond), cond, method)


def _vector_quantity(name: str, value, ref, scale: float, cond: float, method: str) -> Quantity:
    (vx, vy), (rx, ry) = value, ref
    err = math.hypot(vx - rx, vy - ry) / max(math.hypot(rx, ry), scale, 1e-300)
    if math.hypot(vx, vy) <= NOISE * scale:
        vx = vy = 0.0
    if math.hypot(rx, ry) <= NOISE * scale:
        rx = ry = 0.0
    return Quantity(name, _vector(vx, vy), _vector(rx, ry), err, tolerance(cond), cond, method)


def _quiet(x: float, scale: float) -> float:
    """``x`` or 0 when it is rounding noise beside ``scale`` (the error is measured first)."""
    return 0.0 if abs(x) <= NOISE * scale else x + 0.0


def _velocity(asm, cs, point, method, scale) -> VelocityResult:
    if method in CENTRE_METHODS:
        return CENTRE_METHODS[method](asm, cs, point, scale=scale)
    from ..constructions.velocity_by_components import velocity_by_components
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
    rx, ry = solver.point_velocity(kin, m, r.link, r.point)
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
