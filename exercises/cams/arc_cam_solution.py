"""A cam of arcs solved: its dimensions and the follower's motion as the books ask them (at
the start of the lift, where the follower leaves the flank, at the apex, and at any asked
cam angle), each held to the outline itself (:mod:`tarsim.constructions.reference.cam_arcs`).

The reference reads the follower's place off the outline (a flat face at its support, a
roller where the axis meets the outline grown by its radius), knowing nothing of which part
it touches; the velocity and acceleration are that place's rates on the part it touches (on
the part's own side of a join), found exactly. They are held to the books' formulas to
10⁻⁹ of ωd and ω²d (both sides are exact but for rounding, some 10⁻¹³ of the place, grown
at most a thousandfold where a knife edge turns sharply onto a small nose), the flank's
radius to the bisection's, and the flank angle to where the outline's flank meets its
nose.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from tarsim.constructions.cams.arc_cam import arc_motion
from tarsim.constructions.narration import numeral, numerals, phrase, unit_words, words
from tarsim.constructions.reference.cam_arcs import (Flat, face_place, outline, place_rates,
                                                     roller_place)
from tarsim.graphics.cams.arc_cam_figure import draw_arc_cam
from tarsim.graphics.plot import PlotMark, Series, draw_line_plot
from ..checked import Checked
from ..solution_folder import ChapterFiles
from ..worked_document import Bullets, Section, title
from .arc_cam_file import ArcCamExercise

__all__ = ["ArcCamSolution", "solve_arc_cam"]

STEP = 1e-4
"""How near a part's end (rad of cam angle) an asked angle takes that part's side."""

AGREE = 1e-9
"""How far a formula may stand from the outline's rates, as a fraction of ωd (a velocity)
or ω²d (an acceleration)."""


@dataclass(frozen=True)
class Reading:
    """One asked motion: its name, what the books call it, the cam angle (rad from the start
    of the lift), which of lift (0), velocity (1) or acceleration (2), the part's formula
    used, and its value beside the outline's."""

    name: str
    what: str
    theta: float
    which: int
    part: str | None
    value: float
    reference: float
    scale: float

    @property
    def passed(self) -> bool:
        """The formula agrees with the outline to :data:`AGREE` of its scale."""
        return abs(self.value - self.reference) <= AGREE * self.scale


