"""A cam exercise solved: the follower's displacement diagram by construction, its velocity
and acceleration against cam angle, each segment's peaks, and the cam's profile laid out by
inversion (:mod:`.cam_layout`), every number checked.

The constructed displacement points are checked against the closed-form laws, each to the
rounding its construction can carry (:func:`..constructions.cams.rounding.lift_bounds`);
each segment's peak velocity, acceleration and jerk by the textbook formulas (h/β, πh/2β,
…, times ω, ω² and ω³) against the law's own greatest value, found between samples
(:mod:`..constructions.cams.extremes`). The cam turns at constant speed here (α = 0), so
the chain rule's α terms vanish and jerk is y‴ω³.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from tarsim.constructions.cams.displacement import Displacement, draw_displacement
from tarsim.constructions.cams.extremes import EPS, greatest
from tarsim.constructions.cams.rounding import lift_bounds
from tarsim.constructions.cams.survey import AGREE
from tarsim.constructions.errors import IllConditioned
from tarsim.constructions.narration import Word, numeral, numerals, phrase, unit_words, words
from tarsim.constructions.reference.cam_laws import jerk_peak, motion, peaks, pieces
from tarsim.graphics.cams.displacement_figure import draw_displacement_figure
from tarsim.graphics.hiding import shown_answer
from tarsim.graphics.plot import PlotMark, Series, draw_line_plot
from ..checked import Checked
from ..solution_folder import ChapterFiles
from ..worked_document import Bullets, Paragraph, Section, said_steps, title
from .cam_file import CamExercise
from .cam_layout import CamProfile, refuse_undercut
from .cam_readings import CamReadings

__all__ = ["CamSolution", "solve_cam"]

_PEAK = 32 * EPS
"""How far (relative) a textbook peak may stand from its law's greatest value: a few
roundings of each side's handful of products and quotients of h, β and π, and of a sine."""


@dataclass(frozen=True)
class SegmentPeaks:
    """One segment's peaks: by the textbook formula, and by the law sampled (m/s, m/s²)."""

    index: int
    kind: str
    law: str
    velocity: float
    acceleration: float
    velocity_sampled: float
    acceleration_sampled: float
    jerk: float = math.inf
    jerk_sampled: float = 0.0

    @property
    def passed(self) -> bool:
        """The formulas agree with the law's greatest values, to rounding."""
        return all(math.isinf(f) or abs(f - got) <= _PEAK * f for f, got in (
            (self.velocity, self.velocity_sampled),
            (self.acceleration, self.acceleration_sampled), (self.jerk, self.jerk_sampled)))


