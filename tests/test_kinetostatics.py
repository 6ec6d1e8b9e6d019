"""The force reference: Newton–Euler for every link as one linear system, against closed
forms and against the balance of power.

- A slider-crank engine with only a gas force and a reciprocating mass: the textbook's
  piston effort F_P = F_gas − m·a_P, thrust on the wall F_P·tan φ, and turning moment
  F_P·r·sin(θ + φ)/cos φ.
- A four-bar loaded by a couple on its output: the coupler is a two-force member, and
  T2·ω2 = −T4·ω4.
- The course project's crank-shaper (003 §9): the torque from 4 on 3 near 1e-4 N·m and the
  pin force at B near 0.1 N, as the project reports them.
- The balance of power, which no joint force enters, gives the same driving torque.
Tolerances: forces of order 1–1000 N from a well-posed 12 × 12 system, ~1e-12 relative.
"""

from __future__ import annotations

import math
import random
import tempfile
from dataclasses import replace
from pathlib import Path

import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

import tarsim
from tarsim.constructions.errors import InputError
from tarsim.constructions.loads import Couple, Loads, Mass, PointForce
from tarsim.constructions.model import Drive
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.kinetostatics import balance, pin_couples, power_torque
from tarsim.exercises.catalog import bundled, load
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.mechanism_file import parse_mechanism
from tests.random_loads import generate as loads_case, run_case as run_loads_case

ENGINE = """\
name = "In-line engine"
[units]
length = "mm"
[frame]
O = [0, 0]
[[link]]
number = 2
points = ["O", "A"]
lengths = { OA = 60 }
[[link]]
number = 3
points = ["A", "P"]
lengths = { AP = 240 }
[[link]]
number = 4
points = ["P"]
[[slider]]
link = 4
point = "P"
on = 1
through = "O"
angle = 0
[input]
link = 2
angle = 40
omega = 200
[assembly]
P = "forward"
"""


@pytest.mark.parametrize("deg", [20, 40, 75, 130, 200, 300])
def test_the_engine_gives_the_textbooks_piston_effort_and_turning_moment(deg):
    """Gas force 5 kN on a 1.2 kg piston, the rod and crank massless, no weight: the rod
    is a two-force member, so the piston effort F_P = F_gas − m·ẍ_P goes along it and
    T = F_P·r·sin(θ + φ)/cos φ (sin φ = r sin θ / l, the thrust F_P tan φ on the wall)."""
    mech = parse_mechanism(ENGINE).with_drive(Drive(2, math.radians(deg), 200.0))
    kin = solver.solve(mech)
    gas = -5000.0 if math.sin(math.radians(deg)) > 0 else 5000.0   # against the piston's way
    loads = Loads((Mass(4, 1.2, (0.0, 0.0), 1e-9),), (PointForce(4, "P", (gas, 0.0)),),
                  gravity=0.0)
    s = balance(mech, kin, loads)
    th, r, length = math.radians(deg), 0.060, 0.240
    phi = math.asin(r * math.sin(th) / length)
    effort = gas - 1.2 * kin.accelerations["P"][0]
    # The turning moment with the piston effort pushing toward the crank (−x) is
    # −F_P·r·sin(θ + φ)/cos φ on the crank, CCW +; the driver holds it, so T2 is its negative.
    assert s.torque == pytest.approx(effort * r * math.sin(th + phi) / math.cos(phi),
                                     rel=1e-12, abs=1e-9)
    assert s.joint("F_14").force[1] == pytest.approx(-effort * math.tan(phi), rel=1e-12,
                                                     abs=1e-9)
    rod = s.joint("F_23").force
    assert rod[1] == pytest.approx(rod[0] * -math.tan(phi), rel=1e-12, abs=1e-9)
    assert s.torque == pytest.approx(power_torque(mech, kin, loads), rel=1e-12)


