"""A connecting rod given alone, as the books pose its equivalent dynamical system: the
masses with one at the gudgeon pin (l2 = k²/l1 beyond G), the masses at the two pins,
their moment of inertia m·l1·l3 against m·k², and the correction couple (m·l1·l3 − m·k²)·α.

The book's numbers (Khurmi's rod: 2 kg, 250 mm between the pins, G 100 mm from the gudgeon
pin, k = 110 mm, α = 23 000 rad/s² clockwise) are exact in decimals: l2 = 12100/100 =
121 mm, m·l1·l3 = 2·0.1·0.15 = 0.03 kg·m², the couple 2·(0.015 − 0.0121)·23000 = 133.4
N·m. Each is a handful of products and quotients, so it agrees with them to a few
roundings, 1e-12 relative; the masses the book prints to four places (1.0950, 0.9050) are
held to half a unit of its last place.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.constructions.forces.equivalent import (RodLine, equivalent_masses, pin_masses,
                                                    rod_couple)
from tarsim.constructions.narration import speaking
from tarsim.exercises.catalog import load
from tarsim.exercises.cli import cli
from tarsim.exercises.forces.rod_file import parse_rod
from tarsim.exercises.forces.rod_solution import solve_rod
from tarsim.exercises.linkages.exercise_file import parse_exercise

HERE = Path(__file__).parent / "reproducers"
REL = 1e-12
"""A few roundings of products and quotients of numbers of order 0.01–10 (see above)."""

ROD = """
[units]
length = "mm"

[rod]
mass = 2
length = 250
centre = 100
radius_of_gyration = 110
alpha = 23000
alpha_sense = "cw"
"""


def _values(sol):
    return {k: c.value["value"] for k, c in sol.checked.items()}


def test_e3_rod_equivalent():
    """The book's rod stated as the book states it, alone: every answer it prints."""
    path = HERE / "e3-rod-equivalent.toml"
    sol = solve_rod(parse_rod(path.read_text(encoding="utf-8"), str(path)))
    q = _values(sol)
    assert q["l2"] == pytest.approx(0.121, rel=REL)                  # 110²/100 mm
    assert sol.checked["l2"].value["from_pin"] == pytest.approx(0.221, rel=REL)
    assert q["mass_at_P"] == pytest.approx(1.0950, abs=5e-5)         # the book's 4 places
    assert q["mass_at_D"] == pytest.approx(0.9050, abs=5e-5)
    assert q["mass_at_P"] == pytest.approx(2 * 121 / 221, rel=REL)   # m·l2/(l1 + l2)
    assert q["pin_mass_P"] == pytest.approx(2 * 150 / 250, rel=REL)  # m·GA/l
    assert q["pin_mass_A"] == pytest.approx(2 * 100 / 250, rel=REL)
    assert q["equivalent_inertia"] == pytest.approx(0.03, rel=REL)
    assert q["rod_inertia"] == pytest.approx(0.0242, rel=REL)
    assert q["correction_couple"] == pytest.approx(-133.4, rel=REL)  # clockwise, α's sense
    assert sol.checked["correction_couple"].value["sense"] == "cw"
    assert not sol.failures


def test_e3b_ask_equivalent():
    """A linkage file asking the rod's equivalent system is pointed to a [rod] file, and
    told the forces it may ask, as asks.EFFORTS registers them."""
    from tarsim.constructions.asks import EFFORTS

    path = HERE / "e3b-ask-equivalent.toml"
    with pytest.raises(InputError) as e:
        parse_exercise(path.read_text(encoding="utf-8"), str(path))
    message = str(e.value)
    assert "cannot find 'equivalent_system'" in message and "[rod] file" in message
    assert "equivalent_masses" in message and "\n" not in message
    for name in ("correction_couple", "turning_moment", "piston_effort"):
        assert name in message
    # A name near no rod's ask still hears of the forces, after the kinematic names.
    text = path.read_text(encoding="utf-8").replace('"equivalent_system"', '"torque_xyz"')
    with pytest.raises(InputError, match=r'"stroke"; or a force it answers: piston_effort'):
        parse_exercise(text, str(path))
    assert all(name in EFFORTS for name in ("correction_couple", "turning_moment"))


def test_one_mass_at_the_crank_pin_stands_the_other_beyond_g_toward_the_gudgeon_pin():
    sol = solve_rod(parse_rod(ROD + 'one_mass_at = "A"\n'))
    q = _values(sol)
    # l1 = GA = 150 mm, l2 = 12100/150 mm, m·l2/(l1 + l2) at A
    l2 = 0.0121 / 0.15
    assert q["l2"] == pytest.approx(l2, rel=REL)
    assert q["mass_at_A"] == pytest.approx(2 * l2 / (0.15 + l2), rel=REL)
    assert q["mass_at_D"] == pytest.approx(2 * 0.15 / (0.15 + l2), rel=REL)


