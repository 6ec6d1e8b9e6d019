"""The cam's profile laid out by inversion, against closed forms and an independent solver.

- The exact case the issue names: a flat face on simple-harmonic rise and return over a
  turn (lift h, base r₀) wraps a circle of radius r₀ + h/2 centred h/2 off the shaft.
- The same eccentric cam solved as a linkage (tests/data/circular-cam.toml, a circle on a
  flat face, by the analytic linkage solver) moves the face as the cam law does.
- The pressure angle by the profile's normal against the textbook's tan φ = (y′ − σe)/(s₀ + y).
- The pitch curve's radius of curvature against the circle through three near points.
- Each roller circle laid out touches the closed-form profile and none cuts into it.
- An oscillating arm: its roller's centre an arm's length from the turned pivot.
Tolerances: the layout and the closed forms agree to a few roundings of the cam's size
(1e-15 m on 0.1 m); a finite difference over 1e-4 rad is good to (1e-4)² relative.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.constructions.cams.inversion import lay_out_profile
from tarsim.constructions.cams.survey import survey
from tarsim.constructions.errors import InputError
from tarsim.constructions.model import Drive
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.cam_profile import (Follower, follower_motion,
                                                        pressure_angle_translating, station)
from tarsim.exercises.cams.cam_file import parse_cam
from tarsim.exercises.cams.cam_solution import solve_cam
from tarsim.exercises.catalog import load
from tarsim.exercises.cli import cli
from tarsim.exercises.linkages.mechanism_file import load_mechanism

DATA = Path(__file__).parent / "data"
ROLLER = "roller-harmonic-cycloidal"


def test_a_flat_face_on_harmonic_rise_and_return_wraps_the_eccentric_disc():
    """r₀ = 15 mm, h = 50 mm: the profile is the disc of radius r₀ + h/2 = 40 mm about
    (0, −h/2), its radius of curvature 40 mm everywhere, and the face is touched ±h/2 from
    its axis (y′ = h/2·sin θ), so it must be 50 mm wide."""
    s = solve_cam(load("eccentric-flat-face"))
    assert s.passed, s.failures
    sv = s.profile.survey
    for st in sv.stations:
        assert math.dist(st.profile, (0.0, -0.025)) == pytest.approx(0.040, abs=1e-15)
        assert st.rho == pytest.approx(0.040, abs=1e-15)
    lo, hi = sv.face
    assert (lo, hi) == pytest.approx((-0.025, 0.025), abs=1e-15)
    assert s.results["quantities"]["face_width"]["value"] == pytest.approx(0.050, abs=1e-15)


@pytest.mark.parametrize("deg", range(0, 360, 30))
def test_the_eccentric_cam_moves_its_face_as_the_linkage_solver_does(deg):
    """The linkage file puts the disc's centre C at θ₂ from +x, so the cam has turned
    θ = θ₂ + 90° from the follower's lowest place; the face's height is r₀ + y(θ) and its
    speed y′(θ)·ω, ω = 10 rad/s counter-clockwise in both."""
    ex = load("eccentric-flat-face")
    kin = solver.solve(load_mechanism(DATA / "circular-cam.toml").with_drive(
        Drive(2, math.radians(deg), 10.0)))
    m = follower_motion(ex.segments, math.radians(deg + 90))
    assert kin.points["F"][1] == pytest.approx(ex.base_radius + m.y, abs=1e-15)
    assert kin.velocities["F"][1] == pytest.approx(m.y1 * ex.omega, abs=1e-14)


@pytest.mark.parametrize("name", [ROLLER, "offset-knife-edge"])
def test_the_pressure_angle_is_the_textbooks_formula_all_round(name):
    ex = load(name)
    s = solve_cam(ex)
    for st in s.profile.survey.stations:
        m = follower_motion(ex.segments, st.theta)
        want = pressure_angle_translating(m.y, m.y1, ex.base_radius, ex.follower, ex.sigma)
        assert st.pressure_angle == pytest.approx(want, abs=1e-14)
    q = s.results["quantities"]["pressure_angle_max"]
    assert q["value"] == pytest.approx(q["reference"]["value"], abs=1e-14)


def test_the_offset_eases_the_rise_when_it_leans_with_the_cam():
    """A knife edge 12.5 mm right of a counter-clockwise cam: on the rise tan φ =
    (y′ − e)/(s₀ + y), whose greatest size over the rise is less than the radial follower's
    y′/(r_b + y)."""
    ex = load("offset-knife-edge")
    radial = Follower("knife-edge")
    offset, plain = [], []
    for i in range(0, 121):
        t = math.radians(i)
        m = follower_motion(ex.segments, t)
        offset.append(station(ex.segments, ex.base_radius, ex.follower, ex.sigma, t))
        plain.append(station(ex.segments, ex.base_radius, radial, ex.sigma, t))
        assert math.tan(plain[-1].pressure_angle) == pytest.approx(
            m.y1 / (ex.base_radius + m.y), rel=1e-13, abs=1e-16)
    steepest = max(abs(st.pressure_angle) for st in offset)
    assert steepest < max(abs(st.pressure_angle) for st in plain)


def _circle_through(a, b, c) -> float:
    (ax, ay), (bx, by), (cx, cy) = a, b, c
    d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay)
          + (cx * cx + cy * cy) * (ay - by)) / d
    uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx)
          + (cx * cx + cy * cy) * (bx - ax)) / d
    return math.hypot(ax - ux, ay - uy)


@pytest.mark.parametrize("name", [ROLLER, "offset-knife-edge", "oscillating-roller"])
@pytest.mark.parametrize("deg", [17, 55, 100, 200, 233])
def test_the_pitch_curves_radius_is_the_circle_through_three_near_points(name, deg):
    ex = load(name)
    t, h = math.radians(deg), 1e-4
    pts = [station(ex.segments, ex.base_radius, ex.follower, ex.sigma, t + d).pitch
           for d in (-h, 0.0, h)]
    rho = station(ex.segments, ex.base_radius, ex.follower, ex.sigma, t).rho
    assert abs(rho) == pytest.approx(_circle_through(*pts), rel=1e-6)


def test_every_roller_circle_touches_the_profile_and_none_cuts_it():
    """The closed-form profile, sampled every ¼°, stays outside each roller circle laid out
    and comes within the sampling's sag (chord 0.4 mm on ρ ≥ 40 mm: < 1 µm) of touching."""
    s = solve_cam(load(ROLLER))
    c, r = s.profile.layout.construction, s.exercise.follower.radius
    curve = [st.profile for st in s.profile.survey.stations]
    for p in s.profile.layout.places:
        centre = c.output(p.trace).xy
        nearest = min(math.dist(centre, q) for q in curve)
        assert r - 1e-15 <= nearest <= r + 1e-6


