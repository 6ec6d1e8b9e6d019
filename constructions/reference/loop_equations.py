"""The loop equations over body coordinates: ``Φ(q)``, its Jacobian ``Φ_q`` and ``γ``.

Every moving link ``k`` has body coordinates ``q_k = (x_k, y_k, φ_k)``: the global
position of its local origin and the angle of its local +x axis (CCW-positive from
+x, radians). The constraints ``Φ(q, t) = 0`` are

- pin: ``R(φi) p_i + t_i − R(φj) p_j − t_j = 0`` (the frame is the identity);
- slide: ``cross(D, P − G) = 0`` with the guide's global point ``G`` and unit
  direction ``D``; a ``BLOCK`` adds ``φ_link − φ_guide − atan2(direction) = 0``,
  wrapped to ``[−π, π]``; a rolling contact adds the no-slip condition
  ``D·(P − G) + σ r (φ_wheel − φ_face) = 0`` (see ``Contact.roll_sign``);
- arc: ``(|P − C|² − ρ²) / 2ρ = 0`` for a point ``P`` kept ``ρ`` from a point
  ``C`` of another link (a pin in a curved slot, two circles in contact);
- drive: ``φ_input − angle = 0``, wrapped the same way.

Which rows a joint adds is its kind's entry in :mod:`.joint_equations`, which also lays
the rows out: the pins', every joint's, word by word, then the drive's. ``_System``
evaluates them at one position; :mod:`.batch_loops` evaluates the same rows, in the same
order, over many positions.
Each is differentiated exactly, never by finite differences.
"""

from __future__ import annotations

import math

import numpy as np

from ..joints import Arc, Slide
from ..model import Mechanism
from .joint_equations import Equation, joints_with, layout
from .planar import _S, _cross, _locals, _round_angle, _rot, _unit, _wrap

__all__: list[str] = []


