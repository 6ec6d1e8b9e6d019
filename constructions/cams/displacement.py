"""The follower's displacement diagram, drawn by construction as the textbooks draw it.

Cam angle runs across (``per_rad`` drawing metres a radian), lift up (true size). Each
segment of motion is divided into equal parts by ordinates, and its curve is found where
they meet the construction of its law:

- **simple harmonic**: a semicircle on the lift at the segment's start, divided into as
  many equal arcs; each division projected across to its ordinate;
- **parabolic** (uniform acceleration and retardation): the half lift on the start ordinate
  divided in the ratio 1 : 3 : 5 … (by parallels from a line marked 1, 4, 9 …), projected
  across; the second half the same from the top, on the end ordinate. Split unequally, the
  accelerating part's share of the lift (its share of the angle) is so divided over its
  divisions, and the retarding part's over the rest;
- **cycloidal**: a circle of radius h/2π about the start, divided into as many equal arcs;
  each division projected onto the start ordinate, and from there a parallel to the
  segment's diagonal run to its ordinate;
- **uniform velocity**: the diagonal itself; **modified uniform velocity**: a parabola at
  each end by the divided ordinate, over the blended divisions, and the straight run
  between their ends; a **dwell**: a level line.

Every act is a recorded step; the points are read back as (cam angle, lift) and checked
against the closed-form law (:mod:`..reference.cam_laws`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .. import geometry as g
from ..errors import InputError
from ..narration import Word, counted, drawn_angle, drawn_length, phrase
from ..record import Construction, Kind, Panel, Ref

__all__ = ["Segment", "Displacement", "draw_displacement"]


@dataclass(frozen=True)
class Segment:
    """A segment of follower motion: ``kind`` "rise", "dwell" or "return" through the cam
    angle ``angle`` (rad), lifting ``lift`` (m) by ``law``, drawn in ``divisions`` parts."""

    kind: str
    angle: float
    lift: float = 0.0
    law: str = ""
    divisions: int = 6
    blend: float = 0.25
    """A modified uniform velocity's blended fraction at each end."""
    split: float = 0.5
    """The fraction of a parabolic segment that accelerates, the rest retarding."""
    time: float | None = None
    """The time (s) the file gave the segment by, its angle found at the cam's speed."""


@dataclass
class Displacement:
    """The drawn diagram: its record and, segment by segment, the curve's points in order
    as (cam angle from the segment's start in rad, step)."""

    construction: Construction
    per_rad: float
    curves: list[list[tuple[float, Ref]]] = field(default_factory=list)
    starts: list[float] = field(default_factory=list)
    """Each segment's start, as a cam angle (rad)."""
    strokes: list[tuple[Ref, Ref]] = field(default_factory=list)
    """The working lines a draftsman inks, each from one drawn point to another: the
    projections across, the divided line and its parallels, the runs along the diagonal."""
    arcs: list[tuple[Ref, Ref, float]] = field(default_factory=list)
    """The arcs inked, each as (centre, first point, sweep in rad): the semicircles, the
    cycloid's circles."""

    def point(self, ref: Ref) -> tuple[float, float]:
        """A drawn point as (cam angle, lift): rad and m."""
        x, y = self.construction.output(ref).xy
        return x / self.per_rad, y


def draw_displacement(segments: list[Segment], per_rad: float) -> Displacement:
    """Draw the displacement diagram of ``segments`` in turn, from lift 0.

    Raises
    ------
    InputError
        For a law the diagram cannot draw, or an odd division of a parabolic segment.
    """
    c = Construction()
    out = Displacement(c, per_rad)
    c.give("base", g.Line(0.0, 1.0, 0.0), label="", kind=Kind.GUIDE, panel=Panel.SPACE,
           phrase=phrase("cam.axes"))
    theta, lift = 0.0, 0.0
    for k, s in enumerate(segments, start=1):
        out.starts.append(theta)
        drafting = _Segment(c, k, s, theta * per_rad, lift, per_rad, out)
        out.curves.append(drafting.draw())
        theta += s.angle
        lift += s.lift if s.kind == "rise" else -s.lift if s.kind == "return" else 0.0
    return out