def test_an_oscillating_arm_keeps_its_length_and_swings_by_the_lift():
    s = solve_cam(load("oscillating-roller"))
    assert s.passed, s.failures
    f, c = s.exercise.follower, s.profile.layout.construction
    assert f.arm == 0.050 and f.pivot == (0.070, 0.0)
    for p in s.profile.layout.places:
        pivot, rest, trace = (c.output(ref).xy for ref in (p.pivot, p.rest, p.trace))
        assert math.dist(pivot, trace) == pytest.approx(0.050, abs=1e-15)
        assert math.hypot(*rest) == pytest.approx(0.050, abs=1e-15)   # on the prime circle
        swing = math.atan2(trace[1] - pivot[1], trace[0] - pivot[0]) - math.atan2(
            rest[1] - pivot[1], rest[0] - pivot[0])
        assert abs(math.remainder(swing, 2 * math.pi)) == pytest.approx(p.lift / 0.050,
                                                                        abs=1e-14)
    top = max(p.lift for p in s.profile.layout.places) / 0.050
    assert math.degrees(top) == pytest.approx(20.0, abs=1e-12)


def test_a_layout_turned_the_wrong_way_is_caught():
    """The check can fail: the stations laid out with the cam's own turning, not against
    it, stand off the closed form."""
    s = solve_cam(load(ROLLER))
    ex = s.exercise
    wrong = lay_out_profile(s.diagram, ex.base_radius, ex.follower, -ex.sigma)
    assert survey(wrong, ex.base_radius, ex.segments, ex.sigma).misses


UNDERCUT = """\
name = "A small cam under a big roller"
[cam]
base_radius = 10
speed = 100
[follower]
kind = "roller"
radius = 20
[[segment]]
kind = "rise"
angle = 60
lift = 40
law = "cycloidal"
[[segment]]
kind = "return"
angle = 300
lift = 40
law = "cycloidal"
"""


def test_an_undercut_is_refused_at_its_cam_angle_unless_allowed(tmp_path):
    """The pitch curve's least convex radius, 18.6 mm near θ = 48°, is under the 20 mm
    roller: refused with nothing written, or drawn and flagged with --allow-undercut."""
    path = tmp_path / "undercut.toml"
    path.write_text(UNDERCUT, encoding="utf-8")
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["solve", str(path), "-o", str(out), "--no-pdf"])
    assert result.exit_code == 1
    line = result.output.strip()
    assert "\n" not in line and "Traceback" not in line
    assert "the roller (radius 20 mm) undercuts the cam in segment 1 at θ = 48.2" in line
    assert not out.exists()
    result = CliRunner().invoke(cli, ["solve", str(path), "-o", str(out), "--no-pdf",
                                      "--allow-undercut"])
    assert result.exit_code == 0, result.output
    span = _radial_roller_span(0.010, 0.020, 0.040, math.radians(60))
    assert (f"UNDERCUT from θ = {math.degrees(span[0]):.2f}° to {math.degrees(span[1]):.2f}°, "
            "worst in segment 1") in result.output
    doc = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert doc["quantities"]["undercut"]["value"] is True
    assert 0.018 < doc["quantities"]["rho_min"]["value"] < 0.020


