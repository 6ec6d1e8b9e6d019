"""The acceleration polygon (constructions/linkages/acceleration_polygon.py).

Every tip (every point and every coincident point such as A4), every α and every
Coriolis component is checked against the independent analytic solver. The
tolerance is 1e-9 relative to max(|reference|, A_in), where A_in = r·√(ω2⁴ + α2²)
is the input pin's acceleration; for α the scale is max(|α|, √(ω2⁴ + α2²)). The
sweeps stay at well-conditioned positions, where the construction's error is a few
eps (about 4e-15 measured, the worst over all the mechanisms here), so 1e-9 leaves
room without hiding a wrong line or a wrong sign. Near a dead point the tolerance
is ``analytic_centres.tolerance`` of the tip's reported conditioning. Golden
numbers cite their seed and are printed to a fixed number of digits, so their
tolerance is half a unit in the last printed digit.
"""

import math
import re
from pathlib import Path

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from tarsim.constructions.reference import solver
from tarsim.constructions import geometry as g
from tarsim.constructions.linkages.acceleration_polygon import draw_acceleration_polygon
from tarsim.constructions.linkages.polygon import VELOCITY, Polygon
from tarsim.constructions.checks import tolerance
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.errors import AssemblyError, TarsimError
from tarsim.constructions.model import Drive
from tarsim.constructions.record import Panel, Role, replay
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tarsim.exercises.linkages.mechanism_file import load_mechanism
from tarsim.constructions.narration import narrate
from tests.common import (coupler_four_bar, crank_shaper, four_bar, inverted_slider_crank,
                          offset_slider_crank, scotch_yoke, slotted_lever_p37)

DATA = Path(__file__).parent / "data"
REL = 1e-9
SWEEP = [math.radians(d) for d in range(0, 360, 30)]
SEED_ANGLE = math.pi / 2 - 2.34     # seed 003 §6: t = 2.34 s with θ2 = π/2 − t


def from_file(path, alpha):
    m = load_mechanism(path)
    d = m.drive
    return lambda t: m.with_drive(Drive(d.link, t, d.omega or 1.0, alpha))


MECHANISMS = {
    "coupler four-bar": lambda t: coupler_four_bar(t, omega2=2.0),
    "four-bar, α2 ≠ 0": lambda t: four_bar(t, omega2=10.0, alpha2=-35.0),
    "offset slider-crank, α2 ≠ 0": lambda t: offset_slider_crank(t, omega2=3.0, alpha2=7.0),
    "slotted lever P-37": lambda t: slotted_lever_p37(t, omega2=1.5, alpha2=-2.0),
    "crank-shaper": crank_shaper,
    "crank-shaper, α2 ≠ 0": lambda t: crank_shaper(t, omega2=1.3, alpha2=0.8),
    "inverted slider-crank": lambda t: inverted_slider_crank(t, omega2=-2.0, alpha2=3.0),
    "inverted slider-crank, offset slot": lambda t: inverted_slider_crank(
        t, offset=0.03, omega2=2.0, alpha2=3.0),
    "Whitworth chain": lambda t: inverted_slider_crank(t, ground=0.08, crank=0.15,
                                                       omega2=2.0, alpha2=-1.0),
    "Scotch yoke": lambda t: scotch_yoke(t, omega2=-2.0, alpha2=1.0),
    "Watt six-bar": from_file(DATA / "watt-six-bar.toml", alpha=1.5),
    "Stephenson six-bar": from_file(DATA / "stephenson-six-bar.toml", alpha=-20.0),
}


def polygons(mech, **kw) -> tuple[Polygon, Polygon, object]:
    asm = assemble(mech)
    vp = draw_velocity_polygon(asm)
    return draw_acceleration_polygon(asm, vp, **kw), vp, asm


def split(mech, key):
    """A tip or alias name as (point, link): "A4" is A taken on link 4, "O22" is O2 on 2."""
    found = [(key[:i], int(key[i:])) for i in range(1, len(key))
             if key[i:].isdigit() and key[:i] in mech.point_names and int(key[i:]) in mech.numbers]
    assert len(found) == 1, (key, found)
    return found[0]


def reference(kin, mech, key):
    """The analytic acceleration of a tip: a point, or a coincident point "A4" (A on link 4)."""
    if key in kin.accelerations:
        return kin.accelerations[key]
    point, link = split(mech, key)
    return solver.point_acceleration(kin, mech, link, point)


def input_accel(mech) -> float:
    d = mech.drive
    k = mech.link(d.link)
    return k.span(k.names[0], k.names[1]) * math.hypot(d.omega ** 2, d.alpha)


def alpha_scale(mech) -> float:
    return math.hypot(mech.drive.omega ** 2, mech.drive.alpha)