@dataclass(frozen=True)
class ArcCamSolution(ChapterFiles):
    """A solved cam of arcs (see the module's docstring)."""

    exercise: ArcCamExercise

    @cached_property
    def outline(self):
        """The cam's outline from the tangencies alone."""
        c = self.exercise.cam
        return outline(c.kind, c.base, c.nose, c.d, c.alpha)

    def place(self, theta: float) -> float:
        """The follower's lift read off the outline at cam angle ``theta``."""
        c = self.exercise.cam
        psi = c.alpha - theta
        if not c.flat:
            return roller_place(self.outline, psi, c.roller) - c.base - c.roller
        return face_place(self.outline, psi) - c.base

    def _rates(self, theta: float, side: int) -> tuple[float, float, float]:
        """The follower's lift and its first two derivatives per rad of cam angle, read
        exactly off the outline on the ``side`` (+1 after, −1 before, 0 at) of ``theta``."""
        c = self.exercise.cam
        t, t1, t2 = place_rates(self.outline, c.alpha - theta, c.roller, c.flat, side)
        return t - c.base - (0.0 if c.flat else c.roller), -t1, t2     # ψ = α − θ

    @cached_property
    def readings(self) -> list[Reading]:
        """The motions the books ask, then those at the asked angles."""
        ex, c = self.exercise, self.exercise.cam
        w = abs(ex.omega)
        phi, alpha = c.phi, c.alpha
        asks = [("a_lift_start", "the acceleration as the lift begins", 0.0, 2, "flank", 1),
                ("v_max", "the greatest velocity, where the follower leaves the flank", phi, 1,
                 "flank", -1),
                ("a_flank_end", "the acceleration where the follower leaves the flank", phi, 2,
                 "flank", -1),
                ("a_nose_start", "the acceleration as the follower comes onto the nose", phi,
                 2, "nose", 1),
                ("a_apex", "the acceleration at the apex of the nose", alpha, 2, "nose", 0)]
        if c.kind == "eccentric":              # all nose: its lowest place, its greatest
            asks = [("a_lift_start", "the acceleration at the lowest place", 0.0, 2, "nose", 0),
                    ("v_max", "the greatest velocity", _fastest(c), 1, "nose", 0),
                    ("a_apex", "the acceleration at the apex of the nose", alpha, 2, "nose", 0)]
        asks += self._greatest(w)
        for d in ex.at:
            t = math.radians(d)
            part = arc_motion(c, t, w)[3]
            u = 2 * alpha - t if t > alpha else t
            ends = (0.0, phi) if part == "flank" else (phi, alpha)
            side = 1 if u - 3 * STEP < ends[0] else -1 if u + 3 * STEP > ends[1] else 0
            if t > alpha and side:
                side = -side                       # the return runs the lift backwards
            if u > alpha - 3 * STEP and part == "nose":
                side = 0                           # the apex: the nose both sides
            for which, name in enumerate(("y", "v", "a")):
                asks.append((f"{name}_at_{d:g}", "", t, which, None, side))
        out = []
        for name, what, t, which, part, side in asks:
            value = arc_motion(c, t, w, part)[which]
            ref = self._rates(t, side)[which] * w ** which
            out.append(Reading(name, what, t, which, part, value, ref,
                               c.d * w ** which if which else c.d))
        return out

    def _greatest(self, w: float) -> list[tuple]:
        """The greatest acceleration on the flank (where it has one) and the greatest
        retardation on the nose, as the books ask them, each where the part's formula finds
        it and differenced on that part's side."""
        c = self.exercise.cam
        out = []
        parts = ([("a_flank_max", "the greatest acceleration on the flank", "flank", 0.0, c.phi,
                   1.0)] if c.phi > 0 else []) + [
            ("a_nose_max", "the greatest retardation on the nose", "nose", c.phi, c.alpha, -1.0)]
        for name, what, part, lo, hi, sign in parts:
            t = _golden(lambda t, p=part, s=sign: s * arc_motion(c, t, w, p)[2], lo, hi)
            side = 1 if t - 3 * STEP < lo else -1 if t + 3 * STEP > hi and part == "flank" else 0
            out.append((name, what, t, 2, part, side))
        return out

    @cached_property
    def dimensions(self) -> dict[str, tuple[float, float | None, str]]:
        """Each dimension (m or rad) beside the outline's own, and how the book finds it."""
        c = self.exercise.cam
        out = {"nose_distance": (c.d, None, "OQ = r₁ + h − r₂"),
               "lift": (c.lift, self.place(c.alpha), "the outline's apex"),
               "nose_radius": (c.nose, None, "as given, or d cos α = r₁ − r₂"),
               "angle_of_lift": (c.alpha, None, "as given, or from the faces or the flank")}
        flank = self.outline.parts[0]              # the rising flank
        if c.kind == "eccentric":
            return out
        if isinstance(flank, Flat):
            # The roller leaves the flank where its centre passes the flank's end grown out.
            meet = (flank.b[0] + c.roller * flank.normal[0],
                    flank.b[1] + c.roller * flank.normal[1])
            out["flank_angle"] = (c.phi, c.alpha - math.atan2(meet[1], meet[0]),
                                  "tan φ = d sin α/(r₁ + r)")
        else:
            out["flank_radius"] = (c.flank_radius, self.outline.flank_radius,
                                   "R from the triangle OPQ")
            if c.flat:
                out["flank_angle"] = (c.phi, c.alpha - flank.start,
                                      "sin φ = d sin α/(R − r₂)")
            else:
                # The roller leaves the flank where its centre passes the join grown out.
                reach = c.nose + c.roller
                meet = (c.d + reach * math.cos(flank.start), reach * math.sin(flank.start))
                out["flank_angle"] = (c.phi, c.alpha - math.atan2(meet[1], meet[0]),
                                      "φ = α − the angle of OJ, J the join grown by r")
        return out

    @cached_property
    def spring(self) -> tuple[float, float, float] | None:
        """Where the follower's retardation is greatest on the nose (rad), the spring force
        that holds it there, m × that retardation (N), and the same from the outline's
        differences; None where the file gives no mass."""
        ex, c = self.exercise, self.exercise.cam
        if not ex.mass:
            return None
        w = abs(ex.omega)
        theta = _golden(lambda t: -arc_motion(c, t, w, "nose")[2], c.phi, c.alpha)
        side = 1 if theta - 3 * STEP < c.phi else 0
        return (theta, -ex.mass * arc_motion(c, theta, w, "nose")[2],
                -ex.mass * self._rates(theta, side)[2] * w * w)

    @property
    def failures(self) -> list[str]:
        """What disagrees with the outline, by name."""
        spring = self.spring
        return (["spring_force"] if spring and abs(spring[1] - spring[2]) > AGREE * spring[1]
                else []) + [r.name for r in self.readings if not r.passed] + [
            name for name, (v, ref, _) in self.dimensions.items()
            if ref is not None and abs(v - ref) > 1e-9 * abs(v)]

    @property
    def checked(self) -> dict[str, Checked]:
        """results.json: the dimensions, then each motion (SI; angles in rad)."""
        out = {}
        for name, (v, ref, how) in self.dimensions.items():
            out[name] = Checked({"value": v}, None if ref is None else {"value": ref},
                                rel_error=None if ref is None else abs(v - ref) / abs(v),
                                tolerance=None if ref is None else 1e-9,
                                passed=None if ref is None else abs(v - ref) <= 1e-9 * abs(v),
                                method=how)
        if self.spring is not None:
            theta, force, ref = self.spring
            out["spring_force"] = Checked(
                {"value": force, "theta": theta}, {"value": ref},
                rel_error=abs(force - ref) / force, tolerance=AGREE,
                passed=abs(force - ref) <= AGREE * force,
                method="m × the greatest retardation on the nose; the place's exact rates")
        for r in self.readings:
            out[r.name] = Checked({"value": r.value, "theta": r.theta}, {"value": r.reference},
                                  rel_error=abs(r.value - r.reference) / r.scale,
                                  tolerance=AGREE, passed=r.passed,
                                  method="the book's formula; the outline's place's exact "
                                         "rates")
        return out

    # ----- words --------------------------------------------------------------------------
    def _length(self, v: float) -> str:
        ex = self.exercise
        return f"{numeral(v / ex.metre, '.4g')} {unit_words(ex.length_unit)}"

    def lines(self) -> list[str]:
        """What solve prints: the dimensions, then each motion, checked."""
        ex, c = self.exercise, self.exercise.cam
        ok = words("check ok" if not self.failures else "check FAILED")
        out = [words("the nose's centre {d} from the cam's, the lift {h}, the angle of lift "
                     "{alpha}°", d=self._length(c.d), h=self._length(c.lift),
                     alpha=numeral(math.degrees(c.alpha), ".4g"))]
        if c.kind == "eccentric":
            out = [words("the disc's centre {d} from the shaft, the disc's radius {r}: the lift "
                         "{h}", d=self._length(c.d), r=self._length(c.nose),
                         h=self._length(c.lift))]
        else:
            out.append(words(_LEAVES[c.kind == "tangent", _who(c)], r=self._length(c.nose),
                             R=self._length(c.flank_radius),
                             phi=numeral(math.degrees(c.phi), ".4g")))
        unit = ex.length_unit
        for r in self.readings:
            value = numeral(r.value / ex.metre if r.which < 2 else r.value, ".5g").replace(
                "-", "−")
            said = ("{unit}", "{unit}/s", "m/s²")[r.which].format(unit=unit)
            what = words(r.what) if r.what else words(
                "the motion at {theta}°", theta=numeral(math.degrees(r.theta), ".4g"))
            out.append(words("{what}: {name} = {value} {unit} at θ = {theta}°   {check}",
                             what=what, name=r.name, value=value, unit=said,
                             theta=numeral(math.degrees(r.theta), ".4g"),
                             check=words("check ok" if r.passed else "check FAILED")))
        if self.spring is not None:
            theta, force, _ = self.spring
            out.append(words("the spring must hold the follower ({m} kg) to the nose against "
                             "its greatest retardation, at θ = {theta}°: at least {force} N",
                             m=numeral(ex.mass, "g"), theta=numeral(math.degrees(theta), ".4g"),
                             force=numeral(force, ".5g")))
        out.append(words("the outline read at every asked angle: {ok}", ok=ok))
        return out

    def document(self):
        """steps.md: the cam's dimensions and the follower's motion, each line checked."""
        ex = self.exercise
        lines = self.lines()
        head = 1 if ex.cam.kind == "eccentric" else 2
        return [title(ex.name, ex.description),
                Section(phrase("heading.arc_cam"), (Bullets(tuple(lines[:head])),),
                        ("profile",)),
                Section(phrase("heading.arc_motion"), (Bullets(tuple(lines[head:])),),
                        ("displacement", "velocity", "acceleration"))]

    # ----- figures ------------------------------------------------------------------------
    @property
    def figures(self) -> dict[str, Any]:
        """The cam drawn to scale, then the follower's lift, velocity and acceleration over
        the lift and the return, the asked motions marked."""
        ex, c = self.exercise, self.exercise.cam
        w = abs(ex.omega)
        top = 2 * math.degrees(c.alpha)
        xs = [top * i / 720 for i in range(721)]
        values = [arc_motion(c, math.radians(x), w) for x in xs]
        scale = (1 / ex.metre, 1 / ex.metre, 1.0)
        labels = (f"y ({unit_words(ex.length_unit)})",
                  f"ẏ ({unit_words(ex.length_unit + '/s')})", f"ÿ ({unit_words('m/s²')})")
        step = 15 if top > 120 else 10
        ticks = [(float(d), numerals(f"{d}")) for d in range(0, int(top) + 1, step)]
        out = {"profile": draw_arc_cam(self.outline, c, words("{name}: the cam", name=ex.name),
                                       ex.length_unit, ex.metre)}
        for which, stem, heading in ((0, "displacement", "lift"), (1, "velocity", "velocity"),
                                     (2, "acceleration", "acceleration")):
            series = Series(words(heading), tuple((x, v[which] * scale[which])
                                                  for x, v in zip(xs, values)))
            seen = {(round(math.degrees(r.theta), 9), r.value) for r in self.readings
                    if r.which == which}
            marks = [PlotMark(x, v * scale[which], words("θ = {theta}°", theta=numeral(x, ".4g")))
                     for x, v in sorted(seen)]
            out[stem] = draw_line_plot(words("{name}: " + heading, name=ex.name),
                                       words("cam angle θ (°)"), labels[which], [series], marks,
                                       x_range=(0.0, top), x_ticks=ticks,
                                       mark_legend=words("the motions asked"))
        return out


