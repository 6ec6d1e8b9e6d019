"""An engine's loads and answers as the books give and ask them: a double-acting piston's
back pressure on the annulus its rod leaves, and the thrust on the shaft's bearings, each
against the textbook's closed form."""

from __future__ import annotations

import json
import math

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

import tarsim
from tarsim.constructions.errors import InputError, TarsimError
from tarsim.exercises.catalog import resolve
from tarsim.exercises.chapters import read_file
from tarsim.exercises.cli import cli
from tarsim.exercises.linkages.exercise_file import parse_exercise

R, L, BORE, MASS = 0.06, 0.27, 0.1, 1.2
OMEGA = 1800 * math.pi / 30
ROD_MASS = ("[[mass]]\nlink = 3\nmass = 2.0\ncentre = [100, 0]           # from the crank pin A "
            "toward P\nradius_of_gyration = 110    # I = m·k²\n")
BACK = ('name = "gas force"\n', 'name = "gas force"\n[[force]]\nlink = 4\npoint = "P"\n'
        'pressure = "-0.1 N/mm²"\nbore = 100\nrod = 30\nname = "back pressure"\n')


def _toward_crank(theta: float) -> float:
    """The piston's exact acceleration toward the crank at steady ω: x = r cos θ + S,
    S = √(l² − r² sin²θ), −ẍ = ω²(r cos θ + r² cos 2θ/S + r⁴ sin²θ cos²θ/S³)."""
    s = math.sqrt(L * L - (R * math.sin(theta)) ** 2)
    return OMEGA ** 2 * (R * math.cos(theta) + R * R * math.cos(2 * theta) / s
                         + R ** 4 * (math.sin(theta) * math.cos(theta)) ** 2 / s ** 3)


def _text(deg: float = 20, **changes: str) -> str:
    text = resolve("engine-gas-pressure").read_text(encoding="utf-8")
    text = text.replace("angle = 20                  #", f"angle = {deg!r}                  #")
    text = text.replace('find = ["T2", ', 'find = ["T2", "bearing_thrust", "F_23", ')
    for old, new in changes.items():
        assert old in text, old
        text = text.replace(old, new)
    return text


def _answers(text: str) -> dict[str, float]:
    worked = tarsim.solve(parse_exercise(text, "engine.toml"))
    assert worked.passed
    (sol,) = worked.positions
    return {name: q.value["value"] for name, q in sol.quantities.items()}


def test_a_double_acting_piston_s_rod_takes_its_area_off_the_crank_side():
    """650 kN/m² on the 100 mm bore toward the crank, 0.1 N/mm² back on the crank side
    round a 30 mm rod: F_L = p1·πD²/4 − p2·π(D² − d²)/4, less the reciprocating parts' m·a."""
    got = _answers(_text(**{BACK[0]: BACK[1]}))
    load = 650e3 * math.pi * BORE ** 2 / 4 - 0.1e6 * math.pi * (BORE ** 2 - 0.03 ** 2) / 4
    # the polygons and the Newton–Euler reference agree with it to rounding
    assert got["piston_effort"] == pytest.approx(load - MASS * _toward_crank(math.radians(20)),
                                                 rel=1e-12)


@settings(max_examples=12, deadline=None)
@given(deg=st.floats(5, 355).filter(lambda d: abs(d - 180) > 5))
def test_the_bearings_thrust_is_the_rod_s_push_along_the_crank(deg):
    """A massless rod pushes along itself, F_Q = F_P/cos φ: along the crank toward the shaft
    that is F_B = F_Q cos(θ + φ), sin φ = r sin θ/l (negative where it pulls), and square to
    it the crank effort F_Q sin(θ + φ); together they make the rod's whole push."""
    theta = math.radians(deg)
    got = _answers(_text(deg, **{ROD_MASS: ""}))
    effort = 650e3 * math.pi * BORE ** 2 / 4 - MASS * _toward_crank(theta)
    phi = math.asin(R * math.sin(theta) / L)
    # the crank's angle keeps a few roundings of θ, whose 1e-15 its cosine may magnify by
    # tan(θ + φ) where it nears zero: rel 1e-10 leaves room for that at 5° from the quarter
    assert got["bearing_thrust"] == pytest.approx(effort * math.cos(theta + phi) / math.cos(phi),
                                                  rel=1e-10, abs=1e-9 * abs(effort))
    assert math.hypot(got["bearing_thrust"], got["crank_effort"]) == pytest.approx(
        got["F_23"], rel=1e-12)