def errors(mech, ap, kin) -> tuple[float, float, float]:
    """The worst relative errors of the tips (and aliases), the α and the Coriolis components."""
    a_in = input_accel(mech)
    tips = max(math.dist(ap.vector(k), reference(kin, mech, k))
               / max(math.hypot(*reference(kin, mech, k)), a_in)
               for k in list(ap.tips) + list(ap.aliases))
    alphas = max(abs(a - kin.alphas[c]) / max(abs(kin.alphas[c]), alpha_scale(mech))
                 for c, a in ap.rates.items())
    cors = [math.dist(ap.coriolis_of(s.point), rate.coriolis)
            / max(math.hypot(*rate.coriolis), a_in)
            for s, rate in zip(mech.slides, kin.slide_rates) if s.guide_link != 1]
    return tips, alphas, max(cors, default=0.0)


def vector(ap, asm, label):
    """A drawn component (m/s²): the segment of ``components[label]``, start → end."""
    c = asm
    start, end = c[ap.components[label]].inputs
    (sx, sy), (ex, ey) = c.output(start).xy, c.output(end).xy
    return (ex - sx) / ap.scale, (ey - sy) / ap.scale


def sentences(ap, asm):
    return [narrate(asm[r]) for r in ap.steps]


# ----- parity with the analytic solver ------------------------------------------------
@pytest.mark.parametrize("theta", SWEEP, ids=[f"{round(math.degrees(t))}deg" for t in SWEEP])
@pytest.mark.parametrize("name", list(MECHANISMS))
def test_every_tip_alpha_and_coriolis_matches_the_analytic_solver(name, theta):
    mech = MECHANISMS[name](theta)
    try:
        kin = solver.solve(mech)
    except AssemblyError:
        # The Stephenson six-bar cannot close over part of the turn: the assembly
        # under the polygons must refuse it too, in one line.
        with pytest.raises(TarsimError) as e:
            polygons(mech)
        assert "\n" not in str(e.value)
        return
    ap, _, _ = polygons(mech)
    tips, alphas, cors = errors(mech, ap, kin)
    assert tips <= REL
    assert alphas <= REL
    assert cors <= REL
    # Every moving link has its α, every point and every coincident point a tip, and
    # every slot on a moving link its Coriolis component.
    assert set(ap.rates) == set(kin.alphas) - {1}
    assert set(mech.point_names) <= set(ap.tips)
    slots = {s.point: s for s in mech.slides if s.guide_link != 1}
    assert set(ap.coriolis) == set(slots)
    for p, s in slots.items():
        if p not in mech.link(s.guide_link).names:
            assert f"{p}{s.guide_link}" in ap.tips


def test_the_sweep_covers_every_kind_of_joint():
    # A guard on the parity sweep: it must contain a moving slot on a lever, a pin in
    # a slot, a frame guide and a ternary link, or the test above proves less.
    kinds = set()
    for name in MECHANISMS:
        m = MECHANISMS[name](1.0)
        kinds |= {("slot" if s.guide_link != 1 else "guide", s.kind.value) for s in m.slides}
        kinds |= {"ternary" for k in m.links if len(k.names) >= 3 and k.number != 1}
    assert {("slot", "block"), ("slot", "pin"), ("guide", "block"), "ternary"} <= kinds


# ----- golden numbers: the crank-shaper of seed 003 -----------------------------------
def shaper_at(theta):
    mech = crank_shaper(theta, omega2=-1.0, alpha2=0.0)
    ap, vp, asm = polygons(mech)
    return mech, ap, vp, asm


def lever_unit(asm):
    (ox, oy), (ax, ay) = asm.xy("O4"), asm.xy("A")
    r = math.hypot(ax - ox, ay - oy)
    return (ax - ox) / r, (ay - oy) / r, r


