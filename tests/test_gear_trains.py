"""Gear trains: the notes' planetary questions Q1–Q4 and a compound train, answered exactly
by the notes' own method and checked by the Willis equations solved as a linear system;
bad trains refused in one line naming the gears."""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.constructions.gears.tabular import tabulate
from tarsim.constructions.gears.train import Gear, GearTrain, Mesh
from tarsim.constructions.reference.willis import willis_speeds
from tarsim.exercises.catalog import bundled, load
from tarsim.exercises.cli import cli
from tarsim.exercises.gears.train_file import parse_train
from tarsim.exercises.gears.train_solution import solve_train

F = Fraction


def solved(name):
    return solve_train(load(name))


def test_q1_the_planet_turns_60_rpm_against_the_sun_and_the_arm_24_with_it():
    s = solved("planetary-q1")
    sun, arm, planet = s.found.speeds[2], s.found.speeds[3], s.found.speeds[4]
    assert (sun, planet, arm) == (F(-80), F(60), F(-24))       # the question's cw sun
    t = s.found.table
    # the notes' table: 0, +10/3, −5/2, +1 for the ring, sun, planet and arm
    assert [t.total[m] for m in (1, 2, 4, 3)] == [0, F(10, 3), F(-5, 2), 1]
    assert [t.held[m] for m in (1, 2, 4, 3)] == [-1, F(7, 3), F(-7, 2), 0]


def test_q2_gives_the_notes_ratio_of_minus_three_sevenths():
    s = solved("planetary-q2")
    assert s.quantities["omega5/omega4"].exact == F(-3, 7)
    assert (s.found.speeds[4], s.found.speeds[5]) == (F(140), F(-60))
    assert [s.found.table.total[m] for m in (3, 2, 4, 5)] == [1, 0, F(7, 3), -1]


@pytest.mark.parametrize("name", ["planetary-q1", "planetary-q2", "planetary-q3", "planetary-q4"])
def test_every_planet_drawn_stands_on_a_pin_of_the_arm(name):
    # Q2's second planet meshes with the first only, at a larger carrier radius: the arm
    # carries it on a pin of its own, as it does the first.
    fig = solved(name).figures["train"]
    links = [p.points for p in fig.items if getattr(p, "style", "") == "link"]
    boxes = [pts for pts in links if len(pts) == 4 and pts[0][1] == pts[1][1]]
    axis = next(p.points[0][1] for p in fig.items if getattr(p, "style", "") == "reference")
    planets = 0
    for box in boxes:
        xs, ys = [x for x, _ in box], [y for _, y in box]
        y = (min(ys) + max(ys)) / 2
        if abs(y - axis) < 1e-6 or max(ys) - min(ys) < 3.5:     # on the main axis, or a rim
            continue
        planets += 1
        assert any(a[1] == b[1] and abs(a[1] - y) < 1e-9 and min(a[0], b[0]) < min(xs)
                   and max(a[0], b[0]) >= max(xs) - 1e-9
                   for pts in links if pts is not box for a, b in zip(pts, pts[1:])), (name, y)
    assert planets >= 2                     # each planet drawn above the axis and below


def test_q3_the_reverted_train_has_the_notes_train_value_five_ninths():
    s = solved("planetary-q3")
    assert s.quantities["omega5/omega6"].exact == F(5, 9)
    assert s.found.table.held[5] == F(-40 * 40, 60 * 60)        # −(40×40)/(60×60)


def test_q4_the_output_ring_turns_a_thirty_sixth_of_the_sun():
    s = solved("planetary-q4")
    assert s.quantities["omega5/omega2"].exact == F(1, 36)
    assert [s.found.table.total[m] for m in (1, 2, 3, 4, 5, 6)] == \
        [0, 8, F(-4, 3), F(-4, 3), F(2, 9), 1]


def test_the_compound_train_value_cancels_its_idler():
    s = solved("compound-train")
    assert s.quantities["omega6/omega2"].exact == F(-20 * 25, 60 * 75)      # −1/9
    assert s.found.speeds[6] == F(100)                                        # 900 cw in


