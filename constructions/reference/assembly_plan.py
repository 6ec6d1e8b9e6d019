"""Record the closed-form assembly's order once, then replay it over many input angles.

The dyad-by-dyad assembly of :mod:`.solver` takes the same acts in the same order at
every input angle: which point is cut from which two arcs, which link is posed from
which points. Only the numbers, the branch a near point picks, and whether a link
reaches, depend on the angle. :func:`record_plan` runs the scalar ``_Assembly`` once
through hooks that note each act; :meth:`AssemblyPlan.place` replays the acts with
numpy over an array of input angles and returns the start vector of body coordinates
for all of them, with the positions that cannot assemble and those too near a verdict
or a tangency to trust to the replay (the caller hands those to the scalar solver).

A branch is honoured exactly as the scalar solver honours it: a word is a side, and a
near point picks, at each angle, the solution nearer that point (apply
:func:`~.solver.follow_branches` first to keep the side taken at the stated position).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from enum import StrEnum
from functools import cached_property

import numpy as np

from .dyad_assembly import _Assembly
from .loop_equations import _System
from .planar import _SLACK, _unit
from .solver import SINGULAR_RCOND
from ..errors import AssemblyError
from ..joints import Arc, Slide
from ..model import Mechanism

__all__ = ["AssemblyPlan", "Placement", "record_plan", "WELL"]

WELL = 1e-3
"""Below this a cut's clearance over its size hands the position to the scalar solver: near
a tangency the replay's round-off, amplified there, could tip a later reach's verdict."""

_CLEAR = 4.0
"""A reach fails clearly when it misses by this many times the scalar solver's slack; a
miss nearer the slack is re-decided by the scalar solver, so the verdicts agree."""

_TIE = 1e-9
"""Near points about this (relatively) equidistant from both solutions are re-decided."""


class LineFrom(StrEnum):
    """How a guide line through an unlocated point is found (see ``_Assembly._lines``)."""

    GUIDE = "guide"
    """The sliding point itself on the posed guide link's line."""
    SHIFTED = "shifted"
    """Another point of the sliding link, whose angle is known, on a line shifted with it."""
    CARRIED = "carried"
    """A point of the guide link (its angle known, not posed) through the located block."""


@dataclass(frozen=True, slots=True)
class Turned:
    """A block sets ``link``'s angle to link ``by``'s plus ``offset``."""

    link: int
    by: int
    offset: float


@dataclass(frozen=True, slots=True)
class Rolled:
    """A wheel's angle from the distance rolled along its face (``slide`` is the contact)."""

    slide: Slide


@dataclass(frozen=True, slots=True)
class RolledRound:
    """A wheel's angle from how far its centre has gone round the circle it rolls on."""

    arc: Arc


@dataclass(frozen=True, slots=True)
class RolledOn:
    """A wheel's centre from its angle: the distance rolled along its face (``slide``)."""

    slide: Slide


@dataclass(frozen=True, slots=True)
class Placed:
    """Link ``link`` posed at its located point ``at``, its angle known or from ``pair``."""

    link: int
    at: str
    pair: tuple[str, str] | None
    new: tuple[str, ...]
    """The link's points this locates."""


@dataclass(frozen=True, slots=True)
class Guide:
    """The line of ``slide`` that an unlocated point lies on, found as ``how`` says."""

    slide: Slide
    how: LineFrom


@dataclass(frozen=True, slots=True)
class CircleCut:
    """Point ``name`` cut from two arcs (link, centre point, radius), left/right of them."""

    name: str
    first: tuple[int, str, float]
    second: tuple[int, str, float]
    branch: object


@dataclass(frozen=True, slots=True)
class LineCut:
    """Point ``name`` cut from an arc and a guide line, forward/backward along it."""

    name: str
    circle: tuple[int, str, float]
    line: Guide
    branch: object


@dataclass(frozen=True, slots=True)
class LinesCut:
    """Point ``name`` where two guide lines cross."""

    name: str
    first: Guide
    second: Guide


@dataclass(frozen=True, slots=True)
class SlotTurned:
    """The guide link of ``slide`` turned about its point ``pivot`` until its slot passes
    the block; ``branch`` is a word or a near point."""

    slide: Slide
    pivot: str
    branch: object