def sliding(ap, asm, point, slot):
    """Aˢ of the block (or pin) relative to the slot, read off the polygon (m/s²)."""
    label = f"Aˢ_{point}/{slot}"
    if label in ap.components:
        return vector(ap, asm, label)
    x, y = vector(ap, asm, "−" + label)         # drawn reversed, as it is subtracted
    return -x, -y


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def test_crank_shaper_seed_003_at_t_2_34():
    # Seed 003 §7 (ground-truth table) at t = 2.34 s, θ2 = π/2 − t, ω2 = −1 rad/s, α2 = 0.
    # Angles and rates to 5 decimals, mm quantities to 0.001 mm: tolerance half a unit in
    # the last printed digit (the polygon agrees with the analytic solver to ~1e-15).
    mech, ap, vp, asm = shaper_at(SEED_ANGLE)
    ux, uy, r3 = lever_unit(asm)
    assert math.atan2(uy, ux) == pytest.approx(1.23854, abs=0.5e-5)
    assert r3 * 1e3 == pytest.approx(396.483, abs=0.5e-3)
    assert vp.rates[4] == pytest.approx(0.19212, abs=0.5e-5)
    assert vp.vector("B")[0] * 1e3 == pytest.approx(-189.192, abs=0.5e-3)
    assert ap.rates[4] == pytest.approx(0.56939, abs=0.5e-5)
    assert ap.rates[3] == ap.rates[4] and ap.rates[5] == 0.0 and ap.rates[2] == 0.0
    bx, by = ap.vector("B")
    assert bx * 1e3 == pytest.approx(-535.635, abs=0.5e-3)
    assert by == pytest.approx(0.0, abs=1e-15)       # the ram's guide is horizontal
    assert math.hypot(*ap.coriolis_of("A")) * 1e3 == pytest.approx(62.665, abs=0.5e-3)
    assert math.hypot(*ap.coriolis_of("B")) * 1e3 == pytest.approx(23.711, abs=0.5e-3)
    assert math.hypot(*vector(ap, asm, "Aⁿ_A4")) * 1e3 == pytest.approx(14.634, abs=0.5e-3)
    assert math.hypot(*vector(ap, asm, "Aᵗ_A4")) * 1e3 == pytest.approx(225.753, abs=0.5e-3)
    assert math.hypot(*vector(ap, asm, "Aⁿ_A2")) * 1e3 == pytest.approx(180.0, abs=0.5e-3)
    # The sliding accelerations r̈3 = d²(O4A)/dt², r̈4 = d²(O4B)/dt², signed along O4 → A.
    assert dot(sliding(ap, asm, "A2", "A4"), (ux, uy)) * 1e3 == pytest.approx(90.805, abs=0.5e-3)
    assert dot(sliding(ap, asm, "B5", "B4"), (ux, uy)) * 1e3 == pytest.approx(-140.353,
                                                                              abs=0.5e-3)
    # The worked solution prints the seed's numbers.
    said = " ".join(sentences(ap, asm))
    for text in ("180 mm/s²", "14.6339 mm/s²", "62.6646 mm/s²", "23.7113 mm/s²",
                 "535.635 mm/s²", "0.56939 rad/s² (ccw"):
        assert text in said


def test_crank_shaper_seed_003_at_the_start_position():
    # Seed 003 §10, row t = 0 (θ2 = 90°, ω2 = −1): θ4 = 1.57080, O4A 680, ω4 = −0.26471,
    # ṗ = 232.941 mm/s, α4 = 0, p̈ = 0, r̈3 = −132.353 and r̈4 = +61.661 mm/s² (§10, the
    # start-position paragraph); half a unit in the last printed digit.
    mech, ap, vp, asm = shaper_at(math.pi / 2)
    ux, uy, r3 = lever_unit(asm)
    assert math.atan2(uy, ux) == pytest.approx(1.57080, abs=0.5e-5)
    assert r3 * 1e3 == pytest.approx(680.0, abs=0.5e-3)
    assert vp.rates[4] == pytest.approx(-0.26471, abs=0.5e-5)
    assert vp.vector("B")[0] * 1e3 == pytest.approx(232.941, abs=0.5e-3)
    assert ap.rates[4] == pytest.approx(0.0, abs=0.5e-5)
    assert ap.vector("B")[0] * 1e3 == pytest.approx(0.0, abs=0.5e-3)
    assert dot(sliding(ap, asm, "A2", "A4"), (ux, uy)) * 1e3 == pytest.approx(-132.353,
                                                                              abs=0.5e-3)
    assert dot(sliding(ap, asm, "B5", "B4"), (ux, uy)) * 1e3 == pytest.approx(61.661, abs=0.5e-3)


# ----- where the Coriolis component vanishes ------------------------------------------
# (a) the crank on the line of centres O2O4 (θ2 = ±90°): V_A is ⟂ the lever, so nothing
#     slides at A (nor at B, the lever being at its mid-stroke): V_P/P4 = 0.
# (b) a limit position of the lever: O4A is tangent to the crank circle, so the triangle
#     O2 A O4 has its right angle at A and cos ∠AO2O4 = O2A / O2O4. O2O4 points along −y
#     from O2, so θ2 = −π/2 ± acos(O2A / O2O4), i.e. sin θ2 = −O2A / O2O4: there ω4 = 0.
R2, R1 = 0.18, 0.5                                   # O2A and O2O4 of seed 003 §2
LINE_OF_CENTRES = {"θ2 = +90°": math.pi / 2, "θ2 = −90°": -math.pi / 2}
LIMITS = {"right limit": -math.pi / 2 + math.acos(R2 / R1),
          "left limit": -math.pi / 2 - math.acos(R2 / R1)}
VANISHING = {**LINE_OF_CENTRES, **LIMITS}


