"""Tests of constructions/linkages/centres.py: every instant centre against the analytic reference.

The reference is constructions/reference/centres.py, which locates ``I_ij`` where the
velocity fields of links i and j (from the vector-loop solver) agree; it shares no code
with the construction. A centre's tolerance is ``tolerance(conditioning)``, the first-order
error ``64 eps / conditioning`` of the recorded acts (floor 1e-9), measured relative to
``max(size, |I_ij|)`` so a far centre is judged against its own distance. Golden numbers
cite their seed; a printed number is asserted to half a unit in its last printed digit.
"""

import dataclasses
import math
from itertools import combinations
from pathlib import Path

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from tarsim.constructions import geometry as g
from tarsim.constructions.reference.solver import Kinematics, SingularPosition, solve
from tarsim.constructions.checks import tolerance
from tarsim.constructions.reference.centres import (AnalyticCentre, centre_error, instant_centre,
                                                    mechanism_size)
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.linkages.assembly_record import Assembly
from tarsim.constructions.narration import narrate
from tarsim.constructions.linkages.centres import ILL_CONDITIONED, Centres, omega_ratio
from tarsim.constructions.errors import DegenerateInput, TarsimError
from tarsim.constructions.linkages.kennedy import locate_centres
from tarsim.constructions.joints import SlideKind
from tarsim.constructions.model import Drive, Link, Mechanism
from tarsim.constructions.units import Units
from tarsim.constructions.record import slice as backward_slice
from tarsim.exercises.linkages.mechanism_file import load_mechanism, parse_mechanism
from tests.common import (crank_shaper, four_bar, four_bar_toml, offset_slider_crank, scotch_yoke,
                          slotted_lever_p37)

D = math.radians
DATA = Path(__file__).parent / "data"
CIRCULAR_CAM = DATA / "circular-cam.toml"
OFFSET_CAM = DATA / "offset-cam.toml"


def _warnings(s) -> list[str]:
    """The centres' warnings as the notes print them."""
    return [narrate(w) for w in s.cs.warnings()]


def half_digit(printed: str) -> float:
    """Half a unit in the last digit of a printed decimal: the rounding bound."""
    decimals = len(printed.split(".")[1]) if "." in printed else 0
    return 0.5 * 10.0 ** -decimals


# ----------------------------------------------------------------------------- helpers

@dataclasses.dataclass
class Solved:
    """One position: the construction, its centres and the analytic solution."""

    mech: Mechanism
    asm: Assembly
    cs: Centres
    kin: Kinematics
    size: float


def solved(mech: Mechanism) -> Solved:
    kin = solve(mech)
    asm = assemble(mech)
    return Solved(mech, asm, locate_centres(asm), kin, mechanism_size(kin))


def at(mech: Mechanism, deg: float, omega: float | None = None) -> Mechanism:
    """The same mechanism at input angle ``deg``, turning (ω = 10 unless the file gives one)."""
    w = omega if omega is not None else (mech.drive.omega or 10.0)
    return mech.with_drive(Drive(mech.drive.link, D(deg), w, 0.0))


def joint_centre(s: Solved, i: int, j: int) -> AnalyticCentre | None:
    """The centre a joint fixes, from the solver: a shared pin, or the normal to a block's guide."""
    for name in s.mech.point_names:
        if {i, j} <= set(s.mech.links_at(name)):
            return AnalyticCentre(s.kin.points[name], None)
    for slide, rate in zip(s.mech.slides, s.kin.slide_rates):
        if slide.kind is SlideKind.BLOCK and {slide.link, slide.guide_link} == {i, j}:
            dx, dy = rate.direction
            return AnalyticCentre(None, g.Point.at_infinity(-dy, dx).direction)
    return None


def reference(s: Solved, i: int, j: int) -> AnalyticCentre:
    """The analytic ``I_ij``; for links that move together, the joint that couples them.

    When the relative velocity of two links vanishes everywhere (ω3 = ω4 of a four-bar at
    the position where I13 falls on I14, a block with no sliding speed) every point is a
    centre of their relative motion, and only the joint itself (the pin, or the normal to
    the guide) says where the construction must put it.
    """
    try:
        return instant_centre(s.kin, i, j)
    except DegenerateInput:
        joint = joint_centre(s, i, j)
        if joint is None:
            raise
        return joint