@pytest.mark.parametrize("deg", [0, 60, 150, 250])
def test_a_four_bar_holding_a_couple_on_its_output(deg):
    """Massless links, 50 N·m on the output: the coupler carries its force along AB, and
    the input holds T2 = −T4·ω4/ω2."""
    ex = load("four-bar")
    mech = ex.mechanism.with_drive(Drive(2, math.radians(deg), 10.0))
    kin = solver.solve(mech)
    loads = Loads(couples=(Couple(4, 50.0),), gravity=0.0)
    s = balance(mech, kin, loads)
    assert s.torque == pytest.approx(-50.0 * kin.omegas[4] / kin.omegas[2], rel=1e-12)
    f = s.joint("F_23").force
    ab = (kin.points["B"][0] - kin.points["A"][0], kin.points["B"][1] - kin.points["A"][1])
    assert abs(f[0] * ab[1] - f[1] * ab[0]) <= 1e-12 * math.hypot(*f) * math.hypot(*ab)


LOADED = """
[forces]
gravity = true

[[mass]]
link = 2
mass = 1.19                # a slender rod, 180 mm

[[mass]]
link = 3
mass = 0.1
centre = "A"
inertia = 5.83e-4

[[mass]]
link = 4
mass = 4.49
centre = [440, 0]          # half the lever's 880 mm
length = 880

[[mass]]
link = 5
mass = 0.1
centre = "B"
inertia = 1e-4
"""


def _shaper(extra: str = ""):
    text = Path(bundled()["crank-shaper"]).read_text(encoding="utf-8") + LOADED + extra
    return parse_exercise(text, "crank-shaper.toml", "crank-shaper")


def test_the_crank_shaper_reproduces_the_projects_orders_of_magnitude():
    """003 §9 without cutting force: the couple from 4 on 3 is ~1e-4 N·m (here I3·α4 =
    5.83e-4 × 0.5696 = 3.32e-4 N·m at t = 2.34 s), the slot's push on the ram's pin ~0.1 N
    (here 0.0567 N); the slender-rod inertias are the project's 3.21e-3 and 0.290 kg·m²."""
    ex = _shaper()
    masses = {m.link: m for m in ex.loads.masses}
    assert masses[2].inertia == pytest.approx(3.213e-3, rel=1e-12)
    assert masses[4].inertia == pytest.approx(4.49 * 0.88 ** 2 / 12, rel=1e-12)
    assert "slender rod" in masses[4].assumed and masses[3].assumed == ""
    mech = ex.at(ex.positions[1]).mechanism
    kin = solver.solve(mech)
    s = balance(mech, kin, ex.loads)
    couple = s.joint("T_43").moment
    assert abs(couple) == pytest.approx(5.83e-4 * abs(kin.alphas[4]), rel=1e-9)
    assert 1e-4 < abs(couple) < 1e-3
    assert 0.01 < s.joint("F_45").size < 0.1
    assert s.torque == pytest.approx(power_torque(mech, kin, ex.loads), rel=1e-11)


def test_a_cutting_force_on_the_ram_is_held_by_the_crank():
    """1000 N against the ram at θ2 = 90° (the ram moving +x, the lever upright): the slot
    takes it all at B, F_45 = 1000 N, and T2 = −1000 N × (the ram's speed per unit ω2)."""
    ex = _shaper('\n[[force]]\nlink = 5\npoint = "B"\nforce = [-1000, 0]\n')
    mech = ex.at(ex.positions[0]).mechanism
    kin = solver.solve(mech)
    s = balance(mech, kin, ex.loads)
    assert s.joint("F_45").force[0] == pytest.approx(1000.0, rel=1e-12)
    vb = kin.velocities["B"][0]
    assert s.torque == pytest.approx(-(-1000.0 * vb) / kin.omegas[2], rel=1e-9)
    assert s.torque == pytest.approx(power_torque(mech, kin, ex.loads), rel=1e-12)


