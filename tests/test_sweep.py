"""Tests for exercises.sweep (the whole-cycle check), graphics.plot and `tarsim sweep`/`list`.

Golden numbers are the crank-shaper's (seed 003 §5): O2A = r2 = 180 mm, O2O4 = r1 =
500 mm, ram line h = 380 mm above O2; the lever's half-swing is φ = asin(r2/r1), the ram
is extreme where the crank is square to the lever, at θ2 = −φ and 180° + φ, and the
stroke is 2 (r1 + h) tan φ = 679.134 mm. Seed 003 §7 gives the t = 2.34 s position.
"""

import csv
import io
import math
import xml.etree.ElementTree as ET

import pytest
from click.testing import CliRunner

from tarsim.constructions.errors import AssemblyError, InputError
from tarsim.exercises.catalog import resolve
from tarsim.exercises.cli import cli
from tarsim.exercises.linkages.exercise_file import load_exercise
from tarsim.exercises.linkages.sweep import pick_output, sweep_exercise
from tarsim.exercises.linkages.sweep_files import sweep_to_files
from tarsim.exercises.linkages.sweep_output import drive_at, evaluate
from tarsim.graphics import figure
from tarsim.graphics.plot import PlotMark, Series, draw_line_plot, nice_ticks
from tests.common import four_bar_toml

R1, R2, H = 500.0, 180.0, 380.0
PHI = math.asin(R2 / R1)
STROKE = 2 * (R1 + H) * math.tan(PHI)          # mm
SVG = "{http://www.w3.org/2000/svg}"


def exercise(name):
    return load_exercise(resolve(name), name)


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args], prog_name="tarsim",
                              catch_exceptions=False)


@pytest.fixture(scope="module")
def shaper():
    return sweep_exercise(exercise("crank-shaper"), 360)


@pytest.fixture(scope="module")
def shaper_files(shaper):
    return sweep_to_files(shaper)


def rows(text):
    return list(csv.reader(io.StringIO(text)))


# ----- the crank-shaper: seed 003 §5 ----------------------------------------------------------
def test_the_ram_is_the_default_output_and_is_signed_along_its_guide(shaper):
    assert shaper.output.kind == "slider" and shaper.output.point == "B"
    assert shaper.output.direction == (1.0, 0.0)
    assert len(shaper.samples) == 360 and len(shaper.solved) == 360
    # The sweep turns the way ω2 does (cw), from the [input] angle of 90°.
    assert math.degrees(shaper.samples[1].angle) == pytest.approx(89.0)


def test_refined_extremes_give_the_stroke_of_seed_003(shaper):
    assert STROKE == pytest.approx(679.134, abs=1e-3)            # seed 003 §5
    lo, hi = shaper.extent("s")
    # Refined by bisection to 1e-13 rad on the analytic solver: the step does not matter.
    assert (hi - lo) * 1e3 == pytest.approx(STROKE, rel=1e-12)
    assert hi * 1e3 == pytest.approx((R1 + H) * math.tan(PHI), rel=1e-12)


def test_the_table_alone_brackets_the_stroke_within_its_step(shaper):
    # At a 1° step an extreme is missed by at most δ = 0.5°, so by ½|s''| δ² with
    # s'' = A/ω2² there (V = 0, α2 = 0): the table's own acceleration bounds the error.
    s = [x.values["s"] for x in shaper.solved]
    table = max(s) - min(s)
    ends = [e for e in shaper.events if e.key == "v"]
    delta = math.radians(0.5)
    slack = sum(0.5 * abs(e.values["a"]) * delta ** 2 for e in ends)   # ω2 = 1 rad/s
    assert STROKE * 1e-3 - slack <= table <= STROKE * 1e-3
    assert slack < 1e-4 * STROKE * 1e-3                      # about (π/360)² relative


