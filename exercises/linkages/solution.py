"""A worked solution: run the constructions an exercise asks for and check every number.

The asks of the mechanism as a whole (DOF, Grashof, time ratio, stroke) are
answered once; those of a position (centres, ω, V, A …) at each position the
exercise names. Both walk the registry of methods
(:func:`~tarsim.constructions.methods.answer_all`): each answer is drawn into the
record, read off the drawing and put beside its analytic value with the relative
error and the tolerance its conditioning allows. Nothing here draws a figure:
the figures and files are made from a :class:`Solution` by
:mod:`.solution_files`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from tarsim.constructions.linkages.assembly_record import Assembly
from tarsim.constructions.checks import Answer, Quantity
from tarsim.constructions.errors import BranchError, DeadPoint, InputError, TarsimError
from tarsim.constructions.linkages.given_rate import convert
from tarsim.constructions.methods import Work, answer_all
from tarsim.constructions.narration import narrate, spoken
from tarsim.constructions.linkages.polygon import Polygon
from tarsim.constructions.record import Panel
from tarsim.constructions.reference.solver import Kinematics
from tarsim.constructions.registry import METHODS
from tarsim.constructions.scales import ROOM
from .exercise_file import Exercise, Position

__all__ = ["Solution", "Overall", "solve_exercise", "solve_positions", "solve_overall"]


@dataclass
class Solution:
    """Everything one position of an exercise produced."""

    exercise: Exercise
    work: Work
    quantities: dict[str, Quantity]
    answers: list[Answer]
    position: Position | None = None
    """Which of the exercise's positions this is (None: the file's [input] angle)."""

    @property
    def assembly(self) -> Assembly:
        """The mechanism drawn by compass at this position, with every construction's steps."""
        return self.work.assembly

    @property
    def kinematics(self) -> Kinematics:
        """The analytic solution at this position."""
        return self.work.kinematics

    @property
    def velocity_polygon(self) -> Polygon | None:
        """The velocity polygon, if the solution drew one."""
        return self.work.made("velocity polygon")

    @property
    def acceleration_polygon(self) -> Polygon | None:
        """The acceleration polygon, if the solution drew one."""
        return self.work.made("acceleration polygon")

    @property
    def notes(self) -> list[str]:
        """What the solution says beside its figures (warnings, assumptions), in the
        language being spoken."""
        return self.notes_in(spoken())

    def notes_in(self, lang: str) -> list[str]:
        """The solution's notes in ``lang``."""
        return [narrate(text, lang) for _, text in self.work.notes]

    @property
    def failures(self) -> list[Quantity]:
        """Quantities whose construction disagrees with the reference."""
        return [q for q in self.quantities.values() if not q.passed]


@dataclass
class Overall:
    """The answers about the mechanism as a whole, and the work they were drawn in."""

    work: Work | None = None
    quantities: dict[str, Quantity] = field(default_factory=dict)
    answers: list[Answer] = field(default_factory=list)


def solve_overall(ex: Exercise, *, room: tuple[float, float] = ROOM) -> Overall:
    """Answer what ``ex`` asks of the mechanism as a whole (DOF, Grashof, time ratio, stroke),
    its scales chosen for a drawing area of ``room`` (paper mm).

    Raises
    ------
    TarsimError
        If the limit positions cannot be drawn or the crank does not turn fully.
    """
    if not ex.mechanism_asks:
        return Overall()
    try:
        work = _work(ex, ex.mechanism_asks, room)
        quantities, answers = answer_all(work, METHODS)
    except TarsimError as e:
        if not ex.mechanism.source:
            raise
        raise e.in_file(ex.mechanism.source) from None     # of no one position: the file's
    return Overall(work, quantities, answers)


def _work(ex: Exercise, asks, room: tuple[float, float]) -> Work:
    """The work of ``asks``: the input's rates converted first when the exercise gives them
    by another member (the drawing's conversion for the construction, the solver's for the
    reference, the drawn one stated under the figures)."""
    mech, reference, said = ex.mechanism, None, None
    if mech.given is not None:
        mech, reference, said = convert(mech)
    work = Work(mech, asks, ex.methods, ex.stated, room, reference=reference,
                loads=ex.loads)
    if said:
        work.note(said)
    return work


def solve_positions(ex: Exercise, *, room: tuple[float, float] = ROOM) -> list[Solution]:
    """Solve ``ex`` at each of its positions (or at its [input] angle if it lists none), its
    scales chosen for a drawing area of ``room`` (paper mm; the sheet's, the figures' to
    say: :func:`tarsim.graphics.paper.room`).

    Raises
    ------
    TarsimError
        As :func:`solve_exercise`, with the position named.
    """
    if not ex.positions:
        return [solve_exercise(ex, room=room)]
    out = []
    for p in ex.positions:
        sol = solve_exercise(ex.at(p), where=p.label, room=room)
        sol.position = p
        out.append(sol)
    return out


def solve_exercise(ex: Exercise, *, where: str | None = None,
                   room: tuple[float, float] = ROOM) -> Solution:
    """Solve what ``ex`` asks at its stated position, said as ``where`` (default: its input
    angle, "θ2 = 90°"), its scales chosen for a drawing area of ``room`` (paper mm).

    Raises
    ------
    TarsimError
        If the mechanism cannot be assembled, is singular at this position, or a
        construction breaks down; the message says which, and leads with the position.
    """
    mech = ex.mechanism
    if ex.without_motion:
        raise InputError(ex.without_motion, file=mech.source or None)
    try:
        work = _work(ex, ex.position_asks, room)
        work.prepare()
        quantities, answers = answer_all(work, METHODS)
    except TarsimError as e:
        if isinstance(e, (InputError, BranchError, DeadPoint)) and where is None:
            raise                   # the file's line says where: a key, a branch, the angle
        d = mech.drive
        raise e.at(where or f"θ{d.link} = {mech.units.angle_brief(d.angle)}") from None
    return Solution(ex, work, quantities, answers)


def notes_under(sol: Solution, panel: Panel) -> list[str]:
    """The solution's notes that belong under the figures of ``panel``."""
    return [narrate(text, spoken()) for p, text in sol.work.notes if p is panel]
