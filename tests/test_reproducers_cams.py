"""Cam files that once passed a wrong answer or failed a right one, each held to the answer
it should have given.

The numbers asserted are closed forms (the pitch curve of a radial roller in polar form,
R = r_b + r + y: κ = (R² + 2y′² − R y″)/(R² + y′²)^{3/2}, tan φ = y′/R), found with
mpmath where a maximum lies between the ends, and the oracle of tests/random_cams.py, which
reads the file itself; never what tarsim printed.
"""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import mpmath as mp
import pytest
from click.testing import CliRunner
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import tarsim
from tarsim.constructions.cams.displacement import Segment
from tarsim.constructions.cams.rounding import join_bound, lift_bounds
from tarsim.constructions.cams.survey import survey
from tarsim.constructions.reference.cam_laws import LAWS
from tarsim.constructions.reference.cam_profile import follower_motion
from tarsim.exercises.cams.cam_file import parse_cam
from tarsim.exercises.cams.cam_solution import solve_cam
from tarsim.exercises.cams.solve import solve as solve_any
from tarsim.exercises.cli import cli
from tests.random_cams import extremes

HERE = Path(__file__).parent / "reproducers"

REFUSAL = ("the roller (radius {r}) undercuts the cam in segment {k} at θ = {theta}, "
           "where the pitch curve's radius is {rho}; use a smaller roller, a larger base "
           "circle or a gentler segment, or --allow-undercut to draw it marked\n")


def shm_peak_radius(base: float, roller: float, lift: float, beta: float) -> float:
    """The radius of curvature of a radial roller's pitch curve where a simple-harmonic lift
    turns (y′ = 0, y″ = −π²h/2β², R = r_b + r + h): κ = (R − y″)/R²."""
    big = base + roller + lift
    return big * big / (big + math.pi ** 2 * lift / (2 * beta ** 2))


def shm_steepest(base: float, roller: float, lift: float, beta: float) -> float:
    """The greatest pressure angle over a simple-harmonic return from R₀ + h to R₀ (R₀ =
    r_b + r): tan φ = |y′|/(R₀ + y), its maximum where the derivative of that ratio
    vanishes, found by mpmath to 30 digits."""
    mp.mp.dps = 30
    r0, h, b = mp.mpf(base + roller), mp.mpf(lift), mp.mpf(beta)

    def ratio(u):
        return (h * mp.pi / (2 * b) * mp.sin(mp.pi * u)) / (r0 + h / 2 * (1 + mp.cos(mp.pi * u)))

    best = max((ratio(mp.mpf(i) / 200), mp.mpf(i) / 200) for i in range(1, 200))[1]
    u = mp.findroot(lambda u: mp.diff(ratio, u), best)
    return float(mp.atan(ratio(u)))


def solve(name: str, *args: str, tmp_path: Path):
    out = tmp_path / name
    result = CliRunner().invoke(cli, ["solve", str(HERE / f"{name}.toml"), "-o", str(out),
                                      "--no-pdf", *args])
    return result, out


def error_line(output: str, path: Path) -> str:
    """The CLI's one error line, less its "Error: " and the file it may be led by."""
    assert output.startswith("Error: ") and output.count("\n") == 1, output
    return output.removeprefix("Error: ").removeprefix(f"{path}: ")