def test_centre_from_the_crank_pin_and_inertia_given_are_the_same_rod():
    by_k = _values(solve_rod(parse_rod(ROD)))
    text = ROD.replace("centre = 100", 'centre = 150\ncentre_from = "A"').replace(
        "radius_of_gyration = 110", "inertia = 0.0242").replace(
        'alpha = 23000\nalpha_sense = "cw"', "alpha = -23000")
    by_i = _values(solve_rod(parse_rod(text)))
    assert by_i.keys() == by_k.keys()
    for k in by_k:
        assert by_i[k] == pytest.approx(by_k[k], rel=REL), k


@settings(max_examples=60, deadline=None)
@given(st.floats(0.1, 50), st.floats(0.05, 1.0), st.floats(0.05, 0.95), st.floats(0.1, 0.6),
       st.floats(-1e5, 1e5))
def test_the_masses_keep_the_rods_mass_centre_and_inertia(m, length, f, kf, alpha):
    """Each system keeps m and G; the equivalent one I_G too, the pins' m·l1·l3, and the
    couple is what the pins' I overstates I_G by, times α. The sums are of a few terms of
    one sign each but for the first moment, which cancels: it is held against m·l."""
    centre = f * length
    k = kf * length
    rod = RodLine(m, length, centre, m * k * k)
    e = equivalent_masses(rod)
    x1, x2 = -centre, e.l2
    assert e.at_pin + e.beyond == pytest.approx(m, rel=1e-13)
    assert abs(e.at_pin * x1 + e.beyond * x2) <= 1e-13 * m * (abs(x1) + x2)
    assert e.at_pin * x1 ** 2 + e.beyond * x2 ** 2 == pytest.approx(m * k * k, rel=1e-13)
    mp, ma = pin_masses(rod)
    assert abs(mp * centre - ma * (length - centre)) <= 1e-13 * m * length
    pins_i = mp * centre ** 2 + ma * (length - centre) ** 2
    assert pins_i == pytest.approx(m * centre * (length - centre), rel=1e-13)
    couple = rod_couple(m, length - centre, centre, m * k * k, alpha)
    assert abs(couple - (pins_i - m * k * k) * alpha) <= 1e-13 * pins_i * abs(alpha) + 1e-300


@pytest.mark.parametrize("extra, where, said", [
    ('[ask]\nfind = ["correction_couple"]\n', "find",
     "correction_couple is (m·l1·l3 − m·k²)·α: give [rod] alpha"),
    ('[ask]\nfind = ["equivalent_system"]\n', "find", "did you mean 'equivalent_masses'?"),
])
def test_what_cannot_be_found_is_refused_at_the_ask(extra, where, said):
    text = ROD.replace('alpha = 23000\nalpha_sense = "cw"\n', "") + extra
    with pytest.raises(InputError) as e:
        parse_rod(text, "rod.toml")
    assert said in str(e.value) and "rod.toml:" in str(e.value)
    assert "\n" not in str(e.value) and len(str(e.value)) < 200


@pytest.mark.parametrize("change, said", [
    (("centre = 100", "centre = 250"), "not between the pins"),
    (("alpha = 23000", "alpha = -23000"), "write alpha's size alone"),
    (('alpha_sense = "cw"', 'alpha_sense = "left"'), 'alpha_sense is "cw" or "ccw"'),
    (("radius_of_gyration = 110", "radius_of_gyration = 110\ninertia = 0.02"), "one of them"),
    (("mass = 2", "mass = 0"), "the rod's mass (kg) must be positive"),
    (("centre = 100", 'centre = 100\ncentre_from = "B"'), "centre_from is one of the rod's"),
])
def test_a_rod_wrongly_given_is_refused_at_its_line(change, said):
    with pytest.raises(InputError) as e:
        parse_rod(ROD.replace(*change), "rod.toml")
    message = str(e.value)
    assert said in message and re.match(r"rod\.toml:\d+:", message), message
    assert "\n" not in message and len(message) < 200


