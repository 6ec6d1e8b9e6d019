"""A 50-digit reference: Newton on the loop equations in mpmath, independent of both sides.

The benchmark judges two float64 programs, the constructions and the analytic solver
(:mod:`tarsim.constructions.reference.solver`), so its yardstick must be neither. This
module writes the loop equations of a :class:`~tarsim.constructions.model.Mechanism`
afresh, in body coordinates ``(x_k, y_k, φ_k)`` of each moving link:

- a pin: the point's global places on each link that carries it agree;
- a slide: ``cross(D, P − G) = 0`` on the guide's line, and for a block
  ``φ_link − φ_guide − atan2(D_local) = 0``;
- an arc: ``|P − C| − ρ = 0``;
- the drive: ``φ_input − θ = 0``;

and solves them by Newton at 120 significant digits, with a central-difference
Jacobian (step 1e-50: its error is far below the answer's). A float64 position is
used only as Newton's start, to pick the branch the mechanism is drawn in; the
answer does not inherit its error. Velocities and accelerations are the first and
second derivatives of the position with respect to the input angle, by central
differences of converged solutions at ``θ ± 1e-30`` (truncation 1e-60, rounding
1e-120 / 1e-60), times ω and ω², plus ``α·dq/dθ``. Instant centres come from the
velocity fields (where two links' fields agree), the limit positions from where the
output's ``dq/dθ`` is zero, found by the secant method at full precision.

So every number is good to at least 50 digits away from a dead point. Within Δ rad of
one the derivatives' truncation grows as ``(1e-30 / Δ)²``, which still leaves some 40
digits at 1e-9 rad; at the dead point itself ``dq/dθ`` is undefined and the solve fails.
Rolling contacts are not modelled (none is in the bundled catalog).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath
from mpmath import mp, mpf

from tarsim.constructions.joints import SlideKind
from tarsim.constructions.model import Drive, Mechanism

__all__ = ["DPS", "MpKinematics", "MpCentre", "mp_solve", "mp_limits", "Unmodelled"]

DPS = 120
"""Working digits: the derivatives by differences keep at least 50 of them."""

NOISE = mpf("1e-40")
"""A relative ω or velocity below this fraction of the mechanism's is taken as zero."""



class Unmodelled(Exception):
    """The mechanism has a joint this reference does not model (a rolling contact)."""


@dataclass(frozen=True)
class MpCentre:
    """An instant centre at full precision: a point, or a direction at infinity."""

    point: tuple | None
    direction: tuple | None


@dataclass
class MpKinematics:
    """Positions, ω, α and point velocities and accelerations, as mpmath numbers (SI)."""

    mech: Mechanism
    points: dict
    origins: dict
    angles: dict
    omegas: dict
    alphas: dict
    origin_velocities: dict
    origin_accelerations: dict

    def _arm(self, link: int, p) -> tuple:
        o = self.origins[link]
        return p[0] - o[0], p[1] - o[1]

    def velocity(self, point: str, link: int | None = None) -> tuple:
        """Velocity of ``point`` taken on ``link`` (default: the first link carrying it)."""
        return self.velocity_at(link or _carrier(self.mech, point), self.points[point])

    def acceleration(self, point: str, link: int | None = None) -> tuple:
        """Acceleration of ``point`` taken on ``link``: ``a_O + α × r − ω² r``."""
        link = link or _carrier(self.mech, point)
        if link == 1:
            return mpf(0), mpf(0)
        (rx, ry), w, al = self._arm(link, self.points[point]), self.omegas[link], self.alphas[link]
        ax, ay = self.origin_accelerations[link]
        return ax - al * ry - w * w * rx, ay + al * rx - w * w * ry

    def omega(self, link: int):
        """ω of ``link`` (0 for the frame)."""
        return mpf(0) if link == 1 else self.omegas[link]

    def centre(self, i: int, j: int) -> MpCentre | None:
        """``I_ij``: where the two velocity fields agree.

        A relative ω below ``NOISE`` of the mechanism's (its derivatives are good to
        some 40 digits at worst) is taken as zero: the centre is then at infinity, or,
        with no relative velocity either, undefined (the links move together: None).
        """
        with mp.workdps(DPS):
            places = list(self.points.values())
            size = max(mpmath.hypot(p[0] - q[0], p[1] - q[1]) for p in places for q in places)
            scale = max(abs(w) for w in self.omegas.values()) * size
            q = (mpf(0), mpf(0))
            vi, vj = self.velocity_at(i, q), self.velocity_at(j, q)
            dvx, dvy = vi[0] - vj[0], vi[1] - vj[1]
            dw = self.omega(i) - self.omega(j)
            if abs(dw) * size > NOISE * scale:
                return MpCentre((-dvy / dw, dvx / dw), None)
            # Δv(Q) = Δω k × (Q − I): with Δω ≈ 0 it is the same at every Q of the mechanism.
            if mpmath.hypot(dvx, dvy) > NOISE * scale:
                return MpCentre(None, (-dvy, dvx))
            return None

    def velocity_at(self, link: int, p) -> tuple:
        """Velocity of the place ``p`` taken as fixed to ``link``."""
        if link == 1:
            return mpf(0), mpf(0)
        (rx, ry), w, (vx, vy) = self._arm(link, p), self.omegas[link], self.origin_velocities[link]
        return vx - w * ry, vy + w * rx


