"""The problem sheets of the chapters a sheet was added for last: a flywheel's, a connecting
rod's, a cam's given by its arcs, a rotor's with unknowns or weights, an engine's. Each holds
the data its file gives and none of the numbers its solution finds."""

from __future__ import annotations

import pytest

from tarsim.constructions.narration import speaking
from tarsim.exercises.chapters import chapter_of
from tarsim.graphics.svg import to_svg
from tests.test_handout import _NUMBER, _answers_on, _given, _sheet, _texts, _without_ticks

FLYWHEELS = ["engine-harmonic-torque", "flywheel-between-speeds", "four-stroke-triangles",
             "petrol-engine-areas", "punch-sheared-area", "punching-press",
             "single-cylinder-table", "steam-engine-energy-coefficient",
             "three-cylinder-triangles", "rod-equivalent-masses"]


def _holds_data_and_no_answer(name: str, lang: str, *, skip=()):
    ex, sheet = _sheet(name, lang)
    svg = _without_ticks(to_svg(sheet.figure))
    tokens = set(_NUMBER.findall(" ".join(_texts(svg, ticks=False))))
    given = _given(name) - set(skip)
    for x in given:
        assert f"{x:g}" in tokens, f"{x:g} of {name}'s file is not on its sheet"
    with speaking("en"):
        results = chapter_of(ex).solve(ex).results
    found = _answers_on(svg, results, given, ticks=False)
    assert not found, f"answers on {name}'s sheet: {sorted(found)}"
    return ex, sheet


@pytest.mark.parametrize("lang", ["en", "fa"])
@pytest.mark.parametrize("name", FLYWHEELS)
def test_a_flywheels_sheet_holds_its_data_and_no_answer(name, lang):
    _holds_data_and_no_answer(name, lang)


@pytest.mark.parametrize("lang", ["en", "fa"])
@pytest.mark.parametrize("name", ["circular-arc-flat-face", "tangent-cam-roller"])
def test_a_cam_of_arcs_sheet_draws_what_is_given_and_no_answer(name, lang):
    """The base circle and the nose (where its radius is given) are drawn at the solution's
    scale: the circular arc's r1 = 40 and r2 = 10 mm at 1 cm = 10 mm are circles of 40 and
    10 mm; the tangent cam's nose is found, so only its base circle (30 mm at 1 cm = 20 mm)
    is drawn, its roller (10 mm) dashed at the apex."""
    ex, sheet = _holds_data_and_no_answer(name, lang)
    circles = sorted(round(c.radius, 6) for c in sheet.figure.items
                     if type(c).__name__ == "Circle" and c.style == "link")
    assert circles == ([10.0, 40.0] if name == "circular-arc-flat-face" else [15.0])


ROTORS = ["unknown-angles", "unknown-plane-and-angle", "unknown-planes",
          "primary-balance-unknowns", "three-masses-between", "weights-one-plane"]


@pytest.mark.parametrize("lang", ["en", "fa"])
@pytest.mark.parametrize("name", ROTORS)
def test_a_rotor_with_unknowns_sheet_holds_its_data_and_no_answer(name, lang):
    _holds_data_and_no_answer(name, lang)


def test_a_mass_with_an_unknown_angle_is_left_out_of_the_end_view_and_its_plane_of_the_side():
    """unknown-plane-and-angle's D is found at 252.72° in a plane 366.7 mm from A: the sheet
    draws A, B and C on their radial lines (A's mass a gap, "…"), three planes at 0, 100 and
    300 mm and no fourth, and leaves D's cells empty but its given radius, 80 mm."""
    _, sheet = _sheet("unknown-plane-and-angle", "en")
    texts = _texts(to_svg(sheet.figure))
    assert "A: … kg at 80 mm, 190°" in texts
    assert not [t for t in texts if t.startswith("D:")]
    assert "not drawn, its radial line to be found: D" in texts
    assert "366.7" not in " ".join(texts) and "252.7" not in " ".join(texts)
    assert "mass D: ? kg at 80 mm, ?, plane at ? mm" in texts
    assert "mass D: its mass, its angle, its plane" in texts


def test_weights_are_given_and_asked_as_weights():
    """weights-one-plane gives 60, 80 and 100 N: the sheet states them in N (not the masses
    W/g it is solved with, 6.116 kg) and asks the balance weight."""
    _, sheet = _sheet("weights-one-plane", "en")
    texts = _texts(to_svg(sheet.figure))
    assert "weight 1: 60 N at 150 mm, 0°, plane at 0 mm" in texts
    assert "in plane B: the balance weight and its angle" in texts
    assert "W (N)" in texts and not [t for t in texts if "6.116" in t]


def test_a_view_names_only_what_it_draws():
    """Every plane of unknown-plane-and-angle's sheet's side view is a mass's plane: its
    legend names no balancing plane. three-masses-between's end view draws mass 1 alone, on
    the reference radius: O stands in the whole turn left free, across from it (x < 0),
    not on the mass's line."""
    _, sheet = _sheet("unknown-plane-and-angle", "en")
    texts = _texts(to_svg(sheet.figure))
    assert "a mass's plane" in texts and "a balancing plane" not in texts
    _, sheet = _sheet("three-masses-between", "en")
    o = next(t for t in sheet.sheets[0].items if getattr(t, "text", "") == "O")
    dot = next(c for c in sheet.sheets[0].items
               if type(c).__name__ == "Circle" and c.style == "dot")
    assert o.at[0] < dot.centre[0] - 3.0      # 4.2 mm to the left of O's dot, less its width
