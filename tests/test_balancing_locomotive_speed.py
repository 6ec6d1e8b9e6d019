"""A locomotive with no running speed, as the books pose it: the speed is the unknown.

The balance masses are m·r products, free of ω; the lift speed follows from them and the
dead load P on a wheel, ω = √(P/(B·b)) with B·b the balanced reciprocating part's share of
the heavier wheel's product (B the mass at the balance radius b); and every m·r·ω²
quantity (hammer blow, variation of tractive force, swaying couple) is then given at that
speed, as the books ask "the swaying couple at the speed found". With no dead load there
is no speed at all: the masses alone are given, and nothing in N.

Every closed form here is a handful of products and one square root of numbers of order
0.1–1000, and the polygons lay off the same few vectors: they agree to a few roundings,
1e-12 relative (an angle 1e-9°).
"""

from __future__ import annotations

import cmath
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.constructions.narration import speaking
from tarsim.exercises.balancing.balance_solution import solve_balance
from tarsim.exercises.balancing.rotor_file import parse_balance
from tarsim.exercises.catalog import bundled

HERE = Path(__file__).parent / "reproducers"
REL = 1e-12
"""Relative agreement of a few sums and a square root with their hand values (see above)."""


def _hand(rev, m, r, c, z1, z2, za, zb, b):
    """The two-plane balance of two cylinders at 0° and 90° by hand: each cylinder's
    m_rev + c·m at r, couples about wheel A then forces; each wheel's mass (kg) at b and
    angle (°), and B·b, c·m's share of the product in the wheels (the same in both, the
    cylinders' arms being |(l₁, l₂)| from either wheel in this symmetric layout)."""
    each = (rev + c * m) * r
    span = zb - za
    in_b = -each * ((z1 - za) + 1j * (z2 - za)) / span
    in_a = -each * (1 + 1j) - in_b
    share = c * m * r * math.hypot(z1 - za, z2 - za) / span
    return [(abs(v) / b, math.degrees(cmath.phase(v)) % 360) for v in (in_a, in_b)], share


def _solve(path_or_text, name="l.toml"):
    text = path_or_text.read_text(encoding="utf-8") if isinstance(path_or_text, Path) \
        else path_or_text
    s = solve_balance(parse_balance(text, name))
    assert s.passed, s.failures
    return s


def test_b2_outside_locomotive():
    """The outside-cylinder locomotive of the books with no speed: 360 kg rotating and
    300 kg reciprocating, r = 0.3 m, cylinders 1.75 m and wheels 1.45 m apart, ⅔
    balanced at 0.75 m, 30 kN a wheel on 1.8 m treads. By hand: 248.256 kg at 174.64° and
    275.36°, the wheels lift at 21.2402 rad/s (68.8183 km/h), and there the swaying
    couple (1 − c)·m·ω²·r·a/√2 is 16 748 N·m."""
    s = _solve(HERE / "b2-outside-locomotive.toml")
    q = s.results["quantities"]
    masses, share = _hand(360, 300, 0.3, 2 / 3, 0, 1.75, 0.15, 1.6, 0.75)
    for plane, (mass, angle) in zip("AB", masses):
        assert q[f"mass_{plane}"]["value"] == pytest.approx(mass, rel=REL)
        assert q[f"angle_{plane}"]["value"] == pytest.approx(angle, abs=1e-9)
    w = math.sqrt(30000 / share)
    assert q["lift_speed"]["value"] == pytest.approx(w, rel=REL)
    assert q["lift_road_speed"]["value"] == pytest.approx(w * 0.9 * 3.6, rel=REL)
    sway = (1 - 2 / 3) * 300 * w ** 2 * 0.3 * 1.75 / math.sqrt(2)
    assert q["primary_couple_left"]["value"] == pytest.approx(sway, rel=REL)
    assert round(q["primary_couple_left"]["value"]) == 16748
    assert q["primary_force_left"]["value"] == pytest.approx(
        math.sqrt(2) * (1 - 2 / 3) * 300 * w ** 2 * 0.3, rel=REL)
    # each force and couple says it is at the lift speed, and the lines say so first
    for name in ("primary_couple_left", "primary_force", "hammer_blow_A"):
        assert q[name]["at_lift_speed"] == pytest.approx(w, rel=REL)
    assert "mass_A" in q and "at_lift_speed" not in q["mass_A"]
    first = s.lines()[0]
    assert first.startswith("no speed is given: every force and couple below is at the lift "
                            "speed found, ω = 21.2402 rad/s, 68.8183 km/h"), first
    # the hammer blow at the lift speed is the dead load, in the heavier wheel
    assert max(q["hammer_blow_A"]["value"], q["hammer_blow_B"]["value"]) == pytest.approx(
        30000, rel=REL)


