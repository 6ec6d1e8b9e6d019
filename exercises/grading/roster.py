"""Students, not files: who handed in each file of a class folder, from a roster or from
the files' names, and a row of the class's sheet for every student and every file.

A roster is a CSV file with a row a student: their id, their name and the file they
handed in (:data:`HEADERS` gives the names a column may be headed by). A file-name
pattern (:class:`Pattern`) reads the id, and the name, off each file's name instead, as
a course's upload names them ("{id}_{name}.svg"). Both may be given: the roster's file
column names a student's file where it has one, the pattern the rest. A student with no
file gets a row saying so, and a file no student is found for is graded with a row saying
that: nothing is passed over without a word.
"""

from __future__ import annotations

import csv
import re
from dataclasses import dataclass
from pathlib import Path

from tarsim.constructions.errors import InputError
from .batch import ClassFile
from .drawing import printable
from .grade import Grade

__all__ = ["Student", "Row", "HEADERS", "Pattern", "read_roster", "class_rows",
           "NO_DRAWING"]

HEADERS = {
    "id": ("id", "student id", "student number", "id number", "شماره دانشجویی"),
    "name": ("name", "full name", "student", "student name", "نام"),
    "file": ("file", "file name", "filename", "drawing", "فایل"),
}
"""The headers a roster's columns are known by, in any case, with ``_`` or ``-`` for a
space: the student's id (needed), their name and the file they handed in."""

NO_DRAWING = "no drawing handed in"
"""The row of a student on the roster whom no file is found for."""

MAX_ROSTER = 1_000_000
"""The largest roster read (bytes): a class of thousands is some tens of kilobytes."""


@dataclass(frozen=True)
class Student:
    """A student: the id the course knows them by, and their name (may be empty)."""

    id: str
    name: str = ""


@dataclass
class Row:
    """A row of the class's sheet: a file of the class folder (None for a student who
    handed in none), the student it is (None if none is found), its grade or why there
    is none (``outcome``), and what the match says (``note``)."""

    file: ClassFile | None
    student: Student | None = None
    outcome: Grade | str = ""
    note: str = ""

    @property
    def drawing(self) -> str:
        """The file's name as grades.csv gives it ("" if none)."""
        return self.file.name if self.file else ""

    @property
    def folder(self) -> str:
        """The folder its grade went into ("" if it has no grade)."""
        return self.file.folder if self.file and isinstance(self.outcome, Grade) else ""


# ----- a roster -------------------------------------------------------------------------
@dataclass(frozen=True)
class Roster:
    """A roster read: its students in its order, and the file each names ("" if none)."""

    students: list[Student]
    files: dict[str, str]
    """Student id → the file name the roster gives (only those it gives)."""
    source: str = "roster"
    """The roster's file name, as its errors give it."""


def read_roster(path: str | Path) -> Roster:
    """Read the roster CSV at ``path`` (UTF-8, a byte-order mark allowed): a header row
    naming its columns by :data:`HEADERS`, then a row a student.

    Raises
    ------
    InputError
        Naming the file and line: it cannot be read, has no id column, two columns of one
        kind, a row with no id, or an id or a file on two rows.
    """
    path = Path(path)
    name = printable(path.name)
    try:
        if not path.is_file():
            raise InputError("not a file; give the roster as a .csv file", file=name)
        if path.stat().st_size > MAX_ROSTER:
            raise InputError(f"is more than a roster holds ({MAX_ROSTER} bytes)", file=name)
        text = path.read_bytes().decode("utf-8-sig")
    except OSError as e:
        raise InputError(f"cannot be read ({e.strerror or e})", file=name) from None
    except UnicodeDecodeError:
        raise InputError("is not UTF-8 text; save the roster as CSV (UTF-8)", file=name
                         ) from None
    try:
        rows = list(csv.reader(text.splitlines()))
    except csv.Error as e:
        raise InputError(f"is not a CSV file ({e})", file=name) from None
    if not rows:
        raise InputError("is empty; give a header row (id, name, file) and a row a student",
                         file=name)
    columns = _columns(rows[0], name)
    students, files, seen_file = [], {}, {}
    lines: dict[str, int] = {}
    for line, row in enumerate(rows[1:], start=2):
        if not any(cell.strip() for cell in row):
            continue
        cell = {kind: row[i].strip() if i < len(row) else "" for kind, i in columns.items()}
        sid = cell["id"]
        if not sid:
            raise InputError("a row with no student id; give each student's id", file=name,
                             line=line)
        if sid in lines:
            raise InputError(f"student {printable(sid)[:40]} is on line {lines[sid]} too; "
                             "give each student one row", file=name, line=line)
        lines[sid] = line
        students.append(Student(sid, cell.get("name", "")))
        if cell.get("file"):
            drawn = cell["file"]
            if drawn.casefold() in seen_file:
                raise InputError(f"the file {printable(drawn)[:60]} is named on line "
                                 f"{seen_file[drawn.casefold()]} too; one file is one "
                                 "student's", file=name, line=line)
            seen_file[drawn.casefold()] = line
            files[sid] = drawn
    if not students:
        raise InputError("has no students, only a header row", file=name)
    return Roster(students, files, name)


def _columns(header: list[str], name: str) -> dict[str, int]:
    """Which column of ``header`` gives each kind of :data:`HEADERS` (id is needed)."""
    found: dict[str, int] = {}
    for i, title in enumerate(header):
        said = re.sub(r"[\s_-]+", " ", title.strip().casefold())
        for kind, names in HEADERS.items():
            if said in names:
                if kind in found:
                    raise InputError(f"columns '{header[found[kind]].strip()}' and "
                                     f"'{title.strip()}' both give the student's {kind}; "
                                     "keep one", file=name, line=1)
                found[kind] = i
    if "id" not in found:
        raise InputError("no column of student ids: head one "
                         + ", ".join(f"'{h}'" for h in HEADERS["id"][:4])
                         + " (and the others 'name' and 'file')", file=name, line=1)
    return found


