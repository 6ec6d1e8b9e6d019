"""An input given by another member's motion (issue: "the velocity of a point", "ω of a link
that is not pivoted", "a slider as the driver"): the piston's speed and acceleration along
its stroke, or the coupler's ω and α. The drawing converts it to the crank's ω2 and α2 with
provisional polygons, the solver its own way; each member given comes back as given."""

from __future__ import annotations

import pytest

from tarsim.constructions.errors import TarsimError
from tarsim.exercises.catalog import load, resolve
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution import solve_exercise

SHAPER = resolve("hinkle-slider-crank").read_text(encoding="utf-8")


def test_the_piston_driven_slider_crank_gives_back_its_pistons_motion():
    sol = solve_exercise(load("piston-driven-slider-crank"))
    q = sol.quantities
    assert q["V_C"].value["vector"][0] == pytest.approx(0.300, rel=1e-12)
    assert q["A_C"].value["vector"][0] == pytest.approx(1.000, rel=1e-11)
    for name in ("omega2", "omega3", "V_B", "alpha2", "alpha3"):
        assert q[name].passed, name
    # the crank's rates are the piston's over its speed per unit crank rate
    w2 = q["omega2"].value["value"]
    assert w2 < 0 and any("so ω2 = " in note for note in sol.notes)


def test_a_couplers_omega_and_alpha_drive_the_crank():
    text = (SHAPER.replace("omega = 10", "omega = { link = 3, value = 2, alpha = 5 }")
            .replace('find = ["centres", "omega3", "V_C", "V_D", "Vmin_3_B_C", "Vmin_3"]',
                     'find = ["omega2", "omega3", "alpha3", "V_C"]')
            .replace('methods = ["radius-rotation", "parallel-line", "components"]',
                     'methods = ["polygon"]'))
    assert 'find = ["omega2", "omega3", "alpha3", "V_C"]' in text
    sol = solve_exercise(parse_exercise(text, "given.toml", "given"))
    q = sol.quantities
    assert q["omega3"].value["value"] == pytest.approx(2.0, rel=1e-12)
    assert q["alpha3"].value["value"] == pytest.approx(5.0, rel=1e-11)
    assert all(x.passed for x in q.values())


@pytest.mark.parametrize("swap, words", [
    ('speed = { point = "D", value = 300 }', "of input link 2 (O2, B) or on a frame guide (C); "
                                             "'D' is neither"),
    ('speed = { point = "O2", value = 300 }', "O2 is link 2's frame pivot, at rest"),
    ('speed = { point = "B", value = 300, sense = "up" }', 'must be "ccw" or "cw"'),
    ('omega = { link = 2, value = 3 }', "give the input link's own as omega = <number>"),
    ('omega = { link = 3 }', "gives the input by another member's motion"),
    ('speed = { point = "C", value = 0 }', "the speed given is 0, which leaves the mechanism"),
    ('omega = { link = 3, value = 2 }\nspeed = { point = "C", value = 3 }',
     "give the input's omega or a speed, not both"),
])
def test_a_given_input_that_cannot_be_is_refused_at_its_line(swap, words):
    with pytest.raises(TarsimError, match=r"given\.toml:\d+: \[input\.") as e:
        parse_exercise(SHAPER.replace("omega = 10", swap), "given.toml", "given")
    assert words in str(e.value)


def test_a_wheels_centre_speed_drives_the_chain_that_rolls_it():
    # The rolling wheel's centre at 3 m/s to the left: the wheel turns at V_B / r = 3 / 0.03.
    text = resolve("rolling-wheel").read_text(encoding="utf-8").replace(
        "omega = 4", 'speed = { point = "B", value = -3000 }')
    sol = solve_exercise(parse_exercise(text, "wheel.toml", "wheel"))
    q = sol.quantities
    assert q["V_B"].value["vector"][0] == pytest.approx(-3.0, rel=1e-12)
    assert q["omega4"].value["value"] == pytest.approx(100.0, rel=1e-12)
    assert all(x.passed for x in q.values())


def test_at_a_dead_centre_the_piston_gives_no_crank_speed():
    text = resolve("piston-driven-slider-crank").read_text(encoding="utf-8").replace(
        "angle = 60", "angle = 0")
    with pytest.raises(TarsimError, match=r"piston\.toml: V_C along its guide does not move "
                                          r"with link 2 at this position, so no ω2 gives it "
                                          r"300 mm/s"):
        solve_exercise(parse_exercise(text, "piston.toml", "piston"))


def test_the_crank_pins_speed_drives_its_crank():
    # The crank pin A of the bundled four-bar (O2A = 100 mm) moves at 1 m/s clockwise and
    # gains speed at 5 m/s²: ω2 = −V_A / O2A = −10 rad/s, α2 = −Aᵗ_A / O2A = −50 rad/s².
    # The rest scale as velocities are linear in ω2: ω3/ω2 is the four-bar's at ω2 = 10.
    sol = solve_exercise(load("crank-pin-speed"))
    q = sol.quantities
    assert all(x.passed for x in q.values())
    # the conversion divides by the polygon's 100 mm at 1 rad/s: a few roundings, 1e-12
    assert q["omega2"].value["value"] == pytest.approx(-10.0, rel=1e-12)
    assert q["alpha2"].value["value"] == pytest.approx(-50.0, rel=1e-11)
    assert q["V_A"].value["value"] == pytest.approx(1.0, rel=1e-12)
    four_bar = solve_exercise(load("four-bar").asking(("omega3", "omega4"))).quantities
    for name in ("omega3", "omega4"):
        assert q[name].value["value"] == pytest.approx(-four_bar[name].value["value"],
                                                       rel=1e-12)
    assert any("V_A square to O2A" in note and "so ω2 = −10 rad/s" in note
               for note in sol.notes)
