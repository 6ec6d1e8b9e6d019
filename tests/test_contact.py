"""Tests for direct contact of a circle on a flat face: the equivalent slide, positions, figure.

A circle of radius r on link i touching a flat face on link j is exactly a pin at the
circle's centre running in a slot of j, parallel to the face and r from it (the
equivalent linkage, lecture notes §2.13). The cams are an eccentric circle, e = 25 mm,
r = 40 mm, ω2 = 10 rad/s ccw:

- ``circular-cam.toml``: a translating follower on a vertical guide through O2, its
  face horizontal above the cam, so the face's height is y = e sin θ2 + r exactly;
- ``offset-cam.toml``: the guide 15 mm left of O2 and the face tilted 10°;
- ``OSCILLATING`` (inline): an arm pivoted at O3 whose face runs along its axis.
"""

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from tarsim.constructions.reference import solver
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.joints import Contact, Profile, SlideKind, contact_slide
from tarsim.constructions.model import Drive, Link, Mechanism
from tarsim.exercises.linkages.mechanism_file import load_mechanism, parse_mechanism
from tarsim.exercises.linkages.report import check_positions
from tarsim.graphics.linkages.diagram import draw_kinematic_diagram
from tarsim.graphics.figure import Circle, Path as FigPath
from tarsim.graphics.svg import to_svg

DATA = Path(__file__).parent / "data"
E, R, OMEGA = 0.025, 0.040, 10.0
TILT, GUIDE_X = math.radians(10.0), -0.015
ANGLES = range(0, 360, 15)
SVG = "{http://www.w3.org/2000/svg}"

OSCILLATING = """\
name = "Eccentric circular cam, oscillating flat-faced follower"
[frame]
O2 = [0, 0]
O3 = [-70, 60]
[[link]]
number = 2
points = ["O2", "C"]
lengths = { O2C = 25 }
[[link]]
number = 3
points = ["O3", "G"]
lengths = { O3G = 130 }
[[contact]]
circle = { link = 2, centre = "C", radius = 40 }
face = { link = 3, through = "O3", angle = 0 }
side = "right"
[input]
link = 2
angle = 30
omega = 10
"""

def cam(name: str) -> Mechanism:
    if name == "oscillating":
        return parse_mechanism(OSCILLATING, "oscillating.toml")
    return load_mechanism(DATA / f"{name}.toml")


def at(mech: Mechanism, deg: float) -> Mechanism:
    return mech.with_drive(Drive(2, math.radians(deg), OMEGA))


# ----- the model ----------------------------------------------------------------------------
@pytest.mark.parametrize("side, offset", [("left", 1.0), ("right", -1.0)])
def test_the_slot_is_the_face_moved_by_the_radius_to_the_circle(side, offset):
    # A face along local +y through (3, 4): left of it is −x.
    face_link = Link(3, (("F", (3.0, 4.0)),))
    c = Contact(Profile(2, centre="C", radius=0.5), Profile(3, through="F", angle=math.pi / 2),
                side)
    s = contact_slide(c, face_link)
    assert (s.kind, s.link, s.point, s.guide_link, s.contact) == (SlideKind.PIN, 2, "C", 3, c)
    assert s.direction == pytest.approx((0.0, 1.0), abs=1e-16)
    assert s.through == pytest.approx((3.0 - 0.5 * offset, 4.0), abs=1e-15)


def test_a_contact_is_one_higher_pair():
    m = cam("circular-cam")
    assert m.mobility() == (1, 3, 2, 1)  # 3(3 − 1) − 2·2 − 1
    assert m.slides[1].contact.label == "contact of link 2 on link 3"
    assert m.slides[1].contact.circle.is_circle and not m.slides[1].contact.face.is_circle


# ----- positions and velocities against the closed form --------------------------------------
@pytest.mark.parametrize("deg", ANGLES)
def test_a_centred_follower_rises_e_sin_theta_plus_r(deg):
    th = math.radians(deg)
    kin = solver.solve(at(cam("circular-cam"), deg))
    # Round-off of a few ulps of 65 mm; the Jacobian is well conditioned everywhere.
    assert kin.points["F"] == pytest.approx((0.0, E * math.sin(th) + R), abs=1e-15)
    assert kin.velocities["F"] == pytest.approx((0.0, E * OMEGA * math.cos(th)), abs=1e-14)
    guide = kin.slide_rates[0]  # the follower's block on its guide, measured from O2
    assert (guide.position, guide.velocity) == pytest.approx(
        (E * math.sin(th) + R, E * OMEGA * math.cos(th)), abs=1e-14)
    assert kin.omegas[3] == pytest.approx(0.0, abs=1e-14)  # it translates