def test_steps_md_gives_the_mesh_in_millimetres_and_degrees_as_the_terminal_does():
    """The spur pair of module 10, 20 and 40 teeth at 20°: its results table says the
    circular pitch πm, the path of contact √(ra₂² − rb₂²) + √(ra₃² − rb₃²) − (r₂ + r₃) sin φ
    (addendum one module) and the contact ratio path / (πm cos φ), not the exact fractions
    of their floats."""
    import math

    m, phi, r2, r3 = 10.0, math.radians(20.0), 100.0, 200.0
    path = (math.sqrt((r2 + m) ** 2 - (r2 * math.cos(phi)) ** 2)
            + math.sqrt((r3 + m) ** 2 - (r3 * math.cos(phi)) ** 2) - (r2 + r3) * math.sin(phi))
    table = solved("involute-pair").steps().split("## Results")[1]
    rows = {cells[0]: cells[1:3] for line in table.splitlines() if line.startswith("| ")
            for cells in [[c.strip() for c in line.strip("|").split("|")]]}
    assert rows["pressure_angle"] == ["20°", "20°"]
    assert rows["circular_pitch"] == [f"{math.pi * m:.6g} mm"] * 2
    assert rows["path_of_contact"] == [f"{path:.6g} mm"] * 2
    assert rows["contact_ratio"] == [f"{path / (math.pi * m * math.cos(phi)):.6g}"] * 2
    assert rows["least_teeth"][0] == "15 teeth on the pinion"
    assert "/" not in "".join(rows["arc_of_contact"])


@pytest.mark.parametrize("name", sorted(bundled("gears")))
def test_every_bundled_train_agrees_with_willis_exactly(name):
    s = solved(name)
    assert s.passed
    assert s.found.speeds == {m: s.reference[m] for m in s.found.speeds}
    # a planet listed twice is solved whole by Willis: the copy turns as its planet
    assert set(s.reference) == set(s.found.speeds) | {c for c, _ in s.exercise.twins}
    assert all(s.reference[c] == s.reference[f] for c, f in s.exercise.twins)


def test_a_near_unity_reverted_train_keeps_its_fraction_exact():
    """A reverted train of 100/101 and 100/101 teeth: 1 − 10000/10201, which floating point
    holds to 1e-16 only; the tabular method gives 201/10201 itself."""
    train = GearTrain(
        (Gear(2, 100), Gear(3, 101, carrier=6), Gear(4, 100, carrier=6), Gear(5, 101)),
        (Mesh(2, 3), Mesh(4, 5)), ((3, 4),), arm=6, fixed=2, input_member=6,
        input_speed=F(1))
    train.check()
    assert tabulate(train).speeds[5] == F(201, 10201) == willis_speeds(train)[5]


@settings(max_examples=60, deadline=None)
@given(sun=st.integers(12, 90), planet=st.integers(12, 60),
       fixed=st.sampled_from(("sun", "ring")), driver=st.sampled_from(("sun", "ring", "arm")),
       speed=st.integers(-3000, 3000).filter(bool))
def test_the_tabular_method_is_the_willis_solution(sun, planet, fixed, driver, speed):
    ring = sun + 2 * planet
    number = {"ring": 1, "sun": 2, "arm": 3}
    if fixed == driver:
        driver = "arm"
    train = GearTrain((Gear(1, ring), Gear(2, sun), Gear(4, planet, carrier=3)),
                      (Mesh(2, 4), Mesh(4, 1, internal=True)), arm=3, fixed=number[fixed],
                      input_member=number[driver], input_speed=F(speed))
    train.check()
    assert tabulate(train).speeds == willis_speeds(train)


# ----- bad trains ------------------------------------------------------------------------------
Q1 = (Path(bundled("gears")["planetary-q1"])).read_text(encoding="utf-8")


