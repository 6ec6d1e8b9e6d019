"""A rod's inertia from a pendulum test and a flywheel's angular acceleration at one crank
position, as the books give them, each against its closed form."""

from __future__ import annotations

import json
import math

import pytest
from click.testing import CliRunner
from hypothesis import given
from hypothesis import strategies as st

from tarsim.constructions.loads import GRAVITY, pendulum_radius
from tarsim.exercises.cli import cli

# The books' vertical engine: a 2 m rod of 250 kg, G 800 mm from the big end, hung from the
# gudgeon pin it makes 8 oscillations in 22 s; crank 400 mm at 200 rpm, 40° past the t.d.c.
VERTICAL = """
[units]
length = "mm"
angular_velocity = "rpm"
[frame]
O = [0, 0]
[[link]]
number = 2
points = ["O", "A"]
lengths = { OA = 400 }
[[link]]
number = 3
points = ["A", "P"]
lengths = { AP = 2000 }
[[link]]
number = 4
points = ["P"]
[[slider]]
link = 4
point = "P"
on = 1
through = "O"
angle = 90
[input]
link = 2
angle = "90 + 40"
omega = 200
[assembly]
P = "forward"
[ask]
find = ["T2", "turning_moment", "rod_radius_of_gyration"]
methods = ["polygon"]
[forces]
gravity = false
[[mass]]
link = 3
mass = 250
centre = [800, 0]
{inertia}
"""

# The books' horizontal gas engine: 210 rpm, bore 220, stroke 440, rod 924 mm, 20 kg
# reciprocating, 30° from the i.d.c., 500 kN/m² on the cover side and 60 on the crank side
# (piston rod 40 mm); a flywheel of 380 kg at k = 600 mm while the engine gives 22 kW.
GAS = """
[units]
length = "mm"
angular_velocity = "rpm"
[frame]
O = [0, 0]
[[link]]
number = 2
points = ["O", "A"]
lengths = { OA = "440/2" }
[[link]]
number = 3
points = ["A", "P"]
lengths = { AP = 924 }
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
angle = 30
omega = 210
[assembly]
P = "forward"
[ask]
find = ["turning_moment", "flywheel_alpha"]
methods = ["polygon"]
[forces]
gravity = false
{forces}
[[mass]]
link = 4
mass = 20
centre = "P"
[[force]]
link = 4
point = "P"
pressure = "500 kN/m²"
bore = 220
[[force]]
link = 4
point = "P"
pressure = "-60 kN/m²"
bore = 220
rod = 40
"""


def _solve(tmp_path, text: str, name: str = "e"):
    path = tmp_path / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    out = tmp_path / name
    result = CliRunner().invoke(cli, ["solve", str(path), "--no-pdf", "-o", str(out)])
    return result, out


def _quantities(tmp_path, text: str, name: str = "e") -> tuple[dict, str]:
    result, out = _solve(tmp_path, text, name)
    assert result.exit_code == 0, result.output
    (position,) = json.loads((out / "results.json").read_text(encoding="utf-8"))["positions"]
    return ({k: v["value"] for k, v in position["quantities"].items()},
            (out / "steps.md").read_text(encoding="utf-8"))


def _refused(tmp_path, text: str) -> str:
    result, out = _solve(tmp_path, text, "bad")
    assert result.exit_code == 1, result.output
    (line,) = result.output.strip().splitlines()
    assert line.startswith("Error: ") and not out.exists()
    return line


@given(h=st.floats(0.01, 5.0), k=st.floats(0.01, 5.0))
def test_a_pendulum_s_period_gives_back_its_radius_of_gyration(h, k):
    """T = 2π·√((k² + h²)/(g·h)) of a body hung h from G, read back, is k: the square root
    and its square lose a few ulps of k² + h², relative to k² that many times (h/k)²."""
    period = 2 * math.pi * math.sqrt((k * k + h * h) / (GRAVITY * h))
    assert pendulum_radius(period, h) == pytest.approx(k, rel=1e-13 * (1 + (h / k) ** 2))


def test_e3b_try_pendulum(tmp_path):
    """Hung from the gudgeon pin, h = 2 − 0.8 = 1.2 m, T = 22/8 s: k² = g·h·T²/(4π²) − h²
    (0.9028 m, the books' 0.903); the inertia torque is the one the rod's I = m·k² gives."""
    k = math.sqrt(GRAVITY * 1.2 * (22 / 8) ** 2 / (4 * math.pi ** 2) - 1.2 ** 2)
    swung, steps = _quantities(tmp_path, VERTICAL.replace(
        "{inertia}", 'oscillations = { count = 8, seconds = 22, about = "P" }'), "swung")
    assert f"k = √(g·h·T²/(4π²) − h²) = {k * 1e3:.6g} mm" in steps
    assert f"I = m·k² = {250 * k * k:.6g} kg·m²" in steps
    # k² is a difference of two terms of 0.8 and 1.4 m²: a few ulps of them, relative to k²
    assert swung["rod_radius_of_gyration"] == pytest.approx(k, rel=1e-14)
    given_k, _ = _quantities(tmp_path, VERTICAL.replace("{inertia}",
                                                            f"radius_of_gyration = {k * 1e3!r}"),
                             "given")
    assert given_k["rod_radius_of_gyration"] == pytest.approx(k, rel=1e-14)
    # the same I to its last few ulps (k in mm, squared), so the same torque to rounding
    assert swung["T2"] == pytest.approx(given_k["T2"], rel=1e-12)
    # the period alone, or hung from a knife edge at the same place given as a point
    for inertia in ('oscillations = { period = "22/8", about = [2000, 0] }',):
        again, _ = _quantities(tmp_path, VERTICAL.replace("{inertia}", inertia), "again")
        assert again["T2"] == pytest.approx(given_k["T2"], rel=1e-12)

    # on a knife edge in the small end's 80 mm bore, h = 1.2 + 0.04 m
    h = 1.24
    edge = math.sqrt(GRAVITY * h * (22 / 8) ** 2 / (4 * math.pi ** 2) - h * h)
    knife, steps = _quantities(tmp_path, VERTICAL.replace(
        "{inertia}", 'oscillations = { count = 8, seconds = 22, about = "P", bore = 80 }'),
        "knife")
    assert knife["rod_radius_of_gyration"] == pytest.approx(edge, rel=1e-14)
    assert "hung on a knife edge in the bore at P" in steps and "h = 1240 mm" in steps


