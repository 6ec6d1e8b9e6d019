"""A turning moment given as a formula or a table is read to the data's own precision: the
intercepts by root-finding on the formula, each loop by quadrature (a table's by its
trapezoids), the drawing at equal steps kept beside it as the graphical answer."""

from __future__ import annotations

import math

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.forces.flywheel import Diagram, read_table
from tarsim.constructions.forces.flywheel_exact import exact_reading, loop_area
from tarsim.constructions.forces.torque_formula import parse_formula
from tarsim.exercises.cli import cli
from tarsim.exercises.forces.flywheel_file import parse_flywheel
from tarsim.exercises.forces.flywheel_solution import solve_flywheel

QUADRATURE = 1e-9
"""16-point Gauss–Legendre on a loop of a smooth T converges to rounding within a few panel
doublings (its error falls as h³²), and the intercepts are narrowed to the last bit, an
intercept off by δθ costing its areas δθ²·|T′|/2 only. What is left is rounding: the mean's
(some 1e-16 of a) over the cycle, against a ΔE of b ≥ a/1000 here, below 1e-12 of ΔE;
1e-9 is a thousand times that, and a thousand times finer than the drawing at 0.1° steps
(which misses b by 1e-6 of it: the check below fails on the drawn number)."""


@settings(max_examples=60, deadline=None)
@given(a=st.floats(0.0, 1e5), b=st.floats(1.0, 1e4), k=st.sampled_from([1, 2, 3, 4]))
def test_harmonic_delta_e_is_its_amplitude(a, b, k):
    """T = a + b·sin kθ over a turn: 2k loops of ±∫ b sin kθ over half a period, 2b/k each;
    the energy swings between two levels 2b/k apart, so ΔE = 2b/k (b itself for sin 2θ)."""
    d = Diagram(parse_formula(f"{a!r} + {b!r}*sin({k}*theta)"), 2 * math.pi)
    r = exact_reading(d)
    assert r.delta_e == pytest.approx(2 * b / k, rel=QUADRATURE)
    assert r.mean == pytest.approx(a, rel=1e-12, abs=1e-12 * b)
    assert len(r.areas) == 2 * k
    for area in r.areas:
        assert abs(area) == pytest.approx(2 * b / k, rel=QUADRATURE)


def test_loop_area_closed_forms():
    """∫₀^π sin = 2 and ∫₀^1 θ⁷ = 1/8, each to a few roundings (16 nodes integrate a
    polynomial of degree 31 exactly; sin converges in a panel or two)."""
    assert loop_area(math.sin, 0.0, math.pi) == pytest.approx(2.0, rel=1e-14)
    assert loop_area(lambda t: t ** 7, 0.0, 1.0) == pytest.approx(0.125, rel=1e-14)


def test_formula_not_repeating_on_its_own():
    """T = 1000 + 500 sin(θ/2) is given for one turn and repeats from there: its mean is
    1000 + 1000/π; it crosses it where sin(θ/2) = 2/π, at θ = 2u and 2π − 2u; the loop
    between is 500·2·(cos u − cos(π − u)) − (1000/π)·(2π − 4u), the other its negative."""
    r = exact_reading(Diagram(parse_formula("1000 + 500*sin(theta/2)"), 2 * math.pi))
    excess = 1000 / math.pi
    u = math.asin(excess / 500)                   # θ/2 at the first intercept
    loop = 1000 * (math.cos(u) - math.cos(math.pi - u)) - excess * (2 * math.pi - 4 * u)
    assert r.mean == pytest.approx(1000 + excess, rel=1e-12)
    # an intercept is narrowed to the last bit of θ
    assert r.intercepts == pytest.approx((2 * u, 2 * math.pi - 2 * u), rel=1e-12)
    assert r.areas == pytest.approx((loop, -loop), rel=QUADRATURE)
    assert r.delta_e == pytest.approx(loop, rel=QUADRATURE)


