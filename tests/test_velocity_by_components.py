"""Velocities by components (constructions/linkages/velocity_by_components.py).

Every computed velocity is checked against the analytic solver. The tolerance is
relative to |V_input|: 1e-9 on well-conditioned positions, widened to
64·eps/conditioning where the result step's recorded conditioning is poor (a
result's error grows as eps/conditioning of the acts it rests on). Golden numbers
cite seed 004 §11; they are printed to 3 (or 5) decimals, so the tolerance is half
a unit in the last printed digit.
"""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.reference import solver
from tarsim.constructions import geometry as g
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.linkages.assembly_record import Assembly
from tarsim.constructions.errors import AssemblyError, TarsimError
from tarsim.constructions.joints import Slide, SlideKind
from tarsim.constructions.model import Drive, Link, Mechanism
from tarsim.constructions.units import Units
from tarsim.constructions.record import Role
from tarsim.constructions.record import slice as backward_slice
from tarsim.constructions.linkages.velocity_by_components import velocity_by_components
from tarsim.exercises.catalog import bundled
from tarsim.exercises.linkages.mechanism_file import load_mechanism, parse_mechanism
from tarsim.constructions.narration import narrate
from tests.common import (coupler_four_bar, crank_shaper, four_bar, four_bar_toml,
                          offset_slider_crank, scotch_yoke, slotted_lever_p37)

EPS = 2.220446049250313e-16
MM = 1e-3
DATA = Path(__file__).parent / "data"


def seed_slider_crank():
    """Seed 004 §11: crank O2B 40, rod BC 120 mm in-line, θ2 = 60°, ω2 = 10 rad/s.

    D is a third point of the rod on line BC (its midpoint), so that V_D is found by
    case 3, which draws V_B″ and V_C″ and the line through their tips (Hinkle Fig. 5.7).
    """
    return Mechanism(
        (Link(1, (("O2", (0.0, 0.0)),)),
         Link(2, (("O2", (0.0, 0.0)), ("B", (40 * MM, 0.0))), "crank"),
         Link(3, (("B", (0.0, 0.0)), ("C", (120 * MM, 0.0)), ("D", (60 * MM, 0.0))), "rod"),
         Link(4, (("C", (0.0, 0.0)),), "slider")),
        Drive(2, math.radians(60), 10.0),
        (Slide(SlideKind.BLOCK, 4, "C", 1, (0.0, 0.0), (1.0, 0.0)),),
        branches={"C": "forward"}, units=Units("mm"), name="seed 004 slider-crank")


def hand_assembled(mech, guides):
    """Draw ``mech`` from the analytic positions, for mechanisms the compass cannot yet place.

    ``guides`` maps a slide index to (point it passes through, direction).
    """
    c = Assembly(mechanism=mech)
    points = {n: c.give(f"P:{n}", g.Point(*xy), label=n)
              for n, xy in solver.solve_positions(mech).items()}
    lines = {}
    for i, (through, (dx, dy)) in guides.items():
        line, _ = g.line_through(c.output(points[through]), g.Point(dx, dy, 0.0))
        lines[i] = c.give(f"guide:{i}", line, label=f"guide {i}")
    k = mech.link(mech.drive.link)
    axes = {k.number: c.draw(f"axis:{k.number}", "line_through", points[k.names[0]],
                             points[k.names[1]])}
    c.points, c.guides, c.axes, c.position_steps = points, lines, axes, frozenset(c.steps)
    return c


def speed_in(mech):
    d = mech.drive
    return abs(d.omega) * mech.link(d.link).span(*mech.link(d.link).names[:2])


def check(asm, point, *, link=None, scale=2.0, cond_floor=0.0):
    """Run the method, compare with the analytic solver, check the record; return the result."""
    m = asm.mechanism
    r = velocity_by_components(asm, point, scale=scale, link=link)
    kin = solver.solve(m)
    want = solver.point_velocity(kin, m, r.link, point)
    got = r.value(asm)
    step = asm[r.vector]
    assert step.conditioning > cond_floor
    tol = max(1e-9, 64 * EPS / step.conditioning)
    assert math.dist(got, want) <= tol * speed_in(m), (point, got, want)
    check_record(asm, r)
    return r


