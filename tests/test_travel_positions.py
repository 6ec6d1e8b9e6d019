"""A position by the piston's travel from the inner dead centre, as the books set an engine
("when the piston has moved one-fourth of its stroke"): the crank angle found is the closed
form's, on the out-stroke turning with ω, and a file that cannot mean it is refused."""

import json
import math

import pytest
from click.testing import CliRunner

from tarsim.exercises.cli import cli

R, L = 300.0, 1500.0

ENGINE = """
name = "Engine by its piston's travel"
[units]
length = "mm"
angular_velocity = "rpm"
[frame]
O = [0, 0]
[[link]]
number = 2
points = ["O", "A"]
lengths = {{ OA = "600/2" }}
[[link]]
number = 3
points = ["A", "P"]
lengths = {{ AP = 1500 }}
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
angle = 0
omega = {omega}
[assembly]
P = "forward"
[ask]
find = ["V_P"]
methods = ["polygon"]
at = {at}
"""


def _travel_angle(x: float) -> float:
    """θ (deg, 0 to 180) from the i.d.c. where the piston has moved x: the book's exact
    x = r(1 − cos θ) + l − √(l² − r² sin² θ), which rises over the out-stroke, bisected."""
    lo, hi = 0.0, math.pi
    for _ in range(200):
        mid = (lo + hi) / 2
        moved = R * (1 - math.cos(mid)) + L - math.sqrt(L * L - (R * math.sin(mid)) ** 2)
        lo, hi = (mid, hi) if moved < x else (lo, mid)
    return math.degrees(lo)


def _solve(tmp_path, omega=200, at='[{ stroke = "1/4" }, { travel = 450 }]'):
    path = tmp_path / "engine.toml"
    path.write_text(ENGINE.format(omega=omega, at=at), encoding="utf-8")
    out = tmp_path / "out"
    return CliRunner().invoke(cli, ["solve", str(path), "-o", str(out), "--no-pdf"]), out


def test_a_quarter_stroke_and_a_travel_give_the_closed_form_angles(tmp_path):
    run, out = _solve(tmp_path)
    assert run.exit_code == 0, run.output
    got = [p["input"]["angle_deg"] for p in
           json.loads((out / "results.json").read_text(encoding="utf-8"))["positions"]]
    # The angle is narrowed to the last bit of a well-conditioned travel (dx/dθ ≈ r sin θ,
    # far from 0 here): 1e-9° is a thousand times the rounding of the solver's positions.
    assert got[0] == pytest.approx(_travel_angle(0.25 * 600), abs=1e-9)
    assert got[1] == pytest.approx(_travel_angle(450), abs=1e-9)
    assert "150 mm from the i.d.c. (0.25 of the stroke)" in run.output


def test_a_clockwise_crank_travels_its_out_stroke_clockwise(tmp_path):
    run, out = _solve(tmp_path, omega=-200, at='[{ stroke = 0.25 }]')
    assert run.exit_code == 0, run.output
    (p,) = json.loads((out / "results.json").read_text(encoding="utf-8"))["positions"]
    assert p["input"]["angle_deg"] % 360 == pytest.approx(360 - _travel_angle(150), abs=1e-9)


@pytest.mark.parametrize("at, words", [
    ('[{ stroke = 1.5 }]', "the share of the stroke travelled, 0 to 1"),
    ('[{ travel = 700 }]', "past the piston's stroke, 600 mm"),
    ('[{ travel = "x/2" }]', "travel in at is a length in mm"),
])
def test_a_travel_the_piston_cannot_make_is_refused_at_its_line(tmp_path, at, words):
    run, out = _solve(tmp_path, at=at)
    assert run.exit_code == 1 and words in run.output, run.output
    line = ENGINE.format(omega=200, at=at).splitlines().index(f"at = {at}") + 1
    assert f"engine.toml:{line}:" in run.output and "Traceback" not in run.output
    assert not out.exists()


def test_a_four_bar_has_no_stroke_to_travel(tmp_path):
    from tarsim.exercises.templates import template

    text = template("linkage").replace('methods = ["radius-rotation", "polygon"]',
                                       'methods = ["polygon"]\nat = [{ stroke = "1/2" }]')
    path = tmp_path / "four-bar.toml"
    path.write_text(text, encoding="utf-8")
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "o"), "--no-pdf"])
    assert run.exit_code == 1 and "needs a crank driving a block" in run.output, run.output


def test_en2_vertical_travel(tmp_path):
    """A vertical engine (r 80, l 320 mm), the piston 40 mm down from the t.d.c.: the angle
    the crank has turned from the t.d.c. is asked, and the position is said from the t.d.c."""
    from pathlib import Path
    path = Path(__file__).parent / "reproducers" / "en2-vertical-travel.toml"
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "o"), "--no-pdf"])
    assert run.exit_code == 0, run.output
    position = json.loads((tmp_path / "o" / "results.json").read_text())["positions"][0]
    turned = position["turned_from_dead_centre"]
    r, rod = 80.0, 320.0

    def travel(t):           # the piston's travel from the t.d.c., the crank turned t
        return r * (1 - math.cos(t)) + rod - math.sqrt(rod * rod - (r * math.sin(t)) ** 2)

    lo, hi = 0.0, math.pi    # travel rises over the out-stroke: bisect it to the last bit
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if travel(mid) < 40.0 else (lo, mid)
    # the section search stops within a few ulps of the crank angle
    assert turned["value"] == pytest.approx(lo, abs=1e-12)
    assert turned["from"] == "t.d.c." and "from the t.d.c." in position["position"]
    assert "the crank 54.3147° past it" in position["position"]
