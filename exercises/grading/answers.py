"""A table of numeric answers graded against results.json's quantities.

JSON: ``{"V_B": 0.2329, "omega4": -0.265, "I13": [0.0, -0.5]}`` (or each as results.json
writes it, ``{"value": …}``, ``{"vector": [x, y]}``, ``{"point": [x, y]}``). CSV: rows of
``name,value`` or ``name,x,y``, a header row allowed. Values are SI, as results.json has
them. A vector given by its size is graded by its magnitude, by its components as a
vector; a point (an instant centre) by its distance from where it belongs.

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
from .matching import LEAST_CONDITIONING

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
                raise InputError(f"{name}:{number}: a row is name,value or name,x,y; got "
                                 f"{row!r}")
            cells = [c.strip() for c in row[1:3] if c.strip()]
            rows.append((row[0].strip(), cells[0] if len(cells) == 1 else cells))
    out: dict[str, float | tuple[float, float]] = {}
    for key, value in rows:
        if isinstance(value, dict):
            value = next((value[k] for k in ("value", "vector", "point") if k in value), None)
        try:
            if isinstance(value, (list, tuple)):
                if len(value) != 2:
                    raise ValueError
                answer = (float(value[0]), float(value[1]))
            else:
                answer = float(value)
        except (TypeError, ValueError):
            if key.lower() in ("name", "quantity"):
                continue                      # a CSV header row
            raise InputError(f"{name}: the answer {key} must be a number or an [x, y] pair, "
                             f"got {value!r}") from None
        if not all(math.isfinite(v) for v in (answer if isinstance(answer, tuple)
                                             else (answer,))):
            raise InputError(f"{name}: the answer {key} must be finite, got {value!r}")
        out[str(key)] = answer
    return out


def grade_answers(exercise: str, sol, path: Path, drafting: Drafting = DRAFTING) -> Grade:
    """Grade the answers in ``path`` against the position ``sol``'s quantities, at
    ``drafting``'s precision."""
    answers = read_answers(path)
    out = Grade(exercise, path.name)
    quantities = sol.quantities
    # A point is held beside the mechanism's own size, not its distance from the origin.
    points = sol.work.kinematics.points.values()
    reach = max([math.dist(p, r) for p in points for r in points] + [1e-300])
    for name, value in answers.items():
        q = quantities.get(name)
        if q is None:
            out.items.append(Item(name, "extra", None, value, None,
                                  f"{name} is not asked at this position"))
            continue
        pair = q.reference.get("vector") or q.reference.get("point")
        if isinstance(value, tuple):
            if pair is None:
                out.items.append(Item(name, "wrong magnitude", q.reference.get("value"),
                                      list(value), None, f"{name} is a number, not a pair"))
                continue
            out.items.append(_pair_verdict(name, q, value, pair, rel_tol(q, drafting), reach))
            continue
        if "value" not in q.reference:
            out.items.append(Item(name, "extra", None, value, None,
                                  f"{name} is a point: give it as [x, y]"))
            continue
        expected = q.reference["value"]
        tol = rel_tol(q, drafting) * max(abs(expected), 1e-300)
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
        if name not in answers and ("value" in quantities[name].reference
                                    or "point" in quantities[name].reference):
            ref = quantities[name].reference
            out.items.append(Item(name, "missing", ref.get("value", ref.get("point")), None,
                                  None, f"{name} is asked and not answered"))
    return out


def rel_tol(q, drafting: Drafting) -> float:
    """The relative tolerance of a number read off a drawing of :data:`LENGTH`."""
    return max(drafting.floor, (drafting.pen / LENGTH + math.tan(drafting.angle))
               / max(q.conditioning, LEAST_CONDITIONING))


def _pair_verdict(name: str, q, value: tuple[float, float], pair, rel: float,
                  reach: float) -> Item:
    """A vector or a point given by its two components, against the expected ``pair``: held
    to ``rel`` of the vector's size, or of a point's distance from the origin or the
    mechanism's ``reach``, the larger."""
    ex, ey = pair
    size = max(math.hypot(ex, ey), reach if "point" in q.reference else 1e-300)
    tol = rel * size
    miss = math.hypot(value[0] - ex, value[1] - ey)
    item = Item(name, "correct", [ex, ey], list(value), tol)
    if miss > tol:
        if "vector" in q.reference and math.hypot(value[0] + ex, value[1] + ey) <= tol:
            item.verdict, item.message = "wrong sense", f"{name} points the other way"
        elif "point" in q.reference:
            item.verdict = "wrong position"
            item.message = f"{name} is {miss:.4g} m from where it belongs"
        else:
            item.verdict = "wrong direction"
            item.message = f"{name} is {100 * miss / size:.1f} % of its size off"
    return item