class _Segment:
    def __init__(self, c: Construction, k: int, s: Segment, x0: float, y0: float,
                 per_rad: float, out: Displacement):
        self.c, self.k, self.s, self.x0, self.y0, self.out = c, k, s, x0, y0, out
        self.width = s.angle * per_rad
        self.h = s.lift if s.kind == "rise" else -s.lift if s.kind == "return" else 0.0

    def act(self, ref: str, verb: str, *inputs: Ref, said=None, label: str = "",
            kind: Kind | None = None, **params) -> Ref:
        ref = f"s{self.k}:{ref}"
        self.c.draw(ref, verb, *inputs, label=label, phrase=said, kind=kind, **params)
        return ref

    def give(self, ref: str, obj, said=None, label: str = "", kind: Kind | None = None) -> Ref:
        ref = f"s{self.k}:{ref}"
        self.c.give(ref, obj, label=label, phrase=said, kind=kind)
        return ref

    def ordinates(self) -> list[Ref]:
        """The segment's start and its equal divisions: an ordinate at each."""
        n = self.s.divisions
        start = self.give("x0", g.Point(self.x0, 0.0), said=phrase(
            "cam.ordinates", k=self.k, kind=Word(self.s.kind), n=counted(n),
            angle=drawn_angle(self.s.angle)))
        out = []
        for i in range(n + 1):
            foot = self.act(f"foot{i}", "lay_off", start, "base", length=i * self.width / n)
            out.append(self.act(f"ord{i}", "perpendicular_through", foot, "base",
                                kind=Kind.LINE))
        return out

    def draw(self) -> list[tuple[float, Ref]]:
        s = self.s
        if s.kind == "dwell" or self.h == 0.0:
            return self.dwell()
        law = {"simple harmonic": self.harmonic, "parabolic": self.parabolic,
               "cycloidal": self.cycloidal, "uniform velocity": self.uniform,
               "modified uniform velocity": self.modified}.get(s.law)
        if law is None:
            raise InputError(f"segment {self.k}: the displacement diagram draws simple "
                             "harmonic, parabolic, cycloidal and (modified) uniform velocity "
                             f"motion, not '{s.law}'")
        return law(self.ordinates())

    def angles(self) -> list[float]:
        n = self.s.divisions
        return [i * self.s.angle / n for i in range(n + 1)]

    def level(self, ref: Ref, ordinate: Ref, i: int) -> Ref:
        """Project the point ``ref`` across to ``ordinate``: the curve's point ``i``."""
        across = self.act(f"across{i}", "parallel_through", ref, "base", kind=Kind.LINE)
        point = self.act(f"pt{i}", "intersect_lines", across, ordinate, label=str(i))
        self.out.strokes.append((ref, point))
        return point

    def dwell(self) -> list[tuple[float, Ref]]:
        a = self.give("a", g.Point(self.x0, self.y0), said=phrase(
            "cam.dwell", k=self.k, angle=drawn_angle(self.s.angle)))
        b = self.give("b", g.Point(self.x0 + self.width, self.y0))
        self.act("line", "line_through", a, b)
        return [(0.0, a), (self.s.angle, b)]

    def uniform(self, ordinates: list[Ref]) -> list[tuple[float, Ref]]:
        a = self.give("a", g.Point(self.x0, self.y0))
        b = self.give("b", g.Point(self.x0 + self.width, self.y0 + self.h))
        line = self.act("diagonal", "line_through", a, b, said=phrase("cam.uniform", k=self.k))
        self.out.strokes.append((a, b))
        return [(t, self.act(f"pt{i}", "intersect_lines", line, o, label=str(i)))
                for i, (t, o) in enumerate(zip(self.angles(), ordinates))]

    def harmonic(self, ordinates: list[Ref]) -> list[tuple[float, Ref]]:
        n = self.s.divisions
        centre = self.give("C", g.Point(self.x0, self.y0 + self.h / 2))
        # The semicircle on the lift, bulging back from the start: from the low end for a
        # rise, from the top for a return, in n equal arcs.
        first = self.give("S0", g.Point(self.x0, self.y0), said=phrase(
            "cam.harmonic", k=self.k, n=counted(n), lift=drawn_length(abs(self.h))))
        turn = -math.pi / n if self.h > 0 else math.pi / n
        self.act("semicircle", "circle_through", centre, first, kind=Kind.ARC)
        self.out.arcs.append((centre, first, n * turn))
        out = []
        for i, (t, o) in enumerate(zip(self.angles(), ordinates)):
            s = self.act(f"S{i}", "rotate_about", first, centre, angle=i * turn) if i else first
            out.append((t, self.level(s, o, i)))
        return out

    def parabola(self, part: int, x: float, y: float, sign: float, rise: float, m: int
                 ) -> tuple[Ref, list[Ref]]:
        """A parabola's heights on the ordinate at (x, y), its vertex there: ``rise`` divided
        in the ratio 1 : 3 : 5 … by parallels from a line marked at 1, 4, 9 … equal steps
        (``m`` of them), up (``sign`` +1) or down. The marked line leans into the segment,
        clear of its neighbours' constructions. Returns the foot and the m divisions."""
        words = dict(k=self.k, half=Word("first" if part == 0 else "second"), m=counted(m),
                     where=Word("start" if part == 0 else "end"),
                     way=Word("up from the foot" if sign > 0 else "down from the top"))
        if self.s.law == "modified uniform velocity":
            said = phrase("cam.blend", rise=drawn_length(abs(rise)), **words)
        elif self.s.split != 0.5:
            said = phrase("cam.parabolic_part", rise=drawn_length(abs(rise)), **words)
        else:
            said = phrase("cam.parabolic", **words)
        foot = self.give(f"h{part}:O", g.Point(x, y), said=said)
        top = self.give(f"h{part}:M", g.Point(x, y + sign * rise))
        ordinate = self.act(f"h{part}:ord", "line_through", foot, top)
        step = abs(rise) / (m * m)
        inward = 1.0 if part == 0 else -1.0
        ray_to = self.give(f"h{part}:R", g.Point(x + inward * abs(rise), y + sign * 0.5 * rise))
        ray = self.act(f"h{part}:ray", "line_through", foot, ray_to, kind=Kind.LINE)
        marks = [self.act(f"h{part}:m{j}", "lay_off", foot, ray, length=j * j * step)
                 for j in range(1, m + 1)]
        closing = self.act(f"h{part}:close", "line_through", marks[-1], top, kind=Kind.LINE)
        self.out.strokes += [(foot, marks[-1]), (marks[-1], top)]
        heights = []
        for j in range(1, m):
            par = self.act(f"h{part}:par{j}", "parallel_through", marks[j - 1], closing,
                           kind=Kind.LINE)
            heights.append(self.act(f"h{part}:d{j}", "intersect_lines", par, ordinate))
            self.out.strokes.append((marks[j - 1], heights[-1]))
        return foot, heights + [top]

    def ends(self, ordinates: list[Ref], rise: float, m: int,
             last: tuple[float, int] | None = None) -> list[tuple[float, Ref]]:
        """Parabolas of ``rise`` over the first ``m`` divisions and of ``last`` (its rise and
        divisions, the first's unless given) over the last, each projected across to its
        ordinates; between them, the straight run joining their ends."""
        n, angles = self.s.divisions, self.angles()
        rise2, m2 = last or (rise, m)
        out: list[tuple[float, Ref]] = []
        foot, heights = self.parabola(0, self.x0, self.y0, 1.0 if self.h > 0 else -1.0,
                                      rise, m)
        out.append((angles[0], foot))
        for j, hgt in enumerate(heights, start=1):
            out.append((angles[j], self.level(hgt, ordinates[j], j)))
        foot2, heights2 = self.parabola(1, self.x0 + self.width, self.y0 + self.h,
                                        -1.0 if self.h > 0 else 1.0, rise2, m2)
        if n == m + m2:
            heights2 = heights2[:-1]                     # the parts meet at an ordinate
        tail = [(angles[n - j], self.level(hgt, ordinates[n - j], n - j))
                for j, hgt in reversed(list(enumerate(heights2, start=1)))]
        if n > m + m2:
            run = self.act("run", "line_through", out[-1][1], tail[0][1], kind=Kind.LINE,
                           said=phrase("cam.modified", k=self.k))
            self.out.strokes.append((out[-1][1], tail[0][1]))
            for i in range(m + 1, n - m2):
                out.append((angles[i], self.act(f"pt{i}", "intersect_lines", run,
                                                ordinates[i], label=str(i))))
        return out + tail + [(angles[n], foot2)]

    def parabolic(self, ordinates: list[Ref]) -> list[tuple[float, Ref]]:
        n, k = self.s.divisions, self.s.split
        if k == 0.5 and n % 2:
            raise InputError(f"segment {self.k}: a parabolic segment is divided into an even "
                             f"number of parts (the two halves alike), not {n}")
        m = round(k * n)
        if not (1 <= m < n and abs(m - k * n) < 1e-9):
            raise InputError(f"segment {self.k}: its acceleration ({k:g} of the segment) must "
                             f"end on one of its {n} divisions")
        # The velocity is greatest where the parts meet, 2h/β, so each part's share of the
        # lift is its share of the angle.
        return self.ends(ordinates, abs(self.h) * k, m, (abs(self.h) * (1 - k), n - m))

    def modified(self, ordinates: list[Ref]) -> list[tuple[float, Ref]]:
        n, b = self.s.divisions, self.s.blend
        m = round(b * n)
        if not (m >= 1 and abs(m - b * n) < 1e-9 and 2 * m <= n):
            raise InputError(f"segment {self.k}: the blend ({b:g} of the segment at each end) "
                             f"must cover a whole number of its {n} divisions")
        speed = abs(self.h) / (1 - b)                   # lift per unit of the segment's angle
        return self.ends(ordinates, speed * b / 2, m)

    def cycloidal(self, ordinates: list[Ref]) -> list[tuple[float, Ref]]:
        n = self.s.divisions
        radius = abs(self.h) / (2 * math.pi)
        start = self.give("A", g.Point(self.x0, self.y0), said=phrase(
            "cam.cycloidal", k=self.k, n=counted(n), radius=drawn_length(radius)))
        end = self.give("B", g.Point(self.x0 + self.width, self.y0 + self.h))
        diagonal = self.act("diagonal", "line_through", start, end, kind=Kind.LINE)
        up = self.act("ordinate", "perpendicular_through", start, "base", kind=Kind.LINE)
        east = self.give("E", g.Point(self.x0 + radius, self.y0))
        self.act("circle", "circle_through", start, east, kind=Kind.ARC)
        self.out.arcs.append((start, east, 2 * math.pi))
        self.out.strokes.append((start, end))
        sign = -1.0 if self.h > 0 else 1.0
        out = []
        for i, (t, o) in enumerate(zip(self.angles(), ordinates)):
            p = self.act(f"Q{i}", "rotate_about", east, start, angle=sign * 2 * math.pi * i / n)
            on = self.act(f"q{i}", "intersect_lines",
                          self.act(f"qa{i}", "parallel_through", p, "base", kind=Kind.LINE), up)
            run = self.act(f"run{i}", "parallel_through", on, diagonal, kind=Kind.LINE)
            point = self.act(f"pt{i}", "intersect_lines", run, o, label=str(i))
            self.out.strokes += [(p, on), (on, point)]
            out.append((t, point))
        return out