@pytest.mark.parametrize("deg", ANGLES)
def test_a_tilted_face_stays_r_from_the_centre(deg):
    # The face's upward normal n = (−sin 10°, cos 10°): n·F = n·C + r with F on x = −15 mm.
    th = math.radians(deg)
    kin = solver.solve(at(cam("offset-cam"), deg))
    n = (-math.sin(TILT), math.cos(TILT))
    c = (E * math.cos(th), E * math.sin(th))
    vc = (-E * OMEGA * math.sin(th), E * OMEGA * math.cos(th))
    y = (n[0] * c[0] + n[1] * c[1] + R - n[0] * GUIDE_X) / n[1]
    assert kin.points["F"] == pytest.approx((GUIDE_X, y), abs=1e-15)
    assert kin.velocities["F"][1] == pytest.approx((n[0] * vc[0] + n[1] * vc[1]) / n[1],
                                                   abs=1e-14)


# ----- the construction against the analytic solver --------------------------------------------
@pytest.mark.parametrize("name", [
    "circular-cam",
    "offset-cam",
    "oscillating",
])
def test_construction_matches_analytic_round_a_turn(name):
    m = cam(name)
    worst = max(check_positions(at(m, deg)).worst for deg in ANGLES)
    assert worst < 1e-12


# ----- the diagram ------------------------------------------------------------------------------
def drawn(name: str):
    m = cam(name)
    fig = draw_kinematic_diagram(assemble(m))
    root = ET.fromstring(to_svg(fig))
    texts = [t.text for t in root.iter(SVG + "text")]
    (scale,) = [t for t in texts if t.startswith("Scale 1 cm = ")]
    per_cm = float(scale.split()[4])
    return m, fig, root, texts, 10.0 / per_cm  # paper mm per file mm


@pytest.mark.parametrize("name", [
    "circular-cam",
    "offset-cam",
    "oscillating",
])
def test_the_cam_is_drawn_as_its_circle_and_face_not_a_slot(name):
    m, fig, root, texts, s = drawn(name)
    # The cam's circle, to scale, in the links' style: 40 mm of cam.
    radii = [float(c.get("r")) for g in root.iter(SVG + "g") if g.get("class") == "link"
             for c in g.iter(SVG + "circle")]
    assert radii == [pytest.approx(40.0 * s, abs=1e-3)]  # SVG coordinates to 0.001 mm
    (circle,) = [it for it in fig.items if isinstance(it, Circle) and it.style == "link"]
    # Exactly one link line touches it: the face (the slot would pass through the centre).
    (cx, cy), r = circle.centre, circle.radius

    def gap(path):
        (x0, y0), (x1, y1) = path.points
        return abs((x1 - x0) * (cy - y0) - (y1 - y0) * (cx - x0)) / math.dist(*path.points)

    lines = [it for it in fig.items if isinstance(it, FigPath) and it.style == "link"]
    tangents = [p for p in lines if abs(gap(p) - r) < 1e-9 * r]
    assert tangents  # the face (with the oscillating arm, the arm's bar lies along it too)
    # P, a dot, is where the face touches the circle.
    (p,) = [it.centre for it in fig.items if isinstance(it, Circle) and it.style == "arrowhead"
            and abs(math.dist(it.centre, (cx, cy)) - r) < 1e-9 * r]
    (a, b) = tangents[0].points
    assert math.dist(a, p) + math.dist(p, b) == pytest.approx(math.dist(a, b), rel=1e-12)
    # Only the cam's own bar runs to C; a slotted follower would run its bar past it.
    assert sum(any(math.dist(q, (cx, cy)) < 1e-9 for q in p.points) for p in lines) == 1
    assert "P" in texts and "C" in texts
    # C is a centre, not a joint: the only pins are the ground pivots'.
    pins = [c for g in root.iter(SVG + "g") if g.get("class") == "pin"
            for c in g.iter(SVG + "circle")]
    assert len(pins) == sum(1 for n in m.frame.names if len(m.links_at(n)) > 1)