def test_the_bearings_thrust_is_drawn_and_said(tmp_path):
    """The radial part F_R is read off the force polygon and said in steps.md, in English
    and in Persian."""
    path = tmp_path / "e.toml"
    path.write_text(_text(), encoding="utf-8")
    for lang, word in (("en", "thrust on the shaft's bearings"), ("fa", "یاتاقان")):
        out = tmp_path / lang
        result = CliRunner().invoke(cli, ["solve", str(path), "--no-pdf", "--lang", lang, "-o",
                                          str(out)])
        assert result.exit_code == 0, result.output
        assert word in (out / "steps.md").read_text(encoding="utf-8")
        q = json.loads((out / "results.json").read_text(encoding="utf-8"))
        assert "bearing_thrust" in q["positions"][0]["quantities"]


@pytest.mark.parametrize("change, key, words", [
    ({"bore = 100\n": "bore = 100\nrod = 100\n"}, "rod", "less than the bore's"),
    ({"bore = 100\n": "area = 7854\nrod = 20\n"}, "rod", "taken off the bore"),
    ({'pressure = "650 kPa"        # on the bore: p·π·d²/4 toward the crank\nbore = 100\n':
      "force = [-100, 0]\nrod = 20\n"}, "rod", "for a gas pressure"),
])
def test_a_bad_piston_rod_is_refused_at_its_line(change, key, words, tmp_path):
    text = _text(**change)
    line = next(i for i, s in enumerate(text.splitlines(), 1) if s.startswith(f"{key} ="))
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(InputError) as e:
        read_file(path, "bad")
    message = str(e.value)
    assert message.startswith(f"{path}:{line}: ") and words in message, message
    assert "\n" not in message


def test_double_acting_engine():
    """The bundled double-acting engine: 0.55 N/mm² on the 300 mm bore, 0.1 N/mm² back round
    the 50 mm piston rod, 180 kg at 150 rpm, crank 225 mm, rod 1125 mm, 60° from the inner
    dead centre; the rod's mass neglected, so the textbook's chain holds exactly:
    F_P = F_L − m·a, F_T = F_P sin(θ + φ)/cos φ, F_B = F_P cos(θ + φ)/cos φ."""
    from tarsim.exercises.catalog import load

    worked = tarsim.solve(load("double-acting-engine"))
    assert worked.passed
    (sol,) = worked.positions
    got = {name: q.value["value"] for name, q in sol.quantities.items()}
    r, rod, theta, omega = 0.225, 1.125, math.radians(60), 150 * math.pi / 30
    s = math.sqrt(rod * rod - (r * math.sin(theta)) ** 2)
    a = omega ** 2 * (r * math.cos(theta) + r * r * math.cos(2 * theta) / s
                      + r ** 4 * (math.sin(theta) * math.cos(theta)) ** 2 / s ** 3)
    f_p = 0.55e6 * math.pi * 0.3 ** 2 / 4 - 0.1e6 * math.pi * (0.3 ** 2 - 0.05 ** 2) / 4 - 180 * a
    phi = math.asin(r * math.sin(theta) / rod)
    assert got["piston_effort"] == pytest.approx(f_p, rel=1e-12)
    assert got["crank_effort"] == pytest.approx(f_p * math.sin(theta + phi) / math.cos(phi),
                                                rel=1e-12)
    assert got["bearing_thrust"] == pytest.approx(f_p * math.cos(theta + phi) / math.cos(phi),
                                                  rel=1e-12)
    assert got["turning_moment"] == pytest.approx(r * got["crank_effort"], rel=1e-12)


