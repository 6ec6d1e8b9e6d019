"""The velocity polygon by relative velocities (constructions/linkages/velocity_polygon.py).

Every tip and every ω is checked against the independent analytic solver. The
tolerance is 1e-9 relative to max(|reference|, |V_input|) for velocities and to
max(|ω|, |ω2|) for angular velocities: the sweeps stay at well-conditioned
positions (no tip's two lines cross below about 10°), where the construction's
error is a few eps (about 1e-15 measured), so 1e-9 leaves room without hiding a
wrong line. Golden numbers cite their seed; they are printed to a fixed number of
digits, so their tolerance is half a unit in the last printed digit.
"""

import math
import re
from pathlib import Path

import pytest

from tarsim.constructions.reference import solver
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.errors import AssemblyError, TarsimError
from tarsim.constructions.model import Drive
from tarsim.constructions.record import Panel, Role, replay
from tarsim.constructions.scales import nice
from tarsim.constructions.linkages.polygon import Polygon
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tarsim.exercises.catalog import bundled
from tarsim.exercises.linkages.mechanism_file import load_mechanism
from tarsim.constructions.narration import narrate
from tests.common import (coupler_four_bar, crank_shaper, four_bar, offset_slider_crank,
                          scotch_yoke, slotted_lever_p37)

DATA = Path(__file__).parent / "data"
REL = 1e-9
SWEEP = [math.radians(d) for d in range(0, 360, 30)]


def from_file(path, omega=None):
    m = load_mechanism(path)
    d = m.drive
    w = d.omega if omega is None else omega
    return lambda t: m.with_drive(Drive(d.link, t, w or 1.0, d.alpha))


MECHANISMS = {
    "four-bar": lambda t: four_bar(t, omega2=10.0),
    "coupler four-bar": coupler_four_bar,
    "offset slider-crank": lambda t: offset_slider_crank(t, omega2=3.0),
    "crank-shaper": crank_shaper,
    "slotted lever P-37": slotted_lever_p37,
    "Scotch yoke": lambda t: scotch_yoke(t, omega2=-2.0),
    "Watt six-bar": from_file(DATA / "watt-six-bar.toml"),
    "Stephenson six-bar": from_file(DATA / "stephenson-six-bar.toml"),
    **{f"catalog {k}": from_file(p) for k, p in bundled().items()},
}


def reference(kin, mech, key):
    """The analytic velocity of a tip: a point, or a coincident point "A4" (A on link 4)."""
    if key in kin.velocities:
        return kin.velocities[key]
    if key == "P" and key not in mech.point_names:
        return (0.0, 0.0)      # a wheel's contact with the ground: at rest (no slip)
    point, link = re.fullmatch(r"(.+?)(\d+)", key).groups()
    return solver.point_velocity(kin, mech, int(link), point)


def polygon(mech, **kw) -> tuple[Polygon, object]:
    asm = assemble(mech)
    return draw_velocity_polygon(asm, **kw), asm


def worst_errors(mech, vp):
    kin = solver.solve(mech)
    v_in = mech.input_speed
    tips = max(math.dist(vp.vector(k), reference(kin, mech, k))
               / max(math.hypot(*reference(kin, mech, k)), v_in) for k in vp.tips)
    omegas = max(abs(w - kin.omegas[c]) / max(abs(kin.omegas[c]), abs(mech.drive.omega))
                 for c, w in vp.rates.items())
    return tips, omegas, kin


# ----- parity with the analytic solver ------------------------------------------------
@pytest.mark.parametrize("theta", SWEEP, ids=[f"{round(math.degrees(t))}deg" for t in SWEEP])
@pytest.mark.parametrize("name", list(MECHANISMS))
def test_every_tip_and_omega_matches_the_analytic_solver(name, theta):
    mech = MECHANISMS[name](theta)
    try:
        solver.solve(mech)
    except AssemblyError:
        # The Stephenson six-bar cannot close over part of the turn: the polygon's
        # assembly must refuse it too, in one line.
        with pytest.raises(TarsimError) as e:
            polygon(mech)
        assert "\n" not in str(e.value)
        return
    vp, _ = polygon(mech)
    tips, omegas, kin = worst_errors(mech, vp)
    assert tips <= REL
    assert omegas <= REL
    # Every moving link's ω is read off, and every point and coincident point has a tip.
    assert set(vp.rates) == set(kin.omegas) - {1}
    assert set(mech.point_names) <= set(vp.tips)


@pytest.mark.parametrize("name", ["crank-shaper", "slotted lever P-37", "Scotch yoke"])
def test_coincident_points_on_a_slot_are_both_drawn(name):
    vp, asm = polygon(MECHANISMS[name](math.radians(40)))
    assert "A4" in vp.tips and vp.tips["A4"] != vp.tips["A"]
    assert asm[vp.tips["A4"]].label == "a4"
    assert asm[vp.tips["A"]].label == "a2"   # the notes' A2 = A3
    assert vp.vector("A2") == vp.vector("A3") == vp.vector("A")