F2 = '''
name = "Engine T = 15000 + 6000 sin 2θ driving a steady load: flywheel rim"
[units]
speed = "rpm"
length = "m"
[turning_moment]
torque = "15000 + 6000*sin(2*theta)"
cycle = 360
[flywheel]
speed = 240
speed_fluctuation = "±1 %"
diameter = 1.5
density = 7200
width_to_thickness = 2
'''


def test_f2_sin2theta_rim():
    """The books' T = 15000 + 6000 sin 2θ at 240 rpm within ±1 %, a rim of 1.5 m: ΔE = 6000 J
    exactly (the drawing's 5999.99 J only beside it), I = ΔE/(C_s·ω²), m = I/r², the section
    t = √(m/(ρ·2πr·2)), and α = 6000/I at 45° and 225°."""
    sol = solve_flywheel(parse_flywheel(F2))
    q = sol.checked
    omega = 240 * 2 * math.pi / 60
    inertia = 6000 / (0.02 * omega ** 2)
    mass = inertia / 0.75 ** 2
    thickness = math.sqrt(mass / (7200 * 2 * math.pi * 0.75) / 2)
    # each is ΔE times exact factors: ΔE's QUADRATURE, and a few roundings
    assert q["delta_E"].value["value"] == pytest.approx(6000, rel=QUADRATURE)
    assert f"{q['delta_E'].value['value']:.6g}" == "6000"
    assert q["inertia"].value["value"] == pytest.approx(inertia, rel=QUADRATURE)
    assert q["rim_mass"].value["value"] == pytest.approx(mass, rel=QUADRATURE)
    assert q["rim_thickness"].value["value"] == pytest.approx(thickness, rel=QUADRATURE)
    assert q["rim_width"].value["value"] == pytest.approx(2 * thickness, rel=QUADRATURE)
    assert q["greatest_acceleration"].value["value"] == pytest.approx(6000 / inertia,
                                                                       rel=QUADRATURE)
    assert q["greatest_acceleration"].value["angle_deg"] == pytest.approx([45, 225], abs=1e-6)
    # the drawing at 0.1° steps: each loop's trapezoids miss h²/12·|ΔT′| = h²/12·2·12000,
    # 6.1e-3 J per loop beside 6000 J; its ΔE is below the exact one by about that
    drawn = q["delta_E_drawn"]
    h = math.radians(0.1)
    assert drawn.reference["value"] == pytest.approx(6000, rel=QUADRATURE)
    assert 6000 - drawn.value["value"] == pytest.approx(h ** 2 / 12 * 24000, rel=0.01)
    assert drawn.passed and not q["delta_E"].value["value"] == drawn.value["value"]
    assert all(c.passed is not False for c in q.values())


def test_table_of_straight_pieces_is_its_trapezoids():
    """A table (0°, 0), (90°, 400), (180°, 0), (360°, 0) of straight pieces: mean 100 N·m
    (the triangle ½·π·400 over 2π); it crosses 100 at 22.5° and 157.5°, and above it lies
    the triangle of base 135° = 3π/4 and height 300, ½·(3π/4)·300 = 112.5π J; ΔE is that,
    to rounding."""
    pts = tuple((math.radians(a), t) for a, t in ((0, 0.0), (90, 400.0), (180, 0.0)))
    r = read_table(pts, 2 * math.pi)
    assert r.mean == pytest.approx(100.0, rel=1e-14)
    assert [math.degrees(c) for c in r.intercepts] == pytest.approx([22.5, 157.5], rel=1e-13)
    assert r.delta_e == pytest.approx(112.5 * math.pi, rel=1e-13)
    assert r.areas == pytest.approx((112.5 * math.pi, -112.5 * math.pi), rel=1e-13)