_LEAVES = {
    (True, "roller"): "the nose's radius {r}; the roller leaves the flank {phi}° after the lift "
                      "begins",
    (True, "knife edge"): "the nose's radius {r}; the knife edge leaves the flank {phi}° after "
                          "the lift begins",
    (False, "face"): "the flank's radius {R}; the face leaves the flank {phi}° after the lift "
                     "begins",
    (False, "roller"): "the flank's radius {R}; the roller leaves the flank {phi}° after the "
                       "lift begins",
    (False, "knife edge"): "the flank's radius {R}; the knife edge leaves the flank {phi}° after "
                           "the lift begins"}
"""Where the follower leaves the flank, said of the follower the file gives (a tangent cam's
nose radius, or a circular-arc cam's flank radius, first)."""


def _who(cam) -> str:
    """The follower as the steps name it: a face, a roller or a knife edge (no roller)."""
    return "face" if cam.flat else "roller" if cam.roller else "knife edge"


def _fastest(cam) -> float:
    """Where the follower of an eccentric disc rises fastest (rad): its velocity rises once
    and falls once over the lift (a slider-crank's piston between its dead centres)."""
    return _golden(lambda t: arc_motion(cam, t, 1.0)[1], 0.0, cam.alpha)


def _golden(f, lo: float, hi: float) -> float:
    """Where ``f`` is greatest on [lo, hi]: the best of 400 equal samples, then
    golden-section search between its neighbours (so a greatest at an end, or a lesser
    hump elsewhere, is not mistaken for it)."""
    n = 400
    xs = [lo + (hi - lo) * i / n for i in range(n + 1)]
    best = max(range(n + 1), key=lambda i: f(xs[i]))
    top = _refine(f, xs[max(best - 1, 0)], xs[min(best + 1, n)])
    return top if f(top) >= f(xs[best]) else xs[best]


def _refine(f, lo: float, hi: float) -> float:
    """Golden-section search for the greatest of ``f`` on [lo, hi], where it rises at most
    once and falls at most once (an end, where it only falls or only rises)."""
    g, lo0, hi0 = (math.sqrt(5) - 1) / 2, lo, hi
    for _ in range(120):
        a, b = hi - g * (hi - lo), lo + g * (hi - lo)
        if f(a) < f(b):
            lo = a
        else:
            hi = b
    mid, span = 0.5 * (lo + hi), hi0 - lo0
    # An end, where the greatest is one, said as that end rather than a rounding off it.
    return lo0 if mid - lo0 < 1e-12 * span else hi0 if hi0 - mid < 1e-12 * span else mid


def solve_arc_cam(ex: ArcCamExercise) -> ArcCamSolution:
    """Solve the cam of arcs ``ex``."""
    return ArcCamSolution(ex)
