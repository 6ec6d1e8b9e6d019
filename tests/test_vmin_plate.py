"""The slowest point of a plate (a link whose points are not on one line), ``Vmin_k``:
its nearest point to I_1k (a corner, the foot on a side, or I_1k itself within it), held
to the closed form of Hinkle's slider-crank and to shapely's nearest point of the
triangle, a geometry tarsim does not use."""

from __future__ import annotations

import math
import re

import pytest
from shapely.geometry import Point, Polygon
from shapely.ops import nearest_points

from tarsim.exercises.catalog import resolve
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution import solve_exercise

R, L, THETA, W = 0.040, 0.120, math.radians(60), 10.0     # Hinkle §5-4: crank, rod, θ2, ω2


def plate(bd: float, cd: float, side: str) -> dict[str, tuple[float, float]]:
    """B, C and D (m): D from its lengths to B and C, on ``side`` of B→C."""
    b = (R * math.cos(THETA), R * math.sin(THETA))
    c = (b[0] + math.sqrt(L * L - b[1] ** 2), 0.0)
    ux, uy = (c[0] - b[0]) / L, (c[1] - b[1]) / L
    x = (bd * bd - cd * cd + L * L) / (2 * L)
    h = math.sqrt(bd * bd - x * x) * (1 if side == "left" else -1)
    return {"B": b, "C": c, "D": (b[0] + x * ux - h * uy, b[1] + x * uy + h * ux)}


def asking(text: str, name: str) -> str:
    """The file's text asking ``name`` alone."""
    out, n = re.subn(r"^find = .*$", f'find = ["{name}"]', text, flags=re.M)
    assert n == 1
    return out


def solved(bd: float, cd: float, side: str):
    text = asking(resolve("hinkle-slider-crank").read_text(encoding="utf-8"), "Vmin_3")
    text = text.replace("lengths = { BC = 120, BD = 60, CD = 75 }",
                        f"lengths = {{ BC = 120, BD = {bd * 1000!r}, CD = {cd * 1000!r} }}")
    text = text.replace('sides = { D = "left" }', f'sides = {{ D = "{side}" }}')
    return solve_exercise(parse_exercise(text, "h.toml", "h")).quantities["Vmin_3"]


@pytest.mark.parametrize("bd, cd, side, where", [
    (0.060, 0.075, "left", "a corner"),          # the bundled plate: D itself
    (0.060, 0.075, "right", "a side"),           # D below BC: the foot on CD
    (0.3985, 0.4025, "left", "within"),          # a plate round I13: I13, at rest
])
def test_the_slowest_point_of_a_plate_is_its_point_nearest_i13(bd, cd, side, where):
    pts = plate(bd, cd, side)
    c = pts["C"]
    i13 = (c[0], c[0] * math.tan(THETA))         # O2B produced meets the normal to the stroke
    w3 = W * R * math.cos(THETA) / math.sqrt(L * L - (R * math.sin(THETA)) ** 2)
    poly = Polygon([pts["B"], pts["C"], pts["D"]])
    inside = poly.contains(Point(i13))
    assert inside == (where == "within")
    near = i13 if inside else nearest_points(poly.exterior, Point(i13))[0].coords[0]
    name = min(pts, key=lambda n: math.dist(pts[n], near))
    q = solved(bd, cd, side)
    # lengths near 0.1 m from a few square roots: 1e-12 of the size; the speed ω3·|MI13|
    assert q.value["point"] == pytest.approx(list(near), abs=1e-12)
    assert q.value["value"] == pytest.approx(abs(w3) * math.dist(near, i13), abs=1e-12)
    assert q.value["from"] == name
    assert q.value["along"] == pytest.approx(math.dist(pts[name], near), abs=1e-12)
    assert (q.value["along"] == 0.0) == (where == "a corner")     # a corner is the point
    assert q.passed and q.method == "nearest point of the plate to I13"


def test_the_frame_has_no_slowest_point_and_says_so():
    from tarsim.constructions.errors import TarsimError

    text = asking(resolve("hinkle-slider-crank").read_text(encoding="utf-8"), "Vmin_1")
    with pytest.raises(TarsimError, match=r"^h\.toml:\d+: \[ask\.find\] cannot find 'Vmin_1' "
                                          r"for this mechanism: Vmin_<k> is asked of a moving"):
        parse_exercise(text, "h.toml", "h")
