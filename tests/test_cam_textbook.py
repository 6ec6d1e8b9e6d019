"""Cams as the books pose them: a roller by its diameter, uniform acceleration and
retardation over unequal parts, the motion at a stated cam angle, a swinging arm's angular
rates; each against its closed form."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.cams.displacement import Segment
from tarsim.constructions.cams.readings import read_at
from tarsim.constructions.errors import InputError
from tarsim.constructions.reference.cam_laws import motion, peaks
from tarsim.exercises.cams.cam_file import parse_cam
from tarsim.exercises.cams.cam_solution import solve_cam
from tarsim.exercises.catalog import bundled, load
from tarsim.exercises.cli import cli

CAM = Path(bundled("cams")["roller-harmonic-cycloidal"]).read_text(encoding="utf-8")

VALVE = Path(bundled("cams")["valve-unequal-acceleration"]).read_text(encoding="utf-8")
W = 150 * 2 * math.pi / 60          # the valve cam's 150 rpm


def test_a_roller_may_be_given_by_its_diameter():
    """diameter = 20 is a roller of radius 10 mm: the prime circle 40 + 10 mm."""
    ex = parse_cam(VALVE, "cam.toml")
    assert ex.follower.radius == pytest.approx(0.010, rel=1e-15)


@pytest.mark.parametrize("old, new, words", [
    ("diameter = 20", "diameter = 20\nradius = 10",
     "the roller's radius or its diameter, not both"),
    ("diameter = 20", "diameter = 0", "a roller follower gives its radius (radius = 10) or its "
                                      "diameter"),
    ("accelerating = 80 ", "accelerating = 120 ", "less than all of it, not 120°"),
    ("accelerating = 80 ", "accelerating = 77 ", "the acceleration ends 77° into the "
                                                 "segment's 120°, on no division of 2 to 24"),
    ("accelerating = 80 ", "accelerating = 45\ndivisions = 6 ",
     "the acceleration must end on a division: 45° of 120° in 6 equal parts does not"),
    ("law = \"simple harmonic\"", "law = \"simple harmonic\"\naccelerating = 30",
     "only a parabolic segment (uniform acceleration and retardation) is split"),
    ("at = [60, 180] ", "at = [60, 400] ", "a cam angle asked at is from 0° to 360°, not 400°"),
    ("at = [60, 180] ", "at = [60, 60] ", "a cam angle is asked at twice"),
    ("at = [60, 180] ", "at = \"60\" ", "at lists cam angles in degrees"),
])
def test_a_bad_book_input_is_refused_in_one_line_at_its_place(old, new, words):
    assert old in VALVE
    with pytest.raises(InputError) as e:
        parse_cam(VALVE.replace(old, new, 1), "cam.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("cam.toml:") and words in message, message


def test_unequal_acceleration_and_retardation_are_the_books_closed_forms():
    """h = 30 mm over β = 120°, accelerating over β₁ = 80°, retarding over β₂ = 40°: the
    velocity peaks at V = 2h/β·ω where the parts meet (h = V(β₁ + β₂)/2), the acceleration
    is V/β₁·ω = 2h/(β·β₁)·ω² and the retardation 2h/(β·β₂)·ω², twice it."""
    s = solve_cam(load("valve-unequal-acceleration"))
    assert s.passed and not s.misses                 # each constructed point on its law
    h, b, b1, b2 = 0.030, math.radians(120), math.radians(80), math.radians(40)
    q = s.results["quantities"]
    assert q["v_max_1"]["value"] == pytest.approx(2 * h / b * W, rel=1e-14)
    assert q["acceleration_1"]["value"] == pytest.approx(2 * h / (b * b1) * W * W, rel=1e-14)
    assert q["retardation_1"]["value"] == pytest.approx(2 * h / (b * b2) * W * W, rel=1e-14)
    assert q["a_max_1"]["value"] == pytest.approx(q["retardation_1"]["value"], rel=1e-14)
    # Each part's share of the lift is its share of the angle: 20 mm by 80°.
    assert motion("parabolic", h, b, b1, split=2 / 3).y == pytest.approx(0.020, rel=1e-14)
    # The jump of y″ is at 80°, not at the middle.
    assert 80.0 in s.jumps and 60.0 not in s.jumps


def test_an_equal_split_is_the_parabolic_law_unchanged():
    """split = ½ is the textbook's 2hu², 4hu/β, 4h/β² to the last bit (division by ½ is
    exact), so every cam with a parabolic segment solves as it did."""
    h, b = 0.04, 1.3
    for u in (0.0, 0.1, 0.37, 0.5, 0.77, 1.0):
        m = motion("parabolic", h, b, u * b)
        y, y1, y2 = ((2 * h * u * u, 4 * h * u / b, 4 * h / b ** 2) if u <= 0.5 else
                     (h - 2 * h * (1 - u) ** 2, 4 * h * (1 - u) / b, -4 * h / b ** 2))
        assert (m.y, m.y1, m.y2) == pytest.approx((y, y1, y2), rel=1e-15, abs=1e-18)
    assert peaks("parabolic", h, b) == (2 * h / b, 4 * h / b ** 2)


def test_the_motion_at_an_asked_cam_angle_is_the_law_there(tmp_path):
    """60° into the rise (in its acceleration, β₁ = 80°): y = h·u²/k with u = ½, k = ⅔, so
    y = 3h/8 = 11.25 mm, ẏ = 2h·u/(kβ)·ω, ÿ = 2h/(kβ²)·ω². 180° is 30° into the simple
    harmonic return over 90°: ẏ = −(πh/2β)·sin(π/3)·ω, ÿ = −(π²h/2β²)·cos(π/3)·ω²."""
    out = tmp_path / "valve"
    result = CliRunner().invoke(cli, ["solve", "valve-unequal-acceleration", "-o", str(out),
                                      "--no-pdf"])
    assert result.exit_code == 0, result.output
    assert "at θ = 60° (segment 1): y = 11.25 mm, v = 337.5 mm/s" in result.output
    q = json.loads((out / "results.json").read_text(encoding="utf-8"))["quantities"]
    h, b, k = 0.030, math.radians(120), 2 / 3
    assert q["y_at_60"]["value"] == pytest.approx(3 * h / 8, rel=1e-14)
    assert q["v_at_60"]["value"] == pytest.approx(2 * h * 0.5 / (k * b) * W, rel=1e-14)
    assert q["a_at_60"]["value"] == pytest.approx(2 * h / (k * b * b) * W * W, rel=1e-14)
    br = math.radians(90)
    assert q["v_at_180"]["value"] == pytest.approx(
        -math.pi * h / (2 * br) * math.sin(math.pi / 3) * W, rel=1e-13)
    assert q["a_at_180"]["value"] == pytest.approx(
        -math.pi ** 2 * h / (2 * br ** 2) * math.cos(math.pi / 3) * W * W, rel=1e-13)
    assert q["y_at_180"]["value"] == pytest.approx(h / 2 * (1 + math.cos(math.pi / 3)),
                                                   rel=1e-14)
    assert q["v_at_60"]["passed"] and q["a_at_180"]["passed"]
    assert "θ = 60°" in (out / "displacement.svg").read_text(encoding="utf-8")


def test_on_a_join_the_motion_is_the_later_segments():
    """At 120°, the end of the rise, the dwell begins: y = h, ẏ = ÿ = 0; at 150° the
    return begins, ÿ = −π²h/2β²·ω² (the harmonic's first value), not the dwell's 0."""
    ex = parse_cam(VALVE, "cam.toml")
    end = read_at(ex.segments, math.radians(120))
    assert (end.segment, end.law.y, end.law.y1, end.law.y2) == (2, pytest.approx(0.030), 0, 0)
    start = read_at(ex.segments, math.radians(150))
    b = math.radians(90)
    assert start.segment == 3
    assert start.law.y2 == pytest.approx(-math.pi ** 2 * 0.030 / (2 * b * b), rel=1e-14)
    assert start.passed


def test_a_swinging_arms_angular_rates_are_the_peaks_over_the_arm():
    """The bundled arm swings 20° in 120° cycloidally at 200 rpm: ψ̇_max = 2Ψω/β,
    ψ̈_max = 2πΨω²/β²; back in 120° by simple harmonic motion: πΨω/2β, π²Ψω²/2β²."""
    s = solve_cam(load("oscillating-roller"))
    q = s.results["quantities"]
    w, psi, b = 200 * 2 * math.pi / 60, math.radians(20), math.radians(120)
    assert q["omega_max_1"]["value"] == pytest.approx(2 * psi * w / b, rel=1e-14)
    assert q["alpha_max_1"]["value"] == pytest.approx(2 * math.pi * psi * w * w / b ** 2,
                                                      rel=1e-14)
    assert q["omega_max_3"]["value"] == pytest.approx(math.pi * psi * w / (2 * b), rel=1e-14)
    assert q["alpha_max_3"]["value"] == pytest.approx(math.pi ** 2 * psi * w * w / (2 * b * b),
                                                      rel=1e-14)


def test_an_arm_asked_at_a_cam_angle_gives_its_swing_and_rates():
    """30° into the 120° cycloidal swing of 20°: u = ¼, ψ = Ψ(u − sin 2πu/2π),
    ψ̇ = Ψω/β·(1 − cos 2πu) = Ψω/β, ψ̈ = 2πΨω²/β²·sin 2πu = 2πΨω²/β²."""
    text = Path(bundled("cams")["oscillating-roller"]).read_text(encoding="utf-8")
    ex = parse_cam(text.replace("[names]", "[ask]\nat = [30]\n\n[names]"), "arm.toml")
    q = solve_cam(ex).results["quantities"]
    w, psi, b = 200 * 2 * math.pi / 60, math.radians(20), math.radians(120)
    assert q["psi_at_30"]["value"] == pytest.approx(psi * (0.25 - 1 / (2 * math.pi)), rel=1e-14)
    assert q["omega_at_30"]["value"] == pytest.approx(psi * w / b, rel=1e-14)
    assert q["alpha_at_30"]["value"] == pytest.approx(2 * math.pi * psi * w * w / b ** 2,
                                                      rel=1e-14)


LAWS = st.sampled_from(["uniform velocity", "modified uniform velocity", "simple harmonic",
                        "parabolic", "cycloidal"])


@settings(max_examples=150, deadline=None)
@given(LAWS, st.floats(5.0, 300.0), st.floats(1e-4, 1.0), st.floats(0.0, 1.0),
       st.sampled_from([1 / 3, 0.5, 0.75]), st.booleans())
def test_differences_of_the_lift_agree_with_each_law_anywhere(law, degrees, lift, u, split,
                                                              rise):
    """Property: at any cam angle of a segment, its law's y′ and y″ agree with second-order
    differences of its y to 10⁻⁵ of the segment's peak (the module's bound: truncation
    ~10⁻⁷, rounding a few 10⁻⁸), at its ends and beside a jump of y″ too. (A return's
    heights are taken from its own foot here: the differences need only its shape.)"""
    beta = math.radians(degrees)
    segs = [Segment("rise" if rise else "return", beta, lift, law, split=split),
            Segment("dwell", 2 * math.pi - beta)]
    reading = read_at(segs, u * beta)
    assert reading.passed, (reading.law, reading.y1_diff, reading.y2_diff)


BASE = Path(bundled("cams")["base-circle-for-pressure-angle"]).read_text(encoding="utf-8")


def test_the_least_base_circle_for_a_radial_roller_is_the_books_closed_form():
    """A radial roller (10 mm) rising 30 mm by simple harmonic motion over 90°, held to 30°:
    R_p ≥ y′/tan 30° − y, greatest where tan πu = π/(β tan 30°) (d/du of
    (πh/2β)·sin πu/t − h/2·(1 − cos πu) vanishing); the slower, higher return asks less."""
    ex = parse_cam(BASE.replace("offset = 12 ", "offset = 0 "), "cam.toml")
    h, b, t = 0.030, math.radians(90), math.tan(math.radians(30))
    pu = math.atan2(math.pi, b * t)
    want = math.pi * h / (2 * b) * math.sin(pu) / t - h / 2 * (1 - math.cos(pu)) - 0.010
    # golden-section search finds the top to ~1e-8 in θ, where the value moves ~1e-16
    assert ex.base_radius == pytest.approx(want, rel=1e-12)
    s = solve_cam(ex)
    assert s.steepest == pytest.approx(math.radians(30), rel=1e-12)   # the layout touches 30°
    assert s.passed and s.results["quantities"]["base_radius"]["passed"]


def test_an_offset_base_circle_makes_the_layout_touch_the_limit_on_the_steeper_side():
    """12 mm offset, the cam counter-clockwise: tan φ = (y′ − e)/(s₀ + y) eases the rise and
    steepens the return, so the return sets s₀; the layout of the cam found (by inversion,
    knowing nothing of the formula) has its greatest pressure angle 30°, on the return, and
    every other station under it; s₀² + e² = (r_b + r)²."""
    from tarsim.constructions.cams.base_circle import least_prime_reach

    ex = parse_cam(BASE, "cam.toml")
    s = solve_cam(ex)
    assert s.steepest == pytest.approx(math.radians(30), rel=1e-12)
    assert s.profile.survey.steepest_at.segment == 3
    s0 = least_prime_reach(ex.segments, ex.follower, 1.0, math.radians(30))
    assert math.hypot(s0, 0.012) == pytest.approx(ex.base_radius + 0.010, rel=1e-15)
    smaller = parse_cam(BASE.replace("pressure_angle = 30 ", "base_radius = %r " % (
        (ex.base_radius - 1e-6) * 1000)), "cam.toml")      # a micrometre less breaks it
    assert solve_cam(smaller).steepest > math.radians(30)


@pytest.mark.parametrize("old, new, words", [
    ("pressure_angle = 30 ", "pressure_angle = 30\nbase_radius = 40 ",
     "[cam] gives the base circle one way"),
    ("pressure_angle = 30 ", "pressure_angle = 95 ", "between 0° and 90°, not 95°"),
    ("kind = \"roller\"\nradius = 10\n", "kind = \"flat-faced\"\n", "its pressure angle is 0"),
    ("offset = 12 ", "motion = \"oscillating\"\npivot = [70, 0]\narm = 50 ",
     "found for a translating follower"),
])
def test_a_bad_pressure_angle_cam_is_refused_in_one_line(old, new, words):
    assert old in BASE
    with pytest.raises(InputError) as e:
        parse_cam(BASE.replace(old, new, 1), "cam.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("cam.toml:") and words in message, message


def test_an_eccentric_disc_under_a_flat_face_is_simple_harmonic_of_twice_its_eccentricity():
    """A disc of radius R = 40 mm, e = 25 mm off the shaft, at 10 rad/s: the face stays
    tangent to the disc, lifting e(1 − cos θ): v_max = eω, a_max = eω²; the profile laid
    out by inversion is the disc itself, its radius of curvature R everywhere."""
    s = solve_cam(load("eccentric-flat-face"))
    assert s.exercise.disc == (40.0, 25.0) and s.exercise.base_radius == pytest.approx(0.015)
    q = s.results["quantities"]
    assert q["v_max_1"]["value"] == pytest.approx(0.025 * 10, rel=1e-14)
    assert q["a_max_1"]["value"] == pytest.approx(0.025 * 100, rel=1e-14)
    assert q["rho_min"]["value"] == pytest.approx(0.040, rel=1e-12)
    assert q["face_width"]["value"] == pytest.approx(2 * 0.025, rel=1e-12)


@pytest.mark.parametrize("old, new, words", [
    ("kind = \"flat-faced\" ", "kind = \"roller\"\nradius = 5\noffset = 3 ",
     "under a follower translating on a line through the shaft"),
    ("eccentricity = 25 ", "eccentricity = 45 ", "the eccentricity (45) must be more than 0"),
    ("eccentricity = 25 ", "", "gives its radius (or disc_diameter) and its eccentricity"),
    ("disc_radius = 40 ", "disc_radius = 40\ndisc_diameter = 80 ", "not both"),
])
def test_a_bad_eccentric_disc_is_refused_in_one_line(old, new, words):
    text = Path(bundled("cams")["eccentric-flat-face"]).read_text(encoding="utf-8")
    assert old in text
    with pytest.raises(InputError) as e:
        parse_cam(text.replace(old, new, 1), "cam.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("cam.toml:") and words in message, message


def test_a_cam_may_be_given_by_its_least_diameter():
    """base_diameter = 80 is the base circle of radius 40 mm, on a cam of segments and on a
    cam of arcs alike: the same exercise as base_radius = 40."""
    by_radius = parse_cam(VALVE, "cam.toml")
    by_diameter = parse_cam(VALVE.replace("base_radius = 40", "base_diameter = 80"), "cam.toml")
    assert by_diameter.base_radius == pytest.approx(0.040, rel=1e-15)
    assert by_diameter == by_radius
    arc = Path(bundled("cams")["circular-arc-flat-face"]).read_text(encoding="utf-8")
    halved = parse_cam(arc.replace("base_radius = 40 ", "base_diameter = 80 "), "cam.toml")
    assert halved.cam == parse_cam(arc, "cam.toml").cam
    assert halved.cam.base == pytest.approx(0.040, rel=1e-15)


@pytest.mark.parametrize("name", ["valve-unequal-acceleration", "circular-arc-flat-face"])
def test_a_base_circle_given_by_radius_and_diameter_both_is_refused(name):
    text = Path(bundled("cams")[name]).read_text(encoding="utf-8")
    with pytest.raises(InputError) as e:
        parse_cam(text.replace("base_radius = 40", "base_radius = 40\nbase_diameter = 80", 1),
                  "cam.toml")
    line = next(i for i, t in enumerate(text.splitlines(), 1) if t.startswith("base_radius"))
    message = str(e.value)             # at the diameter's line, under the radius's
    assert "\n" not in message and message.startswith(f"cam.toml:{line + 1}:"), message
    assert "base circle's radius or its diameter, not both" in message, message


def test_an_eccentric_disc_makes_its_own_segments():
    text = Path(bundled("cams")["eccentric-flat-face"]).read_text(encoding="utf-8")
    with pytest.raises(InputError, match="leave out the \\[\\[segment\\]\\] tables"):
        parse_cam(text + '\n[[segment]]\nkind = "dwell"\nangle = 360\n', "cam.toml")
    half = parse_cam(text.replace("disc_radius = 40 ", "disc_diameter = 80 "), "cam.toml")
    assert half.base_radius == pytest.approx(0.015, rel=1e-15)


def test_each_segments_greatest_pressure_angle_and_duration():
    """A radial roller (R_p = 40 mm) rising 30 mm by simple harmonic motion over 90°:
    tan φ = y′/(R_p + y) is greatest where (R_p + h/2) cos πu = h/2; the return over 150°
    where (R_p + h/2) cos πu = −h/2. Each segment lasts β/ω."""
    text = BASE.replace("pressure_angle = 30 ", "base_radius = 30 ").replace(
        "offset = 12 ", "offset = 0 ")
    q = solve_cam(parse_cam(text, "cam.toml")).results["quantities"]
    c = 0.015 / 0.055

    def steepest(beta):
        # y there: h/2 (1 − c) on the rise, h/2 (1 + cos πu) = h/2 (1 − c) on the return too
        k = math.pi * 0.030 / (2 * math.radians(beta))
        return math.atan2(k * math.sqrt(1 - c * c), 0.040 + 0.015 * (1 - c))
    # golden-section search finds each top to ~1e-8 in θ, where φ moves ~1e-16
    assert q["pressure_angle_max_1"]["value"] == pytest.approx(steepest(90), rel=1e-12)
    assert q["pressure_angle_max_3"]["value"] == pytest.approx(steepest(150), rel=1e-12)
    assert q["pressure_angle_max"]["value"] == q["pressure_angle_max_1"]["value"]
    w = 200 * 2 * math.pi / 60
    assert q["time_1"]["value"] == pytest.approx(math.radians(90) / w, rel=1e-15)
    assert q["time_4"]["value"] == pytest.approx(math.radians(60) / w, rel=1e-15)


def test_a_flat_faces_least_base_circle_keeps_the_profiles_curvature():
    """Under a flat face the profile's radius is r_b + y + y″. A cycloidal rise of 25 mm over
    90°: y + y″ is least where cos w = −1/(4π²/β² − 1) = −1/15 (w = 2πu, sin w < 0), so
    r_b = ρ − (y + y″) there; the layout then finds its least radius ρ."""
    text = BASE.replace("pressure_angle = 30 ", "rho_min = 5 ").replace(
        'kind = "roller"\nradius = 10\noffset = 12 ', 'kind = "flat-faced"')
    text = text.replace("lift = 30\nlaw = \"simple harmonic\"", "lift = 25\nlaw = \"cycloidal\"",
                        1).replace("lift = 30", "lift = 25")
    ex = parse_cam(text, "cam.toml")
    w = math.atan2(-math.sqrt(1 - 1 / 225), -1 / 15) + 2 * math.pi
    h, b = 0.025, math.radians(90)
    least = h * (w / (2 * math.pi) - math.sin(w) / (2 * math.pi)) \
        + 2 * math.pi * h / b ** 2 * math.sin(w)
    assert ex.base_radius == pytest.approx(0.005 - least, rel=1e-12)
    s = solve_cam(ex)
    assert s.profile.survey.sharpest.rho == pytest.approx(0.005, rel=1e-9)
    assert s.results["quantities"]["base_radius"]["passed"] and s.passed
    with pytest.raises(InputError, match="rho_min sizes the base circle under a translating flat"):
        parse_cam(BASE.replace("pressure_angle = 30 ", "rho_min = 5 "), "cam.toml")


def test_a_dwell_may_take_the_rest_of_the_turn():
    """"Dwell for the rest of the revolution": the segment whose angle is "rest" takes 360°
    less the others' (here 360 − 120 − 30 − 90 = 120°), the same cam as one stating it."""
    text = VALVE.replace("angle = 120\n\n[ask]", 'angle = "rest"\n\n[ask]')
    assert text != VALVE
    ex = parse_cam(text, "cam.toml")
    assert ex.segments == parse_cam(VALVE, "cam.toml").segments
    for bad, words in (('angle = 30\n', 'angle = "rest"\n'), ):
        with pytest.raises(InputError, match="only one segment may take the rest"):
            parse_cam(text.replace(bad, words, 1), "cam.toml")