class _System:
    """``Φ(q)``, ``Φ_q`` and the acceleration right-hand side over body coordinates."""

    def __init__(self, mech: Mechanism):
        self.m = mech
        self.moving = sorted(k.number for k in mech.links if k.number != 1)
        self.col = {k: 3 * i for i, k in enumerate(self.moving)}
        self.loc = _locals(mech)
        self.pins = [(n, at[0], j) for n in mech.point_names
                     for at in [mech.links_at(n)] for j in at[1:]]
        self.slides = [(s, np.asarray(s.through, dtype=float), _unit(s.direction),
                        math.atan2(s.direction[1], s.direction[0]))
                       for s in joints_with(mech, Equation.LINE)]
        # A block's link turns with its guide: a second row, beside its line's.
        turns = joints_with(mech, Equation.TURN)
        self.turning = {i for i, (s, *_) in enumerate(self.slides) if s in turns}
        # A rolling contact's no-slip row D·(P − G) is the slide's cross row taken with
        # the direction turned −90° (cross(S⁻¹D, e) = D·e), plus σ r (φ_wheel − φ_face).
        rolling = joints_with(mech, Equation.NO_SLIP)
        self.rolls = [(s, through, np.array([d[1], -d[0]]),
                       s.contact.roll_sign * s.contact.circle.radius)
                      for s, through, d, _ in self.slides if s in rolling]
        self.arcs = joints_with(mech, Equation.DISTANCE)
        # A wheel rolling on a circle adds r·(φ_wheel − φ_guide) − k·β = 0, β the angle its
        # centre has gone round the circle's from the guide's +x (see Arc.roll_gain).
        self.rounds = list(joints_with(mech, Equation.ROLLED_ROUND))
        is_len = [True] * (2 * len(self.pins))
        is_len += [e is not Equation.TURN for e, _ in layout(mech)]
        self.is_len = np.array(is_len + [False])
        sizes = [abs(c) for v in self.loc.values() for c in v]
        sizes += [abs(c) for s in mech.slides for c in s.through]
        sizes += [a.radius for a in self.arcs]
        self.lc = max(sizes, default=0.0) or 1.0
        # The scalings of rows (lengths in units of lc) and columns (x, y in lc, φ alone).
        self.row_scale = np.where(self.is_len, 1.0 / self.lc, 1.0)
        self.col_scale = np.tile([self.lc, self.lc, 1.0], len(self.moving))

    def state(self, q, k: int) -> tuple[np.ndarray, float]:
        if k == 1:
            return np.zeros(2), 0.0
        c = self.col[k]
        return q[c:c + 2], float(q[c + 2])

    def _slide_terms(self, q, s, through, d):
        (tl, fl), (tg, fg) = self.state(q, s.link), self.state(q, s.guide_link)
        arm_l, arm_g = _rot(fl) @ self.loc[s.link, s.point], _rot(fg) @ through
        return tl + arm_l, tg + arm_g, _rot(fg) @ d, arm_l, arm_g

    def residual(self, q) -> np.ndarray:
        out: list[float] = []
        for n, i, j in self.pins:
            (ti, fi), (tj, fj) = self.state(q, i), self.state(q, j)
            out += list(ti + _rot(fi) @ self.loc[i, n] - tj - _rot(fj) @ self.loc[j, n])
        for i, (s, through, d, off) in enumerate(self.slides):
            p, g, dg, _, _ = self._slide_terms(q, s, through, d)
            out.append(_cross(dg, p - g))
            if i in self.turning:
                out.append(_wrap(self.state(q, s.link)[1] - self.state(q, s.guide_link)[1] - off))
        for s, through, u, k in self.rolls:
            p, g, ug, _, _ = self._slide_terms(q, s, through, u)
            turned = self.state(q, s.link)[1] - self.state(q, s.guide_link)[1]
            out.append(_cross(ug, p - g) + k * turned)
        for a in self.arcs:
            e = self._arc_terms(q, a)[0]
            out.append((float(e @ e) - a.radius ** 2) / (2.0 * a.radius))
        for a in self.rounds:
            e = self._arc_terms(q, a)[0]
            fw, fg = self.state(q, a.link)[1], self.state(q, a.guide_link)[1]
            out.append(a.contact.circle.radius * (fw - fg)
                       - a.roll_gain * _round_angle(math.atan2(e[1], e[0]) - fg))
        out.append(_wrap(self.state(q, self.m.drive.link)[1] - self.m.drive.angle))
        return np.array(out)

    def _arc_terms(self, q, a: Arc):
        """``e = P − C`` and the arms of P and C from their links' origins."""
        (tl, fl), (tg, fg) = self.state(q, a.link), self.state(q, a.guide_link)
        arm_l, arm_g = _rot(fl) @ self.loc[a.link, a.point], _rot(fg) @ self.loc[a.guide_link,
                                                                                a.centre]
        return tl + arm_l - tg - arm_g, arm_l, arm_g

    def jacobian(self, q) -> np.ndarray:
        jac = np.zeros((len(self.is_len), 3 * len(self.moving)))

        def put(row: int, k: int, dt, dphi: float, sign: float = 1.0) -> None:
            if k != 1:
                c = self.col[k]
                jac[row, c:c + 2] += sign * np.asarray(dt)
                jac[row, c + 2] += sign * dphi

        def line_row(row: int, s: Slide, through, d) -> None:
            p, g, dg, arm_l, arm_g = self._slide_terms(q, s, through, d)
            put(row, s.link, (-dg[1], dg[0]), _cross(dg, _S @ arm_l))
            put(row, s.guide_link, (dg[1], -dg[0]),
                _cross(_S @ dg, p - g) - _cross(dg, _S @ arm_g))

        row = 0
        for n, i, j in self.pins:
            for k, sign in ((i, 1.0), (j, -1.0)):
                arm = _S @ _rot(self.state(q, k)[1]) @ self.loc[k, n]
                put(row, k, (1.0, 0.0), arm[0], sign)
                put(row + 1, k, (0.0, 1.0), arm[1], sign)
            row += 2
        for i, (s, through, d, _) in enumerate(self.slides):
            line_row(row, s, through, d)
            row += 1
            if i in self.turning:
                put(row, s.link, (0.0, 0.0), 1.0)
                put(row, s.guide_link, (0.0, 0.0), -1.0)
                row += 1
        for s, through, u, k in self.rolls:
            line_row(row, s, through, u)
            put(row, s.link, (0.0, 0.0), k)
            put(row, s.guide_link, (0.0, 0.0), -k)
            row += 1
        for a in self.arcs:
            e, arm_l, arm_g = self._arc_terms(q, a)
            put(row, a.link, e / a.radius, float(e @ (_S @ arm_l)) / a.radius)
            put(row, a.guide_link, -e / a.radius, -float(e @ (_S @ arm_g)) / a.radius)
            row += 1
        for a in self.rounds:
            e, arm_l, arm_g = self._arc_terms(q, a)
            k, r = a.roll_gain, a.contact.circle.radius
            m = (_S @ e) / float(e @ e)                # ∂β/∂e
            put(row, a.link, -k * m, r - k * float(m @ (_S @ arm_l)))
            put(row, a.guide_link, k * m, k - r + k * float(m @ (_S @ arm_g)))
            row += 1
        put(row, self.m.drive.link, (0.0, 0.0), 1.0)
        return jac

    def gamma(self, q, qd) -> np.ndarray:
        """Return ``−(Φ_q q̇)_q q̇ − Φ_tt`` (the drive row carries α)."""
        out: list[float] = []
        for n, i, j in self.pins:
            (_, fi), (_, fj) = self.state(q, i), self.state(q, j)
            wi, wj = self.state(qd, i)[1], self.state(qd, j)[1]
            out += list(_rot(fi) @ self.loc[i, n] * wi ** 2 - _rot(fj) @ self.loc[j, n] * wj ** 2)

        def line_gamma(s: Slide, through, d) -> float:
            p, g, dg, arm_l, arm_g = self._slide_terms(q, s, through, d)
            (vl, wl), (vg, wg) = self.state(qd, s.link), self.state(qd, s.guide_link)
            e_dot = vl + wl * (_S @ arm_l) - vg - wg * (_S @ arm_g)
            return (wg ** 2 * _cross(dg, p - g) - 2.0 * wg * _cross(_S @ dg, e_dot)
                    - _cross(dg, wg ** 2 * arm_g - wl ** 2 * arm_l))

        for i, (s, through, d, _) in enumerate(self.slides):
            out.append(line_gamma(s, through, d))
            if i in self.turning:
                out.append(0.0)
        out += [line_gamma(s, through, u) for s, through, u, _ in self.rolls]
        for a in self.arcs:
            e, arm_l, arm_g = self._arc_terms(q, a)
            (vl, wl), (vg, wg) = self.state(qd, a.link), self.state(qd, a.guide_link)
            e_dot = vl + wl * (_S @ arm_l) - vg - wg * (_S @ arm_g)
            out.append((float(e @ (wl ** 2 * arm_l - wg ** 2 * arm_g)) - float(e_dot @ e_dot))
                       / a.radius)
        for a in self.rounds:
            e, arm_l, arm_g = self._arc_terms(q, a)
            (vl, wl), (vg, wg) = self.state(qd, a.link), self.state(qd, a.guide_link)
            e_dot = vl + wl * (_S @ arm_l) - vg - wg * (_S @ arm_g)
            ee = float(e @ e)
            m = (_S @ e) / ee
            out.append(a.roll_gain * (float(m @ (wg ** 2 * arm_g - wl ** 2 * arm_l))
                                      - 2.0 * float(e @ e_dot) * _cross(e, e_dot) / ee ** 2))
        out.append(self.m.drive.alpha)
        return np.array(out)

    def scaled(self, jac) -> np.ndarray:
        """Make the Jacobian dimensionless: lengths in units of the mechanism's size."""
        return jac * self.row_scale[:, None] * self.col_scale[None, :]

    def scaled_max(self, residual: np.ndarray) -> float:
        """The largest of a residual's entries, lengths in units of the mechanism's size."""
        return float(np.max(np.abs(residual * self.row_scale)))
