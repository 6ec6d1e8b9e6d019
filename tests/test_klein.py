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


def off_line(r: float, l_: float, theta: float, w: float, ce: float, angle: float):
    """Velocity and acceleration (m/s, m/s²) of a point E of the rod, ce from the crank pin
    C at ``angle`` (rad, counter-clockwise) to CP: V_E = V_C + ω3 k × CE, a_E = a_C +
    α3 k × CE − ω3² CE, ω of the crank constant."""
    s, c = math.sin(theta), math.cos(theta)
    beta = math.asin(-r * s / l_)                       # the angle of CP
    w3, a3, _, _ = rod(r, l_, theta, w)
    ex, ey = ce * math.cos(beta + angle), ce * math.sin(beta + angle)
    v = (-w * r * s - w3 * ey, w * r * c + w3 * ex)
    a = (-w * w * r * c - a3 * ey - w3 * w3 * ex, -w * w * r * s + a3 * ex - w3 * w3 * ey)
    return v, a


def test_klein_finds_a_point_of_the_rod_off_its_line_by_the_similar_triangle():
    # E, 250 mm from C at 25° to CP, has its images e on CM and e′ on CN where CMe and CNe′
    # are similar to the rod's CPE; V_E = ω·Oe, a_E = ω²·e′O (the method names any image d).
    # Closed forms of lengths near 0.1 m and rates near 50 rad/s, a few roundings: 1e-12.
    sol = solve_exercise(load("klein-slider-crank"))
    v, a = off_line(0.150, 0.600, math.radians(60), -450 * 2 * math.pi / 60, 0.250,
                    math.radians(25))
    q = sol.quantities
    assert q["V_E"].method == "Klein's construction (V = ω·Od, CMd similar to the rod)"
    assert q["A_E"].method == "Klein's construction (a = ω²·d′O, CNd′ similar to the rod)"
    for name, want in (("V_E", v), ("A_E", a)):
        assert q[name].value["vector"] == pytest.approx(list(want), rel=1e-12)
        assert q[name].passed


def test_klein_takes_the_hinkle_rods_point_off_its_line():
    from tarsim.exercises.catalog import resolve
    from tarsim.exercises.linkages.exercise_file import parse_exercise

    text = resolve("hinkle-slider-crank").read_text(encoding="utf-8").replace(
        'methods = ["radius-rotation", "parallel-line", "components"]', 'methods = ["klein"]')
    text = text.replace("omega = 10", "omega = 10\nalpha = 0")
    # D: BD = 60, CD = 75 mm off BC = 120 mm; its angle at B by the cosine rule
    at_b = math.acos((60 ** 2 + 120 ** 2 - 75 ** 2) / (2 * 60 * 120))
    v, a = off_line(0.040, 0.120, math.radians(60), 10.0, 0.060, at_b)
    q = solve_exercise(parse_exercise(text, "h.toml", "h").asking(("V_D", "A_D"))).quantities
    assert q["V_D"].value["vector"] == pytest.approx(list(v), rel=1e-12)   # as above
    assert q["A_D"].value["vector"] == pytest.approx(list(a), rel=1e-12)
    four = resolve("four-bar").read_text(encoding="utf-8").replace(
        'methods = ["radius-rotation", "parallel-line", "components"]', 'methods = ["klein"]')
    with pytest.raises(TarsimError, match=r"^f\.toml:\d+: \[ask\.methods\] Klein's "
                                          "construction is drawn on a slider-crank"):
        parse_exercise(four, "f.toml", "f")


def test_a_rods_point_given_by_its_angle_sits_where_its_two_lengths_put_it():
    # "D, 60 mm from B at θ to BC": with cos θ from BD = 60, CD = 75, BC = 120 mm, the
    # angle places D where the two lengths do (to the rounding of acos and cos: 1e-12).
    from tarsim.exercises.catalog import resolve
    from tarsim.exercises.linkages.exercise_file import parse_exercise

    text = resolve("hinkle-slider-crank").read_text(encoding="utf-8")
    at_b = math.degrees(math.acos((60 ** 2 + 120 ** 2 - 75 ** 2) / (2 * 60 * 120)))
    by_angle = text.replace("lengths = { BC = 120, BD = 60, CD = 75 }",
                            f"lengths = {{ BC = 120, BD = 60 }}\nangles = {{ CBD = {at_b!r} }}")
    assert by_angle != text
    rods = [dict(parse_exercise(t, "h.toml", "h").mechanism.link(3).points)
            for t in (text, by_angle)]
    assert rods[1]["D"] == pytest.approx(rods[0]["D"], rel=1e-12, abs=1e-15)
    with pytest.raises(TarsimError, match=r"^h\.toml:\d+: \[link 3, BDC\] angle BDC of link 3 "
                                          "must name the angle at B or C"):
        parse_exercise(by_angle.replace("CBD =", "BDC ="), "h.toml", "h")
    with pytest.raises(TarsimError, match=r"say on which side of B→C point D lies"):
        parse_exercise(by_angle.replace('sides = { D = "left" }', ""), "h.toml", "h")