@settings(max_examples=12, deadline=None)
@given(deg=st.floats(5, 355).filter(lambda d: abs(d - 180) > 5))
def test_the_rod_s_correction_couple_is_the_books(deg):
    """engine-gas-pressure's rod, 2 kg, G 100 mm from the crank pin of a 270 mm rod, k =
    110 mm: its two masses at the pins have I = m·GA·GP about G, so the correction couple
    is (m·GA·GP − m·k²)·α_rod, α_rod = ω²·r sin θ (l² − r²)/S³ exactly (CCW +, the crank
    turning CCW), S = √(l² − r² sin²θ)."""
    theta = math.radians(deg)
    got = _answers(_text(deg))                # the bundled file asks correction_couple
    s = math.sqrt(L * L - (R * math.sin(theta)) ** 2)
    alpha = OMEGA ** 2 * R * math.sin(theta) * (L * L - R * R) / s ** 3
    # the rod's α off the acceleration polygon carries a few roundings of its size
    assert got["correction_couple"] == pytest.approx(
        (2.0 * 0.1 * 0.17 - 2.0 * 0.11 ** 2) * alpha, rel=1e-9)


def test_a_massless_rod_needs_no_correction_couple():
    got = _answers(_text(**{ROD_MASS: ""}))
    assert got["correction_couple"] == 0.0


@settings(max_examples=12, deadline=None)
@given(deg=st.floats(5, 355).filter(lambda d: abs(d - 180) > 5))
def test_the_reciprocating_parts_inertia_force_is_the_books(deg):
    """F_I = m·a toward the crank, a = ω²(r cos θ + r² cos 2θ/S + r⁴ sin²θ cos²θ/S³) exactly
    (the books' ω²r(cos θ + cos 2θ/n) to first order), and the piston effort is the gas
    force less it: F_P = F_L − F_I."""
    theta = math.radians(deg)
    got = _answers(_text(deg).replace('find = ["T2", ', 'find = ["inertia_force", "T2", '))
    # a passes through 0 near the quarter: there it is held to the rounding of m·ω²·r
    assert got["inertia_force"] == pytest.approx(MASS * _toward_crank(theta), rel=1e-12,
                                                 abs=1e-12 * MASS * OMEGA ** 2 * R)
    assert got["piston_effort"] == pytest.approx(
        650e3 * math.pi * BORE ** 2 / 4 - got["inertia_force"], rel=1e-12)


@settings(max_examples=10, deadline=None)
@given(deg=st.floats(5, 60))
def test_the_speed_that_reverses_the_gudgeon_pin_s_load(deg):
    """Near the inner dead centre the piston's inertia pulls against the gas: the effort
    F_L − m·ω²·c (a = ω²·c toward the crank, c = r cos θ + r² cos 2θ/S + r⁴ sin²θ cos²θ/S³)
    falls to zero at ω_r = √(F_L/(m·c)), the books' speed above which the load reverses."""
    theta = math.radians(deg)
    got = _answers(_text(deg).replace('find = ["T2", ', 'find = ["reversal_speed", "T2", '))
    c = _toward_crank(theta) / OMEGA ** 2
    assert got["reversal_speed"] == pytest.approx(
        math.sqrt(650e3 * math.pi * BORE ** 2 / 4 / (MASS * c)), rel=1e-12)


def test_no_speed_reverses_a_load_its_inertia_adds_to():
    """At 120° the piston speeds away from the crank: its inertia pushes with the gas, and
    the ask is refused in one line saying so."""
    with pytest.raises(TarsimError) as e:
        _answers(_text(120).replace('find = ["T2", ', 'find = ["reversal_speed", "T2", '))
    assert "θ2 = 120°" in str(e.value) and "no speed reverses" in str(e.value)
    assert "\n" not in str(e.value)


