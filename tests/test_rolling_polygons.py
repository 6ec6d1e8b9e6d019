"""Both polygons through a wheel rolling on the ground: its contact point P is at rest (the
wheel's instant centre) yet accelerates ω²·r toward the wheel's centre; the centre runs
parallel to the ground, so a_B = α·r along it. Against those relations and the solver."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from tarsim.exercises.catalog import load
from tarsim.exercises.linkages.solution import solve_exercise

ASKED = ("omega4", "alpha4", "V_B", "V_M", "A_B", "A_M")


@pytest.fixture(scope="module")
def wheel():
    ex = load("rolling-wheel")
    return solve_exercise(replace(ex, methods=("polygon",)).asking(ASKED))


def test_every_velocity_and_acceleration_through_the_rolling_contact_checks(wheel):
    for name in ASKED:
        q = wheel.quantities[name]
        assert q.passed and q.rel_error <= q.tolerance, name


def test_the_wheels_centre_moves_as_rolling_says(wheel):
    q = wheel.quantities
    r = 0.030                                           # the wheel's radius
    w, a = q["omega4"].value["value"], q["alpha4"].value["value"]
    vb, ab = q["V_B"].value["vector"], q["A_B"].value["vector"]
    # rolling without slip on the ground (+x): V_B = −ω r, a_B = −α r, both along x
    assert vb[0] == pytest.approx(-w * r, rel=1e-12) and abs(vb[1]) <= 1e-12 * abs(vb[0])
    assert ab[0] == pytest.approx(-a * r, rel=1e-11) and abs(ab[1]) <= 1e-11 * abs(ab[0])


def test_the_contact_point_accelerates_toward_the_centre(wheel):
    from tarsim.constructions.linkages.acceleration_polygon import drawn_acceleration_polygon

    ap = drawn_acceleration_polygon(wheel.work)
    w = wheel.quantities["omega4"].value["value"]
    px, py = ap.vector("P")
    assert (px, py) == pytest.approx((0.0, w * w * 0.030), rel=1e-12, abs=1e-12)
    assert math.hypot(px, py) == pytest.approx(w * w * 0.030, rel=1e-12)
