"""Balancing by the force and couple polygons (001 ch. 7), against the vector sums.

- The notes' Example 1: the book prints 61.4 N at 124.4° (its numbers take sin 225° as
  +√2/2); the true balancing product is 1.3907 kg·m at 3.90°, the polygon's vertices
  (0.17321, 0.1), (−0.32679, 0.96603), (−1.38746, −0.09463) kg·m (the digest's).
- Two planes: the balanced rotor's force and couple vanish, and a pure couple (two equal
  masses opposite, apart along the shaft) is held by equal and opposite masses.
- Engines: the single cylinder's forces by the textbook formulas; the in-line four's
  primary forces and couples balanced, its secondary forces 4·m·ω²·r/n.
Tolerances: sums of a few products of order 1 kg·m, 1e-12 relative.
"""

from __future__ import annotations

import cmath
import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.constructions.balancing.rotor import Engine, Mass, Plane, Rotor
from tarsim.constructions.balancing.engine import draw_engine
from tarsim.constructions.balancing.polygons import draw_balance
from tarsim.constructions.errors import InputError
from tarsim.constructions.reference.balance import quadrant_angle, resultant
from tarsim.exercises.balancing.balance_solution import solve_balance
from tarsim.exercises.catalog import bundled, load
from tarsim.exercises.cli import cli
from tarsim.exercises.balancing.rotor_file import parse_balance


def test_the_notes_example_balances_at_1_3907_kg_m_and_3_90_degrees():
    s = solve_balance(load("notes-example-1"))
    assert s.passed, s.failures
    v = s.balance.product("B")
    assert math.hypot(*v) == pytest.approx(1.39068, abs=5e-6)
    assert math.degrees(math.atan2(v[1], v[0])) == pytest.approx(3.9020, abs=5e-4)
    c = s.balance.construction
    tips = [c.output(r).xy for _, r in s.balance.force]
    want = [(0.17321, 0.10000), (-0.32679, 0.96603), (-1.38746, -0.09463)]
    for got, w in zip(tips, want):
        assert got == pytest.approx(w, abs=5e-6)
    x, y = resultant(s.exercise.rotor.masses)
    assert quadrant_angle(x, y) == pytest.approx(183.902, abs=5e-4)     # third quadrant
    assert math.hypot(x, y) * 25 == pytest.approx(34.767, abs=5e-4)      # N at 5 rad/s
    assert math.hypot(*v) / 0.1 == pytest.approx(13.9068, abs=5e-4)       # kg at 0.1 m


def test_the_reference_radius_shows_past_a_mass_that_lies_along_it(solved):
    # The four-mass shaft's mass 1 sits at 0°: the caption points to "the short dashed one",
    # so it must run on beyond mass 1's circle, not lie hidden under its radial line.
    fig = solved("four-mass-shaft").figures["space"]
    ref = next(p.points for p in fig.items if getattr(p, "style", "") == "reference")
    (x0, y0), (x1, y1) = ref
    on_it = [c for c in fig.items if getattr(c, "style", "") == "pin"
             and abs(c.centre[1] - y0) < 1e-6 and c.centre[0] > x0]
    assert on_it and y1 == y0
    assert x1 >= max(c.centre[0] + c.radius for c in on_it) + 5.0


def test_the_books_erratum_is_sin_225_taken_positive():
    """With sin 225° = +√2/2 the sums are the book's: ΣF_y = 2.0267, 61.40 N at 124.4°."""
    wrong_y = 0.2 * math.sin(math.radians(30)) + 1.0 * math.sin(math.radians(120)) \
        + 1.5 * math.sqrt(2) / 2
    x, _ = resultant(load("notes-example-1").rotor.masses)
    assert wrong_y == pytest.approx(2.0267, abs=5e-5)
    assert math.hypot(x, wrong_y) * 25 == pytest.approx(61.40, abs=5e-3)
    assert quadrant_angle(x, wrong_y) == pytest.approx(124.4, abs=0.05)


