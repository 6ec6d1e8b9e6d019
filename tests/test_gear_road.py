"""A car's differential as the books pose it: ``[road]`` gives the car's speed round a curve,
the curve's mean radius, the track and the road wheels' diameter, and the two road wheels'
speeds, ω = v·(R ± t/2)/(R·r), are the differential's two given speeds. Each answer is held
to the book's closed form."""

from __future__ import annotations

import math
from fractions import Fraction
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.constructions.narration import narrate
from tarsim.exercises.cli import cli
from tarsim.exercises.gears.train_file import parse_train
from tarsim.exercises.gears.train_solution import solve_train

F = Fraction
HERE = Path(__file__).parent / "reproducers"

DIFFERENTIAL = """name = "a car's differential"

[units]
speed = "{speed}"
length = "{length}"

[[gear]]
number = 1
teeth = {pinion}
[[gear]]
number = 2
teeth = {crown}
[[gear]]
number = 3
teeth = {side}
[[gear]]
number = 4
teeth = {side}
[[gear]]
number = 5
teeth = {planet}
carrier = 6

[arm]
number = 6

[[shaft]]
members = [2, 6]

[[mesh]]
gears = [1, 2]
kind = "bevel"
[[mesh]]
gears = [3, 5]
kind = "bevel"
[[mesh]]
gears = [5, 4]
kind = "bevel"

{road}
[ask]
find = ["omega1", "omega2", "omega3", "omega4"]
"""

ROAD = """[road]
road_speed = {v}
curve_radius = {R}
track = {t}
wheel_diameter = {d}
outer = 3
inner = 4
"""


def differential(road: str = ROAD.format(v=60, R=50, t=1.5, d=0.8), speed: str = "rpm",
                 length: str = "m", pinion: int = 12, crown: int = 60, side: int = 20,
                 planet: int = 10) -> str:
    return DIFFERENTIAL.format(road=road, speed=speed, length=length, pinion=pinion,
                               crown=crown, side=side, planet=planet)


def test_G5_differential_on_curve(tmp_path):
    """The held-out G5: 54 km/h round a 30 m curve, track 1.5 m, wheels 0.75 m, the pinion
    16 to the crown 64. v = 15 m/s, r = 0.375 m: the outer wheel 15·30.75/(30·0.375) =
    41 rad/s = 1230/π rpm (391.521), the inner 39 rad/s = 1170/π rpm (372.423), the crown
    their mean 40 rad/s = 1200/π rpm (381.972) and the propeller 64/16 of it, 4800/π rpm
    (1527.89), the hand values of the trial's report. The rpm given speeds carry π and are
    taken at ten significant figures, so each agrees within 1e-9 of its size."""
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["solve", str(HERE / "G5-differential-on-curve.toml"),
                                      "-o", str(out), "--no-pdf"])
    assert result.exit_code == 0, result.output
    q = solve_train(parse_train((HERE / "G5-differential-on-curve.toml").read_text(),
                                "G5.toml")).quantities
    for name, rpm in (("omega3", 1230), ("omega4", 1170), ("omega2", 1200), ("omega1", 4800)):
        assert float(q[name].exact) == pytest.approx(rpm / math.pi, rel=1e-9), name
        assert q[name].exact == q[name].reference
    steps = (out / "steps.md").read_text(encoding="utf-8")
    assert "R + t/2 = 30750 mm" in steps and "≈ 391.521 rpm" in steps
    assert "R − t/2 = 29250 mm" in steps and "≈ 372.423 rpm" in steps


@settings(max_examples=30, deadline=None)
@given(st.integers(5, 200), st.integers(3, 500), st.integers(10, 25), st.integers(4, 12),
       st.integers(8, 24), st.integers(30, 90), st.sampled_from(["cw", "ccw"]))
