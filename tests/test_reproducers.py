"""Inputs that once failed, each held to the answer it should have given.

Every file in ``tests/reproducers/`` once gave a traceback or a wrong answer. The
numbers asserted here are the course's closed forms (a slotted lever's time ratio
(180° + 2α)/(180° − 2α) with sin α = O2A/O2O4; a crank-rocker's limits with crank
and rod in line; Grashof's breakpoint S + L = P + Q) or the analytic solver run
round the revolution, never what tarsim printed. Files that cannot be solved must
give one line naming the file, its line and the setting, exit 1, and write nothing.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from click.testing import CliRunner

import tarsim
from tarsim.constructions import registry
from tarsim.constructions.errors import AssemblyError, InputError
from tarsim.constructions.linkages.limit_positions import draw_limit_positions
from tarsim.constructions.model import Drive
from tarsim.constructions.reference.limits import limit_reference
from tarsim.constructions.reference import solver
from tarsim.exercises.catalog import bundled, load
from tarsim.exercises.cli import cli
from tarsim.exercises.linkages.solution import solve_overall

HERE = Path(__file__).parent / "reproducers"


def solved(name: str):
    """The reproducer ``name`` solved through the Python API."""
    return tarsim.solve(tarsim.load(str(HERE / f"{name}.toml")))


def overall(name: str) -> dict:
    return solved(name).results["quantities"]


def slotted_lever_ratio(crank: float, centres: float) -> float:
    """(180° + 2α)/(180° − 2α), sin α = O2A / O2O4: the lever tangent to the crank circle."""
    alpha = math.degrees(math.asin(crank / centres))
    return (180.0 + 2.0 * alpha) / (180.0 - 2.0 * alpha)


# ----- wrong answers --------------------------------------------------------------------------
def test_check_dof_at_change_point_position():
    """A change-point position has mobility one, and momentarily two."""
    # O2A = O4B = 100, AB = O2O4 = 300 at θ2 = 0°: A, B, O2 and O4 lie on one line, where the
    # parallelogram and the antiparallelogram assemblies meet.
    q = overall("check-dof-at-change-point-position")["dof"]
    assert (q["value"], q["here"]) == (1, 2)
    assert q["reference"] == {"value": 1, "here": 2}
    assert q["passed"]
    assert "change point" in q["method"]


def test_away_from_the_change_point_the_mobility_is_one(tmp_path):
    text = (HERE / "check-dof-at-change-point-position.toml").read_text(encoding="utf-8")
    path = tmp_path / "turned.toml"
    path.write_text(text.replace("angle = 0 ", "angle = 60 ", 1), encoding="utf-8")
    q = tarsim.solve(tarsim.load(str(path))).results["quantities"]["dof"]
    assert "here" not in q and q["value"] == 1 and q["reference"] == {"value": 1}


def test_check_range_bracket_skips_gap():
    """The crank range stops at Grashof's breakpoint, not past the triple-rocker gap."""
    g, b, c = 298.2558607712765, 335.6835800020368, 168.17049912159501
    q = overall("check-range-bracket-skips-gap")["range_O2A"]
    # O2A + AB = O2O4 + O4B: beyond it a triple-rocker; further on a crank-rocker again, but
    # one whose crank is the rocker O4B, which is another mechanism.
    high = (g + c - b) / 1000.0
    assert q["low"] == 0.0
    assert q["high"] == pytest.approx(high, rel=1e-12)
    # The reference bisects the turning test, whose slack is 1e-12 of the loop; 1e-9 of the
    # longest link is the check's own tolerance for a range.
    assert q["reference"]["low"] == 0.0
    assert q["reference"]["high"] == pytest.approx(high, abs=1e-9 * b / 1000.0)
    assert q["passed"]


def test_check_range_change_point_parallelogram():
    """A change-point linkage keeps its class at its length alone."""
    q = overall("check-range-change-point-parallelogram")["range_AB"]
    assert q["low"] == q["high"] == 0.3
    assert q["reference"]["low"] == pytest.approx(0.3, abs=1e-9 * 0.3)
    assert q["reference"]["high"] == pytest.approx(0.3, abs=1e-9 * 0.3)
    assert q["passed"]
    assert "change-point linkage" in q["method"]


def test_check3_grashof_range_change_point():
    # Links 100, 101, 100, 100 (frame O2O4 = 100): with x for any of the 100s, S + L =
    # x + 101 > P + Q = 200 from x = 99 up, a triple-rocker; at x = 101 the loop is
    # 100, 100, 101, 101, S + L = P + Q, a change point, which ends the range.
    q = overall("check3-grashof-range-change-point")
    for span in ("O2O4", "O4B", "O2A"):
        got = q[f"range_{span}"]
        assert (got["low"], got["high"], got["class"]) == (0.099, 0.101, "triple-rocker")
        # The reference bisects the turning test to 1e-12 of the loop; 1e-9 of the
        # longest link is the check's own tolerance for a range.
        assert got["reference"]["low"] == pytest.approx(0.099, abs=1e-9 * 0.101)
        assert got["reference"]["high"] == pytest.approx(0.101, abs=1e-9 * 0.101)
        assert got["passed"]