@pytest.mark.parametrize("omega2", [-1.0, 1.0])
@pytest.mark.parametrize("where", list(VANISHING))
def test_coriolis_vector_vanishes(where, omega2):
    mech = crank_shaper(VANISHING[where], omega2=omega2)
    ap, vp, asm = polygons(mech)
    a_in = input_accel(mech)
    for p in ("A", "B"):
        assert math.hypot(*ap.coriolis_of(p)) <= REL * a_in
    if where in LIMITS:
        assert abs(vp.rates[4]) <= REL * abs(omega2)
        # seed 003 §10: the lever's extremes are θ4 = 1.20253 and 1.93906 rad.
        ux, uy, _ = lever_unit(asm)
        assert math.atan2(uy, ux) == pytest.approx(
            1.20253 if where == "right limit" else 1.93906, abs=0.5e-5)
    else:
        va, va4 = vp.vector("A"), vp.vector("A4")
        assert math.dist(va, va4) <= REL * mech.input_speed
    # The rest of the polygon is still right there.
    tips, alphas, cors = errors(mech, ap, solver.solve(mech))
    assert max(tips, alphas, cors) <= REL


@pytest.mark.parametrize("where", list(VANISHING))
def test_coriolis_sentence_says_it_is_zero(where):
    mech = crank_shaper(VANISHING[where], omega2=-1.0)
    ap, _, asm = polygons(mech)
    why = "ω4 = 0" if where in LIMITS else "no sliding"
    for p in ("A2/A4", "B5/B4"):
        said = [s for s in sentences(ap, asm) if "Coriolis component" in s and p in s
                and "⟂" not in s]
        assert len(said) == 1 and "is zero" in said[0] and why in said[0], said
        # A zero vector is not drawn as an arrow.
        assert not any(label.endswith(f"Aᶜ_{p}") for label in ap.components)


# ----- the direction of the Coriolis component ---------------------------------------
def turned(v, omega):
    """v turned 90° in the sense of ω: (−v_y, v_x) for ω > 0, (v_y, −v_x) for ω < 0."""
    return (-v[1], v[0]) if omega > 0 else (v[1], -v[0])


SIGN_CASES = {
    "crank-shaper A": (lambda t, w: crank_shaper(t, omega2=w), "A", 3, 4),
    "crank-shaper B": (lambda t, w: crank_shaper(t, omega2=w), "B", 5, 4),
    "P-37 A": (lambda t, w: slotted_lever_p37(t, omega2=w), "A", 3, 4),
    "inverted A": (lambda t, w: inverted_slider_crank(t, omega2=w), "A", 3, 4),
    "Whitworth A": (lambda t, w: inverted_slider_crank(t, ground=0.08, crank=0.15,
                                                       omega2=w), "A", 3, 4),
}


@pytest.mark.parametrize("theta", [math.radians(40), math.radians(230), SEED_ANGLE])
@pytest.mark.parametrize("case", list(SIGN_CASES))
def test_coriolis_is_v_rel_turned_the_way_the_slot_turns(case, theta):
    build, p, block, slot = SIGN_CASES[case]
    drawn = {}
    for w in (-1.5, 1.5):
        mech = build(theta, w)
        kin = solver.solve(mech)
        ap, vp, asm = polygons(mech)
        v_rel = [a - b for a, b in zip(solver.point_velocity(kin, mech, block, p),
                                       solver.point_velocity(kin, mech, slot, p))]
        w4 = kin.omegas[slot]
        by_hand = tuple(2.0 * abs(w4) * c for c in turned(v_rel, w4))
        cor = ap.coriolis_of(p)
        rate = next(r for s, r in zip(mech.slides, kin.slide_rates)
                    if s.point == p and s.guide_link == slot)
        a_in = input_accel(mech)
        assert math.hypot(*by_hand) > 0.05 * a_in       # a case where the sign matters
        assert math.dist(cor, by_hand) <= REL * a_in
        assert math.dist(cor, rate.coriolis) <= REL * a_in
        # The sentence names the sense of ω of the slotted link.
        said = [s for s in sentences(ap, asm) if s.startswith("Along it lay off the Coriolis")
                and f"V_{p}" in s]
        assert len(said) == 1 and ("(ccw)" if w4 > 0 else "(cw)") in said[0]
        # The arrow is drawn as Aᶜ when added, and reversed (−Aᶜ) when subtracted.
        label = next(k for k in ap.components if "Aᶜ_" in k and k.split("Aᶜ_")[1][0] == p)
        arrow = vector(ap, asm, label)
        want = cor if not label.startswith("−") else (-cor[0], -cor[1])
        assert math.dist(arrow, want) <= REL * a_in
        drawn[w] = cor
    # Reversing the crank reverses both ω4 and v_rel, so 2ω × v_rel is unchanged.
    assert math.dist(drawn[-1.5], drawn[1.5]) <= REL * math.hypot(*drawn[1.5])


# ----- near and at a dead point --------------------------------------------------------
def toggling_four_bar(theta2, **kw):
    """Non-Grashof four-bar whose coupler and rocker are collinear at θ2 = 90°.

    A = (0, 0.3), O4 = (0.4, 0): |AO4| = 0.5 = AB + O4B, the dead point of a crank
    input; just below 90° |AO4| < 0.5 and it assembles.
    """
    return four_bar(theta2, o4=(0.4, 0.0), crank=0.3, coupler=0.2, rocker=0.3, **kw)