def effective_conditioning(s: Solved, pair: tuple[int, int]) -> float:
    """The conditioning that bounds the centre's error as the check measures it.

    This is the step's compounded conditioning, except for a direction cut from two
    parallel lines. The kernel gives that cut the lines' separation over their distance
    from the origin (how well it would fix a point), but a direction is compared by
    angle, and its angle is the lines' own: as well conditioned as the lines are.
    """
    step = s.asm[s.cs.centre(*pair).ref]
    if step.output.is_at_infinity and step.verb == "intersect_lines":
        return min(s.asm[r].conditioning for r in step.inputs)
    return step.conditioning


def label(pair) -> str:
    return f"I{pair[0]}{pair[1]}"


def centre_failures(s: Solved) -> list[str]:
    """Every centre that misses its references, or whose conditioning makes the check vacuous.

    A primary is held to the joint the solver put it at (pin position, guide normal) and,
    unless the two links move together, to the velocity fields as well; a secondary to the
    fields. Each allows ``tolerance(conditioning)`` for the construction plus the
    reference's own ``rounding``.
    """
    bad = []
    for pair in sorted(s.cs.found):
        rule = s.cs.centre(*pair).rule
        cond = effective_conditioning(s, pair)
        if not cond > 0.0:
            bad.append(f"{label(pair)} ({rule}) carries conditioning {cond}, so no error "
                       f"bound follows from it")
            continue
        found, refs = s.cs.point(*pair), []
        joint = joint_centre(s, *pair)
        if joint is not None:
            refs.append(("joint", joint))
        try:
            refs.append(("velocity fields", instant_centre(s.kin, *pair)))
        except DegenerateInput:
            if joint is None:
                bad.append(f"{label(pair)} ({rule}): links move together and no joint fixes it")
        for name, ref in refs:
            err, tol = centre_error(found, ref, s.size), tolerance(cond) + ref.rounding
            if not err <= tol:
                bad.append(f"{label(pair)} ({rule}): got {found}, expected {ref} ({name}), "
                           f"rel. error {err:.2e} > {tol:.2e} (cond {cond:.2e})")
    return bad


def omega_tolerance(s: Solved, d: int, j: int) -> float:
    """Bound on |ω_j from the centres − ω_j analytic|.

    ω_j = ω_d·|I_dj I_1d| / |I_dj I_1j|. A relative position error ``tol`` (of
    ``far = max(size, |I|)``) in each centre moves each length by at most 2·tol·far, so
    the ratio moves by 2·tol·far·(1 + |ω_j/ω_d|)/|I_dj I_1j|. With I_1j or I_dj at infinity
    the ratio is exactly 0 or 1 and only the floor remains.
    """
    pairs = [tuple(sorted((d, j))), (1, d), (1, j)]
    tol = tolerance(min(effective_conditioning(s, p) for p in pairs))
    wd, wj = s.kin.omegas[d], s.kin.omegas[j]
    gain = 1.0
    p_dj, p_1j = reference(s, d, j), reference(s, 1, j)
    if not (p_dj.is_at_infinity or p_1j.is_at_infinity):
        spread = math.dist(p_dj.point, p_1j.point)
        far = max(s.size, math.hypot(*p_dj.point), math.hypot(*p_1j.point))
        gain = 2.0 * far / spread
    return tol * (abs(wd) + abs(wj)) * gain


def omega_failures(s: Solved) -> list[str]:
    d = s.mech.drive.link
    wd = s.kin.omegas[d]
    bad = []
    for j in s.mech.numbers:
        if j in (1, d):
            continue
        got = omega_ratio(s.cs, d, j) * wd
        want, tol = s.kin.omegas[j], omega_tolerance(s, d, j)
        if not abs(got - want) <= tol:
            bad.append(f"ω{j}: {got!r} from the centres, {want!r} analytic (tol {tol:.1e})")
    return bad


def check_all(s: Solved) -> None:
    n = len(s.mech.links)
    assert len(s.cs.found) == n * (n - 1) // 2
    assert sorted(s.cs.found) == list(combinations(sorted(s.mech.numbers), 2))
    assert centre_failures(s) == []
    assert omega_failures(s) == []


# ----------------------------------------------------------------------------- 1. the reference

