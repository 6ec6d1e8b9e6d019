"""The velocity (Kutzbach) diagram: any member driving, planets at several carrier radii.

Each train's speeds are worked by hand with Willis' formula (ω_b − ω_arm)/(ω_a − ω_arm) =
∓N_a/N_b for a mesh a–b, − external, + internal), then read off the diagram as the slopes
of drawn lines. The property runs the generator's planetary trains (tests/random_trains.py):
whatever member drives and however many carrier radii the arm has, the diagram is drawn and
reads the table's speeds, which are Willis'.
"""

from __future__ import annotations

import json
import math
import random
from fractions import Fraction as F

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from tarsim.constructions.gears.kutzbach import carrier_radii, undrawable
from tarsim.exercises.gears.train_file import parse_train
from tarsim.exercises.gears.train_solution import solve_train
from tests.random_trains import build, oracle, train_toml

RPM = 2 * math.pi / 60


def train(gears, meshes, *, fixed, arm, drive, speed, shafts=()) -> str:
    """A planetary train's file: ``gears`` as (number, teeth, carrier or None), ``meshes``
    as (a, b, internal), the input ``drive`` at ``speed`` rpm (ccw +)."""
    out = [f"name = \"a train\"\nfixed = {fixed}\n"]
    for n, teeth, carrier in gears:
        out.append(f"[[gear]]\nnumber = {n}\nteeth = {teeth}\n"
                   + (f"carrier = {carrier}\n" if carrier else ""))
    out.append(f"[arm]\nnumber = {arm}\n")
    for members in shafts:
        out.append(f"[[shaft]]\nmembers = {list(members)}\n")
    for a, b, internal in meshes:
        out.append(f"[[mesh]]\ngears = [{a}, {b}]\n" + ('kind = "internal"\n' if internal
                                                         else ""))
    sense = "ccw" if speed > 0 else "cw"
    out.append(f"[input]\nmember = {drive}\nspeed = {abs(speed)}\nsense = \"{sense}\"\n")
    return "\n".join(out)


# Two planet sets on one arm 6 in one fixed ring 1 (140 teeth): the sun 2 (60) and the planet
# 3 (40) at R = (60 + 40)/2 = 50 modules; the planet 4 (30) and the sun 5 (80) at
# R′ = (80 + 30)/2 = 55 = (140 − 30)/2.
TWO_SETS = dict(gears=[(1, 140, None), (2, 60, None), (3, 40, 6), (4, 30, 6), (5, 80, None)],
                meshes=[(2, 3, False), (3, 1, True), (4, 1, True), (4, 5, False)],
                fixed=1, arm=6)

# A reverted compound planet 3–4 (60, 40) between the fixed sun 2 (40) and the sun 5 (60) at
# R = 50, and a second planet 7 (20) on the sun 5 inside the ring 8 (100) at R′ = 40.
REVERTED = dict(gears=[(2, 40, None), (3, 60, 6), (4, 40, 6), (5, 60, None), (7, 20, 6),
                       (8, 100, None)],
                meshes=[(2, 3, False), (4, 5, False), (5, 7, False), (7, 8, True)],
                fixed=2, arm=6, shafts=[(3, 4)])


def solved(layout, drive, speed):
    return solve_train(parse_train(train(**layout, drive=drive, speed=speed), "t.toml"))


def assert_diagram_reads(s, want):
    """The table, Willis and the diagram all give ``want`` (rpm)."""
    assert s.found.speeds == s.reference == want
    fastest = max(abs(float(w)) for w in want.values()) * RPM
    for m, w in want.items():
        # slopes of drawn lines: a few roundings of coordinates of the fastest's size
        assert abs(s.diagram.omegas[m] - float(w) * RPM) <= 1e-12 * fastest, m
    assert s.passed


def test_two_planet_sets_at_two_carrier_radii_read_their_own_centres():
    """Willis for the first set: (ω2 − ω6)/(0 − ω6) = −N1/N2 = −7/3, so ω2 = 10/3·ω6 and
    400 rpm at the sun gives ω6 = 120; the second set: (ω5 − ω6)/(0 − ω6) = −140/80, so
    ω5 = 11/4·ω6 = 330; the planets (ω − ω6)/(0 − ω6) = N1/N: ω3 = −5/2·ω6 = −300,
    ω4 = −11/3·ω6 = −440. Read at R for every planet, ω4 would be the line through P14
    and the arm's velocity at R: −(50/(70 − 50))·120 = −300, not −440."""
    s = solved(TWO_SETS, 2, 400)
    assert set(carrier_radii(s.train).values()) == {50, 55}
    assert_diagram_reads(s, {1: F(0), 2: F(400), 3: F(-300), 4: F(-440), 5: F(330), 6: F(120)})
    c = s.diagram.construction
    assert c["kz:centre"].label == "C" and c["kz:centre:1"].label == "C′"
    assert c.output("kz:centre:1").xy[1] == pytest.approx(55e-3, rel=1e-15)   # R′, in metres


@pytest.mark.parametrize("drive, speed", [(6, 90), (2, None), (5, 50), (3, 150), (7, 210),
                                          (8, 114)])