def input_refs(mech):
    """The input vector's steps (draw_input_velocity): at the drive link's second point, or
    at a rolling wheel's centre after the line from its contact point."""
    s = mech.rolling_input
    if s is not None:
        return [f"arm:{mech.drive.link}", f"v:perp:{s.point}", f"v:tip:{s.point}",
                f"V:{s.point}"]
    p = mech.link(mech.drive.link).names[1]
    return [f"v:perp:{p}", f"v:tip:{p}", f"V:{p}"]


def check_record(asm, r):
    c = asm
    inputs = input_refs(asm.mechanism)
    step = c[r.vector]
    assert r.method == "components"
    assert step.verb == "join" and step.role is Role.RESULT
    assert step.label == f"V_{r.point}" + ("" if r.point in asm.mechanism.link(r.link).names
                                          or r.link == 1 else str(r.link))
    n = len(inputs)
    assert r.steps[:n] == inputs and r.steps[-1] == r.vector
    assert len(set(r.steps)) == len(r.steps)
    assert all(s.startswith("cm:") for s in r.steps[n:])
    order = list(c.steps)
    assert [order.index(s) for s in r.steps] == sorted(order.index(s) for s in r.steps)
    on = set(backward_slice(c, [r.vector]).refs)
    zero = step.output.length == 0.0
    for ref in r.steps:
        s = c[ref]
        assert narrate(s).strip(), ref
        if s.verb == "join":
            assert set(s.inputs) <= on or ref in inputs, ref  # arrows of what was used
            assert s.label.startswith("V_"), ref
            if ref.startswith("cm:V:") and not ref.endswith(":result"):
                assert s.role is Role.CONSTRUCTION
        elif not zero:
            assert ref in on, ref  # every working line leads to the answer
    # and nothing the answer rests on is left out of the narration
    assert {ref for ref in on if ref.startswith("cm:")} <= set(r.steps)


# ----------------------------------------------------------------------------- case 1

@pytest.mark.parametrize("deg", range(0, 360, 30))
def test_four_bar_rocker_pin_by_case_1(deg):
    asm = assemble(four_bar(math.radians(deg), omega2=3.0))
    r = check(asm, "B")
    c = asm
    # the notes' case 1: V_A′ along AB, laid off at B, ⟂ AB at its tip, meets ⟂ O4B
    assert narrate(c["cm:A:foot@A-B"]) == ("Project the tip of V_A onto AB: V_A′ is the "
                                           "component of V_A along AB.")
    assert narrate(c["cm:B:along@A"]) == "With dividers lay off V_B′ = V_A′ at B along AB."
    assert narrate(c["cm:B:tip"]) == ("The perpendicular to AB from the tip of V_B′ meets the "
                                      "path of B (⟂ O4B) at the tip of V_B.")
    assert {"cm:line:A-B", "cm:line:O4-B", "cm:B:path@O4", "cm:B:perp@A"} <= set(r.steps)
    # equal components along AB: the rigid-body principle itself
    (ax, ay), (bx, by) = asm.xy("A"), asm.xy("B")
    u = ((bx - ax) / math.hypot(bx - ax, by - ay), (by - ay) / math.hypot(bx - ax, by - ay))
    va = c.output("V:A").vector
    vb = c.output(r.vector).vector
    assert va[0] * u[0] + va[1] * u[1] == pytest.approx(vb[0] * u[0] + vb[1] * u[1], abs=1e-15)


