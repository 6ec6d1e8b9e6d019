"""An engine's asks as the books pose them: the speed at which the gudgeon pin's load
reverses in rpm beside rad/s, and the inertia torque on the crankshaft split between the
reciprocating parts and the rod."""

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

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
