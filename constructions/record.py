"""The construction record: every drafting act as a step in a DAG.

A figure is a rendering of a :class:`Construction`; a worked solution is its
steps' words; what one figure shows is the :func:`slice` of its answers. Each
step stores the verb and parameters that made it, so :func:`replay` can redo it
from its inputs and confirm the stored output (the replay invariant).

A step says *what* it is by its :class:`Kind` (a Kennedy line, a gauge line, an
arc a point is swung along, a vector, an instant centre, ...), so a figure styles
it without reading its id or its words, and what it *says* by a
:class:`~.narration.Phrase`, rendered in any language by
:func:`~.narration.narrate`. The numbers a figure circles and the numbers of the
written steps are one numbering, :meth:`Slice.numbered`.
"""

from __future__ import annotations

import copy

from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any

from . import geometry as g
from .errors import TarsimError
from .measures import Angle, Dimension, measure, measure_angle
from .narration import Phrase

__all__ = [
    "Ref",
    "Role",
    "Panel",
    "Kind",
    "Step",
    "Slice",
    "Derived",
    "Construction",
    "VERBS",
    "slice",
    "toposort",
    "replay",
    "weakest_act",
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
    FORCE = "force"
    COUPLE = "couple"


class Kind(StrEnum):
    """What a step is on a figure: the one thing graphics styles it by.

    A step that does not say takes the kind of its output: a line is a
    construction ``LINE``, a circle an ``ARC``, a segment a ``VECTOR``, a point a
    ``POINT``, a reading a ``DIMENSION`` or an ``ANGLE``.
    """

    JOINT = "joint"
    """A point of the mechanism itself, drawn by the kinematic diagram."""
    GUIDE = "guide"
    """A guide or slot of the mechanism, or a link's axis: the diagram's, not a working line."""
    POINT = "point"
    """A constructed point: a cut, a foot, a tip."""
    CENTRE = "centre"
    """An instant centre."""
    POLE = "pole"
    """The pole of a velocity or acceleration polygon."""
    LINE = "line"
    """A working (construction) line."""
    KENNEDY_LINE = "Kennedy line"
    """A line through two known centres that carries a third (Kennedy's theorem)."""
    COMMON_NORMAL = "common normal"
    """The common normal at a slot or a contact: a locus of the two links' centre."""
    GAUGE_LINE = "gauge line"
    """The line from a link's fixed centre through the tip of a known velocity."""
    ARC = "arc"
    """A compass arc or circle."""
    SWING = "swing"
    """An arc a point is swung along to a new place: it ends in an arrowhead there."""
    VECTOR = "vector"
    """A vector drawn as an arrow from its start to its tip."""
    DIMENSION = "dimension"
    """A distance read off the drawing: a dimension line with its length."""
    ANGLE = "angle"
    """An angle read with the protractor: an arc with its degrees."""
    CONTACT = "contact point"
    """Where two profiles of the mechanism touch (a cam on its follower): the diagram's P."""


def _kind_of(output: Any) -> Kind:
    """The kind a step takes from its output when it does not say."""
    if isinstance(output, g.Line):
        return Kind.LINE
    if isinstance(output, g.Circle):
        return Kind.ARC
    if isinstance(output, g.Segment):
        return Kind.VECTOR
    if isinstance(output, Dimension):
        return Kind.DIMENSION
    if isinstance(output, Angle):
        return Kind.ANGLE
    return Kind.POINT


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
class Derived:
    """How a step's parameters follow from the outputs of the steps before it.

    Most parameters are the mechanism's own (a link's length, a branch) and hold at every
    position; a few are read off the drawing (a relative normal ``ω²·r``, where ω is read
    off the velocity polygon). A step that records its ``Derived`` can be redone at another
    position of the input (:mod:`.replay`): ``rule(output, *args)`` returns the parameters
    from ``output``, the function giving a step's output by its ref. ``rule`` is a module's
    function, so that a record stays picklable.
    """

    rule: Callable[..., dict[str, Any]]
    args: tuple = ()

    def __call__(self, output: Callable[[Ref], Any]) -> dict[str, Any]:
        """The parameters, read from the outputs ``output`` gives by ref."""
        return self.rule(output, *self.args)


@dataclass(frozen=True, slots=True)
class Step:
    """One drafting act: ``output = verb(*inputs, **params)``.

    ``conditioning`` is the step's own conditioning times the worst of its
    inputs', so a result inherits, and compounds, the ill-conditioning of the acts
    it rests on (``spread`` is the part the verb cannot see, see
    :meth:`Construction.draw`). ``derived`` says how the parameters follow from earlier
    outputs where they are read off the drawing (None: they are the mechanism's own).
    ``phrase`` is what the step says (None: it is not narrated, as a
    point the act before it already named). ``about`` is what the step locates, for
    a figure that draws it by more than its geometry (an instant centre's
    :class:`~.centres.Centre`: its links, its rule, its triangles).
    """

    id: Ref
    verb: str
    inputs: tuple[Ref, ...]
    output: Any
    label: str
    role: Role
    panel: Panel
    kind: Kind
    phrase: Phrase | None = None
    conditioning: float = 1.0
    params: tuple[tuple[str, Any], ...] = ()
    about: Any = None
    spread: float = 1.0
    derived: Derived | None = None

    @property
    def draws(self) -> bool:
        """True if the step puts a mark on a figure beyond the kinematic diagram.

        A point of the mechanism is the diagram's, and a line at infinity has no
        trace; everything else is drawn (a point at a vector's tip or at a pin is
        not dotted, but its number stands beside it).
        """
        if self.kind is Kind.JOINT:
            return False
        return not (isinstance(self.output, g.Line) and self.output.is_at_infinity)


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

    def scratch(self) -> Construction:
        """A copy to draw a trial on: the steps so far shared, the trial's its own, so the
        record itself is left as it was (a construction found by trial, as friction's)."""
        out = copy.copy(self)
        out.steps = dict(self.steps)
        return out

    def give(self, ref: Ref, obj: Any, *, label: str, phrase: Phrase | None = None,
             kind: Kind | None = None, panel: Panel = Panel.SPACE, about: Any = None) -> Ref:
        """Record a datum (a frame point, a guide line) as a given step."""
        self._add(Step(ref, "given", (), obj, label, Role.GIVEN, panel, kind or _kind_of(obj),
                       phrase, about=about))
        return ref

    def draw(self, ref: Ref, verb: str, *inputs: Ref, label: str = "",
             phrase: Phrase | None = None, kind: Kind | None = None,
             role: Role = Role.CONSTRUCTION, panel: Panel = Panel.SPACE, about: Any = None,
             spread: float = 1.0, derived: Derived | None = None, **params: Any) -> Ref:
        """Do the drafting act ``verb`` on the outputs of ``inputs`` and record it.

        ``spread`` (≤ 1) is what the verb cannot see of its conditioning: how far apart its
        inputs stand beside the whole drawing, whose rounding they carry (a line through
        two points close together, near the origin, looks well drawn to the verb alone).
        ``derived`` gives the parameters read off the drawing again at another position
        (:class:`Derived`).

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
        worst = cond * spread * min([1.0] + [self.steps[r].conditioning for r in inputs])
        self._add(Step(ref, verb, tuple(inputs), out, label, role, panel, kind or _kind_of(out),
                       phrase, worst, tuple(sorted(params.items())), about, spread, derived))
        return ref

    def _add(self, step: Step) -> None:
        if step.id in self.steps:
            raise TarsimError(f"step '{step.id}' is recorded twice")
        self.steps[step.id] = step


@dataclass(frozen=True)
class Slice:
    """What one figure shows of a record: its steps in record order, and their numbers.

    Made by :func:`slice`; the figure draws :meth:`steps`, and the written solution
    narrates :meth:`numbered`, so the numbers circled on the figure and the
    numbers of the written steps are one numbering.
    """

    construction: Construction
    refs: tuple[Ref, ...]

    def __iter__(self) -> Iterator[Step]:
        return (self.construction[r] for r in self.refs)

    def __contains__(self, ref: Ref) -> bool:
        return ref in self.refs

    def __len__(self) -> int:
        return len(self.refs)

    def steps(self, panel: Panel | None = None) -> list[Step]:
        """The steps, in record order; with ``panel``, only those drawn in it."""
        return [s for s in self if panel is None or s.panel is panel]

    def numbered(self, panel: Panel = Panel.SPACE) -> list[tuple[int, Step]]:
        """Number the narrated steps drawn in ``panel``: 1, 2, … in record order.

        A given is not numbered, nor a step that says nothing (the point the act
        before it named: B′ where the swung arc cuts the line), nor one that puts
        no mark on the figure; all of them are drawn.
        """
        out: list[tuple[int, Step]] = []
        for step in self.steps(panel):
            if step.role is not Role.GIVEN and step.phrase is not None and step.draws:
                out.append((len(out) + 1, step))
        return out

    def numbers(self, panel: Panel = Panel.SPACE) -> dict[Ref, int]:
        """Each numbered step's number, by ref."""
        return {s.id: n for n, s in self.numbered(panel)}


def slice(construction: Construction, targets: Iterable[Ref], *,  # noqa: A001
          base: Iterable[Ref] = (), arrows: Iterable[Ref] = ()) -> Slice:
    """Return what a figure of ``targets`` shows: every step they rest on, in record order.

    The walk back from the targets stops at ``base``, the steps already on the
    page (the mechanism's own position, which the kinematic diagram draws). Of
    ``arrows``, the vectors a construction drew beside its answer (a polygon's
    absolute vectors and components, the arrows a method drew on its way), each
    whose two ends the figure holds (its steps, or the base steps they stand on)
    is in it too: it feeds no later act but belongs to the figure. Nothing else
    is drawn or narrated.

    Raises
    ------
    TarsimError
        If a target names no step of the construction.

    Examples
    --------
    >>> c = Construction()
    >>> _ = c.give("O", g.Point(0, 0), label="O")
    >>> _ = c.give("P", g.Point(3, 4), label="P")
    >>> _ = c.give("Q", g.Point(9, 9), label="Q")
    >>> _ = c.draw("k", "circle_through", "O", "P")
    >>> _ = c.draw("v", "join", "O", "P")
    >>> slice(c, ["k"]).refs
    ('O', 'P', 'k')
    >>> slice(c, ["k"], base=["O", "P"], arrows=["v"]).refs
    ('k', 'v')
    """
    base = set(base)
    needed: set[Ref] = set()
    stood_on: set[Ref] = set()
    stack = list(targets)
    while stack:
        ref = stack.pop()
        if ref in base:
            stood_on.add(ref)
            continue
        if ref in needed:
            continue
        if ref not in construction.steps:
            raise TarsimError(f"nothing in the construction is called '{ref}'")
        needed.add(ref)
        stack.extend(construction.steps[ref].inputs)
    held = needed | stood_on
    for ref in arrows:
        step = construction[ref]
        if step.kind is Kind.VECTOR and all(r in held for r in step.inputs):
            needed.add(ref)
    return Slice(construction, tuple(s.id for s in construction if s.id in needed))



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


def weakest_act(construction: Construction, targets: Iterable[Ref]) -> Step:
    """The act behind ``targets`` whose own conditioning is the least: the one that lost
    the digits (a step's recorded conditioning is its own times its worst input's).

    Examples
    --------
    >>> c = Construction()
    >>> for name, x, y in (("A", 0, 0), ("B", 1, 0), ("C", 0, 1), ("D", 1, 1e-9)):
    ...     _ = c.give(name, g.Point(x, y), label=name)
    >>> _ = c.draw("g", "line_through", "A", "B")
    >>> _ = c.draw("h", "line_through", "C", "D")
    >>> _ = c.draw("P", "intersect_lines", "g", "h")
    >>> weakest_act(c, ["P"]).id
    'P'
    """
    def own(step: Step) -> float:
        inherited = min([1.0] + [construction[r].conditioning for r in step.inputs])
        return step.conditioning / inherited if inherited > 0.0 else 0.0

    steps = construction.steps
    walked: dict[Ref, Step] = {}
    stack = list(targets)
    while stack:
        ref = stack.pop()
        if ref not in walked:
            walked[ref] = steps[ref]
            stack.extend(steps[ref].inputs)
    return min(walked.values(), key=own)

