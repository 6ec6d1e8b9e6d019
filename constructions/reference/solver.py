"""The independent analytic reference: body coordinates, closed-form assembly, Newton.

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

The position is first found in closed form, dyad by dyad, honouring the branches
(see :func:`solve`), then polished by Newton on the full ``Φ``. Velocities solve
``Φ_q q̇ = −Φ_t`` and accelerations ``Φ_q q̈ = −(Φ_q q̇)_q q̇ − Φ_tt``; both are
differentiated exactly, never by finite differences.

This module shares no code with the graphical constructions: it imports only
numpy, the standard library, :mod:`constructions.model` and
:mod:`constructions.errors`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ..errors import AssemblyError, DeadPoint, InputError
from ..model import Arc, Mechanism, Slide, SlideKind

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

_EPS = float(np.finfo(float).eps)
_SLACK = 64 * _EPS  # rounding slack for a tangency: below it, a cut is taken as exact
SINGULAR_RCOND = 1e-7
"""Below this reciprocal condition number of the scaled Jacobian a position is singular.

A toggle reached through rounding sits about ``sqrt(eps) ≈ 1.5e-8`` from exact
singularity, so a smaller threshold would let dead points through as huge ω.
"""
_NEWTON_STEPS = 12
_S = np.array([[0.0, -1.0], [1.0, 0.0]])  # rotation by +90°: d/dφ R(φ) = S R(φ)


class SingularPosition(DeadPoint):
    """The position is a dead point: the Jacobian is singular, so ω and α are undefined."""


@dataclass(frozen=True, slots=True)
class SlideRate:
    """Relative motion at one slide, signed along the guide's global direction.

    ``position`` is the coordinate of the sliding point along the guide measured
    from the guide's ``through`` point; ``velocity`` and ``acceleration`` are its
    first and second time derivatives (the sliding velocity and acceleration seen
    from the guide link). ``direction`` is the guide's global unit direction and
    ``coriolis`` is ``2 ω_guide × v_rel``.
    """

    slide: Slide
    position: float
    velocity: float
    acceleration: float
    direction: tuple[float, float]
    coriolis: tuple[float, float]


@dataclass(frozen=True)
class FreeMotion:
    """The mechanism's one motion with the input let go: ω and origin velocities up to scale.

    The null vector of the loop equations without the input's row, unit in the
    length-scaled coordinates. Near a dead point of the input the solved ω and v grow
    without bound and carry an error of ``eps/rcond`` of their size, while this
    direction stays as well conditioned as the free linkage itself (``conditioning``:
    its smallest singular value over its largest). Whatever depends on velocity ratios
    alone, such as the instant centres, is taken from it.
    """

    omegas: dict[int, float]
    origin_velocities: dict[int, tuple[float, float]]
    conditioning: float


@dataclass(frozen=True)
class Kinematics:
    """Positions, velocities and accelerations of a mechanism at one input position (SI).

    A point's position, velocity and acceleration are those of the point as a point
    of the first link (in ``Mechanism.links`` order) that lists it. At a pin every
    carrier agrees to the residual, and a pin on the frame is exactly at rest. Use
    :func:`point_velocity` for a point taken on a particular link. ``slide_rates``
    follows the order of ``Mechanism.slides``. ``residual`` is ``max |Φ|`` (m or
    rad) at the solution and ``conditioning`` the reciprocal condition number of
    the length-scaled Jacobian (1 is ideal, below ``SINGULAR_RCOND`` is raised).
    ``origins`` and their rates are each link's local origin, the frame included.
    Angles are wrapped to ``[−π, π]``. ``free`` is the motion with the input let go
    (see :class:`FreeMotion`).
    """

    points: dict[str, tuple[float, float]]
    angles: dict[int, float]
    omegas: dict[int, float]
    alphas: dict[int, float]
    velocities: dict[str, tuple[float, float]]
    accelerations: dict[str, tuple[float, float]]
    slide_rates: tuple[SlideRate, ...]
    residual: float
    conditioning: float
    origins: dict[int, tuple[float, float]]
    origin_velocities: dict[int, tuple[float, float]]
    origin_accelerations: dict[int, tuple[float, float]]
    free: FreeMotion | None = None



def _rot(phi: float) -> np.ndarray:
    c, s = math.cos(phi), math.sin(phi)
    return np.array([[c, -s], [s, c]])


def _cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _wrap(angle: float) -> float:
    return math.remainder(angle, math.tau)


def _round_angle(angle: float) -> float:
    """The angle a wheel's centre has gone round its circle, in [−π, π): one half-open
    wrap, the same as the sweeps' vectorised one, so both turn the wheel alike at ±π."""
    return (angle + math.pi) % math.tau - math.pi


