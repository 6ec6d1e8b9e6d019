"""Gear-train inputs that once failed, each held to the answer it should have given.

Every file in ``tests/reproducers/`` named here once gave a traceback or a failed check.
The speeds asserted are worked by hand from the tooth numbers (Willis' formula, or the
train value of driver over driven teeth), the mesh's bounds from its circles' radii,
never copied from what tarsim printed. A file that cannot be solved gives one line
naming the file, its line and what to fix, exits 1 and writes nothing.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction as F
from pathlib import Path

import pytest
from click.testing import CliRunner

import tarsim
from tarsim.exercises.cli import cli

HERE = Path(__file__).parent / "reproducers"


def path(name: str) -> str:
    return str(HERE / f"{name}.toml")


def line_of(name: str, text: str) -> int:
    """The line of the file ``name`` that starts with ``text``."""
    lines = Path(path(name)).read_text(encoding="utf-8").splitlines()
    return next(k for k, t in enumerate(lines, 1) if t.startswith(text))


def refused(name: str, tmp_path: Path) -> str:
    """Solve ``name`` on the command line; it must be refused with exit 1, writing nothing."""
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["solve", path(name), "-o", str(out), "--no-pdf"])
    assert result.exit_code == 1, result.output
    assert result.exception is None or isinstance(result.exception, SystemExit)
    assert not out.exists()
    return result.output


def test_crash_gear_ratio_over_fixed(tmp_path):
    # ω4/ω1 with the ring 1 fixed divides by 0: refused at the ask's line.
    name = "crash-gear-ratio-over-fixed"
    assert refused(name, tmp_path) == (
        f"Error: {path(name)}:{line_of(name, 'find')}: [ask.find] omega4/omega1 divides by the "
        "speed of member 1, which is fixed; ask a ratio over a turning member\n")


def test_crash_gear_keyerror_arm_fixed(tmp_path):
    """The arm 6 fixed makes Q3 an ordinary compound train: the planet 3 (60 teeth) drives
    at 100 rpm ccw; 4 (40) on its shaft turns alike; the sun 2 (40) meshes 3 and the
    sun 5 (60) meshes 4, each externally: ω2 = −100·60/40, ω5 = −100·40/60."""
    s = tarsim.solve(tarsim.load(path("crash-gear-keyerror-arm-fixed")))
    assert s.passed and s.found.table is None
    assert s.found.speeds == {2: F(-150), 3: F(100), 4: F(100), 5: F(-200, 3), 6: F(0)}
    assert s.reference == s.found.speeds
    assert "The train value e = ω5/ω3 = (N4)/(N5) = (40)/(60) = −2/3" in s.steps()
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["solve", path("crash-gear-keyerror-arm-fixed"), "-o",
                                      str(out), "--no-pdf"])
    assert result.exit_code == 0, result.output
    q = json.loads((out / "results.json").read_text(encoding="utf-8"))["quantities"]["omega5"]
    assert (q["exact"], q["reference"]["exact"]) == ("-200/3", "-200/3")


def test_check3_gear_kutzbach_planet_input(tmp_path):
    """Q1 driven by its planet 4 (40 teeth) at 80 rpm cw, the ring 1 (140) fixed, the sun 2
    (60). Willis about the arm 3: (ω4 − ω3)/(0 − ω3) = N1/N4 = 7/2, so ω3 = −80/(1 − 7/2)
    = 32; (ω2 − ω3)/(ω4 − ω3) = −N4/N2 = −2/3, so ω2 = 32 + 2/3·112 = 320/3."""
    s = tarsim.solve(tarsim.load(path("check3-gear-kutzbach-planet-input")))
    want = {1: F(0), 2: F(320, 3), 3: F(32), 4: F(-80)}
    assert s.found.speeds == s.reference == want
    per = 2 * math.pi / 60
    for m, w in want.items():
        # slopes of drawn lines: a few roundings of coordinates of the fastest's size
        assert s.diagram.omegas[m] == pytest.approx(float(w) * per, abs=1e-12 * 320 / 3 * per)
    # the planet's line runs through its pitch point with the fixed ring (at rest) and C
    assert s.diagram.through[(4,)] == ("kz:pitch:1-4", "kz:centre")
    assert s.passed
    result = CliRunner().invoke(cli, ["solve", path("check3-gear-kutzbach-planet-input"),
                                      "-o", str(tmp_path / "out"), "--no-pdf"])
    assert result.exit_code == 0, result.output


def test_check3_gear_pulled_apart(tmp_path):
    """Module 10, 20 and 40 teeth: addendum radii 110 and 210 mm reach 320 mm together, the
    pitch circles 100 + 200 = 300 mm; the file puts the centres 500 mm apart."""
    name = "check3-gear-pulled-apart"
    assert refused(name, tmp_path) == (
        f"Error: {path(name)}:{line_of(name, 'centre_distance')}: [involute.centre_distance] "
        "gears 2 and 3 do not touch: the centre distance is 500 mm, and their addendum "
        "circles reach only 320 mm; the pitch circles need 300 mm\n")


def test_inf_gear_kutzbach_sun_at_rest(tmp_path):
    """A compound planet 7–5 (37 and 37 teeth) between the fixed sun 6 (30) and the sun 3
    (30), driven at 7.5e28 rpm cw. Willis about the arm 8: (ω7 − ω8)/(0 − ω8) = −30/37, so
    ω8 = 37/67·ω7; then (ω3 − ω8)/(ω5 − ω8) = −37/30 with ω5 = ω7 gives ω3 − ω8 = −ω8: the
    sun 3 stands still. The velocity diagram reads its slope as 1e12 rad/s beside speeds of
    1e28 rpm, the last bit of coordinates of that size: said as 0, measured against the
    fastest speed, and results.json holds no infinity (it once held rel_error: Infinity)."""
    name = "inf-gear-kutzbach-sun-at-rest"
    s = tarsim.solve(tarsim.load(path(name)))
    w7 = F(-75 * 10**27)
    want = {3: F(0), 5: w7, 6: F(0), 7: w7, 8: w7 * F(37, 67)}
    assert s.found.speeds == s.reference == want and s.passed
    k, per = s.diagram, 2 * math.pi / 60
    fastest = abs(float(w7)) * per
    for m, w in want.items():
        # a slope of two drawn points: a few roundings (their two coordinates each) of
        # velocities of the fastest's size, over a span of radii no shorter than 15 of 33.5
        assert abs(k.omegas[m] - float(w) * per) <= 4 * 2.0**-52 * fastest, m
    assert k.said(3) == k.said(6) == 0.0
    assert k.said(8) == pytest.approx(float(w7 * F(37, 67)) * per, rel=4 * 2.0**-52)

    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["solve", path(name), "-o", str(out), "--no-pdf"])
    assert result.exit_code == 0, result.output

    def refuse(word):
        raise ValueError(f"results.json holds {word}")

    doc = json.loads((out / "results.json").read_text(encoding="utf-8"), parse_constant=refuse)
    diagram = doc["quantities"]["omega3"]["velocity_diagram"]
    assert diagram["value"] == 0.0
    # ω3's line runs through O and its pitch point at r3 = 30/2 = 15 modules; the diagram
    # reaches R = 15 + 37/2 = 33.5: 4096 roundings of the fastest, times 33.5/15
    assert diagram["tolerance"] == pytest.approx(4096 * 2.0**-52 * 33.5 / 15, rel=1e-12)
    assert diagram["rel_error"] <= 4 * 2.0**-52
    svg = (out / "kutzbach.svg").read_text(encoding="utf-8")
    assert "ω₃ = 0 rpm<" in svg and "e+12" not in svg

    # the check can fail: ω3 read a billionth of the fastest off, far past the rounding
    k.omegas[3] = 1e-9 * fastest
    assert s.diagram_misses == [3] and not s.passed


def test_check3_gear_reverted_modules_least_teeth(tmp_path):
    """A reverted train, A (20) → B (60) at module 4, C → D at module 5 with D on A's axis
    and |ω3/ω4| = N4/N3 = 3: 4·(20 + 60)/2 = 160 mm = 5·(N3 + 3·N3)/2, so N3 = 16, N4 = 48,
    and ω4 = 1440·(20·16)/(60·48) = 160 rpm, A's sense (two external meshes). The least
    count 1 once took N3 = 1, N4 = 3, the coaxial condition left out (check FAILED, exit 3)."""
    name = "check3-gear-reverted-modules-least-teeth"
    s = tarsim.solve(tarsim.load(path(name)))
    q = s.quantities
    assert (q["teeth3"].exact, q["teeth4"].exact) == (16, 48)
    assert q["teeth3"].reference == 16 and q["teeth4"].reference == 48
    assert q["omega4"].exact == 160 and s.passed
    result = CliRunner().invoke(cli, ["solve", path(name), "-o", str(tmp_path / "out"),
                                      "--no-pdf"])
    assert result.exit_code == 0, result.output