def test_reference_centre_of_a_crank_is_its_pivot_and_of_the_coupler_is_kennedys():
    # A four-bar solved by vector loops: I12 is the pivot O2, and I13 lies on both O2A and
    # O4B (Kennedy), which the reference must satisfy without being told.
    kin = solve(four_bar(D(60), omega2=10.0))
    assert instant_centre(kin, 1, 2).point == pytest.approx((0.0, 0.0), abs=1e-15)
    assert instant_centre(kin, 2, 1).point == pytest.approx((0.0, 0.0), abs=1e-15)
    p = instant_centre(kin, 1, 3).point
    a, b, o4 = kin.points["A"], kin.points["B"], kin.points["O4"]
    # Cross products of unit-order vectors: collinear to rounding.
    assert (a[0] * p[1] - a[1] * p[0]) / math.hypot(*p) == pytest.approx(0.0, abs=1e-14)
    u, v = (b[0] - o4[0], b[1] - o4[1]), (p[0] - o4[0], p[1] - o4[1])
    assert (u[0] * v[1] - u[1] * v[0]) / math.hypot(*v) == pytest.approx(0.0, abs=1e-14)


def test_reference_refuses_links_that_move_together_and_a_still_input():
    # Four-bar at θ2 = 0: I13 falls on I14 = O4, so ω3 = ω4 and v3 = v4 at B: links 3 and 4
    # move together and I34 is every point.
    kin = solve(four_bar(0.0, omega2=10.0))
    with pytest.raises(DegenerateInput) as info:
        instant_centre(kin, 3, 4)
    assert "\n" not in str(info.value) and "3" in str(info.value)
    with pytest.raises(DegenerateInput, match="ω"):
        instant_centre(solve(four_bar(D(60))), 1, 3)   # ω2 = 0: nothing moves


def test_reference_puts_a_translating_link_at_infinity():
    # The slider of an offset slider-crank translates along x: I14 is at infinity along y.
    ref = instant_centre(solve(offset_slider_crank(D(60), omega2=10.0)), 1, 4)
    assert ref.is_at_infinity and ref.direction == (0.0, 1.0)


def test_centre_error_compares_a_far_point_with_a_direction_and_a_near_one_never():
    ref = AnalyticCentre(None, (0.0, 1.0))
    assert centre_error(g.Point(1.0, 1e8), ref, 1.0) == pytest.approx(1e-8, rel=1e-12)
    assert centre_error(g.Point(1.0, 1e3), ref, 1.0) == math.inf
    assert tolerance(1.0) == 1e-9 and tolerance(1e-10) == pytest.approx(64 * 2.22e-6, rel=1e-3)


# ----------------------------------------------------------------------------- 2. parity sweep

EVERY_30 = tuple(range(0, 360, 30))
WATT = DATA / "watt-six-bar.toml"
STEPHENSON = DATA / "stephenson-six-bar.toml"


def _file(path):
    return lambda deg: at(load_mechanism(path), deg)


SWEEP = [
    ("four-bar", lambda deg: four_bar(D(deg), omega2=10.0), EVERY_30),
    ("four-bar crossed", lambda deg: four_bar(D(deg), omega2=10.0, branch="right"), EVERY_30),
    ("four-bar file", lambda deg: at(parse_mechanism(four_bar_toml()), deg), EVERY_30),
    ("offset slider-crank", lambda deg: offset_slider_crank(D(deg), omega2=10.0), EVERY_30),
    ("crank-shaper", lambda deg: crank_shaper(D(deg)), EVERY_30),
    ("P-37", lambda deg: slotted_lever_p37(D(deg)), EVERY_30),
    ("Watt six-bar", _file(WATT), EVERY_30),
    # The Stephenson dyad 5-6 closes only for θ2 in about [−10°, 85°] (tried every 5°).
    ("Stephenson six-bar", _file(STEPHENSON), (-10, 0, 15, 30, 45, 60, 75, 85)),
]


@pytest.mark.parametrize("build, deg", [pytest.param(b, d, id=f"{n}-{d}")
                                        for n, b, angles in SWEEP for d in angles])
def test_every_centre_and_omega_matches_the_analytic_reference(build, deg):
    check_all(solved(build(deg)))


@pytest.mark.parametrize("deg", (30, 120, 250))
def test_scotch_yoke_centres(deg):
    s = solved(scotch_yoke(D(deg), omega2=10.0))
    check_all(s)
    # Both the block and the yoke translate: I13 and I14 are at infinity, ω3 = ω4 = 0.
    assert s.cs.point(1, 4).is_at_infinity and s.cs.point(1, 3).is_at_infinity