def test_the_bundled_rod_is_solved_drawn_to_scale_and_listed(tmp_path):
    """The bundled rod (3 kg, 300 mm, G 120 mm from P, k 130 mm, α 18 000 ccw): its
    results.json rows against the closed forms, and its figure's rod as long on paper as
    its scale bar says."""
    out = tmp_path / "out"
    run = CliRunner().invoke(cli, ["solve", "rod-equivalent-masses", "-o", str(out),
                                   "--no-pdf"])
    assert run.exit_code == 0, run.output
    q = json.loads((out / "results.json").read_text(encoding="utf-8"))["quantities"]
    l2 = 0.0169 / 0.12
    assert q["l2"]["value"] == pytest.approx(l2, rel=REL)
    assert q["mass_at_P"]["value"] == pytest.approx(3 * l2 / (0.12 + l2), rel=REL)
    assert q["pin_mass_P"]["value"] == pytest.approx(1.8, rel=REL)
    assert q["equivalent_inertia"]["value"] == pytest.approx(0.0648, rel=REL)
    assert q["correction_couple"]["value"] == pytest.approx(0.0141 * 18000, rel=REL)
    assert q["correction_couple"]["sense"] == "ccw"
    assert all(row.get("passed", True) for row in q.values())
    fig = solve_rod(load("rod-equivalent-masses")).figures["rod"]
    rod = next(p for p in fig.items if getattr(p, "style", "") == "link")
    scale = re.search(r"1 cm = (\d+) mm", " ".join(getattr(t, "text", "")
                                                    for t in fig.items))
    per_cm = float(scale[1])
    paper = math.dist(*rod.points)
    assert paper == pytest.approx(300 / per_cm * 10, rel=1e-12)
    listed = CliRunner().invoke(cli, ["list"])
    assert "rod-equivalent-masses" in listed.output


def test_the_rods_steps_speak_persian():
    """steps.md in Persian: its words and digits, only names, symbols and units Latin."""
    ex = load("rod-equivalent-masses")
    with speaking("fa"):
        md = solve_rod(ex.named_in("fa")).steps()
    body = md.replace(ex.description, "")
    body = re.sub(r"`[^`]*`|\w*_\w*", "", body)
    assert set(re.findall(r"[A-Za-z]{3,}", body)) <= {"rad"}
    assert re.search("[۰-۹]٫[۰-۹]", body) and not re.search(r"\d\.\d", body)
    with speaking("fa"):
        fig = solve_rod(ex).figures["rod"]
    texts = " ".join(getattr(t, "text", "") for t in fig.items)
    assert "سیستم دینامیکی معادل" in texts and "کوپل تصحیح" in texts


def test_en3_rod_pendulum(tmp_path):
    """The books' 40 kg rod, 1 m between centres, G 650 mm from the small end, hung on a knife
    edge at the top of its 60 mm small-end bore, 35 oscillations in 60 s."""
    path = Path(__file__).parent / "reproducers" / "en3-rod-pendulum.toml"
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "o"), "--no-pdf"])
    assert run.exit_code == 0, run.output
    q = {k: v["value"] for k, v in json.loads(
        (tmp_path / "o" / "results.json").read_text())["quantities"].items()}
    g, T, h, m = 9.81, 60 / 35, 0.650 + 0.030, 40.0          # h to the bore's top
    k = math.sqrt(g * h * T * T / (4 * math.pi ** 2) - h * h)
    l1, l3 = 0.650, 0.350
    # a few roundings of numbers of the data's size: 1e-12 relative
    assert q["rod_radius_of_gyration"] == pytest.approx(k, rel=1e-12)
    assert q["rod_inertia"] == pytest.approx(m * k * k, rel=1e-12)
    assert q["l2"] == pytest.approx(k * k / l1, rel=1e-12)
    assert q["mass_at_P"] == pytest.approx(m * (k * k / l1) / (l1 + k * k / l1), rel=1e-12)
    assert (q["pin_mass_P"], q["pin_mass_A"]) == pytest.approx((14.0, 26.0), rel=1e-12)
    assert q["correction_couple"] == pytest.approx(-(m * l1 * l3 - m * k * k) * 5000, rel=1e-12)
    assert q["pendulum_period"] == pytest.approx(T, rel=1e-15)
    assert round(k * 1000, 3) == 184.864                   # the book's 184.86 mm


def test_a_rod_takes_one_of_k_inertia_and_a_pendulum_test(tmp_path):
    from tarsim.exercises.forces.rod_file import parse_rod
    text = ('[rod]\nmass = 2\nlength = 250\ncentre = 100\nradius_of_gyration = 110\n'
            'oscillations = { count = 8, seconds = 22, about = "P" }\n')
    with pytest.raises(InputError, match=r"f.toml:6: .*one of them"):
        parse_rod(text, "f.toml")
