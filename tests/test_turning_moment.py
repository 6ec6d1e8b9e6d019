"""The turning-moment diagram and the flywheel, against closed forms.

- A torque T_m + A·sin kθ swings the energy through 2A/k (E = −(A/k)·cos kθ); the
  trapezoid and straight-line intercepts are good to (2π/N)² relative.
- The crank-shaper cutting 1000 N on its slow stroke: over a turn the driver does the
  cut's work and nothing else (weight and inertia give back what they take), so the mean
  torque is 1000 N × stroke / 2π, the stroke 2·880·tan(asin 0.36) mm by the lever's limits.
  The cut switches on and off between samples, an error of at most the jump times a step
  over the turn: 1e-3 at 360 steps.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.constructions.errors import InputError
from tarsim.constructions.reference.flywheel import (fluctuation, flywheel_inertia,
                                                     speed_fluctuation)
from tarsim.exercises.catalog import bundled_forces
from tarsim.exercises.cli import cli
from tarsim.exercises.exercise_file import load_exercise, parse_exercise
from tarsim.exercises.turning_moment import turning_moment

FORCES = {name: Path(path) for name, path in bundled_forces().items()}
SHAPER = FORCES["crank-shaper-forces"]


@pytest.mark.parametrize("k", [1, 2, 3])
def test_a_sine_torque_swings_the_energy_by_2a_over_k(k):
    n = 3600
    angles = [2 * math.pi * i / n for i in range(n)]
    r = fluctuation(angles, [80.0 + 25.0 * math.sin(k * t + 0.3) for t in angles])
    assert r.mean == pytest.approx(80.0, rel=1e-14)
    assert r.delta_e == pytest.approx(2 * 25.0 / k, rel=1e-5)
    assert len(r.intercepts) == len(r.areas) == 2 * k
    assert sum(r.areas) == pytest.approx(0.0, abs=1e-9)
    assert all(abs(a) == pytest.approx(2 * 25.0 / k, rel=1e-5) for a in r.areas)


def test_the_flywheel_formulas_invert_each_other():
    i = flywheel_inertia(300.0, 20.0, 0.02)
    assert i == pytest.approx(300.0 / (0.02 * 400.0), rel=1e-15)
    assert speed_fluctuation(300.0, 20.0, i) == pytest.approx(0.02, rel=1e-15)


def test_the_shapers_mean_torque_pays_for_the_cut():
    tm = turning_moment(load_exercise(SHAPER), 360)
    stroke = 2 * 0.880 * math.tan(math.asin(0.36))
    r = tm.reading
    assert r.mean == pytest.approx(1000.0 * stroke / (2 * math.pi), rel=1e-3)
    assert tm.power_miss < 1e-12
    # one rise above the mean while the ram returns, one fall while it cuts
    assert len(r.areas) == 2 and r.areas[0] == pytest.approx(-r.areas[1], rel=1e-12)
    assert r.delta_e == pytest.approx(max(abs(a) for a in r.areas), rel=1e-12)


def test_sweep_writes_the_turning_moment_and_sizes_the_flywheel(tmp_path):
    out = tmp_path / "sw"
    result = CliRunner().invoke(cli, ["sweep", str(SHAPER), "-o", str(out), "--no-pdf",
                                      "--steps", "120"])
    assert result.exit_code == 0, result.output
    assert {"turning-moment.svg", "turning-moment.csv"} <= {p.name for p in out.iterdir()}
    assert "flywheel for C_s = 0.05 at ω = 1 rad/s: I = ΔE/(C_s·ω²) = " in result.output
    assert "balance of power agrees at every step" in result.output
    rows = (out / "turning-moment.csv").read_text(encoding="utf-8").splitlines()
    assert rows[0].startswith("turned_deg,theta_deg,T_Nm,F_12_N") and len(rows) == 121


@pytest.mark.parametrize("old, new, words", [
    ("speed_fluctuation = 0.05", "speed_fluctuation = 0.05\nflywheel = 2",
     "give speed_fluctuation (the flywheel is found) or flywheel"),
    ("speed_fluctuation = 0.05", "speed_fluctuation = -0.05",
     "a coefficient of speed fluctuation must be positive"),
    ("resist = 1000\nstroke = \"slow\"", "resist = 1000\nstroke = \"cutting\"",
     "stroke is both, slow or fast, not 'cutting'"),
    ("link = 5\npoint = \"B\"\nresist", "link = 3\npoint = \"A\"\nresist",
     "a slow stroke belongs to a point on a frame guide"),
    ("resist = 1000", "resist = 1000\nforce = [1, 0]", "in place of force = [x, y]"),
])
def test_bad_flywheel_and_cut_settings_are_refused_in_one_line(old, new, words):
    text = SHAPER.read_text(encoding="utf-8")
    assert old in text
    with pytest.raises(InputError) as e:
        parse_exercise(text.replace(old, new, 1), "cs.toml", "cs")
    message = str(e.value)
    assert "\n" not in message and message.startswith("cs.toml:") and words in message, message


def test_the_force_polygons_fall_on_the_turning_moment_curve():
    """The driving torque the force polygons draw at the exercise's two positions stands on
    the curve (the Newton–Euler torque at the same angle), to a few roundings."""
    tm = turning_moment(load_exercise(SHAPER), 36)
    assert [label.split(" (")[0] for *_, label in tm.marks] == ["θ2 = 90°", "t = 2.34 s"]
    for _, drawn, curve, _ in tm.marks:
        assert drawn == pytest.approx(curve, rel=1e-12)
    assert tm.marks[0][1] == pytest.approx(232.941176, rel=1e-8)    # clockwise positive


def test_the_diagram_is_drawn_at_steady_speed():
    """The loaded four-bar's file gives α2 = 5 rad/s² at its one position; round the turn
    the input runs steadily (α = 0), so weight, inertia and a couple on a rocker (which
    swings back over its own path) do no net work: the mean torque is 0, and the drawn
    position, which speeds up, is no mark on the steady curve."""
    tm = turning_moment(load_exercise(FORCES["four-bar-forces"]), 72)
    assert tm.reading.mean == 0.0
    assert tm.marks == []
    assert tm.lines()[0].startswith("at steady speed, mean driving torque 0 N·m")


def test_a_constant_gas_force_does_no_net_work():
    """engine-forces: 5 kN of gas all round the turn, weight and inertia: all conservative
    or periodic at steady speed, so the mean is 0, said as 0 and not as its rounding."""
    tm = turning_moment(load_exercise(FORCES["engine-forces"]), 72)
    assert tm.reading.mean == 0.0 and tm.reading.delta_e > 100.0


def test_a_flywheel_for_a_standing_input_is_refused():
    text = SHAPER.read_text(encoding="utf-8").replace("omega = -1 ", "omega = 0 ", 1)
    with pytest.raises(InputError, match=r"cs.toml:\d+: a flywheel holds a speed, but link "
                                         r"2's ω is 0 in \[input\]"):
        parse_exercise(text, "cs.toml", "cs")
