"""Position by compass: parity with the analytic solver, and the course's numbers."""

import math
import re

import pytest

from tarsim.constructions.reference import solver
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.errors import AssemblyError
from tarsim.constructions.model import Drive
from tarsim.exercises.catalog import bundled
from tarsim.exercises.linkages.mechanism_file import load_mechanism, parse_mechanism
from tarsim.constructions.narration import narrate
from tests.common import four_bar_toml

BUNDLED = sorted(bundled())

def four_bar(ground=300, crank=100, coupler=250, rocker=200, angle=60, branch='B = "left"'):
    text = four_bar_toml(ground=ground, crank=crank, coupler=coupler, rocker=rocker,
                         angle=angle, branch=branch)
    return parse_mechanism(text, "four-bar.toml")


def at_angle(mech, deg):
    d = mech.drive
    return mech.with_drive(Drive(d.link, math.radians(deg), d.omega, d.alpha))


def worst_error(mech):
    """Largest joint distance between construction and analytic, over the mechanism's size."""
    asm = assemble(mech)
    kin = solver.solve(mech)
    names = mech.point_names
    size = max(math.dist(asm.xy(a), asm.xy(b)) for a in names for b in names)
    return max(math.dist(asm.xy(n), kin.points[n]) for n in names) / size, asm


@pytest.mark.parametrize("name", BUNDLED)
def test_bundled_example_matches_analytic(name):
    # Both sides solve the same well-conditioned triangles (cond. > 0.5 at the files'
    # positions); rounding of a few operations on O(1) numbers stays far below 1e-12.
    err, _ = worst_error(load_mechanism(bundled()[name]))
    assert err < 1e-12


@pytest.mark.parametrize("name", BUNDLED)
def test_bundled_example_matches_analytic_round_the_cycle(name):
    mech = load_mechanism(bundled()[name])
    checked = 0
    for deg in range(0, 360, 15):
        m = at_angle(mech, deg)
        try:
            err, asm = worst_error(m)
        except AssemblyError:
            continue  # the crank cannot reach this angle (a rocker input); both agree below
        worst_cond = min(s.conditioning for s in asm)
        # Error grows as eps / conditioning; 1e-12 leaves a margin of ~100 over that.
        assert err < 1e-12 / max(worst_cond, 1e-3), (deg, worst_cond)
        checked += 1
    assert checked >= 12


def test_crank_shaper_start_position_from_the_course_project():
    # 003 §2: at θ2 = 90°, O4A = 680 mm, O4B = 880 mm and the ram is at 0.
    asm = assemble(load_mechanism(bundled()["crank-shaper"]))
    o4, a, b = asm.xy("O4"), asm.xy("A"), asm.xy("B")
    assert math.dist(o4, a) == pytest.approx(0.680, rel=1e-15)
    assert math.dist(o4, b) == pytest.approx(0.880, rel=1e-15)
    assert b[0] == pytest.approx(0.0, abs=1e-15)


def test_crank_shaper_at_t_2_34_s():
    # 003 §7/§10: θ2 = −44.072° gives θ4 = 1.23854 rad, ram p = 303.643 mm, O4A = 396.483,
    # O4B = 930.913 mm. The document prints 6 significant digits, hence rel = 2e-6.
    mech = at_angle(load_mechanism(bundled()["crank-shaper"]), -44.072)
    asm = assemble(mech)
    o4, a, b = asm.xy("O4"), asm.xy("A"), asm.xy("B")
    assert b[0] == pytest.approx(0.303643, rel=2e-6)
    assert math.dist(o4, a) == pytest.approx(0.396483, rel=2e-6)
    assert math.dist(o4, b) == pytest.approx(0.930913, rel=2e-6)
    assert math.atan2(b[1] - o4[1], b[0] - o4[0]) == pytest.approx(1.23854, rel=2e-6)


def test_crank_shaper_closed_form_round_the_cycle():
    # 003 §3: tan θ4 = (r1 + r2 sin θ2)/(r2 cos θ2), p = (r1 + h) cot θ4.
    mech = load_mechanism(bundled()["crank-shaper"])
    r1, r2, h = 0.5, 0.18, 0.38
    for deg in range(0, 360, 10):
        t = math.radians(deg)
        th4 = math.atan2(r1 + r2 * math.sin(t), r2 * math.cos(t))
        b = assemble(at_angle(mech, deg)).xy("B")
        assert b[0] == pytest.approx((r1 + h) / math.tan(th4), abs=1e-15 * 1e3)


def test_offset_slider_crank_closed_form():
    # Slider on y = e: x = R cos θ + sqrt(L² − (e − R sin θ)²), the forward cut.
    mech = load_mechanism(bundled()["offset-slider-crank"])
    R, L, e = 0.30, 0.70, 0.20
    for deg in range(0, 360, 15):
        t = math.radians(deg)
        x = R * math.cos(t) + math.sqrt(L * L - (e - R * math.sin(t)) ** 2)
        bx, by = assemble(at_angle(mech, deg)).xy("B")
        assert bx == pytest.approx(x, rel=1e-14)
        assert by == pytest.approx(e, rel=1e-15)


