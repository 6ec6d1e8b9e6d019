"""A wheel rolling on the ground as the input, with no pivot: its angle places its centre
(it has rolled r·θ), it turns about its contact point P, and every method starts from its
centre. Against the rolling relations themselves, then the analytic solver."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.linkages.assembly_record import point_ref
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.model import Drive
from tarsim.constructions.narration import narrate
from tarsim.constructions.reference import solver
from tarsim.constructions.linkages.velocity_by_components import velocity_by_components
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tarsim.exercises.catalog import bundled, load
from tarsim.exercises.linkages.mechanism_file import load_mechanism
from tarsim.exercises.linkages.solution_files import solve_worked

R = 0.150                                  # the wheel's radius (m)
ANGLES = [math.radians(d) for d in (-150, -60, 0, 45, 90, 200, 270)]


def wheel(theta: float, omega: float = -20.0, alpha: float = -3.0):
    m = load_mechanism(bundled()["wheel-driven-slider"])
    return m.with_drive(Drive(2, theta, omega, alpha))


@pytest.mark.parametrize("theta", ANGLES)
def test_the_solver_rolls_the_wheel_as_the_relations_say(theta):
    m = wheel(theta)
    kin = solver.solve(m)
    w, a = m.drive.omega, m.drive.alpha
    (cx, cy), (ax, ay) = kin.points["C"], kin.points["A"]
    # On the left of the floor (+x) the wheel rolls back as it turns counter-clockwise.
    assert (cx, cy) == pytest.approx((-R * theta, R), abs=1e-15)
    assert (ax - cx, ay - cy) == pytest.approx((R * math.cos(theta), R * math.sin(theta)),
                                               abs=1e-15)
    # It turns about P, the foot of C: V_X = ω × (X − P); the centre runs along the floor.
    px, py = cx, 0.0
    for name in ("C", "A"):
        x, y = kin.points[name]
        assert kin.velocities[name] == pytest.approx((-w * (y - py), w * (x - px)), abs=1e-14)
    # a_C = α r along the floor; P accelerates ω² r toward C.
    assert kin.accelerations["C"] == pytest.approx((-a * R, 0.0), abs=1e-13)
    a_p = solver.point_acceleration(kin, m, 2, (px, py))
    assert a_p == pytest.approx((0.0, w * w * R), abs=1e-12)


@pytest.mark.parametrize("theta", ANGLES)
def test_the_compass_places_the_centre_where_the_solver_does(theta):
    m = wheel(theta)
    asm, kin = assemble(m), solver.solve(m)
    for name in m.point_names:
        assert math.dist(asm.xy(name), kin.points[name]) <= 1e-15 * 0.6, name


def test_a_rim_point_on_the_contact_is_at_rest_in_every_method():
    m = wheel(math.radians(270))                      # A at the bottom of the rim, on P
    asm = assemble(m)
    assert velocity_by_components(asm, "A", scale=1.0).value(asm) == (0.0, 0.0)
    vp = draw_velocity_polygon(assemble(m), scale=1.0)
    assert vp.vector("A") == (0.0, 0.0)


def test_the_exercise_checks_and_says_the_converted_input():
    worked = solve_worked(load("wheel-driven-slider"))
    assert worked.passed
    (sol,) = worked.positions
    # The centre's 3 m/s forward on the left of the floor is ω2 = −3/0.15 rad/s (cw), and its
    # 0.5 m/s² is α2 = −0.5/0.15 rad/s².
    d = sol.assembly.mechanism.drive
    assert d.omega == pytest.approx(-20.0, rel=1e-12)
    assert d.alpha == pytest.approx(-0.5 / R, rel=1e-12)
    assert "Position: θ2 = 60°, ω2 = 20 rad/s cw, α2 = −3.33333 rad/s²." in worked.steps()
    said = narrate(sol.assembly[point_ref("C")])
    assert "it has rolled r·θ2 = 157.0796 mm" in said and "Lay off 157.0796 mm back" in said


def test_the_steps_state_the_input_as_converted_not_as_provisional():
    worked = solve_worked(load("piston-driven-slider-crank"))
    d = worked.positions[0].assembly.mechanism.drive
    assert d.omega != 1.0
    assert f"ω2 = {abs(d.omega):.6g} rad/s cw" in worked.steps()


def test_a_long_note_wraps_instead_of_widening_the_figure():
    worked = solve_worked(load("wheel-driven-slider"))
    centres = worked.figures["centres"]
    assert (centres.width, centres.height) in ((297.0, 210.0), (210.0, 297.0))


def test_a_rolling_input_has_no_limit_positions():
    from tarsim.constructions.linkages.limit_positions import draw_limit_positions

    with pytest.raises(TarsimError, match="wheel rolling on the frame, not a crank"):
        draw_limit_positions(wheel(1.0))


def test_a_wheel_on_the_right_of_its_face_rolls_the_other_way():
    m = wheel(0.7)
    (s,) = [t for t in m.slides if t.rolling]
    flipped = replace(s.contact, side="right")
    # The floor's direction reversed puts the wheel on its right: the same wheel, the same
    # motion, the distance rolled now measured the other way.
    from tarsim.constructions.joints import contact_slide

    face = replace(flipped.face, angle=math.pi)
    t = contact_slide(replace(flipped, face=face), m.frame)
    m2 = replace(m, slides=tuple(t if u is s else u for u in m.slides))
    kin, kin2 = solver.solve(m), solver.solve(m2)
    assert kin2.points["C"] == pytest.approx(kin.points["C"], abs=1e-15)
    assert kin2.velocities["B"] == pytest.approx(kin.velocities["B"], abs=1e-14)
    assert kin2.accelerations["B"] == pytest.approx(kin.accelerations["B"], abs=1e-12)
