"""A train's side view: no two gears drawn over each other, whatever the carrier radii.

Gears that mesh touch at their pitch point and share a plane; a planet at another carrier
radius that would overlap one in that plane takes a plane of its own, and the ring or sun
both mesh runs across the two.
"""

from __future__ import annotations

import random

from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.exercises.train_file import parse_train
from tarsim.exercises.train_solution import solve_train
from tarsim.graphics.figure import Path as FPath
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
