"""Every scale a balancing or flywheel figure states is a round one, as a student would
choose it: 1, 2, 2.5, 4 or 5 × 10ᵏ of its unit to the centimetre, the drafting ladder
(:data:`tarsim.graphics.fitting.DRAFTING`).

An engine's polygons are drawn in newtons, m·r·ω² a cylinder: a second m·r scale beside the
newtons' is their scale over ω², round only where ω² is ("1 cm = 0.0140724 kg·m" for the
in-line four), and is not stated; the note says what each vector is instead.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

import tarsim.exercises.catalog as catalog
from tarsim.graphics.figure import Text
from tarsim.graphics.fitting import DRAFTING

_CATALOG = Path(catalog.__file__).parent
EXERCISES = sorted(p.stem for chapter in ("balancing", "flywheel")
                   for p in (_CATALOG / chapter).glob("*.toml"))
_STATED = re.compile(r"(\d+(?:\.\d+)?) cm = ([\d.]+(?:e[+-]?\d+)?) (\S+)")


def _on_ladder(per_cm: float) -> bool:
    """Whether ``per_cm`` is 1, 2, 2.5, 4 or 5 × 10ᵏ (to a billionth, float noise)."""
    k = math.floor(math.log10(per_cm))
    return any(math.isclose(per_cm, m * 10.0 ** e, rel_tol=1e-9)
               for e in (k - 1, k, k + 1) for m in DRAFTING)


def test_the_ladder_is_the_drafting_one():
    assert [_on_ladder(v) for v in (0.025, 40.0, 5000.0, 0.0140724, 3.0, 14.58)] == \
        [True, True, True, False, False, False]


@pytest.mark.parametrize("exercise_id", EXERCISES)
def test_every_stated_scale_is_round(solved, exercise_id):
    stated = [(kind, m) for kind, fig in solved(exercise_id).figures.items()
              for t in fig.items if isinstance(t, Text)
              for m in [_STATED.search(t.text)] if m]
    for kind, m in stated:
        per_cm = float(m.group(2)) / float(m.group(1))
        assert _on_ladder(per_cm), f"{exercise_id} {kind}: {m.group()}"


@pytest.mark.parametrize("exercise_id", ["inline-four", "inline-three", "locomotive",
                                         "outside-locomotive", "two-stroke-four"])
def test_an_engine_polygon_states_one_scale_and_what_it_lays_off(solved, exercise_id):
    s = solved(exercise_id)
    for kind in ("primary-force", "primary-couple"):
        texts = [t.text for t in s.figures[kind].items if isinstance(t, Text)]
        assert sum(bool(_STATED.search(t)) for t in texts) == 1, kind
        product = "m·r·l" if kind.endswith("couple") else "m·r"
        assert any(t.startswith(f"each vector {product}·ω²") for t in texts), kind