@pytest.mark.parametrize("old, new, words", [
    # sizes not given: 50 and 50.5 modules are the book's to make good (a corrected ring)
    ("teeth = 140", "teeth = 141", []),
    ("fixed = 1", "fixed = [1, 2]", ["2 fixed members (1, 2)"]),
    ("fixed = 1", "", ["no member is fixed"]),
    ("teeth = 60", "teeth = 60\nmodule = 2", []),             # one module given: still fits
    ("[arm]\nnumber = 3", "[arm]\nnumber = 3\nplanets = 3",
     ["3 planets cannot be spaced equally", "60 + 140 = 200"]),
    ("[arm]\nnumber = 3", "[arm]\nnumber = 3\nplanets = 8",
     ["8 planets gear 4 (planet) do not fit round the sun"]),
    ("member = 2\nspeed", "member = 1\nspeed", ["the input, member 1, is the fixed member"]),
    ("gears = [2, 4]", "gears = [2, 7]", ["a mesh names gear 7, which is not listed"]),
    ("[input]", "[[gear]]\nnumber = 9\nteeth = 30\n\n[input]",
     ["gear 9 is joined to the rest of the train by no mesh or shaft"]),
    ('sense = "cw"', 'sense = "up"', ["unknown sense 'up'"]),
])
def test_a_bad_train_is_refused_in_one_line_naming_the_gears(old, new, words):
    assert old in Q1
    text = Q1.replace(old, new, 1)
    if not words:
        parse_train(text, "q1.toml")
        return
    with pytest.raises(InputError) as e:
        s = solve_train(parse_train(text, "q1.toml"))
        s.lines()
    message = str(e.value)
    assert "\n" not in message and message.startswith("q1.toml")
    for w in words:
        assert w in message, message


def test_gears_of_different_modules_may_not_mesh():
    text = (Q1.replace("teeth = 140", "teeth = 140\nmodule = 3", 1)
            .replace("teeth = 40", "teeth = 40\nmodule = 2", 1))
    lines = text.splitlines()
    table = lines.index("number = 4")            # the line after gear 4's [[gear]]
    with pytest.raises(InputError, match=rf"^q1\.toml:{table}: gear 4 \(planet\) \(module 2 mm\) "
                                         r"and gear 1 \(ring\) \(module 3 mm\) mesh but their "
                                         r"modules differ$"):
        parse_train(text, "q1.toml")


def test_modules_given_set_the_centre_distances_in_millimetres():
    text = Q1.replace("teeth = 140", "teeth = 141\nmodule = 2", 1)
    for n in ("60", "40"):
        text = text.replace(f"teeth = {n}", f"teeth = {n}\nmodule = 2", 1)
    with pytest.raises(InputError, match=r"gear 2 \(sun\) puts it 100 mm from the main axis, "
                                         r"with gear 1 \(ring\) 101 mm"):
        parse_train(text, "q1.toml")


def test_a_train_with_a_free_planet_has_two_degrees_of_freedom():
    text = Q1.replace("[arm]", "[[gear]]\nnumber = 9\nteeth = 30\ncarrier = 3\n\n[arm]", 1)
    with pytest.raises(InputError, match=r"2 degrees of freedom by Grübler \(3\(5 − 1\) − "
                                         r"2·4 − 2 = 2\), not 1: a member turns freely"):
        parse_train(text, "q1.toml")


# ----- the command line ----------------------------------------------------------------------
def test_solve_writes_the_table_steps_and_exact_results(tmp_path):
    out = tmp_path / "q4"
    result = CliRunner().invoke(cli, ["solve", "planetary-q4", "-o", str(out), "--no-pdf"])
    assert result.exit_code == 0, result.output
    assert "ω5/ω2 = 1/36" in result.output
    doc = json.loads((out / "results.json").read_text(encoding="utf-8"))
    q = doc["quantities"]["omega5/omega2"]
    assert (q["exact"], q["reference"]["exact"], q["rel_error"]) == ("1/36", "1/36", 0.0)
    w5 = doc["quantities"]["omega5"]
    assert w5["exact"] == "50" and w5["exact_unit"] == "rpm" and w5["rpm"] == 50.0
    assert w5["unit"] == "rad/s"
    assert w5["value"] == pytest.approx(50 * 2 * 3.141592653589793 / 60, rel=1e-15)
    steps = (out / "steps.md").read_text(encoding="utf-8")
    assert "Row 2: hold the arm 6 and turn gear 1 (fixed ring), the fixed member, −1" in steps
    assert (out / "table.svg").exists()


