"""Locating the instant centres: the primaries by inspection, the rest by Kennedy through the
circle diagram.

The order is the lecture notes' (000-part1 §2.7–2.9):

1. *By inspection.* A pin is the centre of the links it joins; a block on a
   straight guide has its centre at infinity, perpendicular to the guide, and on a
   curved guide at the guide's centre of curvature; a wheel rolling without slip
   has its centre at the contact point. A pin in a straight or curved slot, or a
   direct contact, gives no centre but a locus: the common normal at the contact,
   on which the centre lies (rule 5). For a curved slot or two circles in contact
   the normal is the line through the two centres of curvature. Each kind of joint
   finds its own, as :data:`~.joint_rules.JOINT_RULES` names (:mod:`.inspection`).
2. *By Kennedy.* On the circle diagram a centre is a chord; it is found when two
   triangles with that chord as a side have their other sides known. Each triangle
   gives a line through two known centres, and the centre is where the lines meet.
   The scan restarts from the lowest pair after every find, so the order of
   discovery is the one a student following the circle diagram would take. When two
   triangles give the same line (a multiple joint), another triangle is taken.

Every centre is a recorded step (``I:13``) of the assembly's construction, so a
figure draws it, a scene slices back through it, and a centre at infinity is just
a point with w = 0.
"""

from __future__ import annotations

import math
from itertools import combinations

from .. import geometry as g
from .assembly_record import Assembly
from .centres import SAME, Centre, Centres, centre_ref, omega_ratio, pair_label
from ..errors import DegenerateInput, TarsimError
from .joint_rules import rules_of
from ..narration import Phrase, phrase
from ..record import Kind, Ref, Role

__all__ = ["locate_centres", "WELL_CROSSED"]

WELL_CROSSED = 0.1
"""Sine of the crossing angle (about 6°) below which another triangle pair is sought."""


def locate_centres(asm: Assembly) -> Centres:
    """Find all n(n − 1)/2 instant centres of ``asm`` as recorded construction steps.

    Raises
    ------
    TarsimError
        If the mechanism's mobility is not 1, or some centre cannot be reached by
        Kennedy's theorem (every line for it coincides).
    """
    dof = asm.mechanism.mobility()[0]
    if dof != 1:
        raise TarsimError(f"instant centres need a mechanism of one degree of freedom; this "
                          f"one has {dof} (Grübler)")
    return _Kennedy(asm).run()