def test_a_redundant_guide_is_named():
    """A second guide for the piston, along the first: the file reader's Grübler count
    refuses it already, so it is built here; the two guides' pushes cannot be told apart."""
    single = parse_mechanism(ENGINE)
    kin = solver.solve(single)                   # the same motion, one guide
    mech = replace(single, slides=single.slides + (replace(single.slides[0],
                                                           direction=(-1.0, 0.0)),))
    with pytest.raises(InputError,
                       match="statically indeterminate: the joints F_14, T_14, F_14′, T_14′ "):
        balance(mech, kin, Loads(gravity=9.81))


@pytest.mark.parametrize("extra, words", [
    ("\n[[mass]]\nlink = 9\nmass = 1\n", "names link 9, which is not a moving link"),
    ("\n[[mass]]\nlink = 2\nmass = -1\n", "link 2's mass must be positive, got -1 kg"),
    ("\n[[mass]]\nlink = 2\nmass = 1\ninertia = 0\n", "moment of inertia must be positive"),
    ("\n[[mass]]\nlink = 4\nmass = 1\n", "link 4 (slotted lever) has one point, so no "
                                          "mid-length"),
    ("\n[[mass]]\nlink = 4\nmass = 1\ncentre = [10, 0]\n",
     "link 4 has one point: give its inertia, or its length"),
    ("\n[[force]]\nlink = 5\npoint = \"Q\"\nforce = [1, 0]\n", "link 5 has no point 'Q'"),
    ("\n[forces]\ndriver = 4\n", "the driver must be the input link (2)"),
    ("\n[[couple]]\nlink = 4\nmoment = 1\nsize = 2\n", "unknown setting 'size' in [couple]"),
])
def test_bad_loads_are_refused_in_one_line(extra, words):
    text = Path(bundled()["crank-shaper"]).read_text(encoding="utf-8") + extra
    with pytest.raises(InputError) as e:
        parse_exercise(text, "cs.toml", "cs")
    message = str(e.value)
    assert "\n" not in message and message.startswith("cs.toml:") and words in message, message


@pytest.mark.parametrize("name", ["engine-forces", "crank-shaper-forces"])
@pytest.mark.parametrize("mu", [0.05, 0.2])
def test_friction_dissipates_what_the_driver_puts_in_beyond_the_loads(name, mu):
    """With friction μ at every slide, each slide's push leans against its sliding
    (|tangential| = μ·|normal|, opposing the slide's velocity), and the balance of power
    closes only with the dissipation Σ μ·|N|·|v|: T·ω + Σ F·v + Σ M·ω = D, at every 30°."""
    ex = load(name)
    loads = replace(ex.loads, friction=mu)
    mech = ex.mechanism
    for k in range(12):
        m = mech.with_drive(replace(mech.drive, angle=mech.drive.angle + math.radians(30 * k)))
        kin = solver.solve(m)
        s = balance(m, kin, loads)
        biggest = max(j.size for j in s.joints if j.name.startswith("F"))
        assert power_torque(m, kin, loads, s) == pytest.approx(s.torque, abs=1e-11 * biggest)
        for slide, n in zip(m.slides, s.pushes):
            (rate,) = [r for r in kin.slide_rates if r.slide is slide]
            (joint,) = [j for j in s.joints if j.at == kin.points[slide.point]
                        and (j.by, j.on) == (slide.guide_link, slide.link)
                        and j.name.startswith("F")]
            d = rate.direction
            along = joint.force[0] * d[0] + joint.force[1] * d[1]
            fastest = max(math.hypot(*v) for v in kin.velocities.values())
            resting = abs(rate.velocity) <= 1e-9 * fastest     # friction takes no side
            assert abs(along) == pytest.approx(0.0 if resting else mu * abs(n), rel=1e-12,
                                               abs=1e-12 * biggest)
            assert along * rate.velocity <= 1e-12 * biggest


