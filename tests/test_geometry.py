"""Tests for constructions.geometry: exact references, near-singular acts, properties.

Tolerances follow the module's error model: a verb's result is off by about
``eps / conditioning`` relative to the size ``S`` of the coordinates it was made
from. Every bound below is ``K * EPS * S / cond`` with a small ``K`` (measured
worst cases were K < 4 over 10^4 random near-singular cases; K = 16 leaves room
for platform libm differences), unless the comment next to it says otherwise.
"""

import dataclasses
import math
from decimal import Decimal, localcontext
from fractions import Fraction

import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from tarsim.constructions.errors import DegenerateInput, NoIntersection
from tarsim.constructions.geometry import (
    Branch, Circle, Line, Point, distance, intersect_circles, intersect_line_circle,
    intersect_lines, lay_off, line_through, midpoint, parallel_through, perpendicular_through,
    project_onto, rotate_about, side_of,
)

EPS = 2.0**-52
K = 16
SLACK = 64 * EPS  # the kernel's tangency/parallelism slack, relative to figure size
# Near tangency the half-chord comes out of a square root, so an O(eps) error in h^2
# is an O(sqrt eps) error in the point: eps / cond with cond floored at sqrt(eps).
COND_FLOOR = math.sqrt(EPS)

coords = st.floats(-1e3, 1e3, allow_subnormal=False)
turns = st.floats(-math.pi, math.pi)
points = st.builds(Point, coords, coords)
lines = st.builds(lambda t, c: Line(math.cos(t), math.sin(t), c), turns, coords)  # unit normal
radii = st.floats(1e-2, 1e3)
lengths = st.floats(1e-2, 1e3)


def _size(*vals):  # the figure's size S: the largest coordinate or length involved
    return max(abs(v) for v in vals)


def _dot(u, v):
    return u[0] * v[0] + u[1] * v[1]


# ---- high-precision references, computed from the exact values of the float inputs


def ref_lines(g, h):
    """Exact meet of two lines with Fraction; returns ((x, y), |sine|)."""
    a, b, c = map(Fraction, (g.a, g.b, g.c))
    a2, b2, c2 = map(Fraction, (h.a, h.b, h.c))
    w = a * b2 - b * a2
    return (float((b * c2 - c * b2) / w), float((c * a2 - a * c2) / w)), abs(float(w))


def ref_line_circle(line, circle, pick):
    """Line-circle cut at 50 digits: (point, cond, outside); h is clamped at 0 on a miss."""
    with localcontext(prec=50):
        a, b, c = map(Decimal, (line.a, line.b, line.c))
        n = (a * a + b * b).sqrt()
        a, b, c = a / n, b / n, c / n
        (cx, cy), r = map(Decimal, circle.centre.xy), Decimal(circle.radius)
        d = a * cx + b * cy + c
        h = max(r * r - d * d, Decimal(0)).sqrt() * (1 if pick == "forward" else -1)
        point = (float(cx - d * a + h * b), float(cy - d * b - h * a))
        return point, float(abs(h) / r), float(abs(d) - r)


def ref_circles(c1, c2, pick):
    """Circle-circle cut at 50 digits: (point, cond, gap); h is clamped at 0 on a miss."""
    with localcontext(prec=50):
        (x1, y1), (x2, y2) = map(Decimal, c1.centre.xy), map(Decimal, c2.centre.xy)
        r1, r2 = Decimal(c1.radius), Decimal(c2.radius)
        dx, dy = x2 - x1, y2 - y1
        d = (dx * dx + dy * dy).sqrt()
        a = (d * d + r1 * r1 - r2 * r2) / (2 * d)
        h = max(r1 * r1 - a * a, Decimal(0)).sqrt() * (1 if pick == "left" else -1)
        ux, uy = dx / d, dy / d
        point = (float(x1 + a * ux - h * uy), float(y1 + a * uy + h * ux))
        return point, float(d * abs(h) / (r1 * r2)), float(max(d - r1 - r2, abs(r1 - r2) - d))


# ---- exact values on round numbers


