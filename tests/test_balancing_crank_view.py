"""An engine's polygons are drawn beside the end view of the cranks they are laid along, as
step 1 of steps.md says and the books draw it: from O each crank a radius at its angle
(θᵢ for the primary polygons, 2θᵢ for the secondary ones) from the reference line, the
line of stroke, numbered with its cylinder and its angle.
"""

from __future__ import annotations

import math
import re

import pytest

from tarsim.constructions.narration import speaking
from tarsim.exercises.catalog import load
from tarsim.graphics.balancing.crank_view import RADIUS
from tarsim.graphics.figure import Path, Text
from tarsim.graphics.hiding import hiding
from tarsim import solve

ENGINES = ("inline-four", "inline-three", "two-stroke-four", "locomotive",
           "coupled-locomotive", "outside-locomotive", "primary-balance-unknowns")
KINDS = ("primary-force", "primary-couple", "secondary-force", "secondary-couple")
_ANGLE = 1e-6       # rad: a radius is drawn along its crank's unit vector, to rounding
_MARGIN = 8.0       # mm: draw_caption's margin round the drawing


def _paper_angle(a, b) -> float:
    """The angle (rad, counter-clockwise as seen, paper y running down) of a → b."""
    return math.atan2(a[1] - b[1], b[0] - a[0])


def _same(a: float, b: float) -> bool:
    return abs(math.remainder(a - b, 2 * math.pi)) < _ANGLE


def _cranks(fig):
    """The view's radii: the figure's "link" paths (a polygon has none), each (O, tip)."""
    return [p.points for p in fig.items if isinstance(p, Path) and p.style == "link"]


@pytest.mark.parametrize("engine", ENGINES)
def test_step_one_names_the_view_the_figure_draws(solved, engine):
    s = solved(engine)
    assert "1. Draw the end view of the cranks" in s.files()["steps.md"]
    cranks = s.exercise.engine.cranks
    kinds = [k for k in KINDS if k in s.figures]
    assert kinds[:2] == ["primary-force", "primary-couple"]
    for kind in kinds:
        fig = s.figures[kind]
        order = 1 if kind.startswith("primary") else 2
        radii = _cranks(fig)
        (o,) = {r[0] for r in radii}                      # every radius from one centre
        labels = {t.owner[0]: t.text for t in fig.items
                  if isinstance(t, Text) and t.owner and t.owner[0] in {r[1] for r in radii}}
        for i, theta in enumerate(cranks, start=1):
            want = order * theta
            tips = [tip for a, tip in radii if _same(_paper_angle(a, tip), want)]
            assert len(tips) == 1, (kind, i)              # cranks at one angle share a radius
            assert math.dist(o, tips[0]) == pytest.approx(RADIUS, abs=1e-9)
            # its label names it and its angle: "1, 4: 0°", "3: 100.1°"
            label = labels[tips[0]]
            number, degrees = label.split(": ")
            assert str(i) in number.split(", "), (kind, label)
            assert float(degrees.rstrip("°")) == pytest.approx(
                math.degrees(want) % 360.0, abs=0.05 + 1e-9)   # said to a tenth of a degree
        assert len(radii) == len({round(math.degrees(order * t) % 360.0, 3) % 360.0
                                  for t in cranks})
        # the reference line runs from O along 0°, past the radii
        ref = [p.points for p in fig.items if isinstance(p, Path) and p.style == "reference"
               and p.points[0] == o]
        assert len(ref) == 1 and _same(_paper_angle(*ref[0]), 0.0)
        assert math.dist(*ref[0]) > RADIUS
        heading = "end view of the cranks, at θᵢ" if order == 1 else \
            "end view of the secondary cranks, at 2θᵢ"
        assert sum(isinstance(t, Text) and t.text == heading for t in fig.items) == 1


@pytest.mark.parametrize("engine", ["inline-four", "locomotive"])
def test_the_view_stands_beside_the_polygon_on_the_reading_side(solved, engine):
    """Read first, as step 1 is: left of the polygon in English, right of it in Persian;
    clear of it either way."""
    for lang in ("en", "fa"):
        with speaking(lang):
            fig = solved(engine).figures["primary-force"] if lang == "en" else \
                solve(load(engine)).figures["primary-force"]
        (o,) = {r[0] for r in _cranks(fig)}
        bottom = _MARGIN + fig.drawing[1] + 0.5           # the legend's samples under it
        vectors = [x for p in fig.items if isinstance(p, Path)
                   and p.style in ("vector", "vector_result") and len(p.points) == 2
                   and max(y for _, y in p.points) <= bottom for x, _ in p.points]
        if lang == "en":
            assert o[0] + RADIUS + 12.0 < min(vectors)
        else:
            assert o[0] - RADIUS - 12.0 > max(vectors)
        labels = [t.text for t in fig.items if isinstance(t, Text) and t.owner
                  and t.owner[0] != o and t.owner[0] in {r[1] for r in _cranks(fig)}]
        if lang == "fa":                 # Persian digits, the angle said in درجه
            assert labels and all(re.fullmatch(r"[۰-۹، ]+: [۰-۹٫]+ درجه", t) for t in labels), \
                labels


def test_a_crank_angle_the_solution_found_is_an_answer_hidden_with_them():
    """The primary balance's cranks 2 and 4 and its third cylinder are found: with answers
    hidden their radii are numbered only, crank 1's given angle still said."""
    with hiding(frozenset({"answers"})):
        fig = solve(load("primary-balance-unknowns")).figures["primary-force"]
    tips = {r[1] for r in _cranks(fig)}
    labels = sorted(t.text for t in fig.items if isinstance(t, Text) and t.owner
                    and t.owner[0] in tips)
    assert labels == ["1: 0°", "2", "3", "4"]