def _locals(mech: Mechanism) -> dict[tuple[int, str], np.ndarray]:
    return {(k.number, n): np.array(xy, dtype=float) for k in mech.links for n, xy in k.points}


def _unit(v) -> np.ndarray:
    v = np.asarray(v, dtype=float)
    n = math.hypot(v[0], v[1])
    if n == 0.0:
        raise InputError("a slide has a zero direction vector")
    return v / n


# ----------------------------------------------------------------------------- model checks

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



# ----------------------------------------------------------------------------- closed form

class _Assembly:
    """Locate points dyad by dyad; ``pose`` maps a link to (origin, angle)."""

    def __init__(self, mech: Mechanism):
        self.m = mech
        self.units = mech.units
        self.names = {k.number: k.names for k in mech.links}
        self.loc = _locals(mech)
        self.at: dict[str, np.ndarray] = {n: self.loc[1, n] for n in self.names[1]}
        self.pose: dict[int, tuple[np.ndarray, float]] = {1: (np.zeros(2), 0.0)}
        self.phi: dict[int, float] = {1: 0.0, mech.drive.link: mech.drive.angle}
        self.used: set[str] = set()
        self.picked: dict[str, str] = {}
        """The word each branch took: a near point's is the side it chose."""
        self.deg = math.degrees(mech.drive.angle)

    def run(self) -> dict[int, tuple[np.ndarray, float]]:
        self._rigid()
        while len(self.pose) < len(self.names):
            if not (self._cut_point() or self._slotted_lever()):
                self._stuck()
            self._rigid()
        return self.pose

    def _fail(self, message: str, link: int, joint: str | None = None) -> AssemblyError:
        return AssemblyError(f"{message} at input angle "
                             f"{self.units.angle_brief(self.m.drive.angle)}", link=link,
                             joint=joint, angle_deg=self.deg)

    def _len(self, metres: float) -> str:
        return self.units.length_brief(metres)

    def _label(self, k: int) -> str:
        return self.m.link(k).label

    def _rigid(self) -> None:
        """Propagate BLOCK orientations and pose every link fixed by what is known."""
        changed = True
        while changed:
            changed = False
            for s in self.m.slides:
                if s.kind is not SlideKind.BLOCK:
                    continue
                off = math.atan2(s.direction[1], s.direction[0])
                if s.guide_link in self.phi and s.link not in self.phi:
                    self.phi[s.link] = self.phi[s.guide_link] + off
                    self._turned(s.link, s.guide_link, off)
                    changed = True
                elif s.link in self.phi and s.guide_link not in self.phi:
                    self.phi[s.guide_link] = self.phi[s.link] - off
                    self._turned(s.guide_link, s.link, -off)
                    changed = True
            for s in self.m.slides:
                if s.rolling and s.link in self.phi and s.guide_link in self.pose \
                        and s.point not in self.at:
                    # The wheel's angle (the input) says how far its centre has rolled.
                    origin, phi = self.pose[s.guide_link]
                    along = -s.contact.roll_sign * s.contact.circle.radius * (
                        self.phi[s.link] - phi)
                    self.at[s.point] = origin + _rot(phi) @ (
                        np.asarray(s.through, dtype=float) + along * _unit(s.direction))
                    self._rolled_on(s)
                    changed = True
            for a in self.m.rolling_arcs:
                if a.rolling and a.link not in self.phi and a.guide_link in self.pose \
                        and a.point in self.at and a.centre in self.at:
                    # The angle the centre has gone round says how far the wheel has turned.
                    e = self.at[a.point] - self.at[a.centre]
                    phi = self.pose[a.guide_link][1]
                    beta = _round_angle(math.atan2(e[1], e[0]) - phi)
                    self.phi[a.link] = phi + a.roll_gain * beta / a.contact.circle.radius
                    self._rolled_round(a)
                    changed = True
            for s in self.m.slides:
                if s.rolling and s.link not in self.phi and s.guide_link in self.pose \
                        and s.point in self.at:
                    origin, phi = self.pose[s.guide_link]
                    d = _rot(phi) @ _unit(s.direction)
                    along = float(d @ (self.at[s.point] - origin - _rot(phi) @ np.asarray(
                        s.through, dtype=float)))
                    self.phi[s.link] = phi - along / (s.contact.roll_sign * s.contact.circle.radius)
                    self._rolled(s)
                    changed = True
            for k, names in self.names.items():
                if k in self.pose:
                    continue
                known = [n for n in names if n in self.at]
                if k in self.phi and known:
                    phi = self.phi[k]
                elif len(known) >= 2 and self._angle_from(k, known) is not None:
                    phi = self._angle_from(k, known)
                else:
                    continue
                p = known[0]
                self._placed(k, known)
                origin = self.at[p] - _rot(phi) @ self.loc[k, p]
                self.pose[k], self.phi[k] = (origin, phi), phi
                for n in names:
                    self.at.setdefault(n, origin + _rot(phi) @ self.loc[k, n])
                changed = True

    # Hooks for a recorder of the acts in order (.assembly_plan); a solve records nothing.
    def _turned(self, link: int, by: int, offset: float) -> None:
        """A block set ``link``'s angle to link ``by``'s plus ``offset``."""

    def _rolled(self, s: Slide) -> None:
        """The rolling contact ``s`` set its wheel's angle."""

    def _rolled_round(self, a: Arc) -> None:
        """The rolling contact ``a`` on a circle set its wheel's angle."""

    def _rolled_on(self, s: Slide) -> None:
        """The rolling contact ``s`` set its wheel's centre from the wheel's angle."""

    def _placed(self, k: int, known: list[str]) -> None:
        """Link ``k`` is about to be posed at ``known[0]`` (its angle known, or from ``known``)."""

    def _slotted(self, s: Slide, q: str, branch) -> None:
        """The slot of ``s`` is about to be turned about ``q`` to pass its block."""

    def _angle_from(self, k: int, known: list[str]) -> float | None:
        a = known[0]
        for b in known[1:]:
            dl = self.loc[k, b] - self.loc[k, a]
            if math.hypot(*dl) > 0.0:
                dg = self.at[b] - self.at[a]
                return math.atan2(dg[1], dg[0]) - math.atan2(dl[1], dl[0])
        return None

    def _branch(self, name: str, allowed: tuple[str, ...]):
        b = self.m.branches.get(name)
        if b is None:
            raise InputError(f"point {name} has two solutions: give its branch "
                             f"({' or '.join(allowed)}, or a near point (x, y))",
                             file=self.m.source or None, key=name)
        if isinstance(b, str) and b not in allowed:
            raise InputError(f"'{b}' is not a valid branch for point {name}, must be one of "
                             f"{', '.join(allowed)} or a near point (x, y)",
                             file=self.m.source or None, key=name)
        return b

    def _pick(self, name: str, first: np.ndarray, second: np.ndarray, words: tuple[str, str]):
        """Take ``first`` for ``words[0]``, ``second`` for ``words[1]``, or the nearer one."""
        b = self._branch(name, words)
        self.used.add(name)
        if not isinstance(b, str):
            near = np.asarray(b, dtype=float)
            b = words[int(np.linalg.norm(first - near) > np.linalg.norm(second - near))]
        self.picked[name] = b
        return first if b == words[0] else second

    def _circles(self, name: str) -> list[tuple[int, str, float]]:
        out = []
        for k in self.m.links_at(name):
            if k in self.pose or k in self.phi:
                continue
            known = [n for n in self.names[k] if n in self.at]
            if len(known) == 1:
                r = float(np.linalg.norm(self.loc[k, name] - self.loc[k, known[0]]))
                if r > 0.0:
                    out.append((k, known[0], r))
        for a in self.m.pin_arcs:
            for here, there, k in ((a.point, a.centre, a.guide_link),
                                   (a.centre, a.point, a.link)):
                if here == name and there in self.at:
                    out.append((k, there, a.radius))
        return out

    def _lines(self, name: str) -> list[tuple[np.ndarray, np.ndarray, Slide]]:
        """Global lines (point, unit direction) the unlocated point ``name`` must lie on."""
        out = []
        for s in self.m.slides:
            sl, g, d = s.link, s.guide_link, _unit(s.direction)
            through = np.asarray(s.through, dtype=float)
            if g in self.pose:
                origin, phi = self.pose[g]
                base, dg = origin + _rot(phi) @ through, _rot(phi) @ d
                if s.point == name:
                    out.append((base, dg, s))
                elif name in self.names[sl] and sl in self.phi:
                    shift = _rot(self.phi[sl]) @ (self.loc[sl, name] - self.loc[sl, s.point])
                    out.append((base + shift, dg, s))
            elif g in self.phi and s.point in self.at and name in self.names[g]:
                rg = _rot(self.phi[g])
                out.append((self.at[s.point] + rg @ (self.loc[g, name] - through), rg @ d, s))
        return out

    def _cut_point(self) -> bool:
        for name in self.m.point_names:
            if name in self.at:
                continue
            circles, lines = sorted(self._circles(name)), self._lines(name)
            if len(circles) >= 2:
                self.at[name] = self._circle_circle(name, circles[0], circles[1])
            elif circles and lines:
                self.at[name] = self._circle_line(name, circles[0], lines[0])
            elif len(lines) >= 2:
                self.at[name] = self._line_line(name, lines[0], lines[1])
            else:
                continue
            return True
        return False

    def _circle_circle(self, name, ci, cj) -> np.ndarray:
        (i, x, ri), (j, y, rj) = ci, cj
        cx, cy = self.at[x], self.at[y]
        d = float(np.linalg.norm(cy - cx))
        if d == 0.0:
            if abs(ri - rj) <= _SLACK * max(ri, rj):
                # The circles coincide (a rhombus's moving pin on a frame pivot): the linkage
                # assembles with the pin anywhere on them, i and j turning together about x
                # while the input is held. It is the dead point the Jacobian finds a rounding
                # either side, and a change point a turn may land on: refused as one.
                error = _dead_point(self.m, sorted((i, j)))
                error.detail = f"the circles that place {name} about {x} and {y} coincide"
                raise error
            raise self._fail(f"{self._label(i)} and {self._label(j)} turn about the same point "
                             f"{x} = {y}, so {name} is undetermined", i, name)
        margin = max(d - (ri + rj), abs(ri - rj) - d)
        if margin > _SLACK * max(ri, rj, d):
            raise self._fail(
                f"{self._label(i)} with {x}{name} = {self._len(ri)} and {self._label(j)} with "
                f"{y}{name} = {self._len(rj)} cannot reach {name}: {x} and {y} are "
                f"{self._len(d)} apart (short by {self._len(margin)})", i, name)
        h2 = max(0.0, (ri + rj - d) * (ri + rj + d) * (d - ri + rj) * (d + ri - rj))
        u = (cy - cx) / d
        foot = cx + (d * d + ri * ri - rj * rj) / (2.0 * d) * u
        h = math.sqrt(h2) / (2.0 * d)
        return self._pick(name, foot + h * (_S @ u), foot - h * (_S @ u), ("left", "right"))

    def _circle_line(self, name, circle, line) -> np.ndarray:
        (k, x, r), (base, d, slide) = circle, line
        c = self.at[x]
        foot = base + float((c - base) @ d) * d
        off = float(np.linalg.norm(c - foot))
        if off - r > _SLACK * max(r, off):
            raise self._fail(f"{self._label(k)} with {x}{name} = {self._len(r)} cannot reach "
                             f"the line of {slide.label}: it passes {self._len(off)} from {x}",
                             k, name)
        h = math.sqrt(max(0.0, (r - off) * (r + off)))
        return self._pick(name, foot + h * d, foot - h * d, ("forward", "backward"))

    def _line_line(self, name, first, second) -> np.ndarray:
        (g1, d1, s1), (g2, d2, s2) = first, second
        det = _cross(d2, d1)
        if abs(det) <= _SLACK:
            raise self._fail(f"the lines of {s1.label} and {s2.label} are parallel, so "
                             f"{name} is undetermined", s1.link, name)
        return g1 + _cross(d2, g2 - g1) / det * d1

    def _slotted_lever(self) -> bool:
        """Turn a guide link about its one located point until its slot passes the block."""
        for s in self.m.slides:
            g = s.guide_link
            if s.point not in self.at or g in self.phi:
                continue
            known = [n for n in self.names[g] if n in self.at]
            if len(known) != 1:
                continue
            q = known[0]
            d = _unit(s.direction)
            w = self.at[s.point] - self.at[q]
            c = _cross(d, np.asarray(s.through, dtype=float) - self.loc[g, q])
            reach = float(np.linalg.norm(w))
            # A block this near the pivot of a slot through it leaves the slot's direction to
            # rounding: no assembly to solve (the rank test's SINGULAR_RCOND, in lengths).
            size = max(float(np.max(np.abs(v))) for v in self.loc.values())
            if abs(c) <= _SLACK * size and reach <= SINGULAR_RCOND * size:
                raise self._fail(f"the block {s.point} sits on {q}, the pivot of the slot of "
                                 f"{self._label(g)}, so the slot has no direction", g, s.point)
            if abs(c) - reach > _SLACK * max(abs(c), reach) or reach == 0.0:
                raise self._fail(f"the slot of {self._label(g)} passes {self._len(abs(c))} from "
                                 f"{q}, but {s.point} is {self._len(reach)} from {q}: the "
                                 f"{s.label} cannot reach it", g, s.point)
            a = math.asin(max(-1.0, min(1.0, c / reach)))
            beta = math.atan2(w[1], w[0])
            ahead, behind = beta - a, beta - math.pi + a
            b = self.m.branches.get(s.point, "forward")
            if s.point in self.used:  # that branch located the point itself
                b = "forward"
            if b not in ("forward", "backward") and isinstance(b, str):
                raise InputError(f"'{b}' is not a valid branch for the {s.label}, must be one "
                                 f"of forward, backward or a near point (x, y)",
                                 file=self.m.source or None, key=s.point)
            self._slotted(s, q, b)
            if not isinstance(b, str):  # the slot direction that points more nearly towards it
                n = np.asarray(b, dtype=float) - self.at[q]
                b = max((("forward", ahead), ("backward", behind)),
                        key=lambda t: math.cos(t[1]) * n[0] + math.sin(t[1]) * n[1])[0]
            self.picked.setdefault(s.point, b)
            psi = ahead if b == "forward" else behind
            self.phi[g] = psi - math.atan2(d[1], d[0])
            return True
        return False

    def _stuck(self):
        left = sorted(k for k in self.names if k not in self.pose)
        for k in left:
            if self.names[k] and all(n in self.at for n in self.names[k]):
                raise self._fail(f"the orientation of {self._label(k)} is fixed by no joint "
                                 f"(give it a second point or make its slide a block)", k)
        raise self._fail(f"links {', '.join(map(str, left))} cannot be located dyad by dyad: "
                         f"the mechanism needs a triad (or higher Assur group) solver", left[0])