@pytest.mark.parametrize("off", [1e-4, 1e-6, 1e-8])
def test_near_dead_point_agrees_within_its_conditioning(off):
    mech = toggling_four_bar(math.pi / 2 - off, omega2=1.0, alpha2=2.0)
    ap, _, asm = polygons(mech)
    cond = asm[ap.tips["B"]].conditioning
    # The tip's conditioning is reported, and small: the two lines of b′ nearly coincide.
    assert 0.0 < cond < 1e-3
    tol = tolerance(cond)
    tips, alphas, _ = errors(mech, ap, solver.solve(mech))
    assert tips <= tol and alphas <= tol
    # α grows like 1/off here (≈ 3e5 rad/s² at 1e-4): the check is not vacuous.
    assert abs(ap.rates[3]) > 1.0 / off


def test_dead_point_is_refused_in_one_line():
    mech = toggling_four_bar(math.pi / 2, omega2=1.0, alpha2=2.0)
    asm = assemble(mech)                       # the position itself exists
    with pytest.raises(AssemblyError) as e:
        draw_acceleration_polygon(asm, draw_velocity_polygon(asm))
    msg = str(e.value)
    assert "\n" not in msg and "nan" not in msg.lower()
    assert "dead point at θ2 = 90°" in msg
    assert e.value.joint == "B" and e.value.angle_deg == pytest.approx(90.0)


def test_the_acceleration_polygon_checks_its_own_crossing():
    # Hand the polygon finite (made-up) velocities at the dead point, as if the
    # velocity polygon had let it through: the acceleration polygon must still
    # refuse its own parallel lines, not draw a far, meaningless b′.
    mech = toggling_four_bar(math.pi / 2, omega2=1.0)
    asm = assemble(mech)
    c = asm
    for ref, xy in (("vp:o_v", (0.0, 0.0)), ("vp:tip:A", (-0.3, 0.0)),
                    ("vp:tip:B", (-0.1, 0.2))):
        c.give(ref, g.Point(*xy), label=ref, panel=Panel.VELOCITY)
    tips = {"O2": "vp:o_v", "O4": "vp:o_v", "A": "vp:tip:A", "B": "vp:tip:B"}
    vp = Polygon(VELOCITY, "vp:o_v", 1.0, tips, {2: 1.0, 3: 0.5, 4: 0.25}, [], construction=c)
    with pytest.raises(AssemblyError) as e:
        draw_acceleration_polygon(asm, vp)
    msg = str(e.value)
    assert "\n" not in msg and "dead point at θ2 = 90°" in msg and "A_B is undefined" in msg


# ----- the input ------------------------------------------------------------------------
@pytest.mark.parametrize("given, text", [(False, "α2 = 0 (not given, so taken as 0)"),
                                         (True, "α2 = 0 (given)")])
def test_input_alpha_defaults_to_zero_and_says_so(given, text):
    mech = four_bar(1.0, omega2=2.0).with_drive(Drive(2, 1.0, 2.0, 0.0, alpha_given=given))
    ap, _, asm = polygons(mech)
    said = sentences(ap, asm)
    assert sum(text in s for s in said) == 1
    assert ap.rates[2] == 0.0
    # Aᵗ_A is not drawn; a′ is the end of Aⁿ_A = ω2²·O2A toward O2.
    assert "Aᵗ_A" not in ap.components
    ax, ay = ap.vector("A")
    assert (ax, ay) == pytest.approx((-4.0 * 0.1 * math.cos(1.0), -4.0 * 0.1 * math.sin(1.0)),
                                     rel=1e-14)


def test_a_file_without_alpha_takes_it_as_zero():
    mech = load_mechanism(DATA / "watt-six-bar.toml")      # [input] gives no alpha
    assert mech.drive.alpha_given is False
    ap, _, asm = polygons(mech)
    assert any("(not given, so taken as 0)" in s for s in sentences(ap, asm))
    tips, alphas, _ = errors(mech, ap, solver.solve(mech))
    assert tips <= REL and alphas <= REL


def test_a_given_input_alpha_is_laid_off_in_its_sense():
    mech = four_bar(1.0, omega2=2.0, alpha2=-5.0)
    ap, _, asm = polygons(mech)
    said = sentences(ap, asm)
    assert any(s.startswith("Along it lay off Aᵗ_A = α2·O2A = 5 rad/s² × 0.1 m = 0.5 m/s², "
                            "in the sense of α2 (cw)") for s in said)
    # Aᵗ_A = α2 k × O2A: cw turns O2A by −90°.
    assert vector(ap, asm, "Aᵗ_A") == pytest.approx((-5.0 * -0.1 * math.sin(1.0),
                                                     -5.0 * 0.1 * math.cos(1.0)), rel=1e-14)