def test_a_bevel_differentials_crown_turns_at_the_mean_of_its_wheels(kmh, radius, track_dm,
                                                                      d_dm, pinion, crown,
                                                                      sense):
    """In rad/s the road's speeds are exact: the crown (the cage) turns at the mean of the
    two wheels, (ω_o + ω_i)/2 = v/r, the car's own rolling speed, and the propeller
    N2/N1 as fast the other way round the bevel pair's sense, whatever the road data.
    Exact fractions: a tolerance of 0."""
    t, d = F(track_dm, 10), F(d_dm, 10)
    road = ROAD.format(v=kmh, R=radius, t=float(t), d=float(d)) + f'sense = "{sense}"\n'
    q = solve_train(parse_train(differential(road, speed="rad/s", crown=crown,
                                             pinion=pinion), "d.toml")).quantities
    v, r, s = F(kmh) * F(5, 18), d / 2, 1 if sense == "ccw" else -1
    assert q["omega3"].exact == s * v * (radius + t / 2) / (radius * r)
    assert q["omega4"].exact == s * v * (radius - t / 2) / (radius * r)
    assert q["omega2"].exact == (q["omega3"].exact + q["omega4"].exact) / 2 == s * v / r
    assert abs(q["omega1"].exact) == abs(q["omega2"].exact) * crown / pinion
    assert all(x.exact == x.reference for x in q.values())


def test_the_books_car_at_60_kmh_on_a_50_m_curve():
    """60 km/h round 50 m, track 1.5 m, wheels 0.8 m: v = 50/3 m/s, r = 0.4 m, the outer
    wheel v·50.75/(50·0.4) = 42.2917 rad/s = 403.856 rpm, the inner v·49.25/(50·0.4) =
    41.0417 rad/s = 391.919 rpm, the crown v/r = 41.6667 rad/s = 397.887 rpm (ten
    significant figures taken: within 1e-9 of each)."""
    q = solve_train(parse_train(differential(), "car.toml")).quantities
    v = 60 / 3.6
    for name, path in (("omega3", 50.75), ("omega4", 49.25), ("omega2", 50)):
        assert float(q[name].exact) == pytest.approx(v * path / (50 * 0.4) * 30 / math.pi,
                                                     rel=1e-9)


def test_the_steps_say_how_each_given_speed_came_in_english_and_persian():
    train = parse_train(differential(), "car.toml").train
    en = [narrate(p, "en") for p in train.implied]
    fa = [narrate(p, "fa") for p in train.implied]
    assert len(en) == 3 and "v = 60 km/h = 16.6667 m/s" in en[0]
    assert "ω3 = v·(R + t/2)/(R·r) ≈ 403.856 rpm ccw" in en[1]
    assert "ω4 = v·(R − t/2)/(R·r) ≈ 391.919 rpm ccw" in en[2]
    assert "چرخ بیرونی" in fa[1] and "چرخ درونی" in fa[2] and "پادساعتگرد" in fa[1]


@pytest.mark.parametrize("road, words", [
    (ROAD.format(v=60, R=0.75, t=1.5, d=0.8), "curve radius of 0.75 m is not more than half "
                                              "the track"),
    (ROAD.format(v=60, R=0.5, t=1.5, d=0.8), "is not more than half the track"),
    (ROAD.format(v=60, R=50, t=1.5, d=0.8).replace("track = 1.5\n", ""),
     "[road] track is missing"),
    (ROAD.format(v=60, R=50, t=1.5, d=0.8).replace("inner = 4\n", ""),
     "[road] inner is missing"),
    (ROAD.format(v=60, R=50, t=1.5, d=0.8).replace("inner = 4", "inner = 3"),
     "outer and inner are both member 3"),
    (ROAD.format(v=0, R=50, t=1.5, d=0.8), "road_speed must be positive"),
    (ROAD.format(v=60, R=50, t=1.5, d=0.8) + "radius = 3\n", "unknown road setting 'radius'"),
    (ROAD.format(v=60, R=50, t=1.5, d=0.8) + "[input]\nmember = 1\nspeed = 1000\n",
     "leave out [input]"),
])
def test_road_data_that_cannot_hold_are_refused_in_one_line(road, words):
    with pytest.raises(InputError) as e:
        parse_train(differential(road), "car.toml")
    assert words in str(e.value) and str(e.value).startswith("car.toml:")
    assert "\n" not in str(e.value) and len(str(e.value)) < 220


def test_road_data_put_in_input_are_sent_to_road():
    """The trial's first try, road_speed in [[input]], is refused naming [road]."""
    text = differential("[[input]]\nmember = 3\nroad_speed = 54\n[[input]]\nmember = 4\n"
                        "speed = 300\n")
    with pytest.raises(InputError) as e:
        parse_train(text, "car.toml")
    assert "road_speed is the road's: give a car on a curve as [road]" in str(e.value)
    assert str(e.value).startswith("car.toml:") and "\n" not in str(e.value)