def test_a_linkage_command_refuses_a_train_in_one_line():
    result = CliRunner().invoke(cli, ["check", "planetary-q1"])
    assert result.exit_code == 1
    assert result.output == ("Error: planetary-q1 is a gear train: `tarsim solve planetary-q1` "
                             "solves it; this command is for linkages\n")


def test_draw_sets_a_train_in_side_view(tmp_path):
    out = tmp_path / "q4.svg"
    result = CliRunner().invoke(cli, ["draw", "planetary-q4", "-o", str(out)])
    assert result.exit_code == 0, result.output
    svg = out.read_text(encoding="utf-8")
    assert "the train" in svg and 'class="hatch"' in svg


Q4 = (Path(bundled("gears")["planetary-q4"])).read_text(encoding="utf-8")


@pytest.mark.parametrize("given, t_in", [("torque = 20", F(20)),
                                         ("power = 3769.911184307752", None)])
def test_the_output_and_holding_torques_balance_power_and_torque(given, t_in):
    """The sun at 1800 rpm driven by 20 N·m (or by the power that is, 20 × 1800·2π/60 W):
    the output ring at 50 rpm takes 20 × 36 = 720 N·m against its motion, and the fixed
    ring holds the difference, 700 N·m."""
    text = Q4.replace('sense = "ccw"', f'sense = "ccw"\n{given}', 1).replace(
        'find = ["omega5/omega2", "omega5", "omega6"]',
        'find = ["omega5/omega2", "torque5", "torque1", "torque2"]', 1)
    s = solve_train(parse_train(text, "q4.toml"))
    q = s.quantities
    assert s.passed
    # (a power given: each torque exact over π, its N·m in .si)
    assert q["torque5"].si == pytest.approx(-720.0, rel=1e-13)
    assert q["torque1"].si == pytest.approx(700.0, rel=1e-13)
    assert q["torque2"].si == pytest.approx(20.0, rel=1e-13)
    if t_in is not None:                        # a torque given keeps every torque exact
        assert (q["torque5"].exact, q["torque1"].exact) == (F(-720), F(700))
    assert "T1 = −(T2 + T5) = 700 N·m" in s.steps()


def test_a_holding_torque_needs_the_output_load():
    text = Q4.replace('sense = "ccw"', 'sense = "ccw"\ntorque = 20', 1).replace(
        'find = ["omega5/omega2", "omega5", "omega6"]', 'find = ["torque1"]', 1)
    with pytest.raises(InputError, match="holding torque needs the output's"):
        parse_train(text, "q4.toml")


# ----- the velocity (Kutzbach) diagram ---------------------------------------------------------
@pytest.mark.parametrize("name", ["planetary-q1", "planetary-q3", "planetary-q4"])
def test_the_velocity_diagram_reads_every_speed_the_table_gives(name):
    s = solved(name)
    k = s.diagram
    per = s.train.units.per_rad_s
    fastest = max(abs(float(v)) for v in s.found.speeds.values()) * per
    for m, v in s.found.speeds.items():
        # read as slopes of drawn lines: a few roundings of the drawing's coordinates
        assert abs(k.omegas[m] - float(v) * per) <= 1e-12 * fastest, m
    assert not s.diagram_misses


def test_q1_diagram_draws_the_planet_through_its_two_pitch_points_and_the_arm_through_c():
    k = solved("planetary-q1").diagram
    assert k.through[(4,)] == ("kz:pitch:2-4", "kz:pitch:1-4")
    assert k.through[(3,)] == ("kz:O", "kz:centre")
    assert k.lines[(1,)] == "kz:radial"                      # the fixed ring: v = 0
    # the pitch point with the fixed ring stands on the radial line, the centre half way
    x14 = k.construction.output("kz:pitch:1-4").xy[0]
    xc = k.construction.output("kz:centre").xy[0]
    x24 = k.construction.output("kz:pitch:2-4").xy[0]
    assert x14 == pytest.approx(0.0, abs=1e-15)
    assert xc == pytest.approx(x24 / 2, rel=1e-12)           # R = 50 is mid-way r2 = 30 … r1 = 70


