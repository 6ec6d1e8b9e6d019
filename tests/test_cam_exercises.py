"""A cam exercise end to end: the file, its checks in one line, the solve, its files."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.constructions.errors import InputError
from tarsim.exercises.cams.cam_file import parse_cam
from tarsim.exercises.cams.cam_solution import solve_cam
from tarsim.exercises.catalog import bundled, load
from tarsim.exercises.cli import cli

CAM = Path(bundled("cams")["roller-harmonic-cycloidal"]).read_text(encoding="utf-8")


def test_the_peaks_are_the_textbook_formulas_times_the_cams_speed():
    """40 mm by simple harmonic motion over 120° at 300 rpm: v_max = πh/2β·ω = 942.48 mm/s,
    a_max = π²h/2β²·ω² = 44.41 m/s²; the cycloidal return over 150°: 2h/β·ω = 960 mm/s."""
    s = solve_cam(load("roller-harmonic-cycloidal"))
    assert s.passed and not s.misses
    w = 300 * 2 * math.pi / 60
    rise, back = s.peaks
    assert rise.velocity == pytest.approx(math.pi * 0.040 / (2 * math.radians(120)) * w,
                                          rel=1e-14)
    assert rise.velocity == pytest.approx(0.942478, rel=1e-6)
    assert rise.acceleration == pytest.approx(math.pi ** 2 * 0.040 / (2 * math.radians(120) ** 2)
                                              * w * w, rel=1e-14)
    assert back.velocity == pytest.approx(0.960, rel=1e-12)
    assert back.acceleration == pytest.approx(2 * math.pi * 0.040 / math.radians(150) ** 2
                                              * w * w, rel=1e-14)


def test_the_follower_rises_during_the_rise_whichever_way_the_cam_turns():
    s = solve_cam(load("roller-harmonic-cycloidal"))
    assert s.exercise.omega < 0                   # the cam turns clockwise
    xs, ys, vs, *_ = s.curves
    at = {round(x, 9): (y, v) for x, y, v in zip(xs, ys, vs)}
    assert at[60.0][1] == pytest.approx(0.942478, rel=1e-6)    # mid-rise: up, at its fastest
    assert at[225.0][1] == pytest.approx(-0.960, rel=1e-9)     # mid-return: down
    assert at[60.0][0] == pytest.approx(0.020, rel=1e-12)


@pytest.mark.parametrize("old, new, words", [
    ("angle = 60", "angle = 50", ["the segments add to 350°, not 360°"]),
    ("lift = 40\nlaw = \"simple harmonic\"", "lift = -40\nlaw = \"simple harmonic\"",
     ["a negative lift (-40 mm)"]),
    ("lift = 40\nlaw = \"cycloidal\"", "lift = 30\nlaw = \"cycloidal\"",
     ["leave the follower 10 mm off the base circle"]),
    ("law = \"cycloidal\"", "law = \"spline\"", ["unknown law 'spline'"]),
    ("kind = \"dwell\"\nangle = 30", "kind = \"pause\"\nangle = 30",
     ["a segment is a rise, a dwell or a return, not 'pause'"]),
    # the follower
    ("kind = \"roller\"", "kind = \"spherical\"", ["a follower is knife-edge, roller"]),
    ("radius = 10 ", "radius = 0 ", ["a roller follower gives its radius"]),
    ("radius = 10 ", "radius = 10\noffset = 60 ", ["puts the follower's line clear of the "
                                                   "prime circle (50 mm)"]),
    ("radius = 10 ", "radius = 10\nmotion = \"rocking\" ", ["translating or oscillating"]),
    ("radius = 10 ", "radius = 10\nmotion = \"oscillating\"\npivot = [200, 0]\narm = 50 ",
     ["cannot reach the prime circle"]),
    ("radius = 10 ", "radius = 10\nmotion = \"oscillating\"\narm = 50 ",
     ["gives its pivot from the cam centre"]),
    ("kind = \"roller\"\nradius = 10 ", "kind = \"flat-faced\"\nmotion = \"oscillating\" ",
     ["an oscillating flat face is not laid out yet"]),
    ("radius = 10 ", "radius = 10\ncolour = \"red\" ", ["unknown setting 'colour'"]),
    # [units] written as one value, not a table (once a traceback)
    ("[units]\nlength = \"mm\"\nspeed = \"rpm\"\n", "units = \"mm\"\n", ["[units] is a table"]),
])
def test_a_bad_cam_is_refused_in_one_line_at_its_place(old, new, words):
    assert old in CAM
    with pytest.raises(InputError) as e:
        parse_cam(CAM.replace(old, new, 1), "cam.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("cam.toml:")
    for w in words:
        assert w in message, message


def test_solve_writes_the_diagrams_steps_and_peaks(tmp_path):
    out = tmp_path / "cam"
    result = CliRunner().invoke(cli, ["solve", "roller-harmonic-cycloidal", "-o", str(out),
                                      "--no-pdf"])
    assert result.exit_code == 0, result.output
    assert "v_max = 942.478 mm/s" in result.output
    assert {p.name for p in out.iterdir()} >= {"displacement.svg", "velocity.svg",
                                              "acceleration.svg", "steps.md", "results.json"}
    doc = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert doc["quantities"]["v_max_1"]["value"] == pytest.approx(0.942478, rel=1e-6)
    steps = (out / "steps.md").read_text(encoding="utf-8")
    assert "on the lift of 40 mm draw a semicircle" in steps


def test_the_displacement_figure_inks_each_constructed_point_at_its_laws_height():
    """The figure's dots, read back off the paper, stand at the law's lift: the rise's
    harmonic y = h/2·(1 − cos πi/6) and the return's cycloid, each to paper rounding; the
    semicircle and the cycloid's circle are both inked."""
    from tarsim.constructions.reference.cam_laws import motion
    from tarsim.graphics.figure import Circle, Path as Stroke

    s = solve_cam(load("roller-harmonic-cycloidal"))
    fig = s.figures["displacement"]
    dots = [it.centre for it in fig.items if isinstance(it, Circle) and it.style == "dot"]
    assert len(dots) == sum(len(c) for c in s.diagram.curves) == 18
    base = dots[0][1]                                  # the figure is shifted onto its page
    mm_per_m = (base - min(y for _, y in dots)) / 0.040   # the top of the rise is h = 40 mm
    rise = [motion("simple harmonic", 0.040, math.radians(120), math.radians(20 * i)).y
            for i in range(7)]
    assert [(base - y) / mm_per_m for _, y in dots[:7]] == pytest.approx(rise, abs=1e-12)
    back = [0.040 - motion("cycloidal", 0.040, math.radians(150), math.radians(25 * i)).y
            for i in range(7)]
    assert [(base - y) / mm_per_m for _, y in dots[9:16]] == pytest.approx(back, abs=1e-12)
    across = [it.points for it in fig.items if isinstance(it, Stroke)
              and it.style == "construction" and len(it.points) > 8]
    assert len(across) == 2                               # the semicircle, the cycloid's circle