def test_slow_sweep_rhombus_far(monkeypatch):
    # A rhombus (every link 100 mm), 1 km from the origin, on the branch where its rocker
    # stands still: ω4 is 0, or ω2 where it has folded over into a parallelogram, and its
    # rounding about 0 once sent the sweep bisecting 218 "reversals" of 1e-15 rad/s.
    from tarsim.constructions.reference.turn import TurnSolver
    from tarsim.exercises.linkages import sweep
    calls = []
    real = TurnSolver.solve
    monkeypatch.setattr(TurnSolver, "solve",
                        lambda self, *a, **k: calls.append(1) or real(self, *a, **k))
    ex = tarsim.load(str(HERE / "slow-sweep-rhombus-far.toml"))
    sw = sweep.sweep_exercise(ex, of="omega4")
    w2 = ex.mechanism.drive.omega
    for s in sw.solved:          # ω4 is 0 or ω2 (a link of a parallelogram turns as its twin)
        w4 = s.values["omega"]
        # 1e-9, the checks' floor: a sample 0.1° from a fold, where the loop lies flat,
        # carries rounding some thousand times eps.
        assert min(abs(w4), abs(w4 - w2)) <= 1e-9 * abs(w2), (s.angle, w4)
    # One whole turn, and a bisection of some 60 steps for each of the few true changes.
    assert len(calls) <= 1 + 4 * len(sw.events)
    assert len(sw.events) <= 8
    # O4 stands 100 mm straight above O2: the crank lies along O2O4, A on O4, at θ2 = 90°
    # (the turn runs clockwise from 240°), and the rhombus may go on either way there.
    assert [n for n in sw.notes if "change point" in n] == [
        "the turn passes a change point at θ2 = 90°, where the linkage may go on in either "
        "assembly: beyond it the curves keep their [assembly] side, so they may pass from one "
        "motion to the other there"]


def test_check_stroke_p37_at_200deg():
    """P-37's stroke does not depend on the angle it is drawn from."""
    q = overall("check-stroke-p37-at-200deg")
    # The lever (O4B = 26 cm) swings ±α either side of O4O2, sin α = 6/16; the rod BC stands
    # the same way at both limits, so the ram moves as B does across: 2 · 26 · 6/16 = 19.5 cm.
    assert q["stroke"]["value"] == pytest.approx(0.195, rel=1e-12)
    assert q["time_ratio"]["value"] == pytest.approx(slotted_lever_ratio(6, 16), rel=1e-12)
    assert q["stroke"]["passed"] and q["time_ratio"]["passed"]


@pytest.mark.slow
def test_check_stroke_velocity_homework_292():
    """Homework 292's stroke is the block's whole travel."""
    ex = tarsim.load(str(HERE / "check-stroke-velocity-homework-292.toml"))
    q = solve_overall(ex).quantities["stroke"]
    mech, d = ex.mechanism, ex.mechanism.drive
    guide = next(i for i, s in enumerate(mech.slides) if s.point == "D" and s.guide_link == 1)
    def place(degrees: float) -> float:
        drive = Drive(d.link, math.radians(degrees), 1.0)
        return solver.solve(mech.with_drive(drive)).slide_rates[guide].position

    # The block's place along its guide over the revolution, by the degree, then by the
    # hundredth of a degree either side of each end: there the travel is flat, so the
    # sampled ends fall short by at most s″·Δθ²/8 ≈ 1e-10 of it.
    coarse = [place(k) for k in range(360)]
    ends = []
    for pick in (max, min):
        k = coarse.index(pick(coarse))
        ends.append(pick(place(k + j / 100) for j in range(-100, 101)))
    assert q.value["value"] == pytest.approx(ends[0] - ends[1], rel=1e-8)
    assert q.value["value"] == pytest.approx(0.26293, abs=5e-6)     # 262.93 mm, as the sweep gives
    assert q.passed


def test_check_time_ratio_huge_input_angle():
    """A huge input angle is taken less its whole turns."""
    ex = tarsim.load(str(HERE / "check-time-ratio-huge-input-angle.toml"))
    # −1e9° is −280° and 2 777 777 whole turns; the degrees are reduced before they are
    # turned into radians, so nothing is lost.
    assert math.degrees(ex.mechanism.drive.angle) == pytest.approx(-280.0, abs=1e-12)
    q = overall("check-time-ratio-huge-input-angle")["time_ratio"]
    assert q["value"] == pytest.approx(slotted_lever_ratio(180, 500), rel=1e-12)
    assert q["reference"]["value"] == pytest.approx(slotted_lever_ratio(180, 500), rel=1e-12)
    assert q["passed"]