class _Recorder(_Assembly):
    """The scalar assembly, noting each act as it takes it."""

    def __init__(self, mech: Mechanism):
        super().__init__(mech)
        self.acts: list = []
        self.structural = False

    def _turned(self, link, by, offset):
        self.acts.append(Turned(link, by, offset))

    def _rolled(self, s):
        self.acts.append(Rolled(s))

    def _rolled_on(self, s):
        self.acts.append(RolledOn(s))

    def _rolled_round(self, a):
        self.acts.append(RolledRound(a))

    def _placed(self, k, known):
        pair = None
        if k not in self.phi:
            a = known[0]
            b = next(b for b in known[1:] if math.hypot(*(self.loc[k, b] - self.loc[k, a])) > 0)
            pair = (a, b)
        self.acts.append(Placed(k, known[0], pair,
                                tuple(n for n in self.names[k] if n not in self.at)))

    def _slotted(self, s, q, branch):
        self.acts.append(SlotTurned(s, q, branch))

    def _guide(self, name: str, line) -> Guide:
        s = line[2]
        if s.guide_link in self.pose:
            return Guide(s, LineFrom.GUIDE if s.point == name else LineFrom.SHIFTED)
        return Guide(s, LineFrom.CARRIED)

    def _circle_circle(self, name, ci, cj):
        out = super()._circle_circle(name, ci, cj)
        self.acts.append(CircleCut(name, ci, cj, self.m.branches[name]))
        return out

    def _circle_line(self, name, circle, line):
        out = super()._circle_line(name, circle, line)
        self.acts.append(LineCut(name, circle, self._guide(name, line), self.m.branches[name]))
        return out

    def _line_line(self, name, first, second):
        out = super()._line_line(name, first, second)
        self.acts.append(LinesCut(name, self._guide(name, first), self._guide(name, second)))
        return out

    def _stuck(self):
        self.structural = True
        super()._stuck()


@dataclass(frozen=True)
class Placement:
    """The replayed start for N input angles.

    ``q`` is (N, 3 × moving links) in ``_System`` column order. ``refused`` marks the
    positions where a link clearly cannot reach (the scalar solver refuses them too);
    ``doubtful`` those to hand to the scalar solver: a reach within a few slacks of its
    verdict, a cut near tangency, a near point about equidistant from both solutions.
    """

    q: np.ndarray
    refused: np.ndarray
    doubtful: np.ndarray


@dataclass(frozen=True)
class AssemblyPlan:
    """The acts of the closed-form assembly of ``mechanism``, in order."""

    mechanism: Mechanism
    acts: tuple

    @cached_property
    def system(self) -> _System:
        """The loop equations the replay's start is laid out for (made once a plan)."""
        return _System(self.mechanism)

    def place(self, angles: np.ndarray) -> Placement:
        """Replay the acts with the input link at each of ``angles`` (rad)."""
        return _Replay(self.system, np.asarray(angles, dtype=float)).run(self.acts)


def record_plan(mech: Mechanism, angles) -> AssemblyPlan | None:
    """Record the assembly's acts at the stated input angle, or else at the first of
    ``angles`` where the mechanism assembles; None if it assembles at none.

    Raises
    ------
    InputError
        As the scalar solver does (a missing or invalid branch).
    """
    for angle in [mech.drive.angle, *np.asarray(angles, dtype=float).tolist()]:
        rec = _Recorder(mech.with_drive(replace(mech.drive, angle=float(angle))))
        try:
            rec.run()
        except AssemblyError:
            if rec.structural:
                return None
            continue
        return AssemblyPlan(mech, tuple(rec.acts))
    return None


# ----------------------------------------------------------------------------- the replay

