"""A class graded as ``tarsim grade`` grades a folder: every file of it a row of the class's
sheet, matched to its student by a roster or by its name, each drawing graded
(:func:`~.batch.grade_many`) and the class's folder made in memory
(:func:`~.report.class_folder`), for the command to write as one set.
"""

from __future__ import annotations

from collections.abc import Callable
from contextlib import AbstractContextManager
from dataclasses import dataclass
from pathlib import Path

from ..catalog import load
from .batch import class_files, grade_many
from .report import class_folder
from .roster import Pattern, Row, class_rows, read_roster

__all__ = ["ClassGrades", "grade_class"]


@dataclass
class ClassGrades:
    """A class's rows and its output folder's files, by name."""

    rows: list[Row]
    files: dict[str, str | bytes]

    def summary(self, folder: str | Path) -> str:
        """The line the command ends with: how many drawings were graded into ``folder``,
        how many could not be read, how many students handed in none."""
        handed = [r for r in self.rows if r.file is not None]
        bad = sum(isinstance(r.outcome, str) for r in handed)
        none = len(self.rows) - len(handed)
        return (f"graded {len(handed) - bad} of {len(handed)} drawings into {folder}/"
                + (f"; {bad} could not be read (see grades.csv)" if bad else "")
                + (f"; {none} student{'s' * (none > 1)} handed in none" if none else ""))


def grade_class(source: str, folder: Path, *, out: Path, position: int = 0,
                roster: str | None = None, pattern: str | None = None, pdf: bool = False,
                workers: int = 1, scheduler: str | None = None,
                bar: Callable[[int, str], AbstractContextManager] | None = None
                ) -> ClassGrades:
    """Grade every drawing in ``folder`` (``out``, the output folder, left out of it)
    against the exercise ``source`` (a bundled id or a file) at its ``position``-th
    position (from 0).

    The students are read from ``roster`` (a CSV file) and, for the files it does not
    give, off the files' names by ``pattern`` (:class:`~.roster.Pattern`); with either,
    the gradebooks are made too. The drawings are graded on ``workers`` processes, or on
    the Dask cluster at ``scheduler``, each counted on ``bar`` (of a length and a label)
    if given.

    Raises
    ------
    InputError
        If the exercise, the roster or the pattern cannot be read (before any drawing is).
    TarsimError
        If the cluster cannot be reached.
    """
    exercise = load(source).id
    students = read_roster(roster) if roster else None
    names = Pattern(pattern) if pattern else None
    found = class_files(folder, skip=out)
    rows = class_rows(found, students, names)
    read = [f for f in found if not f.refused]

    def graded(done: Callable[[], None] | None) -> list:
        return [g for _, g in grade_many(source, [f.path for f in read], position, workers,
                                         done=done, scheduler=scheduler)]

    if bar is None:
        grades = graded(None)
    else:
        with bar(len(read), f"grading {len(read)} drawings") as shown:
            grades = graded(lambda: shown.update(1))
    by_file = dict(zip(read, grades))
    for row in rows:
        if row.file is not None:
            row.outcome = row.file.refused or by_file[row.file]
    return ClassGrades(rows, class_folder(rows, exercise, position=position, pdf=pdf,
                                          lms=bool(roster or pattern), workers=workers))
