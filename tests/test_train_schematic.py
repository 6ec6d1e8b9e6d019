"""A train's side view: no two gears drawn over each other, whatever the carrier radii.

Gears that mesh touch at their pitch point and share a plane; a planet at another carrier
radius that would overlap one in that plane takes a plane of its own, and the ring or sun
both mesh runs across the two.
"""

from __future__ import annotations

import random
from fractions import Fraction as F
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.exercises.catalog import bundled
from tarsim.exercises.gears.train_file import parse_train
from tarsim.exercises.gears.train_solution import solve_train
from tarsim.graphics.figure import Path as FPath
from tarsim.graphics.gears.train_schematic import _axes
from tests.random_trains import build, oracle, train_toml
from tests.test_kutzbach import TWO_SETS, train


def boxes(fig) -> list[tuple[float, float, float, float]]:
    """Each gear's face as (x0, x1, y0, y1), paper mm."""
    out = []
    for it in fig.items:
        if isinstance(it, FPath) and it.style == "link" and it.closed:
            xs, ys = [p[0] for p in it.points], [p[1] for p in it.points]
            out.append((min(xs), max(xs), min(ys), max(ys)))
    return out


def overlapping(fig) -> list[tuple]:
    """Pairs of faces that share an area (touching along an edge is meshing)."""
    faces = boxes(fig)
    tol = 1e-6                                         # paper mm: rounding of the layout
    return [(a, b) for i, a in enumerate(faces) for b in faces[i + 1:]
            if min(a[1], b[1]) - max(a[0], b[0]) > tol and min(a[3], b[3]) - max(a[2], b[2])
            > tol]


def test_two_planet_sets_stand_in_two_planes_inside_one_wide_ring():
    s = solve_train(parse_train(train(**TWO_SETS, drive=2, speed=400), "t.toml"))
    fig = s.figures["train"]
    assert not overlapping(fig)
    faces = boxes(fig)
    widest = max(b[1] - b[0] for b in faces)
    narrowest = min(b[1] - b[0] for b in faces)
    assert widest > 2 * narrowest                       # the ring's rims span both planes


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 2**32 - 1),
       family=st.sampled_from(("planetary", "compound-planet", "carrier-radii")))
def test_no_two_gears_are_drawn_over_each_other(seed, family):
    t = build(random.Random(seed), family)
    t.spec["ask"] = {"find": [f"omega{m}" for m in t.members]}
    if t.expect != "answer" or oracle(t) is None:
        return
    s = solve_train(parse_train(train_toml(t.spec), "t.toml"))
    assert not overlapping(s.figures["train"])


def test_a_pinion_driving_the_arm_through_a_gear_on_its_hub():
    """Q1 with a gear 9 (90 teeth) keyed to the arm 3 and a pinion 10 (30) on a side shaft
    driving it at 80 rpm cw: ω3 = ω9 = 80·30/90 = 80/3; the ring fixed, ω2 = ω3·(140 + 60)/60
    = 800/9 and ω4 = ω3 − (ω2 − ω3)·60/40 = −200/3. The pinion stands a centre distance,
    (90 + 30)/2 = 60 modules, off the main axis; the gear 9 on it."""
    q1 = Path(bundled("gears")["planetary-q1"]).read_text(encoding="utf-8")
    text = (q1.replace("[arm]", '[[gear]]\nnumber = 9\nteeth = 90\n\n[[gear]]\nnumber = 10\n'
                       'teeth = 30\n\n[arm]', 1)
            .replace("gears = [2, 4]", "gears = [2, 4]\n\n[[mesh]]\ngears = [10, 9]\n\n"
                     "[[shaft]]\nmembers = [3, 9]", 1)
            .replace("member = 2\nspeed", "member = 10\nspeed", 1))
    s = solve_train(parse_train(text, "q1.toml"))
    assert s.found.speeds == s.reference == {1: 0, 2: F(800, 9), 4: F(-200, 3), 9: F(80, 3),
                                             10: F(-80), 3: F(80, 3)}
    assert s.passed and s.train.off_axis == (10,)
    assert _axes(s.train)[10] == 60.0 and _axes(s.train)[9] == 0.0
    assert not overlapping(s.figures["train"])
