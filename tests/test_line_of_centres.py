"""A crank between two frame pivots turned from its line of centres, as the books give a
slotted lever's ("120° with OC produced, measured clockwise"): every angle of the file is
read from there, in the sense ω turns."""

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli

HERE = Path(__file__).parent / "reproducers"
L2 = HERE / "l2-slotted-lever-line-of-centres.toml"


def _solve(tmp_path: Path, text: str, *args: str):
    tmp_path.mkdir(exist_ok=True)
    path = tmp_path / "m.toml"
    path.write_text(text, encoding="utf-8")
    out = tmp_path / "o"
    return CliRunner().invoke(cli, ["solve", str(path), "-o", str(out), "--no-pdf", *args]), out


def _position(tmp_path: Path, text: str, *args: str) -> dict:
    run, out = _solve(tmp_path, text, *args)
    assert run.exit_code == 0, run.output
    return json.loads((out / "results.json").read_text())["positions"][0]


def test_l2_slotted_lever_line_of_centres(tmp_path):
    """O, the lever's fulcrum, is 200 mm below C, the crank's pivot: OC produced points up
    (90°), and the crank turns clockwise, so 120° from it is 90° − 120° = −30° from +x. The
    values are the hand solution's (circle intersection, differentiated to ~1e-8), given to
    six figures, so 5e-6 relative holds them to their last figure."""
    position = _position(tmp_path, L2.read_text(encoding="utf-8"))
    assert position["input"]["angle_deg"] == pytest.approx(-30.0, abs=1e-9)
    got = position["quantities"]
    hand = {"V_R": 0.240832, "A_R": 23.7551, "omega4": 0.76937, "alpha4": 75.1852,
            "A_cor_P": 1.43535, "A_slide_P": 1.79552}        # SI: m/s, m/s², rad/s, rad/s²
    for name, value in hand.items():
        assert got[name]["value"] == pytest.approx(value, rel=5e-6), name


@pytest.mark.parametrize(("said", "omega", "theta"), [
    ("line of centres", 10, 60.0), ("line of centres", -10, -60.0),
    ("line of centres produced", 10, 240.0), ("Line of Centers produced", -10, 120.0)])
def test_a_four_bar_turned_from_its_line_of_centres(tmp_path, said, omega, theta):
    """O2 at the origin and O4 300 mm along +x: toward O4 is 0°, produced beyond O2 180°;
    60° from there the way ω turns."""
    text = Path(__file__).parents[1].joinpath("docs", "howto", "linkages.md")
    four_bar = text.read_text(encoding="utf-8").split("```toml\n", 1)[1].split("```", 1)[0]
    four_bar = four_bar.replace("omega = 10 ", f'from = "{said}"\nomega = {omega} ')
    position = _position(tmp_path, four_bar)
    assert position["input"]["angle_deg"] % 360 == pytest.approx(theta % 360, abs=1e-9)


def test_the_angle_option_is_turned_from_the_line_of_centres(tmp_path):
    """--angle 120 is the file's own 120° from OC produced: θ2 = −30° as before."""
    text = L2.read_text(encoding="utf-8").replace("angle = 120", "angle = 0")
    position = _position(tmp_path, text, "--angle", "120")
    assert position["input"]["angle_deg"] == pytest.approx(-30.0, abs=1e-9)


def test_a_slider_crank_has_no_line_of_centres(tmp_path):
    """One frame pivot only: the refusal says so on one line and asks for the angle from +x."""
    text = (HERE / "en2-vertical-travel.toml").read_text(encoding="utf-8")
    text = text.replace('from = "t.d.c."', 'from = "line of centres"')
    assert 'from = "line of centres"' in text
    run, out = _solve(tmp_path, text)
    assert run.exit_code == 1 and not out.exists()
    line = run.output.strip()
    assert "\n" not in line and len(line.split("] ", 1)[1]) < 200
    assert "a line of centres joins the crank's pivot to one other: link 2 turns about O, " \
        "the others about none; give the angle from +x" in line, line
