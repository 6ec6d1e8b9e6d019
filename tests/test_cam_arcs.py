"""Cams of arcs as the books work them: a circular-arc cam under a flat face, a tangent cam
under a roller; their dimensions and the follower's motion against the books' closed forms
and against the follower's place read off the outline."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.cams.arc_cam import ArcCam, arc_motion
from tarsim.constructions.errors import InputError
from tarsim.constructions.reference.cam_arcs import (face_place, flank_radius, outline,
                                                    roller_place)
from tarsim.exercises.cams.cam_file import parse_cam
from tarsim.exercises.catalog import bundled, load
from tarsim.exercises.cams.solve import solve

ARC = Path(bundled("cams")["circular-arc-flat-face"]).read_text(encoding="utf-8")
TANGENT = Path(bundled("cams")["tangent-cam-roller"]).read_text(encoding="utf-8")


def test_a_circular_arc_cams_dimensions_and_motion_are_the_books():
    """r₁ = 40, r₂ = 10, h = 10 mm, α = 60°, 500 rpm: OQ = r₁ + h − r₂ = 40 mm;
    R = (r₁² + d² − r₂² − 2r₁d cos α)/2(r₁ − r₂ − d cos α) = 75 mm exactly (2250/30);
    sin φ = d sin α/(R − r₂); ẍ = ω²(R − r₁) as the lift begins, −ω²d at the apex,
    −ω²d cos(α − φ) onto the nose; ẋ_max = ω(R − r₁) sin φ."""
    s = solve(load("circular-arc-flat-face"))
    q = s.results["quantities"]
    w = 500 * 2 * math.pi / 60
    d, big, alpha = 0.040, 0.075, math.radians(60)
    phi = math.asin(d * math.sin(alpha) / (big - 0.010))
    assert q["nose_distance"]["value"] == pytest.approx(d, rel=1e-14)
    assert q["flank_radius"]["value"] == pytest.approx(big, rel=1e-14)
    assert q["flank_radius"]["passed"]                  # the bisection on the tangencies
    assert q["flank_angle"]["value"] == pytest.approx(phi, rel=1e-14)
    assert q["a_lift_start"]["value"] == pytest.approx(w * w * (big - 0.040), rel=1e-14)
    assert q["v_max"]["value"] == pytest.approx(w * (big - 0.040) * math.sin(phi), rel=1e-14)
    assert q["a_nose_start"]["value"] == pytest.approx(-w * w * d * math.cos(alpha - phi),
                                                       rel=1e-14)
    assert q["a_apex"]["value"] == pytest.approx(-w * w * d, rel=1e-14)
    # 30° after the lift begins the face is still on the flank (φ = 32.2°).
    assert q["y_at_30"]["value"] == pytest.approx((big - 0.040) * (1 - math.cos(math.pi / 6)),
                                                  rel=1e-14)
    assert not s.failures and all(v.get("passed", True) for v in q.values())


def test_a_tangent_cams_nose_follows_from_its_faces_and_lift():
    """Faces 60° apart: α = 90° − 30° = 60°; with h = 15 mm, OQ(1 − cos α) = h gives OQ =
    30 mm and r₂ = r₁ + h − OQ = 15 mm. tan φ = OQ sin α/(r₁ + r); leaving the base circle
    ẍ = ω²(r₁ + r); at the apex −ω²·OQ(1 + OQ/(r₂ + r)) (a slider-crank's piston at its
    inner dead centre)."""
    s = solve(load("tangent-cam-roller"))
    q = s.results["quantities"]
    w = 150 * 2 * math.pi / 60
    assert q["nose_distance"]["value"] == pytest.approx(0.030, rel=1e-14)
    assert q["nose_radius"]["value"] == pytest.approx(0.015, rel=1e-13)
    assert q["flank_angle"]["value"] == pytest.approx(
        math.atan2(0.030 * math.sin(math.radians(60)), 0.040), rel=1e-14)
    assert q["flank_angle"]["passed"]        # where the grown flank meets the grown nose
    assert q["a_lift_start"]["value"] == pytest.approx(w * w * 0.040, rel=1e-14)
    assert q["a_apex"]["value"] == pytest.approx(-w * w * 0.030 * (1 + 0.030 / 0.025),
                                                 rel=1e-14)
    assert not s.failures


def test_a_flank_radius_given_for_the_angle_gives_the_same_cam():
    """R = 75 mm in place of α = 60°: cos α = ((R − r₂)² − (R − r₁)² − d²)/2(R − r₁)d = ½."""
    ex = parse_cam(ARC.replace("angle = 60 ", "flank_radius = 75 "), "cam.toml")
    assert ex.cam.alpha == pytest.approx(math.radians(60), rel=1e-14)


@pytest.mark.parametrize("text, old, new, words", [
    ("arc", "angle = 60 ", "angle = 60\nflank_radius = 75 ", "one of them"),
    ("arc", "nose_radius = 10\n", "", "nose_radius is missing"),
    ("arc", "angle = 60 ", "angle = 10 ", "too small for convex arcs"),
    ("arc", "kind = \"flat-faced\"", "kind = \"flat-faced\"\noffset = 5",
     "translating on a line through the cam's centre"),
    ("tangent", "kind = \"roller\"\ndiameter = 20", "kind = \"flat-faced\"",
     "worked under a roller or knife-edge follower"),
    ("arc", "at = [30] ", "at = [130] ", "at most that, not 130°"),
    ("arc", "kind = \"circular arc\"", "kind = \"convex\"", "a cam's kind is circular arc or "
                                                           "tangent, not 'convex'"),
    ("tangent", "lift = 15\n", "", "gives two of nose_radius, lift and angle"),
    ("tangent", "faces_angle = 60 ", "faces_angle = 60\nangle = 60 ",
     "not angle and faces_angle"),
    ("tangent", "diameter = 20", "diameter = 20\nradius = 10", "gives its radius"),
    ("tangent", "lift = 15\n", "lift = 15\nwidth = 3\n", "unknown setting 'width'"),
])
def test_a_bad_cam_of_arcs_is_refused_in_one_line(text, old, new, words):
    source = ARC if text == "arc" else TANGENT
    assert old in source
    with pytest.raises(InputError) as e:
        parse_cam(source.replace(old, new, 1), "cam.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("cam.toml:") and words in message, message


@settings(max_examples=80, deadline=None)
@given(st.floats(0.02, 0.05), st.floats(0.1, 0.6), st.floats(0.1, 0.8), st.floats(20, 80),
       st.floats(0.0, 1.0), st.floats(0.1, 0.8))
def test_the_books_formulas_are_the_outline_anywhere(r1, nose, lift, degrees, u, roller):
    """Property: for any circular-arc or tangent cam the books' x on the flank and on the
    nose is the follower's place read off the outline (a face's support, a roller's centre
    on the grown outline), to rounding; and the flank radius by the triangle OPQ is the
    bisection's."""
    r2, h = nose * r1, lift * r1
    d = r1 + h - r2
    alpha = math.radians(degrees)
    theta = 2 * alpha * u
    if r1 - r2 - d * math.cos(alpha) > 1e-3 * r1:            # arcs can join base and nose
        cam = ArcCam("circular arc", r1, r2, h, alpha, flat=True)
        assert cam.flank_radius == pytest.approx(flank_radius(r1, r2, d, alpha), rel=1e-10)
        shape = outline("circular arc", r1, r2, d, alpha)
        place = face_place(shape, alpha - theta) - r1
        assert arc_motion(cam, theta, 1.0)[0] == pytest.approx(place, abs=1e-12 * d)
        on = ArcCam("circular arc", r1, r2, h, alpha, roller * r1)     # a roller on it
        place = roller_place(shape, alpha - theta, on.roller) - r1 - on.roller
        assert arc_motion(on, theta, 1.0)[0] == pytest.approx(place, abs=1e-12 * d)
    a_t = math.acos((r1 - r2) / d)                            # the tangent cam of r₁, r₂, h
    cam = ArcCam("tangent", r1, r2, h, a_t, roller * r1)
    t = 2 * a_t * u
    place = roller_place(outline("tangent", r1, r2, d, a_t), a_t - t, cam.roller)
    assert arc_motion(cam, t, 1.0)[0] == pytest.approx(place - r1 - cam.roller, abs=1e-12 * d)