def test_check_time_ratio_point_branch():
    """A branch given as a point is followed round the revolution."""
    g, r, rod, rocker = 300.0, 100.0, 250.0, 200.0

    def at_o2(diagonal: float) -> float:
        """The angle at O2 between O2O4 and O2B, for |O2B| = diagonal."""
        return math.degrees(math.acos((g * g + diagonal * diagonal - rocker * rocker)
                                      / (2 * g * diagonal)))

    # Crank and rod in line: extended (|O2B| = AB + O2A) and folded (AB − O2A), the crank
    # turning 180° ± the angle between the two lines O2B.
    between = at_o2(rod - r) - at_o2(rod + r)
    ratio = (180.0 + abs(between)) / (180.0 - abs(between))
    q = overall("check-time-ratio-point-branch")["time_ratio"]
    assert q["value"] == pytest.approx(ratio, rel=1e-12)
    assert q["reference"]["value"] == pytest.approx(ratio, rel=1e-12)
    assert q["passed"]


QUICK_RETURNS = ("crank-pin-speed", "crank-shaper", "four-bar", "grashof-crank-rocker",
                 "hinkle-four-bar", "hinkle-slider-crank",           # rods carrying a point
                 "inverted-slider-crank", "klein-slider-crank", "offset-slider-crank",
                 "piston-driven-slider-crank", "slotted-lever-p37", "velocity-homework-292",
                 "whitworth")                                         # its ram, the lever in line
"""The bundled mechanisms with two limit positions: their cranks turn fully and drive an
output that reverses."""


def test_the_quick_returns_are_every_bundled_mechanism_with_limit_positions():
    # The others fit the construction's dyads but have no limits to draw: a double-crank, and
    # six-bars whose cranks do not turn fully. Each says so in one line; none answers.
    for exercise_id in sorted(bundled()):
        ex = load(exercise_id)
        if exercise_id in QUICK_RETURNS or "time_ratio" not in registry.askable(ex.mechanism):
            continue
        with pytest.raises((InputError, AssemblyError)) as caught:
            solve_overall(ex.asking(("time_ratio",)))
        assert "limit position" in str(caught.value) or "turn fully" in str(caught.value)


def test_a_whitworth_lever_turns_fully_so_its_time_ratio_is_its_rams():
    # the lever has no limits of its own; the ram it drives reverses with lever and rod in
    # line, and the reference follows the ram (tests/test_whitworth_limits.py: closed form)
    lp = draw_limit_positions(load("whitworth").mechanism)
    assert lp.kind == "whitworth" and lp.point == "C"
    assert "time_ratio" in registry.askable(load("whitworth").mechanism)


def turned(mech, degrees: float):
    d = mech.drive
    return mech.with_drive(Drive(d.link, math.radians(degrees), d.omega, d.alpha,
                                 d.alpha_given))


@pytest.mark.parametrize("exercise_id", QUICK_RETURNS)
def test_every_bundled_quick_return_draws_one_time_ratio_and_stroke_from_twelve_angles(
        exercise_id):
    mech = load(exercise_id).mechanism
    first = draw_limit_positions(mech)
    ref = limit_reference(mech, point=first.point, link=first.output)
    for k in range(12):
        lp = draw_limit_positions(turned(mech, 30 * k))
        # 1e-9 is the check's tolerance for a time ratio or stroke drawn at conditioning ≥ 0.1.
        assert lp.time_ratio == pytest.approx(ref.time_ratio, rel=1e-9), 30 * k
        if ref.stroke is not None:
            assert lp.stroke == pytest.approx(ref.stroke, rel=1e-9), 30 * k


@pytest.mark.slow
def test_the_reference_finds_both_reversals_whichever_angle_it_starts_from():
    # From θ2 = 210° the offset slider-crank starts on a reversal; sampled a turn apart, its
    # speed there rounds to both signs, and the reversal was missed.
    mech = load("offset-slider-crank").mechanism
    point = draw_limit_positions(mech).point
    refs = [limit_reference(turned(mech, 30 * k), point=point) for k in range(12)]
    for r in refs:
        assert r.time_ratio == pytest.approx(refs[0].time_ratio, rel=1e-12)
        assert r.stroke == pytest.approx(refs[0].stroke, rel=1e-12)


