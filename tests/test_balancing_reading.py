"""An engine polygon's reading, what its closing side leaves unbalanced and at what crank
angle it is greatest, is set clear of the polygon's vectors: on one line where one finds a
clear spot by the closing side, else broken after its comma. Before, the in-line three's
primary couple printed "21881 N·m unbalanced, greatest at θ₁ = 150.0°" across cyl. 3."""

from __future__ import annotations

import pytest
from shapely.geometry import LineString, box

from tarsim import solve
from tarsim.constructions.narration import speaking
from tarsim.exercises.catalog import load
from tarsim.graphics.figure import Path, Text

ENGINES = ("inline-four", "inline-three", "two-stroke-four")
KINDS = ("primary-force", "primary-couple", "secondary-force", "secondary-couple")
GRAZE = 0.05
"""mm² of a stroke (its pen's width) a text may share before it lies over it."""
UNBALANCED = {"en": "unbalanced", "fa": "نامیزان"}
GREATEST = {"en": "greatest at", "fa": "بیشینه در"}


def _reading(fig, lang: str) -> list[Text]:
    """The texts of the reading: the line naming what is left unbalanced, and the line
    after it where it is broken."""
    texts = [t for t in fig.items if isinstance(t, Text)]
    return [t for t in texts if UNBALANCED[lang] in t.text or GREATEST[lang] in t.text]


@pytest.mark.parametrize("lang", ["en", "fa"])
@pytest.mark.parametrize("engine", ENGINES)
def test_the_reading_crosses_no_vector(engine, lang):
    with speaking(lang):
        figures = solve(load(engine)).figures
    for kind in (k for k in KINDS if k in figures):
        fig = figures[kind]
        reading = _reading(fig, lang)
        if not reading:                     # closed: balanced, said in one short line
            continue
        strokes = [LineString(p.points).buffer(0.1) for p in fig.items
                   if isinstance(p, Path) and not p.closed and len(p.points) >= 2]
        over = [(t.text, round(box(*t.box()).intersection(s).area, 2)) for t in reading
                for s in strokes if box(*t.box()).intersection(s).area > GRAZE]
        assert over == [], (engine, kind, over)
        assert any(GREATEST[lang] in t.text for t in reading)


def test_the_in_line_threes_primary_couple_reading_is_broken_after_its_comma():
    fig = solve(load("inline-three")).figures["primary-couple"]
    lines = _reading(fig, "en")
    assert [t.text for t in lines] == ["21881 N·m unbalanced,", "greatest at θ₁ = 150.0°"]
    first, second = (t.box() for t in lines)
    assert second[1] > first[1]                                  # one under the other
    assert (first[0] + first[2]) / 2 == pytest.approx((second[0] + second[2]) / 2)