def test_the_velocity_is_zero_where_the_crank_is_square_to_the_lever(shaper):
    zeros = sorted(math.degrees(e.angle) % 360 for e in shaper.events if e.key == "v")
    # seed 003 §5: θ2 = −21.10° and 201.10°
    assert zeros == pytest.approx([180 + math.degrees(PHI), 360 - math.degrees(PHI)],
                                  abs=1e-9)
    assert zeros[0] == pytest.approx(201.10, abs=5e-3)
    assert zeros[1] - 360 == pytest.approx(-21.10, abs=5e-3)
    for e in shaper.events:
        if e.key == "v":
            assert abs(e.values["v"]) < 1e-12


def test_the_velocity_peaks_where_the_acceleration_is_zero(shaper):
    # The cutting stroke's peak at θ2 = 90° (O4A = r1 + r2 = 680 mm, O4B = 880 mm):
    # V = ω2 r2 · O4B / O4A; the return's at θ2 = 270° (O4A = 320 mm).
    peaks = {round(math.degrees(e.angle) % 360, 6): e.values["v"] * 1e3
             for e in shaper.events if e.key == "a"}
    assert peaks[90.0] == pytest.approx(R2 * (R1 + H) / (R1 + R2), rel=1e-12)
    assert peaks[270.0] == pytest.approx(-R2 * (R1 + H) / (R1 - R2), rel=1e-12)


def test_the_graphical_positions_sit_on_the_curve(shaper):
    checks = shaper.checks
    assert {c.position for c in checks} == {"θ2 = 90°", "t = 2.34 s"}
    assert {c.key for c in checks} == {"s", "v", "a"}
    for c in checks:
        assert c.rel_error < 1e-9, c
        assert c.graphical == pytest.approx(c.curve, rel=1e-9, abs=1e-12)
    at = {(c.key, c.method): c for c in checks if c.position == "t = 2.34 s"}
    # seed 003 §7: p = 303.643 mm, V = 189.192 mm/s to the left, A = 535.635 mm/s² left
    assert at["s", "compass (position)"].curve * 1e3 == pytest.approx(303.643, abs=1e-3)
    assert at["v", "radius-rotation"].graphical * 1e3 == pytest.approx(-189.192, abs=1e-3)
    assert at["a", "acceleration polygon"].graphical * 1e3 == pytest.approx(-535.635,
                                                                           abs=1e-3)


def test_the_csv_has_a_row_per_step_in_file_units(shaper, shaper_files):
    table = rows(shaper_files["sweep.csv"])
    assert table[0] == ["theta2 (deg)", "t (s)", "x_B (mm)", "y_B (mm)", "s_B (mm)",
                        "V_B (mm/s)", "A_B (mm/s^2)", "note"]
    assert len(table) == 1 + 360
    assert table[1][:3] == ["90", "0", "0"]
    assert table[2][0] == "89"
    assert float(table[2][1]) == pytest.approx(math.radians(1.0))    # t at ω2 = 1 rad/s
    s = [float(r[4]) for r in table[1:]]
    assert max(s) - min(s) == pytest.approx(STROKE, rel=1e-4)
    assert all(r[-1] == "" for r in table[1:])
    assert "nan" not in shaper_files["sweep.csv"].lower()


def test_the_points_table_lists_each_graphical_value(shaper_files):
    table = rows(shaper_files["sweep-points.csv"])
    assert table[0] == ["position", "theta2 (deg)", "quantity", "method", "unit", "graphical",
                        "curve", "rel_error"]
    body = table[1:]
    assert {r[2] for r in body} == {"s_B", "V_B", "A_B"}
    assert all(float(r[7]) < 1e-9 for r in body)


def test_the_plots_parse_and_carry_the_marks(shaper_files):
    for stem in ("sweep-position", "sweep-velocity", "sweep-acceleration"):
        root = ET.fromstring(shaper_files[f"{stem}.svg"])
        words = ["".join(t.itertext()) for t in root.iter(f"{SVG}text")]
        assert "t = 2.34 s" in words, stem
        assert "θ2 = 90°" in words, stem               # θ with a true subscript 2
        marks = [c for c in root.iter(f"{SVG}circle")]
        assert len(marks) >= 2 + 1                     # two marks and the legend's circle
        assert "nan" not in shaper_files[f"{stem}.svg"].lower()
    velocity = shaper_files["sweep-velocity.svg"]
    assert "Crank-shaper quick-return mechanism" in velocity
    assert ">360<" in velocity and ">330<" in velocity           # the 0–360° axis