@pytest.mark.parametrize("deg", range(0, 360, 30))
def test_offset_slider_crank_piston_by_case_1_with_the_guide(deg):
    asm = assemble(offset_slider_crank(math.radians(deg), omega2=-4.0))
    r = check(asm, "C", scale=0.5)
    assert asm["cm:C:tip"].inputs == ("cm:C:perp@A", "guide:0")
    assert narrate(asm["cm:C:tip"]).endswith("meets the guide of C at the tip of V_C.")
    vx, vy = r.value(asm)
    assert abs(vy) <= 1e-15  # along the guide


def test_four_bar_file_units_reach_the_sentences():
    m = parse_mechanism(four_bar_toml(angle=60), "four-bar.toml")
    m = m.with_drive(Drive(2, m.drive.angle, 10.0))
    asm = assemble(m)
    r = check(asm, "B", scale=0.1)
    assert narrate(asm[r.vector]).endswith(" mm/s.")


# ----------------------------------------------------------------------------- cases 2 and 3

@pytest.mark.parametrize("deg", range(0, 360, 30))
def test_coupler_point_off_ab_by_case_2(deg):
    asm = assemble(coupler_four_bar(math.radians(deg)))
    r = check(asm, "C")
    tip = asm["cm:C:tip"]
    assert tip.inputs == ("cm:C:perp@A", "cm:C:perp@B")
    assert "not the vector sum" in narrate(tip)
    labels = {asm[s].label for s in r.steps}
    assert {"V_A′", "V_C′(AC)", "V_B′", "V_C′(BC)", "V_B"} <= labels


@pytest.mark.parametrize("deg", range(0, 360, 30))
def test_coupler_point_on_ab_by_case_3(deg):
    asm = assemble(coupler_four_bar(math.radians(deg)))
    r = check(asm, "D")
    c = asm
    assert c["cm:D:gauge"].inputs == ("cm:A:ncomp@A-B", "cm:B:ncomp@A-B")
    assert c["cm:D:tip"].inputs == ("cm:D:pgram′", "cm:D:pgram″")
    labels = {c[s].label for s in r.steps}
    assert {"V_A″", "V_B″", "V_D″", "V_D′"} <= labels


def test_seed_004_slider_crank_components():
    # Seed 004 §11 (Hinkle Fig. 5.7 procedure on crank 40, rod 120 mm, θ2 = 60°, ω2 = 10).
    m = seed_slider_crank()
    asm = assemble(m)
    scale = 1e-1  # 1 m/s drawn 100 mm long
    rc = check(asm, "C", scale=scale)
    rd = check(asm, "D", scale=scale)
    c = asm

    def mm_s(p, q):
        return math.dist(c.output(p).xy, c.output(q).xy) / scale / MM

    half = 5e-4  # half a unit in the 3rd decimal printed by the seed
    assert mm_s("P:B", "cm:B:foot@B-C") == pytest.approx(389.398, abs=half)    # V_B′
    assert mm_s("P:B", "cm:B:ncomp@B-C") == pytest.approx(91.485, abs=half)    # V_B″
    assert math.hypot(*rc.value(c)) / MM == pytest.approx(406.712, abs=half)   # |V_C|
    assert mm_s("P:C", "cm:C:ncomp@B-C") == pytest.approx(117.408, abs=half)   # V_C″
    # V_B″ and V_C″ lie on opposite sides of BC, so P lies between B and C
    bc = c.output("cm:line:B-C")
    assert (bc.signed_distance(c.output("cm:B:ncomp@B-C"))
            * bc.signed_distance(c.output("cm:C:ncomp@B-C"))) < 0
    p, _ = g.intersect_lines(c.output("cm:D:gauge"), bc)
    pb = g.distance(p, c.output("P:B")) / MM
    assert pb == pytest.approx(52.554, abs=half)
    omega3 = mm_s("P:B", "cm:B:ncomp@B-C") / pb
    assert omega3 == pytest.approx(1.74078, abs=5e-6)  # ω3 = V_B″/PB = V_C″/PC
    assert mm_s("P:C", "cm:C:ncomp@B-C") / (g.distance(p, c.output("P:C")) / MM) == \
        pytest.approx(omega3, rel=1e-12)
    # The seed prints |ω3|; its sense is that of V_B″ about P: clockwise here (the
    # crank pin B is above the line of stroke and ω2 is ccw), as the analytic solver says.
    (px, py), (bx, by) = p.xy, asm.xy("B")
    vx, vy = c.output("cm:B:narrow@B-C").vector
    signed = ((bx - px) * vy - (by - py) * vx) / ((bx - px) ** 2 + (by - py) ** 2) / scale
    assert signed == pytest.approx(-omega3, rel=1e-12)
    assert solver.solve(m).omegas[3] == pytest.approx(signed, rel=1e-12)
    assert "cm:B:narrow@B-C" in rd.steps and "cm:C:narrow@B-C" in rd.steps