def test_planets_meshing_with_each_other_get_no_diagram():
    assert solved("planetary-q2").diagram is None
    from tarsim.constructions.gears.kutzbach import draw_kutzbach

    s = solved("planetary-q2")
    with pytest.raises(InputError, match="gear 4 \\(planet\\) and gear 5 \\(second planet\\) "
                                         "are both planets"):
        draw_kutzbach(s.train, s.found.speeds)


def test_a_diagram_that_reads_a_speed_wrong_fails_the_solve():
    s = solved("planetary-q1")
    s.diagram.omegas[4] *= 1 + 1e-6
    assert s.diagram_misses == [4] and not s.passed
    assert "omega4 (velocity diagram)" in s.failures


def test_the_diagram_has_its_figure_and_its_steps():
    s = solved("planetary-q4")
    fig = s.figures["kutzbach"]
    texts = [t.text for t in fig.items if hasattr(t, "text")]
    assert "ω₅ = 50 rpm ccw" in texts and "ω₆ = 225 rpm ccw" in texts
    steps = s.steps()
    assert "## The velocity (Kutzbach) diagram (`kutzbach.svg`)" in steps
    assert "The planet 3–4 is one body: its line runs through P13 and" in steps


# ----- the involute mesh -----------------------------------------------------------------------
PAIR = (Path(bundled("gears")["involute-pair"])).read_text(encoding="utf-8")


def test_the_drawn_mesh_reads_the_textbook_path_arc_and_contact_ratio():
    """Module 10 mm, 20 and 40 teeth at 20°: the path of contact √(110² − 93.97²) +
    √(210² − 187.9²) − 300 sin 20° = 48.27 mm, its arc 51.37 mm, the ratio 1.635."""
    s = solved("involute-pair")
    q = s.quantities
    assert s.passed
    assert q["path_of_contact"].si == pytest.approx(0.0482728, rel=1e-6)
    assert q["arc_of_contact"].si == pytest.approx(0.0513709, rel=1e-6)
    assert q["contact_ratio"].si == pytest.approx(1.635186, rel=1e-6)
    for name in ("path_of_contact", "arc_of_contact", "contact_ratio", "pressure_angle"):
        assert q[name].rel_error <= 1e-12, name         # a few roundings of one construction
    assert s.mesh.interference == ()


def test_every_drawn_profile_point_lies_on_its_involute_and_both_pass_p():
    from tarsim.constructions.reference.gear_mesh import involute_miss

    s = solved("involute-pair")
    m = s.mesh
    assert not s.profile_misses
    p = m.construction.output("P").xy
    for gear, base in ((2, m.radii["base2"]), (3, m.radii["base3"])):
        assert involute_miss(p, m.centres[gear], base, m.starts[gear]) <= 1e-15
        assert len(m.profiles[gear]) == 9


def test_a_wider_centre_distance_keeps_the_ratio_and_leans_the_line_of_action():
    """Fig 4 of the text: O3 moved out to 305 mm, the base circles are as they were, so the
    pitch point still divides O2O3 as 1 : 2 and the ratio stays; the working pressure angle
    grows to acos((93.97 + 187.94)/305) = 22.44°."""
    import math

    text = PAIR.replace("pressure_angle = 20", "pressure_angle = 20\ncentre_distance = 305")
    s = solve_train(parse_train(text, "pair.toml"))
    assert s.passed
    assert s.quantities["omega3/omega2"].exact == F(-1, 2)
    want = math.acos(0.300 * math.cos(math.radians(20)) / 0.305)
    assert s.mesh.pressure_angle == pytest.approx(want, rel=1e-12)
    c = s.mesh.construction
    o2p = c.output("P").xy[0]
    assert (0.305 - o2p) / o2p == pytest.approx(2.0, rel=1e-12)       # O3P′/O2P′ = ω2/ω3


