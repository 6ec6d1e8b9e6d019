"""Random inputs of every chapter are right or refused in one clear line.

The property, for an input of each family of each chapter drawn by tests/random_inputs.py's
generators (degenerate and malformed ones included): ``tarsim`` gives finite results whose
every check passes and that the chapter's own closed form does not contradict (a linkage's
loop equations, a train's tooth ratios, a cam's laws finely evaluated, a rotor's residual
force and couple, a loaded linkage's power balance), or it raises one TarsimError line that
names the file:line, a link, a point, a position or what the chapter names (a gear, a
segment, a mass, a plane, an element of a drawing) and prints no number of more than 6
significant figures. benchmarks/robustness.py runs the same cases by the hundred thousand.
"""

from __future__ import annotations

import random
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, Phase, given, note, settings
from hypothesis import strategies as st

from tests.random_inputs import CHAPTERS, chapter_module, runner, suffix

pytestmark = pytest.mark.slow

EXAMPLES = 25
"""Cases per family: the file runs in about a minute on two workers. The seeds are fixed
(``derandomize``) and not shrunk (a smaller seed is no simpler an input), so a failure
names the same case on every run; the benchmark explores beyond them."""

FAMILIES = [(chapter, family) for chapter in CHAPTERS
            for family in chapter_module(chapter).FAMILIES]


@pytest.mark.parametrize("chapter, family", FAMILIES)
@settings(max_examples=EXAMPLES, deadline=None, derandomize=True,
          phases=[Phase.explicit, Phase.generate], suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 2**32 - 1))
def test_a_random_input_is_right_or_refused_clearly(chapter, family, seed):
    _, text = chapter_module(chapter).generate(random.Random(seed), family)
    note(text if isinstance(text, str) else repr(text[:400]))
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / f"{family}-{seed}{suffix(chapter)}"
        got = runner(chapter)(text, path, render=seed % 4 == 0)
    assert got.outcome in ("ok", "refused"), (
        f"{got.outcome}: {got.message}\n{got.detail}\n{got.failures}")
