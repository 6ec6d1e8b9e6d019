"""A registry of methods: what each answers, how it constructs, and its analytic reference.

A :class:`Method` answers some kinds of :class:`~.asks.Ask`. For each ask it
*constructs* an :class:`~.checks.Answer` (drawing steps into the record and
returning the refs of its answer, the figure and panel it belongs in) and names
its independent *reference*. :func:`answer_all` walks the asks of one position
(or of the mechanism as a whole) in a solution's order and, for each, every
method the exercise uses for it, putting each answer beside its reference
(:func:`~.checks.check`). The first method's answer is the quantity; the others
stand beside it.

A :class:`Work` is what the methods of one position share: the mechanism drawn
there, its analytic solution, its scales, and constructions several methods use
(the instant centres, the polygons), each made once.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

from . import asks as A
from .linkages.assembly import assemble
from .linkages.assembly_record import Assembly
from .checks import Answer, Expected, Quantity, check
from .errors import GeometryError, IllConditioned, NoIntersection, TarsimError
from .model import Mechanism
from .narration import Number, Phrase, Word, narrate, phrase
from .record import Panel, weakest_act
from .linkages.velocity_drawing import method_words
from .reference import solver
from .reference.centres import mechanism_size
from .reference.rotatability import grashof_class
from .scales import ROOM, Scales, choose_scales

__all__ = ["Method", "Work", "answer_all"]


def drawable_speeds(m: Mechanism, kin: solver.Kinematics) -> list[float]:
    """Magnitudes (file units/s) of the vectors a method may draw on the space diagram: each
    point's velocity, and its component along every line to another point of its link (the
    components a rigid link carries from one end to the other)."""
    out = []
    for k in m.links:
        if k.number == 1:
            continue
        v = {n: solver.point_velocity(kin, m, k.number, n) for n in k.names}
        out += [math.hypot(*w) for w in v.values()]
        for i, p in enumerate(k.names):
            for q in k.names[i + 1:]:
                dx, dy = (b - a for a, b in zip(kin.points[p], kin.points[q]))
                if math.hypot(dx, dy) > 0.0:
                    out.append(abs(v[p][0] * dx + v[p][1] * dy) / math.hypot(dx, dy))
    return [x / m.units.metres for x in out]


def _chosen(method: Method, work: Work, ask: A.Ask) -> bool:
    return not method.chosen_by or any(name in work.chosen for name in method.chosen_by)


@dataclass(frozen=True)
class Method:
    """One graphical method, as the registry knows it.

    ``references`` names, for each kind of ask it answers, the independent analytic
    value its answer is checked against (:mod:`.expected`); ``construct`` draws one
    answer into the work's record. ``stage`` orders a solution: methods of a lower
    stage construct first, and of several methods for one ask the first is the
    quantity's answer. ``chosen_by`` are the names in an exercise's ``[ask]
    methods`` that choose it (none: it is always used), the first of them its own;
    of methods of one stage, the one chosen first answers first. ``when`` decides
    whether the exercise uses the method for an ask where being chosen is not the
    whole rule (a polygon is also drawn when an acceleration needs it). ``askable``
    names the asks it answers of a mechanism beyond those its points and links give
    (a four-bar's Grashof class, a quick-return's time ratio), and ``why_not`` says
    why a mechanism it does not fit has none.
    """

    name: str
    references: Mapping[type[A.Ask], Callable[[Work, A.Ask], Expected]]
    construct: Callable[[Work, A.Ask], Answer]
    stage: int
    chosen_by: tuple[str, ...] = ()
    when: Callable[[Work, A.Ask], bool] | None = None
    askable: Callable[[Mechanism], set[str]] | None = None
    why_not: dict[type[A.Ask], str] = field(default_factory=dict)

    @property
    def answers(self) -> tuple[type[A.Ask], ...]:
        """The kinds of ask the method answers."""
        return tuple(self.references)

    def reference(self, work: Work, ask: A.Ask) -> Expected:
        """The analytic value ``ask`` is checked against."""
        return self.references[type(ask)](work, ask)

    def used(self, work: Work, ask: A.Ask) -> bool:
        """True if the exercise uses this method for ``ask``: chosen (or always used), and
        fit for it where the method says when it is (``when``)."""
        return self.when(work, ask) if self.when is not None else _chosen(self, work, ask)

    def rank(self, work: Work) -> tuple[int, int]:
        """Its place among the methods of one ask: by stage, then as the exercise chose."""
        chosen = [work.chosen.index(n) for n in self.chosen_by if n in work.chosen]
        return self.stage, min(chosen, default=0)


class Work:
    """What the methods of one position (or of the mechanism as a whole) share.

    ``chosen`` are the velocity methods the exercise chose, in its order;
    ``stated`` the scales it states (``velocity``, ``velocity_polygon``,
    ``acceleration_polygon``, in file units per paper cm). The mechanism is
    assembled and solved analytically when first needed, the assembly first, so a
    position that cannot be drawn says so before anything else.
    """

    def __init__(self, mechanism: Mechanism, asks: tuple[A.Ask, ...], chosen: tuple[str, ...],
                 stated: dict[str, float] | None = None, room: tuple[float, float] = ROOM,
                 reference: Mechanism | None = None, loads=None):
        self.mechanism = mechanism
        self.loads = loads
        """The masses, forces and couples the force polygons take (:class:`~.loads.Loads`)."""
        self.room = room
        self.reference = reference or mechanism
        self.asks = asks
        self.chosen = chosen
        self.stated = dict(stated or {})
        self.notes: list[tuple[Panel, str]] = []
        self._shared: dict[str, Any] = {}

    @cached_property
    def assembly(self) -> Assembly:
        """The mechanism drawn by compass at this position."""
        return assemble(self.mechanism)

    @cached_property
    def kinematics(self) -> solver.Kinematics:
        """The analytic solution at this position (of the reference mechanism: the same,
        unless the input's rates were converted from another member's, each its own way)."""
        return solver.solve(self.reference)

    @cached_property
    def scales(self) -> Scales:
        """The position's scales, chosen once (:func:`~.scales.choose_scales`)."""
        v = self.stated.get("velocity")
        return choose_scales(self.assembly, velocity=v, velocity_polygon=v,
                             acceleration_polygon=self.stated.get("acceleration"),
                             room=self.room,
                             speeds=() if v else drawable_speeds(self.mechanism,
                                                                 self.kinematics))

    def prepare(self) -> None:
        """Draw the position, then solve it analytically: a position that cannot be drawn
        says so first."""
        _ = self.assembly
        _ = self.kinematics

    def shared(self, key: str, make: Callable[[], Any]) -> Any:
        """The construction ``key`` several methods use, made by ``make`` the first time."""
        if key not in self._shared:
            self._shared[key] = make()
        return self._shared[key]

    def has(self, key: str) -> bool:
        """True if the shared construction ``key`` has been made."""
        return key in self._shared

    def made(self, key: str) -> Any:
        """The shared construction ``key`` if it has been made, else None."""
        return self._shared.get(key)

    def note(self, text: str | Phrase, panel: Panel = Panel.SPACE) -> None:
        """Say something under the figures of ``panel`` (a warning, an assumption): a
        :class:`~.narration.Phrase`, said in the language each figure is drawn in."""
        if (panel, text) not in self.notes:
            self.notes.append((panel, text))

    def asked(self, kind: type[A.Ask] | tuple[type[A.Ask], ...]) -> list[A.Ask]:
        """The asks of this kind."""
        return [a for a in self.asks if isinstance(a, kind)]

    def scale_of(self, ask: A.Ask) -> float:
        """What an error of ``ask`` is relative to where its reference is near zero."""
        m, d = self.mechanism, self.mechanism.drive
        if isinstance(ask, A.AngularVelocity):
            return abs(d.omega)
        if isinstance(ask, A.AngularAcceleration):
            return math.hypot(d.omega ** 2, d.alpha)
        if isinstance(ask, (A.Velocity, A.Rubbing)) or \
                isinstance(ask, (A.Relative, A.Sliding)) and ask.letter == "V":
            return m.input_speed
        if isinstance(ask, (A.Acceleration, A.AccelerationPart, A.Relative, A.Coriolis,
                            A.Sliding)):
            return m.input_acceleration
        if isinstance(ask, (A.Centre, A.Position, A.Distance, A.LeastVelocity, A.Equivalent)):
            return mechanism_size(self.kinematics)
        if isinstance(ask, A.LengthRange):
            return max(grashof_class(m).lengths)
        if isinstance(ask, A.Effort) and ask.word == "reversal_speed":
            return abs(d.omega)                 # a speed, beside the crank's
        if isinstance(ask, A.Effort) and ask.word == "rod_radius_of_gyration":
            return mechanism_size(self.kinematics)          # a length
        if isinstance(ask, (A.JointForce, A.DrivingTorque, A.Effort)):
            # Beside the largest joint force, or the loads it is made of if they are more
            # (times the mechanism's size, for a moment).
            from .expected import _statics
            from .reference.kinetostatics import load_scale

            size = mechanism_size(self.kinematics)
            biggest = max([math.hypot(*j.force) for j in _statics(self).joints]
                          + [load_scale(m, self.kinematics, self.loads, size)])
            moment = (isinstance(ask, A.DrivingTorque) or getattr(ask, "letter", "") == "T"
                      or getattr(ask, "word", "") in A.MOMENTS)
            if getattr(ask, "word", "") == "flywheel_alpha":     # a moment over the flywheel
                return max(biggest * size, self.loads.resisting) / self.loads.flywheel
            return biggest * (mechanism_size(self.kinematics) if moment else 1.0)
        return 1.0