# ----------------------------------------------------------------------------- 3. four-bar

def test_four_bar_centres_in_the_notes_order():
    # 000-part1 §3.8 (l.811–830): 4 pins are primary; I13 from Δ123 and Δ143 first, then
    # I24 from Δ214 and Δ234.
    s = solved(four_bar(D(60), omega2=10.0))
    assert sorted(label(c.pair) for c in s.cs.primaries) == ["I12", "I14", "I23", "I34"]
    assert {c.rule for c in s.cs.primaries} == {"pin"}
    assert [(label(c.pair), c.order, set(c.triangles)) for c in s.cs.secondaries] == [
        ("I13", 1, {2, 4}), ("I24", 2, {1, 3})]
    assert _warnings(s) == []


def test_four_bar_seed_004_section_11():
    # 004 §11: O2 = (0, 0), O4 = (100, 0) mm, crank 40, coupler 120, rocker 80, θ2 = 60°,
    # ω2 = 10 rad/s, open configuration. Printed to 0.001 mm and 1e-5 rad/s, so each is
    # checked to half a unit in its last digit (the construction's own error is ~1e-12 of
    # that, conditioning ≥ 0.03 here).
    s = solved(four_bar(D(60), o4=(0.1, 0.0), crank=0.04, coupler=0.12, rocker=0.08,
                        omega2=10.0, branch="left"))
    mm = half_digit("133.881") * 1e-3
    assert s.asm.xy("B") == pytest.approx((0.133881, 0.072471), abs=mm)
    assert s.cs.point(1, 3).xy == pytest.approx((0.525623, 0.910406), abs=mm)
    assert s.cs.point(2, 4).xy == pytest.approx((-0.084280, 0.0), abs=mm)
    w = half_digit("4.57349")
    assert omega_ratio(s.cs, 2, 4) * 10.0 == pytest.approx(4.57349, abs=w)
    w3 = omega_ratio(s.cs, 2, 3) * 10.0
    assert abs(w3) == pytest.approx(0.39555, abs=w)
    # The notes' rule (000-part1 §3.8): I23 lies between I12 and I13, so ω3 opposes ω2.
    assert w3 < 0.0
    check_all(s)


def test_four_bar_peer_benchmark_omegas():
    # peers.md §4 (open branch, θ2 = 60°, ω2 = +10): printed to 1e-12; allow half that unit
    # plus the construction's first-order error, 64 eps/0.3 · |ω| ≈ 5e-13.
    s = solved(four_bar(D(60), omega2=10.0))
    tol = half_digit("2.578464796446") + 64 * 2.2e-16 / 0.3 * 3.0
    assert omega_ratio(s.cs, 2, 3) * 10.0 == pytest.approx(-2.578464796446, abs=tol)
    assert omega_ratio(s.cs, 2, 4) * 10.0 == pytest.approx(2.915957761501, abs=tol)


# The position where crank and rocker are parallel (sin(θ4 − θ2) = 0, found by bisection on
# the analytic solution): I13 is at infinity there and far away nearby.
PARALLEL_CRANK_ROCKER = 2.2459278597319274


def test_the_parallel_position_is_where_crank_and_rocker_align():
    kin = solve(four_bar(PARALLEL_CRANK_ROCKER, omega2=10.0))
    assert math.sin(kin.angles[4] - PARALLEL_CRANK_ROCKER) == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("delta", [1e-3, 1e-5, -1e-5, 1e-7])
def test_a_far_centre_is_reported_and_still_within_its_tolerance(delta):
    s = solved(four_bar(PARALLEL_CRANK_ROCKER + delta, omega2=10.0))
    cond = s.cs.conditioning(1, 3)
    # The crossing sine is about |δ|·(O2A/|I14 I34|)-ish: well below the reporting threshold.
    assert cond < ILL_CONDITIONED
    p = s.cs.point(1, 3)
    assert not p.is_at_infinity and math.hypot(*p.xy) > 100 * s.size
    ref = reference(s, 1, 3)
    # Both sides lose digits here: the construction by its crossing, the reference by
    # dividing by the small ω3 (ref.rounding is of the same order as tolerance(cond)).
    assert ref.rounding < 10 * tolerance(cond)
    assert centre_error(p, ref, s.size) <= tolerance(cond) + ref.rounding
    assert any(w.startswith("I13 is ill-conditioned") for w in _warnings(s))
    assert omega_failures(s) == []


