"""The instant-centre reference stays sharp as a four-bar nears the toggle of its input.

Near the toggle the driven ω and v carry an error of eps/rcond of their size, so centres
taken from them would have a tolerance of that size: the reference would be the weaker of
the reference and the construction. The reference takes them from the free motion instead
(``Kinematics.free``). Here each of the six centres of a non-Grashof four-bar at 1e-3,
1e-6 and 1e-9 rad from the toggle is checked against a 50-digit closed form (mpmath).
"""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tarsim.constructions.model import Drive, Link, Mechanism
from tarsim.constructions.units import Units
from tarsim.constructions.reference.centres import instant_centre, mechanism_size, shared_pin
from tarsim.constructions.reference.solver import solve
from tests.common import four_bar

GROUND, CRANK, COUPLER, ROCKER = 4, 3, 2, 2.5      # non-Grashof: 2 + 4 > 3 + 2.5
# The toggle: coupler and rocker in line, |A − O4| = coupler + rocker.
TOGGLE = mp.acos((CRANK ** 2 + GROUND ** 2 - (COUPLER + ROCKER) ** 2) / (2 * CRANK * GROUND))


def toggle_four_bar(theta2: float) -> Mechanism:
    return Mechanism(
        (Link(1, (("O2", (0.0, 0.0)), ("O4", (float(GROUND), 0.0)))),
         Link(2, (("O2", (0.0, 0.0)), ("A", (float(CRANK), 0.0)))),
         Link(3, (("A", (0.0, 0.0)), ("B", (float(COUPLER), 0.0)))),
         Link(4, (("O4", (0.0, 0.0)), ("B", (ROCKER, 0.0))))),
        Drive(2, theta2, 1.0, 0.0), branches={"B": "left"}, units=Units("m"))


def exact_centres(theta2: float) -> dict[tuple[int, int], tuple]:
    """The six centres at the float ``theta2``, to 50 digits: the pins, and I13, I24 by
    Kennedy (O2A × O4B, AB × O2O4)."""
    mp.mp.dps = 50
    th = mp.mpf(theta2)
    o2, o4 = mp.matrix([0, 0]), mp.matrix([GROUND, 0])
    a = mp.matrix([CRANK * mp.cos(th), CRANK * mp.sin(th)])
    d = o4 - a
    dist = mp.norm(d)
    u = d / dist
    along = (dist ** 2 + COUPLER ** 2 - ROCKER ** 2) / (2 * dist)
    b = a + along * u + mp.sqrt(COUPLER ** 2 - along ** 2) * mp.matrix([-u[1], u[0]])  # left

    def meet(p, q, r, s):
        d1, d2 = q - p, s - r
        t = ((r[0] - p[0]) * d2[1] - (r[1] - p[1]) * d2[0]) / (d1[0] * d2[1] - d1[1] * d2[0])
        return p + t * d1

    return {(1, 2): o2, (2, 3): a, (3, 4): b, (1, 4): o4, (1, 3): meet(o2, a, o4, b),
            (2, 4): meet(a, b, o2, o4)}


@pytest.mark.parametrize("gap", [1e-3, 1e-6, 1e-9])
def test_reference_centres_near_the_toggle_are_as_sharp_as_the_position(gap):
    theta2 = float(TOGGLE) - gap
    kin = solve(toggle_four_bar(theta2))
    # The driven motion's own conditioning falls with the gap (about 2e-4·√(gap/1e-6)),
    # the free motion's does not: the free linkage is far from its own dead points.
    assert kin.conditioning < 1e-2
    assert kin.free.conditioning > 0.1
    size = mechanism_size(kin)
    for pair, exact in exact_centres(theta2).items():
        ref = instant_centre(kin, *pair)
        error = float(mp.norm(mp.matrix(ref.point) - exact)) / size
        # The float position itself is off by about eps/√(gap) (a circle cut near
        # tangency: B moves as √ of a change in |A − O4|): 2e-16/√1e-9 ≈ 7e-12. The centre
        # may be no worse than that, and its stated rounding must not be looser than
        # 1e-9 whatever the gap (the driven motion's was 4e-6 for I12 at 1e-9).
        assert error < 64 * 2.2e-16 / math.sqrt(gap), (pair, error)
        assert ref.rounding < 1e-9, (pair, ref.rounding)


def test_a_pin_keeps_its_reference_at_a_change_point():
    # O2O4 300, O2A 100, AB 200 + 1e-8, O4B 200 at θ2 = 180°: all four pins nearly in line,
    # so the linkage with its input let go is near its own dead point too, and neither
    # motion's fields give I34 (they gave it 3.3e-6 off). The pin B is I34 by definition.
    delta, size = 1e-8, 0.4
    mech = four_bar(math.pi, crank=0.1, coupler=0.2 + delta * 1e-3, rocker=0.2, omega2=1.0)
    kin = solve(mech)
    assert kin.free.conditioning < 1e-4          # the free motion is no help here
    mp.mp.dps = 50
    # B cut from circles about A = (−0.1, 0) and O4 = (0.3, 0), 0.4 apart, on the left of
    # A → O4 (y > 0): x from the radical line, y from Pythagoras.
    ab, o4b = mp.mpf(0.2 + delta * 1e-3), mp.mpf(0.2)
    x = (mp.mpf(0.4) ** 2 + ab ** 2 - o4b ** 2) / (2 * mp.mpf(0.4))
    exact = (x - mp.mpf(0.1), mp.sqrt(ab ** 2 - x ** 2))
    ref = instant_centre(kin, 3, 4, pin=shared_pin(mech, 3, 4))
    error = float(mp.sqrt((ref.point[0] - exact[0]) ** 2 + (ref.point[1] - exact[1]) ** 2)) / size
    # B itself is conditioned as √ of the arcs' overlap (1e-8 mm of 400 mm): its error may
    # reach about eps/√(2.5e-11) ≈ 4e-11 (it is 1.5e-17 here); the fields' was 3.3e-6.
    assert error < 64 * 2.2e-16 / math.sqrt(delta * 1e-3 / size)
    assert ref.rounding <= 4 * 2.3e-16
    assert shared_pin(mech, 1, 3) is None and shared_pin(mech, 2, 1) == "O2"