def test_an_eccentric_disc_under_a_roller_is_a_slider_crank():
    """A disc of 100 mm diameter, e = 20 mm off the shaft, a roller of 25 mm diameter, at
    300 rpm: crank e, rod L = 50 + 12.5 mm. From the lowest place the roller's centre is at
    x = e cos ψ + √(L² − e² sin²ψ), ψ = 180° − θ: ẍ = ω²e(1 − e/L) at the lowest place,
    −ω²e(1 + e/L) at the top; 90° on, ẋ = ωe exactly (sin 2ψ = 0)."""
    text = Path(bundled("cams")["eccentric-flat-face"]).read_text(encoding="utf-8")
    text = (text.replace("disc_radius = 40 ", "disc_diameter = 100 ")
            .replace("eccentricity = 25 ", "eccentricity = 20 ")
            .replace("speed = 10 ", "speed = 300 ")
            .replace('kind = "flat-faced" ', 'kind = "roller"\ndiameter = 25\n')
            .replace("[names]", "[ask]\nat = [90]\n\n[names]"))
    text = text.replace('length = "mm"\nspeed = "rad/s"', 'length = "mm"\nspeed = "rpm"')
    ex = parse_cam(text, "cam.toml")
    s = solve(ex)
    q = s.results["quantities"]
    w, e, big = 10 * math.pi, 0.020, 0.0625
    assert q["a_lift_start"]["value"] == pytest.approx(w * w * e * (1 - e / big), rel=1e-14)
    assert q["a_apex"]["value"] == pytest.approx(-w * w * e * (1 + e / big), rel=1e-14)
    assert q["v_at_90"]["value"] == pytest.approx(w * e, rel=1e-14)
    assert q["lift"]["value"] == pytest.approx(2 * e, rel=1e-14)
    # the greatest velocity: where d/dθ of ẋ vanishes, no faster than the crank's ωe(1 + …)
    v = q["v_max"]["value"]
    assert v > w * e and all(arc_motion(ex.cam, math.radians(d), w)[1] <= v * (1 + 1e-12)
                             for d in range(0, 181))
    assert not s.failures