class _Replay:
    """Arrays of the assembly's state over N angles: located points, angles, poses."""

    def __init__(self, system: _System, angles: np.ndarray):
        mech = self.m = system.m
        self.n = len(angles)
        self.system = system
        self.loc = system.loc
        self._turns: dict[int, tuple] = {}
        self.size = max(float(np.max(np.abs(v))) for v in self.loc.values())
        zero = np.zeros(self.n)
        self.at = {n: (np.full(self.n, x), np.full(self.n, y))
                   for n, (x, y) in mech.frame.points}
        self.phi = {1: zero, mech.drive.link: angles}
        self.pose = {1: (zero, zero, zero)}
        self.refused = np.zeros(self.n, dtype=bool)
        self.doubtful = np.zeros(self.n, dtype=bool)

    def run(self, acts) -> Placement:
        with np.errstate(all="ignore"):     # refused positions carry junk, never read
            for act in acts:
                getattr(self, "_" + type(act).__name__.lower())(act)
        system = self.system
        q = np.zeros((self.n, 3 * len(system.moving)))
        for k in system.moving:
            ox, oy, phi = self.pose[k]
            q[:, system.col[k]], q[:, system.col[k] + 1], q[:, system.col[k] + 2] = ox, oy, phi
        bad = ~np.isfinite(q).all(axis=1) & ~self.refused
        return Placement(q, self.refused, (self.doubtful | bad) & ~self.refused)

    # ----- helpers
    def _turn(self, phi, v):
        """``R(φ) v`` for a constant local vector ``v``, as (x, y) arrays (cos φ and sin φ
        taken once for each φ: a link turns each of its points with the same)."""
        seen = self._turns.get(id(phi))
        if seen is None or seen[0] is not phi:
            seen = self._turns[id(phi)] = (phi, np.cos(phi), np.sin(phi))
        _, c, s = seen
        return c * v[0] + (-s) * v[1], s * v[0] + c * v[1]

    def _doubt(self, where) -> None:
        """Hand ``where`` to the scalar solver (a position's first verdict stands)."""
        self.doubtful |= where & ~self.refused

    def _refuse(self, where) -> None:
        """Refuse ``where``: it clearly cannot assemble (unless already in doubt, when the
        replay's numbers past that act are not to be trusted to refuse it)."""
        self.refused |= where & ~self.doubtful

    def _pick(self, branch, first, second, words):
        """``first`` for ``words[0]``, ``second`` for ``words[1]``, or the nearer, by position."""
        if isinstance(branch, str):
            return first if branch == words[0] else second
        nx, ny = float(branch[0]), float(branch[1])
        a = np.hypot(first[0] - nx, first[1] - ny)
        b = np.hypot(second[0] - nx, second[1] - ny)
        self._doubt(np.abs(a - b) <= _TIE * (a + b))
        take = a > b
        return np.where(take, second[0], first[0]), np.where(take, second[1], first[1])

    def _line(self, g: Guide, name: str):
        """Base point and unit direction of a guide line, as (x, y) arrays each."""
        s = g.slide
        through, d = np.asarray(s.through, dtype=float), _unit(s.direction)
        if g.how is LineFrom.CARRIED:
            phi = self.phi[s.guide_link]
            px, py = self.at[s.point]
            sx, sy = self._turn(phi, self.loc[s.guide_link, name] - through)
            return (px + sx, py + sy), self._turn(phi, d)
        ox, oy, phi = self.pose[s.guide_link]
        tx, ty = self._turn(phi, through)
        base = (ox + tx, oy + ty)
        if g.how is LineFrom.SHIFTED:
            sx, sy = self._turn(self.phi[s.link],
                                self.loc[s.link, name] - self.loc[s.link, s.point])
            base = (base[0] + sx, base[1] + sy)
        return base, self._turn(phi, d)

    # ----- the acts
    def _turned(self, act: Turned) -> None:
        self.phi[act.link] = self.phi[act.by] + act.offset

    def _rolled(self, act: Rolled) -> None:
        s = act.slide
        ox, oy, phi = self.pose[s.guide_link]
        dx, dy = self._turn(phi, _unit(s.direction))
        tx, ty = self._turn(phi, np.asarray(s.through, dtype=float))
        px, py = self.at[s.point]
        along = dx * (px - ox - tx) + dy * (py - oy - ty)
        self.phi[s.link] = phi - along / (s.contact.roll_sign * s.contact.circle.radius)

    def _rolledround(self, act: RolledRound) -> None:
        a = act.arc
        (px, py), (cx, cy) = self.at[a.point], self.at[a.centre]
        phi = self.pose[a.guide_link][2]
        beta = np.remainder(np.arctan2(py - cy, px - cx) - phi + np.pi, 2 * np.pi) - np.pi
        self.phi[a.link] = phi + a.roll_gain * beta / a.contact.circle.radius

    def _rolledon(self, act: RolledOn) -> None:
        s = act.slide
        ox, oy, phi = self.pose[s.guide_link]
        along = -s.contact.roll_sign * s.contact.circle.radius * (self.phi[s.link] - phi)
        dx, dy = self._turn(phi, _unit(s.direction))
        tx, ty = self._turn(phi, np.asarray(s.through, dtype=float))
        self.at[s.point] = (ox + tx + along * dx, oy + ty + along * dy)

    def _placed(self, act: Placed) -> None:
        k = act.link
        if act.pair is None:
            phi = self.phi[k]
        else:
            a, b = act.pair
            (ax, ay), (bx, by) = self.at[a], self.at[b]
            dl = self.loc[k, b] - self.loc[k, a]
            phi = np.arctan2(by - ay, bx - ax) - math.atan2(dl[1], dl[0])
        px, py = self.at[act.at]
        rx, ry = self._turn(phi, self.loc[k, act.at])
        ox, oy = px - rx, py - ry
        self.pose[k], self.phi[k] = (ox, oy, phi), phi
        for n in act.new:
            rx, ry = self._turn(phi, self.loc[k, n])
            self.at[n] = (ox + rx, oy + ry)

    def _circlecut(self, act: CircleCut) -> None:
        (_, x, ri), (_, y, rj) = act.first, act.second
        (cx, cy), (ex, ey) = self.at[x], self.at[y]
        dx, dy = ex - cx, ey - cy
        d = np.sqrt(dx * dx + dy * dy)
        size = np.maximum(max(ri, rj), d)
        margin = np.maximum(d - (ri + rj), abs(ri - rj) - d)
        self._refuse(margin > _CLEAR * _SLACK * size)
        h2 = np.maximum(0.0, (ri + rj - d) * (ri + rj + d) * (d - ri + rj) * (d + ri - rj))
        ux, uy = dx / d, dy / d
        along = (d * d + ri * ri - rj * rj) / (2.0 * d)
        fx, fy = cx + along * ux, cy + along * uy
        h = np.sqrt(h2) / (2.0 * d)
        self._doubt((h < WELL * size) | (d <= WELL * size))
        self.at[act.name] = self._pick(act.branch, (fx - h * uy, fy + h * ux),
                                       (fx + h * uy, fy - h * ux), ("left", "right"))

    def _linecut(self, act: LineCut) -> None:
        _, x, r = act.circle
        (bx, by), (dx, dy) = self._line(act.line, act.name)
        cx, cy = self.at[x]
        t = (cx - bx) * dx + (cy - by) * dy
        fx, fy = bx + t * dx, by + t * dy
        off = np.hypot(cx - fx, cy - fy)
        size = np.maximum(r, off)
        self._refuse(off - r > _CLEAR * _SLACK * size)
        h = np.sqrt(np.maximum(0.0, (r - off) * (r + off)))
        self._doubt(h < WELL * size)
        self.at[act.name] = self._pick(act.branch, (fx + h * dx, fy + h * dy),
                                       (fx - h * dx, fy - h * dy), ("forward", "backward"))

    def _linescut(self, act: LinesCut) -> None:
        (gx, gy), (ax, ay) = self._line(act.first, act.name)
        (hx, hy), (bx, by) = self._line(act.second, act.name)
        det = bx * ay - by * ax
        self._refuse(np.abs(det) <= _SLACK / _CLEAR)
        self._doubt(np.abs(det) < WELL)
        t = (bx * (hy - gy) - by * (hx - gx)) / det
        self.at[act.name] = (gx + t * ax, gy + t * ay)

    def _slotturned(self, act: SlotTurned) -> None:
        s, g, q = act.slide, act.slide.guide_link, act.pivot
        d = _unit(s.direction)
        (px, py), (qx, qy) = self.at[s.point], self.at[q]
        wx, wy = px - qx, py - qy
        lever = np.asarray(s.through, dtype=float) - self.loc[g, q]
        c = float(d[0] * lever[1] - d[1] * lever[0])
        reach = np.hypot(wx, wy)
        if abs(c) <= _SLACK * self.size:     # the slot runs through the pivot
            self._refuse(reach <= SINGULAR_RCOND * self.size / _CLEAR)
        self._refuse((abs(c) - reach > _CLEAR * _SLACK * np.maximum(abs(c), reach))
                     | (reach == 0.0))
        ratio = np.clip(c / reach, -1.0, 1.0)
        self._doubt((reach <= WELL * self.size) | (np.sqrt(1.0 - ratio * ratio) < WELL))
        a = np.arcsin(ratio)
        beta = np.arctan2(wy, wx)
        ahead, behind = beta - a, beta - math.pi + a
        b = act.branch
        if isinstance(b, str):
            psi = ahead if b == "forward" else behind
        else:
            nx, ny = float(b[0]) - qx, float(b[1]) - qy
            fore = np.cos(ahead) * nx + np.sin(ahead) * ny
            back = np.cos(behind) * nx + np.sin(behind) * ny
            self._doubt(np.abs(fore - back) <= _TIE * np.hypot(nx, ny))
            psi = np.where(fore >= back, ahead, behind)
        self.phi[g] = psi - math.atan2(d[1], d[0])
