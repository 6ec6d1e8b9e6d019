"""A slider-crank's zero piston acceleration and greatest piston speed over a turn
(``A_P_zero``, ``V_P_max``), held to the exact piston motion bisected in closed form."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution import solve_overall


def engine(r: float, rod: float, omega: float, offset: float = 0.0,
           find: str = '"A_P_zero", "V_P_max"') -> str:
    """A slider-crank in mm: the crank O→C (r) at 40°, the rod C→P, the piston on a
    guide along x through O, ``offset`` mm above it."""
    return f'''
[units]
length = "mm"
angle = "deg"
[frame]
O = [0, 0]
[[link]]
number = 2
points = ["O", "C"]
lengths = {{ OC = {r} }}
[[link]]
number = 3
points = ["C", "P"]
lengths = {{ CP = {rod} }}
[[link]]
number = 4
points = ["P"]
[[slider]]
link = 4
point = "P"
on = 1
through = "O"
angle = 0
offset = {offset}
[input]
link = 2
angle = 40
omega = {omega}
[assembly]
P = "forward"
[ask]
find = [{find}]
'''


def piston(r: float, rod: float, e: float = 0.0):
    """The exact piston place x(θ) = r cos θ + √(l² − (r sin θ − e)²) and its first two
    derivatives in θ."""
    def x1(t):
        s = r * math.sin(t) - e
        return -r * math.sin(t) - s * r * math.cos(t) / math.sqrt(rod * rod - s * s)

    def x2(t):
        s, c = r * math.sin(t) - e, r * math.cos(t)
        q = rod * rod - s * s
        return (-r * math.cos(t) - (c * c - s * r * math.sin(t)) / math.sqrt(q)
                - s * s * c * c / q ** 1.5)

    return x1, x2


def bisect(f, lo: float, hi: float) -> float:
    """f's zero between lo and hi, halved until no float lies between them."""
    f_lo = f(lo)
    while True:
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            return mid
        if (f(mid) < 0) == (f_lo < 0):
            lo, f_lo = mid, f(mid)
        else:
            hi = mid


def answers_of(ex) -> dict:
    overall = solve_overall(ex)
    assert all(q.passed for q in overall.quantities.values())
    return {k: q.value for k, q in overall.quantities.items()}


def answers(text: str) -> dict:
    return answers_of(parse_exercise(text, "engine.toml"))


def test_the_steam_engines_zero_acceleration_is_the_exact_piston_motions():
    """Crank 300 mm, rod 1.5 m, 180 rpm clockwise: A = ω²x″(θ) = 0 where x″ does, out of
    the i.d.c. (θ = 0, the piston farthest from the shaft) at 79.10°, not the books'
    cos θ + cos 2θ/n ≈ 0's 79.27°; the piston is fastest there, ω|x′(θ)|."""
    w = 180 * 2 * math.pi / 60
    q = answers(engine(300, 1500, -w))
    x1, x2 = piston(0.3, 1.5)
    theta = bisect(x2, 0.5, 2.0)
    # Both narrowed to neighbouring floats of A's zero: A's rounding, some ulps of ω²r,
    # over its slope ω²r·O(1) moves the angle by some 1e-15 rad.
    assert q["A_P_zero"]["value"] == pytest.approx(math.degrees(theta), abs=1e-11)
    assert round(q["A_P_zero"]["value"], 2) == 79.10
    assert q["A_P_zero"]["zeros"] == pytest.approx([math.degrees(theta),
                                                     360 - math.degrees(theta)], abs=1e-11)
    # clockwise: the crank stands at −79.10° (280.90°) when it has turned 79.10°
    assert q["A_P_zero"]["crank_angle"] == pytest.approx(360 - math.degrees(theta), abs=1e-11)
    assert q["V_P_max"]["value"] == pytest.approx(w * abs(x1(theta)), rel=1e-13)
    assert q["V_P_max"]["angle"] == pytest.approx(math.degrees(theta), abs=1e-11)


@settings(max_examples=12, deadline=None)
@given(r=st.integers(50, 300), n=st.floats(2.0, 6.0), e=st.floats(-0.4, 0.4),
       ccw=st.booleans())
def test_an_offset_engines_zero_acceleration_is_its_exact_motions(r, n, e, ccw):
    """An offset e (a fraction of the crank) moves the i.d.c. to sin θ₀ = e/(r + l), where
    crank and rod stand in line; the zero is turned from there, the way the crank turns."""
    rod, off = round(n * r), round(e * r)
    q = answers(engine(r, rod, 10.0 if ccw else -10.0, off))
    x1, x2 = piston(r / 1000, rod / 1000, off / 1000)
    dead = math.asin(off / (r + rod))
    sense = 1 if ccw else -1
    theta = bisect(lambda t: x2(dead + sense * t), 0.2, 2.5)       # turned from the i.d.c.
    assert q["A_P_zero"]["value"] == pytest.approx(math.degrees(theta), abs=1e-9)
    crank = math.degrees(dead + sense * theta) % 360
    assert q["A_P_zero"]["crank_angle"] == pytest.approx(crank, abs=1e-9)
    fastest = max(abs(x1(math.radians(z) * sense + dead)) for z in q["A_P_zero"]["zeros"])
    assert q["V_P_max"]["value"] == pytest.approx(10 * fastest, rel=1e-12)


def test_a_linkage_with_no_piston_is_refused_in_one_line():
    text = engine(300, 1500, 10.0, find='"A_C_zero"')
    with pytest.raises(InputError) as e:
        parse_exercise(text, "engine.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("engine.toml:"), message
    assert "cannot find 'A_C_zero'" in message, message


def test_the_shapers_ram_peaks_where_tarsim_sweep_finds_its_acceleration_zero():
    """The crank-shaper's ram: the sweep's zeros of A_B, refined along the curve, are the
    ask's to the last bits (both narrow A_B's change of sign), and V_B_max is the sweep's
    greatest |V_B| there."""
    from tarsim.exercises.catalog import load
    from tarsim.exercises.linkages.sweep import sweep_exercise

    ex = load("crank-shaper")
    sw = sweep_exercise(ex, of="V_B")
    zeros = sorted(math.degrees(e.angle) % 360 for e in sw.events if e.key == "a")
    q = answers_of(ex.asking(("A_B_zero", "V_B_max")))
    first, second = q["A_B_zero"]["zeros"]        # turned from the dead centre, clockwise
    sense = math.copysign(1.0, ex.mechanism.drive.omega)
    crank = sorted((q["A_B_zero"]["crank_angle"],
                    (q["A_B_zero"]["crank_angle"] + sense * (second - first)) % 360))
    assert crank == pytest.approx(zeros, abs=1e-10)
    fastest = max(abs(e.values["v"]) for e in sw.events if e.key == "a")
    assert q["V_B_max"]["value"] == pytest.approx(fastest, rel=1e-12)
