"""Every chapter's random inputs: the module that makes them and the runner that judges them.

Each module makes files the way textbooks and programs make them (``generate(rng) ->
(family, text)``), degenerate and malformed ones among them, and runs one through tarsim
with its chapter's own oracle (``runner(text, path, render=…) -> Outcome``).
benchmarks/robustness.py runs them by the hundred thousand and tests/test_robustness.py a
few of each family under hypothesis, so both read this table.
"""

from __future__ import annotations

import importlib
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

__all__ = ["CHAPTERS", "chapter_module", "runner", "suffix"]

CHAPTERS = {
    "linkages": ("random_mechanisms", "run_case", 0.40),
    "trains": ("random_trains", "run_train_case", 0.15),
    "cams": ("random_cams", "run_case", 0.15),
    "rotors": ("random_rotors", "run_case", 0.10),
    "loads": ("random_loads", "run_case", 0.10),
    "drawings": ("random_drawings", "run_case", 0.10),
}
"""Each chapter's generator module, its runner, and its share of a benchmark's cases (by
what a case costs and how many ways the chapter's files can go wrong). The linkages' oracle
is the textbook's loop equations (tests/closed_forms.py); gear trains', the speed ratios
from the tooth numbers; cams', their laws evaluated finely; rotors' and engines', the
residual force and couple; loads', the balance of power; drawings', finite grades."""


def chapter_module(chapter: str):
    """The generator module of ``chapter``."""
    return importlib.import_module(CHAPTERS[chapter][0])


def runner(chapter: str):
    """The function that runs and judges one input of ``chapter``."""
    return getattr(chapter_module(chapter), CHAPTERS[chapter][1])


def suffix(chapter: str) -> str:
    """How a file of ``chapter`` is named: a drawing is an SVG, the rest TOML."""
    return ".svg" if chapter == "drawings" else ".toml"