# ----- a short steep segment between the samples ---------------------------------------------
def test_wrong_cam_undercut_missed(tmp_path):
    """A 13.44 mm simple-harmonic return over 0.234°, after 359.766° of other motion: at its
    start the pitch curve bends to a radius of 1.3 µm, far under the 15.66 mm roller, and
    the pressure angle reaches 89.28° within it. Both fell between the ¼° samples."""
    r, h, beta = 15.656186737346916, 13.4388265773019, math.radians(0.234)
    rho = shm_peak_radius(43.01832456708332, r, h, beta)         # mm
    assert rho == pytest.approx(0.001308, rel=1e-3)
    start = 142.17 + 172.147 + 45.449
    result, out = solve("wrong-cam-undercut-missed", tmp_path=tmp_path)
    assert result.exit_code == 1
    assert error_line(result.output, HERE / "wrong-cam-undercut-missed.toml") == REFUSAL.format(
        r="15.66 mm", k=4, theta=f"{start:.2f}°", rho=f"{rho:.4g} mm")
    assert not out.exists()

    result, out = solve("wrong-cam-undercut-missed", "--allow-undercut", tmp_path=tmp_path)
    assert result.exit_code == 0, result.output
    q = json.loads((out / "results.json").read_text(encoding="utf-8"))["quantities"]
    # A few roundings of R² and R − y″ (y″ = −6.7e8 mm) on each side.
    assert q["rho_min"]["value"] == pytest.approx(rho * 1e-3, rel=1e-12)
    assert q["rho_min"]["theta"] == pytest.approx(math.radians(start), abs=1e-12)
    steep = shm_steepest(43.01832456708332, r, h, beta)
    assert math.degrees(steep) == pytest.approx(89.279, abs=1e-3)
    # The maximum is found on the law to rounding: its value is flat in θ there.
    assert q["pressure_angle_max"]["value"] == pytest.approx(steep, rel=1e-12)
    # The oracle's dense grid finds nothing sharper or steeper anywhere round the cam.
    ext = extremes((HERE / "wrong-cam-undercut-missed.toml").read_text(encoding="utf-8"))
    assert 1 / ext.curvature == pytest.approx(rho * 1e-3, rel=1e-9)
    assert ext.pressure == pytest.approx(steep, rel=1e-9)
    span = q["undercut"]["spans"]
    assert q["undercut"]["value"] and len(span) == 1 and span[0]["segment"] == 4
    assert span[0]["from"] == pytest.approx(math.radians(start), abs=1e-12)
    # The steps say where it is undercut, and the figure's note says it too.
    said = f"UNDERCUT from θ = {start:.2f}° to {math.degrees(span[0]['to']):.2f}°, worst in " \
           "segment 4"
    assert said in result.output
    assert said in (out / "steps.md").read_text(encoding="utf-8")
    assert f"UNDERCUT in segment 4 from θ = {start:.2f}°" in \
        (out / "profile.svg").read_text(encoding="utf-8")
    assert f"pressure angle: greatest {math.degrees(steep):.2f}°" in result.output


def test_wrong_cam_undercut_missed_2(tmp_path):
    """A 59.29 mm simple-harmonic rise over 1.364° on a 41.54 mm base circle: where it turns
    at its top the pitch curve's radius is 20.6 µm, under the 2.425 mm roller."""
    r, h, beta = 2.4250914442225673, 59.29380426682262, math.radians(1.364)
    rho = shm_peak_radius(41.543024959289404, r, h, beta)
    result, out = solve("wrong-cam-undercut-missed-2", tmp_path=tmp_path)
    assert result.exit_code == 1
    assert error_line(result.output, HERE / "wrong-cam-undercut-missed-2.toml") == REFUSAL.format(
        r="2.425 mm", k=1, theta="1.36°", rho=f"{rho:.4g} mm")
    assert not out.exists()
    s = solve_cam(tarsim.load(str(HERE / "wrong-cam-undercut-missed-2.toml")),
                  allow_undercut=True)
    assert s.passed, s.failures
    assert s.profile.survey.sharpest.rho == pytest.approx(rho * 1e-3, rel=1e-12)
    ext = extremes((HERE / "wrong-cam-undercut-missed-2.toml").read_text(encoding="utf-8"))
    assert 1 / ext.curvature == pytest.approx(rho * 1e-3, rel=1e-9)
    assert s.profile.survey.steepest.pressure_angle == pytest.approx(ext.pressure, rel=1e-9)


