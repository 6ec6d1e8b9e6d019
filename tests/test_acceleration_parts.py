"""The normal and tangential parts of an acceleration (``An_B/A``, ``At_B/A``, ``An_B``,
``At_B``), resolved on the acceleration polygon: against the course's own numbers for the
crank-shaper's lever at t = 2.34 s (seed 003 §7, printed to 1e-3 mm/s²), against the
textbook relations Aⁿ = ω²·r and Aᵗ = α·r, and against the vector-loop solver."""

from __future__ import annotations

import math

import pytest

from tarsim.constructions import asks as A
from tarsim.constructions.errors import TarsimError
from tarsim.exercises.catalog import load
from tarsim.exercises.linkages.solution import solve_positions

LEVER = ("An_A4", "At_A4", "An_B4", "At_B4")


@pytest.fixture(scope="module")
def shaper_at_2_34():
    sols = solve_positions(load("crank-shaper").asking(LEVER + ("alpha4", "omega4")))
    return next(s for s in sols if s.position.slug == "t-2.34s")


@pytest.mark.parametrize("name, magnitude", [
    ("An_A4", 14.634), ("At_A4", 225.753),       # r3 ω4², r3 α4
    ("An_B4", 34.359), ("At_B4", 530.052),       # r4 ω4², r4 α4
])
def test_the_levers_parts_are_the_courses(shaper_at_2_34, name, magnitude):
    q = shaper_at_2_34.quantities[name]
    assert q.value["value"] * 1000 == pytest.approx(magnitude, abs=5e-4)
    assert q.passed


def test_on_a_lever_about_a_frame_pivot_the_parts_are_omega_squared_r_and_alpha_r(
        shaper_at_2_34):
    sol, q = shaper_at_2_34, shaper_at_2_34.quantities
    w, al = q["omega4"].value["value"], q["alpha4"].value["value"]
    (bx, by), (ox, oy) = sol.kinematics.points["B"], sol.kinematics.points["O4"]
    r = math.hypot(bx - ox, by - oy)
    assert q["An_B4"].value["value"] == pytest.approx(w * w * r, rel=1e-12)
    assert q["At_B4"].value["value"] == pytest.approx(abs(al) * r, rel=1e-12)
    # the normal part points from B toward O4, the centre of B's path
    nx, ny = q["An_B4"].value["vector"]
    assert (nx * (ox - bx) + ny * (oy - by)) / (math.hypot(nx, ny) * r) == pytest.approx(1.0)


def test_a_relative_acceleration_parts_into_its_normal_and_tangential_parts():
    (sol,) = solve_positions(load("four-bar").asking(("An_B/A", "At_B/A", "A_B/A", "omega3")))
    q = sol.quantities
    n, t, whole = (q[k].value["vector"] for k in ("An_B/A", "At_B/A", "A_B/A"))
    assert (n[0] + t[0], n[1] + t[1]) == pytest.approx(tuple(whole), rel=1e-12, abs=1e-12)
    assert n[0] * t[0] + n[1] * t[1] == pytest.approx(0.0, abs=1e-9 * math.hypot(*whole) ** 2)
    # Aⁿ_B/A = ω3²·AB, AB = 250 mm: exactly with ω3 as found, and with the README's ω3 =
    # −2.57846 rad/s, whose six figures leave ±1.9e-6 of ω3 and so ±3.9e-6 of ω3²
    w3 = q["omega3"].value["value"]
    assert q["An_B/A"].value["value"] == pytest.approx(w3 * w3 * 0.25, rel=1e-12)
    assert q["An_B/A"].value["value"] == pytest.approx(2.57846 ** 2 * 0.25, rel=3.9e-6)
    assert all(x.passed for x in q.values())


def test_parts_are_refused_where_they_mean_nothing():
    assert A.parse_ask("An_B/A") == A.AccelerationPart("n", "B", "A")
    assert A.parse_ask("At_B4") == A.AccelerationPart("t", "B4")
    with pytest.raises(TarsimError, match="O2 and B are not points of one moving link"):
        solve_positions(load("four-bar").asking(("An_O2/B",)))