# ----- one clear line -----------------------------------------------------------------------------
ONE_LINE = [
    ("crash-1-huge-omega",
     r"crash-1-huge-omega\.toml:33: \[input\.omega\] omega = 1e\+155 is out of the range tarsim "
     r"takes \(between 1e-30 and 1e30 in size, or 0\)"),
    ("crash-2-at-position-point-branch",
     r"link 3 \(coupler, AB = 250 mm\) cannot reach the circle of B about O4 at θ2 = 180°: "
     r"\|O4A\| = 500 mm > 250 mm \+ 200 mm"),
    ("crash-3-nice-scale", r"crash-3-nice-scale\.toml:33: \[input\.omega\] omega = 1e\+154 is out"),
    ("crash-4a-at-time-squared",
     r"crash-4a-at-time-squared\.toml:42: \[ask\.at\] time in at must be a number between 1e-30 "
     r"and 1e30 in size, or 0, got 1e\+200"),
    ("crash-4b-at-time-angle-inf",
     r"crash-4b-at-time-angle-inf\.toml:34: \[input\.alpha\] alpha = 1e\+300 is out"),
    ("crash-6-latin1",
     r"crash-6-latin1\.toml:42: is not UTF-8 text \(byte 0xe9\); save it as UTF-8"),
    ("crash-7-control-char-in-name",
     r"crash-7-control-char-in-name\.toml:1: \[name\] name holds the control character U\+202E"),
    ("crash-8-deep-nesting-500",
     r"crash-8-deep-nesting-500\.toml:16:47: nests arrays or tables too deeply to read"),
    ("nan-5-huge-alpha", r"nan-5-huge-alpha\.toml:30: \[input\.alpha\] alpha = 1e\+300 is out"),
]
"""Each hostile reproducer and the line it must be refused with."""


@pytest.mark.parametrize("name, says", [pytest.param(n, says, id=n) for n, says in ONE_LINE])
def test_a_hostile_file_gets_one_line_and_leaves_nothing(tmp_path, name, says):
    out = tmp_path / "solution"
    result = CliRunner().invoke(cli, ["solve", str(HERE / f"{name}.toml"), "-o", str(out),
                                      "--no-pdf"], catch_exceptions=False)
    assert result.exit_code == 1, result.output
    assert result.stdout == ""
    err = result.stderr
    assert err.startswith("Error: ") and err.count("\n") == 1, err
    assert re.search(says, err), err
    assert not out.exists()


def test_noplace_omega_from_centres(tmp_path):
    # BC = 120 km puts the ram's centres so far out that I24 and I14 meet to rounding: the
    # refusal names the file and the position it was drawn at, as any error of solving.
    out = tmp_path / "solution"
    path = HERE / "noplace-omega-from-centres.toml"
    result = CliRunner().invoke(cli, ["solve", str(path), "-o", str(out), "--no-pdf"],
                                catch_exceptions=False)
    assert result.exit_code == 1 and result.stdout == ""
    assert result.stderr == (
        f"Error: {path}: at θ2 = 323.661°: ω4 from the instant centres: I24 and I14 fall "
        "together at this position, so the ratio of their distances is lost to rounding; "
        "find ω4 by the velocity polygon\n")
    assert not out.exists()


@pytest.mark.parametrize("angle", ["inf", "-inf", "nan"])
def test_an_angle_option_that_is_not_finite_gets_one_line(tmp_path, angle):
    result = CliRunner().invoke(cli, ["solve", "four-bar", "-o", str(tmp_path / "s"),
                                      "--no-pdf", "--angle", angle], catch_exceptions=False)
    assert result.exit_code == 1
    assert result.stderr.startswith("Error: --angle must be a finite number")
    assert not (tmp_path / "s").exists()


def test_an_angle_option_is_taken_less_whole_turns():
    # 1e9° is 280° and whole turns, as in a file: the check prints the position it solved.
    result = CliRunner().invoke(cli, ["check", "four-bar", "--angle", "1e9"],
                                catch_exceptions=False)
    assert result.exit_code == 0, result.output
    assert "280°" in result.stdout


@pytest.mark.slow
def test_markup_in_a_name_is_escaped_in_every_figure(tmp_path):
    text = (HERE / "crash-7-control-char-in-name.toml").read_text(encoding="utf-8")
    hostile = "a<script>&amp;</svg>"
    path = tmp_path / "markup.toml"
    path.write_text(text.replace(text.splitlines()[0], f'name = "{hostile}"', 1),
                    encoding="utf-8")
    solution = tarsim.solve(tarsim.load(str(path)))
    for stem, figure in solution.figures.items():
        root = ET.fromstring(figure._repr_svg_())     # well-formed, whatever the name holds
        titles = [t.text for t in root.iter("{http://www.w3.org/2000/svg}title")]
        assert any(hostile in (t or "") for t in titles), stem