@pytest.mark.parametrize("made, expected", [
    (lambda: intersect_lines(line_through(Point(0, 0), Point(1, 0))[0],
                             line_through(Point(3, -1), Point(3, 1))[0]), ((3.0, 0.0), 1.0)),
    (lambda: intersect_line_circle(Line(0, 1, 0), Circle(Point(0, 3), 5.0), "backward"),
     ((-4.0, 0.0), 0.8)),
    (lambda: intersect_circles(Circle(Point(0, 0), 5.0), Circle(Point(6, 0), 5.0), "right"),
     ((3.0, -4.0), 0.96)),
    (lambda: project_onto(Point(3, 4), Line(0, 1, 0)), ((3.0, 0.0), 1.0)),
    (lambda: lay_off(Point(1, 1), Point(4, 5), -10.0), ((-5.0, -7.0), 5 / math.sqrt(41))),
    (lambda: midpoint(Point(-2, 6), Point(4, 2)), ((1.0, 4.0), 1.0)),
    (lambda: rotate_about(Point(3, 1), Point(2, 1), math.pi / 2), ((2.0, 2.0), 1.0)),  # CCW
])
def test_verbs_on_round_numbers(made, expected):
    p, cond = made()
    # Inputs and answers are small integers: a handful of roundings, 4 ulp is ample.
    assert p.xy == pytest.approx(expected[0], abs=4 * EPS * 10)
    assert cond == pytest.approx(expected[1], rel=4 * EPS)


# ---- intersections lie on both carriers (properties)


@given(turns, coords, coords, st.floats(-9, 0.47))  # angles 1e-9 .. 2.95 rad
def test_line_meet_lies_on_both_lines_and_matches_the_exact_meet(t, c1, c2, log_angle):
    g = Line(math.cos(t), math.sin(t), c1)
    h = Line(math.cos(t + 10**log_angle), math.sin(t + 10**log_angle), c2)
    p, cond = intersect_lines(g, h)
    exact, exact_sine = ref_lines(g, h)
    # The meet's error is eps * S / sine (S bounds every coordinate: |P| >= |c| of each line).
    tol = K * EPS * _size(*exact, c1, c2) / exact_sine
    assert p.xy == pytest.approx(exact, abs=tol)
    assert abs(g.signed_distance(p)) <= tol and abs(h.signed_distance(p)) <= tol


@given(lines, points, st.floats(-1.0, 1.0), st.sampled_from(["forward", "backward"]))
def test_line_circle_cut_lies_on_both(line, centre, s, pick):
    d = line.signed_distance(centre)
    # Radii around |d| so that cuts, near-tangencies and misses all occur.
    radius = abs(d) * (1 + math.copysign(10 ** (-16 * abs(s)), s))
    assume(radius > 1e-3)
    circle = Circle(centre, radius)
    outside = ref_line_circle(line, circle, pick)[2]
    try:
        p, cond = intersect_line_circle(line, circle, pick)
    except NoIntersection:
        assert outside > 0
        return
    tol = K * EPS * _size(*centre.xy, radius, line.c, *p.xy) / max(cond, COND_FLOOR)
    assert abs(line.signed_distance(p)) <= tol
    assert abs(distance(p, centre) - radius) <= tol
    assert 0.0 <= cond <= 1.0


@given(points, turns, lengths, radii, st.floats(-1.0, 1.0), st.booleans(),
       st.sampled_from(["left", "right"]))
def test_circle_cut_lies_on_both(c1, phi, d, r1, s, inner, pick):
    c2 = Point(c1.x + d * math.cos(phi), c1.y + d * math.sin(phi))
    d = distance(c1, c2)
    r2 = (abs(d - r1) if inner else d + r1) * (1 + math.copysign(10 ** (-16 * abs(s)), s))
    assume(r2 > 0)
    k1, k2 = Circle(c1, r1), Circle(c2, r2)
    gap = ref_circles(k1, k2, pick)[2]
    try:
        p, cond = intersect_circles(k1, k2, pick)
    except NoIntersection:
        assert gap > 0
        return
    tol = K * EPS * _size(*c1.xy, *c2.xy, r1, r2, d) / max(cond, COND_FLOOR)
    assert abs(distance(p, c1) - r1) <= tol and abs(distance(p, c2) - r2) <= tol
    assert 0.0 <= cond <= 1.0


# ---- near-parallel lines against an exact rational reference