def test_seed_004_four_bar_rocker_speed():
    # Seed 004 §11 four-bar: O2O4 100, crank 40, coupler 120, follower 80 mm, θ2 = 60°,
    # ω2 = 10 rad/s: V34 = 365.879 mm/s.
    m = Mechanism((Link(1, (("O2", (0.0, 0.0)), ("O4", (100 * MM, 0.0)))),
                   Link(2, (("O2", (0.0, 0.0)), ("A", (40 * MM, 0.0)))),
                   Link(3, (("A", (0.0, 0.0)), ("B", (120 * MM, 0.0)))),
                   Link(4, (("O4", (0.0, 0.0)), ("B", (80 * MM, 0.0))))),
                  Drive(2, math.radians(60), 10.0), branches={"B": "left"}, units=Units("mm"))
    asm = assemble(m)
    r = check(asm, "B", scale=0.1)
    assert math.hypot(*r.value(asm)) / MM == pytest.approx(365.879, abs=5e-4)
    assert asm.xy("B")[0] / MM == pytest.approx(133.881, abs=5e-4)


# ----------------------------------------------------------------------------- slots

@pytest.mark.parametrize("deg", [-44.072, 90.0, *range(0, 360, 30)])
def test_crank_shaper_ram(deg):
    # Seed 003: the ram B is a block on the frame guide and a pin in the lever's slot.
    asm = assemble(crank_shaper(math.radians(deg)))
    r = check(asm, "B", scale=1.0)
    c = asm
    # Hinkle Fig. 5.8: V_A4 ⟂ O4A from the parallel to the slot through the tip of V_A
    assert c["cm:A@4:tip"].inputs == ("cm:A@4:slide@0", "cm:A@4:path@O4")
    # the gauge line from O4 gives V_B4 (case 3 with O4 at rest)
    assert c["cm:B@4:gauge"].inputs[0] == "P:O4"
    assert "V_B4′ = V_O4′ = 0" in narrate(c["cm:B@4:tip"])
    # and back: the parallel to the slot through the tip of V_B4 meets the ram's guide
    assert c["cm:B:tip"].inputs == ("cm:B:slide@2", "guide:1")
    assert {c[s].label for s in r.steps} >= {"V_A4", "V_B4", "V_B"}


@pytest.mark.parametrize("point", ["A", "B"])
def test_crank_shaper_coincident_points_of_the_lever(point):
    asm = assemble(crank_shaper(math.radians(30)))
    r = check(asm, point, link=4, scale=1.0)
    assert r.link == 4 and asm[r.vector].label == f"V_{point}4"


@pytest.mark.parametrize("deg", range(0, 360, 30))
def test_p37_slotted_lever_ram(deg):
    asm = assemble(slotted_lever_p37(math.radians(deg), omega2=2.0))
    r = check(asm, "C", scale=1.0)
    assert "cm:B:tip" in r.steps  # lever end B by case 3 along the slot O4B


