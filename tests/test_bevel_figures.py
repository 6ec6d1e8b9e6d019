"""A train with bevel gears, drawn: the table holds no number that is not a turn about the
main axis, and the side view draws a bevel gear as the books' schematic does.

The car's differential (bundled): the pinion 1 (12 teeth) on the propeller shaft, square to
the crown 2 (60); the cage 6 on the crown carries the bevel planet 5 (10) between the axle
gears 3 and 4 (20 each). The crown turns 1000·12/60 = 200 rpm and ω3 = 2·200 − 210 = 190.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import pytest

from tarsim.constructions.narration import speaking
from tarsim.exercises.catalog import bundled, load
from tarsim.exercises.gears.train_solution import solve_train
from tarsim.graphics.figure import Path as FPath
from tarsim.graphics.gears.bevel_view import bevel_view
from tarsim.graphics.svg import to_svg

_NUMBER = re.compile(r"[+−-]?[0-9۰-۹]+([/.][0-9۰-۹]+)?")
"""A cell's number, in Latin or Persian digits."""


def _texts(svg: str) -> list[tuple[float, float, str]]:
    """Each text of an SVG as (x, y, text)."""
    return [(float(t.get("x")), float(t.get("y")), t.text or "")
            for t in ET.fromstring(svg).iter("{http://www.w3.org/2000/svg}text")]


def _column(texts, head: str) -> list[str]:
    """The texts set in the column under the heading that starts with ``head`` (cells are
    centred on their heading, to the layout's 0.001 mm)."""
    x, y, _ = next(t for t in texts if t[2].startswith(head))
    return [s for tx, ty, s in texts if abs(tx - x) < 1e-3 and ty > y]


@pytest.mark.parametrize("lang", ["en", "fa"])
def test_a_bevel_planet_and_a_square_pinion_have_blank_columns_and_a_footnote(lang):
    """The planet 5 turns about its own axis, the pinion 1 about the propeller shaft: no
    cell of theirs holds a number (today's "+2" and "180" were none of the main axis's);
    each heading carries a mark its footnote explains; the main-axis columns still read the
    closed forms: crown 1000·12/60 = 200, axle P 2·200 − 210 = 190, axle Q 210, cage 200."""
    with speaking(lang):
        s = solve_train(load("car-differential"))
        texts = _texts(to_svg(s.figures["table"]))
    heads = {n: next(t for _, _, t in texts if re.match(rf"{n} \S", t)) for n in "123456"}
    for m, mark in (("1", "†"), ("5", "‡")):
        assert heads[m].endswith(mark)
        assert not any(_NUMBER.fullmatch(c) for c in _column(texts, heads[m]))
        notes = [t for _, _, t in texts if t.startswith(mark)]
        assert len(notes) == 1
        assert ("محور اصلی" if lang == "fa" else "main axis") in notes[0]
    # the pinion's speed is said about its own axis, in its footnote: 1000 rpm
    assert ("۱۰۰۰" if lang == "fa" else "1000") in next(t for _, _, t in texts
                                                        if t.startswith("†"))
    digits = str.maketrans("۰۱۲۳۴۵۶۷۸۹", "0123456789")
    for m, speed in (("2", "200"), ("3", "190"), ("4", "210"), ("6", "200")):
        assert _column(texts, heads[m])[-1].translate(digits) == speed


def _train_figure():
    s = solve_train(load("car-differential"))
    return s, s.figures["train"]


def _edges(path: FPath):
    pts = [*path.points, path.points[0]] if path.closed else list(path.points)
    return [(a, b) for a, b in zip(pts, pts[1:])]


def test_bevel_gears_are_slanted_teeth_not_spur_rectangles():
    """No gear of the differential is a spur gear's upright rectangle; every gear's teeth
    have edges at 45° (the two of a pair meeting on one pitch line), the pinion's shaft and
    the planet's spindle stand square to the main axis, and the pitch points lie at the
    gears' radii to scale: the crown's 60 teeth and the axle gears' 20 stand 3:1 from the
    axis, the pinion's pitch points 12 modules apart (its pitch diameter) and the planet's 10."""
    s, fig = _train_figure()
    closed = [it for it in fig.items if isinstance(it, FPath) and it.style == "link"
              and it.closed]
    for it in closed:
        slopes = [math.degrees(math.atan2(b[1] - a[1], b[0] - a[0])) % 180
                  for a, b in _edges(it)]
        assert any(abs(d - 45) < 1e-6 or abs(d - 135) < 1e-6 for d in slopes)   # slanted
        assert not all(min(d % 90, 90 - d % 90) < 1e-6 for d in slopes)   # no rectangle
    # 2 + 2 + 2 teeth of the main-axis gears, 2 of the pinion, 2 × 2 of the planet
    assert len(closed) == 12
    axis = next(it for it in fig.items if isinstance(it, FPath) and it.style == "reference")
    y0 = axis.points[0][1]                              # the main axis, laid out at 0
    # each trapezoid starts at its pitch point
    pitch = [(x, y - y0) for x, y in (it.points[0] for it in closed)]
    heights = sorted({round(abs(y), 9) for _, y in pitch})
    assert len(heights) == 2 and math.isclose(heights[1] / heights[0], 60 / 20, rel_tol=1e-9)
    mm = heights[0] / 10.0                               # paper mm per module: r3 = 10 modules
    top = [p for p in pitch if math.isclose(-p[1], heights[1], rel_tol=1e-9)]
    assert max(p[0] for p in top) - min(p[0] for p in top) == pytest.approx(2 * 6 * mm)
    upright = [it for it in fig.items if isinstance(it, FPath) and it.style == "link"
               and not it.closed and len(it.points) == 2
               and it.points[0][0] == it.points[1][0]]
    # the planet's spindle, through the axis between the axle gears' webs
    spindle = [it for it in upright if it.points[0][1] - y0 == pytest.approx(
        -(it.points[1][1] - y0))]
    crown, p, spin, q = sorted({round(it.points[0][0], 9) for it in spindle})
    assert spin - p == pytest.approx(q - spin)          # webs: the crown's, P's, Q's
    inner = {round(x, 9) for x, y in pitch if math.isclose(-y, heights[0], rel_tol=1e-9)}
    assert max(inner) - min(inner) == pytest.approx(2 * 5 * mm)     # the planet's 10 teeth
    # the pinion's shaft rises from its back, above the crown's pitch circle
    assert any(min(-(p[1] - y0) for p in it.points) > heights[1] for it in upright)
    assert s.train.square(1) and s.train.square(5) and not s.train.square(2)


def test_a_spur_train_has_no_bevel_view():
    """Every bundled train without bevel teeth keeps its spur side view: no gear of it turns
    square to the main axis, so the bevel layout stands aside."""
    for name in bundled("gears"):
        if name == "car-differential":
            continue
        train = solve_train(load(name)).train
        assert bevel_view(train, {}, lambda g: 1.0) is None, name
