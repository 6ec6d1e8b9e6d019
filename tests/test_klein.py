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


def rod(r: float, l_: float, theta: float, w: float):
    """The rod's ω and α, ω of the crank constant, and its midpoint's velocity and
    acceleration (m/s, m/s²), from r sin θ + L sin β = 0 differentiated twice (β the
    rod's angle from the crank pin to the piston)."""
    s, c = math.sin(theta), math.cos(theta)
    beta = math.asin(-r * s / l_)
    w3 = -w * r * c / (l_ * math.cos(beta))
    a3 = (r * w * w * s + l_ * w3 * w3 * math.sin(beta)) / (l_ * math.cos(beta))
    v_c = (-w * r * s, w * r * c)
    a_c = (-w * w * r * c, -w * w * r * s)
    v_p = (-r * w * s - l_ * w3 * math.sin(beta), 0.0)
    a_p = (-r * w * w * c - l_ * a3 * math.sin(beta) - l_ * w3 * w3 * math.cos(beta), 0.0)
    mid = lambda u, v: ((u[0] + v[0]) / 2, (u[1] + v[1]) / 2)          # noqa: E731
    return w3, a3, mid(v_c, v_p), mid(a_c, a_p)


def test_klein_finds_the_rods_midpoint_and_the_rods_rates_from_its_own_diagram():
    # The bundled Klein exercise's rod carries its midpoint D: V_D and A_D are read off Od
    # and d′O, d and d′ halfway along CM and CN; ω3 = ω·CM/CP and α3 = ω²·QN/CP.
    sol = solve_exercise(load("klein-slider-crank"))
    w = -450 * 2 * math.pi / 60
    w3, a3, v_d, a_d = rod(0.150, 0.600, math.radians(60), w)
    q = sol.quantities
    # closed forms of a few roundings of lengths near 0.1 m and rates near 50 rad/s: 1e-12
    assert q["omega3"].method == "Klein's construction (ω = ω₂·CM/CP)"
    assert q["omega3"].value["value"] == pytest.approx(w3, rel=1e-12)
    assert q["alpha3"].method == "Klein's construction (α = ω₂²·QN/CP)"
    assert q["alpha3"].value["value"] == pytest.approx(a3, rel=1e-12)
    for name, want in (("V_D", v_d), ("A_D", a_d)):
        assert q[name].method.startswith("Klein's construction")
        assert q[name].value["vector"] == pytest.approx(list(want), rel=1e-12)
    # and the polygons beside them agree
    assert q["omega3"].alternatives["velocity polygon"].value["value"] == pytest.approx(
        w3, rel=1e-12)
    assert all(x.passed for x in q.values())


def test_klein_refuses_a_point_off_the_rods_line_and_says_where():
    from tarsim.exercises.catalog import resolve
    from tarsim.exercises.linkages.exercise_file import parse_exercise

    text = resolve("hinkle-slider-crank").read_text(encoding="utf-8").replace(
        'methods = ["radius-rotation", "parallel-line", "components"]', 'methods = ["klein"]')
    ex = parse_exercise(text, "h.toml", "h").asking(("V_D",))
    with pytest.raises(TarsimError, match="Klein's construction finds points on the rod's line "
                                          "BC; D lies off it"):
        solve_exercise(ex)
    four = resolve("four-bar").read_text(encoding="utf-8").replace(
        'methods = ["radius-rotation", "parallel-line", "components"]', 'methods = ["klein"]')
    with pytest.raises(TarsimError, match=r"^f\.toml:\d+: \[ask\.methods\] Klein's "
                                          "construction is drawn on a slider-crank"):
        parse_exercise(four, "f.toml", "f")