@pytest.mark.parametrize("angle", [1e-1, 1e-3, 1e-5, 1e-7, 1e-9])
@pytest.mark.parametrize("base, phi, length", [
    ((0.0, 0.0), 0.0, 1.0), ((37.25, -12.5), 0.7, 50.0), ((-250.0, 400.0), -2.3, 300.0),
])
def test_near_parallel_lines_match_exact_meet(angle, base, phi, length):
    p0 = Point(*base)
    a = Point(base[0] + length * math.cos(phi), base[1] + length * math.sin(phi))
    b = Point(base[0] + length * math.cos(phi + angle), base[1] + length * math.sin(phi + angle))
    (g, cg), (h, ch) = line_through(p0, a), line_through(p0, b)
    p, sine = intersect_lines(g, h)
    exact, exact_sine = ref_lines(g, h)
    assert sine == pytest.approx(exact_sine, abs=2 * EPS)  # |w| from 2 products, unit normals
    # The drawn angle differs from `angle` by the rounding of phi + angle and of b.
    scale = _size(*p0.xy, *a.xy, *b.xy)
    drawn = K * EPS * (scale / length + abs(phi) + 1) / angle
    assert sine == pytest.approx(math.sin(angle), rel=drawn)
    # Kernel alone (lines taken as exact): relative error k * eps / sin(angle), relative to
    # the meet's size, which bounds both lines' offsets |c|.
    assert p.xy == pytest.approx(exact, abs=K * EPS * _size(*exact, g.c, h.c) / exact_sine)
    # End to end, both lines pass exactly through p0. The lines' own rounding compounds
    # with the meet's: the bound uses the product of conditionings, not the worst one.
    assert p.xy == pytest.approx(base, abs=K * EPS * scale / (sine * min(cg, ch)))


@pytest.mark.parametrize("g, h", [
    (Line(0.6, 0.8, -3.0), Line(0.6, 0.8, 5.0)),
    (Line(0.6, 0.8, -3.0), Line(-0.6, -0.8, 5.0)),  # opposite orientation
    (Line(0, 1, -3.0), Line(1e-15, 1, 5.0)),  # sine 1e-15, below the slack: taken as parallel
    (line_through(Point(1, 2), Point(7, -3))[0],
     parallel_through(Point(-4, 9), line_through(Point(1, 2), Point(7, -3))[0])[0]),
])
def test_parallel_lines_meet_at_infinity_in_their_direction(g, h):
    p, cond = intersect_lines(g, h)
    # The common direction is as good as the lines are apart (8 here, or 5 and 13 units).
    sep = abs(g.signed_distance(Point(*h.anchor())))
    assert p.is_at_infinity and cond == pytest.approx(sep / max(sep, abs(g.c), abs(h.c)), rel=1e-9)
    assert p.direction == pytest.approx(Point.at_infinity(*g.direction).direction, abs=4 * EPS)


@pytest.mark.parametrize("g, h", [
    (Line(0.6, 0.8, -3.0), Line(0.6, 0.8, -3.0)),
    (Line(0.6, 0.8, -3.0), Line(-0.6, -0.8, 3.0)),
    (Line(3, 4, -15), Line(0.6, 0.8, -3.0)),
    (line_through(Point(0, 1), Point(1, 2))[0], line_through(Point(5, 6), Point(2, 3))[0]),
    (Line(0, 0, 1), Line(0, 0, -2)),  # the line at infinity with itself
])
def test_coincident_lines_raise(g, h):
    with pytest.raises(DegenerateInput):
        intersect_lines(g, h)


def test_perpendicular_lines_far_from_origin_meet_at_a_finite_point():
    # Parallelism is judged by angle, not by the meet's distance from the origin.
    g, _ = line_through(Point(1e14, 0), Point(1e14, 1))
    h, _ = line_through(Point(0, 1e14), Point(1, 1e14))
    p, sine = intersect_lines(g, h)
    assert sine == 1.0 and not p.is_at_infinity
    assert p.xy == pytest.approx((1e14, 1e14), rel=4 * EPS)  # sine 1: a few roundings


# ---- tangency: circles and lines


