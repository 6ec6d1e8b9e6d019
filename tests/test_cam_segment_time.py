"""A cam's segment given by its time, as the books give it ("rises 35 mm in 0.05 s" at
300 rpm): its angle is β = ωt, and every peak follows from that angle by the laws' closed
forms."""

from __future__ import annotations

import math

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.cams.cam_file import parse_cam
from tarsim.exercises.cams.solve import solve
from tarsim.exercises.cli import cli

TIMED = """name = "timed"
[units]
length = "mm"
speed = "rpm"
[cam]
base_radius = 30
speed = 300
sense = "cw"
[follower]
kind = "roller"
diameter = 20
offset = 10
[[segment]]
kind = "rise"
time = 0.05
lift = 35
law = "cycloidal"
[[segment]]
kind = "dwell"
time = 0.025
[[segment]]
kind = "return"
time = 0.075
lift = 35
law = "uniform acceleration and retardation"
[[segment]]
kind = "dwell"
angle = "rest"
"""


def test_a_segment_given_by_its_time_turns_the_cam_omega_t():
    """At 300 rpm (ω = 10π rad/s) 0.05, 0.025 and 0.075 s are 90°, 45° and 135°: the
    cycloidal rise of h = 35 mm over β = π/2 peaks at v = 2hω/β = 1.4 m/s and
    a = 2πhω²/β² = 87.9646 m/s², the parabolic return over 3π/4 at v = 2hω/β = 0.93333 m/s
    and a = 4hω²/β² = 24.8889 m/s²; time_k gives back each time. Closed forms to 1e-9: the
    peaks are the laws' formulas at an angle exact in binary (90 = 6 × 300 × 0.05)."""
    ex = parse_cam(TIMED, "cam.toml")
    assert [math.degrees(s.angle) for s in ex.segments] == pytest.approx([90, 45, 135, 90],
                                                                         rel=1e-15)
    assert [s.time for s in ex.segments] == [0.05, 0.025, 0.075, None]
    q = solve(ex).results["quantities"]
    w, h = 10 * math.pi, 0.035
    rise, back = math.pi / 2, 3 * math.pi / 4
    assert q["v_max_1"]["value"] == pytest.approx(2 * h * w / rise, rel=1e-9)
    assert q["a_max_1"]["value"] == pytest.approx(2 * math.pi * h * w * w / rise ** 2, rel=1e-9)
    assert q["v_max_3"]["value"] == pytest.approx(2 * h * w / back, rel=1e-9)
    assert q["a_max_3"]["value"] == pytest.approx(4 * h * w * w / back ** 2, rel=1e-9)
    for k, t in ((1, 0.05), (2, 0.025), (3, 0.075)):
        assert q[f"time_{k}"]["value"] == pytest.approx(t, rel=1e-12)


def test_the_steps_say_the_angle_a_time_turns(tmp_path):
    (tmp_path / "timed.toml").write_text(TIMED, encoding="utf-8")
    for lang, said in (("en", "segment 1 is given by its time, 0.05 s: at 300 rpm the cam turns "
                              "β = ωt = 90° in it"),
                       ("fa", "بخش ۱ با زمانش داده شده است، ۰٫۰۵ ثانیه: بادامک با سرعت ۳۰۰ دور "
                              "بر دقیقه در این مدت β = ωt = ۹۰° می‌چرخد")):
        out = tmp_path / lang
        result = CliRunner().invoke(cli, ["solve", str(tmp_path / "timed.toml"), "-o", str(out),
                                          "--no-pdf", "--lang", lang])
        assert result.exit_code == 0, result.output
        assert said in (out / "steps.md").read_text(encoding="utf-8")


@pytest.mark.parametrize("old, new, words", [
    ("time = 0.05\n", "time = 0.05\nangle = 90\n",
     "cam.toml:15: a segment gives its angle or its time, not both"),
    ("speed = 300\n", "", "cam.toml:14: segment 1 is given by its time, and [cam] gives no "
                          "speed"),
    ("time = 0.05\n", "tiem = 0.05\n",
     "cam.toml:15: unknown setting 'tiem' in [[segment]] 1; did you mean 'time'?"),
    ("time = 0.05\n", "duration = 0.05\n",
     "cam.toml:15: unknown setting 'duration' in [[segment]] 1; did you mean 'time'?"),
    ("time = 0.075\n", "tme = 0.075\n",          # a later segment's, before the rest's sum
     "cam.toml:23: unknown setting 'tme' in [[segment]] 3; did you mean 'time'?"),
    ("time = 0.05\n", "time = -0.05\n", "cam.toml:15: a segment's time must be more than 0 s"),
    ("time = 0.05\n", "time = 0.5\n",                # 6 × 300 × 0.5 = 900°, with 45° and 135°
     "cam.toml:28: the other segments take 1080°, leaving no rest of the turn"),
    ('angle = "rest"', "time = 0.5", "cam.toml:28: a segment's angle must be more than 0° and "
                                     "at most 360°, got 900° (0.5 s at the cam's speed)"),
])
def test_a_bad_time_is_refused_in_one_line(old, new, words):
    assert old in TIMED
    with pytest.raises(InputError) as e:
        parse_cam(TIMED.replace(old, new, 1), "cam.toml")
    message = str(e.value)
    assert "\n" not in message and len(message) < 200 and words in message, message


@settings(max_examples=40, deadline=None)
@given(st.integers(60, 3000), st.floats(0.05, 0.45), st.floats(0.05, 0.45))
def test_a_time_is_the_angle_six_n_t(rpm, rise, back):
    """Property: at N rpm a segment of t seconds is the segment of 6Nt degrees (360/60 per
    rpm-second): the same cam, so the same peaks, to rounding."""
    turn = 60 / rpm                                  # one revolution's seconds
    t1, t3 = rise * turn, back * turn
    timed = TIMED.replace("speed = 300", f"speed = {rpm}").replace(
        "time = 0.05\n", f"time = {t1!r}\n").replace("time = 0.075\n", f"time = {t3!r}\n"
                                                     ).replace("time = 0.025\n", "angle = 10\n")
    angled = timed.replace(f"time = {t1!r}\n", f"angle = {6 * rpm * t1!r}\n").replace(
        f"time = {t3!r}\n", f"angle = {6 * rpm * t3!r}\n")
    a, b = parse_cam(timed, "t.toml"), parse_cam(angled, "a.toml")
    assert [s.angle for s in a.segments] == pytest.approx([s.angle for s in b.segments],
                                                          rel=1e-14)
    assert math.degrees(a.segments[0].angle) == pytest.approx(360 * rise, rel=1e-12)
