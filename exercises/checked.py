"""A checked quantity as every chapter writes it: results.json's entry and the terminal's line.

Each chapter checks its numbers its own way (a gear train's speeds are exact fractions, a
cam's peaks a formula beside its law, a linkage's readings a drawing beside the analytic
solver), but what it writes of a check is one shape, in one order: the value (SI, with
what it carries: a vector, a point, an exact fraction), the reference in the same shape,
the relative error, the tolerance, the conditioning, whether it passed, and the method.
:class:`Checked` holds that row and :meth:`Checked.entry` writes it;
:func:`results_document` and :func:`results_text` make results.json of the rows.
:func:`check_line` is how the terminal sets a checked answer beside its verdict.

A field a chapter does not state is None and is not written: a cam's profile reading has
no reference, a single cylinder's forces no check. A non-finite number (an unbounded
tolerance) is written as null, for JSON has no infinity.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

__all__ = ["Checked", "results_document", "results_text", "check_line"]


@dataclass(frozen=True)
class Checked:
    """One quantity as results.json writes it (see the module's docstring).

    ``value`` is the value's own fields (``{"value": …}``, with a vector, a point, an exact
    fraction, a unit); ``beside`` what follows the check (the same quantity by other
    methods, a second reading of it).
    """

    value: Mapping[str, Any]
    reference: Mapping[str, Any] | None = None
    rel_error: float | None = None
    tolerance: float | None = None
    conditioning: float | None = None
    passed: bool | None = None
    method: str | None = None
    beside: Mapping[str, Any] = field(default_factory=dict)

    def entry(self) -> dict[str, Any]:
        """The row as results.json gives it, its fields in the one order.

        >>> Checked({"value": 2.0}, {"value": 2.0}, rel_error=0.0, tolerance=math.inf,
        ...         passed=True, method="velocity polygon").entry()
        {'value': 2.0, 'reference': {'value': 2.0}, 'rel_error': 0.0, 'tolerance': None, \
'passed': True, 'method': 'velocity polygon'}
        """
        out = dict(self.value)
        stated = (("reference", self.reference), ("rel_error", self.rel_error),
                  ("tolerance", self.tolerance), ("conditioning", self.conditioning),
                  ("passed", self.passed), ("method", self.method))
        out.update((name, _json_number(value)) for name, value in stated if value is not None)
        out.update(self.beside)
        return out


def _json_number(x: Any) -> Any:
    """A float as JSON holds it: itself, or null if unbounded (JSON has no infinity)."""
    return None if isinstance(x, float) and not math.isfinite(x) else x


def results_document(exercise: str, quantities: Mapping[str, Checked],
                     positions: Iterable[dict[str, Any]] = ()) -> dict[str, Any]:
    """results.json's document: the exercise, each position's part (a linkage's) and the
    quantities of the exercise as a whole."""
    return {"exercise": exercise, "positions": list(positions),
            "quantities": {name: q.entry() for name, q in quantities.items()}}


def results_text(document: dict[str, Any]) -> str:
    """The document as stable, indented JSON text; never NaN nor infinity.

    Raises
    ------
    ValueError
        If a number in it is not finite (a row states it through :class:`Checked`, which
        writes an unbounded one as null).
    """
    return json.dumps(document, indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def check_line(answer: str, *, width: int, passed: bool, against: str, method: str,
               failed: str = "check FAILED") -> str:
    """A checked answer as the terminal prints it: the answer set in ``width`` columns, the
    verdict, what it was checked against, and the method.

    >>> check_line("ω3 = −2.578 rad/s (cw)", width=36, passed=True, against="1.3e-16",
    ...            method="velocity polygon")
    'ω3 = −2.578 rad/s (cw)               check ok 1.3e-16   velocity polygon'
    """
    return f"{answer:<{width}} {'check ok' if passed else failed} {against}   {method}"