# ----- rounding that must not choose a side, and a system of many scales ------------------------
def _four_bar_at_the_rockers_limit(extra: str) -> str:
    """The bundled four-bar (100/250/200/300 mm) with crank and coupler in line, O2B =
    350 mm: cos θ2 = (350² + 300² − 200²)/(2·350·300), the rocker at its limit (ω4 = 0)."""
    theta = math.degrees(math.acos((350 ** 2 + 300 ** 2 - 200 ** 2) / (2 * 350 * 300)))
    text = Path(bundled()["four-bar"]).read_text(encoding="utf-8")
    text = text.replace("angle = 60", f"angle = {theta!r}")
    text = text.replace('find = ["centres", "omega3", "omega4", "V_B"]\nmethods = '
                        '["radius-rotation", "parallel-line", "components"]',
                        'find = ["F_12", "F_23", "F_34", "F_14", "T2"]\nmethods = ["polygon"]')
    return text + extra


def test_a_pin_at_rest_takes_no_friction_couple():
    # At the rocker's limit ω4 is the rounding of a zero (1e-16 rad/s beside ω2 = 10): the
    # pin O4 does not turn, so its friction circle gives no couple; only B's, −ρ·|F| against
    # ω4 − ω3 = +4 rad/s, stands on link 4.
    ex = parse_exercise(_four_bar_at_the_rockers_limit(
        "\n[forces]\nfriction_circle = 5\n[[mass]]\nlink = 3\nmass = 2\n[[mass]]\nlink = 4\n"
        "mass = 1.5\n[[couple]]\nlink = 4\nmoment = 30\n"), "fb.toml")
    kin = solver.solve(ex.mechanism)
    assert abs(kin.omegas[4]) < 1e-14 * 10 and kin.omegas[3] == pytest.approx(-4.0, rel=1e-12)
    couples = pin_couples(ex.mechanism, kin, ex.loads, {p: 1.0 for p in ex.mechanism.pin_pairs})
    assert couples[4] == -0.005 and couples[1] == 0.005       # O2's alone on the frame
    worked = tarsim.solve(ex)
    assert worked.passed
    # The force polygons take O4 at rest too, to the velocity polygon's rounding, and say so.
    said = [dict(s.phrase.args)["pin"] for s in worked.positions[0].work.assembly
            if s.id.startswith("force:say:rest")]
    assert said == ["O4"]


def test_a_resistance_at_a_dead_centre_stands_still():
    # The piston at its inner dead centre (θ2 = 180°) does not move: a 1000 N resistance
    # then acts nowhere, and with no other load every force and the torque are 0.
    text = ENGINE.replace("angle = 40", "angle = 180") + (
        '\n[ask]\nfind = ["F_12", "F_23", "F_34", "F_14", "T2"]\nmethods = ["polygon"]\n'
        '\n[[force]]\nlink = 4\npoint = "P"\nresist = 1000\n')
    ex = parse_exercise(text, "engine.toml")
    kin = solver.solve(ex.mechanism)
    s = balance(ex.mechanism, kin, ex.loads)
    assert s.torque == 0.0 and all(j.size == 0.0 for j in s.joints)
    assert tarsim.solve(ex).passed


LIGHT_DYAD = """\
name = "a light dyad beside a heavy load at the crank's pivot"
[units]
length = "cm"
angle = "rad"
[frame]
O2 = [0.0, 0.0]
O4 = [-1.1303383200306396e-06, 0.0]
[[link]]
number = 2
points = ["O2", "A"]
lengths = { O2A = 9.511292610498989e-05 }
[[link]]
number = 3
points = ["A", "B"]
lengths = { AB = 1.6229509303720986e-05 }
[[link]]
number = 4
points = ["O4", "B"]
lengths = { O4B = 8.339481373716322e-05 }
[input]
link = 2
angle = -1000000000.0
omega = 10.0
[assembly]
B = "right"
[ask]
find = ["F_12", "F_14", "F_23", "F_34", "T2"]
methods = ["polygon"]
[forces]
gravity = false
[[mass]]
link = 3
mass = 0.67
centre = "B"
[[force]]
link = 2
point = "O2"
force = [632.4, 2104.5]
"""


