"""What a grade is written as: a terminal table, grade.json, the overlay grade.svg, and for
a class, a folder of those for each drawing and grades.csv, written as one set.

The overlay redraws the student's drawing in grey, the polygons tarsim expects in blue in
the drawing's own frame (its pole, turn, hand and scale), and rings each tip graded wrong
in red with its verdict beside it.
"""

from __future__ import annotations

import csv
import io
import json
import math

from ...constructions.narration import Number, words
from ...graphics.rtl import is_rtl
from .grade import Grade

__all__ = ["grade_table", "grade_files", "class_csv", "class_folder", "SHEET"]

SHEET = "grades.csv"
"""A class's sheet, in the output folder beside the drawings' folders."""

_BLUE, _RED, _GREY = "#1f5fbf", "#c62828", "#9e9e9e"


def grade_table(g: Grade) -> str:
    """The grade as the terminal prints it: one line an item, then the score."""
    lines = [f"{g.source}: {g.exercise}"]
    width = max([len(i.name) for i in g.items] + [4])
    for i in g.items:
        tol = "" if i.tolerance is None else f"  (± {i.tolerance:.3g})"
        lines.append(f"  {i.name:<{width}}  {i.verdict:<16}{tol}  {i.message}".rstrip())
    lines += [f"  note: {n}" for n in g.notes]
    lines.append(f"  score {g.score:.0f} % ({sum(i.verdict == 'correct' for i in g.items)} of "
                 f"{len(g.items)} correct)")
    return "\n".join(lines)


def grade_files(g: Grade) -> dict[str, str]:
    """grade.json, and for a drawing grade.svg, by file name."""
    files = {"grade.json": json.dumps(g.as_json(), indent=1, ensure_ascii=False) + "\n"}
    if g.overlay is not None:
        files["grade.svg"] = _overlay(g)
    return files


def _overlay(g: Grade) -> str:
    """The student's drawing, tarsim's polygons over it, the wrong tips ringed."""
    import svgwrite

    drawing, polygons = g.overlay
    pts = drawing.ends() + [c for c, _ in drawing.circles] + [lb.at for lb in drawing.labels]
    for item in g.items:
        pts += [tuple(p) for p in (item.expected, item.found)
                if isinstance(p, list) and len(p) == 2]
    if not pts:
        pts = [(0.0, 0.0), (100.0, 100.0)]
    x0, y0 = min(p[0] for p in pts) - 15, min(p[1] for p in pts) - 15
    x1, y1 = max(p[0] for p in pts) + 15, max(p[1] for p in pts) + 25
    dwg = svgwrite.Drawing(size=(f"{x1 - x0:.2f}mm", f"{y1 - y0:.2f}mm"),
                           viewBox=f"{x0:.3f} {y0:.3f} {x1 - x0:.3f} {y1 - y0:.3f}",
                           profile="full", debug=False)
    student = dwg.add(dwg.g(stroke=_GREY, stroke_width=0.35, fill="none"))
    if drawing.segments:                     # one path: a drawing may hold thousands
        student.add(dwg.path(d=" ".join(f"M{a[0]:.3f} {a[1]:.3f}L{b[0]:.3f} {b[1]:.3f}"
                                        for a, b in drawing.segments)))
    for c, r in drawing.circles:
        student.add(dwg.circle(c, r))
    lettering = dwg.add(dwg.g(fill=_GREY, font_size=3.2, font_family="DejaVu Serif"))
    for label in drawing.labels:
        lettering.add(dwg.text(label.text, insert=label.at))
    right = dwg.add(dwg.g(stroke=_BLUE, stroke_width=0.3, fill="none",
                          stroke_dasharray="1.6,0.8"))
    for drawn in polygons:
        if drawn is None:
            continue
        _, _, pole, expected = drawn
        for tip in expected.values():
            if math.dist(tip, pole) > 0.3:
                right.add(dwg.line(pole, tip))
                right.add(dwg.circle(tip, 0.6))
    marks = dwg.add(dwg.g(stroke=_RED, stroke_width=0.4, fill="none"))
    notes = dwg.add(dwg.g(fill=_RED, font_size=3.0, font_family="DejaVu Sans"))
    for item in g.items:
        if item.verdict == "correct":
            continue
        at = item.found if isinstance(item.found, list) else item.expected
        if not isinstance(at, list):
            continue
        marks.add(dwg.circle(tuple(at), 2.5))
        if isinstance(item.found, list) and isinstance(item.expected, list):
            marks.add(dwg.line(tuple(item.found), tuple(item.expected)))
        notes.add(_said(dwg, f"{item.name}: {words(item.verdict)}", (at[0] + 3.2, at[1] - 3.2)))
    dwg.add(_said(dwg, words("{source}: score {score} %", source=g.source,
                             score=Number(g.score, ".0f")), (x0 + 5, y1 - 6),
                  font_size=4.0, font_family="DejaVu Sans", fill="#000"))
    return dwg.tostring()


def _said(dwg, text: str, at: tuple[float, float], **style):
    """A line of the overlay that reads on from ``at``, right to left in Persian (its
    logical end at ``at``, so it runs rightwards on the page as an English one does)."""
    if is_rtl(text):
        style |= {"direction": "rtl", "text_anchor": "end"}
    return dwg.text(text, insert=at, **style)


def class_csv(grades: list[tuple[str, str, Grade | str]]) -> str:
    """grades.csv: a row a file (its name and the folder its grade went into), the score and
    each item's verdict, or why the file was not graded."""
    names = sorted({i.name for _, _, g in grades if not isinstance(g, str) for i in g.items})
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(["drawing", "folder", "score", *names, "note"])
    for source, folder, g in grades:
        if isinstance(g, str):
            w.writerow([source, "", "", *[""] * len(names), g])
            continue
        verdicts = {i.name: i.verdict for i in g.items}
        w.writerow([source, folder, f"{g.score:.1f}", *[verdicts.get(n, "") for n in names],
                    "; ".join(g.notes)])
    return out.getvalue()


def class_folder(grades: list[tuple[str, str, Grade | str]]) -> dict[str, str]:
    """A class's output folder, by file name: each graded drawing's grade.json (and
    grade.svg) in its own folder, and :data:`SHEET`."""
    files = {f"{folder}/{name}": text for _, folder, g in grades if not isinstance(g, str)
             for name, text in grade_files(g).items()}
    files[SHEET] = class_csv(grades)
    return files