def test_two_planes_leave_no_force_and_no_couple():
    s = solve_balance(load("four-mass-shaft"))
    assert s.passed, s.failures
    force, couple = s.residual
    assert force < 1e-12 * 60 and couple < 1e-12 * 60


def test_a_pure_couple_is_held_by_equal_and_opposite_masses():
    """Two 1 kg masses at 0.1 m, at 0° and 180°, in planes 0.2 and 0.4 m: no resultant
    force, a couple 0.02 kg·m²; planes at 0 and 0.6 m take 0.0333 kg·m each, opposite."""
    rotor = Rotor((Mass("1", 1, 0.1, 0.0, 0.2), Mass("2", 1, 0.1, math.pi, 0.4)),
                  (Plane("A", 0.0, 0.1), Plane("B", 0.6, 0.1)), 10.0)
    b = draw_balance(rotor)
    a, bb = b.product("A"), b.product("B")
    assert a == pytest.approx((-0.1 * 0.2 / 0.6, 0.0), abs=1e-15)
    assert bb == pytest.approx((0.1 * 0.2 / 0.6, 0.0), abs=1e-15)


def test_the_single_cylinder_forces_are_the_textbooks():
    """m·ω²·r = 1.5 × (60π)² × 0.05 = 2664.79 N; at 30°: primary 2664.79·cos 30°, secondary
    2664.79·cos 60°/4; two thirds balanced: (1/3)·2664.79·cos 30° along, (2/3)·2664.79·sin 30°
    across."""
    s = solve_balance(load("single-cylinder"))
    f = 1.5 * (60 * math.pi) ** 2 * 0.05
    q = s.results["quantities"]
    assert q["primary_force"]["value"] == pytest.approx(f * math.cos(math.radians(30)),
                                                        rel=1e-12)
    assert q["secondary_force"]["value"] == pytest.approx(f * 0.5 / 4, rel=1e-12)
    assert q["unbalanced_along"]["value"] == pytest.approx(f / 3 * math.cos(math.pi / 6),
                                                           rel=1e-12)
    assert q["unbalanced_across"]["value"] == pytest.approx(2 * f / 3 * 0.5, rel=1e-12)