def test_a_small_pinion_interferes_as_the_formula_says():
    """12 teeth against 60 at 20°: fewer than the 16 a 1 : 5 pair needs; the wheel's tips
    reach past T2 into the pinion's flank, in the drawing and by the formula."""
    from tarsim.constructions.reference.gear_mesh import least_teeth

    text = PAIR.replace("teeth = 20", "teeth = 12").replace("teeth = 40", "teeth = 60")
    s = solve_train(parse_train(text, "pair.toml"))
    assert least_teeth(5, 20) == 16
    assert s.mesh.interference == s.mesh_reference.interference == (3,)
    assert s.quantities["interference"].passed
    assert "the tips of gear 3 cut into the other's flank" in "\n".join(s.lines())


@pytest.mark.parametrize("old, new, words", [
    ("module = 10\n\n[[gear]]", "\n[[gear]]", ["give gear 2 (pinion) and gear 3 (wheel) their "
                                              "module"]),
    ("pressure_angle = 20", "pressure_angle = 60", ["a pressure angle of 60° is not a gear's"]),
    ("pressure_angle = 20", "pressure_angle = 20\ncentre_distance = 250",
     ["gears 2 and 3 have no line of action: the centre distance 250 mm leaves their base "
      "circles"]),
    ("gears = [2, 3]             # the driver first", "gears = [2, 5]",
     ["there is no gear 5"]),
])
def test_a_bad_involute_mesh_is_refused_in_one_line(old, new, words):
    assert old in PAIR
    with pytest.raises(InputError) as e:
        solve_train(parse_train(PAIR.replace(old, new, 1), "pair.toml"))
    assert "\n" not in str(e.value)
    for w in words:
        assert w in str(e.value), str(e.value)


def test_a_diametral_pitch_is_a_module_of_one_inch_over_it():
    text = PAIR.replace("module = 10", "diametral_pitch = 2.54")     # 10 mm exactly
    s = solve_train(parse_train(text, "pair.toml"))
    assert s.train.gear(2).module == F(1, 100)
    assert s.quantities["contact_ratio"].si == pytest.approx(1.635186, rel=1e-6)


def test_the_train_is_drawn_in_side_view_with_the_fixed_member_hatched():
    from tarsim.graphics.figure import Path as FPath

    s = solved("planetary-q4")
    fig = s.figures["train"]
    texts = {t.text for t in fig.items if hasattr(t, "text")}
    assert {"1", "2", "3", "4", "5", "6"} <= texts
    hatch = [it for it in fig.items if isinstance(it, FPath) and it.style == "hatch"]
    assert hatch                                       # the fixed ring, held by its rims
    boxes = [it for it in fig.items if isinstance(it, FPath) and it.style == "link" and it.closed]
    assert len(boxes) == 2 * 2 + 1 + 2 * 2             # planets 3, 4 twice; sun; two rings' rims
    # at 1 cm = 20 modules, planet 3 (60 teeth: 30 mm tall) stands at the carrier radius,
    # 40 modules = 20 mm, above and below the main axis
    assert "1 cm = 20 modules" in " ".join(texts)
    tall = [b for b in boxes if abs(max(p[1] for p in b.points) - min(p[1] for p in b.points)
                                    - 30.0) < 1e-9]
    (axis,) = [it.points[0][1] for it in fig.items
               if isinstance(it, FPath) and it.style == "reference"]
    assert sorted(round((max(p[1] for p in b.points) + min(p[1] for p in b.points)) / 2 - axis,
                        9) for b in tall) == [-20.0, 20.0]
    # an ordinary train: each gear on its own axis, a centre distance above the one that
    # drives it (2; 3 and 4 on one shaft; the idler 5; 6): four axes
    ordinary = solved("compound-train").figures["train"]
    axes = sorted(it.points[0][1] for it in ordinary.items
                  if isinstance(it, FPath) and it.style == "reference")
    assert len(axes) == 4
    steps = [round(b - a, 9) for a, b in zip(axes, axes[1:])]
    # at 1 cm = 50 modules: 57.5, 32.5 and 40 modules apart (r5 + r6, r4 + r5, r2 + r3)
    assert steps == [11.5, 6.5, 8.0]


