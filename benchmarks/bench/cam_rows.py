"""Cams: the construction against the closed forms, and the extremes a cam can reach.

For every bundled cam (``tarsim list``) and for two families pushed to their limits:

- **displacement**: each point the displacement diagram's construction draws against the
  law's closed form (``constructions/reference/cam_laws.py``), over the lift; tolerance the
  construction's own rounding bound (``constructions/cams/rounding.py``) times AGREE;
- **velocity and acceleration**: the law's greatest y′ω and y″ω², found between samples
  (``exercises/cams/cam_solution.py``'s peaks), against the textbook's peak formula;
  tolerance 32 eps (the chapter's own);
- **profile**: each station the layout by inversion draws against the closed-form pitch
  curve (``constructions/reference/cam_profile.py``), the station whose miss is the
  largest part of its tolerance (the survey's, rebuilt here from its public parts);
- **pressure angle near 90°**: a radial knife edge rising by uniform velocity, h over β,
  on a base circle shrunk to Rb → 0: its greatest pressure angle is atan(h/(β·Rb)) at the
  rise's start (at 50 digits of the file's float numbers). The error is taken over the
  complement 90° − φ, which is what shrinks; as φ is held as a float near π/2, its own
  rounding is u·φ, so the tolerance is 16 u·φ/(90° − φ);
- **radius of curvature near 0**: a flat face rising by simple harmonic motion, h over
  β = 90°, whose profile's radius ρ = Rb + y + y″ is least at the top, Rb + h − h·π²/(2β²)
  = Rb − h: on Rb = h + δ it is δ. Tolerance 16 u·(Rb + h + |y″|)/δ: the sum's roundings
  over what is left of it.
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath
from tarsim.constructions.cams.rounding import join_bound, lift_bounds
from tarsim.constructions.cams.rounding import rounding as act_rounding
from tarsim.constructions.cams.survey import AGREE
from tarsim.constructions.reference.cam_laws import motion
from tarsim.constructions.reference.cam_profile import station
from tarsim.exercises.cams.cam_file import parse_cam
from tarsim.exercises.cams.cam_solution import solve_cam
from tarsim.exercises.catalog import bundled, load

from .chapter_rows import EPS, ChapterStudy, Row
from .svgplot import Curve, write_plot
from .timing import median_time

__all__ = ["steep_cam", "flat_cam", "cam_study"]

PEAK = 32 * EPS
"""The peak formulas' tolerance (the chapter's ``_PEAK``)."""


def steep_cam(base_mm: float):
    """A radial knife edge: rise 40 mm by uniform velocity over 90°, dwell, return the same,
    dwell, on a base circle of ``base_mm``."""
    return parse_cam(f"""
name = "steep cam, Rb = {base_mm:g} mm"
[cam]
base_radius = {base_mm!r}
speed = 100
[follower]
kind = "knife-edge"
[[segment]]
kind = "rise"
angle = 90
lift = 40
law = "uniform velocity"
[[segment]]
kind = "dwell"
angle = 90
[[segment]]
kind = "return"
angle = 90
lift = 40
law = "uniform velocity"
[[segment]]
kind = "dwell"
angle = 90
""", exercise_id="steep-cam")


def flat_cam(delta_mm: float):
    """A translating flat face: rise 20 mm by simple harmonic motion over 90°, dwell, return
    the same, dwell, on a base circle of 20 + ``delta_mm``: its least ρ is ``delta_mm``."""
    return parse_cam(f"""
