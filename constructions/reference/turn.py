"""Solve a whole turn of the input at once: the analytic solver vectorised over positions.

:func:`solve_turn` gives what :func:`.solver.solve` gives at each of N input angles,
as arrays, with the same verdicts: a position the scalar solver refuses (a link that
cannot reach; a dead point, whose rcond is below ``SINGULAR_RCOND``) is marked in
``ok`` and its reason is :meth:`Turn.refusal`, never a number.

How, and why it agrees with the scalar solver to round-off:

1. the scalar assembly runs once, recording its acts (:mod:`.assembly_plan`); the
   acts are replayed over all the angles with numpy (the same closed forms);
2. Newton polishes, as the scalar solver does, only the rows whose scaled residual
   is above 4 eps, in a batch (:mod:`.batch_loops`);
3. the Jacobians of the batch are inverted at once, the pins' translations eliminated
   first (:mod:`.pin_elimination`: a four-bar's 9 × 9 becomes a 3 × 3 written out,
   where LAPACK would take a call a position); ``q̇ = ω Φ_q⁻¹ e_input`` and
   ``q̈ = Φ_q⁻¹ γ``. The inverse also gives the conditioning cheaply:
   ``r = 1 / (‖J‖_F ‖J⁻¹‖_F)`` of the length-scaled Jacobian is a lower bound of the
   scalar solver's rcond, within a factor of its column count; only where that bound
   is below ``TRUSTED`` is the rcond itself taken, by a batched SVD of those rows;
4. a position whose verdict or numbers the replay cannot vouch for goes to the scalar
   solver itself: a reach within a few slacks of its verdict, a cut near tangency,
   a Jacobian whose rcond is below ``TRUSTED`` (where the two solvers' round-off,
   amplified by 1/rcond², could differ by more than 1e-12), a near point nearly
   equidistant from both solutions, a polish that does not converge. Dead points
   are always among these, so their verdict is the scalar solver's own.

:class:`TurnSolver` keeps what is the same at every angle (the equations, the pins'
tree, the recorded acts) for a search that solves a few dozen angles a round.

Every mechanism the scalar solver assembles dyad by dyad replays; there is no
mechanism-wide fallback. One whose assembly fails at every angle, or is refused
whatever the angle (mobility ≠ 1, a triad), has every position refused. A missing
branch raises the scalar solver's InputError, as a loop of scalar solves would.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from .assembly_plan import AssemblyPlan, record_plan
from .batch_loops import BatchLoops, wrap
from .loop_equations import _System
from .pin_elimination import Inverse, PinElimination
from .planar import _EPS
from .solver import _NEWTON_STEPS, Kinematics, SingularPosition, _check, solve
from ..errors import AssemblyError
from ..model import Mechanism

__all__ = ["Turn", "solve_turn", "TurnSolver", "TRUSTED"]

TRUSTED = 2e-2
"""Below this rcond of the scaled Jacobian a position goes to the scalar solver.