# ----------------------------------------------------------------------------- constraint system

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
                        math.atan2(s.direction[1], s.direction[0])) for s in mech.slides]
        # A rolling contact's no-slip row D·(P − G) is the slide's cross row taken with
        # the direction turned −90° (cross(S⁻¹D, e) = D·e), plus σ r (φ_wheel − φ_face).
        self.rolls = [(s, through, np.array([d[1], -d[0]]),
                       s.contact.roll_sign * s.contact.circle.radius)
                      for s, through, d, _ in self.slides if s.rolling]
        self.arcs = mech.pin_arcs
        # A wheel rolling on a circle adds r·(φ_wheel − φ_guide) − k·β = 0, β the angle its
        # centre has gone round the circle's from the guide's +x (see Arc.roll_gain).
        self.rounds = list(mech.rolling_arcs)
        is_len = [True] * (2 * len(self.pins))
        for s, *_ in self.slides:
            is_len += [True, False] if s.kind is SlideKind.BLOCK else [True]
        is_len += [True] * (len(self.rolls) + len(self.arcs) + len(self.rounds))
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
        for s, through, d, off in self.slides:
            p, g, dg, _, _ = self._slide_terms(q, s, through, d)
            out.append(_cross(dg, p - g))
            if s.kind is SlideKind.BLOCK:
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
        for s, through, d, _ in self.slides:
            line_row(row, s, through, d)
            row += 1
            if s.kind is SlideKind.BLOCK:
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

        for s, through, d, _ in self.slides:
            out.append(line_gamma(s, through, d))
            if s.kind is SlideKind.BLOCK:
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