def test_the_inline_four_leaves_only_its_secondary_forces():
    s = solve_balance(load("inline-four"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    f = 1.5 * (60 * math.pi) ** 2 * 0.05
    assert q["primary_force"]["value"] < 1e-9 * f
    assert q["primary_couple"]["value"] < 1e-9 * f
    assert q["secondary_force"]["value"] == pytest.approx(4 * f / 4, rel=1e-12)
    assert q["secondary_couple"]["value"] < 1e-9 * f
    assert "secondary force: unbalanced" in "\n".join(s.lines())


def test_a_three_cylinder_engine_balances_its_forces_not_its_couples():
    """Cranks 120° apart: both force polygons close (an equilateral triangle); the couples
    about the central plane do not: primary √3·m·r·a, a the pitch."""
    e = Engine(tuple(math.radians(a) for a in (0, 120, 240)), (0.0, 0.1, 0.2), 0.05, 0.2,
               1.0, 100.0)
    p = draw_engine(e)
    assert p.left("primary force") < 1e-15 and p.left("secondary force") < 1e-15
    assert p.left("primary couple") == pytest.approx(math.sqrt(3) * 0.05 * 0.1, rel=1e-12)


TEXT = Path(bundled("balancing")["four-mass-shaft"]).read_text(encoding="utf-8")


@pytest.mark.parametrize("old, new, words", [
    ("plane = 900\nradius = 100", "plane = 900\nradius = 0",
     "balancing plane B's radius must be positive"),
    ("plane = 900", "plane = 0", "stand at the same axial position"),
    ("radius = 80\nangle = 0", "radius = 80\nangle = 0\ncolour = 1", "unknown setting 'colour'"),
    ("plane = 900\nradius = 100", "plane = 900\nradius = 100\nmass = 3",
     "gives the radius its mass goes at, or the mass"),
])
def test_a_bad_rotor_is_refused_in_one_line(old, new, words):
    assert old in TEXT
    with pytest.raises(InputError) as e:
        parse_balance(TEXT.replace(old, new, 1), "rotor.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("rotor.toml:") and words in message, \
        message


def test_a_rotor_with_no_balancing_plane_gives_its_out_of_balance_force():
    """With no [[balance]] the rotor is not balanced but asked its out-of-balance force:
    |Σ mᵢrᵢ e^{iθᵢ}|·ω², the resultant the balancing product would be the opposite of."""
    cut = TEXT[:TEXT.index("[[balance]]")]
    ex = parse_balance(cut, "rotor.toml")
    q = solve_balance(ex).results["quantities"]
    x, y = resultant(ex.rotor.masses)
    assert q["unbalanced_force"]["value"] == pytest.approx(
        math.hypot(x, y) * ex.rotor.speed ** 2, rel=1e-12)


def test_solve_writes_the_polygons_table_and_steps(tmp_path):
    out = tmp_path / "b"
    result = CliRunner().invoke(cli, ["solve", "four-mass-shaft", "-o", str(out), "--no-pdf"])
    assert result.exit_code == 0, result.output
    assert {"space.svg", "side.svg", "table.svg", "couple-polygon.svg",
            "force-polygon.svg"} <= {p.name for p in out.iterdir()}
    steps = (out / "steps.md").read_text(encoding="utf-8")
    assert "The couple polygon, plane A the reference" in steps
    doc = json.loads((out / "results.json").read_text(encoding="utf-8"))
    got, want = doc["quantities"]["mr_B"]["value"], doc["quantities"]["mr_B"]["reference"]["value"]
    assert got == pytest.approx(want, abs=1e-12)
    result = CliRunner().invoke(cli, ["check", "four-mass-shaft"])
    assert result.exit_code == 1 and "is a balancing exercise" in result.output


@pytest.mark.parametrize("second, place, case", [(3.0, 0.6, "2-1, between"),
                                                  (-3.0, 3.0, "2-2, outside")])
def test_masses_in_one_axial_plane_take_one_mass_for_force_and_couple(second, place, case):
    """The notes' cases 2-1 and 2-2: m₁r₁ = 2 kg·m at l = 0 and m₂r₂ = ±3 kg·m at l = 1 m
    (the same way, or opposite). Moments about each mass's plane: M r·L₁ = m₁r₁·L and so on,
    so M r = 5 kg·m at 0.6 m (between them), or 1 kg·m at 3 m (outside, L_S = 2 m beyond
    m₂: (L + L_S)·M r = L·m₂r₂ gives 3 × 1 = 1 × 3)."""
    masses = (Mass("1", 2.0, 1.0, 0.0, 0.0),
              Mass("2", abs(second), 1.0, 0.0 if second > 0 else math.pi, 1.0))
    text = "\n".join(f"[[mass]]\nname = \"{m.name}\"\nmass = {m.mass}\nradius = 1\n"
                     f"angle = {math.degrees(m.angle)}\nplane = {m.plane}" for m in masses)
    ex = parse_balance(f"[rotor]\nspeed = 10\n{text}\n[[balance]]\nplane = {place}\n"
                       "radius = 1\n", "axial.toml")
    s = solve_balance(ex)
    words = "\n".join(s.lines())
    assert f"the notes' case {case}" in words
    v = s.balance.product("A")
    assert math.hypot(*v) == pytest.approx(abs(2.0 + second), rel=1e-14)
    # no couple left: the plane is where the moments vanish
    assert "a couple of" not in words


@pytest.mark.parametrize("old, new", [("plane = 900", "plane = 1e308"),
                                      ("radius = 80", "radius = 1e-300")])
def test_sizes_no_figure_can_hold_are_refused_in_one_line(old, new):
    """Found by fuzzing the bundled files: a plane 1e308 away made the side view's scale
    infinite, and a radius of 1e-300 a circle no arc could be drawn on."""
    with pytest.raises(InputError, match=r"rotor.toml:\d+: .* must be between 1e-06 and "
                                          r"1e\+06 in size \(or 0\)"):
        parse_balance(TEXT.replace(old, new, 1), "rotor.toml")


@pytest.mark.parametrize("given, key, want", [
    ("radius = 0.2", "mass_B", 23.219789144 / 0.2),      # kg at the stated 0.2 m
    ("mass = 116", "radius_B", 23.219789144 / 116),      # m for a stated 116 kg
])
def test_four_masses_one_plane(given, key, want):
    """The books' four masses (200, 300, 240, 260 kg at 0.2, 0.15, 0.25, 0.3 m, 45°, 75°,
    135° apart): Σ mᵢrᵢ e^{iθᵢ} summed by hand = 21.63192 + 8.43911i kg·m, so the balancing
    product is 23.21979 kg·m at 201.312° (the books read 116 kg at 201.5° off a drawing).
    results.json gives the mass, or the radius, itself; to 1e-9 relative: the closed form
    is written to ten figures."""
    text = Path(bundled("balancing")["four-masses-one-plane"]).read_text(encoding="utf-8")
    assert "radius = 0.2               #" in text
    ex = parse_balance(text.replace("radius = 0.2               #", given + " #", 1), "b.toml")
    q = solve_balance(ex).results["quantities"][key]
    assert q["value"] == pytest.approx(want, rel=1e-9)
    assert q["value"] == pytest.approx(q["reference"]["value"], rel=1e-12)
    assert q["angle_deg"] == pytest.approx(201.311913, abs=1e-6)


def test_single_cylinder_balance_mass():
    """The books' single cylinder: 240 rpm, stroke 300 mm, 50 kg reciprocating, 37 kg
    revolving, all the revolving and 2/3 of the reciprocating balanced at 400 mm; at 60°.
    By hand: B·b = (37 + 100/3) × 0.15 = 10.55 kg·m, B = 26.375 kg; m·ω²·r = 50·(8π)²·0.15
    and the force left, m·ω²·r·√((1/3 · cos 60°)² + (2/3 · sin 60°)²) = m·ω²·r·√(13/36)
    (2846.83 N, the books' 2.85 kN). No rod: no secondary force is written. 1e-12
    relative: a handful of products of exact data."""
    q = solve_balance(load("single-cylinder-balance-mass")).results["quantities"]
    f = 50 * (8 * math.pi) ** 2 * 0.15
    assert q["balance_mr"]["value"] == pytest.approx(10.55, rel=1e-12)
    assert q["balance_mass"]["value"] == pytest.approx(26.375, rel=1e-12)
    assert q["balance_mass"]["radius"] == pytest.approx(0.4, rel=1e-15)
    assert q["balance_mass"]["angle_deg"] == 180.0
    assert q["unbalanced_resultant"]["value"] == pytest.approx(f * math.sqrt(13 / 36), rel=1e-12)
    assert q["unbalanced_resultant"]["value"] == pytest.approx(2846.83, abs=5e-3)
    assert q["unbalanced_max"]["value"] == pytest.approx(2 * f / 3, rel=1e-12)
    assert "secondary_force" not in q


def test_a_balance_mass_stated_gives_its_radius():
    """balance_mass = 26.375 kg puts it at B·b / B = 10.55 / 26.375 = 0.4 m."""
    text = Path(bundled("balancing")["single-cylinder-balance-mass"]).read_text(
        encoding="utf-8").replace("balance_radius = 400", "balance_mass = 26.375", 1)
    q = solve_balance(parse_balance(text, "e.toml")).results["quantities"]
    assert q["balance_radius"]["value"] == pytest.approx(0.4, rel=1e-12)


def test_an_inline_engine_with_no_rod_gives_its_primary_polygons_alone():
    """The in-line four's cranks 0°, 180°, 180°, 0° with the rod left out: the primary force
    and couple are asked and balanced (4 cranks summing to 0), no secondary is drawn or
    written."""
    text = Path(bundled("balancing")["inline-four"]).read_text(encoding="utf-8")
    s = solve_balance(parse_balance(text.replace("rod = 200\n", "", 1), "e.toml"))
    assert s.passed
    q = s.results["quantities"]
    assert set(q) == {"primary_force", "primary_couple"}
    assert set(s.figures) == {"primary-force", "primary-couple"}


ENGINE = Path(bundled("balancing")["single-cylinder-balance-mass"]).read_text(encoding="utf-8")


@pytest.mark.parametrize("old, new, words", [
    ("stroke = 300 ", "crank = 150\nstroke = 300 ", "gives the crank radius (crank = …) or the "
                                                    "stroke"),
    ("balance_radius = 400", "balance_radius = 400\nbalance_mass = 3", "not both"),
    ("revolving = 37", "revolving = [20, -1]", "revolving masses (kg, at the crank radius) "
                                               "must be positive or 0"),
    ("balance_radius = 400", "balance_radius = 0", "the balance radius must be positive"),
])
def test_a_bad_engine_is_refused_in_one_line(old, new, words):
    assert old in ENGINE
    with pytest.raises(InputError) as e:
        parse_balance(ENGINE.replace(old, new, 1), "engine.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("engine.toml:") and words in message, \
        message


def test_revolving_masses_in_line_with_no_balance_planes_are_refused():
    text = Path(bundled("balancing")["inline-four"]).read_text(encoding="utf-8")
    with pytest.raises(InputError, match=r"e.toml:\d+: revolving is what balance masses take: "
                                         r"give the \[\[balance\]\] planes"):
        parse_balance(text.replace("rod = 200\n", "rod = 200\nrevolving = 2\n", 1), "e.toml")


# ----- unknowns read off the polygons ------------------------------------------------------------
def test_unknown_planes():
    """B, C, D: 5 kg·m at 0°, 4 at 90°, 6.3 at 195°; C 250 mm from B. By hand: A's m·r is
    −(5 + 4i + 6.3e^{i195°}) = 1.08527 − 2.36944i (2.60613 kg·m, 294.61°), so 34.7484 kg at
    75 mm; couples about B, a·(A's m·r) + b·(D's) = −0.25·4i, solved by Cramer's rule for
    the planes a, b. 1e-9 relative: the drawn crossing against the algebra."""
    q = solve_balance(load("unknown-planes")).results["quantities"]
    a = -(5 + 4j + 6.3 * complex(math.cos(math.radians(195)), math.sin(math.radians(195))))
    d = 6.3 * complex(math.cos(math.radians(195)), math.sin(math.radians(195)))
    target = -0.25 * 4j
    det = a.real * d.imag - a.imag * d.real
    la = (target.real * d.imag - target.imag * d.real) / det
    ld = (a.real * target.imag - a.imag * target.real) / det
    assert q["mass_A"]["value"] == pytest.approx(abs(a) / 0.075, rel=1e-9)
    assert q["angle_A"]["value"] == pytest.approx(math.degrees(cmath.phase(a)) % 360, abs=1e-9)
    assert q["plane_A"]["value"] == pytest.approx(la, rel=1e-9)
    assert q["plane_D"]["value"] == pytest.approx(ld, rel=1e-9)
    assert (la, ld) == pytest.approx((0.375904, 0.0670433), abs=5e-7)


def test_unknown_angles():
    """About A's plane: 0.75 (B at 0°) + 1.2e^{iθC} + 1.08e^{iθD} = 0, so by the law of
    cosines cos θC = (1.08² − 0.75² − 1.2²)/(2·0.75·1.2) (the crossing taken puts C below
    B's line, θC = −117.68°); then A closes the force polygon. 1e-9: the crossing of two
    arcs against the algebra."""
    s = solve_balance(load("unknown-angles"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    tc = -math.acos((1.08 ** 2 - 0.75 ** 2 - 1.2 ** 2) / (2 * 0.75 * 1.2))
    ec = complex(math.cos(tc), math.sin(tc))
    ed = -(0.75 + 1.2 * ec) / 1.08
    a = -(1.25 + 1.0 * ec + 0.6 * ed)
    assert q["angle_C"]["value"] == pytest.approx(math.degrees(tc) % 360, abs=1e-9)
    assert q["angle_D"]["value"] == pytest.approx(math.degrees(cmath.phase(ed)) % 360,
                                                  abs=1e-9)
    assert q["mass_A"]["value"] == pytest.approx(abs(a) / 0.1, rel=1e-9)
    assert q["mass_A"]["value"] == pytest.approx(7.39932, abs=5e-5)
    assert "mirror image" in "\n".join(s.lines())
    # the other crossing: C reflected in B's line, θC = +117.68°
    assert q["angle_C"]["mirror"] == pytest.approx(-math.degrees(tc), abs=1e-9)


def test_two_unknown_masses_are_the_balancing_planes_two_planes_finds():
    """The four-mass shaft with its balancing planes written as two masses of unknown mass
    and angle at 100 mm: the same 249.86 kg and 331.60 kg as [[balance]] gives, by the
    reference-plane method's closed form."""
    text = TEXT[:TEXT.index("[[balance]]")].replace("speed = 300\n", "", 1) + "".join(
        f'[[mass]]\nname = "{n}"\nmass = "?"\nradius = 100\nangle = "?"\nplane = {z}\n\n'
        for n, z in (("A", 0), ("B", 900)))
    q = solve_balance(parse_balance(text, "shaft.toml")).results["quantities"]
    from tarsim.constructions.reference.balance import two_planes
    in_a, in_b = two_planes(load("four-mass-shaft").rotor.masses, 0.0, 0.9)
    assert q["mass_A"]["value"] == pytest.approx(math.hypot(*in_a) / 0.1, rel=1e-12)
    assert q["mass_B"]["value"] == pytest.approx(math.hypot(*in_b) / 0.1, rel=1e-12)
    assert q["angle_B"]["value"] == pytest.approx(math.degrees(math.atan2(in_b[1], in_b[0]))
                                                  % 360, abs=1e-9)


def test_one_plane_an_unknown_angle_and_an_unknown_mass():
    """In one plane: 3 kg·m at 0°, 4 kg·m at an unknown angle, and a mass at 90° of unknown
    size: the line along 90° cut by the 4 kg·m arc: 4e^{iθ} = −3 − i·s, so θ in the third
    quadrant with cos θ = −3/4 and s = √(16 − 9) = √7 kg·m (the positive mass)."""
    ex = parse_balance('[rotor]\n[[mass]]\nmass = 3\nradius = 1\nangle = 0\n'
                       '[[mass]]\nmass = 4\nradius = 1\nangle = "?"\n[[mass]]\nmass = "?"\n'
                       'radius = 1\nangle = 90\n', "one.toml")
    q = solve_balance(ex).results["quantities"]
    assert q["mass_3"]["value"] == pytest.approx(math.sqrt(7), rel=1e-12)
    assert q["angle_2"]["value"] == pytest.approx(360 - math.degrees(math.acos(-0.75)),
                                                  abs=1e-9)


OPEN = Path(bundled("balancing")["unknown-planes"]).read_text(encoding="utf-8")


@pytest.mark.parametrize("old, new, words", [
    ('radius = 75', 'radius = "?"', "show only as m·r: give one of them"),
    ('name = "B"\nmass = 50', 'name = "B"\nmass = "?"',
     "5 unknowns, but the force and couple polygons close on two each"),
    ('angle = 195\nplane = "?"', 'angle = 195\nplane = 400', "3 unknowns"),
    ('angle = 0\nplane = 0', 'angle = "?"\nplane = 0', "5 unknowns"),
    ('name = "D"\nmass = 70', 'name = "D"\nmass = "?"', "5 unknowns"),
    ('[[mass]]', '[[balance]]\nradius = 1\n[[mass]]', "leave out the [[balance]]"),
])
def test_a_rotor_whose_unknowns_cannot_close_is_refused_in_one_line(old, new, words):
    assert old in OPEN
    with pytest.raises(InputError) as e:
        parse_balance(OPEN.replace(old, new, 1), "open.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("open.toml:") and words in message, \
        message


def test_unknowns_tangled_in_one_polygon_are_refused():
    """A's mass and plane (its angle 0), C's mass and angle: the force polygon has three
    unknowns, and about any known plane the couple polygon has one (C's plane: A's m·r·l,
    which cannot close two equations alone) or three."""
    text = OPEN.replace('angle = "?"\nplane = "?"', 'angle = 0\nplane = "?"', 1).replace(
        'mass = 80\nradius = 50\nangle = 90', 'mass = "?"\nradius = 50\nangle = "?"', 1).replace(
        'angle = 195\nplane = "?"', 'angle = 195\nplane = 500', 1)
    with pytest.raises(InputError, match=r"open.toml:\d+: neither polygon has just two "
                                         r"unknowns .*\(A \(mass, plane\); C \(mass, angle\)\)"):
        parse_balance(text, "open.toml")


def test_a_mass_and_plane_unknown_with_a_known_angle_close_the_couple_polygon_as_m_r_l():
    """A's mass and plane (angle 0), C's and D's angles (planes 250 and 500 mm): about C's
    plane A's m·r·l along 0° and D's 0.567 kg·m² of unknown direction close the couple
    polygon, then the force polygon gives A's m·r and C's angle. Every mass comes out on
    the 0°–180° line: B 5 and A m_A·0.075 at 0°, C 4 and D 6.3 kg·m at 180° balance the
    force if m_A·0.075 = 5.3, and the couples about B if 5.3·l_A = 4·0.25 + 6.3·0.5."""
    text = OPEN.replace('angle = "?"\nplane = "?"', 'angle = 0\nplane = "?"', 1).replace(
        'angle = 90', 'angle = "?"', 1).replace('angle = 195\nplane = "?"',
                                                 'angle = "?"\nplane = 500', 1)
    s = solve_balance(parse_balance(text, "open.toml"))
    assert s.passed, s.failures
    q = s.results["quantities"]
    # 1e-9: crossings of lines and arcs meeting square, against sums of order 1
    assert q["mass_A"]["value"] == pytest.approx(5.3 / 0.075, rel=1e-9)
    assert q["plane_A"]["value"] == pytest.approx((4 * 0.25 + 6.3 * 0.5) / 5.3, rel=1e-9)
    assert q["angle_C"]["value"] == pytest.approx(180.0, abs=1e-9)
    assert q["angle_D"]["value"] == pytest.approx(180.0, abs=1e-9)


def test_sizes_that_cannot_reach_across_are_refused():
    """About A's plane B gives 0.75 kg·m², C and D at most 0.12 + 0.108: no triangle."""
    text = Path(bundled("balancing")["unknown-angles"]).read_text(encoding="utf-8")
    text = text.replace("mass = 5\n", "mass = 0.5\n").replace("mass = 4\n", "mass = 0.4\n")
    with pytest.raises(InputError, match=r"cannot reach across it"):
        parse_balance(text, "open.toml")


def test_carriers_crossing_too_shallowly_are_refused():
    """Two unknown masses at 10° and 10.0000001°: their lines cross at 1e-7°, so a
    rounding of 1e-12 moves the crossing by some 6e-4 of the polygon: not four figures."""
    with pytest.raises(InputError, match=r"shallow.toml:\d+: the polygons' carriers cross too "
                                         r"shallowly"):
        parse_balance('[rotor]\n[[mass]]\nmass = 3\nradius = 1\nangle = 0\n'
                      '[[mass]]\nmass = "?"\nradius = 1\nangle = 10\n[[mass]]\nmass = "?"\n'
                      'radius = 1\nangle = 190.0000001\n', "shallow.toml")
