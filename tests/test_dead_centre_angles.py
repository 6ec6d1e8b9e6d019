"""Every angle of a file is read as its [input] angle is: from the dead centre [input] names
(from = "t.d.c."), in the sense the crank turns. A position in [ask] at, or --angle, read
from +x instead would silently solve another position."""

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli

HERE = Path(__file__).parent / "reproducers"


def _input(tmp_path: Path, text: str, *args: str) -> dict:
    tmp_path.mkdir(exist_ok=True)
    path = tmp_path / "engine.toml"
    path.write_text(text, encoding="utf-8")
    out = tmp_path / "o"
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(out), "--no-pdf", *args])
    assert run.exit_code == 0, run.output
    return json.loads((out / "results.json").read_text())["positions"][0]


@pytest.mark.parametrize("turned", [54.3147, 120.0, 300.0])
def test_an_angle_in_at_is_turned_from_the_inputs_dead_centre(tmp_path, turned):
    """The vertical engine's t.d.c. points up (90°) and its crank turns clockwise, so a crank
    turned t from the t.d.c. stands at 90° − t from +x."""
    text = (HERE / "en2-vertical-travel.toml").read_text(encoding="utf-8")
    at = text.replace("at = [{ travel = 40 }]", f"at = [{{ angle = {turned} }}]")
    position = _input(tmp_path, at)
    assert position["input"]["angle_deg"] % 360.0 == pytest.approx((90.0 - turned) % 360.0,
                                                                  abs=1e-9)
    assert position["position"].startswith(f"{turned:g}° from the t.d.c.")


def test_the_angle_option_is_turned_from_it_too(tmp_path):
    text = (HERE / "en2-vertical-travel.toml").read_text(encoding="utf-8")
    position = _input(tmp_path / "a", text.replace("at = [{ travel = 40 }]\n", ""),
                      "--angle", "54.3147")
    travelled = _input(tmp_path / "b", text)
    # 40 mm down is 54.3147° from the t.d.c.: the same crank to the figures printed
    assert position["input"]["angle_deg"] == pytest.approx(
        travelled["input"]["angle_deg"], abs=1e-4)