def test_frame_points_are_at_the_pole():
    vp, _ = polygon(four_bar(1.0, omega2=3.0))
    assert vp.tips["O2"] == vp.tips["O4"] == vp.pole
    assert vp.vector("O4") == (0.0, 0.0)


# ----- golden numbers -----------------------------------------------------------------
def test_crank_shaper_seed_003():
    # Seed 003 §7 (typed table) at t = 2.34 s, θ2 = π/2 − t rad, ω2 = −1 rad/s (the
    # MATLAB run): ω4 = +0.19212 rad/s and V_B5 = ṗ = −189.192 mm/s (the ram moves left),
    # printed to 5 decimals and to 0.001 mm/s: tolerance half a unit in the last digit.
    vp, _ = polygon(crank_shaper(math.pi / 2 - 2.34, omega2=-1.0))
    assert vp.rates[4] == pytest.approx(0.19212, abs=0.5e-5)
    vx, vy = vp.vector("B")
    assert vx * 1e3 == pytest.approx(-189.192, abs=0.5e-3)
    assert vy == pytest.approx(0.0, abs=1e-15)
    assert vp.rates[3] == vp.rates[4] and vp.rates[5] == 0.0


def test_four_bar_peers_benchmark():
    # peers.md §4: O2A 100, AB 250, O4B 200, O2O4 300 mm, θ2 = 60°, ω2 = 10 rad/s:
    # ω3 = −2.578464796446, ω4 = 2.915957761501 (12 decimals; the construction is
    # good to a few eps, so 1e-11 relative is ample and still checks every digit).
    vp, _ = polygon(four_bar(math.radians(60), omega2=10.0))
    assert vp.rates[3] == pytest.approx(-2.578464796446, rel=1e-11)
    assert vp.rates[4] == pytest.approx(2.915957761501, rel=1e-11)
    assert vp.rates[2] == pytest.approx(10.0, rel=1e-14)


# ----- the record ---------------------------------------------------------------------
@pytest.mark.parametrize("name", ["coupler four-bar", "crank-shaper", "slotted lever P-37",
                                  "Watt six-bar", "offset slider-crank", "Scotch yoke"])
def test_every_polygon_step_is_in_the_velocity_panel_with_a_sentence(name):
    vp, asm = polygon(MECHANISMS[name](math.radians(50)))
    c = asm
    assert vp.steps[0] == vp.pole and c[vp.pole].label == "o_v"
    for ref in vp.steps:
        step = c[ref]
        assert step.panel is Panel.VELOCITY
        assert len(narrate(step)) > 20 and narrate(step).endswith("."), narrate(step)
    for ref in vp.space_steps:
        assert c[ref].panel is Panel.SPACE and narrate(c[ref])
    # The polygon draws only what rests on the space diagram and on its own steps.
    ours = set(vp.steps) | set(vp.space_steps)
    for ref in vp.steps:
        assert all(i in ours or c[i].panel is Panel.SPACE for i in c[ref].inputs)
    # Each point's absolute velocity is a result drawn from the pole.
    drawn = {c[r].inputs: c[r].role for r in vp.steps if c[r].verb == "join"}
    for tip in set(vp.tips.values()) - {vp.pole}:
        assert drawn[(vp.pole, tip)] in (Role.RESULT, Role.GIVEN)


def test_sentences_speak_the_course():
    vp, asm = polygon(MECHANISMS["catalog four-bar"](math.radians(60)))   # in mm
    said = [narrate(asm[r]) for r in vp.steps]
    assert "Through a draw a line ⟂ AB (the direction of V_B/A)." in said
    assert "Through o_v draw a line ⟂ O4B (the direction of V_B, as O4 is fixed)." in said
    assert any(s.startswith("From o_v lay off o_v a = V_A = ω2·O2A = 10 rad/s × 100 mm = "
                            "1000 mm/s ⟂ O2A") for s in said)
    assert any("ω3 = V_B/A / AB = a b / AB" in s and "(cw" in s for s in said)


def test_slot_sentences_name_the_coincident_points():
    vp, asm = polygon(crank_shaper(math.pi / 2 - 2.34))
    said = [narrate(asm[r]) for r in vp.steps]
    assert ("Through a2 draw the parallel to the slot of link 4 (the direction of V_A4/A2, "
            "the sliding velocity).") in said
    assert any(s.startswith("B lies on line O4A of link 4, so b4 lies on o_v a4") for s in said)


def test_every_step_replays_to_its_output():
    vp, asm = polygon(coupler_four_bar(0.7))
    c = asm
    for ref in vp.steps + vp.space_steps:
        again, stored = replay(c, ref), c.output(ref)
        assert again == stored