class _Kennedy:
    def __init__(self, asm: Assembly):
        self.asm = asm
        self.c = asm
        self.m = asm.mechanism
        self.out = Centres(asm)
        self.size = asm.size

    # ----- 1. by inspection ------------------------------------------------------
    def inspect(self) -> None:
        """Mark every pin's centre, then each other joint's primary centre or common normal,
        as its kind finds it (:data:`~.joint_rules.JOINT_RULES`, :mod:`.inspection`)."""
        stand_ins = {(a.centre, *sorted((a.link, a.guide_link))): a for a in self.m.arcs
                     if rules_of(a).pin is not None}
        for name in self.m.point_names:
            for i, j in combinations(sorted(self.m.links_at(name)), 2):
                if (i, j) in self.out.found:
                    continue
                a = stand_ins.get((name, i, j))
                how, said = ("pin", phrase("centres.pin", point=name, i=i, j=j,
                                           centre=pair_label(i, j)))
                if a is not None:
                    how, said = rules_of(a).pin(a, name, i, j)
                self.record(Centre((i, j), centre_ref(i, j), how), "mark",
                            self.asm.points[name], said=said)
        joints = [(k, j) for js in (self.m.slides, self.m.arcs) for k, j in enumerate(js)
                  if rules_of(j).centre is not None]
        for k, j in sorted(joints, key=lambda kj: rules_of(kj[1]).inspected):
            if tuple(sorted((j.link, j.guide_link))) not in self.out.found:
                rules_of(j).centre(self, k, j)

    def record(self, centre: Centre, verb: str, *inputs: Ref, said: Phrase, **params) -> Centre:
        """Draw the step that locates ``centre`` (it carries the centre as what it is about)."""
        self.c.draw(centre.ref, verb, *inputs, label=centre.label, role=Role.RESULT,
                    kind=Kind.CENTRE, phrase=said, about=centre, **params)
        self.out.found[centre.pair] = centre
        return centre

    # ----- 2. by Kennedy ------------------------------------------------------------
    def run(self) -> Centres:
        self.inspect()
        links = self.out.links
        pairs = list(combinations(links, 2))
        order = 0
        while True:
            todo = [p for p in pairs if p not in self.out.found]
            if not todo:
                return self.out
            for pair in todo:
                choice = self.choose_lines(pair)
                if choice is not None:
                    order += 1
                    self.cut(pair, choice, order)
                    break
            else:
                placed = next((p for p in todo if self.place_by_velocities(p, order + 1)), None)
                if placed is not None:
                    order += 1
                    continue
                names = ", ".join(pair_label(*p) for p in todo)
                together = self.coincident(todo[0])
                why = (f": {together[0]} at this position, so the lines through them are not "
                       "fixed (is a link of next to no length beside the others?)"
                       if together else ": no two distinct lines are known for them (check "
                       "the mechanism's joints)")
                error = TarsimError(f"Kennedy's theorem cannot reach {names}{why}")
                if len(together) > 1:
                    error.detail = "; ".join(together)
                raise error

    def coincident(self, pair: tuple[int, int]) -> list[str]:
        """The triangles of ``pair`` whose two known centres coincide, each as "I12 and I23 of
        link 2 fall together"."""
        i, j = pair
        out = []
        for k in self.out.links:
            a, b = tuple(sorted((i, k))), tuple(sorted((j, k)))
            if k not in pair and a in self.out.found and b in self.out.found and self.same_point(
                    self.c.output(self.out.found[a].ref), self.c.output(self.out.found[b].ref)):
                out.append(f"{pair_label(*a)} and {pair_label(*b)} of link {k} fall together")
        return out

    def candidates(self, pair: tuple[int, int]) -> list[tuple[Ref, int | None]]:
        """Lines known to carry the centre: common normals, then one per usable triangle."""
        i, j = pair
        lines: list[tuple[Ref, int | None]] = [(r, None) for r in self.out.loci.get(pair, [])]
        for k in self.out.links:
            if k in pair:
                continue
            a, b = tuple(sorted((i, k))), tuple(sorted((j, k)))
            if a not in self.out.found or b not in self.out.found:
                continue
            pa, pb = self.c.output(self.out.found[a].ref), self.c.output(self.out.found[b].ref)
            if self.same_point(pa, pb):
                continue  # the triangle's two centres coincide: its line is not fixed
            ref = f"K:{i}{j}/{k}"
            if ref not in self.c:
                self.c.draw(ref, "line_through", self.out.found[a].ref, self.out.found[b].ref,
                            kind=Kind.KENNEDY_LINE,
                            phrase=phrase("centres.kennedy_line", triangle=_tri(i, j, k),
                                          centre=pair_label(i, j), a=pair_label(i, k),
                                          b=pair_label(j, k)))
            lines.append((ref, k))
        return lines

    def choose_lines(self, pair):
        """The first two lines that cross well, else the best-crossing distinct pair."""
        lines = self.candidates(pair)
        best = None
        for (r1, k1), (r2, k2) in combinations(lines, 2):
            l1, l2 = self.c.output(r1), self.c.output(r2)
            if self.same_line(l1, l2):
                continue
            sine = _crossing(l1, l2)
            if sine >= WELL_CROSSED:
                return (r1, k1), (r2, k2), sine
            if best is None or sine > best[2]:
                best = ((r1, k1), (r2, k2), sine)
        return best

    def cut(self, pair, choice, order: int) -> None:
        (r1, k1), (r2, k2), sine = choice
        self.record(Centre(pair, centre_ref(*pair), "kennedy", (r1, r2), (k1, k2), order, sine),
                    "intersect_lines", r1, r2,
                    said=phrase("centres.lines_meet", centre=pair_label(*pair)))

    # ----- 3. when every Kennedy line coincides ------------------------------------
    def place_by_velocities(self, pair: tuple[int, int], order: int) -> bool:
        """Place a centre on its one Kennedy line where the two links' velocities agree.

        At some positions every triangle gives the same line (the crank-shaper with
        its crank along the lever: all finite centres on one line). Kennedy then
        fixes only the line, and the notes' rule 2 finishes it: at a point X of the
        line lay off, square to it, the velocities links i and j would give X (their
        ω from the ratios of the known centres); each link's velocity profile runs
        from its ground centre through its tip (parallel to the line for a
        translating link); the profiles cross where the velocities are equal, and
        the foot of that crossing on the line is I_ij.
        """
        lines = self.candidates(pair)
        fields = [self.velocity_field(n) for n in pair]
        if not lines or None in fields:
            return False
        (wi, _), (wj, _) = fields
        if abs(wi - wj) <= 1e-12 * max(abs(wi), abs(wj)):
            return False
        ref_line, third = lines[0]
        start = self.finite_centre_on(self.c.output(ref_line))
        if start is None:
            return False
        i, j = pair
        tag = f"rule2:{i}{j}:{order}"
        name = pair_label(i, j)
        reach = 0.4 * self.size
        base = self.c.draw(f"{tag}:X", "lay_off", start, ref_line, length=reach,
                           phrase=phrase("centres.rule2_mark", centre=name,
                                         length=self.m.units.length_said(reach),
                                         start=self.c[start].label or start))
        square = self.c.draw(f"{tag}:normal", "perpendicular_through", base, ref_line)
        b = self.c.output(base).xy
        nx, ny = self.c.output(square).direction
        speeds = {}
        for n, (w, off) in zip(pair, fields):
            vx, vy = -w * b[1] + off[0], w * b[0] + off[1]    # ω J B + b
            speeds[n] = vx * nx + vy * ny
        scale = 0.3 * self.size / max(abs(v) for v in speeds.values())
        profiles = []
        for n in pair:
            tip = self.c.draw(f"{tag}:tip{n}", "lay_off", base, square, length=scale * speeds[n],
                              phrase=phrase("centres.rule2_tip", link=n))
            ground = self.out.centre(1, n).ref
            try:
                if self.c.output(ground).is_at_infinity:
                    profile = self.c.draw(f"{tag}:profile{n}", "parallel_through", tip, ref_line,
                                          phrase=phrase("centres.rule2_translating", link=n))
                else:
                    profile = self.c.draw(f"{tag}:profile{n}", "line_through", ground, tip,
                                          phrase=phrase("centres.rule2_profile",
                                                        centre=pair_label(1, n), link=n))
            except DegenerateInput:
                return False
            profiles.append(profile)
        try:
            meet = self.c.draw(f"{tag}:meet", "intersect_lines", *profiles,
                               phrase=phrase("centres.rule2_meet", i=i, j=j))
            if self.c.output(meet).is_at_infinity:
                return False
            self.record(Centre(pair, centre_ref(i, j), "velocities", (ref_line,), (third,), order,
                               0.0), "project_onto", meet, ref_line,
                        said=phrase("centres.rule2_centre", centre=name))
        except DegenerateInput:
            return False
        return True

    def finite_centre_on(self, line: g.Line) -> Ref | None:
        for c in self.out.found.values():
            p = self.c.output(c.ref)
            if not p.is_at_infinity and abs(line.signed_distance(p)) <= SAME * self.size:
                return c.ref
        return None

    def omega(self, n: int) -> float | None:
        """ω_n relative to the input's ω as ±1 (its sense kept, so that the velocities the
        construction lays off point the way the links move), through the known centres."""
        d = self.m.drive.link
        sense = -1.0 if self.m.drive.omega < 0 else 1.0
        if n == d:
            return sense
        if n == 1:
            return 0.0
        for k in (d, *self.out.links):
            if k == 1 or k == n:
                continue
            needed = [(1, k), (1, n), tuple(sorted((k, n)))]
            needed += [] if k == d else [tuple(sorted((d, k)))]
            if all(p in self.out.found for p in needed):
                try:
                    wk = sense if k == d else sense * omega_ratio(self.out, d, k)
                    return wk * omega_ratio(self.out, k, n)
                except DegenerateInput:
                    continue
        return None

    def velocity_field(self, n: int):
        """``(ω_n, b_n)`` with v_n(P) = ω_n J P + b_n, or None if the centres cannot tell."""
        if n == 1:
            return 0.0, (0.0, 0.0)
        if (1, n) not in self.out.found:
            return None
        ground = self.out.point(1, n)
        if not ground.is_at_infinity:
            w = self.omega(n)
            if w is None:
                return None
            cx, cy = ground.xy
            return w, (w * cy, -w * cx)          # −ω J c
        for k in self.out.links:               # a translating link: borrow a point's velocity
            pair = tuple(sorted((k, n)))
            if k in (1, n) or pair not in self.out.found or (1, k) not in self.out.found:
                continue
            pk, x = self.out.point(1, k), self.out.point(*pair)
            wk = self.omega(k)
            if pk.is_at_infinity or x.is_at_infinity or wk is None:
                continue
            (ax, ay), (bx, by) = pk.xy, x.xy
            return 0.0, (-wk * (by - ay), wk * (bx - ax))
        return None

    # ----- tests of sameness ----------------------------------------------------------
    def same_point(self, p: g.Point, q: g.Point) -> bool:
        if p.is_at_infinity or q.is_at_infinity:
            if not (p.is_at_infinity and q.is_at_infinity):
                return False
            (a, b), (c, d) = p.direction, q.direction
            return abs(a * d - b * c) <= SAME
        return math.dist(p.xy, q.xy) <= SAME * self.size

    def same_line(self, l1: g.Line, l2: g.Line) -> bool:
        if l1.is_at_infinity or l2.is_at_infinity:
            return l1.is_at_infinity and l2.is_at_infinity
        if _crossing(l1, l2) > SAME:
            return False
        x, y = l1.anchor()
        return abs(l2.signed_distance(g.Point(x, y))) <= SAME * max(self.size, math.hypot(x, y))


def _crossing(l1: g.Line, l2: g.Line) -> float:
    """Sine of the angle between two lines (1 if either is the line at infinity)."""
    if l1.is_at_infinity or l2.is_at_infinity:
        return 1.0
    return abs(l1.a * l2.b - l1.b * l2.a)


def _tri(i: int, j: int, k: int) -> str:
    return "Δ" + "".join(str(n) for n in (i, k, j))
