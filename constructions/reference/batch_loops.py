"""The loop equations of :mod:`.solver` over a batch of positions: Φ, Φ_q and γ at once.

``_System`` evaluates the constraints of one position; :class:`BatchLoops` evaluates
the same rows, in the same order and with the same formulas, for N positions held as
the rows of a (N, 3 × moving links) array, so that the Newton polish and the velocity
and acceleration solves of a whole turn are a few numpy operations each. A 2-vector
is a pair of (N,) arrays throughout. Φ_q is kept as its :meth:`~BatchLoops.entries`,
those not 0 by their form (25 of a four-bar's 81), and made whole only where asked.
"""

from __future__ import annotations

import math
from enum import StrEnum
from functools import cached_property

import numpy as np

from .loop_equations import _System

__all__ = ["BatchLoops", "wrap"]


def wrap(angle: np.ndarray) -> np.ndarray:
    """Wrap angles to ``[−π, π]`` as ``math.remainder(angle, 2π)`` does (both are exact).

    >>> float(wrap(np.array([3 * math.pi / 2]))[0]) == math.remainder(3 * math.pi / 2, math.tau)
    True
    """
    r = np.fmod(angle, math.tau)
    r = np.where(r > math.pi, r - math.tau, r)
    return np.where(r < -math.pi, r + math.tau, r)


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def _perp(v):
    """``S v``: ``v`` turned +90°."""
    return -v[1], v[0]


def _round_rate(e):
    """``∂β/∂e = S e / (e·e)``: how the angle β of ``e`` turns as ``e`` moves."""
    ee = e[0] * e[0] + e[1] * e[1]
    return -e[1] / ee, e[0] / ee


class _Rows(StrEnum):
    """What a joint's rows of Φ constrain, in ``_System``'s order."""

    PIN = "pin"
    """Two rows: the pin's x and y on both links agree."""
    LINE = "line"
    """A point on a slide's line (a rolling contact's no-slip row is one, turned)."""
    TURN = "turn"
    """Two links' angles differ by a constant (a block on its guide), or the input's angle is
    given (the frame is the other link, the offset None)."""
    ARC = "arc"
    """A point at a fixed distance from a point of another link."""
    ROUND = "round"
    """A wheel turned as far as its centre has rolled round a circle (see Arc.roll_gain)."""