def test_b2c_lift_speed():
    """The lift speed typed back in as road_speed (68.81829854 km/h, ten figures) gives the
    swaying couple the file with no speed gives at it: ω² agrees to the typed figures,
    some 1e-10, so 1e-8 relative."""
    typed = _solve(HERE / "b2c-lift-speed.toml").results["quantities"]
    found = _solve(HERE / "b2-outside-locomotive.toml").results["quantities"]
    assert typed["primary_couple_left"]["value"] == pytest.approx(
        found["primary_couple_left"]["value"], rel=1e-8)
    assert "at_lift_speed" not in typed["primary_couple_left"]


def test_b2d_no_wheel():
    """A dead load with no wheel diameter: the lift speed in rad/s alone, and the forces
    at it; no km/h anywhere."""
    s = _solve(HERE / "b2d-no-wheel.toml")
    q = s.results["quantities"]
    _, share = _hand(360, 300, 0.3, 2 / 3, 0, 1.75, 0.15, 1.6, 0.75)
    assert q["lift_speed"]["value"] == pytest.approx(math.sqrt(30000 / share), rel=REL)
    assert "lift_road_speed" not in q
    assert "km/h" not in "\n".join(s.lines())


def test_the_bundled_outside_locomotive_finds_its_speed():
    """outside-locomotive: 250 kg rotating and 280 kg reciprocating, r = 0.3 m, cylinders
    1.8 m and wheels 1.5 m apart, ⅔ balanced at 0.7 m, 35 kN a wheel on 1.9 m treads, no
    speed. By hand: 206.706 kg at 174.81° and 275.19°, B·b = 61.854 kg·m, the wheels lift
    at 23.7876 rad/s (81.35 km/h), the swaying couple there ±20 165.8 N·m."""
    s = _solve(Path(bundled("balancing")["outside-locomotive"]))
    q = s.results["quantities"]
    masses, share = _hand(250, 280, 0.3, 2 / 3, 0, 1.8, 0.15, 1.65, 0.7)
    for plane, (mass, angle) in zip("AB", masses):
        assert q[f"mass_{plane}"]["value"] == pytest.approx(mass, rel=REL)
        assert q[f"angle_{plane}"]["value"] == pytest.approx(angle, abs=1e-9)
    assert round(q["mass_A"]["value"], 3) == 206.706
    w = math.sqrt(35000 / share)
    assert q["lift_speed"]["value"] == pytest.approx(w, rel=REL)
    assert round(q["lift_road_speed"]["value"], 2) == 81.35
    sway = (1 / 3) * 280 * w ** 2 * 0.3 * 1.8 / math.sqrt(2)
    assert q["primary_couple_left"]["value"] == pytest.approx(sway, rel=REL)
    assert round(q["primary_couple_left"]["value"], 1) == 20165.8
    # and the independent reference agrees with what was drawn
    for name in ("lift_speed", "primary_couple_left", "mass_A"):
        assert q[name]["value"] == pytest.approx(q[name]["reference"]["value"], rel=REL)


def _no_load() -> str:
    return (HERE / "b2d-no-wheel.toml").read_text(encoding="utf-8").replace(
        "dead_load = 30000          # N on each driving wheel\n", "")


def test_no_speed_and_no_dead_load_gives_the_masses_and_nothing_in_newtons():
    """With nothing to find a speed by, the masses alone are given (the same as at any
    speed, to the last bit: m·r is free of ω), the forces are left out of results.json,
    and the lines say so, in English and Persian."""
    text = _no_load()
    assert "dead_load" not in text
    s = _solve(text)
    q = s.results["quantities"]
    at_speed = _solve(text.replace("[engine]\n", "[engine]\nspeed = 25\n")).results[
        "quantities"]
    for name in ("mass_A", "mass_B", "angle_A", "angle_B"):
        assert q[name]["value"] == at_speed[name]["value"]
    assert not [k for k, c in q.items() if c.get("unit") in ("N", "N·m")], q.keys()
    assert "primary_force" not in q and "primary_force_at" in q
    assert "primary_couple_left" in at_speed
    lines = s.lines()
    assert lines[0].startswith("no speed is given: the balance masses need none"), lines[0]
    assert any("the swaying couple and the hammer blow (each m·r·ω²) are left out" in line
               for line in lines)
    with speaking("fa"):
        farsi = s.lines()
    assert farsi[0].startswith("سرعتی داده نشده است"), farsi[0]