@dataclass(frozen=True)
class CamSolution(ChapterFiles):
    """A solved cam (see :func:`solve_cam`)."""

    exercise: CamExercise
    diagram: Displacement

    @cached_property
    def profile(self) -> CamProfile:
        """The cam's profile laid out by inversion from the diagram."""
        return CamProfile(self.exercise, self.diagram)

    @cached_property
    def readings(self) -> CamReadings:
        """The motion at the asked cam angles, an arm's angular rates, a parabolic segment's
        acceleration and retardation."""
        return CamReadings(self.exercise)

    @cached_property
    def bounds(self) -> dict[str, float]:
        """How far rounding can move each constructed point off its law, in lift (m)."""
        return lift_bounds(self.diagram, self.exercise.segments)

    @cached_property
    def misses(self) -> list[tuple[int, int, float]]:
        """Constructed points off their law beyond their rounding: (segment, point, miss
        in m)."""
        out, lift = [], 0.0
        for k, (s, curve, start) in enumerate(zip(self.exercise.segments, self.diagram.curves,
                                                  self.diagram.starts), start=1):
            for i, (_, ref) in enumerate(curve):
                theta, y = self.diagram.point(ref)
                want = lift if s.kind == "dwell" else lift + _y(s, theta - start)
                if abs(y - want) > AGREE * self.bounds[ref]:
                    out.append((k, i, abs(y - want)))
            lift += _net(s)
        return out

    @cached_property
    def peaks(self) -> list[SegmentPeaks]:
        """Each moving segment's peak velocity, acceleration and jerk: by the textbook's
        formula, and the law's greatest found between samples, piece by piece."""
        w = abs(self.exercise.omega)
        out = []
        for k, s in enumerate(self.exercise.segments, start=1):
            if s.kind == "dwell":
                continue
            v, a = peaks(s.law, s.lift, s.angle, s.blend, s.split)
            top = [_law_peak(s, lambda m: abs(m.y1)), _law_peak(s, lambda m: abs(m.y2)),
                   _law_peak(s, lambda m: abs(m.y3))]
            out.append(SegmentPeaks(k, s.kind, s.law, v * w, a * w * w, top[0] * w,
                                    top[1] * w * w, jerk_peak(s.law, s.lift, s.angle) * w ** 3,
                                    top[2] * w ** 3))
        return out

    @property
    def passed(self) -> bool:
        """Every constructed point on its law and every peak formula its law's."""
        return (not self.misses and all(p.passed for p in self.peaks) and self.profile.passed
                and not self.readings.failures and not self.base_failed)

    @property
    def sized(self) -> bool:
        """The base circle was found, from a pressure angle or a flat face's curvature."""
        ex = self.exercise
        return ex.pressure_limit is not None or ex.curvature_limit is not None

    @property
    def found(self) -> float:
        """What the layout finds of the rule that sized the base circle: its greatest
        pressure angle (rad), or a flat face's profile's least radius (m)."""
        if self.exercise.pressure_limit is not None:
            return self.steepest
        return self.profile.survey.sharpest.rho

    @property
    def base_failed(self) -> bool:
        """A base circle found from a rule whose layout does not meet it."""
        return self.sized and not self.readings.base(self.found).passed

    @property
    def failures(self) -> list[str]:
        """What disagrees, by name."""
        return ([f"segment {k} point {i}" for k, i, _ in self.misses]
                + [f"segment {p.index} peaks" for p in self.peaks if not p.passed]
                + [f"profile station {i}" for i, _ in self.profile.survey.misses]
                + self.readings.failures + (["the base circle"] if self.base_failed else []))

    # ----- what it writes ---------------------------------------------------------------------
    def lines(self) -> list[str]:
        """What the command line prints, and steps.md lists, in the language spoken: each
        segment's peaks, checked."""
        ex = self.exercise
        unit = ex.length_unit
        size = 1.0 / ex.metre
        out = []
        for p in self.peaks:
            a = words("∞ (at its ends)") if math.isinf(p.acceleration) else \
                f"{numeral(p.acceleration * size)} {unit}/s²"
            if ex.jerk:
                a += ", j_max = " + (words("∞ (where ÿ jumps)") if math.isinf(p.jerk) else
                                     f"{numeral(p.jerk * size)} {unit}/s³")
            arm = ex.follower.arm if ex.follower.oscillating else 0.0
            swing = words(" (the arm: {w} rad/s, {a} rad/s²)", w=numeral(p.velocity / arm),
                          a="∞" if math.isinf(p.acceleration) else
                          numeral(p.acceleration / arm)) if arm else ""
            out.append(words("segment {k} ({kind}, {law}): v_max = {v} {unit}/s, a_max = "
                             "{a}{swing}   {check}", k=p.index, kind=Word(p.kind),
                             law=Word(p.law), v=numeral(p.velocity * size), unit=unit, a=a,
                             swing=swing,
                             check=words("check ok" if p.passed else "check FAILED")))
        worst = max((m for *_, m in self.misses), default=0.0)
        verdict = words("all on their laws") if not self.misses else f"OFF by {worst:.1e} m"
        out.append(words("displacement diagram: {n} points constructed, {verdict}",
                         n=numeral(sum(len(c) for c in self.diagram.curves), "d"),
                         verdict=verdict))
        base = [self.readings.base_line(self.found)] if self.sized else []
        return out + self.readings.lines() + base + self.profile.lines()

    @cached_property
    def curves(self) -> tuple[list[float], ...]:
        """The follower's lift, velocity, acceleration and jerk (SI) against cam angle
        (degrees), by the laws, each segment sampled at 361 points."""
        ex = self.exercise
        w = abs(ex.omega)            # θ is the angle the cam has turned, whichever its sense
        xs, ys, vs, accs, jerks = [], [], [], [], []
        lift, start = 0.0, 0.0
        for s in ex.segments:
            for i in range(0, 361):
                t = s.angle * i / 360
                m = motion(s.law, s.lift, s.angle, t, rise=s.kind == "rise", blend=s.blend,
                           split=s.split) \
                    if s.kind != "dwell" else None
                xs.append(math.degrees(start + t))
                base = lift - (s.lift if s.kind == "return" else 0.0)
                ys.append((base + m.y) if m else lift)
                vs.append(m.y1 * w if m else 0.0)
                accs.append(m.y2 * w * w if m else 0.0)
                jerks.append(m.y3 * w ** 3 if m else 0.0)
            lift += _net(s)
            start += s.angle
        return xs, ys, vs, accs, jerks

    @property
    def figures(self) -> dict[str, Any]:
        """The displacement, velocity, acceleration (and jerk) diagrams against cam angle,
        each segment's peaks marked; for a swinging arm, its angular velocity and
        acceleration. Then the profile and its table."""
        ex = self.exercise
        unit = ex.length_unit
        xs, ys, vs, accs, jerks = self.curves
        ticks = [(float(d), numerals(f"{d}")) for d in range(0, 361, 30)]
        name = ex.name
        arm = ex.follower.arm if ex.follower.oscillating else 0.0
        rpm = ex.speed_unit == "rpm"
        speed = words("the cam at {speed} {unit}, {sense}", speed=numerals(
            f"{abs(ex.omega) * 60 / (2 * math.pi):.4g}" if rpm else f"{abs(ex.omega):.4g}"),
            unit=unit_words("rpm" if rpm else "rad/s"),
            sense=Word("clockwise" if ex.omega < 0 else "counter-clockwise"))

        def plot(title, label, values, scale, notes=(), which=0):
            scaled = [v * scale for v in values]
            asked = self.readings.marks(which, scale) if which else []
            return draw_line_plot(words("{name}: " + title, name=name), words("cam angle θ (°)"),
                                  label, [Series(words(title), tuple(zip(xs, scaled)))],
                                  self._peak_marks(xs, scaled) + asked, x_range=(0.0, 360.0),
                                  x_ticks=ticks, notes=notes, subtitle=speed,
                                  mark_legend=words("each segment's peak"))
        jumps = self.jumps
        spikes = [words("ÿ jumps at θ = {angles}: the jerk is infinite there, which no curve "
                        "can draw", angles=words(", ").join(numerals(f"{j:.4g}°")
                                                            for j in jumps))] if jumps else []
        curve = [(math.radians(x), y) for x, y in zip(xs, ys)]
        motion_plots = ({"velocity": plot("the arm's angular velocity",
                                          f"ω ({unit_words('rad/s')})", vs, 1 / arm, which=1),
                         "acceleration": plot("the arm's angular acceleration",
                                              f"α ({unit_words('rad/s²')})", accs, 1 / arm,
                                              which=2)}
                        if arm else
                        {"velocity": plot("velocity", f"ẏ ({unit_words(unit + '/s')})", vs,
                                          1.0 / ex.metre, which=1),
                         "acceleration": plot("acceleration", f"ÿ ({unit_words('m/s²')})",
                                              accs, 1.0, which=2)})
        return {"displacement": draw_displacement_figure(
                    self.diagram, curve, words("{name}: displacement", name=name), unit,
                    ex.metre, arm=arm, asked=[(math.radians(d), r.law.y, words(
                        "θ = {theta}°", theta=numerals(f"{d:g}"))) for d, r in
                        self.readings.at])} | motion_plots | (
            {"jerk": plot("jerk", words("jerk ({unit})", unit=unit_words("m/s³")), jerks, 1.0,
                          spikes)} if ex.jerk else {}
        ) | self.profile.figures()

    def _peak_marks(self, xs: list[float], values: list[float]) -> list[PlotMark]:
        """Each moving segment's greatest value in size, marked where it falls."""
        marks, start = [], 0.0
        for s in self.exercise.segments:
            end = start + math.degrees(s.angle)
            if s.kind != "dwell":
                inside = [(abs(v), x, v) for x, v in zip(xs, values) if start <= x <= end]
                _, x, v = max(inside)
                marks.append(PlotMark(x, v, shown_answer(numerals(f"{v:.4g}".replace("-", "−")))))
            start = end
        return marks

    @property
    def jumps(self) -> list[float]:
        """Cam angles (degrees) where the follower's acceleration jumps: a join of segments
        whose y″ differ, the middle of a parabolic segment, the ends of a blend."""
        segs = self.exercise.segments

        def y2(s, u: float) -> float:
            if s.kind == "dwell":
                return 0.0
            return motion(s.law, s.lift, s.angle, u * s.angle, rise=s.kind == "rise",
                          blend=s.blend, split=s.split).y2
        big = max((abs(a) for a in self.curves[3]), default=0.0)
        out, start = [], 0.0
        for k, s in enumerate(segs):
            if abs(y2(s, 0.0) - y2(segs[k - 1], 1.0)) > 1e-9 * big:
                out.append(start)
            inner = {"parabolic": (s.split,),
                     "modified uniform velocity": (s.blend, 1 - s.blend)}.get(s.law, ())
            out += [start + f * s.angle for f in inner if s.kind != "dwell" and f < 1]
            start += s.angle
        return sorted({round(math.degrees(t), 9) for t in out})

    def document(self) -> list[Section]:
        """steps.md: the displacement diagram's construction, then each segment's peaks (the
        lines solve prints, with their checks), then the profile."""
        ex = self.exercise
        rpm = ex.speed_unit == "rpm"
        rate = abs(ex.omega) * 60 / (2 * math.pi) if rpm else abs(ex.omega)
        timed = [words("segment {k} is given by its time, {t} s: at {n} {unit} the cam turns "
                       "β = ωt = {angle}° in it", k=numerals(str(k)), t=numeral(s.time, "g"),
                       n=numeral(rate, ".6g"), unit=unit_words(ex.speed_unit),
                       angle=numeral(math.degrees(s.angle), ".6g"))
                 for k, s in enumerate(ex.segments, 1) if s.time]
        peaks = timed + self.lines()[:len(self.peaks) + 1] + self.readings.lines() + (
            [self.readings.base_line(self.found)] if self.sized else [])
        if self.jumps:
            peaks.append(phrase("md.jumps", jumps=", ".join(f"{numerals(f'{j:g}')}°"
                                                            for j in self.jumps)))
        return [title(ex.name, ex.description),
                Section(phrase("heading.displacement"),
                        (said_steps(self.diagram.construction),), ("displacement",)),
                Section(phrase("heading.peaks"),
                        (Paragraph(phrase("md.chain_rule")), Bullets(tuple(peaks))),
                        ("velocity", "acceleration")),
                self.profile.section()]

    @property
    def checked(self) -> dict[str, Checked]:
        """results.json's quantities: each segment's peaks in SI, beside the sampled law's
        (an infinite one, where ÿ jumps, is null), then the profile's readings."""
        def peak(value: float, sampled: float, law: str) -> Checked:
            return Checked({"value": None if math.isinf(value) else value},
                           {"value": sampled}, method=f"{law} formula")

        out = {f"v_max_{p.index}": peak(p.velocity, p.velocity_sampled, p.law)
               for p in self.peaks}
        out |= {f"a_max_{p.index}": peak(p.acceleration, p.acceleration_sampled, p.law)
                for p in self.peaks}
        if self.exercise.jerk:
            out |= {f"j_max_{p.index}": peak(p.jerk, p.jerk_sampled, p.law) for p in self.peaks}
        if self.sized:
            out["base_radius"] = self.readings.base(self.found)
        return out | self.readings.checked(self.peaks) | self.profile.checked()

    @property
    def steepest(self) -> float:
        """The greatest pressure angle the layout finds (rad, its size)."""
        return abs(self.profile.survey.steepest.pressure_angle)


