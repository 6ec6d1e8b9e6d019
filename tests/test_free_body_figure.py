"""The free bodies (graphics/forces/free_body_figure.py): every point a force acts at named,
every force an arrow named beside it at its body's own force scale, and a force too short
for that scale drawn dashed at a stated length instead of being listed as too small.

The crank-shaper at t = 2.34 s is the case: its loads run from 0.018 N (the block's inertia)
to 44 N (the lever's weight) on bodies whose largest force runs from 0.98 N to 44 N, each
body at its own scale (its largest force 45 mm at most).
"""

from __future__ import annotations

import math
import re
from collections import Counter

import pytest

from tarsim.graphics.figure import Path, Text
from tests.test_force_figure import _gap

SHAPER = "crank-shaper-forces"
AT = "free-bodies-t-2.34s"

_STATED = 10.0
"""The length (mm) the legend states a force too short for its body's scale is drawn at."""


@pytest.fixture(scope="module")
def bodies(solved):
    return solved(SHAPER).figures[AT]


def _names(fig):
    """The forces' names: a name held to a vector (tail, tip) with its size after it."""
    return [t for t in fig.items if isinstance(t, Text) and t.owner and len(t.owner) == 2]


def _shafts(fig):
    return [it for it in fig.items if isinstance(it, Path)
            and it.style in ("vector", "vector_dashed")]


def _own(t, shafts):
    """The shaft of the arrow the name ``t`` names: from its tail toward its tip."""
    (own,) = [s for s in shafts if math.dist(s.points[0], t.owner[0]) < 1e-9
              and _gap(s.points[-1:] * 2, *t.owner) < 1e-6]
    return own


def test_every_point_a_force_acts_at_is_named(bodies):
    """Link 4's A (the block's push) and B (the ram's pin), and each centre of mass a
    weight or an inertia force acts at, are named with the links' own points: the lever
    named only O₄."""
    points = Counter(t.text + t.sub for t in bodies.items if isinstance(t, Text) and t.owner
                     and len(t.owner) == 1 and not t.tail)
    assert points == Counter({"A": 3, "B": 2, "O₂": 1, "O₄": 1, "G₂": 1, "G₄": 1})


def test_each_force_is_named_beside_its_own_arrow(bodies):
    """Every force's name stands within 3 mm of its own arrow and no nearer another (F₁₄
    stood by G₄, 3.6 mm off its shaft)."""
    shafts = _shafts(bodies)
    for t in _names(bodies):
        own = _own(t, shafts)
        gap = _gap(t.box(), own.points[0], t.owner[1])
        assert gap <= 3.0, (t.text, t.sub, gap)
        others = [_gap(t.box(), s.points[0], s.points[-1]) for s in shafts if s is not own]
        assert gap <= min(others) + 1e-9, (t.text, t.sub)


def test_no_load_is_left_out_and_each_is_drawn_at_its_bodys_stated_scale(bodies):
    """All 17 forces are drawn (five were only listed as too small to draw): each as long
    as its body's stated scale makes it (to the 4 figures its name prints), or, shorter
    than 10 mm at that scale, dashed and 10 mm long as the legend states."""
    texts = [t for t in bodies.items if isinstance(t, Text)]
    scales = {}
    for t, statement in zip(texts, texts[1:]):
        if t.weight == "bold" and re.fullmatch(r"link \d", t.text):
            scales[int(t.text[-1])] = float(
                re.fullmatch(r"Force scale 1 cm = ([\d.]+) N", statement.text)[1])
    assert scales == {2: 10.0, 3: 5.0, 4: 10.0, 5: 0.5}
    assert not [t for t in texts if "Too small" in t.text]
    names = _names(bodies)
    assert len(names) == 17
    shafts = _shafts(bodies)
    small = 0
    for t in names:
        size = float(re.fullmatch(r" = ([\d.]+) N", t.tail)[1])
        at_scale = size * 10.0 / scales[int(t.sub[-1])]       # the link it acts on
        if at_scale >= _STATED:
            assert math.dist(*t.owner) == pytest.approx(at_scale, rel=1e-3), t.text + t.sub
            assert _own(t, shafts).style == "vector"
        else:
            small += 1
            assert math.dist(*t.owner) == pytest.approx(_STATED, abs=1e-9), t.text + t.sub
            assert _own(t, shafts).style == "vector_dashed"
    assert small == 7       # Fi2, Fi3, W3, Fi4, F54, Fi5, F45
    legend = [t.text for t in texts if t.text.endswith("drawn 10 mm long")]
    assert legend == ["a force too small for that scale, drawn 10 mm long"]