@pytest.mark.parametrize("c1, r1, c2, r2, touch", [
    ((0, 0), 3.0, (5, 0), 2.0, (3.0, 0.0)),                 # external
    ((0, 0), 5.0, (2, 0), 3.0, (5.0, 0.0)),                 # internal
    ((0, 0), 2.0, (3, 4), 3.0, (1.2, 1.6)),                 # external, slanted
    ((1, 1), 10.0, (4, 5), 5.0, (7.0, 9.0)),                # internal, slanted
    ((1000, -2000), 3.0, (1003, -1996), 2.0, (1001.8, -1997.6)),
])
def test_tangent_circles_touch_with_zero_conditioning(c1, r1, c2, r2, touch):
    k1, k2 = Circle(Point(*c1), r1), Circle(Point(*c2), r2)
    scale = _size(*c1, *c2, r1, r2)
    for pick in Branch.LEFT, Branch.RIGHT:
        p, cond = intersect_circles(k1, k2, pick)
        assert cond == 0.0  # one factor of the half-chord product is exactly 0
        assert p.xy == pytest.approx(touch, abs=K * EPS * scale / COND_FLOOR)


def _check_cut(verb, carriers, pick, ref, scale, cond_per_length):
    """Compare a cut with its 50-digit reference; return its cond, or None if it missed."""
    point, ref_cond, miss = ref
    if miss > SLACK * scale:
        with pytest.raises(NoIntersection) as err:
            verb(*carriers, pick)
        # The margin is a difference of rounded distances: error ~ eps * S.
        assert err.value.margin == pytest.approx(miss, rel=K * EPS * scale / miss)
        return None
    p, cond = verb(*carriers, pick)  # exists, if only within slack
    tol = K * EPS * scale / max(ref_cond, COND_FLOOR)
    assert p.xy == pytest.approx(point, abs=tol)
    assert cond == pytest.approx(ref_cond, abs=tol * cond_per_length + 2 * EPS)
    return cond


@pytest.mark.parametrize("delta", [1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14, 1e-15])
@pytest.mark.parametrize("c1, r1, c2", [
    ((0, 0), 3.0, (5, 0)), ((12.5, -7.0), 40.0, (-20.0, 33.0)),      # touching outside
    ((0, 0), 8.0, (5, 0)), ((12.5, -7.0), 90.0, (-20.0, 33.0)),      # touching inside
])
def test_nearly_tangent_circles(delta, c1, r1, c2):
    k1 = Circle(Point(*c1), r1)
    d = distance(Point(*c1), Point(*c2))
    scale = _size(*c1, *c2, r1, d)
    for sign in 1, -1:  # crossing by delta, then missing by delta (relative to the figure)
        k2 = Circle(Point(*c2), abs(d - r1) + sign * delta * scale)
        # cond = d h / (r1 r2) inherits h's error times d / (r1 r2).
        _check_cut(intersect_circles, (k1, k2), "left", ref_circles(k1, k2, "left"), scale,
                   cond_per_length=d / (r1 * k2.radius))


def test_circle_conditioning_falls_to_zero_at_tangency():
    k1 = Circle(Point(0, 0), 3.0)
    conds = [intersect_circles(k1, Circle(Point(5, 0), 2.0 + 10.0**-e), "left")[1]
             for e in range(1, 15)]
    assert conds == sorted(conds, reverse=True) and conds[-1] < 1e-6
    # Near tangency h^2 is proportional to the overlap, so cond ~ sqrt(overlap): a 100-fold
    # smaller overlap gives a 10-fold smaller cond, up to O(overlap) and eps*S/overlap terms.
    assert conds[5] / conds[7] == pytest.approx(10.0, rel=1e-5)  # overlaps 1e-6 and 1e-8


@pytest.mark.parametrize("delta", [0.0, 1e-15, 1e-10, 1e-5, -1e-15, -1e-10, -1e-5])
@pytest.mark.parametrize("line, centre", [
    (line_through(Point(-10, 0), Point(10, 0))[0], (0.0, 3.0)),
    (line_through(Point(0, 0), Point(3, 4))[0], (-4.0, 3.0)),        # slanted: d = 5 approx.
    (Line(-0.28, 0.96, 120.0), (310.0, -17.5)),
])
def test_nearly_tangent_line_and_circle(delta, line, centre):
    centre = Point(*centre)
    d = abs(line.signed_distance(centre))
    scale = _size(*centre.xy, d, line.c)
    circle = Circle(centre, d + delta * scale)
    for pick in "forward", "backward":
        ref = ref_line_circle(line, circle, pick)
        cond = _check_cut(intersect_line_circle, (line, circle), pick, ref, scale,
                          cond_per_length=1 / circle.radius)  # cond = h / r
        if delta <= 0 and cond is not None:  # touching, or missing within slack:
            assert cond <= math.sqrt(2 * SLACK * scale / circle.radius)  # h^2 <= 2 r slack S