@pytest.mark.parametrize("deg", [20, 75, 140, 250])
def test_scotch_yoke_translates(deg):
    # Hinkle Fig. 5.9: the yoke translates, so V_A4 is the component of V_A along its
    # travel, and every point of the yoke has it.
    m = scotch_yoke(math.radians(deg), omega2=3.0)
    asm = hand_assembled(m, {0: ("A", (0.0, 1.0)), 1: ("O2", (1.0, 0.0))})
    check(asm, "A", link=4)
    r = check(asm, "Y")
    c = asm
    assert c["cm:A@4:tip"].inputs == ("cm:A@4:slide@0", "cm:A@4:glide@1")
    assert c["cm:Y:tip"].verb == "transfer" and "without turning" in narrate(c["cm:Y:tip"])
    assert r.value(c)[1] == pytest.approx(0.0, abs=1e-15)


def test_block_point_taken_on_the_slider_translates():
    asm = assemble(offset_slider_crank(0.7, omega2=2.0))
    r = check(asm, "A", link=4)
    assert asm["cm:A@4:tip"].verb == "transfer"
    assert r.value(asm) == pytest.approx(
        velocity_by_components(asm, "C", scale=2.0).value(asm), abs=1e-15)


@pytest.mark.parametrize("path", [*sorted(bundled().values()), DATA / "stephenson-six-bar.toml",
                                  DATA / "watt-six-bar.toml"], ids=lambda p: Path(p).stem)
def test_every_point_of_the_examples_round_the_cycle(path):
    mech = load_mechanism(path)
    d = mech.drive
    checked = 0
    for deg in range(0, 360, 30):
        m = mech.with_drive(Drive(d.link, math.radians(deg), d.omega or 1.0, d.alpha))
        try:
            asm = assemble(m)
            solver.solve(m)
        except AssemblyError:
            continue  # the input cannot reach this angle
        except solver.SingularPosition:
            continue  # a dead point (the parallelogram folded flat): no velocities exist
        for point in m.point_names:  # one construction: later points reuse earlier ones
            check(asm, point, scale=1.0)
        checked += 1
    assert checked >= 3  # the Stephenson file's input only rocks through part of the circle


# ----------------------------------------------------------------------------- reuse

def test_second_call_reuses_what_the_first_drew():
    asm = assemble(coupler_four_bar(math.radians(40)))
    c = asm
    rb = velocity_by_components(asm, "B", scale=2.0)
    before = set(c.steps)
    rc = velocity_by_components(asm, "C", scale=2.0)
    assert set(rb.steps) <= set(rc.steps)  # V_B is reused, not drawn again
    new = set(c.steps) - before
    assert new and all(s.startswith("cm:C:") or s.startswith("cm:line:") or "@A-C" in s
                       or "@B-C" in s or s == rc.vector for s in new)
    again = velocity_by_components(asm, "C", scale=2.0)
    assert again.vector == rc.vector and len(c) == len(before) + len(new)
    check_record(asm, rc)


def test_point_first_drawn_on_the_way_gets_its_own_result_arrow():
    asm = assemble(crank_shaper(math.radians(30)))
    c = asm
    velocity_by_components(asm, "B", scale=1.0)
    assert c["cm:V:A@4"].role is Role.CONSTRUCTION
    r = check(asm, "A", link=4, scale=1.0)
    assert r.vector == "cm:V:A@4:result" and c[r.vector].role is Role.RESULT
    assert c[r.vector].output.vector == c["cm:V:A@4"].output.vector


def test_the_input_point_and_a_frame_point():
    asm = assemble(four_bar(1.0, omega2=2.0))
    r = check(asm, "A")
    assert asm[r.vector].output.vector == asm["V:A"].output.vector
    r = check(asm, "O4")
    assert r.value(asm) == (0.0, 0.0)


# ----------------------------------------------------------------------------- errors

def test_unreachable_point_is_named():
    # The block (link 3) turns with the lever, but by components alone only its one
    # point A is known: nothing fixes a second locus for O2 taken on it.
    asm = assemble(crank_shaper(0.3))
    with pytest.raises(TarsimError, match=r"^the component method cannot reach O2 as a point of "
                                          r"link 3: no link carrying it has two known velocities "
                                          r"or a known path$"):
        velocity_by_components(asm, "O2", scale=1.0, link=3)


