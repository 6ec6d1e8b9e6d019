"""A cam's readings as the books ask them, beside each segment's peaks: the follower's motion
at a stated cam angle, a swinging arm's angular velocity and acceleration, and a parabolic
segment's acceleration and retardation apart.

Each is written to results.json in SI with its check: the motion at an angle by differences
of the lift (:mod:`tarsim.constructions.cams.readings`), the arm's rates as the roller
centre's peaks over the arm (the lift is the arc y = lψ, so ψ̇ = ẏ/l exactly), and the
parabolic parts' 2h/kβ²·ω² and 2h/(1 − k)β²·ω² against the law's y″ on each piece.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

from tarsim.constructions.cams.readings import AGREE, Reading, read_at
from tarsim.constructions.narration import numeral, numerals, words
from tarsim.constructions.reference.cam_laws import motion
from tarsim.graphics.plot import PlotMark
from ..checked import Checked
from .cam_file import CamExercise

__all__ = ["CamReadings", "BASE_AGREE"]

BASE_AGREE = 1e-9
"""How far (relative) the layout's greatest pressure angle may stand from the limit a base
circle was found for: both greatest values are found on a flat top, where golden-section
search's ~1e-8 in the cam angle costs ~1e-16, and the layout's products of radii round to
a few 1e-16; 1e-9 leaves a wide margin and still fails a base off by a part in a million."""


@dataclass(frozen=True)
class CamReadings:
    """The readings of ``exercise`` beyond its peaks (see the module's docstring)."""

    exercise: CamExercise

    @cached_property
    def at(self) -> list[tuple[float, Reading]]:
        """Each asked cam angle (degrees) and the follower's motion there."""
        return [(d, read_at(self.exercise.segments, math.radians(d))) for d in self.exercise.at]

    @property
    def failures(self) -> list[str]:
        """The readings whose differences disagree with their law, by name."""
        return [f"the motion at {d:g}°" for d, r in self.at if not r.passed]

    def _rates(self, r: Reading) -> tuple[float, float, float]:
        """The lift y (m), ẏ (m/s) and ÿ (m/s²) by the law; the cam at constant speed."""
        w = abs(self.exercise.omega)
        return r.law.y, r.law.y1 * w, r.law.y2 * w * w

    def checked(self, peaks) -> dict[str, Checked]:
        """results.json's rows: at each asked angle y, v and a (a swinging arm's ψ, ω and α,
        in rad), an arm's greatest ω and α on each moving segment, and a parabolic
        segment's acceleration and retardation."""
        ex, w = self.exercise, abs(self.exercise.omega)
        arm = ex.follower.arm if ex.follower.oscillating else 0.0
        out: dict[str, Checked] = {}
        for d, r in self.at:
            y, v, a = self._rates(r)
            by = (r.y1_diff * w, r.y2_diff * w * w)
            scale = 1 / arm if arm else 1.0
            names = ("psi", "omega", "alpha") if arm else ("y", "v", "a")
            at = {"theta": math.radians(d), "segment": r.segment}
            out[f"{names[0]}_at_{d:g}"] = Checked({"value": y * scale} | at, method="the law")
            for name, got, diff, peak in ((names[1], v, by[0], r.peak[0] * w),
                                          (names[2], a, by[1], r.peak[1] * w * w)):
                out[f"{name}_at_{d:g}"] = Checked(
                    {"value": got * scale} | at, {"value": diff * scale},
                    rel_error=abs(got - diff) / peak if peak else 0.0,
                    tolerance=AGREE, passed=abs(got - diff) <= AGREE * peak,
                    method="the law; differences of its lift")
        if arm:
            for p in peaks:
                out[f"omega_max_{p.index}"] = Checked(
                    {"value": p.velocity / arm}, {"value": p.velocity_sampled / arm},
                    method=f"{p.law} formula over the arm")
                out[f"alpha_max_{p.index}"] = Checked(
                    {"value": None if math.isinf(p.acceleration) else p.acceleration / arm},
                    {"value": p.acceleration_sampled / arm},
                    method=f"{p.law} formula over the arm")
        heights = [0.0]
        for s in ex.segments:
            heights.append(heights[-1] + (s.lift if s.kind == "rise" else
                                          -s.lift if s.kind == "return" else 0.0))
        top = max(heights)
        # The follower's whole lift (an arm's swing, in rad): what an eccentric disc's 2e is.
        out["lift"] = Checked({"value": top / arm if arm else top},
                              method="the greatest height the rises reach")
        for k, s in enumerate(ex.segments, start=1):
            out[f"time_{k}"] = Checked({"value": s.angle / w}, method="β/ω")
            if s.law != "parabolic" or s.kind == "dwell":
                continue
            parts = (2 * s.lift / (s.split * s.angle ** 2) * w * w,
                     2 * s.lift / ((1 - s.split) * s.angle ** 2) * w * w)
            for name, value, piece in (("acceleration", parts[0], 0),
                                       ("retardation", parts[1], 1)):
                law = abs(motion(s.law, s.lift, s.angle, 0.5 * s.angle, blend=s.blend,
                                 split=s.split, piece=piece).y2) * w * w
                out[f"{name}_{k}"] = Checked({"value": value}, {"value": law},
                                             method="2h/kβ²·ω², 2h/(1 − k)β²·ω²")
        return out

    def base(self, found: float) -> Checked:
        """The base circle found from the greatest pressure angle allowed (or a flat face's
        least radius of curvature), beside what the layout by inversion finds on the cam so
        made (``found``: its greatest pressure angle in rad, or its profile's least radius
        in m)."""
        ex = self.exercise
        if ex.pressure_limit is None:
            miss, scale = abs(found - ex.curvature_limit), ex.curvature_limit + ex.base_radius
            return Checked({"value": ex.base_radius, "rho_limit": ex.curvature_limit},
                           {"rho_min": found}, rel_error=miss / scale, tolerance=BASE_AGREE,
                           passed=miss <= BASE_AGREE * scale,
                           method="r_b = max(ρ − y − y″); the layout's least radius")
        miss = abs(found - ex.pressure_limit)
        return Checked({"value": ex.base_radius, "pressure_angle_limit": ex.pressure_limit},
                       {"pressure_angle_max": found}, rel_error=miss / ex.pressure_limit,
                       tolerance=BASE_AGREE, passed=miss <= BASE_AGREE * ex.pressure_limit,
                       method="s₀ = max(|y′ − σe|/tan φ_max − y), R_p = √(s₀² + e²); the "
                              "layout's greatest pressure angle")

    def base_line(self, found: float) -> str:
        """The base circle found, and what the layout finds on it."""
        ex = self.exercise
        ok = self.base(found).passed
        if ex.pressure_limit is None:
            return words("the least base circle for a least radius of curvature of {limit}: "
                         "{r} {unit} (the layout's least: {got})   {check}",
                         limit=f"{numeral(ex.curvature_limit / ex.metre, '.4g')} "
                               f"{ex.length_unit}",
                         r=numeral(ex.base_radius / ex.metre, ".4g"), unit=ex.length_unit,
                         got=f"{numeral(found / ex.metre, '.6g')} {ex.length_unit}",
                         check=words("check ok" if ok else "check FAILED"))
        steepest = found
        return words("the least base circle for a greatest pressure angle of {limit}°: {r} "
                     "{unit} (the layout's greatest: {got}°)   {check}",
                     limit=numeral(math.degrees(ex.pressure_limit), ".4g"),
                     r=numeral(ex.base_radius / ex.metre, ".4g"), unit=ex.length_unit,
                     got=numeral(math.degrees(steepest), ".4f"),
                     check=words("check ok" if ok else "check FAILED"))

    def lines(self) -> list[str]:
        """What solve prints of them: the motion at each asked angle, checked; a split
        parabolic segment's acceleration and retardation."""
        ex = self.exercise
        unit, size = ex.length_unit, 1 / ex.metre
        arm = ex.follower.arm if ex.follower.oscillating else 0.0
        out = []

        def signed(x: float) -> str:
            return numeral(x, ".4g").replace("-", "−")
        for d, r in self.at:
            y, v, a = self._rates(r)
            check = words("check ok" if r.passed else "check FAILED")
            if arm:
                out.append(words("at θ = {theta}° (segment {k}): ψ = {psi}°, ω = {w} rad/s, "
                                 "α = {a} rad/s²   {check}", theta=numerals(f"{d:g}"),
                                 k=numeral(r.segment, "d"),
                                 psi=signed(math.degrees(y / arm)),
                                 w=signed(v / arm), a=signed(a / arm),
                                 check=check))
            else:
                out.append(words("at θ = {theta}° (segment {k}): y = {y} {unit}, v = {v} "
                                 "{unit}/s, a = {a} m/s²   {check}", theta=numerals(f"{d:g}"),
                                 k=numeral(r.segment, "d"), y=signed(y * size),
                                 v=signed(v * size), a=signed(a),
                                 unit=unit, check=check))
        w = abs(ex.omega)
        for k, s in enumerate(ex.segments, start=1):
            if s.law == "parabolic" and s.kind != "dwell" and s.split != 0.5:
                out.append(words("segment {k}: uniform acceleration {a} m/s² over {first}°, "
                                 "retardation {r} m/s² over {rest}°", k=numeral(k, "d"),
                                 a=numeral(2 * s.lift / (s.split * s.angle ** 2) * w * w, ".4g"),
                                 r=numeral(2 * s.lift / ((1 - s.split) * s.angle ** 2) * w * w,
                                           ".4g"),
                                 first=numeral(math.degrees(s.split * s.angle), ".4g"),
                                 rest=numeral(math.degrees((1 - s.split) * s.angle), ".4g")))
        return out

    def marks(self, which: int, scale: float) -> list[PlotMark]:
        """The asked angles' readings on a plot: ``which`` 1 for velocity, 2 acceleration,
        each value times ``scale`` as the plot draws it."""
        out = []
        for d, r in self.at:
            value = self._rates(r)[which] * scale
            out.append(PlotMark(d, value, words("θ = {theta}°", theta=numerals(f"{d:g}"))))
        return out
