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