def test_nearly_concentric_circles_report_their_ill_conditioning():
    # d^2 = 1e-400 underflows; the verb must neither divide by it nor hide the singularity.
    _, cond = intersect_circles(Circle(Point(0, 0), 1.0), Circle(Point(1e-200, 0), 1.0), "left")
    assert cond < 1e-100  # the true cond is d h / (r1 r2) = 1e-200


# ---- branches


@given(points, turns, lengths, radii, radii)
def test_left_cut_is_left_of_centre_line(c1, phi, d, r1, r2):
    c2 = Point(c1.x + d * math.cos(phi), c1.y + d * math.sin(phi))
    k1, k2 = Circle(c1, r1), Circle(c2, r2)
    assume(ref_circles(k1, k2, "left")[2] <= 0)
    (left, cond), (right, _) = (intersect_circles(k1, k2, pick) for pick in ("left", "right"))
    assume(cond > 1e-6)
    assert side_of(left, c1, c2) > 0 > side_of(right, c1, c2)


@given(lines, points, st.floats(0.0, 0.999))
def test_forward_cut_is_further_along_the_line(line, centre, frac):
    d = abs(line.signed_distance(centre))
    circle = Circle(centre, d / (1 - frac) + 1e-3)
    fwd, cond = intersect_line_circle(line, circle, Branch.FORWARD)
    bwd, _ = intersect_line_circle(line, circle, Branch.BACKWARD)
    assume(cond > 1e-6)
    assert _dot((fwd.x - bwd.x, fwd.y - bwd.y), line.direction) > 0


# ---- points at infinity


@given(points, turns)
def test_line_through_a_direction_is_parallel_to_it(p, t):
    direction = Point.at_infinity(math.cos(t), math.sin(t))
    for line, cond in line_through(p, direction), line_through(direction, p):
        assert cond == 1.0
        assert Point.at_infinity(*line.direction).direction == pytest.approx(direction.direction,
                                                                             abs=4 * EPS)
        assert abs(line.signed_distance(p)) <= K * EPS * p.size()


def test_two_directions_join_in_the_line_at_infinity():
    line, _ = line_through(Point.at_infinity(1, 2), Point.at_infinity(-3, 1))
    assert line.is_at_infinity and line == Line(0, 0, 1)
    finite = Line(0.6, 0.8, -7.0)
    assert intersect_lines(line, finite)[0] == Point.at_infinity(*finite.direction)
    with pytest.raises(DegenerateInput):  # one direction, twice
        line_through(Point.at_infinity(1, 2), Point.at_infinity(-2, -4))


@given(coords, coords, st.integers(-60, 60), st.floats(0.01, 100), st.booleans())
def test_scaling_a_homogeneous_point_keeps_it(x, y, n, k, negative):
    k = -k if negative else k
    assume(all(v == 0 or abs(v) > 1e-250 for v in (x, y)))  # keep x * 2**n out of subnormals
    assert Point(x * 2.0**n, y * 2.0**n, 2.0**n) == Point(x, y)  # power-of-two scaling is exact
    # Any other factor rounds once in x*k and once in /k: 2 ulp relative.
    assert Point(x * k, y * k, k).xy == pytest.approx((x, y), rel=2 * EPS, abs=1e-300)
    assume(math.hypot(x, y) > 1e-150)
    assert Point(x * 2.0**n, y * 2.0**n, 0.0) == Point(x, y, 0.0)
    assert Point(x * k, y * k, 0.0).direction == pytest.approx(Point(x, y, 0.0).direction,
                                                               abs=4 * EPS)


@pytest.mark.parametrize("dx, dy", [(1, 0), (0, 1), (-0.0, 1.0), (3, -4), (-1e-300, 2)])
def test_a_direction_and_its_opposite_are_one_point(dx, dy):
    assert Point.at_infinity(dx, dy) == Point.at_infinity(-dx, -dy)
    assert math.hypot(*Point.at_infinity(dx, dy).direction) == pytest.approx(1.0, rel=EPS)


