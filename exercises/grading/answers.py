"""A table of numeric answers graded against results.json's quantities.

JSON: ``{"V_B": 0.2329, "omega4": -0.265}`` (or each as ``{"value": …}``, results.json's own
shape). CSV: rows of ``name,value``, a header row allowed. Values are SI, as results.json
has them. A vector is graded by its magnitude.

**Tolerance.** A number read off a drawing is as good as the drawing: a polygon drawn
:data:`LENGTH` long at the exercise's drafting precision (:class:`~.drafting.Drafting`),
over the conditioning of the construction that found it; never tighter than its floor, the
1 % published graphical answers keep to unless the exercise says otherwise.
"""

from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

from ...constructions.errors import InputError
from .grade import Grade, Item
from .drafting import DRAFTING, Drafting

__all__ = ["grade_answers", "read_answers", "LENGTH"]

LENGTH = 100.0
"""Paper (mm) a polygon is taken to be drawn across: the ten centimetres a course asks."""

_MAX_BYTES = 1_000_000


def read_answers(path: Path) -> dict[str, float]:
    """The answers a JSON or CSV file gives, by results.json name.

    Raises
    ------
    InputError
        Naming the file and what is wrong in it.
    """
    name = path.name
    try:
        if path.stat().st_size > _MAX_BYTES:
            raise InputError(f"{name}: more than {_MAX_BYTES:,} bytes; a table of answers is "
                             "a few lines")
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise InputError(f"{name}: cannot be read ({getattr(e, 'strerror', None) or e})") \
            from None
    rows: list[tuple[str, object]] = []
    if path.suffix.lower() == ".json":
        try:
            data = json.loads(text)
        except json.JSONDecodeError as e:
            raise InputError(f"{name}:{e.lineno}: not JSON ({e.msg})") from None
        if not isinstance(data, dict):
            raise InputError(f"{name}: give an object of answers, {{\"V_B\": 0.23, …}}")
        rows = list(data.items())
    else:
        for number, row in enumerate(csv.reader(io.StringIO(text)), 1):
            if not row or not "".join(row).strip():
                continue
            if len(row) < 2:
                raise InputError(f"{name}:{number}: a row is name,value; got {row!r}")
            rows.append((row[0].strip(), row[1].strip()))
    out = {}
    for key, value in rows:
        if isinstance(value, dict):
            value = value.get("value")
        try:
            number = float(value)
        except (TypeError, ValueError):
            if key.lower() in ("name", "quantity"):
                continue                      # a CSV header row
            raise InputError(f"{name}: the answer {key} must be a number, got {value!r}") \
                from None
        if not math.isfinite(number):
            raise InputError(f"{name}: the answer {key} must be finite, got {value!r}")
        out[str(key)] = number
    return out


def grade_answers(exercise: str, sol, path: Path, drafting: Drafting = DRAFTING) -> Grade:
    """Grade the answers in ``path`` against the position ``sol``'s quantities, at
    ``drafting``'s precision."""
    answers = read_answers(path)
    out = Grade(exercise, path.name)
    quantities = sol.quantities
    for name, value in answers.items():
        q = quantities.get(name)
        if q is None:
            out.items.append(Item(name, "extra", None, value, None,
                                  f"{name} is not asked at this position"))
            continue
        if "value" not in q.reference:
            out.items.append(Item(name, "extra", None, value, None,
                                  f"{name} is a point: grade it from a drawing"))
            continue
        expected = q.reference["value"]
        rel = max(drafting.floor, (drafting.pen / LENGTH + math.tan(drafting.angle))
                  / max(q.conditioning, 0.05))
        tol = rel * max(abs(expected), 1e-300)
        item = Item(name, "correct", expected, value, tol)
        if abs(value - expected) > tol:
            signed = "vector" not in q.reference and name.startswith(("omega", "alpha", "T"))
            if signed and abs(value + expected) <= tol:
                item.verdict, item.message = "wrong sense", f"{name} has the wrong sign"
            else:
                item.verdict = "wrong magnitude"
                item.message = f"{name} is {100 * (value - expected) / expected:+.1f} % off"
        out.items.append(item)
    for name in quantities:
        if name not in answers and "value" in quantities[name].reference:
            out.items.append(Item(name, "missing", quantities[name].reference["value"], None,
                                  None, f"{name} is asked and not answered"))
    return out
