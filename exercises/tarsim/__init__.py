"""tarsim (ترسیم, "graphical construction"): the compass-and-ruler methods of planar
mechanism kinematics, drawn as textbook figures and checked against an analytic solution.

>>> import tarsim
>>> solution = tarsim.solve(tarsim.load("four-bar"))
>>> solution.passed, sorted(solution.figures)[:2]
(True, ['V_B-components', 'V_B-parallel-line'])

Installed, this file is the ``tarsim`` package itself; the repository keeps the
three layers in its top-level folders, installed as ``tarsim.constructions``
(the geometry kernel, the construction record, the methods and the analytic
reference), ``tarsim.graphics`` (figures) and ``tarsim.exercises`` (files, the
bundled catalog, the command line).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from tarsim.exercises.linkages.exercise_file import Exercise
    from tarsim.exercises.linkages.solution_files import WorkedSolution

__all__ = ["load", "solve", "Exercise", "WorkedSolution"]


def __getattr__(name: str) -> Any:
    # The solver, the figures and their libraries load on first use, so ``tarsim --help``
    # and ``import tarsim`` stay quick.
    if name == "Exercise":
        from tarsim.exercises.linkages.exercise_file import Exercise
        return Exercise
    if name == "WorkedSolution":
        from tarsim.exercises.linkages.solution_files import WorkedSolution
        return WorkedSolution
    raise AttributeError(f"module 'tarsim' has no attribute {name!r}")


def load(source: str | Path) -> Exercise:
    """Read an exercise: a TOML file's path, or the id of a bundled one (``tarsim list``).

    Raises
    ------
    tarsim.constructions.errors.InputError
        If it cannot be read, naming file:line and what to fix.
    """
    from tarsim.exercises.catalog import load as _load
    return _load(source)


def solve(exercise: Exercise) -> WorkedSolution:
    """Solve an exercise by construction and check every number against the analytic solver.

    The solution has ``.results`` (the results.json document), ``.figures``
    (file stem → figure, each with ``.save(path)``, shown inline in a notebook),
    ``.steps()`` (steps.md), ``.passed`` and ``.write(folder)``; a gear train's
    (``[[gear]]`` tables) the same, solved by the notes' tabular method; a cam's (``[cam]``)
    its follower's motion and its profile laid out by inversion (an undercut refused).

    Raises
    ------
    tarsim.constructions.errors.TarsimError
        If the mechanism cannot be assembled or a construction breaks down.
    """
    from tarsim.exercises.chapters import chapter_of

    return chapter_of(exercise).solve(exercise)
