"""The crank-shaper of seed 003 at t = 2.34 s, against finite differences of its exact position.

The reference here uses neither the analytic solver nor any tarsim construction: the
position is written in closed form and differentiated numerically.

Geometry (seed 003 §2, mm): O2 at the origin, O4 = (0, −r1) with r1 = 500, crank
O2A = r2 = 180, ram line y = h = 380. The lever's slot passes through O4 and A, and the
ram's pin B runs in it on the ram line:

    A  = (r2 cos θ2, r2 sin θ2)
    θ4 = atan2(A_y + r1, A_x)                       (the slot O4 → A)
    r3 = |O4A| = hypot(A_x, A_y + r1)
    B lies on O4 + s (cos θ4, sin θ4) with y = h, so its rise from O4 is r1 + h:
    r4 = |O4B| = (r1 + h) / sin θ4,    p = x_B = (r1 + h) cos θ4 / sin θ4
                                         = (r1 + h) A_x / (A_y + r1).

The input is θ2(t) = π/2 − t (ω2 = −1 rad/s, α2 = 0; seed §2, §6), so with ' = d/dθ2
the chain rule gives ẋ = −x' and ẍ = x'' (θ̈2 = 0).

Finite differences, 5-point central, in θ2:

    f'  ≈ (f(x−2h) − 8 f(x−h) + 8 f(x+h) − f(x+2h)) / 12h
          truncation h⁴ |f⁽⁵⁾| / 30, rounding ≈ (18/12) ε |f| / h
    f'' ≈ (−f(x−2h) + 16 f(x−h) − 30 f(x) + 16 f(x+h) − f(x+2h)) / 12h²
          truncation h⁴ |f⁽⁶⁾| / 90, rounding ≈ (64/12) ε |f| / h²

(ε ≈ 2.2e-16 times the few ulps of cos/atan2/hypot.) The functions are analytic with
their nearest complex singularity about 1.7 from the real axis (r2 sin θ2 = −r1), so
the high derivatives stay moderate: at this position |f⁽⁵⁾/f'| ≤ 35 and
|f⁽⁶⁾/f''| ≤ 105 over θ4, p, r3, r4. Balancing truncation against rounding gives
h ≈ 1e-3 for f' and h ≈ 4e-3 for f''; we take the powers of two 2⁻¹⁰ and 2⁻⁸, so
that x ± h and x ± 2h are exact (x ≈ −0.769 stays in [0.5, 1) in magnitude, where h
is a whole number of ulps). The estimated error is then

    f'  : h⁴·35/30 + 1.5 ε |f/f'| / h        ≈ 1e-12 + 5e-12   ≲ 1e-11 relative
    f'' : h⁴·105/90 + 5.3 ε |f/f''| / h²     ≈ 3e-10 + 5e-10   ≲ 1e-9 relative

with |f/f'| ≤ 15 and |f/f''| ≤ 7 here, both worst for r4 (measured against 40-digit
differentiation while writing this: 2.2e-12 and 3.0e-10).
So the FD rates are compared with the polygons to 1e-10 (first derivatives: ω4,
velocities, sliding speeds) and 1e-8 (second: α4, accelerations, Coriolis, which
mixes both), 10 times the estimate; with the seed's printed numbers to half a unit
in the last printed digit, which the FD error is far below.
"""

import math

import pytest

from tarsim.constructions.linkages.acceleration_polygon import draw_acceleration_polygon
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tests.common import crank_shaper

R1, R2, H = 500.0, 180.0, 380.0     # mm: O2O4, O2A, height of the ram line above O2
T = 2.34                            # s, seed 003 §6–7
OMEGA2 = -1.0
H1 = 2.0 ** -10                     # step for first derivatives (≈ 9.8e-4 rad)
H2 = 2.0 ** -8                      # step for second derivatives (≈ 3.9e-3 rad)
FIRST, SECOND = 1e-10, 1e-8         # relative tolerances, from the estimate above


def theta2(t: float) -> float:
    return math.pi / 2 + OMEGA2 * t


