"""The grade of one drawing or one table of answers: items, verdicts and a score.

**Scheme.** Every item a drawing is graded on counts one point, or the points the
exercise's ``[grading] weights`` give it: each tip of a polygon the exercise asks about or
the drawing labels (the input's own tip only when a scale is stated, since otherwise it sets
the scale), each centre, and each number of an answers table. An item is ``correct``
within its tolerance; ``wrong magnitude``, ``wrong direction``, ``wrong sense``
(a vector), ``wrong position`` (an instant centre), ``missing`` or ``extra`` otherwise, and
scores nothing. The score is the share of the points scored, in per cent.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from pathlib import Path

from ...constructions.errors import InputError

__all__ = ["Grade", "Item", "VERDICTS", "grade"]

VERDICTS = ("correct", "wrong magnitude", "wrong direction", "wrong sense", "wrong position",
            "missing", "extra")
"""Every verdict an item may get."""


@dataclass
class Item:
    """One graded item: its name, verdict, what was expected and found (paper mm for a
    drawn tip, SI for a number), the tolerance it was held to, and a line of advice."""

    name: str
    verdict: str
    expected: object = None
    found: object = None
    tolerance: float | None = None
    message: str = ""


@dataclass
class Grade:
    """A drawing's or a table's grade."""

    exercise: str
    source: str
    items: list[Item] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    overlay: object = None
    """What the overlay draws (the drawing and the polygons expected), if a drawing."""
    weights: dict[str, float] = field(default_factory=dict)
    """Points an item scores, by name (1 for any other)."""

    @property
    def score(self) -> float:
        """Per cent of the points scored (an extra is an item too, and scores nothing)."""
        total = sum(self.weights.get(i.name, 1.0) for i in self.items)
        if not total:
            return 0.0
        return 100.0 * sum(self.weights.get(i.name, 1.0) for i in self.items
                           if i.verdict == "correct") / total

    def as_json(self) -> dict:
        """grade.json's content."""
        return {"exercise": self.exercise, "drawing": self.source,
                "score": round(self.score, 2),
                "items": [asdict(i) for i in self.items], "notes": self.notes}


def grade(exercise, source: str | Path, position: int = 0, positions=None) -> Grade:
    """Grade ``source`` (an SVG drawing, or a JSON or CSV table of answers) against the
    solved ``exercise`` at its ``position``-th position (``positions``: the exercise solved
    already, as a class is graded against one solve).

    Raises
    ------
    InputError
        If the file cannot be read as any of them, in one line naming it.
    """
    from ..solution import solve_positions
    from .answers import grade_answers
    from .centres import grade_centres
    from .drafting import DRAFTING
    from .drawing import file_name, read_drawing
    from .polygon import grade_polygons

    path = Path(source)
    positions = solve_positions(exercise) if positions is None else positions
    if not positions:
        raise InputError(f"{exercise.id}: it solves no position, so there is nothing drawn "
                         "to grade against")
    if not 0 <= position < len(positions):
        raise InputError(f"{exercise.id} has {len(positions)} position(s); position "
                         f"{position + 1} does not exist")
    sol = positions[position]
    drafting = getattr(exercise, "drafting", None) or DRAFTING
    suffix = path.suffix.lower()
    if suffix in (".json", ".csv"):
        out = grade_answers(exercise.id, sol, path, drafting)
        out.weights = dict(drafting.weights)
        return out
    if suffix != ".svg":
        raise InputError("a drawing is an .svg, and a table of answers a .json or .csv",
                         file=file_name(path))
    drawing = read_drawing(path)
    out = Grade(exercise.id, file_name(path), overlay=(drawing, []),
                weights=dict(drafting.weights))
    out.notes += drawing.notes
    grade_polygons(out, sol, drawing, drafting)
    grade_centres(out, sol, drawing, drafting)
    if not out.items and not out.notes:
        out.notes.append("no labels naming a pole, a tip or a centre were found (o, a, b, … "
                         "for velocities; o′, a′, … for accelerations; I13 or 13 for "
                         "centres): nothing could be graded")
    return out