@pytest.mark.parametrize("inertia, words", [
    ('oscillations = { count = 8, seconds = 22, about = "Q" }', "no point 'Q'"),
    ('oscillations = { count = 8, seconds = 2, about = "P" }', "at least 2π·√(h/g) = 2.198 s"),
    ('oscillations = { count = 8, period = 2, about = "P" }', "one of them"),
    ('oscillations = { count = 8, seconds = 22 }', "about is the point"),
    ('oscillations = { count = 8, seconds = 22, about = [800, 0] }', "from its centre"),
    ('oscillations = { count = 0, seconds = 22, about = "P" }', "must be positive"),
    ('oscillations = { count = 8, seconds = 22, about = "P", at = 1 }', "unknown setting 'at'"),
    ('oscillations = { count = 8, seconds = 22, about = [0, 0], bore = 80 }', "about = \"P\""),
    ('radius_of_gyration = 900\noscillations = { period = 2.75, about = "P" }', "twice"),
])
def test_a_bad_pendulum_is_refused_at_its_line(inertia, words, tmp_path):
    line = _refused(tmp_path, VERTICAL.replace("{inertia}", inertia))
    assert "bad.toml:" in line and words in line, line


def test_e2b_try_flywheel_alpha(tmp_path):
    """α = (T − P/ω)/(m·k²): T the turning moment from the polygons at 30° (its closed form
    F_P·r·sin(θ + φ)/cos φ, F_P the gas force less the exact m·a), P = 22 kW at 210 rpm, I =
    380·0.6² (the books' 6.967 rad/s², with their cos θ + cos 2θ/n)."""
    r, rod, t, w = 0.22, 0.924, math.radians(30), 210 * math.pi / 30
    s = math.sqrt(rod * rod - (r * math.sin(t)) ** 2)
    gas = 500e3 * math.pi * 0.22 ** 2 / 4 - 60e3 * math.pi * (0.22 ** 2 - 0.04 ** 2) / 4
    effort = gas - 20 * w * w * (r * math.cos(t) + r * r * math.cos(2 * t) / s
                                 + r ** 4 * math.sin(t) ** 2 * math.cos(t) ** 2 / s ** 3)
    phi = math.asin(r * math.sin(t) / rod)
    torque = effort * r * math.sin(t + phi) / math.cos(phi)
    alpha = (torque - 22000 / w) / (380 * 0.6 ** 2)
    for forces in ("power = 22000\nflywheel = { mass = 380, radius_of_gyration = 600 }",
                   f"mean_torque = {22000 / w!r}\nflywheel = {380 * 0.36!r}"):
        q, steps = _quantities(tmp_path, GAS.replace("{forces}", forces))
        # the polygons and the reference both give T to its rounding (1e-12 of it)
        assert q["turning_moment"] == pytest.approx(torque, rel=1e-11)
        assert q["flywheel_alpha"] == pytest.approx(alpha, rel=1e-11)
        assert "α = (T − T_mean)/I = 6.95989 rad/s²" in steps


def test_the_flywheel_slows_where_the_turning_moment_falls_short(tmp_path):
    """With the crank turning clockwise the turning moment along the rotation is −T (CCW +):
    at the mirrored position the engine drives the same, so α is the same; a mean torque
    above T gives a retardation, T − T_mean < 0."""
    given = GAS.replace("{forces}", "mean_torque = 1000\nflywheel = 100")
    ccw, _ = _quantities(tmp_path, given, "a")
    cw, _ = _quantities(tmp_path, given.replace("angle = 30\nomega = 210",
                                                "angle = -30\nomega = -210"), "b")
    assert cw["turning_moment"] == pytest.approx(-ccw["turning_moment"], rel=1e-12)
    assert cw["flywheel_alpha"] == pytest.approx(ccw["flywheel_alpha"], rel=1e-12)
    slow, _ = _quantities(tmp_path, given.replace("mean_torque = 1000", "mean_torque = 3000"),
                          "c")
    assert slow["flywheel_alpha"] == pytest.approx((ccw["turning_moment"] - 3000) / 100,
                                                   rel=1e-12)
    assert slow["flywheel_alpha"] < 0


@pytest.mark.parametrize("forces, words", [
    ("power = 22000", "give its flywheel"),
    ("power = 22000\nmean_torque = 1000\nflywheel = 100", "not both"),
    ("power = -1\nflywheel = 100", "must be positive"),
    ("power = 22000\nflywheel = { mass = 380 }", "radius_of_gyration = 600"),
    ("flywheel = 100", "flywheel_alpha is (T − T_mean)/I"),
])
def test_a_bad_flywheel_load_is_refused_in_one_line(forces, words, tmp_path):
    line = _refused(tmp_path, GAS.replace("{forces}", forces))
    assert words in line, line


def test_a_rod_with_no_inertia_has_no_radius_of_gyration(tmp_path):
    line = _refused(tmp_path, GAS.replace("{forces}", "").replace(
        '"flywheel_alpha"]', '"rod_radius_of_gyration"]'))
    assert "give the rod a [[mass]]" in line, line