# ----- a tolerance at the data's own scale -----------------------------------------------------
def test_check3_cam_tolerance_false_alarm(tmp_path):
    """A cam 100 m across whose 7 mm parabolic return is drawn 350 m along the diagram: the
    lines through its points, 4 mm apart, carry a rounding of 1e-10 m, which a fixed 1e-12
    of the greatest lift (7.8e-11 m) called a failure. Each point's tolerance now follows
    from the rounding its acts can carry, and stays far under the lift it checks."""
    result, out = solve("check3-cam-tolerance-false-alarm", tmp_path=tmp_path)
    assert result.exit_code == 0, result.output
    assert "all on their laws" in result.output
    s = solve_cam(tarsim.load(str(HERE / "check3-cam-tolerance-false-alarm.toml")))
    assert s.passed
    lifts = [seg.lift for seg in s.exercise.segments]
    worst = max(abs(s.diagram.point(ref)[1] - _law_lift(s, k, ref))
                for k, curve in enumerate(s.diagram.curves) for _, ref in curve)
    assert worst > 1e-12 * max(lifts)                  # the old tolerance's false alarm
    for seg, curve in zip(s.exercise.segments, s.diagram.curves):
        for _, ref in curve:
            # A check that can fail: each tolerance is under a thousandth of what it checks.
            assert 16 * s.bounds[ref] < 1e-3 * (seg.lift or math.inf)
    ext = extremes((HERE / "check3-cam-tolerance-false-alarm.toml").read_text(encoding="utf-8"))
    q = json.loads((out / "results.json").read_text(encoding="utf-8"))["quantities"]
    assert q["pressure_angle_max"]["value"] == pytest.approx(ext.pressure, rel=1e-9)
    assert q["rho_min"]["value"] == pytest.approx(1 / ext.curvature, rel=1e-9)


def _law_lift(s, k: int, ref) -> float:
    """The lift the law gives at the cam angle the point is drawn at."""
    from tarsim.constructions.reference.cam_profile import segment_motion

    segs = s.exercise.segments
    height = sum(x.lift if x.kind == "rise" else -x.lift if x.kind == "return" else 0.0
                 for x in segs[:k])
    theta = s.diagram.point(ref)[0]
    return segment_motion(segs[k], height, theta - s.diagram.starts[k]).y


def test_a_lift_lost_in_the_rounding_of_a_large_cam_is_refused(tmp_path):
    """The same cam with its 7 mm return made 2 µm: drawn 350 m along, its points could
    be moved further by rounding than the lift itself, so no check of them could fail. It
    is refused, naming the segment."""
    text = (HERE / "check3-cam-tolerance-false-alarm.toml").read_text(encoding="utf-8")
    old, new = 0.007110798774278666, 2e-6
    text = text.replace(f"lift = {old!r}", f"lift = {new!r}").replace(
        "lift = 78.30763768425905", f"lift = {78.30763768425905 + old - new!r}")
    path = tmp_path / "lost.toml"
    path.write_text(text, encoding="utf-8")
    result = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "out"),
                                      "--no-pdf"])
    assert result.exit_code == 1
    line = error_line(result.output, path)
    assert len(line) < 200
    assert line.startswith("segment 5 (return of 2e-06 m over 100.3°) is too small "
                           "beside the rest of the cam to draw: rounding could move its "
                           "points ")
    moved = float(line.split("its points ")[1].split(" m;")[0])
    assert moved >= new
    assert not (tmp_path / "out").exists()


