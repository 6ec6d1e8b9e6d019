"""An exercise's stated space scale ("1 cm = 4 cm") is the scale its figures are drawn at."""

from __future__ import annotations

import math
import re

import pytest

from constructions.assembly import assemble
from constructions.errors import InputError
from exercises.exercise_file import parse_exercise
from graphics.diagram import draw_kinematic_diagram
from tests.common import four_bar_toml


def _with_scale(scale: str) -> str:
    return four_bar_toml() + f'\n[ask]\nfind = ["omega4"]\nscale = "{scale}"\n'


@pytest.mark.parametrize("stated, per_cm_mm", [("1 cm = 4 cm", 40.0), ("1 cm = 50 mm", 50.0),
                                               ("1cm=0.2 m", 200.0), ("1 cm = 2.5 in", 63.5)])
def test_the_stated_scale_is_drawn_true(stated, per_cm_mm):
    ex = parse_exercise(_with_scale(stated))
    assert ex.mechanism.scale == pytest.approx(per_cm_mm)        # the file's unit is mm
    fig = draw_kinematic_diagram(assemble(ex.mechanism))
    texts = [t.text for t in fig.items if hasattr(t, "text")]
    assert any(re.fullmatch(r"Scale 1 cm = [\d.]+ mm", t) for t in texts)
    # The crank O2A (100 mm) is drawn 100 / per_cm centimetres long on paper.
    pins = [it.centre for it in fig.items if getattr(it, "style", "") == "pin"]
    lengths = sorted(math.dist(p, q) for p in pins for q in pins if p < q)
    assert any(abs(d - 10 * 100 / per_cm_mm) < 1e-6 for d in lengths)


@pytest.mark.parametrize("bad", ["4 cm", "1 cm = -4 cm", "1 cm = 4 furlongs", "2 cm = 4 cm"])
def test_a_malformed_scale_is_named_at_its_line(bad):
    with pytest.raises(InputError, match=r"ex.toml:\d+: \[ask.scale\] scale must read like "
                                         r"\"1 cm = 4 cm\""):
        parse_exercise(_with_scale(bad), "ex.toml")