def position(th2: float) -> dict[str, float]:
    """The exact position (mm, rad) at crank angle θ2, in closed form."""
    ax, ay = R2 * math.cos(th2), R2 * math.sin(th2)
    th4 = math.atan2(ay + R1, ax)
    return {"theta4": th4, "p": (R1 + H) * ax / (ay + R1), "r3": math.hypot(ax, ay + R1),
            "r4": (R1 + H) / math.sin(th4)}


def d1(key: str, x: float, h: float) -> float:
    f = [position(x + k * h)[key] for k in (-2, -1, 1, 2)]
    return (f[0] - 8.0 * f[1] + 8.0 * f[2] - f[3]) / (12.0 * h)


def d2(key: str, x: float, h: float) -> float:
    f = [position(x + k * h)[key] for k in (-2, -1, 0, 1, 2)]
    return (-f[0] + 16.0 * f[1] - 30.0 * f[2] + 16.0 * f[3] - f[4]) / (12.0 * h * h)


def rates(t: float) -> dict[str, float]:
    """Position, velocity and acceleration of every variable by FD, in time (mm, rad, s)."""
    x = theta2(t)
    out = dict(position(x))
    for key in ("theta4", "p", "r3", "r4"):
        out[key + "_dot"] = OMEGA2 * d1(key, x, H1)               # ẋ = θ̇2 x'
        out[key + "_ddot"] = OMEGA2 ** 2 * d2(key, x, H2)         # ẍ = θ̇2² x'' (θ̈2 = 0)
    return out


@pytest.fixture(scope="module")
def fd():
    return rates(T)


@pytest.fixture(scope="module")
def drawn():
    asm = assemble(crank_shaper(theta2(T), omega2=OMEGA2, alpha2=0.0))
    vp = draw_velocity_polygon(asm)
    return asm, vp, draw_acceleration_polygon(asm, vp)


def coriolis(fd, slide: str) -> tuple[float, float]:
    """2 ω4 × (ṙ u): the sliding velocity along u = (cos θ4, sin θ4) turned by ω4 (mm/s²)."""
    w4, speed = fd["theta4_dot"], fd[slide + "_dot"]
    ux, uy = math.cos(fd["theta4"]), math.sin(fd["theta4"])
    return 2.0 * w4 * speed * -uy, 2.0 * w4 * speed * ux


# ----- the reference against the seed ---------------------------------------------------
def test_closed_form_position_is_the_seeds(fd):
    # Seed 003 §7 ground truth: θ4 = 1.23854 rad, p = 303.643, O4A = 396.483,
    # O4B = 930.913 mm; half a unit in the last printed digit.
    assert fd["theta4"] == pytest.approx(1.23854, abs=0.5e-5)
    assert fd["p"] == pytest.approx(303.643, abs=0.5e-3)
    assert fd["r3"] == pytest.approx(396.483, abs=0.5e-3)
    assert fd["r4"] == pytest.approx(930.913, abs=0.5e-3)


def test_finite_differences_give_the_seeds_rates(fd):
    # Seed 003 §7 (signs for ω2 = −1 as stated there, §10 table row t = 2.34): the FD
    # error (≲ 1e-9 relative) is far below half a unit in the last printed digit.
    w4, a4 = fd["theta4_dot"], fd["theta4_ddot"]
    assert w4 == pytest.approx(0.19212, abs=0.5e-5)
    assert fd["p_dot"] == pytest.approx(-189.192, abs=0.5e-3)
    assert a4 == pytest.approx(0.56939, abs=0.5e-5)
    assert fd["p_ddot"] == pytest.approx(-535.635, abs=0.5e-3)
    # The sliding speeds are printed as magnitudes; their accelerations are signed.
    assert abs(fd["r3_dot"]) == pytest.approx(163.089, abs=0.5e-3)
    assert abs(fd["r4_dot"]) == pytest.approx(61.710, abs=0.5e-3)
    assert fd["r3_ddot"] == pytest.approx(90.805, abs=0.5e-3)
    assert fd["r4_ddot"] == pytest.approx(-140.353, abs=0.5e-3)
    assert math.hypot(*coriolis(fd, "r3")) == pytest.approx(62.665, abs=0.5e-3)
    assert math.hypot(*coriolis(fd, "r4")) == pytest.approx(23.711, abs=0.5e-3)
    assert fd["r3"] * w4 ** 2 == pytest.approx(14.634, abs=0.5e-3)        # a_A4^n
    assert fd["r3"] * abs(a4) == pytest.approx(225.753, abs=0.5e-3)       # a_A4^t