def test_a_marks_label_keeps_inside_the_ticks_and_its_leader_off_the_curve(shaper):
    """The t = 2.34 s mark of the acceleration plot sits at the curve's trough, near the
    frame's foot: its label goes in the trough, not onto the frame or a tick, and no
    label or leader crosses the curve."""
    from shapely.geometry import LineString, box

    from tarsim.exercises.linkages.sweep_files import sweep_figures
    from tarsim.graphics.figure import Path, Text
    from tarsim.graphics.plot import _MARK_TEXT, _TICK

    for stem, fig in sweep_figures(shaper).items():
        paths = [it for it in fig.items if isinstance(it, Path)]
        (frame,) = [p for p in paths if p.style == "plot_frame"]
        x0, y0 = map(min, zip(*frame.points))
        x1, y1 = map(max, zip(*frame.points))
        curves = [LineString(p.points) for p in paths if p.style == "plot_curve"]
        labels = [t for t in fig.items if isinstance(t, Text) and t.size == _MARK_TEXT]
        assert {t.text for t in labels} == {"t = 2.34 s", "θ"}, stem     # θ₂ = 90°
        for t in labels:
            a, b, c, d = t.box()
            assert a > x0 + _TICK and c < x1 - _TICK and b > y0 + _TICK and d < y1 - _TICK, \
                (stem, t.text)
            assert not any(box(a, b, c, d).intersects(k) for k in curves), (stem, t.text)
        for leader in [p for p in paths if p.style == "plot_leader"]:
            assert not any(LineString(leader.points).intersects(k) for k in curves), stem


def test_the_same_sweep_gives_the_same_files():
    ex = exercise("crank-shaper")
    a, b = (sweep_to_files(sweep_exercise(ex, 24)) for _ in range(2))
    assert a == b


# ----- the steps: curves as columns, each step as the scalar solver gives it --------------------
@pytest.mark.parametrize("name, of", [("four-bar", "V_B"), ("crank-shaper", None),
                                      ("four-bar", "theta4")])
def test_each_step_is_the_scalar_solvers(name, of):
    ex = exercise(name)
    sw = sweep_exercise(ex, 36, of=of)
    mech = ex.mechanism
    for i, step in enumerate(sw.samples):
        assert step.values == sw.values_at(i) and list(step.values) == list(sw.curves)
        want = evaluate(mech, sw.output, drive_at(mech, step.angle))
        if of == "theta4":          # the curve's θ is made continuous over the turn
            want["theta"] += math.tau * round((step.values["theta"] - want["theta"]) / math.tau)
        # the batch against the scalar solver: 1e-12 of each quantity's scale (see
        # tests/test_batch_solver.py), here the curve's largest, which also bounds what is
        # shown as 0 (rounding within 1e-12 of it)
        for key, value in step.values.items():
            size = max(abs(v) for v in sw.curves[key].tolist())
            assert abs(value - want[key]) <= 1e-12 * size, (i, key)


def test_a_points_velocity_and_acceleration_built_together_are_as_built_alone():
    # the sweep draws V_B and A_B in one solve; each is answered by the methods, and with
    # the numbers, of its own solve
    from dataclasses import replace

    from tarsim.exercises.linkages.solution import solve_positions
    ex = exercise("four-bar")
    sw = sweep_exercise(ex, 36, of="V_B")
    for name, key in (("V_B", "v"), ("A_B", "a")):
        q = solve_positions(replace(ex.asking((name,)), positions=()))[0].quantities[name]
        alone = [(q.method, math.hypot(*q.value["vector"]))] + [
            (m, math.hypot(*a.value["vector"])) for m, a in q.alternatives.items()]
        assert [(c.method, c.graphical) for c in sw.checks if c.key == key] == alone


