"""A cam file as the books state the problem: every setting known or refused at its line, the
books' names for followers and laws, an outstroke split by "the acceleration is r times the
retardation", the prime circle and each segment's greatest pressure angle said.

Every number asserted is a closed form of the book's data, or a value worked by hand from
the book's statement (the reproducers' sources); never what tarsim printed.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.constructions.reference.cam_laws import LAWS, motion
from tarsim.exercises.cams.cam_file import parse_cam
from tarsim.exercises.cams.cam_settings import (CAM_KEYS, FOLLOWER_KEYS, SEGMENT_KEYS,
                                                UNIT_KEYS, book_follower, book_law)
from tarsim.exercises.catalog import bundled, load
from tarsim.exercises.cli import cli

ROOT = Path(__file__).resolve().parents[1]
HERE = Path(__file__).parent / "reproducers"
CAM = Path(bundled("cams")["roller-harmonic-cycloidal"]).read_text(encoding="utf-8")
ARC = Path(bundled("cams")["tangent-cam-roller"]).read_text(encoding="utf-8")

TIGHT = 1e-12
"""A closed form of the book's data against the law's numbers: each a handful of products
and quotients of h, β, ω and π, rounded a few times at 1e-16."""


def solved(path: Path, tmp_path: Path) -> tuple[str, dict]:
    """The command line's output and results.json's quantities for the file at ``path``."""
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / path.stem),
                                   "--no-pdf"])
    assert run.exit_code == 0, run.output
    doc = json.loads((tmp_path / path.stem / "results.json").read_text(encoding="utf-8"))
    return run.output, doc["quantities"]


def refusal(text: str) -> str:
    """parse_cam's one-line refusal of ``text``."""
    with pytest.raises(InputError) as e:
        parse_cam(text, "cam.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("cam.toml:"), message
    return message


def line_of(text: str, needle: str) -> int:
    """The line (from 1) of ``text`` that first begins with ``needle``."""
    found = re.search(rf"^{re.escape(needle)}", text, re.M)
    return text[:found.start()].count("\n") + 1


# ----- the book's outstroke: "the acceleration being twice the retardation" --------------------
H, BETA, W = 0.036, math.radians(150), 360 * 2 * math.pi / 60     # m, rad, rad/s
K = 1 / (1 + 2)            # the accelerating fraction when a_acc = 2 a_ret
RETURN = math.radians(120)


def _c5_closed_forms(q: dict) -> None:
    """C5 (Khurmi-style): 36 mm in 150° at 360 rpm, the acceleration twice the retardation,
    a simple-harmonic return over 120°. With the velocity 2h/β where the parts meet, the
    acceleration lasts kβ = 50° and the retardation 100°."""
    acc, ret = 2 * H / (K * BETA ** 2) * W * W, 2 * H / ((1 - K) * BETA ** 2) * W * W
    assert q["acceleration_1"]["value"] == pytest.approx(acc, rel=TIGHT)
    assert q["retardation_1"]["value"] == pytest.approx(ret, rel=TIGHT)
    assert acc == pytest.approx(44.7898, rel=1e-5)      # the hand values, to their 6 figures
    assert ret == pytest.approx(22.3949, rel=1e-5)
    assert q["a_max_1"]["value"] == pytest.approx(acc, rel=TIGHT)
    assert q["v_max_1"]["value"] == pytest.approx(2 * H / BETA * W, rel=TIGHT)
    assert q["v_max_3"]["value"] == pytest.approx(math.pi * H / (2 * RETURN) * W, rel=TIGHT)
    assert q["a_max_3"]["value"] == pytest.approx(math.pi ** 2 * H / (2 * RETURN ** 2) * W * W,
                                                  rel=TIGHT)
    # 60° in: past the 50° of acceleration, u = 0.4 of the rise.
    u = 60 / 150
    assert q["y_at_60"]["value"] == pytest.approx(H - H * (1 - u) ** 2 / (1 - K), rel=TIGHT)
    assert q["y_at_60"]["value"] == pytest.approx(0.01656, rel=1e-9)    # 16.56 mm by hand
    assert q["v_at_60"]["value"] == pytest.approx(2 * H * (1 - u) / ((1 - K) * BETA) * W,
                                                  rel=TIGHT)
    assert q["a_at_60"]["value"] == pytest.approx(-ret, rel=TIGHT)


def test_c5_unequal_ratio(tmp_path):
    """The book's problem with the split worked by hand, accelerating = 50."""
    _, q = solved(HERE / "c5-unequal-ratio.toml", tmp_path)
    _c5_closed_forms(q)
    # the book's own statement, the acceleration twice the retardation
    assert q["acceleration_1"]["value"] == pytest.approx(2 * q["retardation_1"]["value"],
                                                         rel=TIGHT)


def test_c5_naive_ratio_key(tmp_path):
    """acceleration_ratio = 2, as the book states it: once read as nothing and an equal split
    solved without a word (a_max 29.86 m/s², the motion at 60° all wrong); now the book's
    numbers, the same as the split worked by hand."""
    out, q = solved(HERE / "c5-naive-ratio-key.toml", tmp_path)
    _c5_closed_forms(q)
    assert "uniform acceleration 44.79 m/s² over 50°, retardation 22.39 m/s² over 100°" in out


@settings(max_examples=60, deadline=None)
@given(ratio=st.sampled_from([1 / 5, 1 / 3, 1 / 2, 2 / 3, 1.0, 3 / 2, 2.0, 3.0, 5.0, 7.0]),
       angle=st.sampled_from([60, 90, 120, 150, 180]), lift=st.floats(1, 80))
def test_a_ratio_splits_the_segment_so_the_law_accelerates_r_times_as_hard(ratio, angle, lift):
    """Whatever the ratio, the law the reader sets up accelerates ``ratio`` times as hard as
    it retards (the reference's y″ on each piece), and the split lies on a division."""
    text = CAM.replace('lift = 40\nlaw = "simple harmonic"',
                       f'lift = 40\nlaw = "parabolic"\nacceleration_ratio = {ratio!r}', 1)
    s = parse_cam(text, "cam.toml").segments[0]
    assert s.split == pytest.approx(1 / (1 + ratio), rel=1e-15)
    assert abs(s.split * s.divisions - round(s.split * s.divisions)) < 1e-9
    y2 = [motion(s.law, lift, math.radians(angle), 0.5, split=s.split, piece=p).y2
          for p in (0, 1)]
    assert y2[0] / -y2[1] == pytest.approx(ratio, rel=1e-12)


@pytest.mark.parametrize("extra, law, words", [
    ("acceleration_ratio = 2", "simple harmonic",
     "only a parabolic segment (uniform acceleration and retardation) is split by "
     "acceleration_ratio"),
    ("acceleration_ratio = 0", "parabolic", "a positive number (2 where it is twice"),
    ("acceleration_ratio = -2", "parabolic", "a positive number"),
    ("accelerating = 40\nacceleration_ratio = 2", "parabolic",
     "give the degrees of acceleration or the acceleration_ratio, not both"),
    ("acceleration_ratio = 1.7", "parabolic", "on no division of 2 to 24 equal parts"),
])
def test_a_ratio_the_segment_cannot_take_is_refused_at_its_line(extra, law, words):
    text = CAM.replace('lift = 40\nlaw = "simple harmonic"',
                       f'lift = 40\nlaw = "{law}"\n{extra}', 1)
    message = refusal(text)
    assert words in message, message
    assert message.startswith(f"cam.toml:{line_of(text, extra.splitlines()[-1])}:"), message


def test_the_bundled_ratio_cam_is_its_closed_forms():
    """knife-edge-acceleration-ratio: 40 mm in 120° at 240 rpm, the acceleration three times
    the retardation: k = ¼, 30° then 90°; 2h/kβ²·ω² = 46.08 m/s² exactly (β = 2π/3,
    ω = 8π), a third of it retarding, 2h/β·ω = 960 mm/s."""
    from tarsim.exercises.cams.cam_solution import solve_cam
    s = solve_cam(load("knife-edge-acceleration-ratio"))
    assert s.passed
    q = {k: c.value["value"] for k, c in s.checked.items()}
    assert q["acceleration_1"] == pytest.approx(46.08, rel=TIGHT)
    assert q["retardation_1"] == pytest.approx(15.36, rel=TIGHT)
    assert q["v_max_1"] == pytest.approx(0.960, rel=TIGHT)
    assert q["y_at_20"] == pytest.approx(0.040 * (1 / 6) ** 2 / 0.25, rel=TIGHT)
    assert q["v_at_90"] == pytest.approx(0.320, rel=TIGHT)


# ----- every table refuses what it does not know ---------------------------------------------
@pytest.mark.parametrize("text, after, typo, hint", [
    (CAM, 'speed = "rpm"', "lenght", "did you mean 'length'?"),
    (CAM, "sense = \"cw\"", "base", "did you mean 'base_radius'?"),
    (CAM, "radius = 10 ", "radious", "did you mean 'radius'?"),
    (CAM, 'law = "simple harmonic"', "acceleraton_ratio", "did you mean 'acceleration_ratio'?"),
    (CAM, 'law = "simple harmonic"', "colour", "expected kind, angle, time, lift, law"),
    (CAM, "jerk = true", "jerks", "did you mean 'jerk'?"),
    (CAM, "jerk = true", "torque", "a cam's [ask] table takes jerk = true"),
    (ARC, "lift = 15", "nose_radios", "did you mean 'nose_radius'?"),
    (ARC, "diameter = 20", "diametre", "did you mean 'diameter'?"),
])
def test_a_setting_no_table_knows_is_refused_at_its_line(text, after, typo, hint):
    """The hazard: a [[segment]] or [cam] key it did not know was read as nothing, and the
    cam of another problem solved without a word."""
    assert after in text
    broken = text.replace(after, f"{after}\n{typo} = 2", 1)
    message = refusal(broken)
    assert message.startswith(f"cam.toml:{line_of(broken, f'{typo} = 2')}:"), message
    assert hint in message, message


_TABLES = {"[cam]": ("sense = \"cw\"", CAM_KEYS), "[follower]": ("radius = 10 ", FOLLOWER_KEYS),
           "[[segment]]": ('law = "cycloidal"', SEGMENT_KEYS),
           "[units]": ('speed = "rpm"', UNIT_KEYS)}


@settings(max_examples=80, deadline=None)
@given(table=st.sampled_from(sorted(_TABLES)), key=st.from_regex(r"[a-z][a-z_]{0,14}",
                                                                 fullmatch=True))
def test_any_unknown_setting_in_any_table_is_refused_naming_it(table, key):
    after, known = _TABLES[table]
    if key in known:
        return
    broken = CAM.replace(after, f"{after}\n{key} = 1", 1)
    message = refusal(broken)
    assert f"unknown setting '{key}'" in message, message
    assert message.startswith(f"cam.toml:{line_of(broken, f'{key} = 1')}:"), message


@pytest.mark.parametrize("old, new, words", [
    ('kind = "dwell"\nangle = 30', 'kind = "dwell"\nangle = 30\nlift = 5',
     "a dwell holds the follower still: lift is a rise's or a return's"),
    ('kind = "roller"\nradius = 10 ', 'kind = "knife-edge"\nradius = 10 ',
     "radius is a roller's, not a translating knife-edge follower's"),
    ("radius = 10 ", "radius = 10\narm = 50 ", "arm is an oscillating follower's"),
    ("radius = 10 ", "radius = 10\nmotion = \"oscillating\"\npivot = [70, 0]\narm = 50\n"
     "offset = 5 ", "offset is a translating follower's"),
])
def test_a_setting_this_cam_has_no_use_for_is_refused_not_dropped(old, new, words):
    assert old in CAM
    message = refusal(CAM.replace(old, new, 1))
    assert words in message, message


CIRCULAR = Path(bundled("cams")["circular-arc-flat-face"]).read_text(encoding="utf-8")


@pytest.mark.parametrize("text, old, new, words", [
    (ARC, "lift = 15", "lift = 15\nflank_radius = 80",
     "a tangent cam's flanks are straight: flank_radius is a circular arc cam's"),
    (CIRCULAR, 'kind = "flat-faced"', 'kind = "flat face"\nradius = 5',
     "radius is a roller's, not a flat-faced follower's"),
])
def test_a_cam_of_arcs_refuses_a_setting_it_has_no_use_for(text, old, new, words):
    assert old in text
    message = refusal(text.replace(old, new, 1))
    assert words in message, message


# ----- the books' names ----------------------------------------------------------------------
@pytest.mark.parametrize("name, kind", [
    ("flat-face", "flat-faced"), ("flat faced", "flat-faced"), ("Flat", "flat-faced"),
    ("mushroom", "flat-faced"), ("knife edge", "knife-edge"), ("knife-edged", "knife-edge"),
    ("Knife edge follower", "knife-edge"), ("roller follower", "roller")])
def test_a_follower_is_read_by_any_name_the_books_give_it(name, kind):
    text = CAM.replace('kind = "roller"\nradius = 10 ', f'kind = "{name}"\n'
                       + ("radius = 10 " if kind == "roller" else ""), 1)
    assert parse_cam(text, "cam.toml").follower.kind == kind


@pytest.mark.parametrize("name, law", [
    ("uniform acceleration and retardation", "parabolic"), ("uniform acceleration", "parabolic"),
    ("Uniform Acceleration and Retardation Motion", "parabolic"), ("parabolic", "parabolic"),
    ("simple harmonic motion", "simple harmonic"), ("SHM", "simple harmonic"),
    ("cycloidal motion", "cycloidal"), ("uniform velocity", "uniform velocity"),
    ("constant velocity", "uniform velocity")])
def test_a_law_is_read_by_any_name_the_books_give_it(name, law):
    text = CAM.replace('law = "simple harmonic"', f'law = "{name}"', 1)
    assert parse_cam(text, "cam.toml").segments[0].law == law


def test_the_templates_comments_name_only_what_it_accepts():
    """`tarsim new cam` once suggested kind = "flat-face" and law = "uniform acceleration",
    both refused: every name its comments give is read now."""
    template = (ROOT / "exercises" / "templates" / "cam.toml").read_text(encoding="utf-8")
    kinds = re.search(r'^kind = "roller" +# (.*)$', template, re.M).group(1)
    names = [n for n in re.split(r",|\bor\b|[()]", kinds) if n.strip()]
    assert len(names) >= 5 and all(book_follower(n) for n in names), names
    law_lines = re.search(r'^law = "simple harmonic" +# or (.*\n(?: +#.*\n)*)', template, re.M)
    laws = [n.strip(" #\n") for n in re.split(r",|\n", law_lines.group(1)) if n.strip(" #\n")]
    laws = [re.sub(r"\s*\(and retardation\)", "", n) for n in laws]
    assert len(laws) >= 6 and all(book_law(n) for n in laws), laws
    assert {book_law(n) for n in laws} == set(LAWS)


# ----- the prime circle and each segment's pressure angle ------------------------------------
def test_c3_prime_circle_is_said_and_written(tmp_path):
    """C3 (Norton): the least base circle for 30° under a 12.5 mm roller; the prime circle,
    43.7736 mm by hand, is the base circle and the roller."""
    out, q = solved(HERE / "c3-base-circle-pressure-angle.toml", tmp_path)
    assert q["prime_radius"]["value"] == pytest.approx(q["base_radius"]["value"] + 0.0125,
                                                       rel=1e-15)
    assert q["prime_radius"]["value"] == pytest.approx(0.0437736, rel=1e-6)
    assert q["prime_radius"]["passed"] is True
    assert "the prime circle: radius 43.7736 mm (the base circle's 31.2736 mm and the " \
           "roller's 12.5 mm)" in out


def test_a_given_base_circles_prime_circle_is_base_and_roller():
    """The bundled roller cam: base 40 mm, roller 10 mm; a knife edge has no prime row."""
    from tarsim.exercises.cams.cam_solution import solve_cam
    q = solve_cam(load("roller-harmonic-cycloidal")).checked
    assert q["prime_radius"].value["value"] == pytest.approx(0.050, rel=1e-15)
    assert q["prime_radius"].reference["value"] == pytest.approx(0.050, rel=1e-12)
    assert "prime_radius" not in solve_cam(load("offset-knife-edge")).checked


def test_c2_offset_knife_uv(tmp_path):
    """C2: a knife edge 12 mm off a 40 mm base circle, the cam ccw; a uniform-velocity rise of
    30 mm in 90°, a parabolic return in 120°. tan φ = (y′ − σe)/(s₀ + y), s₀ = √(40² − 12²):
    on the rise y′ = h/β throughout, steepest at y = 0 (10.538° by hand); on the return
    |y′| + e over s₀ + y grows to the middle, where y′ = −2h/β and y = h/2."""
    out, q = solved(HERE / "c2-offset-knife-uv.toml", tmp_path)
    h, e, s0 = 30.0, 12.0, math.sqrt(40 ** 2 - 12 ** 2)
    rise = math.atan((h / (math.pi / 2) - e) / s0)
    back = math.atan((2 * h / (2 * math.pi / 3) + e) / (s0 + h / 2))
    # Both lie at a piece's end, where the survey evaluates the closed form itself: a few
    # roundings of a sine and a square root.
    for k, want in ((1, rise), (3, back)):
        row = q[f"pressure_angle_max_{k}"]
        assert row["value"] == pytest.approx(want, rel=1e-9)
        assert row["unit"] == "rad" and row["deg"] == pytest.approx(math.degrees(want),
                                                                    rel=1e-9)
    assert math.degrees(rise) == pytest.approx(10.538, abs=5e-4)      # the hand value
    assert f"segment 1 (rise): greatest pressure angle {math.degrees(rise):.2f}° at θ = " \
           "0.00°" in out
    assert f"segment 3 (return): greatest pressure angle {math.degrees(back):.2f}°" in out
    assert q["pressure_angle_max"]["deg"] == pytest.approx(math.degrees(back), rel=1e-9)
