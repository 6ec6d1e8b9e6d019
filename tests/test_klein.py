"""Klein's construction of an in-line slider-crank's piston velocity and acceleration, against
the closed form x(θ) = r cos θ + √(L² − r² sin² θ) differentiated at constant ω, and
against the polygons."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from tarsim.constructions.errors import TarsimError
from tarsim.exercises.catalog import load
from tarsim.exercises.linkages.solution import solve_exercise


def piston(r: float, l_: float, theta: float, w: float) -> tuple[float, float]:
    """Velocity and acceleration of the piston along the stroke (m/s, m/s²), ω constant."""
    s, c = math.sin(theta), math.cos(theta)
    d = math.sqrt(l_ * l_ - r * r * s * s)
    dx = -r * s - r * r * s * c / d
    ddx = -r * c - r * r * (c * c - s * s) / d - r ** 4 * s * s * c * c / d ** 3
    return w * dx, w * w * ddx


def test_klein_gives_the_closed_form_and_the_polygons_agree():
    sol = solve_exercise(load("klein-slider-crank"))
    w = -450 * 2 * math.pi / 60                        # 450 rpm clockwise
    v, a = piston(0.150, 0.600, math.radians(60), w)
    for name, want in (("V_P", v), ("A_P", a)):
        q = sol.quantities[name]
        assert q.method.startswith("Klein's construction")
        assert q.value["vector"][0] == pytest.approx(want, rel=1e-12)
        assert abs(q.value["vector"][1]) <= 1e-12 * abs(want)
        polygon = q.alternatives["velocity polygon" if name == "V_P" else "acceleration polygon"]
        assert polygon.value["vector"][0] == pytest.approx(q.value["vector"][0], rel=1e-12)


def test_klein_refuses_what_it_cannot_draw():
    offset = load("offset-slider-crank")
    ex = replace(offset, methods=("klein",), positions=()).asking(("V_B",))
    with pytest.raises(TarsimError, match="Klein's construction is drawn on an in-line "
                                          "slider-crank; this stroke passes 20 cm from O2"):
        solve_exercise(ex)
    four = replace(load("four-bar"), methods=("klein",)).asking(("V_B",))
    with pytest.raises(TarsimError, match="Klein's construction is drawn on a slider-crank"):
        solve_exercise(four)
