"""An involute pair that cannot mesh is refused in one line; one that can prints no number
its formula contradicts.

The bounds come from the pair's circles (radii m·N/2; base r cos φ; addendum r + a·m; root
r − d·m): the base circles must stand apart (a line of action), each gear's tips must clear
the other's root circle (ra + rf ≤ C), and the line of action must run inside both addendum
circles for some length, √(ra₂² − rb₂²) + √(ra₃² − rb₃²) − C sin φ′ > 0 with
cos φ′ = (rb₂ + rb₃)/C, that is C < √((rb₂ + rb₃)² + (√(ra₂² − rb₂²) + √(ra₃² − rb₃²))²),
which is never beyond where the addendum circles stop touching, C = ra₂ + ra₃.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.catalog import bundled
from tarsim.exercises.gears.train_file import parse_train
from tarsim.exercises.gears.train_solution import solve_train

PAIR = Path(bundled("gears")["involute-pair"]).read_text(encoding="utf-8")
# module 10 mm, 20 and 40 teeth at 20°: base radii 93.97 and 187.94 mm, addendum radii 110
# and 210, root radii 87.5 and 187.5


def refusal(text: str) -> str:
    with pytest.raises(InputError) as e:
        solve_train(parse_train(text, "pair.toml"))
    message = str(e.value)
    assert "\n" not in message and message.startswith("pair.toml:")
    return message


def at(distance: float) -> str:
    return PAIR.replace("pressure_angle = 20", f"pressure_angle = 20\ncentre_distance = "
                        f"{distance}", 1)


def test_gears_pulled_apart_do_not_touch():
    assert refusal(at(330)).endswith(
        "gears 2 and 3 do not touch: the centre distance is 330 mm, and their addendum "
        "circles reach only 320 mm; the pitch circles need 300 mm")


def test_addendum_circles_that_overlap_off_the_line_of_action_never_touch():
    """Between 319.74 and 320 mm the addendum circles still overlap, but the line of action
    runs inside both for no length: its path of contact would be negative."""
    phi = math.radians(20)
    rb = (100 * math.cos(phi), 200 * math.cos(phi))
    reach = math.sqrt(110**2 - rb[0] ** 2) + math.sqrt(210**2 - rb[1] ** 2)
    widest = math.hypot(sum(rb), reach)
    assert 319.7 < widest < 319.8
    assert refusal(at(319.9)).endswith(
        "gears 2 and 3 overlap only off the line of action: at a centre distance of 319.9 mm "
        f"their teeth never touch; it must stay below {widest:.6g} mm; the pitch circles need "
        "300 mm")


def test_tips_that_strike_the_other_gears_root_jam():
    # ra2 + rf3 = 110 + 187.5 = 297.5 mm (and ra3 + rf2 = 210 + 87.5, the same)
    assert refusal(at(295)).endswith(
        "gears 2 and 3 jam: at a centre distance of 295 mm the tips of gear 2 strike the root "
        "circle of gear 3, which needs 297.5 mm; the pitch circles need 300 mm")
    s = solve_train(parse_train(at(297.5), "pair.toml"))     # the tips just clear the root
    assert s.passed and s.quantities["contact_ratio"].si > 0


def test_a_gear_of_too_few_teeth_has_no_root_circle():
    # 2 teeth of module 10: a pitch radius of 10 mm, a dedendum of 12.5 mm
    assert refusal(PAIR.replace("teeth = 20", "teeth = 2", 1)).endswith(
        "gear 2 has too few teeth for its dedendum: its pitch radius 10 mm is no more than "
        "the dedendum 12.5 mm")


@settings(max_examples=200, deadline=None)
@given(z1=st.integers(6, 60), more=st.integers(0, 90), angle=st.sampled_from((14.5, 20, 25)),
       form=st.sampled_from(((1.0, 1.25), (0.8, 1.0), (1.0, 1.157), (1.25, 1.5))),
       where=st.floats(-0.3, 1.3))
# 6 teeth against 59 at 14.5°, pulled out: contact begins past P, on T3's side, and once
# read as the wheel's tips reaching past T2
@example(z1=6, more=53, angle=14.5, form=(1.0, 1.25), where=0.9375)
def test_a_pair_meshes_as_its_formulas_say_or_is_refused(z1, more, angle, form, where):
    """Centre distances across the feasible range and beyond it: inside, the drawn path and
    arc of contact and the contact ratio are positive and the formulas' (to a few roundings
    of the drawing's size); outside, one line refuses the pair."""
    z2, m = z1 + more, 4.0
    add, ded = form
    phi = math.radians(angle)
    r = (m * z1 / 2, m * z2 / 2)
    rb = tuple(x * math.cos(phi) for x in r)
    ra = tuple(x + add * m for x in r)
    rf = tuple(x - ded * m for x in r)
    reach = sum(math.sqrt(a * a - b * b) for a, b in zip(ra, rb))
    low = max(sum(rb), ra[0] + rf[1], ra[1] + rf[0])
    high = math.hypot(sum(rb), reach)
    c = low + where * (high - low)
    text = (PAIR.replace("teeth = 20", f"teeth = {z1}", 1)
            .replace("teeth = 40", f"teeth = {z2}", 1).replace("module = 10", "module = 4")
            .replace("pressure_angle = 20", f"pressure_angle = {angle}\naddendum = {add}\n"
                     f"dedendum = {ded}\ncentre_distance = {c!r}", 1)
            .replace('"least_teeth"', '"omega3"'))
    edge = 1e-9 * high                       # the feasible range's ends, to rounding
    if min(rf) <= 0 or c <= low - edge or c >= high + edge:
        assert "gear" in refusal(text)
        return
    if c <= low + edge or c >= high - edge:
        return                               # on an end: either verdict is a rounding
    s = solve_train(parse_train(text, "pair.toml"))
    q = s.quantities
    assert s.passed, s.failures
    assert s.mesh.interference == s.mesh_reference.interference
    working = math.acos(sum(rb) / c)
    path = reach - c * math.sin(working)
    assert path > 0
    for name, want in (("path_of_contact", path * 1e-3), ("arc_of_contact",
                                                         path / math.cos(working) * 1e-3),
                       ("contact_ratio", path / (math.pi * m * math.cos(phi)))):
        # drawn lengths: a few roundings of the drawing's size (the centre distance)
        assert q[name].si > 0
        assert abs(q[name].si - want) <= 1e-9 * c * 1e-3 / min(1.0, path * 1e-3) * want \
            or abs(q[name].si - want) <= 1e-9 * abs(want), name
