"""A cam's extremes found between samples: for random segment layouts, very short steep
segments and segments that start or end a hair off a ¼° sample among them, the greatest
pressure angle and the least radius of curvature tarsim reports are those of the laws.

Two independent readings, both written here or in tests/random_cams.py, neither tarsim's:

- mpmath at 30 digits evaluates the textbook's tan φ = (y′ − σe)/(s₀ + y) and the
  curvature of the cam-frame pitch point R(−σθ)·(e, s₀ + y), differentiated numerically,
  at the angle tarsim reports, and a little either side of it within its piece: the value
  reported is the law's there (to the rounding of the reported angle times the slope), and
  nothing near it is greater;
- the oracle of tests/random_cams.py grids every piece of every law densely and zooms in on
  its best points: nothing round the cam is steeper or sharper than what was reported.
"""

from __future__ import annotations

import mpmath as mp
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from tarsim.constructions.reference.cam_laws import pieces
from tarsim.exercises.cams.cam_file import parse_cam
from tarsim.exercises.cams.cam_solution import solve_cam
from tests.random_cams import extremes, to_toml

LAWS = ("uniform velocity", "modified uniform velocity", "simple harmonic", "parabolic",
        "cycloidal")

# The pressure angle and curvature are each a few roundings of sums of numbers of the cam's
# size, divided by a speed |q₁| ≥ s₀ + y ≥ r_b − |e|/… of the same order in these layouts
# (the offset at most ¾ of the prime radius): 1e-12 relative holds with room; mpmath's
# numerical derivative at 30 digits adds nothing at that level.
LOCAL = 1e-12
# The oracle's grid and tarsim's search both locate a maximum, flat there, to rounding.
GLOBAL = 1e-9
EPS = 2.0 ** -52


@st.composite
def layouts(draw):
    """A translating roller or knife edge and 2–5 segments: round, odd, very short (0.01°
    to 1°) and a hair (1e-9° to 1e-5°) off a multiple of ¼°."""
    n = draw(st.integers(2, 5))
    angle = st.one_of(st.sampled_from([30.0, 60.0, 90.0, 120.0]),
                      st.floats(5.0, 120.0).map(lambda a: round(a, 3)),
                      st.floats(0.01, 1.0),
                      st.tuples(st.integers(4, 400), st.floats(1e-9, 1e-5),
                                st.sampled_from([1, -1])).map(
                          lambda t: 0.25 * t[0] + t[1] * t[2]))
    angles = [draw(angle) for _ in range(n - 1)]
    if sum(angles) > 350.0:
        angles = [a * 300.0 / sum(angles) for a in angles]
    angles.append(360.0 - sum(angles))
    kinds = ["rise"] + [draw(st.sampled_from(["rise", "dwell", "return"]))
                        for _ in range(n - 2)] + ["return"]
    segments, height = [], 0.0
    for kind, a in zip(kinds, angles):
        t = {"kind": kind, "angle": a}
        if kind != "dwell":
            law = draw(st.sampled_from(LAWS))
            # A return takes none, a fair part or all of the height: a lift a millionth of
            # the cam's is refused as lost in the drawing's rounding (test_reproducers_cams.py),
            # so a part leaves a tenth at least (three parts in turn leave 1e-3 of the rise),
            # never the 4e-16 of a part an ulp short of all.
            lift = draw(st.floats(1.0, 60.0)) if kind == "rise" else \
                height * draw(st.one_of(st.just(0.0), st.floats(0.01, 0.9), st.just(1.0)))
            height += lift if kind == "rise" else -lift
            t |= {"law": law, "lift": lift}
            if law == "modified uniform velocity":
                t |= {"divisions": 8, "blend": draw(st.sampled_from([0.25, 0.5]))}
        segments.append(t)
    segments[-1]["lift"] += height
    base = draw(st.floats(10.0, 80.0))
    roller = draw(st.one_of(st.just(0.0), st.floats(2.0, 30.0)))
    follower = {"kind": "roller", "radius": roller} if roller else {"kind": "knife-edge"}
    follower["offset"] = (base + roller) * draw(st.one_of(
        st.just(0.0), st.floats(0.01, 0.75), st.floats(-0.75, -0.01)))
    return to_toml({"name": "layout", "units": {"length": "mm"},
                    "cam": {"base_radius": base, "speed": 100,
                            "sense": draw(st.sampled_from(["cw", "ccw"]))},
                    "follower": follower, "segment": segments})


def _law(law: str, piece: int, u, h, beta, blend):
    """A rise's lift by ``law``'s formula on its ``piece``, in mpmath (u = θ/β)."""
    if law == "uniform velocity":
        return h * u
    if law == "simple harmonic":
        return h / 2 * (1 - mp.cos(mp.pi * u))
    if law == "cycloidal":
        return h * (u - mp.sin(2 * mp.pi * u) / (2 * mp.pi))
    if law == "parabolic":
        return 2 * h * u * u if piece == 0 else h - 2 * h * (1 - u) ** 2
    c = h / (blend * (1 - blend))
    if piece == 0:
        return c * u * u / 2
    if piece == 2 or blend == 0.5:
        return h - c * (1 - u) ** 2 / 2
    return h * (u - blend / 2) / (1 - blend)