# ----- a four-bar: ω4 against the table's own θ4 -----------------------------------------------
def test_omega4_is_the_rate_of_the_tabled_theta4():
    sw = sweep_exercise(exercise("four-bar"), 360, of="omega4")
    assert sw.output.kind == "link" and not sw.rotates
    theta = [s.values["theta"] for s in sw.samples]
    omega = [s.values["omega"] for s in sw.samples]
    dt = sw.step / 10.0                    # ω2 = 10 rad/s: one step of θ2 takes Δθ2/ω2
    n = len(theta)
    worst = max(abs((theta[i + 1] - theta[i - 1]) / (2 * dt) - omega[i]) for i in range(1, n - 1))
    # The central difference errs by (Δt²/6)·|d³θ4/dt³| ≈ (h²/6)·|ω4|·(a few): h = 1°
    # makes that a few 1e-4 of the peak ω4.
    assert worst < 1e-3 * max(map(abs, omega))
    assert 60.0 == pytest.approx(math.degrees(max(theta) - min(theta)), abs=0.1)
    for c in sw.checks:
        assert c.rel_error < 1e-9, c


def test_a_link_that_turns_fully_is_shown_in_one_turn():
    text = four_bar_toml(ground=100, crank=300, coupler=250, rocker=280, angle=0)
    ex = _exercise_text(text.replace("angle = 0", "angle = 0\nomega = 5"))
    sw = sweep_exercise(ex, 36, of="theta4")
    assert sw.rotates
    assert all(0.0 <= s.values["theta"] < math.tau for s in sw.solved)


def _exercise_text(text):
    from tarsim.exercises.linkages.exercise_file import parse_exercise
    return parse_exercise(text, "m.toml", "m")


def test_unassembled_positions_are_gaps_with_their_reason():
    text = four_bar_toml(coupler=150, angle=0).replace("angle = 0", "angle = 0\nomega = 5")
    sw = sweep_exercise(_exercise_text(text), 72, of="omega4")
    skipped = [s for s in sw.samples if not s.values]
    assert 0 < len(skipped) < 72
    assert all(s.reason.startswith("cannot assemble: ") for s in skipped)
    files = sweep_to_files(sw)
    table = rows(files["sweep.csv"])
    gaps = [r for r in table[1:] if r[-1]]
    assert len(gaps) == len(skipped) and all(set(r[2:-1]) == {""} for r in gaps)
    assert "nan" not in "".join(v for v in files.values()).lower()


def test_no_assembled_position_is_an_error():
    text = four_bar_toml(coupler=10, rocker=50, angle=0).replace("angle = 0",
                                                                "angle = 0\nomega = 5")
    with pytest.raises(AssemblyError, match="no position of the revolution"):
        sweep_exercise(_exercise_text(text), 8)


def test_progress_is_reported_once_a_step():
    calls = []
    sweep_exercise(exercise("four-bar"), 12, progress=calls.append)
    assert calls == [1] * 12


@pytest.mark.parametrize("name, kind, point", [
    ("crank-shaper", "slider", "B"),          # V_B is asked
    ("four-bar", "point", "B"),               # V_B, taken on the coupler (its first carrier)
    ("slotted-lever-p37", "slider", "C"),     # no V_ or A_ asked: the ram on its guide
])
def test_the_default_output(name, kind, point):
    out = pick_output(exercise(name))
    assert (out.kind, out.point) == (kind, point)
    if kind == "slider":
        assert out.guide.guide_link == 1
    assert out.link in exercise(name).mechanism.links_at(point)


def test_an_unknown_output_names_the_closest():
    with pytest.raises(InputError, match="did you mean 'V_B'"):
        pick_output(exercise("four-bar"), "V_Q")
    with pytest.raises(InputError, match="did you mean 'omega4'"):
        pick_output(exercise("four-bar"), "omega9")


# ----- graphics.plot ---------------------------------------------------------------------------
def test_nice_ticks_hold_the_range():
    ticks = nice_ticks(-495.0, 232.9)
    assert ticks[0] <= -495.0 and ticks[-1] >= 232.9 and 0.0 in ticks
    assert len({round(b - a, 9) for a, b in zip(ticks, ticks[1:])}) == 1