def _y(s, theta: float) -> float:
    """A segment's lift from its start's height at ``theta`` into it."""
    m = motion(s.law, s.lift, s.angle, theta, rise=s.kind == "rise", blend=s.blend,
               split=s.split)
    return m.y - (s.lift if s.kind == "return" else 0.0)


def _law_peak(s, size) -> float:
    """The greatest ``size`` of a segment's law's motion over its pieces (each piece's own
    formula at its ends, where y″ jumps)."""
    cuts = pieces(s.law, s.blend, s.split)
    return max(greatest(lambda t, i=i: size(motion(s.law, s.lift, s.angle, t, blend=s.blend,
                                                   split=s.split,
                                                   piece=i)), a * s.angle, b * s.angle)
               for i, (a, b) in enumerate(zip(cuts, cuts[1:])))


def _net(s) -> float:
    return s.lift if s.kind == "rise" else -s.lift if s.kind == "return" else 0.0


def solve_cam(ex: CamExercise, *, allow_undercut: bool = False) -> CamSolution:
    """The displacement diagram of ``ex`` by construction, at a cam-angle scale that sets a
    turn six times the greatest lift across, and the profile laid out from it.

    Raises
    ------
    InputError
        If the follower undercuts the cam, unless ``allow_undercut``.
    """
    biggest = max((s.lift for s in ex.segments), default=0.0) or ex.base_radius
    solution = CamSolution(ex, draw_displacement(list(ex.segments),
                                                 6 * biggest / (2 * math.pi)))
    _refuse_lost_lifts(solution)
    if not allow_undercut:
        refuse_undercut(solution.profile)
    return solution


def _refuse_lost_lifts(solution: CamSolution) -> None:
    """Refuse a segment whose lift rounding could hide: its points' tolerance as large as
    the lift itself, so their check could not fail.

    Raises
    ------
    IllConditioned
        Naming the segment, its lift and the tolerance.
    """
    ex = solution.exercise
    for k, (s, curve) in enumerate(zip(ex.segments, solution.diagram.curves), start=1):
        if s.kind == "dwell" or not s.lift:
            continue
        tol = AGREE * max(solution.bounds[ref] for _, ref in curve)
        if tol >= s.lift:
            unit, metre = ex.length_unit, ex.metre
            raise IllConditioned(
                f"segment {k} ({s.kind} of {s.lift / metre:.3g} {unit} over "
                f"{math.degrees(s.angle):.4g}°) is too small beside the rest of the cam to draw: "
                f"rounding could move its points {tol / metre:.1e} {unit}; make it a dwell or "
                "give it more lift or angle", name=f"segment {k}", method="displacement diagram",
                conditioning=s.lift / tol, miss=tol / s.lift)
