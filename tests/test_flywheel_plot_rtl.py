"""The punching press's flywheel plots in Persian: every line read from the right margin
ends on it, and no number of the y axis touches a mark standing on the axis.

A right-to-left line was set by its left end, its width estimated 2 % over the font's
advances (graphics/sans_advances.py, HINTING): cairo set it narrower, and a note stopped
3 mm short of the margin the title ended on. A line set by its right end ends on the
margin whatever width the viewer gives it. The energy at the first intercept is marked on
the y axis, and its "0" (in Persian a dot, ۰) stood 0.7 mm from the mark's circle.
"""

from __future__ import annotations

import math

import pytest

from tarsim import solve
from tarsim.constructions.narration import speaking
from tarsim.exercises.catalog import load
from tarsim.graphics.figure import Circle, Path, Text
from tarsim.graphics.rtl import is_rtl

FIGURES = [("punch-sheared-area", "energy"), ("punching-press", "turning-moment")]
_MARGIN = 10.0      # mm: the plot's page margin, where its headings and notes start
_CLEAR = 1.0        # mm: the least gap between a number's box and a mark's circle


def _figure(exercise_id: str, stem: str, lang: str):
    with speaking(lang):                 # named in the language, as solve --lang names it
        return solve(load(exercise_id).named_in(lang)).figures[stem]


@pytest.mark.parametrize("exercise_id, stem", FIGURES)
def test_every_line_read_from_the_right_margin_ends_on_it(exercise_id, stem):
    fig = _figure(exercise_id, stem, "fa")
    edge = fig.width - _MARGIN
    texts = [t for t in fig.items if isinstance(t, Text) and is_rtl(t.text)]
    # the lines whose estimated right end is at the margin: heading, subtitle and every
    # note line (a legend opens with its sample)
    at_edge = [t for t in texts if abs(t.box()[2] - edge) < 1e-6]
    assert len(at_edge) >= 3, [t.text for t in at_edge]
    for t in at_edge:
        assert (t.anchor, t.at[0]) == ("end", pytest.approx(edge, abs=1e-9)), t.text
    # each legend entry's words end at their own sample, 2 mm off it, set by that end
    bottom = max(y for p in fig.items if isinstance(p, Path) and p.style == "plot_frame"
                 for _, y in p.points)
    samples = [c.centre[0] for c in fig.items if isinstance(c, Circle)
               and c.style == "plot_mark" and c.centre[1] > bottom]
    words = [t for t in texts if t.anchor == "end" and any(
        abs(t.at[0] - (x - 3.0)) < 1e-9 for x in samples)]
    assert len(words) == len(samples) >= 1


@pytest.mark.parametrize("lang", ["en", "fa"])
@pytest.mark.parametrize("exercise_id, stem", FIGURES)
def test_no_number_touches_a_mark(exercise_id, stem, lang):
    fig = _figure(exercise_id, stem, lang)
    marks = [c for c in fig.items if isinstance(c, Circle) and c.style == "plot_mark"]
    assert marks
    for t in fig.items:
        if not isinstance(t, Text) or not t.text.strip("\u200e−+0123456789۰۱۲۳۴۵۶۷۸۹.٫") == "":
            continue
        x0, y0, x1, y1 = t.box()
        for c in marks:
            dx = max(x0 - c.centre[0], 0.0, c.centre[0] - x1)
            dy = max(y0 - c.centre[1], 0.0, c.centre[1] - y1)
            assert math.hypot(dx, dy) - c.radius >= _CLEAR, (t.text, c.centre)