def test_a_reverted_planet_and_a_second_planet_any_member_driving(drive, speed):
    """The sun 2 fixed: (ω3 − ω6)/(0 − ω6) = −40/60, so ω3 = ω4 = 5/3·ω6;
    (ω5 − ω6)/(ω4 − ω6) = −40/60, so ω5 = ω6 − 4/9·ω6 = 5/9·ω6; (ω7 − ω6)/(ω5 − ω6) =
    −60/20, so ω7 = 7/3·ω6; (ω8 − ω6)/(ω7 − ω6) = 20/100, so ω8 = 19/15·ω6. With the arm at
    90 rpm: 150, 50, 210, 114. The sun 2 is fixed, so it cannot drive: refused."""
    if speed is None:
        with pytest.raises(Exception, match="the input, member 2, is the fixed member"):
            solved(REVERTED, drive, 1)
        return
    s = solved(REVERTED, drive, speed)
    assert_diagram_reads(s, {2: F(0), 3: F(150), 4: F(150), 5: F(50), 6: F(90), 7: F(210),
                             8: F(114)})


def test_a_planet_driving_away_from_the_fixed_member_is_scaled_from_a_trial():
    """The planet 7 meshes no fixed gear, so no line follows from its speed alone: the
    diagram is drawn for the arm at a trial speed, the planet's slope read, and the arm's
    true speed is the trial's times 210 rpm over that slope: 90 rpm."""
    s = solved(REVERTED, 7, 210)
    steps = s.steps()
    assert "drawn first for the arm 6 at a trial 21.99 rad/s ccw" in steps
    assert "so the arm 6 turns 9.425 rad/s ccw" in steps               # 90 rpm
    assert s.diagram.through[(6,)] == ("kz:O", "kz:v:6")


def test_a_ring_and_a_carrier_radius_at_one_level_are_one_named_line():
    """R = 50 (the compound planet) is the ring 8's pitch radius too: one level, named
    "R = r₈" on the figure."""
    s = solved(REVERTED, 6, 90)
    texts = [t.text for t in s.figures["kutzbach"].items if hasattr(t, "text")]
    assert "R = r₈" in texts and "R′" in texts


def test_each_line_runs_over_every_point_read_off_it():
    """Q1 driven by its planet: the planet's line is drawn through P14 and C, and P24 is read
    off it below C; the figure's line reaches P24."""
    s = solved(dict(gears=[(1, 140, None), (2, 60, None), (4, 40, 3)],
                    meshes=[(2, 4, False), (4, 1, True)], fixed=1, arm=3), 4, -80)
    fig = s.figures["kutzbach"]
    paths = [p for p in fig.items if getattr(p, "style", "") in ("link", "vector")]
    origin = paths[0].points[0]                        # the radial line rises from O
    mm = 10.0 / (s.diagram.per_cm * s.diagram.stated)
    x, y = s.diagram.construction.output("kz:pitch:2-4").xy
    p24 = (origin[0] + x * mm, origin[1] - y * mm)
    ends = [q for p in paths if p.style == "vector" for q in p.points]
    assert min(math.dist(q, p24) for q in ends) < 1e-9          # the planet's line ends there


@settings(max_examples=150, deadline=None)
@given(seed=st.integers(0, 2**32 - 1),
       family=st.sampled_from(("planetary", "compound-planet", "carrier-radii")))
@example(seed=227, family="planetary")        # a gear keyed to the arm's hub, held
def test_the_diagram_reads_the_table_and_willis_for_any_driver(seed, family):
    """A planetary train of the generator, posed with any member driving (a pinion on a side
    shaft among them): unless the arm is held (an ordinary train) or planets mesh each other
    off the radial line, the diagram is drawn and every member's slope is the table's
    speed, which is Willis' and the closed form's."""
    r = random.Random(seed)
    t = build(r, family)
    t.spec["ask"] = {"find": [f"omega{m}" for m in t.members]}
    want = oracle(t)
    if t.expect != "answer" or want is None:
        return
    s = solve_train(parse_train(train_toml(t.spec), "t.toml"))
    assert s.found.speeds == s.reference == want
    tr = s.train
    if tr.arm in tr.body(tr.fixed) or any(tr.carried(m.a) and tr.carried(m.b)
                                          for m in tr.meshes):
        assert s.diagram is None          # an ordinary train; planets in series (Q2)
        return
    assert undrawable(s.train) is None and s.diagram is not None
    # every member on the radial line: all but a pinion on a side shaft
    assert set(s.diagram.omegas) == set(want) - set(t.side)
    per = s.train.units.per_rad_s
    fastest = max(abs(float(want[m])) for m in s.diagram.omegas) * per
    for m, w in s.diagram.omegas.items():
        assert abs(w - float(want[m]) * per) <= 1e-9 * fastest, m
        miss, allowed = s.diagram_check(m)
        # measured against the fastest member, the check is never as wide as the speeds
        # (CEILING, 1e-5 of them); a member at rest is said as nil, its slope's rounding aside
        assert miss <= allowed <= 1e-5, m
        assert s.diagram.said(m) == 0.0 or want[m] != 0, m
    assert not s.diagram_misses
    json.dumps(s.results, allow_nan=False)      # every number finite
