"""A class's grades as Moodle's and Canvas's gradebooks import them: moodle.csv and
canvas.csv, beside grades.csv, a row a student.

Both are written whenever the students are known (a roster or a file-name pattern):
each is a few kilobytes, a course uses one or the other, and writing both spares an
option to get wrong and a second run. Without students there is no id for a gradebook
to match a row by, so neither is written.

A student's score is their drawing's, in per cent (out of 100). A student with no
drawing, one whose file could not be graded, or one who handed in two files gets an
empty score: both gradebooks then leave the grade as it was, and the teacher decides;
the Moodle file's feedback column says why.

**Moodle** (Grades › Import › CSV file; docs.moodle.org "Grade import", and
``grade/import/csv`` in Moodle's source, whose tests import a file headed
``"First name",Surname,"ID number",…,"Assignment: …","Feedback: …"``): the first row
names the columns; at import the teacher maps *Map from* "ID number" to *Map to*
"useridnumber", the score's column to a grade item (or a new one) and the feedback's to
that item's feedback. Moodle asks that a grade and its feedback be imported together.

**Canvas** (Grades › Import; Canvas's ``app/models/gradebook_importer.rb``): the header
must open with ``Student`` and ``ID`` and end its student columns with ``Section``; with
``SIS User ID`` and ``SIS Login ID`` between them, a row is matched by its Canvas ID, else
its SIS User ID, else its SIS Login ID, else the student's name. The roster's id goes in
``SIS User ID`` and ``ID`` is left empty (tarsim cannot know Canvas's own numbers, and
a wrong one would grade another student). A second row starting ``Points Possible``
gives the assignment's out-of; a column whose title matches no assignment makes a new
one, and a title ending in a number in brackets is read as an assignment's id, so the
column is titled without one.
"""

from __future__ import annotations

import csv
import io

from .grade import Grade
from .overlay import credited
from .roster import Row

__all__ = ["moodle_csv", "canvas_csv", "LMS_FILES", "item_title", "as_text"]

LMS_FILES = ("moodle.csv", "canvas.csv")
"""The gradebook files, in the output folder beside grades.csv."""

_FORMULA = ("=", "+", "-", "@", "\t", "\r")
"""What a cell a spreadsheet would read as a formula opens with."""


def as_text(row: list[str]) -> list[str]:
    """A row's cells as a spreadsheet opens them safely: one that would be read as a
    formula (a file a student named "=HYPERLINK(…).svg") is led by an apostrophe, which
    keeps it text.

    >>> as_text(["=1+1.svg", "ali.svg", "75.00"])
    ["'=1+1.svg", 'ali.svg', '75.00']
    """
    return [f"'{c}" if c.startswith(_FORMULA) else c for c in row]


def item_title(exercise: str, position: int) -> str:
    """The grade column's title: the exercise, and its position if not the first (never a
    number in brackets, which Canvas reads as an assignment's id).

    >>> item_title("crank-shaper", 1)
    'crank-shaper at position 2'
    """
    return exercise if position == 0 else f"{exercise} at position {position + 1}"


def _graded(rows: list[Row]) -> dict[str, list[Row]]:
    """Each student's rows, by id, in the rows' order."""
    out: dict[str, list[Row]] = {}
    for r in rows:
        if r.student is not None:
            out.setdefault(r.student.id, []).append(r)
    return out


def _score_and_word(theirs: list[Row]) -> tuple[str, str]:
    """A student's score (per cent, "" if none stands) and the feedback that goes with it."""
    if len(theirs) > 1:
        return "", (f"{len(theirs)} files handed in ("
                    + ", ".join(r.drawing for r in theirs) + "): graded by hand")
    row = theirs[0]
    if not isinstance(row.outcome, Grade):
        return "", f"{row.drawing}: {row.outcome}" if row.drawing else row.outcome
    g = row.outcome
    took = sum(credited(g, i) for i in g.items)
    wrong = [f"{i.name} {i.verdict}" for i in g.items if i.verdict != "correct"]
    said = f"score {g.score:.0f} % ({took} of {len(g.items)} items credited)"
    return f"{g.score:.2f}", said + ("; " + ", ".join(wrong) if wrong else "")


def moodle_csv(rows: list[Row], title: str) -> str:
    """moodle.csv: ID number, the student's name, the score in the column ``title`` and
    its feedback, a row a student (see the module's docstring)."""
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(as_text(["ID number", "Full name", title, f"Feedback: {title}"]))
    for sid, theirs in _graded(rows).items():
        score, said = _score_and_word(theirs)
        w.writerow(as_text([sid, theirs[0].student.name, score, said]))
    return out.getvalue()


def canvas_csv(rows: list[Row], title: str) -> str:
    """canvas.csv: Student, ID, SIS User ID, SIS Login ID, Section, then the score in the
    column ``title``, out of the 100 its Points Possible row gives (see the module's
    docstring)."""
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(as_text(["Student", "ID", "SIS User ID", "SIS Login ID", "Section", title]))
    w.writerow(["Points Possible", "", "", "", "", "100"])
    for sid, theirs in _graded(rows).items():
        score, _ = _score_and_word(theirs)
        w.writerow(as_text([theirs[0].student.name or sid, "", sid, "", "", score]))
    return out.getvalue()
