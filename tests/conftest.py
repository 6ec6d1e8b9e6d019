"""Fixtures shared across modules: the bundled exercises, each solved once per test run.

Solving an exercise (assembly, constructions, figures) is the slowest thing the
tests do, and several modules read the same solution: the crank-shaper's is read
by the catalog, limit-position, scale, pruning and polygon tests. A solution is
not changed by reading it, so one per run serves them all.
"""

from __future__ import annotations

import pytest

from tarsim import solve
from tarsim.exercises.catalog import load
from tarsim.exercises.linkages.solution_files import WorkedSolution

from tests.browser import chromium


@pytest.fixture(scope="session")
def solved():
    """``solved(exercise_id)``: the bundled exercise, of any chapter, solved and drawn, once
    per run."""
    cache: dict[str, WorkedSolution] = {}

    def get(exercise_id: str) -> WorkedSolution:
        if exercise_id not in cache:
            cache[exercise_id] = solve(load(exercise_id))
        return cache[exercise_id]
    return get


@pytest.fixture(scope="session")
def files(solved):
    """``files(exercise_id)``: every file of the bundled exercise's solution, as text, once."""
    cache: dict[str, dict[str, str]] = {}

    def get(exercise_id: str) -> dict[str, str]:
        if exercise_id not in cache:
            cache[exercise_id] = solved(exercise_id).files()
        return cache[exercise_id]
    return get


@pytest.fixture(scope="module")
def browser():
    """A headless chromium for a module's browser tests (a test file runs on one worker:
    --dist loadfile). It is closed with its module: while it runs, its driver's thread
    keeps the figures from being drawn on forked workers."""
    with chromium() as b:
        yield b