# ----- labels and components --------------------------------------------------------------
def test_tips_are_primed_and_components_are_labelled():
    ap, _, asm = polygons(coupler_four_bar(0.7))
    c = asm
    assert c[ap.pole].label == "o_a" and ap.tips["O2"] == ap.tips["O4"] == ap.pole
    assert {p: c[ap.tips[p]].label for p in "ABCD"} == {"A": "a′", "B": "b′", "C": "c′",
                                                        "D": "d′"}
    ap, _, asm = polygons(four_bar(0.7, omega2=3.0, alpha2=4.0))
    assert {"Aⁿ_A", "Aᵗ_A", "Aⁿ_B/A", "Aᵗ_B/A", "Aⁿ_B", "Aᵗ_B"} <= set(ap.components)
    ap, _, asm = polygons(crank_shaper(SEED_ANGLE))
    c = asm
    assert {k: c[ap.tips[k]].label for k in ("A", "A4", "B", "B4")} == {
        "A": "a2′", "A4": "a4′", "B": "b5′", "B4": "b4′"}
    assert ap.vector("A2") == ap.vector("A3") == ap.vector("A")
    labels = set(ap.components)
    assert {"Aⁿ_A2", "Aⁿ_A4", "Aᵗ_A4"} <= labels
    assert {"−Aᶜ_A2/A4", "Aᶜ_B5/B4"} <= labels     # A4 = A2 − Aᶜ − Aˢ; B5 = B4 + Aᶜ + Aˢ
    assert {"−Aˢ_A2/A4", "Aˢ_B5/B4"} <= labels
    for label, ref in ap.components.items():
        assert c[ref].label == label and c[ref].panel is Panel.ACCELERATION


@pytest.mark.parametrize("theta", SWEEP[::3])
def test_components_are_the_textbook_terms(theta):
    # Aⁿ_X/K = −ω²·KX (from X toward K) and Aᵗ_X/K = α k × KX, each against the solver.
    mech = four_bar(theta, omega2=-4.0, alpha2=9.0)
    ap, _, asm = polygons(mech)
    kin = solver.solve(mech)
    P = kin.points
    a_in = input_accel(mech)
    for label, (k, x, link) in {"A": ("O2", "A", 2), "B/A": ("A", "B", 3),
                                "B": ("O4", "B", 4)}.items():
        rx, ry = P[x][0] - P[k][0], P[x][1] - P[k][1]
        w, a = kin.omegas[link], kin.alphas[link]
        assert math.dist(vector(ap, asm, f"Aⁿ_{label}"), (-w * w * rx, -w * w * ry)) <= REL * a_in
        assert math.dist(vector(ap, asm, f"Aᵗ_{label}"), (-a * ry, a * rx)) <= REL * a_in


# ----- the acceleration image ------------------------------------------------------------
@pytest.mark.parametrize("theta", SWEEP[::2])
def test_coupler_image_is_similar_same_handed_and_divided(theta):
    mech = coupler_four_bar(theta, omega2=-3.0)
    ap, _, asm = polygons(mech)
    c = asm
    P = {n: asm.xy(n) for n in "ABC"}
    p = {n: c.output(ap.tips[n]).xy for n in "ABC"}
    ratio = [math.dist(p[u], p[v]) / math.dist(P[u], P[v]) for u, v in ("AB", "BC", "CA")]
    assert ratio[1] == pytest.approx(ratio[0], rel=1e-12)
    assert ratio[2] == pytest.approx(ratio[0], rel=1e-12)
    # The image side is √(α3² + ω3⁴) times the link side, at the polygon's scale.
    kin = solver.solve(mech)
    assert ratio[0] == pytest.approx(math.hypot(kin.alphas[3], kin.omegas[3] ** 2) * ap.scale,
                                     rel=1e-9)

    def turn(q):
        (ax, ay), (bx, by), (cx, cy) = q["A"], q["B"], q["C"]
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    assert math.copysign(1.0, turn(p)) == math.copysign(1.0, turn(P))
    # D lies on AB beyond B: d′ divides a′b′ as D divides AB.
    d = c.output(ap.tips["D"]).xy
    t = 0.32 / 0.25
    assert d[0] == pytest.approx(p["A"][0] + t * (p["B"][0] - p["A"][0]), abs=1e-12)
    assert d[1] == pytest.approx(p["A"][1] + t * (p["B"][1] - p["A"][1]), abs=1e-12)
    assert any("the acceleration image" in s and s.startswith("D lies on line AB")
               for s in sentences(ap, asm))


# ----- the record ---------------------------------------------------------------------
@pytest.mark.parametrize("name", ["coupler four-bar", "crank-shaper", "slotted lever P-37",
                                  "Watt six-bar", "offset slider-crank, α2 ≠ 0",
                                  "inverted slider-crank"])