def test_a_light_dyad_beside_a_heavy_pivot_load_is_solved_to_its_own_rounding():
    # 2200 N at the crank's pivot goes straight to the frame; the dyad carries only the
    # coupler's inertia, some 1e-6 N. Solved as one system, the dyad's forces were found to
    # the rounding of the 2200 N (T2 off by 15 %); refined against its exact residual, the
    # Newton–Euler torque is the balance of power's (which no joint force enters) to 1e-9.
    ex = parse_exercise(LIGHT_DYAD, "dyad.toml")
    kin = solver.solve(ex.mechanism)
    s = balance(ex.mechanism, kin, ex.loads)
    assert s.joint("F_12").size == pytest.approx(math.hypot(632.4, 2104.5), rel=1e-6)
    assert abs(s.torque) < 1e-11
    assert s.torque == pytest.approx(power_torque(ex.mechanism, kin, ex.loads), rel=1e-9)
    assert tarsim.solve(ex).passed


JAMMED = """\
name = "a slotted lever jammed by friction"
[units]
angle = "deg"
[frame]
O4 = [0.0, 0.0]
O2 = [0.0, 10.0]
[[link]]
number = 2
points = ["O2", "A"]
lengths = { O2A = 9.136783895943333 }
[[link]]
number = 3
points = ["A"]
[[link]]
number = 4
points = ["O4"]
[[link]]
number = 5
points = ["B"]
[[slider]]
link = 3
point = "A"
on = 4
[[slider]]
link = 5
point = "B"
on = 1
through = [0.0, 22.88521608304749]
angle = 0.0
[[slider]]
kind = "pin"
link = 5
point = "B"
on = 4
[input]
link = 2
angle = -62.555868906335036
omega = -10.0
alpha = 1e+25
[ask]
find = ["F_14", "F_12", "T2"]
methods = ["polygon"]
[forces]
friction = 0.3
[[mass]]
link = 5
mass = 5.0
centre = "B"
inertia = 0.1
[[mass]]
link = 2
mass = 3.0
centre = "A"
"""


def test_friction_that_holds_two_ways_is_refused():
    # μ = 0.3 with an inertia load of ~1e28 N: the slides' pushes hold on two sets of sides,
    # each a Newton–Euler solution consistent with the friction it takes, with driving
    # torques an order of magnitude apart. No one answer is the mechanism's.
    import itertools

    from tarsim.constructions.reference import kinetostatics as ks

    ex = parse_exercise(JAMMED, "jam.toml")
    mech = ex.mechanism
    kin = solver.solve(mech)
    held = []
    for signs in itertools.product((1.0, -1.0), repeat=len(mech.slides)):
        _, pushes = ks._solve(mech, kin, ex.loads, dict(enumerate(signs)), {})
        if all((1.0 if pushes[i] >= 0 else -1.0) == s for i, s in enumerate(signs)):
            held.append(signs)
    assert len(held) >= 2, held
    with pytest.raises(InputError, match=r"at θ2 = −62.5559° friction of μ = 0.3 holds the "
                                         r"slides' pushes on two sets of sides"):
        balance(mech, kin, ex.loads)


@pytest.mark.slow
@pytest.mark.parametrize("family", ["four-bar", "slider-crank", "slotted-lever", "unsupported"])
@settings(max_examples=12, deadline=None, derandomize=True,
          phases=[Phase.explicit, Phase.generate], suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 2**32 - 1))
def test_a_random_loaded_linkage_is_right_or_refused_in_a_located_line(family, seed):
    """tests/random_loads.py: the chapters' linkages with random masses, forces, couples,
    friction and flywheels, degenerate and broken ones included. Solved, the driving torque
    at each position (and round the turn, one case in four) is held to the balance of
    energy found by finite differences of the positions, T·ω = d(KE + PE)/dt − Σ F·v −
    Σ M·ω, which no joint force enters; refused, to one located line."""
    _, text = loads_case(random.Random(seed), family)
    with tempfile.TemporaryDirectory() as folder:
        got = run_loads_case(text, Path(folder) / f"{family}-{seed}.toml")
    assert got.outcome in ("ok", "refused"), (got.outcome, got.message, got.detail, text)
