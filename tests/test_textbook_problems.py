"""Textbook problems as the books state them (tests/data/textbook): every asked quantity
that can be stated is answered, and each answer agrees with its closed form
(benchmarks/textbook_problems.py prints the share stated directly)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from benchmarks.textbook_problems import CORPUS, closed_form, outcomes  # noqa: E402

PROBLEMS = sorted(CORPUS.glob("*.toml"))


def test_the_corpus_is_there():
    assert len(PROBLEMS) >= 7


@pytest.mark.parametrize("path", PROBLEMS, ids=lambda p: p.stem)
def test_each_stated_quantity_is_its_closed_form(path):
    for what, outcome, detail in outcomes(path):
        assert outcome in ("stated", "not stated"), f"{what}: {outcome}, {detail}"


def test_a_closed_form_is_arithmetic_alone():
    """The corpus's closed forms see numbers and the named functions, nothing else."""
    assert closed_form("hypot(3, 4) + 2*pi/60*0") == 5.0
    with pytest.raises(NameError):
        closed_form("__import__('os')")