F3 = '''
name = "F3: machine torque (5000 + 500 sin t) driven by an engine of (5000 + 600 sin 2t)"
[units]
speed = "rpm"
length = "m"
[turning_moment]
torque = "5000 + 600*sin(2*theta)"
cycle = 360
[resisting_torque]
torque = "5000 + 500*sin(theta)"
cycle = 360
[flywheel]
speed = 150
mass = 500
radius_of_gyration = 0.4
'''


def test_f3_engine_and_machine(tmp_path):
    """The engine's 5000 + 600 sin 2θ against the machine's 5000 + 500 sin θ: the excess
    600 sin 2θ − 500 sin θ has the energy E = −300 cos 2θ + 500 cos θ, whose extremes are at
    sin θ = 0 or cos θ = 5/12: E = 200, −800 and 4850/12, so ΔE = 14450/12 J exactly. The
    excess is greatest where 2400c² − 500c − 1200 = 0 (c = cos θ), c = (500 − √11770000)/4800,
    at θ = 232.37° (its least at 127.63°), α = excess/I with I = 500·0.4². The figure draws
    what it is, the excess T_e − T_m beside the two given torques, in English and Persian."""
    path = tmp_path / "f3.toml"
    path.write_text(F3, encoding="utf-8")
    q = solve_flywheel(parse_flywheel(F3)).checked
    assert q["delta_E"].value["value"] == pytest.approx(14450 / 12, rel=QUADRATURE)
    c = (500 - math.sqrt(500 ** 2 + 4 * 2400 * 1200)) / 4800
    theta = 2 * math.pi - math.acos(c)
    excess = 600 * math.sin(2 * theta) - 500 * math.sin(theta)
    # T at its extreme is the extreme to rounding; its place to some √(rounding) of the cycle
    assert q["greatest_acceleration"].value["value"] == pytest.approx(excess / 80, rel=1e-12)
    assert q["greatest_acceleration"].value["angle_deg"] == pytest.approx(
        [math.degrees(theta)], abs=1e-5)
    assert q["greatest_retardation"].value["angle_deg"] == pytest.approx(
        [360 - math.degrees(theta)], abs=1e-5)
    svgs = {}
    for lang in ("en", "fa"):
        out = tmp_path / lang
        result = CliRunner().invoke(cli, ["solve", str(path), "--no-pdf", "--lang", lang,
                                          "-o", str(out)])
        assert result.exit_code == 0, result.output
        svgs[lang] = (out / "turning-moment.svg").read_text(encoding="utf-8")
    assert "<title>Excess-torque diagram</title>" in svgs["en"]
    for label in ("excess torque T", "engine's turning moment T", "machine's resisting torque T"):
        assert label in svgs["en"]
    assert ">turning moment<" not in svgs["en"]
    for label in ("نمودار گشتاور اضافی", "گشتاور اضافی", "گشتاور چرخشی موتور",
                  "گشتاور مقاوم ماشین"):
        assert label in svgs["fa"]


def test_a_formula_repeats_over_its_cycle():
    """T = 1000 + 500 sin(θ/2) given over a turn repeats from there: it is least, 1000 N·m,
    at θ = 0 (the cycle's end), not below it just past 360° where sin(θ/2) would turn
    negative; the shaft's greatest retardation is (T_mean − 1000)/I = (1000/π)/I there, and
    the reference, reading the same repeating diagram, agrees."""
    sol = solve_flywheel(parse_flywheel('[units]\nspeed = "rpm"\n[turning_moment]\n'
                                        'torque = "1000 + 500*sin(theta/2)"\n[flywheel]\n'
                                        'speed = 300\nspeed_fluctuation = 0.02\n'))
    q = sol.checked
    inertia = q["inertia"].value["value"]
    # T's least is exact (T(0) = 1000 to the last bit); the mean and I to QUADRATURE
    assert q["greatest_retardation"].value["value"] == pytest.approx(1000 / math.pi / inertia,
                                                                      rel=QUADRATURE)
    assert q["greatest_retardation"].value["angle_deg"] == [0.0]
    assert sol.failures == []
