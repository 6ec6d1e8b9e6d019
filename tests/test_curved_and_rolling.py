"""Curved paths and rolling: a pin in a curved slot, a roller on a circular cam, a block
on a curved guide, and a wheel rolling on the ground (notes 000-part1 §2.7 (3b), (4), (5)).

Each is checked against its own closed-form geometry, written here from scratch (two
circles cut, a line cut by a circle), differentiated by central differences: the
reference shares nothing with the analytic solver or the compass.

- ``roller-cam``: roller R (r = 15) on follower O3R = 90 touches a circular cam
  (r = 50) whose centre C is 20 from O2, so |CR| = 65;
- ``curved-slot``: crank pin A (O2A = 50) runs in a slot of lever O4K (80) curved
  about K with radius 110, so |KA| = 110 (O2O4 = 100: a Grashof crank-rocker);
- ``curved-guide-slider-crank``: rod AB = 120 drives block B on a frame arc of
  radius 220 about C = (150, −200), so the block turns with CB;
- ``rolling-wheel``: rod AB = 150 drives wheel B (r = 30) rolling on y = 0, so
  B runs on y = 30 and the wheel turns −ẋ_B / r.
"""

import math
from pathlib import Path

import pytest

from tarsim.constructions.reference.solver import solve
from tarsim.constructions.checks import tolerance
from tarsim.constructions.reference.centres import centre_error, instant_centre
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.linkages.centres import omega_ratio
from tarsim.constructions.errors import InputError, TarsimError
from tarsim.constructions.linkages.kennedy import locate_centres
from tarsim.constructions.model import Drive
from tarsim.constructions.linkages.velocity_by_centres import METHODS
from tarsim.constructions.linkages.velocity_by_components import velocity_by_components
from tarsim.exercises.linkages.mechanism_file import load_mechanism, parse_mechanism
from tarsim.constructions.narration import narrate

DATA = Path(__file__).parent / "data"
ANGLES = range(0, 360, 30)
H = 1e-5                                    # central-difference step, rad
FD = 1e-7                                   # central differences of O(H²) ≈ 1e-10, times ω
mm = 1e-3


def _cut(c1, r1, c2, r2, side):
    """Where circles about c1 and c2 cut, left or right of c1 → c2."""
    dx, dy = c2[0] - c1[0], c2[1] - c1[1]
    d = math.hypot(dx, dy)
    a = (d * d + r1 * r1 - r2 * r2) / (2 * d)
    h = math.sqrt(r1 * r1 - a * a) * (1 if side == "left" else -1)
    return (c1[0] + (a * dx - h * dy) / d, c1[1] + (a * dy + h * dx) / d)


def _crank(o, r, t):
    return (o[0] + r * math.cos(t), o[1] + r * math.sin(t))


def roller_cam(t):
    """Follower angle: R where |CR| = 65 and |O3R| = 90 (left of C → O3)."""
    c = _crank((0, 0), 20 * mm, t)
    o3 = (120 * mm, 40 * mm)
    r = _cut(c, 65 * mm, o3, 90 * mm, "left")
    return {"R": r, 3: math.atan2(r[1] - o3[1], r[0] - o3[0])}


def curved_slot(t):
    """Lever angle: K where |AK| = 110 and |O4K| = 80 (left of A → O4)."""
    a = _crank((0, 0), 50 * mm, t)
    o4 = (100 * mm, 0.0)
    k = _cut(a, 110 * mm, o4, 80 * mm, "left")
    return {"K": k, 4: math.atan2(k[1] - o4[1], k[0] - o4[0])}


def curved_guide(t):
    """B where |AB| = 120 and |CB| = 220 (right of A → C); the block's axis is the
    tangent there with C on its left, so it points 90° ahead of C → B."""
    a = _crank((0, 0), 40 * mm, t)
    c = (150 * mm, -200 * mm)
    b = _cut(a, 120 * mm, c, 220 * mm, "right")
    return {"B": b, 3: math.atan2(b[1] - a[1], b[0] - a[0]),
            4: math.atan2(b[1] - c[1], b[0] - c[0]) + math.pi / 2}


def rolling_wheel(t):
    """Wheel centre on y = r, ahead along +x; the wheel has turned −x_B / r."""
    a = _crank((0, 60 * mm), 40 * mm, t)
    dy = a[1] - 30 * mm
    b = (a[0] + math.sqrt((150 * mm) ** 2 - dy * dy), 30 * mm)
    return {"B": b, 3: math.atan2(b[1] - a[1], b[0] - a[0]), 4: -b[0] / (30 * mm)}


