"""π in a file's numbers, as the books write a speed: "2π rad/s" is speed = "2*pi".

Only where the number is a float anyway (a cam's, a rotor's, a load's, a linkage's): a gear
train's numbers stay exact fractions, so π is no number there.
"""

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli
from tarsim.exercises.file_numbers import arithmetic, file_number

HERE = Path(__file__).parent / "reproducers"


@pytest.mark.parametrize("text, value", [("2*pi", 2 * math.pi), ("π/2", math.pi / 2),
                                         ("(180 + 60) * pi / 180", 4 * math.pi / 3),
                                         ("-pi", -math.pi)])
def test_pi_is_read_where_a_float_is(text, value):
    assert file_number(text, "x") == pytest.approx(value, rel=1e-15)
    assert arithmetic(text) is None           # an exact number (a gear's) has no π


@pytest.mark.parametrize("text", ["pi()", "pi ** 2", "math.pi", "e", "pie"])
def test_nothing_but_pi_is_a_name(text):
    assert arithmetic(text, pi=True) is None


def test_c3_base_circle_pressure_angle(tmp_path):
    run = CliRunner().invoke(cli, ["solve", str(HERE / "c3-base-circle-pressure-angle.toml"),
                                   "-o", str(tmp_path / "o"), "--no-pdf"])
    assert run.exit_code == 0, run.output
    q = json.loads((tmp_path / "o" / "results.json").read_text())["quantities"]
    h, w, beta = 0.025, 2 * math.pi, math.pi / 2            # m, rad/s, rad
    # cycloidal rise: v = 2hω/β, a = 2πhω²/β² (to the rounding of a few products)
    assert q["v_max_1"]["value"] == pytest.approx(2 * h * w / beta, rel=1e-12)
    assert q["a_max_1"]["value"] == pytest.approx(2 * math.pi * h * w**2 / beta**2, rel=1e-12)


def test_a_linkage_speed_in_pi(tmp_path):
    """The bundled four-bar at ω2 = "10*pi/π" is the four-bar at 10 rad/s."""
    from tarsim.exercises.catalog import everything
    text = Path(everything()["four-bar"]).read_text(encoding="utf-8")
    path = tmp_path / "f.toml"
    path.write_text(text.replace("omega = 10 ", 'omega = "10*pi/π" '), encoding="utf-8")
    assert 'omega = "10*pi/π"' in path.read_text(encoding="utf-8")
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "o"), "--no-pdf"])
    assert run.exit_code == 0, run.output
    q = json.loads((tmp_path / "o" / "results.json").read_text())["positions"][0]["quantities"]
    assert q["omega3"]["value"] == pytest.approx(-2.57846, abs=5e-6)   # as at 10 rad/s