def test_the_modified_uniform_velocity_peaks_are_its_blends():
    """A 40 mm return over 120° blended by a quarter at each end, at 240 rpm: the run's
    speed h/(1 − b)β·ω = 640 mm/s, the blends' acceleration h/b(1 − b)β²·ω² = 30.72 m/s²."""
    s = solve_cam(load("offset-knife-edge"))
    back = s.peaks[1]
    assert (back.law, back.kind) == ("modified uniform velocity", "return")
    assert back.velocity == pytest.approx(0.640, rel=1e-14)
    assert back.acceleration == pytest.approx(30.72, rel=1e-14)
    assert back.passed


@pytest.mark.parametrize("new, words", [
    ("blend = 0.3", "covering a whole number of its 8 divisions, not 0.3"),
    ("blend = 0.75", "up to ½"),
    ("divisions = 7", "covering a whole number of its 7 divisions, not 0.25"),
    ("divisions = \"eight\"", "2 to 24 equal parts, not 'eight'"),
])
def test_a_bad_blend_is_refused_at_its_line(new, words):
    text = Path(bundled("cams")["offset-knife-edge"]).read_text(encoding="utf-8")
    key = new.split(" =")[0]
    old = next(line for line in text.splitlines() if line.startswith(key + " ="))
    with pytest.raises(InputError) as e:
        parse_cam(text.replace(old, new, 1), "cam.toml")
    assert str(e.value).startswith("cam.toml:") and words in str(e.value), str(e.value)


def test_the_jerk_is_given_when_asked_and_its_infinite_spikes_named():
    """[ask] jerk = true: the harmonic rise peaks at π³h/2β³·ω³ = 2092.92 m/s³, the
    cycloidal return at 4π²h/β³·ω³ = 2728.75 m/s³ (ω = 10π rad/s); ÿ jumps from the dwells
    into the harmonic rise and out of it (0°, 120°), not at the cycloid's ends."""
    s = solve_cam(load("roller-harmonic-cycloidal"))
    assert s.exercise.jerk and "jerk" in s.figures
    w = 10 * math.pi
    rise, back = s.peaks
    assert rise.jerk == pytest.approx(math.pi ** 3 * 0.04 / (2 * math.radians(120) ** 3)
                                      * w ** 3, rel=1e-14)
    assert rise.jerk == pytest.approx(2092.924, rel=1e-6)
    assert back.jerk == pytest.approx(2728.748, rel=1e-6)
    assert rise.passed and back.passed                    # the formulas match the sampled law
    assert s.jumps == [0.0, 120.0]
    assert s.results["quantities"]["j_max_3"]["value"] == pytest.approx(2728.748, rel=1e-6)
    # printed in the file's length unit, as v_max and a_max are (mm/s³ here, not m/s³)
    assert any("j_max = 2.09292e+06 mm/s³" in line for line in s.lines())
    knife = solve_cam(load("offset-knife-edge"))
    assert knife.jumps == [0.0, 60.0, 120.0, 150.0, 180.0, 240.0, 270.0]
    assert "jerk" not in knife.figures and "j_max_1" not in knife.results["quantities"]


def test_a_cam_asks_only_for_jerk():
    with pytest.raises(InputError, match=r"cam.toml:\d+: a cam's \[ask\] table takes jerk"):
        parse_cam(CAM.replace("jerk = true", "torque = true"), "cam.toml")


def test_a_base_circle_too_small_to_draw_is_refused_in_one_line():
    """Found by fuzzing: a base radius of 1e-300 mm left the turning arrow no radius."""
    with pytest.raises(InputError, match=r"cam.toml:\d+: the base radius must be between"):
        parse_cam(CAM.replace("base_radius = 40", "base_radius = 1e-300"), "cam.toml")