# ----- a file-name pattern --------------------------------------------------------------
class Pattern:
    """A file-name pattern: ``{id}`` and ``{name}`` stand for the student's id and name,
    ``*`` for any text, and the rest is the name as written (in any case). A pattern with
    an ending (``{id}_{name}.svg``) is matched against whole names; one without
    (``{id}_{name}``) against names less their ending, so it fits a student's file
    whatever they saved it as.

    >>> Pattern("{id}_{name}.svg").match("9812_Ali Rezaei.svg")
    Student(id='9812', name='Ali Rezaei')

    Raises
    ------
    InputError
        If it has no ``{id}``, a field twice, or a field it does not know.
    """

    def __init__(self, text: str):
        self.text = text
        fields = re.findall(r"\{([^{}]*)\}", text)
        unknown = [f for f in fields if f not in ("id", "name")]
        if unknown or "id" not in fields or len(set(fields)) < len(fields) \
                or re.search(r"[{}]", re.sub(r"\{(id|name)\}", "", text)):
            raise InputError(f"'{printable(text)[:60]}' must hold {{id}} once, and may hold "
                             "{name} once and * for any text (e.g. '{id}_{name}.svg')",
                             file="--pattern")
        self.whole = bool(Path(text).suffix)
        parts = re.split(r"(\{id\}|\{name\}|\*)", text)
        self._regex = re.compile("".join(
            {"{id}": r"(?P<id>.+?)", "{name}": r"(?P<name>.+?)", "*": ".*?"}.get(p,
                                                                                re.escape(p))
            for p in parts), re.IGNORECASE | re.DOTALL)

    def match(self, name: str) -> Student | None:
        """The student the file ``name`` is of, or None if the name does not fit."""
        against = name if self.whole else (name[:name.rfind(".")] if "." in name[1:]
                                           else name)
        m = self._regex.fullmatch(against)
        if not m or not m["id"].strip():
            return None
        return Student(m["id"].strip(), (m.groupdict().get("name") or "").strip())


# ----- a row for every student and every file -------------------------------------------
def class_rows(files: list[ClassFile], roster: Roster | None = None,
               pattern: Pattern | None = None) -> list[Row]:
    """A row for every file of the class, and for every student on the roster who handed
    in none (:data:`NO_DRAWING`), in the roster's order and then the files' (or the files'
    order alone, with no roster). A file is a student's when the roster's file column
    names it, else when ``pattern`` reads their id off its name; a file that is nobody's,
    or a second file for one student, is said so in its row's note.

    Raises
    ------
    InputError
        If a roster with no file column comes with no pattern.
    """
    if roster is None and pattern is None:
        return [Row(f) for f in files]
    if pattern is None and not roster.files:
        raise InputError("the roster names no student's file: give each in a column headed "
                         "'file', or --pattern to read their ids off the files' names",
                         file=roster.source)
    by_name = {f.path.name.casefold(): f for f in files}
    owner: dict[str, Student] = {}                   # file name (casefolded) → student
    missing_named: dict[str, str] = {}
    known = {s.id: s for s in roster.students} if roster else {}
    if roster:
        for s in roster.students:
            named = roster.files.get(s.id)
            if named is None:
                continue
            if named.casefold() in by_name:
                owner[named.casefold()] = s
            else:
                missing_named[s.id] = named
    unknown: dict[str, str] = {}
    if pattern:
        for f in files:
            key = f.path.name.casefold()
            if key in owner:
                continue
            read = pattern.match(f.path.name)
            if read is None:
                unknown[key] = f"its name does not fit the pattern {pattern.text}"
            elif roster and read.id not in known:
                unknown[key] = f"student {read.id} is not on the roster"
            elif roster and read.id in roster.files and read.id not in missing_named:
                unknown[key] = (f"the roster gives student {read.id}'s file as "
                                f"{printable(roster.files[read.id])[:60]}")
            else:
                owner[key] = known.get(read.id, read)
    else:
        unknown = {f.path.name.casefold(): "no roster row names this file" for f in files
                   if f.path.name.casefold() not in owner}
    return _rows(files, roster, owner, unknown, missing_named)


def _rows(files, roster, owner, unknown, missing_named) -> list[Row]:
    """The rows, once each file's student is known (see :func:`class_rows`)."""
    handed: dict[str, list[ClassFile]] = {}
    for f in files:
        if (s := owner.get(f.path.name.casefold())) is not None:
            handed.setdefault(s.id, []).append(f)
    rows: list[Row] = []
    students = roster.students if roster else []
    for s in students:
        theirs = handed.get(s.id, [])
        if not theirs:
            why = NO_DRAWING + (f" (the roster names {printable(missing_named[s.id])[:60]}, "
                                "which is not in the class folder)"
                                if s.id in missing_named else "")
            rows.append(Row(None, s, why))
        rows += [Row(f, s, note=_twice(theirs)) for f in theirs]
    listed = {id(r.file) for r in rows if r.file is not None}
    for f in files:
        if id(f) in listed:
            continue
        s = owner.get(f.path.name.casefold())
        theirs = handed.get(s.id, []) if s else []
        rows.append(Row(f, s, note=_twice(theirs) if s else unknown[f.path.name.casefold()]))
    return rows


def _twice(theirs: list[ClassFile]) -> str:
    """The note of a student who handed in more than one file."""
    if len(theirs) < 2:
        return ""
    return (f"{len(theirs)} files for one student (" + ", ".join(f.name for f in theirs)
            + "): their grade is left to you")