def test_exactly_parallel_crank_and_rocker_put_i13_at_infinity_unreported():
    s = solved(four_bar(PARALLEL_CRANK_ROCKER, omega2=10.0))
    assert centre_failures(s) == []
    # ω3 = 0: the coupler translates (its centre is at infinity). The analytic ω3 is 0 to
    # rounding (|ω3| ≲ 1e-14·ω2).
    assert omega_ratio(s.cs, 2, 3) * 10.0 == pytest.approx(s.kin.omegas[3], abs=1e-13)
    assert not any("I13" in w for w in _warnings(s))


@pytest.mark.parametrize("deg, branch", [(60, "left"), (135, "left"), (250, "right")])
def test_parallelogram_four_bar_has_two_centres_at_infinity(deg, branch):
    # Ground = coupler = 0.3, crank = rocker = 0.1; the branch that makes a parallelogram.
    s = solved(four_bar(D(deg), crank=0.1, coupler=0.3, rocker=0.1, omega2=10.0, branch=branch))
    (ax, ay), (bx, by) = s.asm.xy("A"), s.asm.xy("B")
    assert (bx - ax, by - ay) == pytest.approx((0.3, 0.0), abs=1e-15)
    for pair, direction in [((1, 3), (math.cos(D(deg)), math.sin(D(deg)))),
                            ((2, 4), (1.0, 0.0))]:
        p = s.cs.point(*pair)
        assert p.is_at_infinity
        ref = reference(s, *pair)
        assert ref.is_at_infinity   # the analytic reference agrees it is a direction
        assert centre_error(p, ref, s.size) <= (tolerance(effective_conditioning(s, pair))
                                                + ref.rounding)
        # ...and it is the crank's direction (I13) and the ground's (I24).
        assert centre_error(p, AnalyticCentre(None, g.Point.at_infinity(*direction).direction),
                            s.size) <= 1e-15
    assert omega_ratio(s.cs, 2, 3) == 0.0      # the coupler translates
    assert omega_ratio(s.cs, 2, 4) == 1.0      # the rocker turns with the crank
    assert _warnings(s) == []
    check_all(s)


# ----------------------------------------------------------------------------- 4. slider-crank

def test_offset_slider_crank_block_centre_is_square_to_the_guide():
    # 000-part1 §3.8 (l.836): I14 at infinity, perpendicular to the slide; ω4 = 0 (l.866).
    s = solved(offset_slider_crank(D(60), omega2=10.0))
    c = s.cs.centre(1, 4)
    assert c.rule == "block" and s.cs.point(1, 4).direction == (0.0, 1.0)
    assert omega_ratio(s.cs, 2, 4) == 0.0
    # I13 = (line I12–I23) ∩ (line through I34 ⟂ slide); I24 on the line through I12 ⟂ slide.
    assert s.cs.point(1, 3).xy[0] == pytest.approx(s.asm.xy("C")[0], abs=1e-15)
    assert s.cs.point(2, 4).xy[0] == pytest.approx(0.0, abs=1e-15)
    check_all(s)


@pytest.mark.parametrize("deg, sign", [(0, -1.0), (180, 1.0)])
def test_in_line_slider_crank_at_dead_centre_has_coincident_centres(deg, sign):
    # 000-part1 §3.8 Question 1: at dead centre I13 ≡ I34 and I24 ≡ I12. The slider stops,
    # but the crank drives, so the analytic solve is regular and ω3 = ∓(r/L)·ω2.
    mech = offset_slider_crank(D(deg), offset=0.0, omega2=10.0)
    s = solved(mech)   # neither the construction nor the solver raises here
    same = 1e-12 * s.size
    assert math.dist(s.cs.point(1, 3).xy, s.cs.point(3, 4).xy) <= same
    assert math.dist(s.cs.point(2, 4).xy, s.cs.point(1, 2).xy) <= same
    w3 = sign * 0.30 / 0.70 * 10.0
    assert s.kin.omegas[3] == pytest.approx(w3, rel=1e-12)
    assert omega_ratio(s.cs, 2, 3) * 10.0 == pytest.approx(w3, rel=1e-12)
    assert omega_ratio(s.cs, 2, 4) == 0.0
    check_all(s)