class BatchLoops:
    """Φ(q), Φ_q and the acceleration right-hand side of ``system`` for N positions."""

    def __init__(self, system: _System):
        self.sy = system
        self.rows, self.cols = system.row_scale, system.col_scale
        self._for, self._cs = None, {}
        self.layout = self._lay_out()

    def _lay_out(self) -> list[tuple[int, _Rows, object]]:
        """Each joint's first row, kind and terms, in ``_System``'s row order."""
        sy, out, row = self.sy, [], 0
        for pin in sy.pins:
            out.append((row, _Rows.PIN, pin))
            row += 2
        for i, (s, through, d, off) in enumerate(sy.slides):
            out.append((row, _Rows.LINE, (s, through, d, 0.0)))
            if i in sy.turning:
                out.append((row + 1, _Rows.TURN, (s.link, s.guide_link, off)))
            row += 2 if i in sy.turning else 1
        for s, through, u, k in sy.rolls:
            out.append((row, _Rows.LINE, (s, through, u, k)))
            row += 1
        for a in sy.arcs:
            out.append((row, _Rows.ARC, a))
            row += 1
        for a in sy.rounds:
            out.append((row, _Rows.ROUND, a))
            row += 1
        out.append((row, _Rows.TURN, (sy.m.drive.link, 1, None)))     # None: the input angle
        return out

    # ----- body coordinates
    def state(self, q, k: int):
        """``(t, φ)`` of link ``k``: origin (x, y) and angle, as arrays (0 for the frame)."""
        if k == 1:
            return (0.0, 0.0), 0.0
        c = self.sy.col[k]
        return (q[:, c], q[:, c + 1]), q[:, c + 2]

    def arm(self, q, k: int, v):
        """``R(φ_k) v`` for a constant local vector ``v``."""
        if k == 1:
            return float(v[0]), float(v[1])
        c, s = self._turns(q)[k]
        return c * v[0] + (-s) * v[1], s * v[0] + c * v[1]

    def _turns(self, q) -> dict[int, tuple[np.ndarray, np.ndarray]]:
        """Return cos φ and sin φ of each moving link, kept for the last ``q`` asked."""
        if self._for is not q:
            cols = q[:, 2::3]
            c, s = np.cos(cols), np.sin(cols)
            self._cs = {k: (c[:, i], s[:, i]) for i, k in enumerate(self.sy.moving)}
            self._for = q
        return self._cs

    def _slide_terms(self, q, s, through, d):
        (tl, _), (tg, _) = self.state(q, s.link), self.state(q, s.guide_link)
        arm_l = self.arm(q, s.link, self.sy.loc[s.link, s.point])
        arm_g = self.arm(q, s.guide_link, through)
        p = (tl[0] + arm_l[0], tl[1] + arm_l[1])
        g = (tg[0] + arm_g[0], tg[1] + arm_g[1])
        return p, g, self.arm(q, s.guide_link, d), arm_l, arm_g

    def _arc_terms(self, q, a):
        (tl, _), (tg, _) = self.state(q, a.link), self.state(q, a.guide_link)
        arm_l = self.arm(q, a.link, self.sy.loc[a.link, a.point])
        arm_g = self.arm(q, a.guide_link, self.sy.loc[a.guide_link, a.centre])
        e = (tl[0] + arm_l[0] - tg[0] - arm_g[0], tl[1] + arm_l[1] - tg[1] - arm_g[1])
        return e, arm_l, arm_g

    # ----- Φ, Φ_q, γ
    def residual(self, q, angles) -> np.ndarray:
        """Φ at each row of ``q`` with the input at ``angles``: (N, constraints)."""
        sy = self.sy
        out = np.empty((len(q), len(sy.is_len)))
        for row, kind, item in self.layout:
            if kind is _Rows.PIN:
                n, i, j = item
                (ti, _), (tj, _) = self.state(q, i), self.state(q, j)
                ai, aj = self.arm(q, i, sy.loc[i, n]), self.arm(q, j, sy.loc[j, n])
                out[:, row] = ti[0] + ai[0] - tj[0] - aj[0]
                out[:, row + 1] = ti[1] + ai[1] - tj[1] - aj[1]
            elif kind is _Rows.LINE:
                s, through, d, roll = item
                p, g, dg, _, _ = self._slide_terms(q, s, through, d)
                out[:, row] = _cross(dg, (p[0] - g[0], p[1] - g[1]))
                if roll:
                    turned = self.state(q, s.link)[1] - self.state(q, s.guide_link)[1]
                    out[:, row] += roll * turned
            elif kind is _Rows.TURN:
                link, other, offset = item
                offset = angles if offset is None else offset
                out[:, row] = wrap(self.state(q, link)[1] - self.state(q, other)[1] - offset)
            elif kind is _Rows.ARC:
                e = self._arc_terms(q, item)[0]
                out[:, row] = (e[0] * e[0] + e[1] * e[1] - item.radius ** 2) / (2.0 * item.radius)
            else:
                e = self._arc_terms(q, item)[0]
                fw, fg = self.state(q, item.link)[1], self.state(q, item.guide_link)[1]
                beta = np.remainder(np.arctan2(e[1], e[0]) - fg + math.pi, math.tau) - math.pi
                out[:, row] = item.contact.circle.radius * (fw - fg) - item.roll_gain * beta
        return out

    def scaled_residual(self, q, angles) -> np.ndarray:
        """``max |Φ|`` of each row, lengths over the mechanism's size: (N,)."""
        return np.max(np.abs(self.residual(q, angles) * self.rows), axis=1)

    def jacobian(self, q) -> np.ndarray:
        """Φ_q at each row of ``q``: (N, constraints, coordinates)."""
        return self.dense(self.entries(q))

    def entries(self, q) -> np.ndarray:
        """Φ_q's entries that are not 0 by its form, at each row of ``q``: (E, N) in the
        order of :attr:`pattern`. A pin's rows hold a handful of the 81 entries of a
        four-bar's Φ_q; the rest are zeros not worth the memory."""
        slot = self.slots
        out = np.zeros((len(slot), len(q)))
        for row, col, value in self._terms(q):
            out[slot[row, col]] += value
        return out

    def dense(self, entries: np.ndarray) -> np.ndarray:
        """Φ_q (N, constraints, coordinates) from its :meth:`entries` (E, N)."""
        sy = self.sy
        jac = np.zeros((len(sy.is_len), 3 * len(sy.moving), entries.shape[1]))
        jac[self.pattern] = entries      # each entry contiguous
        return jac.transpose(2, 0, 1)

    @cached_property
    def slots(self) -> dict[tuple[int, int], int]:
        """The place of each entry of Φ_q not 0 by its form, by (row, column)."""
        found = {}
        with np.errstate(all="ignore"):     # its numbers at q = 0 are not read
            for row, col, _ in self._terms(np.zeros((1, 3 * len(self.sy.moving)))):
                found.setdefault((row, col), len(found))
        return found

    @cached_property
    def pattern(self) -> tuple[np.ndarray, np.ndarray]:
        """The rows and columns of :meth:`entries`, in their order (an index of Φ_q)."""
        rows, cols = zip(*self.slots) if self.slots else ((), ())
        return np.array(rows, dtype=int), np.array(cols, dtype=int)

    def _terms(self, q):
        """Each term of Φ_q as ``(row, column, value)``, in the order they add up; a term
        0 by its form (the y of a pin's x row, the x of a turn's row) is left out."""
        sy = self.sy

        def put(row, k, dt, dphi, sign=1.0):
            if k != 1:
                c = sy.col[k]
                for col, value in ((c, dt[0]), (c + 1, dt[1]), (c + 2, dphi)):
                    if not (isinstance(value, float) and value == 0.0):
                        yield row, col, sign * value

        def line_row(row, s, through, d):
            p, g, dg, arm_l, arm_g = self._slide_terms(q, s, through, d)
            yield from put(row, s.link, (-dg[1], dg[0]), _cross(dg, _perp(arm_l)))
            yield from put(row, s.guide_link, (dg[1], -dg[0]),
                           _cross(_perp(dg), (p[0] - g[0], p[1] - g[1]))
                           - _cross(dg, _perp(arm_g)))

        for row, kind, item in self.layout:
            if kind is _Rows.PIN:
                n, i, j = item
                for k, sign in ((i, 1.0), (j, -1.0)):
                    arm = _perp(self.arm(q, k, sy.loc[k, n]))
                    yield from put(row, k, (1.0, 0.0), arm[0], sign)
                    yield from put(row + 1, k, (0.0, 1.0), arm[1], sign)
            elif kind is _Rows.LINE:
                s, through, d, roll = item
                yield from line_row(row, s, through, d)
                if roll:
                    yield from put(row, s.link, (0.0, 0.0), roll)
                    yield from put(row, s.guide_link, (0.0, 0.0), -roll)
            elif kind is _Rows.TURN:
                yield from put(row, item[0], (0.0, 0.0), 1.0)
                yield from put(row, item[1], (0.0, 0.0), -1.0)
            elif kind is _Rows.ARC:
                e, arm_l, arm_g = self._arc_terms(q, item)
                sl, sg, rho = _perp(arm_l), _perp(arm_g), item.radius
                yield from put(row, item.link, (e[0] / rho, e[1] / rho),
                               (e[0] * sl[0] + e[1] * sl[1]) / rho)
                yield from put(row, item.guide_link, (-e[0] / rho, -e[1] / rho),
                               -(e[0] * sg[0] + e[1] * sg[1]) / rho)
            else:
                e, arm_l, arm_g = self._arc_terms(q, item)
                k, r, m = item.roll_gain, item.contact.circle.radius, _round_rate(e)
                sl, sg = _perp(arm_l), _perp(arm_g)
                yield from put(row, item.link, (-k * m[0], -k * m[1]),
                               r - k * (m[0] * sl[0] + m[1] * sl[1]))
                yield from put(row, item.guide_link, (k * m[0], k * m[1]),
                               k - r + k * (m[0] * sg[0] + m[1] * sg[1]))

    def gamma(self, q, qd) -> np.ndarray:
        """``−(Φ_q q̇)_q q̇ − Φ_tt`` at each row (the input's row carries α): (N, constraints)."""
        sy = self.sy
        out = np.zeros((len(q), len(sy.is_len)))

        def e_dot(s_link, g_link, arm_l, arm_g):
            (vl, wl), (vg, wg) = self.state(qd, s_link), self.state(qd, g_link)
            pl, pg = _perp(arm_l), _perp(arm_g)
            return (vl[0] + wl * pl[0] - vg[0] - wg * pg[0],
                    vl[1] + wl * pl[1] - vg[1] - wg * pg[1]), wl, wg

        for row, kind, item in self.layout:
            if kind is _Rows.PIN:
                n, i, j = item
                ai, aj = self.arm(q, i, sy.loc[i, n]), self.arm(q, j, sy.loc[j, n])
                wi, wj = self.state(qd, i)[1], self.state(qd, j)[1]
                out[:, row] = ai[0] * wi ** 2 - aj[0] * wj ** 2
                out[:, row + 1] = ai[1] * wi ** 2 - aj[1] * wj ** 2
            elif kind is _Rows.LINE:
                s, through, d, _ = item
                p, g, dg, arm_l, arm_g = self._slide_terms(q, s, through, d)
                ed, wl, wg = e_dot(s.link, s.guide_link, arm_l, arm_g)
                inner = (wg ** 2 * arm_g[0] - wl ** 2 * arm_l[0],
                         wg ** 2 * arm_g[1] - wl ** 2 * arm_l[1])
                out[:, row] = (wg ** 2 * _cross(dg, (p[0] - g[0], p[1] - g[1]))
                               - 2.0 * wg * _cross(_perp(dg), ed) - _cross(dg, inner))
            elif kind is _Rows.TURN:
                out[:, row] = sy.m.drive.alpha if item[2] is None else 0.0
            elif kind is _Rows.ARC:
                e, arm_l, arm_g = self._arc_terms(q, item)
                ed, wl, wg = e_dot(item.link, item.guide_link, arm_l, arm_g)
                inner = (wl ** 2 * arm_l[0] - wg ** 2 * arm_g[0],
                         wl ** 2 * arm_l[1] - wg ** 2 * arm_g[1])
                out[:, row] = (e[0] * inner[0] + e[1] * inner[1]
                               - (ed[0] * ed[0] + ed[1] * ed[1])) / item.radius
            else:
                e, arm_l, arm_g = self._arc_terms(q, item)
                ed, wl, wg = e_dot(item.link, item.guide_link, arm_l, arm_g)
                ee, m = e[0] * e[0] + e[1] * e[1], _round_rate(e)
                inner = (wg ** 2 * arm_g[0] - wl ** 2 * arm_l[0],
                         wg ** 2 * arm_g[1] - wl ** 2 * arm_l[1])
                out[:, row] = item.roll_gain * (
                    m[0] * inner[0] + m[1] * inner[1]
                    - 2.0 * (e[0] * ed[0] + e[1] * ed[1]) * _cross(e, ed) / ee ** 2)
        return out