def test_undercut_asked_draws_the_cam_and_says_so():
    """[ask] undercut = true: a roller larger than a convex stretch of the pitch curve is
    reported (results.json's undercut true, its spans) rather than refused."""
    # A rise of 40 mm in 40°: the pitch curve's nose is some 20 mm round, the roller 20 mm.
    text = (CAM.replace("angle = 120\nlift = 40", "angle = 40\nlift = 40")
            .replace("angle = 30", "angle = 110").replace("radius = 10 ", "radius = 20 ")
            .replace("jerk = true", "undercut = true"))
    with pytest.raises(InputError, match="undercuts the cam"):
        solve_cam(parse_cam(text.replace("undercut = true", ""), "cam.toml"))
    from tarsim.exercises.cams.solve import solve
    s = solve(parse_cam(text, "cam.toml"))
    q = s.results["quantities"]["undercut"]
    assert q["value"] is True and q["spans"]
    # each span's worst radius is under the roller's: ρ < r is what undercuts
    assert all(span["rho"] < 0.020 for span in q["spans"])


def test_the_whole_lift_is_the_greatest_height_the_rises_reach():
    """An eccentric disc's face rises 2e = 50 mm; a swinging arm's lift is its swing, 20°."""
    assert solve_cam(load("eccentric-flat-face")).results["quantities"]["lift"]["value"] == \
        pytest.approx(0.050, rel=1e-15)
    assert solve_cam(load("oscillating-roller")).results["quantities"]["lift"]["value"] == \
        pytest.approx(math.radians(20), rel=1e-15)
