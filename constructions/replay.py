"""Redo a record at another position of the input: the same acts on new data.

A worked solution draws one position with every choice made there: which dyad locates
which point, which branch of a cut, which lines cross best. Turning the input through a
revolution (``tarsim view``) redoes those acts verb by verb, with the givens that move
given anew (the input's ray) and each parameter read off the drawing read again
(:class:`~.record.Derived`). Nothing is planned, said or recorded, so a position costs
the verbs alone rather than a solve.

Acts chosen at one position may be wrong at another: a cut that has passed to its other
branch is still "left", lines that crossed well may have turned parallel, a component
that was zero is still a mark. So a replayed position is only as good as its check: the
caller holds it to the analytic solution and constructs it afresh where it fails.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

from .record import VERBS, Construction, Ref

__all__ = ["Replay"]


class Replay:
    """The acts of ``record`` that ``targets`` rest on, ready to be redone.

    Examples
    --------
    A point laid off 2 along a ray, redone with the ray turned:

    >>> from tarsim.constructions import geometry as g
    >>> c = Construction()
    >>> _ = c.give("O", g.Point(0.0, 0.0), label="O")
    >>> _ = c.give("ray", g.Line(0.0, 1.0, 0.0), label="ray")
    >>> _ = c.draw("A", "lay_off", "O", "ray", length=2.0)
    >>> again = Replay(c, ["A"])
    >>> out, _ = again.run({"ray": g.Line(-1.0, 0.0, 0.0)})
    >>> tuple(round(v, 12) + 0.0 for v in out["A"].xy)
    (0.0, 2.0)
    """

    def __init__(self, record: Construction, targets: Iterable[Ref]):
        needed: set[Ref] = set()
        stack = list(targets)
        while stack:
            ref = stack.pop()
            if ref not in needed:
                needed.add(ref)
                stack.extend(record[ref].inputs)
        self.record = record
        self.acts = [(s.id, None if s.verb == "given" else VERBS[s.verb], s.inputs,
                      dict(s.params), s.derived, s.spread, s.output, s.conditioning)
                     for s in record if s.id in needed]

    def run(self, given: Mapping[Ref, Any]) -> tuple[dict[Ref, Any], dict[Ref, float]]:
        """Every act redone with the givens in ``given`` replaced: the outputs by ref, and
        each one's conditioning compounded as :meth:`~.record.Construction.draw` does
        (with the spread of the recorded position).

        Raises
        ------
        TarsimError
            Whatever a verb raises where the acts no longer apply (``NoIntersection``,
            ``DegenerateInput``).
        """
        out: dict[Ref, Any] = {}
        cond: dict[Ref, float] = {}
        for ref, verb, inputs, params, derived, spread, output, conditioning in self.acts:
            if verb is None:
                out[ref], cond[ref] = given.get(ref, output), conditioning
                continue
            if derived is not None:
                params = {**params, **derived(out.__getitem__)}
            out[ref], own = verb(*[out[r] for r in inputs], **params)
            worst = 1.0
            for r in inputs:
                if cond[r] < worst:
                    worst = cond[r]
            cond[ref] = own * spread * worst
        return out, cond
