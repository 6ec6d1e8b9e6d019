"""The grade of one drawing or one table of answers: items, verdicts and a score.

**Scheme.** Every item a drawing is graded on counts one point, or the points the
exercise's ``[grading] weights`` give it: each tip of a polygon the drawing labels or the
mechanism's moving points call for, each centre, and each number of an answers table. An
item is ``correct`` within its tolerance; ``follows from an earlier error`` when it is drawn
rightly from a wrong tip before it (it scores, unless the exercise's ``[grading] follow``
is false); ``wrong magnitude``, ``wrong direction``, ``wrong sense``, ``reversed
Coriolis``, ``swapped`` (a vector), ``wrong position`` (an instant centre) or ``missing``
otherwise, and scores nothing. A label that names nothing graded (a construction point, an
answer not asked) is said in a note and costs nothing. The score is the share of the points
scored, in per cent.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from pathlib import Path

from tarsim.constructions.errors import InputError

__all__ = ["Grade", "Item", "VERDICTS", "FOLLOWS", "grade"]

FOLLOWS = "follows from an earlier error"

VERDICTS = ("correct", FOLLOWS, "wrong magnitude", "wrong direction", "wrong sense",
            "reversed Coriolis", "swapped", "wrong position", "missing")
"""Every verdict an item may get."""

_BETTER = 20.0
"""Points (per cent) another position must score above the one asked, and ``_LIKELY`` at
least, for a drawing to be said to be of that position."""
_LIKELY = 75.0


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
    follow: bool = True
    """Whether an item that follows from an earlier error scores."""
    position: int = 1
    """The position graded at, from 1."""
    position_matched: int | None = None
    """Another position (from 1) the drawing matches far better, if one does."""

    def scores(self, item: Item) -> bool:
        """True if ``item`` earns its points."""
        return item.verdict == "correct" or self.follow and item.verdict == FOLLOWS

    @property
    def score(self) -> float:
        """Per cent of the points scored."""
        total = sum(self.weights.get(i.name, 1.0) for i in self.items)
        if not total:
            return 0.0
        return 100.0 * sum(self.weights.get(i.name, 1.0) for i in self.items
                           if self.scores(i)) / total

    def as_json(self) -> dict:
        """grade.json's content."""
        return {"exercise": self.exercise, "drawing": self.source, "position": self.position,
                "score": round(self.score, 2),
                **({"position_matched": self.position_matched}
                   if self.position_matched else {}),
                "items": [asdict(i) for i in self.items], "notes": self.notes}


def grade(exercise, source: str | Path, position: int = 0, positions=None) -> Grade:
    """Grade ``source`` (an SVG drawing, or a JSON or CSV table of answers) against the
    solved ``exercise`` at its ``position``-th position (``positions``: the exercise solved
    already, as a class is graded against one solve). A drawing that scores far better at
    another position is said to be of it (:attr:`Grade.position_matched`).

    Raises
    ------
    InputError
        If the file cannot be read as any of them, or nothing on it can be graded, in one
        line naming it.
    """
    from ..linkages.solution import solve_positions
    from .answers import grade_answers
    from .drafting import DRAFTING
    from .drawing import file_name, read_drawing

    path = Path(source)
    positions = solve_positions(exercise) if positions is None else positions
    if not positions:
        raise InputError(f"{exercise.id}: it solves no position, so there is nothing drawn "
                         "to grade against")
    if not 0 <= position < len(positions):
        raise InputError(f"{exercise.id} has {len(positions)} position(s); position "
                         f"{position + 1} does not exist")
    drafting = getattr(exercise, "drafting", None) or DRAFTING
    suffix = path.suffix.lower()
    if suffix in (".json", ".csv"):
        out = grade_answers(exercise.id, positions[position], path, drafting)
    elif suffix in (".svg", ".svgz"):
        drawing = read_drawing(path)
        out = _graded_drawing(exercise.id, positions[position], drawing, drafting)
    else:
        raise InputError("a drawing is an .svg (or .svgz), and a table of answers a .json or "
                         ".csv", file=file_name(path))
    out.weights, out.follow, out.position = dict(drafting.weights), drafting.follow, \
        position + 1
    if out.overlay is not None:
        _other_position(out, exercise.id, positions, position, out.overlay[0], drafting)
    if not out.items:
        said = (out.notes[-1] if out.notes else None) or (
            "no labels naming a pole, a tip or a centre were found (o, a, b, … for "
            "velocities; o′, a′, … for accelerations; I13 or 13 for centres)")
        said = said if len(said) <= 130 else said[:129] + "…"
        raise InputError(f"nothing on it could be graded: {said}", file=out.source)
    return out


def _graded_drawing(exercise: str, sol, drawing, drafting) -> Grade:
    """A drawing graded at the position ``sol``: its polygons and its space diagram's
    centres, the space diagram (when on the sheet) setting the polygons' orientation."""
    from .centres import grade_centres, space_frame
    from .polygon import grade_polygons
    from .sheet import split
    from tarsim.constructions.linkages.velocity_polygon import drawn_velocity_polygon

    out = Grade(exercise, drawing.source, overlay=(drawing, []))
    out.notes += drawing.notes
    # A point the space diagram may label: the mechanism's, and a contact point's a tip has.
    names = {*sol.work.mechanism.point_names, *drawn_velocity_polygon(sol.work).tips}
    polygons, space = split(drawing, names)
    frame, centres = space_frame(sol, space, out.notes)
    grade_polygons(out, sol, polygons, drafting,
                   None if frame is None else (frame.turn, frame.hand))
    grade_centres(out, sol, frame, centres, drafting)
    out.overlay = (drawing, out.overlay[1] if out.overlay else [])
    return out


def _other_position(out: Grade, exercise: str, positions, asked: int, drawing,
                    drafting) -> None:
    """Say so when the drawing scores far better at another of the exercise's positions."""
    if len(positions) < 2 or not out.items or out.score >= 100.0 - _BETTER:
        return
    best = None
    for k, sol in enumerate(positions):
        if k != asked:
            other = _graded_drawing(exercise, sol, drawing, drafting)
            other.weights, other.follow = dict(drafting.weights), drafting.follow
            if other.items and (best is None or other.score > best[1]):
                best = (k, other.score)
    if best and best[1] >= max(_LIKELY, out.score + _BETTER):
        k, score = best
        label = getattr(positions[k].position, "label", "")
        out.position_matched = k + 1
        out.notes.insert(0, f"this drawing matches position {k + 1}" +
                         (f" ({label})" if label else "") + f", where it scores {score:.0f} %, "
                         f"not position {asked + 1}, which was asked")