# ----- the velocity image -------------------------------------------------------------
@pytest.mark.parametrize("theta", SWEEP[::2])
def test_coupler_image_is_similar_and_same_handed(theta):
    mech = coupler_four_bar(theta, omega2=-3.0)
    vp, asm = polygon(mech)
    c = asm
    P = {n: asm.xy(n) for n in "ABC"}
    p = {n: c.output(vp.tips[n]).xy for n in "ABC"}
    ratio = [math.dist(p[u], p[v]) / math.dist(P[u], P[v]) for u, v in ("AB", "BC", "CA")]
    assert ratio[1] == pytest.approx(ratio[0], rel=1e-12)
    assert ratio[2] == pytest.approx(ratio[0], rel=1e-12)
    # The image side is |ω3| times the link side, at the polygon's scale.
    assert ratio[0] == pytest.approx(abs(vp.rates[3]) * vp.scale, rel=1e-12)

    def turn(q):
        (ax, ay), (bx, by), (cx, cy) = q["A"], q["B"], q["C"]
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    assert math.copysign(1.0, turn(p)) == math.copysign(1.0, turn(P))
    # D lies on AB beyond B: d divides ab as D divides AB.
    d = c.output(vp.tips["D"]).xy
    t = 0.32 / 0.25
    assert d[0] == pytest.approx(p["A"][0] + t * (p["B"][0] - p["A"][0]), abs=1e-12)
    assert d[1] == pytest.approx(p["A"][1] + t * (p["B"][1] - p["A"][1]), abs=1e-12)


# ----- scale --------------------------------------------------------------------------
def test_scale_is_chosen_nice_and_an_explicit_one_is_kept():
    mech = four_bar(1.0, omega2=10.0)
    vp, asm = polygon(mech)
    mant = vp.scale / 10.0 ** math.floor(math.log10(vp.scale))
    assert round(mant, 9) in (1.0, 2.0, 5.0)
    # The input velocity is drawn between a quarter and a half of the mechanism's size.
    drawn = math.dist(*(asm.output(r).xy for r in (vp.pole, vp.tips["A"])))
    assert asm.size / 5.0 < drawn <= asm.size / 2.0
    other, _ = polygon(mech, scale=0.01, pole=(3.0, -2.0))
    assert other.scale == 0.01
    for k in vp.tips:
        assert other.vector(k) == pytest.approx(vp.vector(k), rel=1e-12, abs=1e-14)
    assert nice(0.037, up=False) == 0.02 and nice(5.0, up=False) == 5.0


@pytest.mark.parametrize("bad", [0.0, -1.0, math.inf, math.nan])
def test_a_bad_scale_is_refused(bad):
    with pytest.raises(TarsimError, match="positive number"):
        polygon(four_bar(1.0, omega2=1.0), scale=bad)


def test_a_second_polygon_on_one_construction_is_refused():
    asm = assemble(four_bar(1.0, omega2=1.0))
    draw_velocity_polygon(asm)
    with pytest.raises(TarsimError, match="already holds a velocity polygon"):
        draw_velocity_polygon(asm)


def test_unknown_tip_names_the_tips():
    vp, _ = polygon(four_bar(1.0, omega2=1.0))
    with pytest.raises(TarsimError, match="no tip for Z"):
        vp.vector("Z")


# ----- degenerate and unsupported -----------------------------------------------------
def test_dead_point_is_one_line_not_nan():
    # Non-Grashof four-bar at θ2 = 90°: A = (0, 0.3), O4 = (0.4, 0), |AO4| = 0.5 =
    # AB + O4B, so coupler and rocker are collinear: the lines ⟂ AB through a and
    # ⟂ O4B through o_v are parallel.
    mech = four_bar(math.pi / 2, o4=(0.4, 0.0), crank=0.3, coupler=0.2, rocker=0.3, omega2=1.0)
    with pytest.raises(AssemblyError) as e:
        draw_velocity_polygon(assemble(mech))
    msg = str(e.value)
    assert "\n" not in msg and "dead point" in msg and "nan" not in msg.lower()
    assert e.value.joint == "B" and e.value.angle_deg == pytest.approx(90.0)
    with pytest.raises(AssemblyError):   # the analytic solver agrees it is singular
        solver.solve(mech)


def test_near_dead_point_still_matches():
    # 1° off a rocker limit (crank and coupler collinear): ω4 → 0, which is fine.
    mech = four_bar(math.radians(60) + 1e-3, omega2=10.0)
    vp, _ = polygon(mech)
    tips, omegas, _ = worst_errors(mech, vp)
    assert tips <= REL and omegas <= REL


def test_a_wheel_rolling_on_the_ground_is_at_rest_at_its_contact_point():
    # The contact P is the wheel's instant centre: its tip is the pole, and the wheel's
    # centre runs parallel to the ground, so V_B lies along it.
    mech = load_mechanism(DATA / "rolling-wheel.toml")
    vp, _ = polygon(mech)
    assert vp.vector("P") == (0.0, 0.0)
    kin = solver.solve(mech)
    assert vp.vector("B") == pytest.approx(kin.velocities["B"], rel=1e-12)
    assert abs(vp.vector("B")[1]) <= 1e-12 * abs(vp.vector("B")[0])


def test_input_at_rest_gives_a_polygon_at_the_pole():
    vp, _ = polygon(four_bar(1.0, omega2=0.0))
    assert vp.vector("B") == (0.0, 0.0) and vp.rates[4] == 0.0