# ----- a join whose other side is steep ---------------------------------------------------------
def test_check3_cam_rise_end_beside_steep_return(tmp_path):
    """A 5 cm rise over 92.91° ends where a 5 cm uniform-velocity return over 0.0157° begins
    (y′ = −h/β = −182 m/rad, 3900 times the rise's). The rise's last station is laid out at
    6·(β/6), one rounding past the join, where the closed form reads the return: 4e-14 m
    below the 5 cm the station carries, past a bound that held only the rise's slope. The
    bound now holds the steeper side's |y′| over the rounding of the station's angle."""
    name = "check3-cam-rise-end-beside-steep-return"
    result, out = solve(name, tmp_path=tmp_path)
    assert result.exit_code == 0, result.output
    assert "33 stations laid out, each where the closed form puts it" in result.output
    s = solve_cam(tarsim.load(str(HERE / f"{name}.toml")))
    assert s.passed, s.failures
    h, beta = 0.05, math.radians(0.015712393305678234)
    e, prime = -0.023505833719771716, 0.05842123335539133 + 0.029210616677695667
    s0 = math.sqrt(prime ** 2 - e ** 2)
    layout = s.profile.layout
    end = layout.places[6]
    join = math.radians(92.91)
    # The station meant for the join, its angle a rounding or two of 1.62 rad from it.
    assert end.theta == pytest.approx(join, abs=4 * 2.2e-16 * join) and end.lift == h
    read = follower_motion(s.exercise.segments, end.theta)
    assert read.y1 == pytest.approx(-h / beta, rel=1e-15)            # the return's slope
    # The pitch point at the join: the follower's line e off the centre, s₀ + h up it,
    # turned back through θ (the cam counter-clockwise). A few roundings of the cam's
    # 0.14 m, and the angle's rounding times 0.14 m, are each under 1e-16 m.
    turned = complex(e, s0 + h) * complex(math.cos(join), -math.sin(join))
    trace = layout.construction.output(end.trace).xy
    assert math.dist(trace, (turned.real, turned.imag)) < 1e-15
    # The greatest pressure angle: on the uniform-velocity return |y′ − σe| is constant, so
    # tan φ = |y′ − σe|/(s₀ + y) is greatest where y = 0, at the return's end.
    steep = math.atan((h / beta + e) / s0)
    assert math.degrees(steep) == pytest.approx(89.9735, abs=1e-4)
    q = s.results["quantities"]["pressure_angle_max"]
    assert q["value"] == pytest.approx(steep, rel=1e-13)       # atan is flat here: ~1e-16
    assert q["theta"] == pytest.approx(join + beta, abs=1e-12)
    ext = extremes((HERE / f"{name}.toml").read_text(encoding="utf-8"))
    assert ext.pressure == pytest.approx(steep, rel=1e-9)      # nothing steeper round the cam

    # The check can still fail: the same lift laid off 1e-10 m long at the join (2e-9 of
    # the lift) is caught, and only there.
    ex = s.exercise
    c = layout.construction.scratch()
    moved = c.draw("P6+", "lay_off", end.rest, end.axis, length=end.lift + 1e-10)
    wrong = dataclasses.replace(layout, construction=c,
                                places=[dataclasses.replace(end, trace=moved)
                                        if p is end else p for p in layout.places])
    bounds = lift_bounds(s.diagram, ex.segments)
    misses = survey(wrong, ex.base_radius, ex.segments, ex.sigma, bounds).misses
    assert [i for i, _ in misses] == [6]
    assert misses[0][1] == pytest.approx(1e-10, rel=1e-3)
    assert not survey(layout, ex.base_radius, ex.segments, ex.sigma, bounds).misses


@settings(max_examples=300, deadline=None)
@given(first=st.floats(1e-4, 300.0), second=st.floats(1e-4, 300.0),
       lift=st.floats(1e-6, 1.0), n=st.integers(2, 24), ulps=st.integers(-3, 3),
       laws=st.sampled_from([(a, b) for a in LAWS for b in LAWS]))
def test_a_station_meant_for_a_join_reads_the_closed_form_within_its_join_bound(
        first, second, lift, n, ulps, laws):
    """Whatever the two segments' angles, laws and divisions, the closed form read at the
    first one's last station, n·(β/n) from its start and then moved a few roundings either
    way, stands off the lift at the join by no more than join_bound: a rise and a return of
    one lift, then a dwell to close the turn. Past the join it reads the return, whose
    slope may be thousands of times the rise's."""
    rest = 360.0 - first - second
    assume(rest > 1e-3)
    segs = [Segment("rise", math.radians(first), lift, laws[0], n, 0.5),
            Segment("return", math.radians(second), lift, laws[1], n, 0.5),
            Segment("dwell", math.radians(rest))]
    theta = n * (segs[0].angle / n)
    for _ in range(abs(ulps)):
        theta = math.nextafter(theta, math.copysign(math.inf, ulps))
    # The lift at the join, from the laws: the rise's top; the return's subtraction of its
    # lift from the height rounds it by a rounding of the lift.
    got = follower_motion(segs, theta).y
    assert abs(got - lift) <= join_bound(segs, theta) + 2.2e-16 * lift


# ----- a tangent cam's knife edge coming onto a small nose -----------------------------------
def tangent_nose_start(r1: float, r2: float, lift: float, roller: float, w: float) -> float:
    """The follower's acceleration as it comes onto a tangent cam's nose, by the closed form
    −ω²·OQ·[cos u + (cos²u − sin²u)/R + sin²u cos²u/R³], R = √(n² − sin²u), n = (r₂ + r)/OQ
    (a slider-crank of crank OQ = r₁ + h − r₂ and rod r₂ + r), u = α − φ the nose's turn
    from the apex there, cos α = (r₁ − r₂)/OQ and tan φ = OQ sin α/(r₁ + r)."""
    oq = r1 + lift - r2
    alpha = math.acos((r1 - r2) / oq)
    u = alpha - math.atan2(oq * math.sin(alpha), r1 + roller)
    c, s = math.cos(u), math.sin(u)
    big = math.sqrt(((r2 + roller) / oq) ** 2 - s * s)
    return -w * w * oq * (c + (c * c - s * s) / big + s * s * c * c / big ** 3)