# ----------------------------------------------------------------------------- solve

def _dead_point(mech: Mechanism, free: list[int]) -> SingularPosition:
    """The refusal of a dead point, where links ``free`` can move with the input held."""
    who = "link" if len(free) == 1 else "links"
    return SingularPosition(
        f"dead point at input angle {mech.units.angle_brief(mech.drive.angle)}: {who} "
        f"{', '.join(map(str, free))} can move while link {mech.drive.link} is held, so ω and "
        "α are undefined; choose another input angle or another input link", link=free[0],
        angle_deg=math.degrees(mech.drive.angle))


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


def _velocity(p, origin, v0, omega) -> tuple[float, float]:
    rx, ry = p[0] - origin[0], p[1] - origin[1]
    return (float(v0[0] - omega * ry), float(v0[1] + omega * rx))


def _acceleration(p, origin, a0, omega, alpha) -> tuple[float, float]:
    rx, ry = p[0] - origin[0], p[1] - origin[1]
    return (float(a0[0] - alpha * ry - omega ** 2 * rx),
            float(a0[1] + alpha * rx - omega ** 2 * ry))


def _where(kin: Kinematics, mech: Mechanism, link: int, point) -> tuple[float, float]:
    mech.link(link)
    if isinstance(point, str):
        if point not in kin.points:
            raise InputError(f"there is no point {point}", file=mech.source or None)
        return kin.points[point]
    return (float(point[0]), float(point[1]))


def point_velocity(kin: Kinematics, mech: Mechanism, link: int, point) -> tuple[float, float]:
    """Return the velocity of a point taken as fixed to ``link``: ``v_O + ω × r``.

    Parameters
    ----------
    kin, mech : Kinematics, Mechanism
        A solution and the mechanism it solves.
    link : int
        The link the point is fixed to (1 gives zero).
    point : str or (float, float)
        A point name, or a global position in metres (e.g. a coincident point).

    Raises
    ------
    InputError
        If the link or the point name is unknown.
    """
    return _velocity(_where(kin, mech, link, point), kin.origins[link],
                     kin.origin_velocities[link], kin.omegas[link])


def point_acceleration(kin: Kinematics, mech: Mechanism, link: int,
                       point) -> tuple[float, float]:
    """Return the acceleration of a point fixed to ``link``: ``a_O + α × r − ω² r``.

    See :func:`point_velocity` for the parameters.
    """
    return _acceleration(_where(kin, mech, link, point), kin.origins[link],
                         kin.origin_accelerations[link], kin.omegas[link], kin.alphas[link])
