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
undefined is refused before anything is written.
"""

from __future__ import annotations

import json
import math
from typing import Any

from tarsim.constructions.checks import Quantity
from tarsim.constructions.model import Mechanism

from .exercise_file import Exercise
from .solution import Solution

__all__ = ["results_document", "results_json"]


def results_document(solutions: list[Solution], exercise: Exercise,
                     overall: dict[str, Quantity] | None = None) -> dict[str, Any]:
    """The results.json document: each position's quantities, and ``overall`` (the
    mechanism's DOF, Grashof class, time ratio, stroke) at the top level."""
    return {
        "exercise": exercise.id,
        "positions": [_position(s) for s in solutions],
        "quantities": {name: _quantity(q, exercise.mechanism)
                       for name, q in (overall or {}).items()},
    }


def results_json(solutions: list[Solution], exercise: Exercise,
                 overall: dict[str, Quantity] | None = None) -> str:
    """The document as stable, indented JSON text."""
    return json.dumps(results_document(solutions, exercise, overall), indent=2,
                      ensure_ascii=False, allow_nan=False) + "\n"


def _position(s: Solution) -> dict[str, Any]:
    d = s.exercise.mechanism.drive
    return {
        "input": {"link": d.link, "angle_deg": float(f"{math.degrees(d.angle):.12g}"),
                  "omega": d.omega,
                  "alpha": d.alpha, "alpha_given": d.alpha_given},
        **({"position": s.position.label} if s.position else {}),
        "quantities": {name: _quantity(q, s.exercise.mechanism)
                       for name, q in s.quantities.items()},
        "notes": s.notes_in("en"),            # data, not prose: one language
    }


def _quantity(q: Quantity, mech: Mechanism) -> dict[str, Any]:
    """A quantity as results.json gives it, its points in the file's axes."""
    q = q.in_file_axes(mech)
    out = dict(q.value)
    out.update(reference=q.reference, rel_error=_num(q.rel_error), tolerance=_num(q.tolerance),
               conditioning=_num(q.conditioning), passed=q.passed, method=q.method)
    if q.alternatives:
        out["by_method"] = {m: _quantity(a, mech) for m, a in q.alternatives.items()}
    return out


def _num(x: float) -> float | None:
    """Round-trip a float, with an unbounded tolerance written as null."""
    return x if math.isfinite(x) else None
