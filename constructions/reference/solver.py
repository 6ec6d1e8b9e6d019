"""The independent analytic reference: one position's kinematics from the loop equations.

The position is first found in closed form, dyad by dyad, honouring the branches
(:mod:`.dyad_assembly`; see :func:`solve`), then polished by Newton on the full ``Φ``
(:mod:`.loop_equations`). Velocities solve ``Φ_q q̇ = −Φ_t`` and accelerations
``Φ_q q̈ = −(Φ_q q̇)_q q̇ − Φ_tt``; both are differentiated exactly, never by finite
differences. What a solve gives and how it refuses a dead point live in :mod:`.kinematics`.

This module shares no code with the graphical constructions: it imports only
numpy, the standard library, :mod:`constructions.model` and
:mod:`constructions.errors`.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..errors import AssemblyError, InputError
from ..model import Mechanism
from .dyad_assembly import _Assembly
# What a solve returns and raises, and how it is read: the solver is their public entry point.
from .kinematics import (SINGULAR_RCOND, FreeMotion, Kinematics, SingularPosition, SlideRate,
                         _acceleration, _dead_point, _velocity, point_acceleration,
                         point_velocity)
from .loop_equations import _System
from .planar import _EPS, _S, _rot, _unit, _wrap

__all__ = [
    "Kinematics",
    "FreeMotion",
    "SlideRate",
    "SingularPosition",
    "SINGULAR_RCOND",
    "solve",
    "solve_positions",
    "point_velocity",
    "point_acceleration",
    "constraint_jacobian",
    "follow_branches",
]

_NEWTON_STEPS = 12


def _check(mech: Mechanism) -> None:
    d = mech.drive
    numbers = [d.angle, d.omega, d.alpha]
    numbers += [c for k in mech.links for _, xy in k.points for c in xy]
    numbers += [c for s in mech.slides for c in (*s.through, *s.direction)]
    if not all(math.isfinite(v) for v in numbers):
        raise InputError("a coordinate or an input value is not a finite number",
                         file=mech.source or None)
    if mech.drive.link == 1:
        raise InputError("the input cannot be the frame (link 1)", file=mech.source or None)
    mech.link(mech.drive.link)
    for s in mech.slides:
        if s.link == s.guide_link:
            raise InputError(f"{s.label}: a link cannot slide on itself", file=mech.source or None)
        if s.point not in mech.link(s.link).names:
            raise InputError(f"{s.label}: link {s.link} has no point {s.point}; list it on the "
                             f"link", file=mech.source or None)
        mech.link(s.guide_link)
        _unit(s.direction)
    for a in mech.arcs:
        for k, name in ((a.link, a.point), (a.guide_link, a.centre)):
            if name not in mech.link(k).names:
                raise InputError(f"{a.label}: link {k} has no point {name}",
                                 file=mech.source or None)
        if a.link == a.guide_link or not a.radius > 0.0:
            raise InputError(f"{a.label}: an arc joins two links at a positive radius",
                             file=mech.source or None)
    n = mech.mobility()[0]
    if n != 1:
        raise AssemblyError(f"the mechanism has {n} degrees of freedom by Grübler; the analytic "
                            f"solver needs exactly one (one input)", link=mech.drive.link)


def _singular(system: _System, jac: np.ndarray) -> tuple[float, SingularPosition | None]:
    _, sv, vt = np.linalg.svd(system.scaled(jac))
    rcond = float(sv[-1] / sv[0]) if sv[0] > 0.0 else 0.0
    if rcond >= SINGULAR_RCOND:
        return rcond, None
    null = np.abs(vt[-1]).reshape(-1, 3).max(axis=1)
    error = _dead_point(system.m, [k for k, v in zip(system.moving, null)
                                   if v >= 0.2 * null.max()])
    error.detail = f"the loop equations' Jacobian is singular there: rcond {rcond:.1e}"
    return rcond, error


def constraint_jacobian(mech: Mechanism) -> np.ndarray:
    """The length-scaled Jacobian of every joint's constraints at ``mech``'s position.

    Columns are the moving links' x, y, φ; rows every constraint but the input's,
    so its nullity is the mechanism's mobility (:mod:`.mobility`).
    """
    system, q = _start(mech)
    return system.scaled(system.jacobian(q))[:-1]        # the last row is the input's


def follow_branches(mech: Mechanism) -> Mechanism:
    """``mech`` with each near-point branch replaced by the side it takes at the stated
    input position.

    A point says which assembly the drawing shows; turned to another input angle, the
    linkage stays in that assembly (it cannot jump to the other without being taken
    apart), while the point nearest a fixed place may lie on the other. A mechanism that
    will not assemble at its stated position is returned as it is.

    >>> from tarsim.constructions.model import Drive, Link, Mechanism
    >>> m = Mechanism((Link(1, (("O2", (0, 0)), ("O4", (3, 0)))),
    ...                Link(2, (("O2", (0, 0)), ("A", (1, 0)))),
    ...                Link(3, (("A", (0, 0)), ("B", (3, 0)))),
    ...                Link(4, (("O4", (0, 0)), ("B", (2, 0))))),
    ...               Drive(2, 1.0, omega=1.0), branches={"B": (5.0, 0.0)})
    >>> follow_branches(m).branches
    {'B': 'left'}
    """
    if all(isinstance(b, str) for b in mech.branches.values()):
        return mech
    _check(mech)
    try:
        picked = _Assembly(mech)
        picked.run()
    except AssemblyError:
        return mech
    return replace(mech, branches={n: picked.picked.get(n, b) if not isinstance(b, str) else b
                                   for n, b in mech.branches.items()})


def _start(mech: Mechanism) -> tuple[_System, np.ndarray]:
    """The loop equations and the closed-form start vector of body coordinates."""
    _check(mech)
    system = _System(mech)
    poses = _Assembly(mech).run()
    q = np.zeros(3 * len(system.moving))
    for k in system.moving:
        (x, y), phi = poses[k]
        q[system.col[k]:system.col[k] + 3] = (x, y, phi)
    return system, q


def _conditioned(system: _System, q: np.ndarray,
                 jac: np.ndarray | None = None) -> tuple[np.ndarray, float]:
    """Return the Jacobian at ``q`` (``jac``, if it is known) and its rcond; raise at a
    dead point."""
    if jac is None:
        jac = system.jacobian(q)
    rcond, err = _singular(system, jac)
    if err is not None:
        raise err
    return jac, rcond


def _newton(system: _System, q: np.ndarray,
            jac: np.ndarray) -> tuple[np.ndarray, np.ndarray | None, np.ndarray | None]:
    """Polish a well-conditioned start until the scaled residual is at round-off.

    Returns the polished ``q`` with its Jacobian and residual where the polish had them
    at that ``q`` already (else None): the closed-form start is usually at round-off, so
    the caller need not form them again.
    """
    res = None
    for _ in range(_NEWTON_STEPS):
        res = system.residual(q)
        if system.scaled_max(res) <= 4 * _EPS:
            return q, jac, res
        dq = np.linalg.solve(jac, -res)
        q = q + dq
        if np.max(np.abs(dq)) <= 4 * _EPS * system.lc:
            return q, None, None
        jac = system.jacobian(q)
    return q, jac, None


def solve(mech: Mechanism) -> Kinematics:
    """Solve the position, velocity and acceleration of ``mech`` at its input position.

    The closed-form start honours ``mech.branches``:

    - a point cut from two arcs (a pin of links i < j, each with one other located
      point X on i and Y on j) takes ``left``/``right`` of the directed line X → Y;
    - a point cut from an arc and a located guide line takes ``forward``/``backward``
      along the guide's global direction;
    - a block at a located point P in the slot of a link turning about its one
      located point Q takes ``forward`` (the default: P lies ahead of the foot of Q
      along the slot's global direction) or ``backward``; if P's branch was already
      spent locating P, the default applies;
    - an ``(x, y)`` near point takes the solution nearer that point (for a slotted
      lever: the one whose slot direction points more nearly from Q towards it).

    Parameters
    ----------
    mech : Mechanism
        A single-input mechanism (Grübler mobility 1) in SI units.

    Returns
    -------
    Kinematics
        Positions, angles, ω, α, point velocities and accelerations, slide rates.

    Raises
    ------
    AssemblyError
        If a link cannot reach (the message names the link and its length), the
        mobility is not 1, or no dyad order exists (the mechanism needs a triad).
    SingularPosition
        At a dead point, where the Jacobian is singular.
    InputError
        If a branch is missing or invalid, or a slide names an unknown point.

    Examples
    --------
    A parallelogram four-bar (ground and coupler 4, crank and rocker 3) at θ2 = 90°:

    >>> from tarsim.constructions.model import Drive, Link, Mechanism
    >>> import math
    >>> m = Mechanism((Link(1, (("O2", (0, 0)), ("O4", (4, 0)))),
    ...                Link(2, (("O2", (0, 0)), ("A", (3, 0)))),
    ...                Link(3, (("A", (0, 0)), ("B", (4, 0)))),
    ...                Link(4, (("O4", (0, 0)), ("B", (3, 0))))),
    ...               Drive(2, math.pi / 2, omega=1.0), branches={"B": "left"})
    >>> kin = solve(m)
    >>> tuple(round(c, 12) + 0.0 for c in kin.points["B"])
    (4.0, 3.0)
    >>> round(kin.omegas[3], 12) + 0.0, round(kin.omegas[4], 12) + 0.0
    (0.0, 1.0)
    """
    system, start = _start(mech)
    jac, rcond = _conditioned(system, start)
    q, polished_jac, res = _newton(system, start, jac)
    if q is not start:                      # polished: the Jacobian and its rcond anew
        jac, rcond = _conditioned(system, q, polished_jac)
    if res is None:
        res = system.residual(q)
    if system.scaled_max(res) > 1e-10:
        raise AssemblyError(f"the position polish did not converge at input angle "
                            f"{mech.units.angle_brief(mech.drive.angle)} (residual "
                            f"{system.scaled_max(res):.1e})", link=mech.drive.link)
    rhs = np.zeros(len(system.is_len))
    rhs[-1] = mech.drive.omega
    qd = np.linalg.solve(jac, rhs)
    qdd = np.linalg.solve(jac, system.gamma(q, qd))
    return _pack(system, q, qd, qdd, rcond, _free_motion(system, jac),
                 float(np.max(np.abs(res))))


def solve_positions(mech: Mechanism) -> dict[str, tuple[float, float]]:
    """Solve only where every point is: the vector loops without their derivatives.

    At or near a dead point the velocities are undefined but the position is not,
    so this does not refuse it: the closed-form start is polished by Newton only
    where the Jacobian is well conditioned.

    Raises
    ------
    AssemblyError
        As :func:`solve`, except at dead points.
    """
    system, q = _start(mech)
    jac = system.jacobian(q)
    if _singular(system, jac)[1] is None:
        q = _newton(system, q, jac)[0]
    return {n: _point(system, q, n) for n in mech.point_names}


def _point(system: _System, q: np.ndarray, name: str) -> tuple[float, float]:
    at = system.m.links_at(name)
    k = 1 if 1 in at else at[0]
    t, f = system.state(q, k)
    p = t + _rot(f) @ system.loc[k, name]
    return (float(p[0]), float(p[1]))


def _free_motion(system: _System, jac: np.ndarray) -> FreeMotion:
    """The null vector of the Jacobian without the input's row (see :class:`FreeMotion`),
    signed so that the input turns as its ω does."""
    _, sv, vt = np.linalg.svd(system.scaled(jac)[:-1])
    rates = vt[-1] * system.col_scale
    w = system.state(rates, system.m.drive.link)[1]
    if w * system.m.drive.omega < 0.0:
        rates = -rates
    omegas, velocities = {}, {}
    for k in system.moving:
        v, omegas[k] = system.state(rates, k)
        velocities[k] = (float(v[0]), float(v[1]))
    return FreeMotion(omegas, velocities, float(sv[-1] / sv[0]) if sv[0] > 0.0 else 0.0)


def _pack(system: _System, q, qd, qdd, rcond: float, free: FreeMotion,
          residual: float) -> Kinematics:
    mech = system.m
    origins, angles, vel0, omegas, acc0, alphas = {}, {}, {}, {}, {}, {}
    for k in [1] + system.moving:
        (t, f), (v, w), (a, al) = system.state(q, k), system.state(qd, k), system.state(qdd, k)
        origins[k], angles[k] = (float(t[0]), float(t[1])), _wrap(f)
        vel0[k], omegas[k] = (float(v[0]), float(v[1])), float(w)
        acc0[k], alphas[k] = (float(a[0]), float(a[1])), float(al)
    points, vels, accs = {}, {}, {}
    for n in mech.point_names:
        at = mech.links_at(n)
        k = 1 if 1 in at else at[0]
        t, f = system.state(q, k)
        p = t + _rot(f) @ system.loc[k, n]
        points[n] = (float(p[0]), float(p[1]))
        vels[n] = _velocity(p, origins[k], vel0[k], omegas[k])
        accs[n] = _acceleration(p, origins[k], acc0[k], omegas[k], alphas[k])
    rates = []
    for s, through, d, _ in system.slides:
        p, g, dg, arm_l, arm_g = system._slide_terms(q, s, through, d)
        (vl, wl), (vg, wg) = system.state(qd, s.link), system.state(qd, s.guide_link)
        (al, bl), (ag, bg) = system.state(qdd, s.link), system.state(qdd, s.guide_link)
        e, sd = p - g, _S @ dg
        e_dot = vl + wl * (_S @ arm_l) - vg - wg * (_S @ arm_g)
        e_ddot = (al + bl * (_S @ arm_l) - wl ** 2 * arm_l
                  - ag - bg * (_S @ arm_g) + wg ** 2 * arm_g)
        speed = wg * float(sd @ e) + float(dg @ e_dot)
        accel = (bg * float(sd @ e) - wg ** 2 * float(dg @ e) + 2.0 * wg * float(sd @ e_dot)
                 + float(dg @ e_ddot))
        cor = 2.0 * wg * speed * sd
        rates.append(SlideRate(s, float(dg @ e), speed, accel, (float(dg[0]), float(dg[1])),
                               (float(cor[0]), float(cor[1]))))
    return Kinematics(points, angles, omegas, alphas, vels, accs, tuple(rates), residual,
                      rcond, origins, vel0, acc0, free)
