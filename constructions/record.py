"""The construction record: every drafting act as a step in a DAG.

A figure is a rendering of a :class:`Construction`; a worked solution is its
sentences; a scene is the backward :func:`slice` of the asked results. Each step
stores the verb and parameters that made it, so :func:`replay` can redo it from
its inputs and confirm the stored output (the replay invariant).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any

from . import geometry as g
from .errors import TarsimError
from .measures import measure, measure_angle

__all__ = [
    "Ref",
    "Role",
    "Panel",
    "Step",
    "Construction",
    "VERBS",
    "slice",
    "toposort",
    "replay",
]

Ref = str
"""A step's id, unique within its construction."""


class Role(StrEnum):
    """What a step is to the reader: a datum, a working line or an answer."""

    GIVEN = "given"
    CONSTRUCTION = "construction"
    RESULT = "result"


class Panel(StrEnum):
    """The figure panel a step is drawn in."""

    SPACE = "space"
    CIRCLE = "circle"
    VELOCITY = "velocity"
    ACCELERATION = "acceleration"


VERBS: Mapping[str, Callable[..., tuple[Any, float]]] = {
    "line_through": g.line_through,
    "perpendicular_through": g.perpendicular_through,
    "parallel_through": g.parallel_through,
    "swing_arc": g.swing_arc,
    "circle_through": g.circle_through,
    "intersect_lines": g.intersect_lines,
    "intersect_line_circle": g.intersect_line_circle,
    "intersect_circles": g.intersect_circles,
    "rotate_about": g.rotate_about,
    "project_onto": g.project_onto,
    "lay_off": g.lay_off,
    "midpoint": g.midpoint,
    "mark": g.mark,
    "normal_direction": g.normal_direction,
    "join": g.join,
    "transfer": g.transfer,
    "measure": measure,
    "measure_angle": measure_angle,
}
"""The drafting verbs a step may name, by name."""


@dataclass(frozen=True, slots=True)
class Step:
    """One drafting act: ``output = verb(*inputs, **params)``.

    ``conditioning`` is the step's own conditioning times the worst of its
    inputs', so a result inherits, and compounds, the ill-conditioning of the acts
    it rests on.
    """

    id: Ref
    verb: str
    inputs: tuple[Ref, ...]
    output: Any
    label: str
    role: Role
    panel: Panel
    sentence: str
    conditioning: float = 1.0
    params: tuple[tuple[str, Any], ...] = ()
    number: int | None = None


@dataclass
class Construction:
    """An ordered record of steps; insertion order is a topological order."""

    steps: dict[Ref, Step] = field(default_factory=dict)

    def __getitem__(self, ref: Ref) -> Step:
        return self.steps[ref]

    def __contains__(self, ref: Ref) -> bool:
        return ref in self.steps

    def __iter__(self):
        return iter(self.steps.values())

    def __len__(self) -> int:
        return len(self.steps)

    def output(self, ref: Ref) -> Any:
        """Return the geometric object a step made."""
        return self.steps[ref].output

    def give(self, ref: Ref, obj: Any, *, label: str, sentence: str,
             panel: Panel = Panel.SPACE) -> Ref:
        """Record a datum (a frame point, a guide line) as a given step."""
        self._add(Step(ref, "given", (), obj, label, Role.GIVEN, panel, sentence))
        return ref

    def draw(self, ref: Ref, verb: str, *inputs: Ref, label: str = "",
             sentence: str = "", role: Role = Role.CONSTRUCTION,
             panel: Panel = Panel.SPACE, **params: Any) -> Ref:
        """Do the drafting act ``verb`` on the outputs of ``inputs`` and record it.

        Raises
        ------
        TarsimError
            Whatever the verb raises (``NoIntersection``, ``DegenerateInput``).
        """
        if verb not in VERBS:
            raise TarsimError(f"step '{ref}' names '{verb}', which is not a drafting verb; "
                              f"the verbs are {', '.join(VERBS)}")
        for ref_in in inputs:
            if ref_in not in self.steps:
                raise TarsimError(f"step '{ref}' uses '{ref_in}', which is not yet drawn")
        out, cond = VERBS[verb](*(self.steps[r].output for r in inputs), **params)
        # Chained acts compound: an ill-conditioned cut of ill-conditioned lines is
        # worse than either, so the act's own conditioning multiplies the worst input's.
        worst = cond * min([1.0] + [self.steps[r].conditioning for r in inputs])
        self._add(Step(ref, verb, tuple(inputs), out, label, role, panel, sentence,
                       worst, tuple(sorted(params.items()))))
        return ref

    def _add(self, step: Step) -> None:
        if step.id in self.steps:
            raise TarsimError(f"step '{step.id}' is recorded twice")
        self.steps[step.id] = step

    def numbered(self, refs: Iterable[Ref]) -> list[Step]:
        """Return the steps in ``refs`` in record order, numbered 1, 2, … for narration."""
        wanted = set(refs)
        out: list[Step] = []
        for step in self.steps.values():
            if step.id in wanted:
                out.append(_renumber(step, len(out) + 1))
        return out


def _renumber(step: Step, n: int) -> Step:
    return Step(step.id, step.verb, step.inputs, step.output, step.label, step.role,
                step.panel, step.sentence, step.conditioning, step.params, n)


def slice(construction: Construction, targets: Iterable[Ref]) -> set[Ref]:  # noqa: A001
    """Return every step the ``targets`` rest on, the targets included.

    This is what a scene needs: nothing outside it is drawn or narrated.

    Examples
    --------
    >>> c = Construction()
    >>> _ = c.give("O", g.Point(0, 0), label="O", sentence="")
    >>> _ = c.give("P", g.Point(3, 4), label="P", sentence="")
    >>> _ = c.give("Q", g.Point(9, 9), label="Q", sentence="")
    >>> _ = c.draw("k", "circle_through", "O", "P")
    >>> sorted(slice(c, ["k"]))
    ['O', 'P', 'k']
    """
    needed: set[Ref] = set()
    stack = list(targets)
    while stack:
        ref = stack.pop()
        if ref in needed:
            continue
        if ref not in construction.steps:
            raise TarsimError(f"nothing in the construction is called '{ref}'")
        needed.add(ref)
        stack.extend(construction.steps[ref].inputs)
    return needed


def toposort(construction: Construction, refs: Iterable[Ref] | None = None) -> list[Step]:
    """Return the steps (all, or those in ``refs``) inputs-first, in record order."""
    wanted = None if refs is None else set(refs)
    return [s for s in construction.steps.values() if wanted is None or s.id in wanted]


def replay(construction: Construction, ref: Ref) -> Any:
    """Redo one step from its recorded inputs and parameters and return the output.

    A given step replays to itself.
    """
    step = construction.steps[ref]
    if step.verb == "given":
        return step.output
    args = [construction.steps[r].output for r in step.inputs]
    return VERBS[step.verb](*args, **dict(step.params))[0]