# ----------------------------------------------------------------------------- 5. crank-shaper

def test_crank_shaper_at_the_seed_position():
    # 003 §2: t = 2.34 s with θ2 = π/2 − t (ω2 = −1): ω4 = +0.19212 rad/s (printed to 1e-5).
    s = solved(crank_shaper(math.pi / 2 - 2.34))
    assert len(s.cs.found) == 10
    assert omega_ratio(s.cs, 2, 4) * -1.0 == pytest.approx(0.19212, abs=half_digit("0.19212"))
    for pair in [(1, 5), (3, 4)]:
        assert s.cs.centre(*pair).rule == "block" and s.cs.point(*pair).is_at_infinity
    assert s.cs.point(1, 5).direction == (0.0, 1.0)   # the ram slides along x
    check_all(s)


def test_crank_shaper_with_the_crank_along_the_lever():
    # θ2 = 90°: O4, O2 and A are on the y-axis, the lever is vertical and every finite
    # centre lies on that line, so all Kennedy lines for I25 coincide.
    s = solved(crank_shaper(D(90)))
    for pair in s.cs.found:
        p = s.cs.point(*pair)
        if not p.is_at_infinity:
            assert p.xy[0] == pytest.approx(0.0, abs=1e-15)
    check_all(s)


# ----------------------------------------------------------------------------- 6. multiple joint

# 000-part1 §3.8 Homework 1: a four-bar 1-2-3-4 whose coupler-rocker pin P also carries
# link 5; the dyad 5-6 runs to a ground pivot O6. Dimensions are ours.
MULTIPLE_JOINT = """\
name = "Six-bar with a multiple joint"
[frame]
O2 = [0, 0]
O4 = [300, 0]
O6 = [420, 120]
[[link]]
number = 2
points = ["O2", "A"]
lengths = { O2A = 100 }
[[link]]
number = 3
points = ["A", "P"]
lengths = { AP = 250 }
[[link]]
number = 4
points = ["O4", "P"]
lengths = { O4P = 200 }
[[link]]
number = 5
points = ["P", "Q"]
lengths = { PQ = 180 }
[[link]]
number = 6
points = ["O6", "Q"]
lengths = { O6Q = 150 }
[input]
link = 2
angle = 60
omega = 10
[assembly]
P = "left"
Q = "left"
"""


@pytest.mark.parametrize("deg", EVERY_30)
def test_multiple_joint_six_bar(deg):
    s = solved(at(parse_mechanism(MULTIPLE_JOINT, "multiple.toml"), deg))
    assert s.mech.mobility() == (1, 6, 7, 0)
    # The notes: 8 primary (I34 = I35 = I45 at P), 7 secondary.
    assert len(s.cs.primaries) == 8 and len(s.cs.secondaries) == 7
    p = s.asm.xy("P")
    assert s.cs.point(3, 4).xy == p and s.cs.point(3, 5).xy == p and s.cs.point(4, 5).xy == p
    # Δ235 and Δ245 both give the line I23–P: the notes switch to Δ215.
    tri = s.cs.centre(2, 5).triangles
    assert set(tri) != {3, 4} and 1 in tri
    check_all(s)


# ----------------------------------------------------------------------------- 7. cams

@pytest.mark.skipif(not CIRCULAR_CAM.exists(), reason="the cam file is not there yet")
@pytest.mark.parametrize("deg", [0, 30, 100, 200, 300])
def test_circular_cam_with_flat_follower(deg):
    s = solved(at(load_mechanism(CIRCULAR_CAM), deg))
    check_all(s)
    # The follower translates (I13 at infinity, ⟂ its vertical guide); I23 is on the common
    # normal through the circle's centre C and on I12–I13: directly below C on the x axis,
    # since the follower's speed is ω2·x_C.
    assert s.cs.point(1, 3).direction == pytest.approx((1.0, 0.0), abs=1e-15)
    cx, _ = s.kin.points["C"]
    assert s.cs.point(2, 3).xy == pytest.approx((cx, 0.0), abs=1e-15)
    assert None in s.cs.centre(2, 3).triangles   # one of its lines is the common normal