def _engine(slider: str, assembly: str, crank: str) -> str:
    """The bundled horizontal engine with its line of stroke, its piston's side and its
    [input] crank angle changed."""
    return _text(**{"angle = 0\n[input]": f"{slider}\n[input]",
                    'P = "forward"': f"P = {assembly}",
                    "angle = 20                  # past the inner dead centre (the crank toward "
                    "the piston)\nomega = 188.49555921538757": crank})


@pytest.mark.parametrize("slider, assembly, crank, degrees", [
    # the books' vertical engines: the piston above, the crank 40° past the t.d.c. (90°)
    ("angle = 90", '"forward"', 'angle = 40\nfrom = "t.d.c."\nomega = -300', 90 - 40),
    ("angle = 90", '"forward"', 'angle = 40\nfrom = "top dead centre"\nomega = 300', 90 + 40),
    ("angle = 90", '"forward"', 'angle = 20\nfrom = "b.d.c."\nomega = -300', 270 - 20),
    # a horizontal engine whose piston lies to the left of the shaft (−x): the i.d.c. is 180°
    ("angle = 0", '"backward"', 'angle = 30\nfrom = "i.d.c."\nomega = 300', 180 + 30),
    ("angle = 0", "[-300, 0]", 'angle = 30\nfrom = "idc"\nomega = 300', 180 + 30),
    # the line given pointing down at a piston above: the piston's side, not the line's sense
    ("angle = -90", '"backward"', 'angle = 40\nfrom = "t.d.c."\nomega = -300', 90 - 40),
])
def test_a_crank_angle_from_a_dead_centre(slider, assembly, crank, degrees):
    """The books' crank angle "θ from the t.d.c. (i.d.c.)", turned the way ω turns from the
    crank lying along the line of stroke toward the piston, is θ2 from +x; and the piston's
    speed there is the in-line slider-crank's ω·r·|sin θ + r sin 2θ/(2S)|, θ from the
    dead centre (S = √(l² − r² sin²θ))."""
    ex = parse_exercise(_engine(slider, assembly, crank), "engine.toml")
    angle = math.degrees(ex.mechanism.drive.angle) % 360
    assert angle == pytest.approx(degrees, abs=1e-12)     # the data's degrees, rounded once
    theta = math.radians(float(crank.split("\n")[0].split("=")[1]))
    if "b.d.c." in crank:
        theta += math.pi
    s = math.sqrt(L * L - (R * math.sin(theta)) ** 2)
    speed = 300 * (R * math.sin(theta) + R * R * math.sin(2 * theta) / (2 * s))   # rad/s
    worked = tarsim.solve(parse_exercise(_engine(slider, assembly, crank).replace(
        'find = ["T2", ', 'find = ["V_P", "T2", '), "engine.toml"))
    (sol,) = worked.positions
    # a velocity polygon's rounding, some 1e-15 of the crank pin's speed
    assert sol.quantities["V_P"].value["value"] == pytest.approx(abs(speed), rel=1e-12)


@pytest.mark.parametrize("slider, crank, words", [
    ('angle = 90\nthrough = "O"', 'angle = 40\nfrom = "top"\nomega = 300',
     "names the dead centre"),
    ("angle = 90\nthrough = [10, 0]", 'angle = 40\nfrom = "t.d.c."\nomega = 300',
     "passes 10 mm from the crank's pivot O"),
])
def test_a_bad_dead_centre_is_refused_at_its_line(slider, crank, words):
    with pytest.raises(InputError) as e:
        parse_exercise(_engine(slider, '"forward"', crank).replace('through = "O"\n', "", 1),
                       "engine.toml")
    assert str(e.value).startswith("engine.toml:") and words in str(e.value), str(e.value)
    assert "\n" not in str(e.value)
