"""What a grade is written as: a terminal table, grade.json, the overlay grade.svg
(:mod:`.overlay`), the student's page feedback.html and .pdf (:mod:`.feedback`), and for a
class, a folder of those for each file graded, grades.csv, the class's plot summary.svg
(:mod:`.summary`) and, the students known, the gradebooks (:mod:`.lms`), written as one
set.
"""

from __future__ import annotations

import csv
import io
import json

from tarsim.constructions.narration import speaking, spoken
from .feedback import feedback_html, feedback_pdf
from .grade import Grade
from .lms import LMS_FILES, as_text, canvas_csv, item_title, moodle_csv
from .overlay import overlay_svg
from .roster import Row
from .summary import SUMMARY, summary_svg

__all__ = ["grade_table", "grade_files", "class_csv", "class_folder", "SHEET", "FEEDBACK",
           "CLASS_FILES"]

SHEET = "grades.csv"
"""A class's sheet, in the output folder beside the drawings' folders."""

FEEDBACK = "feedback.html"
"""A student's page, in their drawing's folder."""

CLASS_FILES = (SHEET, SUMMARY, *LMS_FILES)
"""The files a class's run writes beside the drawings' folders."""


def grade_table(g: Grade) -> str:
    """The grade as the terminal prints it: one line an item, then the score."""
    lines = [f"{g.source}: {g.exercise}"]
    width = max([len(i.name) for i in g.items] + [4])
    said = max([len(i.verdict) for i in g.items] + [16])
    unit = " mm" if g.overlay is not None else " SI"    # a drawing's paper, a table's units
    for i in g.items:
        tol = "" if i.tolerance is None else f"  (± {i.tolerance:.3g}{unit})"
        lines.append(f"  {i.name:<{width}}  {i.verdict:<{said}}{tol}  {i.message}".rstrip())
    lines += [f"  note: {n}" for n in g.notes]
    lines.append(f"  score {g.score:.0f} % ({sum(g.scores(i) for i in g.items)} of "
                 f"{len(g.items)} credited)")
    return "\n".join(lines)


def grade_files(g: Grade, *, who: str = "", position: int | None = None,
                pdf: bool = False) -> dict[str, str | bytes]:
    """A drawing's or a table's files, by name: grade.json; for a drawing, grade.svg; the
    student's page feedback.html (for ``who``, at the exercise's ``position``-th
    position), and with ``pdf`` feedback.pdf (which needs libcairo).

    Raises
    ------
    RenderError
        With ``pdf``, if cairosvg or libcairo2 is missing.
    """
    files: dict[str, str | bytes] = {
        "grade.json": json.dumps(g.as_json(), indent=1, ensure_ascii=False) + "\n"}
    overlay = overlay_svg(g) if g.overlay is not None else None
    if overlay is not None:
        files["grade.svg"] = overlay
    files[FEEDBACK] = feedback_html(g, who, overlay, position)
    if pdf:
        files["feedback.pdf"] = feedback_pdf(g, who, overlay, position)
    return files


def class_csv(rows: list[Row]) -> str:
    """grades.csv: a row a file of the class folder and a row a student on the roster who
    handed in none; each gives the file's name, the folder its grade went into, the
    student's id and name (if known), the score and each item's verdict, or why there is
    no grade, and the notes."""
    names = sorted({i.name for r in rows if isinstance(r.outcome, Grade)
                    for i in r.outcome.items})
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(as_text(["drawing", "folder", "id", "name", "score", *names, "note"]))
    for r in rows:
        who = [r.student.id, r.student.name] if r.student else ["", ""]
        if not isinstance(r.outcome, Grade):
            w.writerow(as_text([r.drawing, "", *who, "", *[""] * len(names),
                                "; ".join(n for n in (r.outcome, r.note) if n)]))
            continue
        g = r.outcome
        verdicts = {i.name: i.verdict for i in g.items}
        w.writerow(as_text([r.drawing, r.folder, *who, f"{g.score:.1f}",
                            *[verdicts.get(n, "") for n in names],
                            "; ".join(n for n in (r.note, *g.notes) if n)]))
    return out.getvalue()


def class_folder(rows: list[Row], exercise: str, *, position: int = 0, pdf: bool = False,
                 lms: bool = False, workers: int = 1) -> dict[str, str | bytes]:
    """A class's output folder, by file name: each graded file's :func:`grade_files` in
    its own folder, :data:`SHEET`, :data:`~.summary.SUMMARY` and, with ``lms`` (the
    students known), the gradebooks :data:`~.lms.LMS_FILES`, of the ``exercise`` (its id)
    at its ``position``-th position. The PDFs, cairosvg's slowest work by far, are made on
    ``workers`` processes.

    Raises
    ------
    RenderError
        With ``pdf``, if cairosvg or libcairo2 is missing.
    """
    files: dict[str, str | bytes] = {}
    graded = [r for r in rows if isinstance(r.outcome, Grade)]
    pages = []
    for r in graded:
        who = "" if r.student is None else (f"{r.student.name} ({r.student.id})"
                                             if r.student.name else r.student.id)
        made = grade_files(r.outcome, who=who, position=position)
        files.update({f"{r.folder}/{name}": data for name, data in made.items()})
        pages.append((r.outcome, who, made.get("grade.svg"), position, spoken()))
    if pdf:
        for r, data in zip(graded, _in_turn(_pdf, pages, workers)):
            files[f"{r.folder}/feedback.pdf"] = data
    files[SHEET] = class_csv(rows)
    unread = sum(1 for r in rows if r.file is not None and not isinstance(r.outcome, Grade))
    files[SUMMARY] = summary_svg([r.outcome for r in graded], exercise, unread)
    if lms:
        title = item_title(exercise, position)
        files["moodle.csv"] = moodle_csv(rows, title)
        files["canvas.csv"] = canvas_csv(rows, title)
    return files


def _pdf(page: tuple) -> bytes:
    """feedback.pdf of one page: (grade, who, overlay, position, language)."""
    g, who, overlay, position, lang = page
    with speaking(lang):
        return feedback_pdf(g, who, overlay, position)


def _in_turn(fn, jobs: list, workers: int) -> list:
    """``fn`` of each job, in order, on ``workers`` processes (here, if one)."""
    if workers <= 1 or len(jobs) < 2:
        return [fn(job) for job in jobs]
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(max_workers=workers) as pool:
        return list(pool.map(fn, jobs, chunksize=max(1, len(jobs) // (4 * workers))))