@pytest.mark.skipif(not OFFSET_CAM.exists(), reason="the cam file is not there yet")
@pytest.mark.parametrize("deg", [0, 30, 100, 200, 300])
def test_offset_cam_with_tilted_face(deg):
    s = solved(at(load_mechanism(OFFSET_CAM), deg))
    check_all(s)
    # The tilted face turns the common normal, but I23 stays on I12–I13, the x axis.
    assert s.cs.point(2, 3).xy[1] == pytest.approx(0.0, abs=1e-15)
    assert None in s.cs.centre(2, 3).triangles


# ----------------------------------------------------------------------------- 8. refusals

def test_two_degrees_of_freedom_are_refused_naming_the_count():
    # A five-bar O2-A-B-C-O5 is drawn through a one-DOF helper (a sixth link AC pins its
    # shape), then asked for its centres without that link: 3(5 − 1) − 2·5 = 2.
    frame = Link(1, (("O2", (0.0, 0.0)), ("O5", (0.4, 0.0))))
    crank = Link(2, (("O2", (0.0, 0.0)), ("A", (0.1, 0.0))))
    l3 = Link(3, (("A", (0.0, 0.0)), ("B", (0.25, 0.0))))
    l4 = Link(4, (("B", (0.0, 0.0)), ("C", (0.25, 0.0))))
    l5 = Link(5, (("O5", (0.0, 0.0)), ("C", (0.2, 0.0))))
    helper = Link(6, (("A", (0.0, 0.0)), ("C", (0.3, 0.0))))
    drive = Drive(2, D(60), 10.0)
    rigid = Mechanism((frame, crank, l3, l4, l5, helper), drive,
                      branches={"B": "left", "C": "left"}, units=Units("m"))
    five = Mechanism((frame, crank, l3, l4, l5), drive, units=Units("m"))
    assert rigid.mobility()[0] == 1 and five.mobility()[0] == 2
    asm = dataclasses.replace(assemble(rigid), mechanism=five)
    with pytest.raises(TarsimError) as info:
        locate_centres(asm)
    message = str(info.value)
    assert "\n" not in message and " 2 " in f" {message} "


# ----------------------------------------------------------------------------- 9. conditioning

@pytest.mark.parametrize("deg", [90, 270])
def test_a_centre_at_infinity_does_not_zero_the_conditioning_downstream(deg):
    # P-37 at θ2 = 90° (and 270°): link 5 translates for an instant, so I15 is cut from two
    # parallel Kennedy lines and is a direction. Lines through a direction are as well drawn
    # as lines through a point; the centres found from them (I35, I36, I46, I25, I26) are
    # finite, well crossed and correct to 1e-16, so they must carry a positive conditioning
    # and no "ill-conditioned" warning. (Until the kernel gave parallel lines their
    # separation as conditioning, a 0 here made every downstream tolerance infinite.)
    s = solved(slotted_lever_p37(D(deg)))
    assert s.cs.point(1, 5).is_at_infinity
    zero = [label(p) for p in s.cs.found
            if not s.cs.point(*p).is_at_infinity and s.cs.conditioning(*p) == 0.0]
    assert zero == []
    assert _warnings(s) == []


@pytest.mark.parametrize("build", [_file(WATT), lambda deg: at(parse_mechanism(MULTIPLE_JOINT),
                                                                deg)], ids=["watt", "multiple"])
@pytest.mark.parametrize("deg", [60, 90, 270])
def test_warnings_name_exactly_the_ill_conditioned_finite_centres(build, deg):
    s = solved(build(deg))
    named = {w.split()[0] for w in _warnings(s)}
    expected = {c.label for c in s.cs.secondaries
                if not s.cs.point(*c.pair).is_at_infinity
                and s.cs.conditioning(*c.pair) < ILL_CONDITIONED}
    assert named == expected
    assert all("\n" not in w for w in _warnings(s))


# ----------------------------------------------------------------------------- 10. property

