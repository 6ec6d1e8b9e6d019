"""An engine's asks as the books pose them: the speed at which the gudgeon pin's load
reverses in rpm beside rad/s, and the inertia torque on the crankshaft split between the
reciprocating parts and the rod."""

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tarsim.exercises.cli import cli

HERE = Path(__file__).parent / "reproducers"


def _solve(tmp_path: Path, path: Path) -> tuple[str, dict]:
    out = tmp_path / "o"
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(out), "--no-pdf"])
    assert run.exit_code == 0, run.output
    return run.output, json.loads((out / "results.json").read_text())["positions"][0]


def _closed_form_reversal() -> float:
    """The vertical petrol engine (r 75, l 300 mm, 1.5 kg, 1800 rpm, 1.2 N/mm² on a 100 mm
    bore) with its piston a third of the stroke down from the t.d.c.: the load on the
    gudgeon pin reverses where the inertia of the reciprocating parts, m·ω²·|x''(θ)| with
    x(θ) = r cos θ + √(l² − r² sin² θ) the pin's height, grows to the gas force and the
    weight (g = 9.81, the course's): ω_rev = √(F_rest / (m·|x''|))."""
    r, rod, m, g = 0.075, 0.3, 1.5, 9.81

    def x(t: float) -> float:
        return r * math.cos(t) + math.sqrt(rod * rod - (r * math.sin(t)) ** 2)

    lo, hi = 0.0, math.pi / 2             # θ where the pin has come down a third of 150 mm
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if x(0.0) - x(mid) < 0.050 else (lo, mid)
    h = 1e-4                              # a central difference, good to ~1e-8 relative
    second = (x(lo + h) - 2 * x(lo) + x(lo - h)) / (h * h)
    rest = 1.2e6 * math.pi * 0.1 ** 2 / 4 + m * g
    return math.sqrt(rest / (m * abs(second)))


def test_e2_reversal_speed_rpm(tmp_path):
    """The speed comes in rad/s as before, its rpm beside it in results.json and on the
    line: ω·60/2π. The hand solution gave 547.984 rad/s = 5232.87 rpm; the closed form
    above, its second difference good to ~1e-8, agrees to 1e-6."""
    output, position = _solve(tmp_path, HERE / "e2-reversal-speed-rpm.toml")
    q = position["quantities"]["reversal_speed"]
    assert q["value"] == pytest.approx(_closed_form_reversal(), rel=1e-6)
    assert q["rpm"] == pytest.approx(q["value"] * 60 / (2 * math.pi), rel=1e-15)
    assert q["rpm"] == pytest.approx(5232.87, rel=1e-6)     # the hand value, 6 figures
    assert "reversal_speed = 547.984 rad/s (5232.87 rpm)" in output


def _reciprocating_torque() -> float:
    """The horizontal engine (r 150, l 600 mm, 80 kg reciprocating, 300 rpm ccw) 40° from
    the i.d.c.: by virtual work the piston's inertia force −m·a, moving at v, turns the
    crank with (−m·a)·v/ω, with x(θ) = r cos θ + √(l² − r² sin² θ), v = ω·x' and a = ω²·x''
    at a steady speed, so T = −m·ω²·x'·x''."""
    r, rod, m, w = 0.150, 0.600, 80.0, 300 * 2 * math.pi / 60
    theta, h = math.radians(40.0), 1e-4

    def x(t: float) -> float:
        return r * math.cos(t) + math.sqrt(rod * rod - (r * math.sin(t)) ** 2)

    first = (x(theta + h) - x(theta - h)) / (2 * h)         # central differences, ~1e-8
    second = (x(theta + h) - 2 * x(theta) + x(theta - h)) / (h * h)
    return -m * w * w * first * second


def test_e3_inertia_torque_parts(tmp_path):
    """The book's (b), (c) and (d): the torque of the reciprocating parts' inertia alone, of
    the rod's alone (its mass and its I from the pendulum test), and their sum, the turning
    moment (no gas, no weight). The hand solution gave −1109.85 and −171.91 N·m (six and
    five figures); the reciprocating part's virtual work above agrees to 1e-6, and the two
    parts, drawn each on polygons of their own, add to the whole to the polygons' rounding."""
    output, position = _solve(tmp_path, HERE / "e3-inertia-torque-parts.toml")
    q = position["quantities"]
    recip = q["inertia_torque_reciprocating"]["value"]
    rod = q["inertia_torque_rod"]["value"]
    assert recip == pytest.approx(_reciprocating_torque(), rel=1e-6)
    assert recip == pytest.approx(-1109.85, rel=5e-6)
    assert rod == pytest.approx(-171.91, rel=3e-5)
    assert recip + rod == pytest.approx(q["turning_moment"]["value"], rel=1e-12)
    assert "inertia_torque_reciprocating = −1109.85 N·m (cw)" in output
    assert "inertia_torque_rod = −171.909 N·m (cw)" in output


def test_the_rods_inertia_torque_needs_its_mass(tmp_path):
    """Without the rod's [[mass]] its part is refused in one line naming the link."""
    text = (HERE / "e3-inertia-torque-parts.toml").read_text(encoding="utf-8")
    start = text.index("[[mass]]\nlink = 3")
    text = text[:start] + text[text.index("[[mass]]\nlink = 4"):]
    text = text.replace('"rod_radius_of_gyration", ', "")
    path = tmp_path / "e3.toml"
    path.write_text(text, encoding="utf-8")
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "o"), "--no-pdf"])
    assert run.exit_code == 1 and not (tmp_path / "o").exists()
    line = run.output.strip()
    assert "\n" not in line and line.endswith(
        "inertia_torque_rod is the turning moment of link 3's inertia loads alone: give "
        "link 3 a [[mass]]"), line


@settings(max_examples=12, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(turned=st.floats(5.0, 175.0) | st.floats(185.0, 355.0))
def test_the_parts_add_to_the_inertia_torque_at_any_crank(tmp_path_factory, turned):
    """At any crank angle clear of the dead centres the two parts, each checked against the
    balance of power, add to the whole turning moment of an engine loaded by inertia alone
    (superposition: the polygons are linear in the loads), to its rounding."""
    tmp = tmp_path_factory.mktemp("e3")
    out = tmp / "o"
    run = CliRunner().invoke(cli, ["solve", str(HERE / "e3-inertia-torque-parts.toml"),
                                   "-o", str(out), "--no-pdf", "--angle", f"{turned!r}"])
    assert run.exit_code == 0, run.output
    q = json.loads((out / "results.json").read_text())["positions"][0]["quantities"]
    whole = q["turning_moment"]["value"]
    parts = q["inertia_torque_reciprocating"]["value"] + q["inertia_torque_rod"]["value"]
    size = abs(q["inertia_torque_reciprocating"]["value"]) + abs(q["inertia_torque_rod"]["value"])
    assert abs(parts - whole) <= 1e-12 * max(size, abs(whole))
