"""A load that changes with the position: a [[force]]'s pressure given as a list, one for each
of [ask] at's positions in order, as the books give a steam pressure at each crank angle."""

from __future__ import annotations

import json
import math

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli

R, L, BORE, MASS = 0.25, 1.25, 0.4, 250.0
OMEGA = 150 * math.pi / 30

ENGINE = """
[units]
length = "mm"
angular_velocity = "rpm"
[frame]
O = [0, 0]
[[link]]
number = 2
points = ["O", "A"]
lengths = { OA = 250 }
[[link]]
number = 3
points = ["A", "P"]
lengths = { AP = 1250 }
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
from = "i.d.c."
omega = 150
[assembly]
P = "forward"
[ask]
find = ["turning_moment"]
methods = ["polygon"]
AT
[forces]
gravity = false
[[mass]]
link = 4
mass = 250
centre = "P"
[[force]]
link = 4
point = "P"
PRESSURE
bore = 400
"""


def _text(at: str = 'at = [{ angle = 30 }, { angle = 150 }]',
          pressure: str = 'pressure = ["0.45 N/mm²", "0.3 N/mm²"]') -> str:
    return ENGINE.replace("AT", at).replace("PRESSURE", pressure)


def _turning_moment(theta_deg: float, pressure: float, gas: float | None = None) -> float:
    """T = F_P·r·sin(θ + φ)/cos φ, F_P = p·πD²/4 (or ``gas`` N toward the crank) − m·a, a the
    piston's exact acceleration toward the crank at steady ω, sin φ = r sin θ/l."""
    t = math.radians(theta_deg)
    s = math.sqrt(L * L - (R * math.sin(t)) ** 2)
    a = OMEGA ** 2 * (R * math.cos(t) + R * R * math.cos(2 * t) / s
                      + R ** 4 * math.sin(t) ** 2 * math.cos(t) ** 2 / s ** 3)
    effort = (pressure * math.pi * BORE ** 2 / 4 if gas is None else gas) - MASS * a
    phi = math.asin(R * math.sin(t) / L)
    return effort * R * math.sin(t + phi) / math.cos(phi)


def _run(tmp_path, text: str):
    tmp_path.mkdir(parents=True, exist_ok=True)
    path = tmp_path / "e.toml"
    path.write_text(text, encoding="utf-8")
    return CliRunner().invoke(cli, ["solve", str(path), "--no-pdf", "-o", str(tmp_path / "e")])


def test_forces_pressure_per_position(tmp_path):
    """The books' engine: 0.45 N/mm² at 30° from the i.d.c. and 0.3 N/mm² at 150°, asked in
    one file, gives each position's turning moment with its own pressure (the books'
    approximate acceleration gives 6112.7 and 5111.7 N·m; the exact one 6108.15, 5108.43)."""
    result = _run(tmp_path, _text())
    assert result.exit_code == 0, result.output
    positions = json.loads((tmp_path / "e" / "results.json").read_text())["positions"]
    got = [p["quantities"]["turning_moment"]["value"] for p in positions]
    # the polygons and the Newton–Euler reference agree to rounding of a few N in 10⁵
    assert got[0] == pytest.approx(_turning_moment(30, 0.45e6), rel=1e-9)
    assert got[1] == pytest.approx(_turning_moment(150, 0.3e6), rel=1e-9)
    assert round(got[0], 2) == 6108.15 and round(got[1], 2) == 5108.43


def test_the_same_pressure_list_in_another_order_swaps_the_moments(tmp_path):
    """The list is matched to the positions in order, not by size."""
    result = _run(tmp_path, _text(pressure='pressure = ["0.3 N/mm²", "0.45 N/mm²"]'))
    assert result.exit_code == 0, result.output
    positions = json.loads((tmp_path / "e" / "results.json").read_text())["positions"]
    got = [p["quantities"]["turning_moment"]["value"] for p in positions]
    assert got[0] == pytest.approx(_turning_moment(30, 0.3e6), rel=1e-9)
    assert got[1] == pytest.approx(_turning_moment(150, 0.45e6), rel=1e-9)


def _moments(tmp_path, text: str) -> list[float]:
    result = _run(tmp_path, text)
    assert result.exit_code == 0, result.output
    positions = json.loads((tmp_path / "e" / "results.json").read_text())["positions"]
    return [p["quantities"]["turning_moment"]["value"] for p in positions]


def test_a_force_per_position(tmp_path):
    """force = [[-1000, 0], [-3000, 0]]: 1000 N toward the crank at 30°, 3000 N at 150°."""
    got = _moments(tmp_path, _text(pressure="force = [[-1000, 0], [-3000, 0]]")
                   .replace("bore = 400", ""))
    assert got[0] == pytest.approx(_turning_moment(30, 0, 1000), rel=1e-9)
    assert got[1] == pytest.approx(_turning_moment(150, 0, 3000), rel=1e-9)


def test_a_resisting_force_per_position_is_each_position_s_own(tmp_path):
    """resist = [1000, 3000] gives at each position what resist = 1000 (or 3000) alone does."""
    listed = _moments(tmp_path / "a", _text(pressure="resist = [1000, 3000]")
                      .replace("bore = 400", ""))
    alone = [_moments(tmp_path / f"b{k}", _text(pressure=f"resist = {v}")
                      .replace("bore = 400", ""))[k] for k, v in enumerate((1000, 3000))]
    assert listed == pytest.approx(alone, rel=1e-12)
    # and the resistance counts: without it the moments differ by its own r·sin(θ+φ)/cos φ
    assert abs(listed[1] - _turning_moment(150, 0)) > 100


@pytest.mark.parametrize("at, pressure, words", [
    ('at = [{ angle = 30 }, { angle = 150 }, { angle = 90 }]', None,
     "2 given here, 3 positions there"),
    ('', None, "list them there"),
    (None, 'pressure = []', "0 given here, 2 positions there"),
    (None, 'resist = [1000]', "a resist per position"),
    ('at = [{ angle = 30, pressure = "0.45 N/mm²" }]', None,
     "a pressure that changes with the position is a list in its [[force]]"),
    (None, 'pressure = ["0.45 N/mm²", "a lot"]', "pressure"),
])
def test_a_pressure_list_that_does_not_match_the_positions_is_refused(at, pressure, words,
                                                                        tmp_path):
    kw = {k: v for k, v in (("at", at), ("pressure", pressure)) if v is not None}
    result = _run(tmp_path, _text(**kw))
    assert result.exit_code == 1
    (line,) = result.output.strip().splitlines()
    assert line.startswith("Error: ") and "e.toml:" in line and words in line, line
    assert not (tmp_path / "e").exists()


def test_a_turn_swept_refuses_a_pressure_per_position(tmp_path):
    """The turning moment round the turn has no pressure between the listed positions: it is
    refused in one line, not drawn with the first's."""
    path = tmp_path / "e.toml"
    path.write_text(_text(), encoding="utf-8")
    result = CliRunner().invoke(cli, ["sweep", str(path), "-o", str(tmp_path / "s")])
    assert result.exit_code == 1
    (line,) = result.output.strip().splitlines()
    assert line.startswith("Error: ") and "a pressure given per position" in line, line