@pytest.mark.parametrize("make", [
    lambda: Point(math.nan, 0), lambda: Point(0, math.inf), lambda: Point(0, 0, 0),
    lambda: Point(1, 1, 1e-320), lambda: Line(0, 0, 0), lambda: Line(math.nan, 1, 0),
    lambda: Circle(Point(0, 0), 0.0), lambda: Circle(Point(0, 0), -1.0),
    lambda: Circle(Point(0, 0), math.nan), lambda: Circle(Point(1, 0, 0), 1.0),
    lambda: Point.at_infinity(1, 0).xy, lambda: Point(1, 0).direction,
    lambda: Line(1e-320, 0.0, 1.0),  # c / |(a, b)| overflows: too far away to represent
    lambda: parallel_through(Point.at_infinity(-2, 0), Line(0, 1, 0)),  # its own direction
    lambda: intersect_circles(Circle(Point(0, 0), 5.0), Circle(Point(6, 0), 5.0), "forward"),
    lambda: intersect_line_circle(Line(0, 1, 0), Circle(Point(0, 3), 5.0), "left"),
])
def test_degenerate_objects_raise(make):
    with pytest.raises(DegenerateInput):
        make()


def test_verbs_carry_directions():
    assert parallel_through(Point.at_infinity(0, 1), Line(0, 1, 0))[0].is_at_infinity
    turned, _ = rotate_about(Point.at_infinity(1, 1), Point(0, 0), math.pi / 2)
    assert turned.direction == pytest.approx(Point.at_infinity(-1, 1).direction, abs=4 * EPS)
    # A direction has no sense: laying off "toward" (-1, 0) goes along its canonical (1, 0).
    assert lay_off(Point(1, 1), Point.at_infinity(-1, 0), 2.0) == (Point(3, 1), 1.0)


def test_parallel_through_the_line_s_own_computed_direction_raises():
    g, _ = line_through(Point(1, 2), Point(7, -3))
    own, _ = intersect_lines(g, parallel_through(Point(-4, 9), g)[0])  # 1 ulp off g's
    with pytest.raises(DegenerateInput):
        parallel_through(own, g)


# ---- rotate, project, lay off, perpendicular


@given(points, points, st.floats(-10, 10))
def test_rotate_about_keeps_distance_and_turns_by_angle(p, centre, angle):
    q, _ = rotate_about(p, centre, angle)
    # Rounding in p - centre, the rotation and the sum: a few eps of the coordinates.
    tol = K * EPS * _size(*p.xy, *centre.xy)
    assert distance(q, centre) == pytest.approx(distance(p, centre), abs=tol)
    back, _ = rotate_about(q, centre, -angle)
    assert back.xy == pytest.approx(p.xy, abs=2 * tol)


@given(points, lines)
def test_project_onto_drops_a_perpendicular(p, line):
    foot, _ = project_onto(p, line)
    tol = K * EPS * _size(*p.xy, line.c)
    assert abs(line.signed_distance(foot)) <= tol
    residual = (p.x - foot.x, p.y - foot.y)
    assert abs(_dot(residual, line.direction)) <= tol
    assert math.hypot(*residual) == pytest.approx(abs(line.signed_distance(p)), abs=tol)


@given(points, points, st.floats(-1e3, 1e3))
def test_lay_off_gives_the_length_toward_the_target(start, toward, length):
    assume(distance(start, toward) > 1e-6 * _size(*start.xy, *toward.xy))
    end, cond = lay_off(start, toward, length)
    # The unit direction carries eps / cond; the length multiplies it.
    tol = K * EPS * _size(*start.xy, length) / cond
    assert distance(start, end) == pytest.approx(abs(length), abs=tol)
    sep = distance(start, toward)
    u = ((toward.x - start.x) / sep, (toward.y - start.y) / sep)  # unit: no underflow below
    offset = (end.x - start.x, end.y - start.y)
    assert abs(_dot(offset, (-u[1], u[0]))) <= tol  # off the ray by at most tol
    if abs(length) > tol:  # and on the side the sign of length says
        assert math.copysign(1, _dot(offset, u)) == math.copysign(1, length)


@given(points, lines)
def test_perpendicular_through_passes_through_p_at_right_angles(p, line):
    perp, _ = perpendicular_through(p, line)
    assert abs(perp.signed_distance(p)) <= K * EPS * p.size()
    assert perp.direction == pytest.approx(line.normal, abs=2 * EPS)


# ---- immutability


@pytest.mark.parametrize("obj, field", [
    (Point(1, 2), "x"), (Point(1, 2), "w"), (Line(0, 1, 2), "c"),
    (Circle(Point(0, 0), 1.0), "radius"),
])
def test_objects_are_frozen(obj, field):
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(obj, field, 0.5)