def test_p37_lever_is_tangent_to_the_crank_circle_at_its_limit():
    # Notes §3.4: at the limit positions O2A' ⟂ O4A', i.e. cos(β/2) = O2A/O2O4.
    mech = load_mechanism(bundled()["slotted-lever-p37"])
    half_return = math.degrees(math.acos(6 / 16))
    # The crank angle (from +x) where O2A ⟂ O4A, with O2 above O4 on the y axis.
    limit = -90 + half_return
    asm = assemble(at_angle(mech, limit))
    o2, o4, a = asm.xy("O2"), asm.xy("O4"), asm.xy("A")
    dot = (a[0] - o2[0]) * (a[0] - o4[0]) + (a[1] - o2[1]) * (a[1] - o4[1])
    assert dot == pytest.approx(0.0, abs=1e-15)
    assert math.dist(o4, a) == pytest.approx(math.sqrt(16**2 - 6**2) / 100, rel=1e-14)


def test_branches_left_right_and_near_point():
    left = assemble(four_bar()).xy("B")
    right = assemble(four_bar(branch='B = "right"')).xy("B")
    near = assemble(four_bar(branch="B = [150, -150]")).xy("B")
    # peers.md §4: open B = (273.679454, 198.260508), crossed B = (156.677688, −139.494498)
    # mm, printed to 1e-6 mm: half a printed unit is 5e-10 m.
    assert left == pytest.approx((0.273679454, 0.198260508), abs=5e-10)
    assert right == pytest.approx((0.156677688, -0.139494498), abs=5e-10)
    assert near == right


def test_missing_branch_names_the_point_and_choices():
    with pytest.raises(AssemblyError, match=r'point B has two positions .*B = "left" or "right"'):
        assemble(four_bar(branch=None))


def test_unreachable_position_names_the_dyad():
    mech = four_bar(ground=510, angle=180)
    with pytest.raises(AssemblyError) as e:
        assemble(mech)
    assert str(e.value) == ("link 3 (AB = 250 mm) cannot reach the circle of B about O4 at "
                            "θ2 = 180°: |O4A| = 610 mm > 250 mm + 200 mm")


def test_triad_is_refused_with_a_clear_error():
    # A crank driving a class-III Assur group (a ternary link on three binary links):
    # DOF = 3(6 − 1) − 2·7 = 1, but no dyad locates any of X, Y, Z.
    text = """
[frame]
O2 = [0, 0]
P1 = [200, 0]
P2 = [100, 200]
[[link]]
number = 2
points = ["O2", "Q"]
lengths = { O2Q = 40 }
[[link]]
number = 3
points = ["X", "Y", "Z"]
lengths = { XY = 80, XZ = 70, YZ = 60 }
sides = { Z = "left" }
[[link]]
number = 4
points = ["P1", "X"]
lengths = { P1X = 120 }
[[link]]
number = 5
points = ["P2", "Y"]
lengths = { P2Y = 110 }
[[link]]
number = 6
points = ["Q", "Z"]
lengths = { QZ = 90 }
[input]
link = 2
angle = 30
"""
    mech = parse_mechanism(text, "triad.toml")
    assert mech.mobility()[0] == 1
    with pytest.raises(AssemblyError, match=r"needs a triad"):
        assemble(mech)


def test_every_step_has_a_sentence_or_is_a_bare_line():
    asm = assemble(load_mechanism(bundled()["slotted-lever-p37"]))
    results = [s for s in asm if s.role == "result"]
    assert {s.label for s in results} == {"A", "B", "C"}
    for s in results:
        assert narrate(s) and re.search(r"\b" + s.label + r"\b", narrate(s))


@pytest.mark.parametrize("name", ["watt-six-bar", "stephenson-six-bar"])
def test_six_bars_assemble_dyad_by_dyad(name):
    from pathlib import Path
    mech = load_mechanism(Path(__file__).parent / "data" / f"{name}.toml")
    assert mech.mobility() == (1, 6, 7, 0)
    for deg in range(0, 360, 30):
        try:
            err, asm = worst_error(at_angle(mech, deg))
        except AssemblyError:
            continue
        assert err < 1e-12 / max(min(s.conditioning for s in asm), 1e-3)
    err, asm = worst_error(mech)
    assert err < 1e-12
    # Each joint is found by its own recorded act; the coupler point of the plate by two arcs.
    verbs = {s.label: s.verb for s in asm if s.role == "result"}
    assert set(verbs) == {"A", "B", "C", "D"}


# ----- the dyad rules are a registry -----------------------------------------------------------
def test_the_dyad_rules_are_tried_in_their_registered_order():
    from tarsim.constructions.linkages.dyad_rules import DYAD_RULES
    names = [r.name for r in sorted(DYAD_RULES.values(), key=lambda r: r.order)]
    assert names == ["a point of a drawn link", "a wheel rolling without slip",
                     "a wheel rolling round a circle without slip",
                     "a slot swung through its block (RPR)", "the slot of a translating block",
                     "two guides (RPP)", "an arc and a guide (RRP)", "two arcs (RRR)"]


def test_a_new_dyad_rule_plugs_into_the_registry(monkeypatch):
    """A rule registered under a new name is consulted by the walk, in its order."""
    from tarsim.constructions.linkages import assembly as asm_module
    from tarsim.constructions.linkages import joint_rules
    from tarsim.constructions.linkages.dyad_rules import DyadRule
    seen = []

    def note(assembler) -> bool:
        seen.append(sorted(assembler.known))
        return False                       # locates nothing: the walk goes on as before

    rules = dict(joint_rules.DYAD_RULES)
    rules["a rule that looks first"] = DyadRule("a rule that looks first", -1, note)
    monkeypatch.setattr(joint_rules, "DYAD_RULES", rules)
    asm = asm_module.assemble(four_bar(math.radians(60)))
    assert seen and seen[0] == ["A", "O2", "O4"]          # asked before B was found
    assert asm.xy("B") == assemble(four_bar(math.radians(60))).xy("B")