@st.composite
def crank_rockers(draw):
    """A Grashof crank-rocker (the crank strictly shortest, margin ≥ 2 % of the ground),
    anywhere in the plane, at any crank angle, on either branch."""
    ground = draw(st.floats(0.05, 2.0))
    crank = ground * draw(st.floats(0.05, 0.45))
    coupler = ground * draw(st.floats(0.5, 1.6))
    rocker = ground * draw(st.floats(0.5, 1.6))
    lengths = sorted([ground, crank, coupler, rocker])
    assume(lengths[0] == crank and lengths[1] > crank)
    assume(lengths[0] + lengths[3] <= lengths[1] + lengths[2] - 0.02 * ground)
    phi = draw(st.floats(-math.pi, math.pi))
    o2 = (draw(st.floats(-1.0, 1.0)), draw(st.floats(-1.0, 1.0)))
    o4 = (o2[0] + ground * math.cos(phi), o2[1] + ground * math.sin(phi))
    theta = draw(st.floats(-math.pi, math.pi))
    branch = draw(st.sampled_from(["left", "right"]))
    return four_bar(theta, o2=o2, o4=o4, crank=crank, coupler=coupler, rocker=rocker,
                    omega2=draw(st.sampled_from([-7.0, 1.0, 10.0])), branch=branch)


@settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(crank_rockers())
def test_random_crank_rockers_match_the_reference(mech):
    try:
        s = solved(mech)
    except SingularPosition:
        assume(False)
    check_all(s)


def test_when_every_kennedy_line_coincides_rule_2_draws_the_velocity_profiles():
    """Crank-shaper at θ2 = 90°: every finite centre is on the y-axis, so I25 comes from
    the links' velocity profiles along that line (notes' rule 2), not from two lines."""
    m = crank_shaper(math.radians(90))
    asm = assemble(m)
    cs = locate_centres(asm)
    c = cs.centre(2, 5)
    assert c.rule == "velocities"
    kin = solve(m)
    assert centre_error(cs.point(2, 5), instant_centre(kin, 2, 5), asm.size) < 1e-15
    steps = backward_slice(asm, [c.ref]).refs
    verbs = [asm[r].verb for r in steps if r.startswith("rule2:")]
    assert verbs.count("lay_off") == 3          # X and the two velocity tips
    assert "intersect_lines" in verbs            # the profiles cross
    # both ground centres feed the profiles: I12 (a pin) and I15 (at infinity, a parallel)
    assert {"I:12", "I:15"} <= set(steps)
    assert asm[c.ref].verb == "project_onto"


@pytest.mark.parametrize("omega2", [1.0, -1.0])
def test_rule_2_lays_each_velocity_off_the_way_its_link_moves(omega2):
    """The velocities at X that rule 2 lays off point as the links' own velocities there
    do, whichever way the crank turns: the centre found is the same either way (the
    construction is homogeneous in ω), but a drawn arrow must not point backwards."""
    m = crank_shaper(math.radians(90), omega2=omega2)
    asm = assemble(m)
    cs = locate_centres(asm)
    kin = solve(m)
    tips = [r for r in backward_slice(asm, [cs.centre(2, 5).ref]).refs if ":tip" in r]
    assert len(tips) == 2
    for ref in tips:
        link = int(ref[-1])
        step = asm[ref]
        x, tip = asm.output(step.inputs[0]).xy, asm.output(ref).xy
        drawn = (tip[0] - x[0], tip[1] - x[1])
        if link == 2:               # a turning link: ω J (X − I12)
            w, (cx, cy) = kin.omegas[2], cs.point(1, 2).xy
            true = (-w * (x[1] - cy), w * (x[0] - cx))
        else:                       # the ram translates: its velocity anywhere
            true = kin.velocities["B"]
        assert drawn[0] * true[0] + drawn[1] * true[1] > 0, link



def test_a_centre_of_two_links_at_rest_together_is_drawn_and_reported_undefined():
    # The crank-shaper at its lever's limit: links 4 and 5 are both momentarily at rest, so
    # every point is I45. The construction completes, and the reference says why it holds
    # no single point.
    from tarsim.exercises.catalog import load
    from tarsim.exercises.file_numbers import radians_in_turn
    from tarsim.exercises.linkages.solution import solve_positions

    ex = load("crank-shaper").asking(("centres",))
    m = ex.mechanism
    limit = m.with_drive(dataclasses.replace(m.drive, angle=radians_in_turn(
        -21.100196024093016, "deg")))
    ex = dataclasses.replace(ex, mechanism=limit, positions=())
    q = solve_positions(ex)[0].quantities["I45"]
    assert q.reference["anywhere"] is True and "move together" in q.reference["undefined"]
    assert q.passed and "point" in q.value