def _readings(ex, k: int, theta: float):
    """(|φ|, convex curvature) at cam angle ``theta`` in segment ``k`` (from 1), by each
    piece of its law that holds ``theta`` (two at a piece's end), as mpmath functions of
    the angle, with the piece's span."""
    mp.mp.dps = 30
    segs = ex.segments
    s = segs[k - 1]
    start = sum(x.angle for x in segs[:k - 1])
    height = sum(x.lift if x.kind == "rise" else -x.lift if x.kind == "return" else 0.0
                 for x in segs[:k - 1])
    f = ex.follower
    prime = ex.base_radius + f.radius
    e, sigma = mp.mpf(f.offset), ex.sigma
    s0 = mp.sqrt(mp.mpf(prime) ** 2 - e * e)
    cuts = (0.0, 1.0) if s.kind == "dwell" else pieces(s.law, s.blend)
    out = []
    for i, (a, b) in enumerate(zip(cuts, cuts[1:])):
        if not start + a * s.angle - 1e-12 <= theta <= start + b * s.angle + 1e-12:
            continue

        def y(t, i=i):
            u = (t - start) / mp.mpf(s.angle)
            if s.kind == "dwell":
                return mp.mpf(height)
            up = _law(s.law, i, u, mp.mpf(s.lift), mp.mpf(s.angle), mp.mpf(s.blend))
            return height + up if s.kind == "rise" else height - up

        def point(t, y=y):
            r = s0 + y(t)
            c, sn = mp.cos(-sigma * t), mp.sin(-sigma * t)
            return c * e - sn * r, sn * e + c * r

        def steep(t, y=y):
            return abs(mp.atan((mp.diff(y, t) - sigma * e) / (s0 + y(t))))

        def bend(t, point=point):
            x1, x2 = (mp.diff(lambda v: point(v)[0], t, n) for n in (1, 2))
            y1, y2 = (mp.diff(lambda v: point(v)[1], t, n) for n in (1, 2))
            return -sigma * (x1 * y2 - y1 * x2) / (x1 * x1 + y1 * y1) ** 1.5

        out.append((steep, bend, start + a * s.angle, start + b * s.angle))
    return out


def _held_locally(readings, which: int, theta: float, value: float) -> bool:
    """The value reported is the law's at ``theta`` by one of its pieces, and that piece is
    no greater a little either side of it (within the piece)."""
    for r in readings:
        f, lo, hi = r[which], r[2], r[3]
        at = mp.mpf(theta)
        # tarsim reads the law at t into the segment and reports θ = start + t, one double
        # sum: θ stands up to half an ulp (≤ EPS·|θ|/2) off the place the value belongs to.
        # Where the quantity runs steeply, as it does at the end of a blend a fraction of a
        # degree long (|dκ/dθ| ≈ 4e10 /m·rad against κ ≈ 1.6e6 /m), that half ulp alone moves
        # it ~3e-12 of itself: the slope times EPS·|θ| bounds it with a factor two to spare.
        slack = LOCAL * abs(value) + abs(float(mp.diff(f, at))) * EPS * abs(theta)
        if abs(float(f(at)) - value) > slack:
            continue
        near = [theta + d * (hi - lo) for d in (-1e-6, -1e-9, 1e-9, 1e-6)]
        if all(float(f(mp.mpf(t))) <= value * (1 + LOCAL) for t in near if lo <= t <= hi):
            return True
    return False


# The cam's sharpest point is the end of a blend a quarter of a degree long: its curvature
# there (1.6e6 /m) climbs 4e10 /m a radian, so the half ulp the reported θ is rounded by
# moves the law's value at it 3e-12 of itself, past LOCAL alone.
STEEP_END = """\
name = "layout"
[units]
length = "mm"
[cam]
base_radius = 10.0
speed = 100
sense = "cw"
[follower]
kind = "knife-edge"
offset = 5.0
[[segment]]
kind = "rise"
angle = 30.0
law = "uniform velocity"
lift = 1.0
[[segment]]
kind = "rise"
angle = 30.0
law = "uniform velocity"
lift = 1.0
[[segment]]
kind = "rise"
angle = 0.25
law = "modified uniform velocity"
lift = 1.0
divisions = 8
blend = 0.25
[[segment]]
kind = "return"
angle = 299.75
law = "uniform velocity"
lift = 3.0
"""


@pytest.mark.slow
@settings(max_examples=40, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(layouts())
@example(STEEP_END)
def test_a_cams_extremes_are_its_laws_between_samples(text):
    ex = parse_cam(text, "layout.toml")
    s = solve_cam(ex, allow_undercut=True)
    q = s.results["quantities"]
    steep, sharp = q["pressure_angle_max"], q["rho_min"]
    assert _held_locally(_readings(ex, steep["segment"], steep["theta"]), 0, steep["theta"],
                         steep["value"])
    assert _held_locally(_readings(ex, sharp["segment"], sharp["theta"]), 1, sharp["theta"],
                         1 / sharp["value"])
    ext = extremes(text)
    assert steep["value"] == pytest.approx(ext.pressure, rel=GLOBAL)
    assert 1 / sharp["value"] == pytest.approx(ext.curvature, rel=GLOBAL)
    assert s.passed, s.failures