def _construct(method: Method, work: Work, ask: A.Ask) -> Answer:
    """``method``'s answer to ``ask``; a drafting act that breaks down inside it is said with
    what was being drawn, where, and any miss in the file's units."""
    try:
        return method.construct(work, ask)
    except GeometryError as e:
        mech = work.mechanism
        d = mech.drive
        place = f"{ask.name} by {method.name} at θ{d.link} = {mech.units.angle_brief(d.angle)}"
        if isinstance(e, NoIntersection):
            raise TarsimError(f"{place}: two of its lines or arcs miss each other by "
                              f"{mech.units.length_brief(e.margin)}") from None
        raise TarsimError(f"{place}: {e}") from None


def answer_all(work: Work, methods: tuple[Method, ...]) -> tuple[dict[str, Quantity], list[Answer]]:
    """Answer every ask of ``work`` by the methods that answer it, each beside its reference.

    ``methods`` is the registry. Returns each asked quantity by name (the first
    method's answer, with the others beside it), in a solution's order, and every
    answer drawn, for the figures.

    Raises
    ------
    TarsimError
        If no method the exercise uses answers an ask, or a construction breaks down.
    """
    quantities: dict[str, Quantity] = {}
    answers: list[Answer] = []
    for ask in A.ordered(work.asks):
        using = sorted((m for m in methods if isinstance(ask, m.answers) and m.used(work, ask)),
                       key=lambda m: m.rank(work))
        if not using:
            raise TarsimError(f"no method the exercise uses answers {ask.name}; choose one in "
                              "[ask] methods")
        found, refused = [], []
        for m in using:
            answer = _construct(m, work, ask)
            try:
                found.append(check(answer, m.reference(work, ask), scale=work.scale_of(ask)))
            except IllConditioned as e:
                refused.append((answer, e))
                continue
            answers.append(answer)
        _left_out(work, refused, found, methods, using)
        quantities[ask.name] = found[0].with_alternatives(found[1:])
    return quantities, answers