def test_C5_tangent_knife(tmp_path):  # noqa: N802 (named after its file)
    """A tangent cam under a knife edge (r₁ 25, r₂ 8, h 12 mm, 600 rpm): the acceleration as
    the follower comes onto the nose, −1126.353115 m/s², is right, and the outline's exact
    rates agree with it, so the run ends with exit 0 (differences at the join once gave
    −1126.34963 and failed the check)."""
    result, out = solve("C5-tangent-knife", tmp_path=tmp_path)
    assert result.exit_code == 0, result.output
    assert "check FAILED" not in result.output
    got = json.loads((out / "results.json").read_text(encoding="utf-8"))["quantities"]
    exact = tangent_nose_start(0.025, 0.008, 0.012, 0.0, 600 * math.pi / 30)
    # Both are the same slider-crank in double precision: 10⁻⁹ leaves 10⁴ ulps of room.
    assert got["a_nose_start"]["value"] == pytest.approx(exact, rel=1e-9)
    assert exact == pytest.approx(-1126.353115, abs=5e-7)      # the hand value, to its digits
    assert got["a_nose_start"]["passed"] and got["a_nose_max"]["passed"]
    # The follower leaves the flank at tan φ = OQ sin α/r₁ (no roller): 43.22°, said of the
    # knife edge the file gives, in English and in Persian.
    alpha = math.acos(17 / 29)
    phi = math.degrees(math.atan2(29 * math.sin(alpha), 25))
    assert f"the knife edge leaves the flank {phi:.4g}° after" in result.output
    assert "roller" not in result.output
    result, out = solve("C5-tangent-knife", "--lang", "fa", tmp_path=tmp_path / "fa")
    steps = (out / "steps.md").read_text(encoding="utf-8")
    assert "لبهٔ نوک‌تیز پیرو ۴۳٫۲۲° پس از آغاز صعود از یال جدا می‌شود" in steps
    assert "غلتک" not in steps


@settings(max_examples=30, deadline=None)
@given(st.floats(10, 60), st.floats(0.1, 0.9), st.floats(0.05, 2.0), st.floats(0.05, 1.5),
       st.sampled_from(["knife-edge", "roller"]), st.floats(0.0, 0.999))
def test_no_check_fails_on_a_tangent_cam(r1, nose, lift, roller, follower, at):
    """Property: on any tangent cam (nose 0.1 to 0.9 of r₁, lift 0.05 to 2 r₁), under a knife
    edge or a roller up to 1.5 r₁, every motion the books ask and one asked anywhere on the
    lift pass their check, and the acceleration as the follower comes onto the nose is the
    closed form's to 10⁻⁹ of ω²·OQ (the check's own tolerance, 10⁴ ulps)."""
    r = roller * r1 if follower == "roller" else 0.0
    radius = f"radius = {r!r}\n" if follower == "roller" else ""
    where = 2 * math.degrees(math.acos((r1 - nose * r1) / (r1 + lift * r1 - nose * r1))) * at
    text = (f'name = "tangent"\n[units]\nlength = "mm"\nspeed = "rpm"\n[cam]\n'
            f'kind = "tangent"\nbase_radius = {r1!r}\nnose_radius = {nose * r1!r}\n'
            f'lift = {lift * r1!r}\nspeed = 600\n[follower]\nkind = "{follower}"\n{radius}'
            f'[ask]\nat = [{math.floor(where * 1e6) / 1e6!r}]\n')
    q = solve_any(parse_cam(text, "cam.toml")).results["quantities"]
    failed = [k for k, v in q.items() if v.get("passed") is False]
    assert not failed, failed
    w = 20 * math.pi
    oq = (r1 + lift * r1 - nose * r1) / 1000
    exact = tangent_nose_start(r1 / 1000, nose * r1 / 1000, lift * r1 / 1000, r / 1000, w)
    assert abs(q["a_nose_start"]["value"] - exact) <= 1e-9 * w * w * oq