def test_every_step_is_in_the_acceleration_panel_and_replays(name):
    ap, _, asm = polygons(MECHANISMS[name](math.radians(50)))
    c = asm
    assert ap.steps[0] == ap.pole
    arrows = set(ap.components.values())
    for ref in ap.steps:
        step = c[ref]
        assert step.panel is Panel.ACCELERATION
        assert replay(c, ref) == step.output
        if ref not in arrows:           # a component arrow is said by the act before it
            assert len(narrate(step)) > 20 and narrate(step).endswith("."), narrate(step)
    # The polygon rests only on the space diagram and on its own steps: it takes the
    # velocity polygon's numbers (ω, V_rel), never its tips.
    ours = set(ap.steps) | set(ap.space_steps)
    for ref in ap.steps:
        assert all(i in ours or c[i].panel is Panel.SPACE for i in c[ref].inputs)
    drawn = {c[r].inputs: c[r].role for r in ap.steps if c[r].verb == "join"}
    for tip in set(ap.tips.values()) - {ap.pole}:
        assert drawn[(ap.pole, tip)] in (Role.RESULT, Role.GIVEN)


# ----- scale, pole and refusals --------------------------------------------------------
def test_scale_is_chosen_nice_and_an_explicit_one_is_kept():
    mech = four_bar(1.0, omega2=10.0, alpha2=30.0)
    ap, _, asm = polygons(mech)
    mant = ap.scale / 10.0 ** math.floor(math.log10(ap.scale))
    assert round(mant, 9) in (1.0, 2.0, 5.0)
    drawn = math.dist(*(asm.output(r).xy for r in (ap.pole, ap.tips["A"])))
    assert asm.size / 5.0 < drawn <= asm.size / 2.0
    other, _, _ = polygons(mech, scale=0.001, pole=(3.0, -2.0))
    assert other.scale == 0.001
    for k in ap.tips:
        assert other.vector(k) == pytest.approx(ap.vector(k), rel=1e-12, abs=1e-12)
    assert other.rates == pytest.approx(ap.rates, rel=1e-12)


@pytest.mark.parametrize("bad", [0.0, -1.0, math.inf, math.nan])
def test_a_bad_scale_is_refused(bad):
    with pytest.raises(TarsimError, match="positive number"):
        polygons(four_bar(1.0, omega2=1.0), scale=bad)


def test_polygons_on_other_or_used_constructions_are_refused():
    mech = four_bar(1.0, omega2=1.0)
    asm = assemble(mech)
    vp = draw_velocity_polygon(asm)
    with pytest.raises(TarsimError, match="another construction"):
        draw_acceleration_polygon(assemble(mech), vp)
    draw_acceleration_polygon(asm, vp)
    with pytest.raises(TarsimError, match="already holds an? acceleration polygon"):
        draw_acceleration_polygon(asm, vp)


def test_unknown_names_are_refused_with_what_there_is():
    ap, _, _ = polygons(crank_shaper(SEED_ANGLE))
    with pytest.raises(TarsimError, match="no tip for Z"):
        ap.vector("Z")
    with pytest.raises(TarsimError,
                       match="no Coriolis component at C; the polygon has one at A, B"):
        ap.coriolis_of("C")
    ap, _, _ = polygons(four_bar(1.0, omega2=1.0))
    with pytest.raises(TarsimError, match="has one at no point"):
        ap.coriolis_of("A")


def test_input_at_rest_gives_a_polygon_at_the_pole():
    ap, _, _ = polygons(four_bar(1.0, omega2=0.0, alpha2=0.0))
    assert ap.vector("B") == (0.0, 0.0) and ap.rates[4] == 0.0


# ----- property: random four-bars away from toggle ------------------------------------
@settings(max_examples=60, deadline=None)
@given(crank=st.floats(0.05, 0.9), theta=st.floats(-math.pi, math.pi),
       rocker=st.floats(0.1, 1.5), phi=st.floats(-math.pi, math.pi),
       omega=st.floats(-20.0, 20.0).filter(lambda w: abs(w) > 0.1),
       alpha=st.floats(-100.0, 100.0))
def test_random_four_bars_match_the_analytic_solver(crank, theta, rocker, phi, omega, alpha):
    # Ground O2O4 = 1. Pick B directly (at angle φ from O4), so the four-bar always
    # closes: the coupler is |AB| and the branch is B's side of A → O4 (solver.solve).
    a = (crank * math.cos(theta), crank * math.sin(theta))
    b = (1.0 + rocker * math.cos(phi), rocker * math.sin(phi))
    coupler = math.dist(a, b)
    assume(coupler > 0.05)
    ab, ob = (b[0] - a[0], b[1] - a[1]), (rocker * math.cos(phi), rocker * math.sin(phi))
    # Away from toggle: coupler and rocker cross at ≥ ~6° (b′ is cut from lines ⟂ AB and
    # ⟂ O4B), and A is not near O4.
    assume(abs(ab[0] * ob[1] - ab[1] * ob[0]) >= 0.1 * coupler * rocker)
    assume(math.dist(a, (1.0, 0.0)) > 0.05)
    side = (1.0 - a[0]) * (b[1] - a[1]) - (0.0 - a[1]) * (b[0] - a[0])
    mech = four_bar(theta, o4=(1.0, 0.0), crank=crank, coupler=coupler, rocker=rocker,
                    omega2=omega, alpha2=alpha, branch="left" if side > 0 else "right")
    kin = solver.solve(mech)
    assert math.dist(kin.points["B"], b) <= 1e-9      # the same assembly as was drawn
    ap, _, _ = polygons(mech)
    tips, alphas, _ = errors(mech, ap, kin)
    assert tips <= 1e-8 and alphas <= 1e-8