def test_dead_point_is_one_line_naming_point_and_position():
    # Rocker toggle: A, B, O4 in line (AB 0.2 + O4B 0.3 = |AO4| 0.5 at θ2 = 0), so the
    # perpendicular to AB through the tip of V_B′ and the path of B (⟂ O4B) are parallel.
    m = Mechanism((Link(1, (("O2", (0.0, 0.0)), ("O4", (0.1, 0.5)))),
                   Link(2, (("O2", (0.0, 0.0)), ("A", (0.1, 0.0)))),
                   Link(3, (("A", (0.0, 0.0)), ("B", (0.2, 0.0)))),
                   Link(4, (("O4", (0.0, 0.0)), ("B", (0.3, 0.0))))),
                  Drive(2, 0.0, 1.0), branches={"B": "left"})
    asm = assemble(m)
    with pytest.raises(TarsimError,
                       match=r"^the component method cannot find V_B at θ2 = 0°: ") as e:
        velocity_by_components(asm, "B", scale=1.0)
    assert "\n" not in str(e.value) and "parallel" in str(e.value)
    with pytest.raises(solver.SingularPosition):
        solver.solve(m)


@pytest.mark.parametrize("kwargs, words", [
    ({"point": "Z", "scale": 1.0}, "there is no point Z"),
    ({"point": "B", "scale": 0.0}, "positive"),
    ({"point": "B", "scale": 1.0, "link": 9}, "there is no link 9"),
])
def test_bad_requests(kwargs, words):
    asm = assemble(four_bar(1.0, omega2=2.0))
    with pytest.raises(TarsimError, match=words):
        velocity_by_components(asm, **kwargs)


def test_a_second_call_at_another_scale_is_refused():
    asm = assemble(four_bar(1.0, omega2=2.0))
    velocity_by_components(asm, "B", scale=2.0)
    with pytest.raises(TarsimError, match="drawn at 2 m per m/s, not 1; use that scale"):
        velocity_by_components(asm, "B", scale=1.0)


# ----------------------------------------------------------------------------- properties

@settings(max_examples=40, deadline=None)
@given(theta=st.floats(-math.pi, math.pi), omega=st.floats(0.1, 50.0),
       sign=st.sampled_from([1.0, -1.0]), branch=st.sampled_from(["left", "right"]))
def test_four_bar_points_match_analytic_anywhere(theta, omega, sign, branch):
    m = coupler_four_bar(theta, omega2=sign * omega)
    m = Mechanism(m.links, m.drive, m.slides, {"B": branch}, m.units)
    for point in ("B", "C", "D"):
        check(assemble(m), point)


@settings(max_examples=40, deadline=None)
@given(theta=st.floats(-math.pi, math.pi), omega=st.floats(0.1, 50.0))
def test_slider_crank_piston_matches_analytic_anywhere(theta, omega):
    check(assemble(offset_slider_crank(theta, omega2=omega)), "C", scale=0.2)


def test_each_vector_of_a_figure_has_a_name_of_its_own():
    """V_E of the coupler plate takes V_A's component along AB (for V_B) and along AE: the
    second is V_A′(AE), and V_B's component along BE is V_B′(BE), not a second V_B′."""
    asm = assemble(load_mechanism(bundled()["hinkle-four-bar"]))
    speed = asm.mechanism.input_speed
    for point in ("B", "D", "E"):
        r = velocity_by_components(asm, point, scale=0.05 / speed)
        names = [asm[s].label for s in r.steps
                 if asm[s].verb == "join" and asm[s].label]
        assert len(names) == len(set(names)), names
    c = asm
    said = " ".join(narrate(s) for s in c)
    assert "V_E′(AE) = V_A′(AE)" in said and "V_E′(BE) = V_B′(BE)" in said