def _radial_roller_span(base, roller, lift, beta):
    """Where a radial roller of radius ``roller`` undercuts a cycloidal rise of ``lift`` over
    ``beta``: the pitch curve R = base + roller + y in polar form bends at
    κ = (R² + 2y′² − R y″)/(R² + y′²)^{3/2}, found above 1/roller by bisection on the law."""
    def kappa(t):
        w = 2 * math.pi * t / beta
        y = lift * (t / beta - math.sin(w) / (2 * math.pi))
        y1 = lift / beta * (1 - math.cos(w))
        y2 = 2 * math.pi * lift / beta ** 2 * math.sin(w)
        r = base + roller + y
        return (r * r + 2 * y1 * y1 - r * y2) / (r * r + y1 * y1) ** 1.5 - 1 / roller

    ts = [beta * i / 4000 for i in range(4001)]
    inside = [t for t in ts if kappa(t) > 0]
    ends = []
    for edge, step in ((inside[0], -beta / 4000), (inside[-1], beta / 4000)):
        a, b = edge, edge + step               # kappa(a) > 0 ≥ kappa(b)
        for _ in range(100):
            m = 0.5 * (a + b)
            a, b = (m, b) if kappa(m) > 0 else (a, m)
        ends.append(a)
    return ends


def test_a_flat_face_on_a_profile_that_turns_concave_is_refused():
    """A 50 mm cycloidal rise in 60° on a 20 mm base circle: r_b + y + y″ goes negative
    (y″ = 2πh/β²·sin 2πθ/β reaches −0.29 m), so no flat face can follow."""
    text = UNDERCUT.replace("base_radius = 10", "base_radius = 20").replace(
        "kind = \"roller\"\nradius = 20", "kind = \"flat-faced\"").replace("40", "50")
    with pytest.raises(InputError) as e:
        solve_cam(parse_cam(text, "flat.toml"))
    assert "the flat face meets a concave profile in segment 1 at θ = " in str(e.value)
    s = solve_cam(parse_cam(text, "flat.toml"), allow_undercut=True)
    # ρ = r_b + y + y″ is least where its derivative h/β(1 − cos w) + 4π²h/β³·cos w vanishes,
    # w = 2πθ/β: cos w = 1/(1 − 4π²/β²), on the half turn where sin w < 0.
    h, beta = 0.050, math.radians(60)
    w = 2 * math.pi - math.acos(1 / (1 - 4 * math.pi ** 2 / beta ** 2))
    least = 0.020 + h * (w / (2 * math.pi) - math.sin(w) / (2 * math.pi)) \
        + 2 * math.pi * h / beta ** 2 * math.sin(w)
    st = s.profile.survey.sharpest
    # Both sides are a few roundings of 0.3 m; the angle's rounding moves ρ only to second
    # order at its least.
    assert st.rho == pytest.approx(least, abs=1e-15) and least < 0
    assert st.theta == pytest.approx(w * beta / (2 * math.pi), abs=1e-7)
    assert f"θ = {math.degrees(st.theta):.2f}°" in str(e.value)


def test_solve_writes_the_profile_its_table_and_steps(tmp_path):
    out = tmp_path / "cam"
    result = CliRunner().invoke(cli, ["solve", "offset-knife-edge", "-o", str(out),
                                      "--no-pdf"])
    assert result.exit_code == 0, result.output
    assert {"profile.svg", "profile-table.svg"} <= {p.name for p in out.iterdir()}
    steps = (out / "steps.md").read_text(encoding="utf-8")
    assert "Draw the offset circle about O, radius 12.5 mm" in steps
    assert "Station 3 (60°): along the follower's line lay off the lift 20 mm" in steps


def test_an_oscillating_arm_reports_its_angular_peaks():
    """A cycloidal swing of 20° over 120° peaks at ψ′ = 2·20/120 = 1/3, so the arm turns at
    most ω/3 = 6.98 rad/s with the cam at 200 rpm; the roller's centre at 50 mm times it."""
    s = solve_cam(load("oscillating-roller"))
    w = 200 * 2 * math.pi / 60
    rise = s.peaks[0]
    assert rise.velocity == pytest.approx(0.050 * w / 3, rel=1e-14)
    assert f"(the arm: {w / 3:.6g} rad/s" in s.lines()[0]


def test_draw_lays_a_cam_out(tmp_path):
    """`tarsim draw` on a cam writes its layout, the figure solve writes as profile.svg; an
    input angle means nothing to a cam and is refused."""
    out = tmp_path / "cam.svg"
    result = CliRunner().invoke(cli, ["draw", "oscillating-roller", "-o", str(out)])
    assert result.exit_code == 0, result.output
    svg = out.read_text(encoding="utf-8")
    assert "Cam: oscillating roller follower: profile" in svg
    result = CliRunner().invoke(cli, ["draw", "oscillating-roller", "-o", str(out),
                                      "--angle", "30"])
    assert result.exit_code == 1 and "leave out --angle" in result.output
