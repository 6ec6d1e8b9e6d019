"""Cam follower motion: the displacement diagram drawn by construction against the closed-form
laws, and the laws themselves against their own derivatives and the notes' chain rule."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.cams.displacement import Segment, draw_displacement
from tarsim.constructions.errors import InputError
from tarsim.constructions.reference.cam_laws import LAWS, motion, peaks, time_rates

CURVED = ("simple harmonic", "parabolic", "cycloidal", "uniform velocity")


@pytest.mark.parametrize("law", CURVED)
@pytest.mark.parametrize("kind", ["rise", "return"])
@pytest.mark.parametrize("divisions", [4, 6, 8])
def test_every_constructed_point_lies_on_its_law(law, kind, divisions):
    """A rise of 40 mm over 120° (a return starting from the top): each point the
    construction finds where its ordinate meets the semicircle's, the divided ordinate's or
    the circle's projection stands at the law's lift, to a few roundings of 40 mm."""
    lift, beta = 0.040, math.radians(120)
    before = [Segment("rise", math.radians(40), lift, "uniform velocity", 2)] \
        if kind == "return" else []
    d = draw_displacement([*before, Segment(kind, beta, lift, law, divisions)], per_rad=0.05)
    start, curve = d.starts[-1], d.curves[-1]
    assert len(curve) == divisions + 1
    for i, (_, ref) in enumerate(curve):
        theta, y = d.point(ref)
        assert theta - start == pytest.approx(i * beta / divisions, abs=1e-15)
        want = motion(law, lift, beta, theta - start, rise=kind == "rise").y
        assert abs(y - want) <= 4e-16 * 8, (i, y, want)


@pytest.mark.parametrize("kind", ["rise", "return"])
@pytest.mark.parametrize("divisions, blend", [(4, 0.25), (8, 0.25), (12, 0.25), (6, 1 / 3),
                                              (6, 1 / 6), (4, 0.5)])
def test_the_modified_uniform_velocity_is_drawn_on_its_law(kind, divisions, blend):
    """Parabolas over the blended divisions at each end, the straight run between: each
    point on y = Vθ²/2bβ, straight, h − V(β − θ)²/2bβ, V = h/(1 − b)β. A blend of ½ is the
    parabolic law itself."""
    lift, beta = 0.040, math.radians(120)
    before = [Segment("rise", math.radians(40), lift, "uniform velocity", 2)] \
        if kind == "return" else []
    seg = Segment(kind, beta, lift, "modified uniform velocity", divisions, blend)
    d = draw_displacement([*before, seg], per_rad=0.05)
    start, curve = d.starts[-1], d.curves[-1]
    assert len(curve) == divisions + 1
    for i, (_, ref) in enumerate(curve):
        theta, y = d.point(ref)
        assert theta - start == pytest.approx(i * beta / divisions, abs=1e-15)
        want = motion(seg.law, lift, beta, theta - start, rise=kind == "rise", blend=blend)
        assert abs(y - want.y) <= 4e-16 * 8, (i, y, want.y)
        if blend == 0.5:
            assert want.y == pytest.approx(motion("parabolic", lift, beta, theta - start,
                                                  rise=kind == "rise").y, abs=1e-17)


def test_a_blend_off_the_divisions_is_refused():
    with pytest.raises(InputError, match="whole number of its 6 divisions"):
        draw_displacement([Segment("rise", 1.0, 0.01, "modified uniform velocity", 6, 0.25)],
                          per_rad=0.05)


def test_a_parabolic_segment_needs_an_even_division():
    with pytest.raises(InputError, match="even number of parts"):
        draw_displacement([Segment("rise", 1.0, 0.01, "parabolic", 5)], per_rad=0.05)


def test_a_law_the_diagram_cannot_draw_is_named():
    with pytest.raises(InputError, match="not 'spline'"):
        draw_displacement([Segment("rise", 1.0, 0.01, "spline", 4)], per_rad=0.05)


@settings(max_examples=80, deadline=None)
@given(law=st.sampled_from(LAWS), lift=st.floats(1e-3, 0.2), beta=st.floats(0.3, 3.0),
       u=st.floats(0.02, 0.98), rise=st.booleans())
def test_each_coefficient_is_the_derivative_of_the_one_before(law, lift, beta, u, rise):
    theta, dt = u * beta, 1e-6 * beta
    if law == "parabolic" and abs(u - 0.5) < 0.01:
        u = 0.4                                   # y″ jumps at the half: not across it
        theta = u * beta
    if law == "modified uniform velocity" and min(abs(u - 0.25), abs(u - 0.75)) < 0.01:
        u = 0.5                                   # y″ jumps where the blends end
        theta = u * beta
    m = motion(law, lift, beta, theta, rise=rise)
    a = motion(law, lift, beta, theta - dt, rise=rise)
    b = motion(law, lift, beta, theta + dt, rise=rise)
    scale = (lift, lift / beta, lift / beta ** 2, lift / beta ** 3)
    for low, high, got, s in ((a.y, b.y, m.y1, scale[1]), (a.y1, b.y1, m.y2, scale[2]),
                              (a.y2, b.y2, m.y3, scale[3])):
        assert (high - low) / (2 * dt) == pytest.approx(got, abs=1e-5 * s)


@pytest.mark.parametrize("law", LAWS)
def test_the_textbook_peaks_are_the_laws_own(law):
    lift, beta = 0.03, math.radians(100)
    v, a = peaks(law, lift, beta)
    samples = [motion(law, lift, beta, beta * i / 4000) for i in range(4001)]
    assert max(abs(m.y1) for m in samples) == pytest.approx(v, rel=1e-6)
    if math.isfinite(a):
        assert max(abs(m.y2) for m in samples) == pytest.approx(a, rel=1e-6)
    ends = samples[0], samples[-1]
    assert (ends[0].y, ends[1].y) == (0.0, pytest.approx(lift, rel=1e-15))


def test_the_chain_rule_gives_jerk_with_alpha_dot_not_alpha_squared():
    """y(θ(t)) with θ = θ0 + ωt + αt²/2 + α̇t³/6, differentiated in time numerically: the jerk
    is y‴ω³ + 3y″ωα + y′α̇, and the notes' printed y′α² misses it."""
    law, lift, beta = "cycloidal", 0.02, 1.5
    w, al, ad, t0 = 3.0, 2.0, -30.0, 0.2

    def y(t):
        theta = t0 + w * t + al * t * t / 2 + ad * t ** 3 / 6
        return motion(law, lift, beta, theta).y
    h, k = 1e-5, 1e-4            # steps the truncation and the rounding both stay small at
    jerk = (y(2 * k) - 2 * y(k) + 2 * y(-k) - y(-2 * k)) / (2 * k ** 3)
    v, a, j = time_rates(motion(law, lift, beta, t0), w, al, ad)
    assert v == pytest.approx((y(h) - y(-h)) / (2 * h), rel=1e-7)
    assert a == pytest.approx((y(h) - 2 * y(0) + y(-h)) / h ** 2, rel=1e-5)
    assert j == pytest.approx(jerk, rel=1e-5)
    m = motion(law, lift, beta, t0)
    printed = m.y3 * w ** 3 + 3 * m.y2 * w * al + m.y1 * al ** 2
    assert abs(printed - jerk) > 1e-2 * abs(jerk)