@pytest.mark.parametrize("ratio, angle, least", [(1, 20, 13), (2, 20, 15), (1000, 20, 18),
                                                 (1, 14.5, 23), (5, 25, 11)])
def test_the_fewest_teeth_free_of_interference_drawn_and_by_formula(ratio, angle, least):
    """The mesh drawn again with a tooth more each time until the wheel's tips clear T2,
    against N ≥ 2k/((1 + 2G) sin²φ)·(G + √(G² + (1 + 2G) sin²φ)): 13 for a 1 : 1 pair at 20°,
    18 against a rack, 23 at 14.5°."""
    from tarsim.constructions.gears.involute import Involute, least_teeth_drawn
    from tarsim.constructions.reference.gear_mesh import least_teeth

    drawn = least_teeth_drawn(0.005, ratio, Involute(2, 3, angle))
    assert drawn == least_teeth(ratio, angle) == least


def test_the_circular_pitch_is_one_tooth_stepped_round_the_pitch_circle():
    import math

    s = solved("involute-pair")
    q = s.quantities["circular_pitch"]
    assert q.si == pytest.approx(math.pi * 0.010, rel=1e-14) and q.passed
    c = s.mesh.construction
    assert math.dist(c.output("P").xy, c.output("P1").xy) == pytest.approx(
        2 * 0.100 * math.sin(math.pi / 20), rel=1e-14)               # the chord of 18°


def test_a_train_with_its_arm_held_is_an_ordinary_train():
    """Q1 with the arm fixed instead of the ring: every axis stands still, so the planet
    turns 80 × 60/40 = 120 rpm against the sun and the ring 80 × 60/140 with the planet."""
    s = solve_train(parse_train(Q1.replace("fixed = 1", "fixed = 3", 1), "q1.toml"))
    assert s.found.table is None and s.passed
    assert s.found.speeds == {1: F(240, 7), 2: F(-80), 4: F(120), 3: F(0)}


def test_an_unknown_input_member_is_refused_at_its_line():
    text = Q1.replace("member = 2\nspeed", "member = 9\nspeed", 1)
    line = text.splitlines().index("member = 9") + 1
    with pytest.raises(InputError, match=rf"^q1\.toml:{line}: there is no member 9; the members "
                                         r"are 1, 2, 4, 3$"):
        parse_train(text, "q1.toml")


def test_a_pinion_on_a_side_shaft_drives_the_sun_as_an_ordinary_pair():
    """Q1's sun (60 teeth) driven by a pinion 5 (20) on a shaft of its own at 80 rpm cw:
    ω2 = 80·20/60 = 80/3 ccw; then the table, the ring fixed: ω3 = ω2·60/(140 + 60) = 8,
    ω4 = ω3 − (ω2 − ω3)·60/40 = −20. The pinion has no column in the table, nor a line in
    the velocity diagram, which starts from the sun."""
    text = (Q1.replace("[arm]", '[[gear]]\nnumber = 5\nname = "pinion"\nteeth = 20\n\n[arm]', 1)
            .replace("gears = [2, 4]", "gears = [2, 4]\n\n[[mesh]]\ngears = [5, 2]", 1)
            .replace("member = 2\nspeed", "member = 5\nspeed", 1))
    s = solve_train(parse_train(text, "q1.toml"))
    assert s.found.speeds == s.reference == {1: 0, 2: F(80, 3), 4: F(-20), 5: F(-80), 3: F(8)}
    assert s.passed and s.train.off_axis == (5,)
    assert set(s.diagram.omegas) == {1, 2, 3, 4} and s.diagram.through[(2,)] == ("kz:O", "kz:v:2")
    assert "| whole train locked, +1 | +1 | +1 | +1 |  | +1 |" in s.steps()
