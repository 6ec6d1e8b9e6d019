"""The analytic solver's closed-form start: every point located dyad by dyad.

Each unlocated point is cut from two circles (a pin between two links, a pin in a curved
slot, two circles in contact), a circle and a guide line, or two guide lines; a slotted
link is turned about its one located point until its slot passes the block; a link with
two located points, or a known angle and one point, is posed whole. Blocks carry their
guide's angle across, and a rolling contact turns its wheel through the distance rolled:
which joints take which of these acts is their kind's entry in :mod:`.joint_equations`.
Each choice between two solutions honours ``Mechanism.branches`` (see :func:`.solver.solve`).

The hooks (``_turned``, ``_placed``, …) do nothing here; :mod:`.assembly_plan` overrides
them to record the acts in order and replay them over a whole turn.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import AssemblyError, InputError
from ..joints import Arc, Slide
from ..model import Mechanism
from .joint_equations import Act, acting
from .kinematics import SINGULAR_RCOND, _dead_point
from .planar import _S, _SLACK, _cross, _locals, _round_angle, _rot, _unit

__all__: list[str] = []


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
        self.acting = acting(mech)
        """The joints that take each closed-form act (a block, a rolling wheel), by act."""

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
        """Take every joint's closed-form acts (a block's angle, a wheel's roll), then pose
        every link fixed by what is known, until nothing changes."""
        acts = {Act.TURN_WITH_GUIDE: self._turn_with_guide, Act.ROLL_OUT: self._roll_out,
                Act.ROLL_ROUND: self._roll_round, Act.ROLL_BACK: self._roll_back}
        changed = True
        while changed:
            changed = False
            for act, joints in self.acting.items():
                for j in joints:
                    changed = acts[act](j) or changed
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

    # The closed-form acts of the joints (.joint_equations.Act): each True if it acted.
    def _turn_with_guide(self, s: Slide) -> bool:
        """A block's link takes its guide's angle, or its guide the block's."""
        off = math.atan2(s.direction[1], s.direction[0])
        if s.guide_link in self.phi and s.link not in self.phi:
            self.phi[s.link] = self.phi[s.guide_link] + off
            self._turned(s.link, s.guide_link, off)
            return True
        if s.link in self.phi and s.guide_link not in self.phi:
            self.phi[s.guide_link] = self.phi[s.link] - off
            self._turned(s.guide_link, s.link, -off)
            return True
        return False

    def _roll_out(self, s: Slide) -> bool:
        """The wheel's angle (the input) says how far its centre has rolled."""
        if not (s.link in self.phi and s.guide_link in self.pose and s.point not in self.at):
            return False
        origin, phi = self.pose[s.guide_link]
        along = -s.contact.roll_sign * s.contact.circle.radius * (self.phi[s.link] - phi)
        self.at[s.point] = origin + _rot(phi) @ (
            np.asarray(s.through, dtype=float) + along * _unit(s.direction))
        self._rolled_on(s)
        return True

    def _roll_round(self, a: Arc) -> bool:
        """The angle the centre has gone round says how far the wheel has turned."""
        if not (a.link not in self.phi and a.guide_link in self.pose and a.point in self.at
                and a.centre in self.at):
            return False
        e = self.at[a.point] - self.at[a.centre]
        phi = self.pose[a.guide_link][1]
        beta = _round_angle(math.atan2(e[1], e[0]) - phi)
        self.phi[a.link] = phi + a.roll_gain * beta / a.contact.circle.radius
        self._rolled_round(a)
        return True

    def _roll_back(self, s: Slide) -> bool:
        """How far the wheel's centre has rolled says the wheel's angle."""
        if not (s.link not in self.phi and s.guide_link in self.pose and s.point in self.at):
            return False
        origin, phi = self.pose[s.guide_link]
        d = _rot(phi) @ _unit(s.direction)
        along = float(d @ (self.at[s.point] - origin - _rot(phi) @ np.asarray(
            s.through, dtype=float)))
        self.phi[s.link] = phi - along / (s.contact.roll_sign * s.contact.circle.radius)
        self._rolled(s)
        return True

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