def test_a_plot_clips_a_periodic_curve_to_its_axis():
    pts = tuple((x, float(x)) for x in range(-10, 371, 10))
    fig = draw_line_plot("t", "θ_2 (°)", "y (mm)", [Series("y", pts)], [PlotMark(90, 90, "m")],
                         x_range=(0.0, 360.0), x_ticks=[(0.0, "0"), (360.0, "360")])
    curve = next(it for it in fig.items if getattr(it, "style", "") == "plot_curve")
    xs = [p[0] for p in curve.points]
    assert xs == sorted(xs)
    frame = next(it for it in fig.items if getattr(it, "style", "") == "plot_frame")
    assert min(xs) == pytest.approx(frame.points[0][0])
    assert max(xs) == pytest.approx(frame.points[1][0])


def test_no_leader_runs_through_another_marks_circle(solved):
    # The single cylinder's 769.3 N and 888.3 N at 30° are marks a few millimetres apart
    # on two crossing curves: a leader through one circle to the other's label would point
    # at the wrong value.
    from tarsim.graphics.plot import _MARK_R

    fig = solved("single-cylinder").figures["forces"]
    circles = [c.centre for c in fig.items if getattr(c, "style", "") == "plot_mark"]
    leaders = [p.points for p in fig.items if getattr(p, "style", "") == "plot_leader"]
    assert leaders
    for a, b in leaders:
        own = min(circles, key=lambda c: abs(math.dist(c, a) - _MARK_R))   # starts on its own
        for c in circles:
            if c != own:
                t = max(0.0, min(1.0, ((c[0] - a[0]) * (b[0] - a[0]) + (c[1] - a[1])
                                       * (b[1] - a[1])) / math.dist(a, b) ** 2))
                near = math.dist(c, (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])))
                assert near > _MARK_R, (a, b, c)


# ----- the command line ------------------------------------------------------------------------
def test_sweep_writes_its_files_and_reports(tmp_path):
    out = tmp_path / "shaper-sweep"
    result = run("sweep", "crank-shaper", "-o", out, "--steps", 72, "--no-pdf")
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in out.iterdir()) == [
        ".tarsim-manifest.json", "sweep-acceleration.svg", "sweep-points.csv", "sweep-position.svg",
        "sweep-velocity.svg", "sweep.csv"]
    assert len(rows((out / "sweep.csv").read_text(encoding="utf-8"))) == 1 + 72
    text = result.stdout
    assert "stroke 679.134 mm" in text
    assert "V_B = 0 at θ2 = 201.1002°, 338.8998°" in text
    assert "t = 2.34 s" in text and "radius-rotation" in text
    assert result.stderr == ""


def test_sweep_of_an_unknown_output_is_one_line_and_writes_nothing(tmp_path):
    out = tmp_path / "never"
    result = run("sweep", "four-bar", "--of", "V_Q", "-o", out)
    assert result.exit_code == 1
    assert result.stdout == ""
    assert result.stderr.count("\n") == 1 and "did you mean 'V_B'?" in result.stderr
    assert result.stderr.startswith("Error: ")
    assert not out.exists()


def test_sweep_that_never_assembles_is_one_line(tmp_path):
    path = tmp_path / "m.toml"
    path.write_text(four_bar_toml(coupler=10, rocker=50, angle=0), encoding="utf-8")
    out = tmp_path / "never"
    result = run("sweep", path, "-o", out, "--steps", 8)
    assert result.exit_code == 1
    # Led by the [[link]] table of the link that cannot reach (link 3, line 10).
    assert result.stderr.startswith(f"Error: {path}:10: no position of the revolution")
    assert result.stderr.count("\n") == 1 and "Traceback" not in result.stderr
    assert not out.exists()


def test_list_says_what_each_example_asks():
    result = run("list")
    assert result.exit_code == 0
    lines = result.stdout.splitlines()
    i = next(i for i, line in enumerate(lines) if line.startswith("crank-shaper "))
    block = []
    for line in lines[i + 1:]:
        if not line.startswith(" "):
            break
        block.append(line.strip())
    assert block[0].startswith("from course project, kinematic and dynamic analysis of a "
                               "crank-shaper, §2")
    asks = next(line for line in block if line.startswith("asks: "))
    assert "ω4, α4, V_B, A_B, Aᶜ_A, Aᶜ_B at θ2 = 90°, t = 2.34 s" in asks


