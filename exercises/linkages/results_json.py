"""results.json: the stable, machine-readable record of a solution (DESIGN.md contract).

Shape::

    {"exercise": id,
     "positions": [{"input": {"link": 2, "angle_deg": …, "omega": …, "alpha": …},
                    "quantities": {…}, "notes": […]}],
     "quantities": {…}}

Every quantity carries its value in SI units, the analytic ``reference`` in the
same shape, ``rel_error``, the ``tolerance`` its conditioning allows, whether it
``passed``, and the ``method``; a velocity found by several methods lists the
others under ``by_method``. No value is ever NaN: a position where a quantity is
undefined is refused before anything is written. Each quantity is a
:class:`~tarsim.exercises.checked.Checked` row, written as every chapter's are.
"""

from __future__ import annotations

import math
from typing import Any

from tarsim.constructions.checks import Quantity
from tarsim.constructions.model import Mechanism

from ..checked import Checked, results_text
from ..checked import results_document as document
from .exercise_file import Exercise
from .solution import Solution

__all__ = ["results_document", "results_json"]


def results_document(solutions: list[Solution], exercise: Exercise,
                     overall: dict[str, Quantity] | None = None) -> dict[str, Any]:
    """The results.json document: each position's quantities, and ``overall`` (the
    mechanism's DOF, Grashof class, time ratio, stroke) at the top level."""
    return document(exercise.id, {name: checked(q, exercise.mechanism)
                                  for name, q in (overall or {}).items()},
                    [_position(s) for s in solutions])


def results_json(solutions: list[Solution], exercise: Exercise,
                 overall: dict[str, Quantity] | None = None) -> str:
    """The document as stable, indented JSON text."""
    return results_text(results_document(solutions, exercise, overall))


def _position(s: Solution) -> dict[str, Any]:
    d = s.exercise.mechanism.drive
    return {
        "input": {"link": d.link, "angle_deg": float(f"{math.degrees(d.angle):.12g}"),
                  "omega": d.omega,
                  "alpha": d.alpha, "alpha_given": d.alpha_given},
        **({"position": s.position.label} if s.position else {}),
        **({"turned_from_dead_centre": {"value": s.position.turned[0], "unit": "rad",
                                        "from": s.position.turned[1]}}
           if s.position and s.position.turned else {}),
        "quantities": {name: _with_rpm(name, checked(q, s.exercise.mechanism).entry())
                       for name, q in s.quantities.items()},
        "notes": s.notes_in("en"),            # data, not prose: one language
    }


def _with_rpm(name: str, entry: dict[str, Any]) -> dict[str, Any]:
    """An engine's reversal speed with its rpm beside its rad/s, as the books ask it."""
    if name == "reversal_speed":
        entry["rpm"] = entry["value"] * 60 / math.tau
    return entry


def checked(q: Quantity, mech: Mechanism) -> Checked:
    """A quantity as results.json gives it, its points in the file's axes, the quantity by
    other methods beside it."""
    q = q.in_file_axes(mech)
    others = {"by_method": {m: checked(a, mech).entry() for m, a in q.alternatives.items()}} \
        if q.alternatives else {}
    return Checked(q.value, q.reference, rel_error=q.rel_error, tolerance=q.tolerance,
                   conditioning=q.conditioning, passed=q.passed, method=q.method, beside=others)