def _carrier(mech: Mechanism, point: str) -> int:
    at = mech.links_at(point)
    return 1 if 1 in at else at[0]


class _Loops:
    """The loop equations of one mechanism, as an mpmath residual of body coordinates."""

    def __init__(self, mech: Mechanism):
        if any(s.rolling for s in mech.slides):
            raise Unmodelled("a rolling contact is not modelled by the mpmath reference")
        self.m = mech
        self.moving = [k.number for k in mech.links if k.number != 1]
        self.col = {k: 3 * i for i, k in enumerate(self.moving)}
        self.local = {(k.number, n): (mpf(x), mpf(y)) for k in mech.links for n, (x, y) in k.points}

    def pose(self, q, k: int):
        if k == 1:
            return mpf(0), mpf(0), mpf(0)
        c = self.col[k]
        return q[c], q[c + 1], q[c + 2]

    def place(self, q, k: int, xy) -> tuple:
        x, y, f = self.pose(q, k)
        c, s = mpmath.cos(f), mpmath.sin(f)
        return x + c * xy[0] - s * xy[1], y + s * xy[0] + c * xy[1]

    def point(self, q, name: str, k: int | None = None) -> tuple:
        k = k or _carrier(self.m, name)
        return self.place(q, k, self.local[k, name])

    def residual(self, q, theta) -> list:
        m, out = self.m, []
        for name in m.point_names:
            at = m.links_at(name)
            p0 = self.point(q, name, at[0])
            for k in at[1:]:
                p = self.point(q, name, k)
                out += [p[0] - p0[0], p[1] - p0[1]]
        for s in m.slides:
            p = self.point(q, s.point, s.link)
            g = self.place(q, s.guide_link, (mpf(s.through[0]), mpf(s.through[1])))
            _, _, fg = self.pose(q, s.guide_link)
            d0 = (mpf(s.direction[0]), mpf(s.direction[1]))
            c, sn = mpmath.cos(fg), mpmath.sin(fg)
            d = (c * d0[0] - sn * d0[1], sn * d0[0] + c * d0[1])
            out.append((d[0] * (p[1] - g[1]) - d[1] * (p[0] - g[0])) / mpmath.hypot(*d0))
            if s.kind is SlideKind.BLOCK:
                out.append(_wrap(self.pose(q, s.link)[2] - fg - mpmath.atan2(d0[1], d0[0])))
        for a in m.arcs:
            if a.kind is SlideKind.PIN:
                p = self.point(q, a.point, a.link)
                c = self.point(q, a.centre, a.guide_link)
                out.append(mpmath.hypot(p[0] - c[0], p[1] - c[1]) - mpf(a.radius))
        out.append(_wrap(self.pose(q, m.drive.link)[2] - theta))
        return out

    def jacobian(self, q, theta) -> _Factored:
        n = len(q)
        jac = [[mpf(0)] * n for _ in range(n)]
        step = mpf(10) ** (-(mp.dps * 5) // 12)      # 1e-50 at 120 digits
        for j in range(n):
            h = step * max(1, abs(q[j]))
            up, down = list(q), list(q)
            up[j] += h
            down[j] -= h
            ru, rd = self.residual(up, theta), self.residual(down, theta)
            for i in range(n):
                jac[i][j] = (ru[i] - rd[i]) / (2 * h)
        return _Factored(jac)

    def newton(self, q, theta) -> list:
        """Polish ``q`` until the step is below the working precision; raise if it will not.

        The Jacobian is kept while each step shrinks at least a thousandfold (from a
        float64 start that is every step: each gains some 16 digits less the digits the
        conditioning costs) and taken afresh when one does not.
        """
        q = [mpf(v) for v in q]
        tiny = mpf(10) ** (-mp.dps + 8)
        jac, last = None, None
        for _ in range(60):
            r = self.residual(q, theta)
            if len(r) != len(q):
                raise Unmodelled(f"{len(r)} equations for {len(q)} body coordinates")
            if jac is None:
                jac = self.jacobian(q, theta)
            dq = jac.solve([-v for v in r])
            step = max(abs(v) for v in dq)
            q = [a + b for a, b in zip(q, dq)]
            if step <= tiny * max(1, max(abs(v) for v in q)):
                return q
            if last is not None and step > last / 2 and step < mpf(10) ** (-mp.dps // 2):
                return q        # stalled at the rounding of a near-singular Jacobian
            if last is not None and step > last * mpf("1e-3"):
                jac = None
            last = step
        raise ArithmeticError("the mpmath Newton did not converge (a dead point?)")

    def rate(self, q, theta) -> list:
        """dq/dθ at a converged ``q``: the Jacobian solved against the drive row."""
        return self.jacobian(q, theta).solve([mpf(0)] * (len(q) - 1) + [mpf(1)])


class _Factored:
    """A square system's matrix factored once and solved for any right-hand side, step for
    step as ``mp.lu_solve`` solves it: 10 bits above the working precision, rows pivoted
    on their largest element relative to the row's sum, ZeroDivisionError when a row or
    a pivot is below the 1-norm times eps.

    Newton keeps its Jacobian over several steps, and ``mp.lu_solve`` factors it afresh
    each time, through ``mp.matrix``'s indexing: that was most of a reference solve's
    time. On plain lists of rows the same arithmetic gives the same numbers, to the bit.
    """

    def __init__(self, rows: list[list]):
        n = len(rows)
        with mp.extraprec(10):
            a = [list(row) for row in rows]
            tol = max(mpmath.fsum((a[i][j] for i in range(n)), absolute=True)
                      for j in range(n)) * mp.eps
            swaps = []
            for j in range(n - 1):
                biggest, p = 0, None
                for k in range(j, n):
                    s = mpmath.fsum((a[k][col] for col in range(j, n)), absolute=True)
                    if s <= tol:
                        raise ZeroDivisionError("matrix is numerically singular")
                    if (current := 1 / s * abs(a[k][j])) > biggest:
                        biggest, p = current, k
                a[j], a[p] = a[p], a[j]
                swaps.append(p)
                if abs(a[j][j]) <= tol:
                    raise ZeroDivisionError("matrix is numerically singular")
                for row in a[j + 1:]:
                    row[j] /= a[j][j]
                    for k in range(j + 1, n):
                        row[k] -= row[j] * a[j][k]
            if abs(a[n - 1][n - 1]) <= tol:
                raise ZeroDivisionError("matrix is numerically singular")
        self.a, self.swaps = a, swaps

    def solve(self, rhs: list) -> list:
        a, n = self.a, len(self.a)
        with mp.extraprec(10):
            x = list(rhs)
            for k, p in enumerate(self.swaps):
                x[k], x[p] = x[p], x[k]
            for i in range(1, n):                    # L y = P b, L with a unit diagonal
                for j in range(i):
                    x[i] -= a[i][j] * x[j]
            for i in reversed(range(n)):             # U x = y
                for j in range(i + 1, n):
                    x[i] -= a[i][j] * x[j]
                x[i] /= a[i][i]
        return x


def _wrap(angle):
    return angle - 2 * mp.pi * mpmath.nint(angle / (2 * mp.pi))


def _start(loops: _Loops, start: dict[str, tuple[float, float]], theta: float) -> list:
    """Body coordinates from a float64 picture of the points (only Newton's start).

    A link's angle comes from two of its points; a link of one point takes it from a
    slot it carries (the slot's line runs from its pivot to the point in it), else from
    the guide it slides on as a block.
    """
    m = loops.m
    phi = {1: 0.0, m.drive.link: float(theta)}
    for k in loops.moving:
        names = m.link(k).names
        if k not in phi and len(names) >= 2:
            (ax, ay), (bx, by) = (start[n] for n in names[:2])
            (lx, ly), (mx, my) = (m.link(k).local(n) for n in names[:2])
            phi[k] = math.atan2(by - ay, bx - ax) - math.atan2(my - ly, mx - lx)
    for _ in range(len(loops.moving)):
        for s in m.slides:
            pivot = m.link(s.guide_link).names[0]
            if s.guide_link not in phi and s.point in start and pivot != s.point:
                (px, py), (ox, oy) = start[s.point], start[pivot]
                phi[s.guide_link] = (math.atan2(py - oy, px - ox)
                                     - math.atan2(s.direction[1], s.direction[0]))
            if s.kind is SlideKind.BLOCK and s.link not in phi and s.guide_link in phi:
                phi[s.link] = phi[s.guide_link] + math.atan2(s.direction[1], s.direction[0])
    q = []
    for k in loops.moving:
        f = phi.get(k, 0.0)
        name = m.link(k).names[0]
        (px, py), (lx, ly) = start[name], m.link(k).local(name)
        c, s = math.cos(f), math.sin(f)
        q += [px - (c * lx - s * ly), py - (s * lx + c * ly), f]
    return q


def mp_solve(mech: Mechanism, start: dict[str, tuple[float, float]], *,
             dps: int = DPS) -> MpKinematics:
    """Solve ``mech`` at its input position to 50+ digits.

    Parameters
    ----------
    mech : Mechanism
        Pins, slides (blocks and pins in slots) and arcs; no rolling contact.
    start : dict
        A float64 place of every point (from either side): Newton's start, which only
        picks the branch.
    dps : int
        Working digits; the derivative step is ``10**(-dps/4)`` (1e-30 at 120).

    Raises
    ------
    Unmodelled
        If the mechanism has a rolling contact.
    ArithmeticError
        If Newton does not converge, or the position is a dead point (singular Jacobian).
    """
    with mp.workdps(dps):
        h = mpf(10) ** (-dps // 4)
        loops = _Loops(mech)
        d = mech.drive
        theta = mpf(d.angle)
        q = loops.newton(_start(loops, start, theta), theta)
        rate = loops.rate(q, theta)
        up = loops.newton([a + h * b for a, b in zip(q, rate)], theta + h)
        down = loops.newton([a - h * b for a, b in zip(q, rate)], theta - h)
        dq = [(u - w) / (2 * h) for u, w in zip(up, down)]
        ddq = [(u - 2 * c + w) / (h * h) for u, c, w in zip(up, q, down)]
        om, al = mpf(d.omega), mpf(d.alpha)
        kin = MpKinematics(mech, {}, {1: (mpf(0), mpf(0))}, {1: mpf(0)}, {1: mpf(0)},
                           {1: mpf(0)}, {1: (mpf(0), mpf(0))}, {1: (mpf(0), mpf(0))})
        for k in loops.moving:
            c = loops.col[k]
            kin.origins[k] = (q[c], q[c + 1])
            kin.angles[k] = q[c + 2]
            kin.omegas[k] = dq[c + 2] * om
            kin.alphas[k] = ddq[c + 2] * om * om + dq[c + 2] * al
            kin.origin_velocities[k] = (dq[c] * om, dq[c + 1] * om)
            kin.origin_accelerations[k] = (ddq[c] * om * om + dq[c] * al,
                                           ddq[c + 1] * om * om + dq[c + 1] * al)
        kin.points = {n: loops.point(q, n) for n in mech.point_names}
        return kin


@dataclass(frozen=True)
class MpLimits:
    """The two limit positions at full precision: crank angles, time ratio, stroke (m)."""

    crank_angles: tuple
    time_ratio: object
    stroke: object | None


def mp_limits(mech: Mechanism, angles: tuple[float, float],
              starts: tuple[dict[str, tuple[float, float]], dict[str, tuple[float, float]]], *,
              point: str | None = None,
              link: int | None = None) -> MpLimits:
    """Find where the output's rate ``dq/dθ`` is zero, near each of ``angles``.

    The output is block ``point`` along its frame guide, or link ``link``'s angle.
    ``starts`` are float64 places of the points at each angle (Newton's starts); the
    secant method then runs on the rate at full precision.
    """
    with mp.workdps(DPS):
        loops = _Loops(mech)
        slide = next((s for s in mech.slides if s.point == point and s.guide_link == 1), None)

        def at(theta, q):
            q = loops.newton(q, theta)
            return q, loops.rate(q, theta)

        def output_rate(q, dq):
            if slide is None:
                return dq[loops.col[link] + 2]
            k = slide.link
            x, y, f = loops.pose(q, k)
            lx, ly = loops.local[k, point]
            c, s = mpmath.cos(f), mpmath.sin(f)
            c0 = loops.col[k]
            vx = dq[c0] - (s * lx + c * ly) * dq[c0 + 2]
            vy = dq[c0 + 1] + (c * lx - s * ly) * dq[c0 + 2]
            return slide.direction[0] * vx + slide.direction[1] * vy

        found, places = [], []
        for a, begin in zip(angles, starts):
            target = mpf(a)
            state = {"q": loops.newton(_start(loops, begin, target), target)}

            def g(theta, state=state):
                state["q"], dq = at(theta, state["q"])
                return output_rate(state["q"], dq)

            root = mpmath.findroot(g, (target, target + mpf("1e-12")), solver="secant",
                                   tol=mpf(10) ** -60, verify=False)
            q = loops.newton(state["q"], root)
            found.append(root)
            places.append(loops.point(q, point) if point else None)
        first = (found[1] - found[0]) % (2 * mp.pi)
        ratio = max(first, 2 * mp.pi - first) / min(first, 2 * mp.pi - first)
        stroke = None
        if point:
            stroke = mpmath.hypot(places[1][0] - places[0][0], places[1][1] - places[0][1])
        return MpLimits((found[0], found[1]), ratio, stroke)


def at_angle(mech: Mechanism, theta: float) -> Mechanism:
    """``mech`` with its input turned to ``theta`` (rad), ω and α kept."""
    d = mech.drive
    return mech.with_drive(Drive(d.link, theta, d.omega, d.alpha))