def test_an_input_given_by_another_member_is_swept_at_its_converted_rates():
    """The piston's 300 mm/s at θ2 = 60° is ω2 = −7.376 rad/s: the curves turn the crank at
    that, so the constructed V_B and A_B sit on them."""
    sw = sweep_exercise(load_exercise(resolve("piston-driven-slider-crank")), 72)
    w = sw.exercise.mechanism.drive.omega
    assert w == pytest.approx(-7.37622, rel=1e-5)
    v = next(c for c in sw.checks if c.method == "velocity polygon")
    assert abs(v.graphical) == pytest.approx(0.295049, rel=1e-5)      # 295.049 mm/s
    assert all(c.rel_error <= 1e-12 for c in sw.checks), sw.checks


def test_a_sweep_whose_construction_leaves_its_curve_exits_3(monkeypatch, tmp_path):
    from dataclasses import replace

    from tarsim.exercises.linkages import sweep_run

    real = sweep_run.sweep_exercise

    def off(*args, **kw):
        sw = real(*args, **kw)
        return replace(sw, checks=tuple(replace(c, rel_error=0.5) for c in sw.checks))
    monkeypatch.setattr(sweep_run, "sweep_exercise", off)
    result = CliRunner().invoke(cli, ["sweep", "four-bar", "-o", str(tmp_path / "out"),
                                      "--no-pdf", "--steps", "24"])
    assert result.exit_code == 3
    assert result.output.splitlines()[-1].endswith("disagree with the analytic solution beyond "
                                                   "tolerance")


def test_a_tag_on_its_own_curve_is_moved_clear_of_it():
    """A value set at the middle of the segment it belongs to (an energy's rise between
    two intercepts) would be crossed by that segment: it is set a line up or down, or to a
    side, where no curve crosses its words."""
    pts = ((0.0, 0.0), (1.0, 10.0), (2.0, -20.0))
    fig = draw_line_plot("E", "x", "E (J)", [Series("energy", pts)], [], x_range=(0.0, 2.0),
                         x_ticks=[(0.0, "0"), (1.0, "1"), (2.0, "2")],
                         tags=[(0.5, 5.0, "+10 J"), (1.5, -5.0, "−30 J")])
    tags = [it for it in fig.items if isinstance(it, figure.Text) and it.text.endswith(" J")]
    curve = next(it for it in fig.items if isinstance(it, figure.Path) and len(it.points) == 3)
    assert len(tags) == 2
    (x0, y0), (x1, y1), (x2, y2) = curve.points
    for tag, ((ax, ay), (bx, by)) in zip(tags, (((x0, y0), (x1, y1)), ((x1, y1), (x2, y2)))):
        # The segment's height at the tag's x, against the tag's box (3 mm words, about
        # 2 mm wide a character): the segment passes above or below the box, or beside it.
        half_w, half_h = 1.0 * len(tag.text), 1.5
        left, right = tag.at[0] - half_w, tag.at[0] + half_w
        lo, hi = max(min(ax, bx), left), min(max(ax, bx), right)
        if lo > hi:
            continue                                  # beside the segment
        ys = [ay + (by - ay) * (x - ax) / (bx - ax) for x in (lo, hi)]
        assert min(ys) > tag.at[1] + half_h or max(ys) < tag.at[1] - half_h


def test_the_printed_checks_keep_their_columns_apart(tmp_path):
    """An acceleration of millions of mm/s² is as long as its column: each row of the
    table still splits into its six entries, at the header's columns."""
    result = CliRunner().invoke(cli, ["sweep", "engine-forces", "-o", str(tmp_path / "out"),
                                      "--no-pdf", "--steps", "24"])
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    head = next(i for i, line in enumerate(lines) if line.startswith("position "))
    starts = [lines[head].index(word) for word in ("quantity", "method", "graphical",
                                                    "curve", "rel. error")]
    rows = lines[head + 1:head + 4]
    assert any("e+06" in row for row in rows)          # the long one is among them
    for row in rows:
        for at in starts:                              # every column starts after a gap
            assert row[at - 2:at] == "  " and row[at] != " ", row
