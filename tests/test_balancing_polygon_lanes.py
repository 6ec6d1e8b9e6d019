"""An engine's force and couple polygons show every vector and are drawn to the unit their
reading is given in.

The in-line four's polygons fold onto one line: its secondary force's closing side runs
back over all four vectors, and its primary force's cranks 1 and 2 retrace one another.
Each vector must be seen, side by side where they lie on one line; and a polygon whose
reading is in newtons states its scale in newtons, round (tests/test_balancing_round_scales.py).
"""

from __future__ import annotations

import math
import re

import pytest

from tarsim.graphics.figure import Path, Text

ENGINES = ("inline-four", "inline-three")
KINDS = ("primary-force", "primary-couple", "secondary-force", "secondary-couple")
_MARGIN = 8.0      # mm: draw_caption's margin round the drawing
_HEAD_STOP = 0.7 * 2.6   # mm: draw_arrow stops the shaft this short of the tip


def _shafts(fig) -> list[tuple[tuple[float, float], tuple[float, float], str]]:
    """The polygon's arrow shafts (the legend's samples, under the drawing, left out)."""
    bottom = _MARGIN + fig.drawing[1] + 0.5
    return [(p.points[0], p.points[1], p.style) for p in fig.items
            if isinstance(p, Path) and p.style in ("vector", "vector_result")
            and len(p.points) == 2 and max(y for _, y in p.points) <= bottom]


def _shared(a, b, p, q) -> float:
    """How far (mm) shaft p–q runs along shaft a–b, within a line's width (0.3 mm) of it."""
    n = math.dist(a, b)
    u = ((b[0] - a[0]) / n, (b[1] - a[1]) / n)
    if any(abs((e[0] - a[0]) * u[1] - (e[1] - a[1]) * u[0]) > 0.3 for e in (p, q)):
        return 0.0
    s, t = sorted((e[0] - a[0]) * u[0] + (e[1] - a[1]) * u[1] for e in (p, q))
    return max(0.0, min(t, n) - max(s, 0.0))


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("kind", KINDS)
def test_no_vector_is_drawn_over_another(solved, engine, kind):
    fig = solved(engine).figures[kind]
    shafts = _shafts(fig)
    # every cylinder's vector named is drawn (the three's middle crank, in the central
    # plane, has no couple and no name on the couple polygon)
    named = sum(isinstance(t, Text) and t.text.startswith("cyl. ") for t in fig.items)
    assert named >= 2 and sum(style == "vector" for *_, style in shafts) == named
    for i, (a, b, _) in enumerate(shafts):
        for p, q, _ in shafts[i + 1:]:
            # shafts meeting end to end share no more than the round caps of their ends
            assert _shared(a, b, p, q) <= 0.5, (kind, (a, b), (p, q))


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("kind", KINDS)
def test_the_scale_is_stated_in_the_readings_unit(solved, engine, kind):
    s = solved(engine)
    fig = s.figures[kind]
    texts = [t.text for t in fig.items if isinstance(t, Text)]
    unit = "N·m" if kind.endswith("couple") else "N"
    scale = next(t for t in texts if t.startswith("Scale "))
    m = re.fullmatch(r"Scale 1 cm = ([\d.]+) (\S+)", scale)
    assert m and m.group(2) == unit
    reading = next((t for t in texts if "unbalanced" in t), None)
    if reading is None:
        return
    assert f" {unit} unbalanced" in reading
    # The closing side measured on the paper, at the stated scale, is the reading: to the
    # reading's four figures (its last digit's half is under 0.02 % of it).
    (a, b, _), = [sh for sh in _shafts(fig) if sh[2] == "vector_result"]
    drawn = (math.dist(a, b) + _HEAD_STOP) / 10.0 * float(m.group(1))
    said = float(reading.split()[0])
    assert drawn == pytest.approx(said, rel=5e-4)