CASES = {"roller-cam": roller_cam, "curved-slot": curved_slot,
         "curved-guide-slider-crank": curved_guide, "rolling-wheel": rolling_wheel}


def at(name: str, degrees: float):
    m = load_mechanism(DATA / f"{name}.toml")
    return m.with_drive(Drive(m.drive.link, math.radians(degrees), m.drive.omega))


def _rates(shape, t, omega):
    """First and second time derivatives of each reference quantity at crank angle t."""
    lo, mid, hi = shape(t - H), shape(t), shape(t + H)
    out = {}
    for k, v in mid.items():
        if isinstance(v, tuple):
            d1 = tuple((b - a) / (2 * H) * omega for a, b in zip(lo[k], hi[k]))
            d2 = tuple((b - 2 * m + a) / H ** 2 * omega ** 2
                       for a, m, b in zip(lo[k], v, hi[k]))
        else:
            da = math.remainder(hi[k] - lo[k], math.tau)
            d1 = da / (2 * H) * omega
            d2 = math.remainder(hi[k] - 2 * v + lo[k], math.tau) / H ** 2 * omega ** 2
        out[k] = (v, d1, d2)
    return out


@pytest.mark.parametrize("name", CASES)
@pytest.mark.parametrize("deg", ANGLES)
def test_positions_velocities_and_accelerations_match_the_closed_form(name, deg):
    m = at(name, deg)
    kin = solve(m)
    asm = assemble(m)
    for key, (value, rate, accel) in _rates(CASES[name], m.drive.angle, m.drive.omega).items():
        if isinstance(key, str):
            # The model stands about the frame's first point; the closed form in the file's axes.
            assert math.dist(m.in_file_axes(kin.points[key]), value) < 1e-12, key
            assert math.dist(m.in_file_axes(asm.xy(key)), value) < 1e-12, key
            assert math.dist(kin.velocities[key], rate) < FD, key
            assert math.dist(kin.accelerations[key], accel) < 1e-3 * max(1.0, math.hypot(*accel))
        else:
            assert math.remainder(kin.angles[key] - value, math.tau) == pytest.approx(0, abs=1e-12)
            assert kin.omegas[key] == pytest.approx(rate, abs=FD)
            assert kin.alphas[key] == pytest.approx(accel, abs=1e-3 * max(1.0, abs(accel)))


@pytest.mark.parametrize("name", CASES)
@pytest.mark.parametrize("deg", ANGLES)
def test_every_centre_and_omega_ratio_matches_the_analytic_one(name, deg):
    m = at(name, deg)
    kin, asm = solve(m), assemble(m)
    cs = locate_centres(asm)
    n = len(m.links)
    assert len(cs.found) == n * (n - 1) // 2
    for pair in cs.found:
        err = centre_error(cs.point(*pair), instant_centre(kin, *pair), asm.size)
        assert err <= tolerance(cs.conditioning(*pair)), (pair, err)
    d = m.drive.link
    for k in m.numbers:
        if k not in (1, d):
            w = omega_ratio(cs, d, k) * m.drive.omega
            assert w == pytest.approx(kin.omegas[k], rel=1e-9, abs=1e-12), k


def test_a_block_on_a_curved_guide_has_its_centre_at_the_centre_of_curvature():
    asm = assemble(at("curved-guide-slider-crank", 50))
    cs = locate_centres(asm)
    c = cs.centre(1, 4)
    assert c.rule == "curved" and c.primary
    assert cs.point(1, 4).xy == pytest.approx((0.150, -0.200), abs=1e-15)
    sentence = narrate(asm[c.ref])
    assert "curved about C" in sentence and "centre of curvature C" in sentence


@pytest.mark.parametrize("deg", ANGLES)
def test_a_rolling_wheel_has_its_centre_at_the_contact_point(deg):
    m = at("rolling-wheel", deg)
    asm = assemble(m)
    cs = locate_centres(asm)
    c = cs.centre(1, 4)
    assert c.rule == "rolling" and c.primary
    bx = rolling_wheel(m.drive.angle)["B"][0]
    assert m.in_file_axes(cs.point(1, 4).xy) == pytest.approx((bx, 0.0), abs=1e-15)
    # the wheel's point at the contact is at rest, and the centre moves at −r ω4
    kin = solve(m)
    assert kin.velocities["B"][0] == pytest.approx(-0.030 * kin.omegas[4], abs=1e-15)