def test_forces_at_a_crank_angle_with_no_speed_are_refused_naming_the_speed():
    """``at`` asks forces at a crank angle by name, m·r·ω²: with no speed and no dead load
    to find one, one line at the ``at`` says to give speed or road_speed."""
    text = _no_load().replace("balanced = \"2/3\"\n", "balanced = \"2/3\"\nat = 30\n")
    with pytest.raises(InputError) as e:
        parse_balance(text, "a.toml")
    message = str(e.value)
    assert "\n" not in message and message.startswith("a.toml:") and \
        "give speed = … or road_speed = …" in message, message


@pytest.mark.parametrize("remove", ["wheel_diameter = 1800\n", ""])
def test_the_old_wrong_speed_messages_are_gone(remove):
    """Giving neither speed nor road_speed once drew "… not both", or "[engine] needs
    speed", on a locomotive that needs none. Now it solves; and an engine whose every
    answer is a force (no balance planes) says to give speed or road_speed, never "not
    both"."""
    text = (HERE / "b2-outside-locomotive.toml").read_text(encoding="utf-8").replace(remove, "")
    assert "speed" not in text.split("[engine]")[1].split("[[")[0].replace("road_speed", "")
    _solve(text)
    bare = text.split("[[balance]]")[0].replace("dead_load = 30000          # N on each "
                                                "driving wheel\n", "").replace(
        "balanced = \"2/3\"\n", "").replace("revolving = 360\n", "")
    with pytest.raises(InputError) as e:
        parse_balance(bare, "b.toml")
    message = str(e.value)
    assert "not both" not in message and "needs speed = …" in message and \
        "or road_speed = … (km/h) with wheel_diameter" in message, message


@pytest.mark.parametrize("units, line", [
    ("", "ω = 20 rad/s (read as rad/s; write [units] speed = \"rpm\" for rpm)"),
    ("[units]\nspeed = \"rpm\"\n", None),
])
def test_an_engine_speed_without_its_unit_says_it_was_read_as_rad_per_s(units, line):
    """speed = 20 with no [units] speed is 20 rad/s (the default, unchanged), and the first
    line says so; with speed = "rpm" it is 20·2π/60 rad/s and no such line is written."""
    text = units + ("[engine]\nspeed = 20\ncrank = 0.3\nreciprocating = 30\n[[cylinder]]\n"
                    "crank = 0\nplane = 0\n[[cylinder]]\ncrank = 90\nplane = 1\n")
    s = _solve(text, "u.toml")
    assert s.exercise.engine.speed == pytest.approx(20 if line else 20 * math.pi / 30,
                                                    rel=1e-15)
    first = s.lines()[0]
    assert (first == line) if line else not first.startswith("ω ="), first


@settings(max_examples=25, deadline=None)
@given(load=st.floats(1e3, 1e6), c=st.sampled_from([0.5, 2 / 3, 0.75, 1.0]))
def test_the_hammer_blow_at_the_lift_speed_is_the_dead_load(load, c):
    """Whatever the load and fraction balanced, the speed found makes the greater hammer
    blow B·ω²·b equal the dead load: that is its definition, P = B·b·ω²."""
    text = (HERE / "b2-outside-locomotive.toml").read_text(encoding="utf-8").replace(
        "dead_load = 30000", f"dead_load = {load!r}").replace('balanced = "2/3"',
                                                               f"balanced = {c!r}")
    q = _solve(text).results["quantities"]
    _, share = _hand(360, 300, 0.3, c, 0, 1.75, 0.15, 1.6, 0.75)
    assert q["lift_speed"]["value"] == pytest.approx(math.sqrt(load / share), rel=REL)
    assert max(q["hammer_blow_A"]["value"], q["hammer_blow_B"]["value"]) == pytest.approx(
        load, rel=REL)