def test_the_steps_sit_where_the_error_estimate_says():
    # If truncation dominated, halving h would change f' and f'' by ~15/16 of their
    # error; if rounding did, by ~2× and ~4× theirs. Either way the change bounds the
    # error's size: it must stay within the estimate (1e-11 and 1e-9 relative) times a
    # small factor, or the tolerances above are not justified.
    x = theta2(T)
    for key in ("theta4", "p", "r3", "r4"):
        first, half1 = d1(key, x, H1), d1(key, x, H1 / 2)
        second, half2 = d2(key, x, H2), d2(key, x, H2 / 2)
        assert abs(first - half1) <= 2e-11 * abs(first)
        assert abs(second - half2) <= 4e-9 * abs(second)


# ----- the polygons against the reference -----------------------------------------------
def test_velocity_polygon_matches_the_finite_differences(fd, drawn):
    asm, vp, _ = drawn
    assert vp.rates[4] == pytest.approx(fd["theta4_dot"], rel=FIRST)
    assert vp.rates[3] == vp.rates[4]
    vx, vy = vp.vector("B")
    assert vx * 1e3 == pytest.approx(fd["p_dot"], rel=FIRST)
    assert vy == pytest.approx(0.0, abs=1e-15)
    # The sliding velocities: V_A2/A4 = ṙ3 u and V_B5/B4 = ṙ4 u.
    u = (math.cos(fd["theta4"]), math.sin(fd["theta4"]))
    for a, b, key in (("A", "A4", "r3_dot"), ("B", "B4", "r4_dot")):
        (px, py), (qx, qy) = vp.vector(a), vp.vector(b)
        assert ((px - qx) * u[0] + (py - qy) * u[1]) * 1e3 == pytest.approx(fd[key], rel=FIRST)


def test_acceleration_polygon_matches_the_finite_differences(fd, drawn):
    asm, _, ap = drawn
    assert ap.rates[4] == pytest.approx(fd["theta4_ddot"], rel=SECOND)
    bx, by = ap.vector("B")
    assert bx * 1e3 == pytest.approx(fd["p_ddot"], rel=SECOND)
    assert by == pytest.approx(0.0, abs=1e-15)
    # The Coriolis components, as vectors (direction and sense included).
    for point, slide in (("A", "r3"), ("B", "r4")):
        want = coriolis(fd, slide)
        got = tuple(c * 1e3 for c in ap.coriolis_of(point))
        assert math.dist(got, want) <= SECOND * math.hypot(*want)
    # The sliding accelerations r̈3 and r̈4, read off the drawn components along O4 → A.
    c = asm
    u = (math.cos(fd["theta4"]), math.sin(fd["theta4"]))
    for label, sign, key in (("−Aˢ_A2/A4", -1.0, "r3_ddot"), ("Aˢ_B5/B4", 1.0, "r4_ddot")):
        start, end = c[ap.components[label]].inputs
        (sx, sy), (ex, ey) = c.output(start).xy, c.output(end).xy
        along = sign * ((ex - sx) * u[0] + (ey - sy) * u[1]) / ap.scale
        assert along * 1e3 == pytest.approx(fd[key], rel=SECOND)
    # A of A2 (the crank pin) is ω2²·O2A toward O2, and A4 = ω4²·O4A toward O4 plus α4·O4A.
    r3, w4, a4 = fd["r3"], fd["theta4_dot"], fd["theta4_ddot"]
    ux, uy = u
    want = (-r3 * w4 ** 2 * ux - a4 * r3 * uy, -r3 * w4 ** 2 * uy + a4 * r3 * ux)
    got = tuple(v * 1e3 for v in ap.vector("A4"))
    assert math.dist(got, want) <= SECOND * math.hypot(*want)