name = "flat face, Rb = 20 + {delta_mm:g} mm"
[cam]
base_radius = {20.0 + delta_mm!r}
speed = 100
[follower]
kind = "flat-faced"
[[segment]]
kind = "rise"
angle = 90
lift = 20
law = "simple harmonic"
[[segment]]
kind = "dwell"
angle = 90
[[segment]]
kind = "return"
angle = 90
lift = 20
law = "simple harmonic"
[[segment]]
kind = "dwell"
angle = 90
""", exercise_id="flat-cam")


def _displacement(sol) -> tuple[float, float]:
    """The drawn point furthest off its law, as a part of its tolerance: (error, tolerance),
    both over the greatest lift."""
    ex, d = sol.exercise, sol.diagram
    lift_top = max(s.lift for s in ex.segments) or 1.0
    worst, lift = (0.0, 1.0), 0.0
    for s, curve, start in zip(ex.segments, d.curves, d.starts):
        for _, ref in curve:
            theta, y = d.point(ref)
            want = lift if s.kind == "dwell" else lift + motion(
                s.law, s.lift, s.angle, theta - start, rise=s.kind == "rise",
                blend=s.blend, split=s.split).y - (s.lift if s.kind == "return" else 0.0)
            err, tol = abs(y - want), AGREE * sol.bounds[ref]
            if err / tol > worst[0] / worst[1]:
                worst = (err, tol)
        lift += s.lift if s.kind == "rise" else -s.lift if s.kind == "return" else 0.0
    return worst[0] / lift_top, worst[1] / lift_top


def _profile(sol) -> tuple[float, float]:
    """The layout's station furthest off the closed-form pitch curve, as a part of its
    tolerance (the survey's rule): (miss, tolerance), both over the cam's size."""
    ex, layout = sol.exercise, sol.profile.layout
    f, c = ex.follower, layout.construction
    reach = act_rounding(c)
    lifts = lift_bounds(sol.diagram, ex.segments)
    size = ex.base_radius + max((p.lift for p in layout.places), default=0.0) + f.radius
    worst = (0.0, 1.0)
    for p in layout.places:
        want = station(ex.segments, ex.base_radius, f, ex.sigma, p.theta)
        lift = lifts.get(p.source, 0.0) + join_bound(ex.segments, p.theta)
        tol = AGREE * (reach[p.trace].error + lift
                       + 16 * EPS / 2 * (size + math.hypot(*want.pitch)))
        miss = math.dist(c.output(p.trace).xy, want.pitch)
        if miss / tol > worst[0] / worst[1]:
            worst = (miss, tol)
    return worst[0] / size, worst[1] / size


def _solved(ex):
    sol = solve_cam(ex, allow_undercut=True)
    sol.profile.survey                                  # noqa: B018  (the work timed)
    return sol


def _construction_rows(label: str, ex, repeat: int) -> list[Row]:
    sol = _solved(ex)
    t = median_time(lambda: _solved(ex), repeat)
    err, tol = _displacement(sol)
    rows = [Row(label, "displacement, drawn points (/ lift)", 1.0, err, tol, t,
                f"{sum(len(c) for c in sol.diagram.curves)} points")]
    for p in sol.peaks:
        for what, formula, found in (("velocity", p.velocity, p.velocity_sampled),
                                     ("acceleration", p.acceleration, p.acceleration_sampled)):
            if math.isinf(formula):
                continue
            rows.append(Row(label, f"segment {p.index} peak {what} ({p.law})", 1.0,
                            abs(found - formula) / formula, PEAK, t, ""))
    err, tol = _profile(sol)
    rows.append(Row(label, "profile by inversion, stations (/ cam size)", 1.0, err, tol, t,
                    f"{len(sol.profile.layout.places)} stations"))
    return rows


def cam_study(out: Path, *, quick: bool = False) -> ChapterStudy:
    """Rows for each bundled cam, then the steep and the flat family, with a plot of the
    extremes' errors against their conditioning."""
    repeat = 1 if quick else 3
    rows: list[Row] = []
    names = sorted(bundled("cams"))
    for name in (names[:1] if quick else names):
        rows += _construction_rows(name, load(name), repeat)
    steep_pts, flat_pts = [], []
    for rb in ((4.0, 0.004) if quick else (40.0, 4.0, 0.4, 0.04, 0.004, 4e-4)):
        ex = steep_cam(rb)
        sol = _solved(ex)
        t = median_time(lambda ex=ex: _solved(ex), repeat)
        rise = ex.segments[0]
        with mpmath.workdps(50):
            exact = mpmath.atan(mpmath.mpf(rise.lift) / (mpmath.mpf(rise.angle)
                                                        * mpmath.mpf(ex.base_radius)))
            got = abs(sol.profile.survey.steepest.pressure_angle)
            err = float(abs(got - exact) / (mpmath.pi / 2 - exact))
        want = float(exact)
        rows.append(Row(f"knife edge, Rb = {rb:g} mm", f"greatest pressure angle "
                        f"{math.degrees(want):.6g}° (error / (90° − φ))", math.cos(want), err,
                        16 * EPS / 2 * want / (math.pi / 2 - want), t,
                        "φ is a float near π/2: its ulp is that much of 90° − φ"))
        steep_pts.append((math.cos(want), max(err, 1e-17)))
        rows += [Row(f"knife edge, Rb = {rb:g} mm", r.number, math.cos(want), r.error,
                     r.tolerance, r.time_us, r.note)
                 for r in _construction_rows("", ex, 1) if "profile" in r.number]
    for delta in ((1.0, 1e-4) if quick else (10.0, 1.0, 0.1, 0.01, 1e-3, 1e-4, 1e-5)):
        ex = flat_cam(delta)
        sol = _solved(ex)
        t = median_time(lambda ex=ex: _solved(ex), repeat)
        rb, h, beta = ex.base_radius, ex.segments[0].lift, ex.segments[0].angle
        with mpmath.workdps(50):
            exact = (mpmath.mpf(rb) + h - mpmath.mpf(h) * mpmath.pi ** 2
                     / (2 * mpmath.mpf(beta) ** 2))
            got = sol.profile.survey.sharpest.rho
            err = float(abs(got - exact) / exact)
        want = float(exact)
        scale = rb + h + 2 * h
        rows.append(Row(f"flat face, Rb = 20 + {delta:g} mm", f"least ρ = {want * 1e3:.4g} mm",
                        want / scale, err, 16 * EPS / 2 * scale / want, t, ""))
        flat_pts.append((want / scale, max(err, 1e-17)))
    path = write_plot(out / "cams-extremes.svg",
                      "Cams at their limits: the survey against the closed forms",
                      "conditioning: cos φ (pressure angle), ρ / (Rb + h + |y″|) (curvature)",
                      "relative error",
                      [Curve("pressure angle → 90° (error over 90° − φ)", tuple(steep_pts)),
                       Curve("least radius of curvature → 0 (error over ρ)", tuple(flat_pts)),
                       Curve("tolerance of ρ: 16u / conditioning",
                             tuple((c, 16 * EPS / 2 / c) for c, _ in flat_pts))],
                      note="A radial knife edge on a base circle shrinking to 0.4 µm; a flat "
                           "face whose least ρ shrinks to 10 nm.")
    out_of = [r for r in rows if not r.within]
    steep = [r for r in rows if r.number.startswith("greatest")]
    flat = [r for r in rows if r.number.startswith("least")]
    head = (f"{len(rows) - len(out_of)} of {len(rows)} rows within their tolerance; the "
            f"pressure angle's complement is read to {max(r.error for r in steep):.0e} down "
            f"to φ = {steep[-1].number.split()[3]}, and the least ρ to "
            f"{max(r.error for r in flat):.0e} of itself at conditioning "
            f"{min(r.conditioning for r in flat):.0e}")
    return ChapterStudy("Cams", "the laws' closed forms and the closed-form profile",
                        "conditioning", head, tuple(rows), path)