Near a dead point the two solvers' round-off is amplified: velocities differ by about
eps/rcond and accelerations, which use the velocities, by eps/rcond² of their scale
(measured: 4e-11 at rcond 0.004, 5e-12 at 0.007). Above 2e-2 that is below 1e-12.
"""


@dataclass(frozen=True)
class Turn:
    """Positions, velocities and accelerations at N input angles (SI), as arrays.

    Each field is :class:`.solver.Kinematics`'s, with a leading axis of N positions:
    points, velocities, accelerations and origins are (N, 2); angles, ω and α (N,).
    ``slide_positions``, ``slide_velocities`` and ``slide_accelerations`` follow
    ``Mechanism.slides`` (see :class:`.solver.SlideRate`). Where ``ok`` is false every
    number is NaN: read the verdict from ``ok``, ``dead`` and :meth:`refusal`.
    ``conditioning`` is the scalar solver's rcond where ``by_scalar`` or below 0.02
    (``TRUSTED``), else a lower bound of it (within a factor of the coordinates' count).
    """

    mechanism: Mechanism
    inputs: np.ndarray
    ok: np.ndarray
    dead: np.ndarray
    points: dict[str, np.ndarray]
    angles: dict[int, np.ndarray]
    omegas: dict[int, np.ndarray]
    alphas: dict[int, np.ndarray]
    velocities: dict[str, np.ndarray]
    accelerations: dict[str, np.ndarray]
    slide_positions: tuple[np.ndarray, ...]
    slide_velocities: tuple[np.ndarray, ...]
    slide_accelerations: tuple[np.ndarray, ...]
    residual: np.ndarray
    conditioning: np.ndarray
    origins: dict[int, np.ndarray]
    origin_velocities: dict[int, np.ndarray]
    origin_accelerations: dict[int, np.ndarray]
    by_scalar: np.ndarray
    """The positions the scalar solver decided (see the module docstring)."""
    _refusals: dict[int, AssemblyError] = field(default_factory=dict, repr=False)

    def refusal(self, i: int) -> AssemblyError:
        """The error the scalar solver raises at position ``i`` (one that is not ``ok``).

        A :class:`.solver.SingularPosition` at a dead point, else an ``AssemblyError``;
        the message is the scalar solver's, word for word.
        """
        if i not in self._refusals:
            try:
                solve(_at(self.mechanism, float(self.inputs[i])))
            except AssemblyError as e:
                self._refusals[i] = e
            else:
                raise AssemblyError(f"position {i} assembles: it has no refusal",
                                    link=self.mechanism.drive.link)
        return self._refusals[i]

    def velocity_on(self, link: int, point: str) -> np.ndarray:
        """Velocity (N, 2) of ``point`` fixed to ``link``: ``v_O + ω × r`` (``point_velocity``)."""
        r = self.points[point] - self.origins[link]
        w = self.omegas[link][:, None]
        return self.origin_velocities[link] + w * np.stack([-r[:, 1], r[:, 0]], axis=1)

    def rates_on(self, link: int, point: str) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`velocity_on` and :meth:`acceleration_on` at once (the same numbers)."""
        r = self.points[point] - self.origins[link]
        w, al = self.omegas[link][:, None], self.alphas[link][:, None]
        across = np.stack([-r[:, 1], r[:, 0]], axis=1)
        return (self.origin_velocities[link] + w * across,
                self.origin_accelerations[link] + al * across - w ** 2 * r)

    def acceleration_on(self, link: int, point: str) -> np.ndarray:
        """Acceleration (N, 2) of ``point`` fixed to ``link``: ``a_O + α × r − ω² r``."""
        r = self.points[point] - self.origins[link]
        w, al = self.omegas[link][:, None], self.alphas[link][:, None]
        return (self.origin_accelerations[link] + al * np.stack([-r[:, 1], r[:, 0]], axis=1)
                - w ** 2 * r)


def _at(mech: Mechanism, angle: float) -> Mechanism:
    return mech.with_drive(replace(mech.drive, angle=angle))


def solve_turn(mech: Mechanism, angles) -> Turn:
    """Solve ``mech`` at each of ``angles`` of its input (rad), at its ω and α.

    Parameters
    ----------
    mech : Mechanism
        A single-input mechanism; its branches are honoured at each angle as
        :func:`.solver.solve` honours them (a near point picks anew at each angle:
        pass ``follow_branches(mech)`` to keep the side of the stated position).
    angles : array_like
        N input angles (rad).

    Returns
    -------
    Turn
        The kinematics at every angle, equal to the scalar solver's to round-off.

    Raises
    ------
    InputError
        As :func:`.solver.solve` does (a missing branch, a bad slide).

    Examples
    --------
    The parallelogram of :func:`.solver.solve` at θ2 = 90°, and at 0°, where its four
    links lie in line (a change point: a dead point):

    >>> import math
    >>> from tarsim.constructions.model import Drive, Link, Mechanism
    >>> m = Mechanism((Link(1, (("O2", (0, 0)), ("O4", (4, 0)))),
    ...                Link(2, (("O2", (0, 0)), ("A", (3, 0)))),
    ...                Link(3, (("A", (0, 0)), ("B", (4, 0)))),
    ...                Link(4, (("O4", (0, 0)), ("B", (3, 0))))),
    ...               Drive(2, 0.0, omega=1.0), branches={"B": "left"})
    >>> turn = solve_turn(m, [0.0, math.pi / 2])
    >>> [round(float(v), 12) + 0.0 for v in turn.points["B"][1]]
    [4.0, 3.0]
    >>> turn.ok.tolist(), turn.dead.tolist()
    ([False, True], [True, False])
    """
    return TurnSolver(mech).solve(angles)


class TurnSolver:
    """:func:`solve_turn` of one mechanism, made ready once for many calls.

    The loop equations and their batch form, the pins' tree that inverts their Jacobian
    and the assembly's acts are the same at every input angle (the acts once recorded:
    only their numbers and verdicts depend on the angle), so a search that solves a few
    dozen angles a round, as a zero's bisection does, prepares them once.

    Raises
    ------
    InputError
        As :func:`.solver.solve` does (a bad slide).
    """

    def __init__(self, mech: Mechanism):
        self.mechanism = mech
        self.system = _System(mech)
        self.loops = BatchLoops(self.system)
        try:
            _check(mech)
        except AssemblyError:
            self._assembles = False
        else:
            self._assembles = True
        self._plan: AssemblyPlan | None = None
        self._tree: PinElimination | None = None

    def solve(self, angles) -> Turn:
        """The kinematics at each of ``angles`` (rad), as :func:`solve_turn` gives them."""
        mech, system = self.mechanism, self.system
        angles = np.asarray(angles, dtype=float).reshape(-1)
        n = len(angles)
        if self._plan is None and self._assembles:
            self._plan = record_plan(mech, angles)
        plan = self._plan
        width = 3 * len(system.moving)
        q, qd, qdd = (np.full((n, width), np.nan) for _ in range(3))
        residual, rcond = np.full(n, np.nan), np.full(n, np.nan)
        if plan is None:
            refused, doubtful = np.ones(n, dtype=bool), np.zeros(n, dtype=bool)
        else:
            place = plan.place(angles)
            refused, doubtful = place.refused.copy(), place.doubtful.copy()
            live = np.flatnonzero(~(refused | doubtful))
            if len(live):
                if self._tree is None:
                    self._tree = PinElimination(self.loops)
                good, rows = _solve_rows(self.loops, self._tree, mech, place.q[live],
                                         angles[live])
                doubtful[live[~good]] = True
                at = live[good]
                if len(at) == n:
                    q, qd, qdd, residual, rcond = rows
                else:
                    q[at], qd[at], qdd[at], residual[at], rcond[at] = rows
        by_scalar = doubtful
        refusals: dict[int, AssemblyError] = {}
        kins: dict[int, Kinematics] = {}
        for i in np.flatnonzero(doubtful).tolist():
            try:
                kins[i] = solve(_at(mech, float(angles[i])))
            except AssemblyError as e:
                refusals[i] = e
        ok = ~refused
        ok[list(refusals)] = False
        dead = np.zeros(n, dtype=bool)
        dead[[i for i, e in refusals.items() if isinstance(e, SingularPosition)]] = True
        return _pack(self.loops, angles, q, qd, qdd, residual, rcond, ok, dead, by_scalar,
                     kins, refusals)


def _solve_rows(loops: BatchLoops, tree: PinElimination, mech: Mechanism, q: np.ndarray,
                angles: np.ndarray):
    """Polish, check and differentiate the replayed starts; rows not vouched for are flagged.

    Returns ``(good, (q, q̇, q̈, residual, r))`` with the arrays of the good rows only.
    """
    good = np.ones(len(q), dtype=bool)
    with np.errstate(all="ignore"):
        res = loops.residual(q, angles)
        scaled = np.max(np.abs(res * loops.rows), axis=1)
        todo = np.flatnonzero(scaled > 4 * _EPS)
        if len(todo):
            polished, ok = _newton(loops, q[todo], angles[todo])
            q[todo], good[todo] = polished, ok
            res[todo] = loops.residual(polished, angles[todo])
            scaled[todo] = np.max(np.abs(res[todo] * loops.rows), axis=1)
        good &= np.isfinite(scaled) & (scaled <= 1e-10)
        entries = loops.entries(q)
        inv = tree.invert(entries, good)
        good &= inv.ok
        r = _rcond_bound(loops, entries, inv)
        unsure = np.flatnonzero(good & (r < TRUSTED))
        if len(unsure):             # the bound is loose by up to √n twice: take the true one
            jac = loops.dense(entries[:, unsure])
            sv = np.linalg.svd(jac * loops.rows[None, :, None] * loops.cols[None, None, :],
                               compute_uv=False)
            r[unsure] = sv[:, -1] / sv[:, 0]
        good &= np.isfinite(r) & (r >= TRUSTED)
        if not good.all():
            q, inv, res, r = q[good], inv.take(good), res[good], r[good]
        qd = mech.drive.omega * inv.column(len(loops.rows) - 1)    # the input's row is last
        qdd = inv.solve(loops.gamma(q, qd))
    return good, (q, qd, qdd, np.max(np.abs(res), axis=1), r)


def _rcond_bound(loops: BatchLoops, entries: np.ndarray, inv: Inverse) -> np.ndarray:
    """``1 / (‖J‖_F ‖J⁻¹‖_F)`` of each length-scaled Jacobian (J's :meth:`~.BatchLoops.entries`
    given): at most its rcond (σmin/σmax), and at least that over the number of coordinates,
    since ‖·‖₂ ≤ ‖·‖_F ≤ √n ‖·‖₂."""
    rows, cols = loops.pattern
    scale = (loops.rows[rows] * loops.cols[cols]) ** 2
    big = np.einsum("en,en,e->n", entries, entries, scale)
    return 1.0 / np.sqrt(big * inv.norm2(loops.rows, loops.cols))


def _newton(loops: BatchLoops, q: np.ndarray, angles: np.ndarray):
    """The scalar solver's polish, row by row in a batch: ``(q, vouched)``.

    A row that moves more than round-off is not vouched for: the scalar solver judges
    the dead point at the start too, and a start that far off is worth its own look.
    """
    start, q = q, q.copy()
    ok = np.ones(len(q), dtype=bool)
    active = np.arange(len(q))
    jac = loops.jacobian(q)
    for _ in range(_NEWTON_STEPS):
        active = active[loops.scaled_residual(q[active], angles[active]) > 4 * _EPS]
        if not len(active):
            break
        try:
            dq = np.linalg.solve(jac[active],
                                 -loops.residual(q[active], angles[active])[:, :, None])[:, :, 0]
        except np.linalg.LinAlgError:
            ok[active] = False
            break
        q[active] += dq
        active = active[~(np.max(np.abs(dq), axis=1) <= 4 * _EPS * loops.sy.lc)]
        jac[active] = loops.jacobian(q[active])
    ok &= np.max(np.abs(q - start), axis=1) <= 1e-8 * loops.sy.lc
    return q, ok


def _pack(loops: BatchLoops, angles, q, qd, qdd, residual, rcond, ok, dead, by_scalar, kins,
          refusals) -> Turn:
    """Arrange the body coordinates as a :class:`Turn`; rows the scalar solved, from ``kins``."""
    system = loops.sy
    mech, n = system.m, len(angles)
    still = np.zeros((n, 2))
    origins, vel0, acc0 = {1: still}, {1: still.copy()}, {1: still.copy()}
    angles_, omegas, alphas = {1: np.zeros(n)}, {1: np.zeros(n)}, {1: np.zeros(n)}
    for k in system.moving:
        c = system.col[k]
        origins[k], vel0[k], acc0[k] = q[:, c:c + 2].copy(), qd[:, c:c + 2].copy(), \
            qdd[:, c:c + 2].copy()
        angles_[k], omegas[k], alphas[k] = wrap(q[:, c + 2]), qd[:, c + 2].copy(), \
            qdd[:, c + 2].copy()
    carrier = {name: 1 if 1 in mech.links_at(name) else mech.links_at(name)[0]
               for name in mech.point_names}
    points = {name: origins[k] + _pair(loops.arm(q, k, system.loc[k, name]), n)
              for name, k in carrier.items()}
    rates = [_slide_rates(loops, q, qd, qdd, s, through, d) for s, through, d, _ in system.slides]
    for i, kin in kins.items():
        _put_row(i, kin, points, angles_, omegas, alphas, origins, vel0, acc0, rates)
        residual[i], rcond[i] = kin.residual, kin.conditioning
    turn = Turn(mech, angles, ok, dead, points, angles_, omegas, alphas, {}, {},
                tuple(r[0] for r in rates), tuple(r[1] for r in rates),
                tuple(r[2] for r in rates), residual, rcond, origins, vel0, acc0,
                by_scalar, dict(refusals))
    for name, k in carrier.items():     # as Kinematics does: on the point's first carrier
        turn.velocities[name], turn.accelerations[name] = turn.rates_on(k, name)
    if not ok.all():
        for arrays in (points, angles_, omegas, alphas, turn.velocities, turn.accelerations,
                       origins, vel0, acc0):
            for v in arrays.values():
                v[~ok] = np.nan
        for v in (x for r in rates for x in r):
            v[~ok] = np.nan
        residual[~ok], rcond[~ok] = np.nan, np.nan
    return turn


def _pair(v, n: int) -> np.ndarray:
    """An (x, y) pair of arrays or floats as an (n, 2) array."""
    return np.stack(np.broadcast_arrays(np.broadcast_to(v[0], (n,)), v[1]), axis=1).copy()


def _slide_rates(loops: BatchLoops, q, qd, qdd, s, through, d):
    """Position, velocity and acceleration along the guide of slide ``s`` (see ``SlideRate``)."""
    p, g, dg, arm_l, arm_g = loops._slide_terms(q, s, through, d)
    (vl, wl), (vg, wg) = loops.state(qd, s.link), loops.state(qd, s.guide_link)
    (al, bl), (ag, bg) = loops.state(qdd, s.link), loops.state(qdd, s.guide_link)
    pl, pg = (-arm_l[1], arm_l[0]), (-arm_g[1], arm_g[0])
    e, sd = (p[0] - g[0], p[1] - g[1]), (-dg[1], dg[0])
    e_dot = [vl[i] + wl * pl[i] - vg[i] - wg * pg[i] for i in (0, 1)]
    e_ddot = [al[i] + bl * pl[i] - wl ** 2 * arm_l[i] - ag[i] - bg * pg[i] + wg ** 2 * arm_g[i]
              for i in (0, 1)]

    def dot(a, b):
        return a[0] * b[0] + a[1] * b[1]

    speed = wg * dot(sd, e) + dot(dg, e_dot)
    accel = bg * dot(sd, e) - wg ** 2 * dot(dg, e) + 2.0 * wg * dot(sd, e_dot) + dot(dg, e_ddot)
    n = len(q)
    return tuple(np.broadcast_to(x, (n,)).copy() for x in (dot(dg, e), speed, accel))


def _put_row(i, kin: Kinematics, points, angles, omegas, alphas, origins, vel0, acc0,
             rates) -> None:
    """Row ``i`` of every array from one scalar solution (velocities follow from these)."""
    for arrays, values in ((points, kin.points), (angles, kin.angles), (omegas, kin.omegas),
                           (alphas, kin.alphas), (origins, kin.origins),
                           (vel0, kin.origin_velocities), (acc0, kin.origin_accelerations)):
        for key, v in values.items():
            arrays[key][i] = v
    for (pos, vel, acc), rate in zip(rates, kin.slide_rates):
        pos[i], vel[i], acc[i] = rate.position, rate.velocity, rate.acceleration