def test_the_angle_of_action_is_twice_the_angle_of_lift():
    ex = parse_cam(ARC.replace("angle = 60 ", "action_angle = 120 "), "cam.toml")
    assert ex.cam.alpha == pytest.approx(math.radians(60), rel=1e-15)
    with pytest.raises(InputError, match="not angle and action_angle"):
        parse_cam(ARC.replace("angle = 60 ", "angle = 60\naction_angle = 120 "), "cam.toml")


def test_the_spring_holds_the_follower_against_its_greatest_retardation():
    """A circular-arc cam's retardation on the nose, ω²d cos(α − θ), is greatest at the apex:
    the spring force m·ω²d. A tangent cam's may be greatest where the roller comes onto the
    nose (here 35.6 m/s² there against 31.6 at the apex): m times the greatest, found
    anywhere on the nose."""
    s = solve(parse_cam(ARC.replace('kind = "flat-faced"', 'kind = "flat-faced"\nmass = 1.5'),
                        "cam.toml"))
    w = 500 * 2 * math.pi / 60
    q = s.results["quantities"]
    assert q["spring_force"]["value"] == pytest.approx(1.5 * w * w * 0.040, rel=1e-12)
    tangent = parse_cam(TANGENT.replace("faces_angle = 60 ", "faces_angle = 90 ")
                        .replace("lift = 15\n", "nose_radius = 6\n")
                        .replace("diameter = 20", "radius = 15\nmass = 2")
                        .replace("speed = 150", "speed = 180"), "cam.toml")
    t = solve(tangent)
    w = 6 * math.pi
    worst = max(-arc_motion(tangent.cam, tangent.cam.phi + (tangent.cam.alpha - tangent.cam.phi)
                            * i / 2000, w, "nose")[2] for i in range(2001))
    assert t.results["quantities"]["spring_force"]["value"] == pytest.approx(2 * worst, rel=1e-9)
    assert not t.failures


def test_the_greatest_acceleration_on_the_flank_and_retardation_on_the_nose():
    """A circular-arc flank accelerates most as the lift begins (ω²(R − r₁) cos θ falls),
    its nose retards most at the apex; a tangent cam's straight flank most where it ends
    ((2 − cos²θ)/cos³θ grows), and here its nose where the roller comes onto it."""
    q = solve(load("circular-arc-flat-face")).results["quantities"]
    assert q["a_flank_max"]["value"] == pytest.approx(q["a_lift_start"]["value"], rel=1e-14)
    assert q["a_nose_max"]["value"] == pytest.approx(q["a_apex"]["value"], rel=1e-14)
    q = solve(load("tangent-cam-roller")).results["quantities"]
    assert q["a_flank_max"]["value"] == pytest.approx(q["a_flank_end"]["value"], rel=1e-12)
    assert q["a_nose_max"]["value"] == pytest.approx(q["a_nose_start"]["value"], rel=1e-12)
    assert q["a_nose_max"]["value"] < q["a_apex"]["value"] < 0


def test_a_roller_on_a_circular_arc_cam_rides_its_flank_as_a_slider_crank():
    """The roller's centre stays R + r from the flank's centre P, which turns on a crank
    OP = R − r₁ pointing away: as the lift begins ẍ = ω²k(1 − k/L), k = R − r₁, L = R + r;
    on the nose, a crank OQ = d with the rod r₂ + r: −ω²d(1 + d/(r₂ + r)) at the apex."""
    ex = parse_cam(ARC.replace('kind = "flat-faced"', 'kind = "roller"\nradius = 8'), "cam.toml")
    s = solve(ex)
    q = s.results["quantities"]
    w, r1, d, big = 500 * 2 * math.pi / 60, 0.040, 0.040, 0.075
    k, rod = big - r1, big + 0.008
    assert q["a_lift_start"]["value"] == pytest.approx(w * w * k * (1 - k / rod), rel=1e-13)
    assert q["a_apex"]["value"] == pytest.approx(-w * w * d * (1 + d / 0.018), rel=1e-13)
    assert q["flank_angle"]["passed"] and not s.failures