def _left_out(work: Work, refused: list[tuple[Answer, IllConditioned]], found: list[Quantity],
              methods: tuple[Method, ...], using: list[Method]) -> None:
    """Say which methods were too ill-conditioned to be vouched for, beside the first
    method that is (a note under the figures).

    Raises
    ------
    IllConditioned
        If no method the exercise uses for the ask could be vouched for; the line offers
        a method the exercise did not use, or another position.
    """
    for answer, e in refused:
        why = (phrase("weak.reference") if e.by_reference
               else _weakness(work.assembly, answer.refs or (), answer.conditioning))
        said = phrase("note.unvouched", quantity=e.name, method=Word(method_words(e.method)),
                      why=why, other=Word(method_words(found[0].method)) if found else None)
        if found:
            work.note(said)
            continue
        ask = answer.ask
        offer = next((m.chosen_by[0] for m in methods if isinstance(ask, m.answers)
                      and m.chosen_by and m not in using), None)
        d, units = work.mechanism.drive, work.mechanism.units
        how = ("" if e.by_reference else
               f" (conditioning {e.conditioning:.1e}), and it misses the analytic value by "
               f"{e.miss:.1e} of its scale")
        whole = ask.scope == "mechanism"      # drawn the same from any position
        where = ("on this mechanism" if whole else
                 f"at θ{d.link} = {units.angle_brief(d.angle)}")
        then = (f"add \"{offer}\" to [ask] methods" if offer else
                "it is not given" if whole else "ask it at another position")
        raise IllConditioned(
            f"{e.name} by {method_words(e.method)} cannot be vouched for {where}: "
            f"{narrate(why)}{how}; {then}",
            name=e.name, method=e.method, conditioning=e.conditioning, miss=e.miss,
            by_reference=e.by_reference)


def _weakness(record, refs, conditioning: float) -> Phrase:
    """What lost a construction its digits, in words: its weakest act, or the shortness of
    its vectors where the answer's ``conditioning`` is far below its acts' (see
    :func:`~.velocity_drawing.drawn_share`)."""
    if not refs:
        return phrase("weak.act")
    chain = min(record[r].conditioning for r in refs)
    if conditioning < 1e-2 * chain:
        return phrase("weak.short", share=Number(conditioning / chain, ".1e"))
    act = weakest_act(record, refs)
    inherited = min([1.0] + [record[r].conditioning for r in act.inputs])
    own = act.conditioning / inherited if inherited > 0.0 else 0.0
    if act.verb == "intersect_lines" and not act.output.is_at_infinity:
        return phrase("weak.lines", angle=Number(math.degrees(math.asin(min(1.0, own))), ".2g"))
    return phrase({"intersect_circles": "weak.arcs", "intersect_line_circle": "weak.line_arc",
                   "line_through": "weak.points"}.get(act.verb, "weak.act"))