@pytest.mark.parametrize("name, i, j", [("roller-cam", 2, 3), ("curved-slot", 2, 4)])
def test_a_curved_contact_puts_the_centre_on_the_line_of_centres_of_curvature(name, i, j):
    m = at(name, 40)
    asm = assemble(m)
    cs = locate_centres(asm)
    c = cs.centre(i, j)
    assert c.rule == "kennedy" and None in c.triangles     # one line is the common normal
    arc = m.arcs[0]
    (px, py), (qx, qy) = asm.xy(arc.point), asm.xy(arc.centre)
    ix, iy = cs.point(i, j).xy
    across = ((qx - px) * (iy - py) - (qy - py) * (ix - px)) / math.dist((px, py), (qx, qy))
    assert abs(across) < 1e-15


@pytest.mark.parametrize("name, point", [("roller-cam", "R"), ("curved-slot", "K"),
                                         ("curved-guide-slider-crank", "B"),
                                         ("rolling-wheel", "B"), ("rolling-wheel", "M")])
@pytest.mark.parametrize("method", METHODS)
def test_velocity_by_centres_matches_the_analytic_velocity(name, point, method):
    for deg in (20, 140, 250):
        m = at(name, deg)
        kin, asm = solve(m), assemble(m)
        cs = locate_centres(asm)
        r = METHODS[method](asm, cs, point, scale=1.0)
        v, ref = r.value(asm), kin.velocities[point]
        assert math.dist(v, ref) <= 1e-9 * math.hypot(*ref), (deg, v, ref)


def test_grubler_counts_rolling_as_one_lower_pair_and_a_curved_slot_as_a_higher_pair():
    assert at("rolling-wheel", 0).mobility() == (1, 4, 4, 0)
    assert at("curved-slot", 0).mobility() == (1, 3, 2, 1)
    assert at("roller-cam", 0).mobility() == (1, 3, 2, 1)
    assert at("curved-guide-slider-crank", 0).mobility() == (1, 4, 4, 0)


def _edit(name: str, old: str, new: str) -> str:
    text = (DATA / f"{name}.toml").read_text()
    assert old in text
    return text.replace(old, new)


@pytest.mark.parametrize("name, old, new, words", [
    ("curved-guide-slider-crank", "radius = 220", "# no radius",
     ["[slider 1]", "a curved guide needs its radius"]),
    ("curved-guide-slider-crank", 'centre = "C"', 'centre = "D"',
     ["unknown point of link 1 'D'"]),
    ("curved-guide-slider-crank", 'centre = "C"', 'centre = "C"\nangle = 10',
     ["a curved guide is given by its centre and radius, not angle"]),
    ("curved-guide-slider-crank", 'radius = 220', 'radius = 220\nside = "up"',
     ["unknown side 'up'"]),
    ("curved-slot", "radius = 110", "radius = -110", ["must be a positive length"]),
    ("rolling-wheel", "rolling = true", 'rolling = "yes"', ["rolling must be true or false"]),
    ("roller-cam", 'side = "outside"', 'side = "outside"\nrolling = true',
     ["0 degrees of freedom", "cannot move"]),       # a roller that may not slip locks its cam
    ("roller-cam", 'radius = 50 }\nside = "outside"', 'radius = 10 }\nside = "inside"\n'
     'rolling = true', ["rolls inside a circle only if it is the smaller"]),
    ("roller-cam", 'side = "outside"', 'side = "left"', ["unknown side 'left'", "outside"]),
])
def test_bad_curved_or_rolling_joints_get_one_line_naming_the_joint(name, old, new, words):
    with pytest.raises(InputError) as err:
        parse_mechanism(_edit(name, old, new), f"{name}.toml")
    text = str(err.value)
    assert "\n" not in text and text.startswith(f"{name}.toml:")
    for w in words:
        assert w in text, text


def test_components_beyond_a_curved_joint_say_which_method_to_use():
    with pytest.raises(TarsimError, match="use radius-rotation or parallel-line"):
        velocity_by_components(assemble(at("roller-cam", 40)), "R", scale=1.0)


def test_components_reach_a_rolling_wheel_through_its_contact_point():
    # The wheel turns about its contact P at the instant: P is its pivot, as O4 is a rocker's.
    mech = at("rolling-wheel", 40)
    asm = assemble(mech)
    kin = solve(mech)
    for point in ("B", "M"):
        v = velocity_by_components(asm, point, scale=1.0).value(asm)
        assert v == pytest.approx(kin.velocities[point], rel=1e-12, abs=1e-15)