# ----- curved slots and circle contacts (the notes §2.11–2.12) ----------------------------
def frame_slot_four_bar(theta):
    """The peers four-bar with its rocker replaced by a pin B in a frame slot about O4."""
    from tarsim.constructions.joints import Arc, SlideKind
    from tarsim.constructions.model import Mechanism
    m = four_bar(theta, omega2=10.0, alpha2=3.0)
    links = tuple(k for k in m.links if k.number != 4)
    return Mechanism(links, m.drive, (), dict(m.branches), m.units, "frame slot",
                     arcs=(Arc(SlideKind.PIN, 3, "B", 1, "O4", 0.2),))


CURVED = {
    "pin in a curved slot": from_file(DATA / "curved-slot.toml", alpha=3.0),
    "roller on a circular cam": from_file(DATA / "roller-cam.toml", alpha=-4.0),
    "block on a curved guide": from_file(DATA / "curved-guide-slider-crank.toml", alpha=2.0),
    "pin in a frame slot": frame_slot_four_bar,
}


def curved_coriolis(kin, mech, arc):
    """2ω_j × (V_P − V_Pj) from the analytic velocities of P on its link and on the slot's."""
    (px, py), (qx, qy) = (solver.point_velocity(kin, mech, k, arc.point)
                          for k in (arc.link, arc.guide_link))
    w = kin.omegas[arc.guide_link]
    return -2.0 * w * (py - qy), 2.0 * w * (px - qx)


@pytest.mark.parametrize("theta", SWEEP[::2], ids=[f"{round(math.degrees(t))}deg"
                                                    for t in SWEEP[::2]])
@pytest.mark.parametrize("name", list(CURVED))
def test_curved_slots_match_the_analytic_solver(name, theta):
    mech = CURVED[name](theta)
    kin = solver.solve(mech)
    ap, vp, asm = polygons(mech)
    tips, alphas, _ = errors(mech, ap, kin)
    assert tips <= REL and alphas <= REL
    a_in = input_accel(mech)
    for arc in mech.pin_arcs:
        if arc.guide_link == 1:
            continue
        ref = curved_coriolis(kin, mech, arc)
        assert math.dist(ap.coriolis_of(arc.point), ref) <= REL * max(math.hypot(*ref), a_in)


def test_a_curved_slot_adds_v_rel_squared_over_rho_toward_its_centre():
    mech = CURVED["pin in a curved slot"](math.radians(40))
    kin = solver.solve(mech)
    ap, vp, asm = polygons(mech)
    arc = mech.pin_arcs[0]
    (px, py), (qx, qy) = (solver.point_velocity(kin, mech, k, "A") for k in (2, 4))
    v_rel2 = (px - qx) ** 2 + (py - qy) ** 2
    normal = [label for label in ap.components if label.lstrip("−").startswith("Aⁿ_A2/A4")]
    assert len(normal) == 1
    ax, ay = vector(ap, asm, normal[0])
    assert math.hypot(ax, ay) == pytest.approx(v_rel2 / arc.radius, rel=1e-12)
    # Along AK, toward K (reversed when the slot's own point is the one being found).
    (kx, ky), (x, y) = asm.xy(arc.centre), asm.xy("A")
    toward = ((kx - x) * ax + (ky - y) * ay) / math.dist((kx, ky), (x, y)) / math.hypot(ax, ay)
    assert toward == pytest.approx(1.0 if not normal[0].startswith("−") else -1.0, abs=1e-12)
    said = " ".join(sentences(ap, asm))
    assert "V_A2/A4²/ρ" in said and "centre of curvature K" in said


def test_rounding_noise_is_said_as_zero_in_the_steps():
    """The crank-shaper at θ2 = 90°: the ram stands still in its stroke and the lever has
    no angular acceleration, but the polygon reads them as 1e-14 mm/s² and 1e-17 rad/s²
    of rounding. The steps say 0, not the noise."""
    from tarsim.constructions.narration import narrate

    m = crank_shaper(math.radians(90))
    asm = assemble(m)
    ap = draw_acceleration_polygon(asm, draw_velocity_polygon(asm))
    said = [narrate(asm[r]) for r in ap.steps if asm[r].phrase is not None]
    assert not any(re.search(r"\de-\d", text) for text in said)
    assert any("α4" in t and "= 0 rad/s² (no angular acceleration" in t for t in said)
