"""A table of numeric answers graded against results.json's quantities.

JSON: ``{"V_B": 0.2329, "omega4": -0.265, "I13": [0.0, -0.5]}`` (or each as results.json
writes it, ``{"value": …}``, ``{"vector": [x, y]}``, ``{"point": [x, y]}``). CSV: rows of
``name,value`` or ``name,x,y``, a header row allowed. Values are SI, as results.json has
them. A vector given by its size is graded by its magnitude, by its components as a
vector; a point (an instant centre) by its distance from where it belongs.

**Tolerance.** A number read off a drawing is as good as the drawing, and is held to the
tolerance its vector would be on one (:func:`.drafting.tolerance`): V_B as the tip b drawn at
the exercise's scale (the far corner of its two lines' bands, :mod:`.crossing`, where it is
cut from two), ω4 as the relative velocity it is read from (ω4 times the span it is
read over), a centre as the pen on the space diagram at the exercise's scale, each over the
conditioning of the construction that found it. An answer to what is not asked is said in
a note and costs nothing.
"""

from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

from tarsim.constructions.errors import InputError
from .grade import Grade, Item
from .drafting import DRAFTING, LENGTH, Drafting, exercise_scale, tolerance
from .drawing import file_name
from .crossing import bands, reach
from .matching import LEAST_CONDITIONING, Frame

__all__ = ["grade_answers", "read_answers", "LENGTH"]

_MAX_BYTES = 1_000_000


def read_answers(path: Path) -> dict[str, float]:
    """The answers a JSON or CSV file gives, by results.json name.

    Raises
    ------
    InputError
        Naming the file (and the line, where there is one) and what is wrong in it.
    """
    name = file_name(path)
    try:
        if not path.is_file():                # a pipe or a device would be read forever
            raise InputError("not a file (a folder, a pipe or a device); give a table of "
                             "answers", file=name)
        if path.stat().st_size > _MAX_BYTES:
            raise InputError(f"more than {_MAX_BYTES:,} bytes; a table of answers is a few "
                             "lines", file=name)
        text = path.read_bytes().decode("utf-8-sig")
    except OSError as e:
        raise InputError(f"cannot be read ({e.strerror or e})", file=name) from None
    except UnicodeDecodeError as e:
        raise InputError(f"not UTF-8 text (byte {e.start + 1} is not); save it as UTF-8",
                         file=name) from None
    rows = _json_rows(text, name) if path.suffix.lower() == ".json" else _csv_rows(text, name)
    if len(rows) > _MAX_ANSWERS:
        raise InputError(f"{len(rows):,} answers, more than a table of answers gives (at most "
                         f"{_MAX_ANSWERS})", file=name)
    out: dict[str, float | tuple[float, float]] = {}
    for key, value in rows:
        if len(key) > _MAX_NAME:
            raise InputError(f"an answer's name runs to {len(key):,} characters; "
                             "results.json's names are short (V_B, omega4)", file=name)
        if isinstance(value, dict):
            value = next((value[k] for k in ("value", "vector", "point") if k in value), None)
        try:
            if isinstance(value, (list, tuple)):
                if len(value) != 2:
                    raise ValueError
                answer = (_number(value[0]), _number(value[1]))
            else:
                answer = _number(value)
        except (TypeError, ValueError):
            if key.lower() in ("name", "quantity"):
                continue                      # a CSV header row
            raise InputError(f"the answer {key} must be a number or an [x, y] pair, got "
                             f"{_shown(value)}", file=name) from None
        if not all(math.isfinite(v) and abs(v) <= _LARGEST
                   for v in (answer if isinstance(answer, tuple) else (answer,))):
            raise InputError(f"the answer {key} must be a finite number under "
                             f"{_LARGEST:.0e} (SI), got {_shown(value)}", file=name)
        out[key] = answer
    return out


_MAX_ANSWERS = 200
"""The most answers a table may give: an exercise asks for some dozen quantities."""

_MAX_NAME = 64
"""The longest name an answer may have (characters)."""

_LARGEST = 1e100
"""The largest answer read (SI): past any mechanism's, so a percentage of it stays finite."""


def _json_rows(text: str, name: str) -> list[tuple[str, object]]:
    """The (name, value) pairs of a JSON table; an integer is read as the float it is."""
    try:
        data = json.loads(text, parse_int=float)
    except json.JSONDecodeError as e:
        raise InputError(f"not JSON ({e.msg})", file=name, line=e.lineno) from None
    except RecursionError:
        raise InputError("not a table of answers: its JSON nests too deep to read",
                         file=name) from None
    if not isinstance(data, dict):
        raise InputError("give an object of answers, {\"V_B\": 0.23, …}", file=name)
    return list(data.items())


def _csv_rows(text: str, name: str) -> list[tuple[str, object]]:
    """The (name, value or [x, y]) rows of a CSV table, blank rows skipped."""
    rows: list[tuple[str, object]] = []
    reader = csv.reader(io.StringIO(text))
    try:
        for row in reader:
            if not row or not "".join(row).strip():
                continue
            if len(row) < 2:
                raise InputError(f"a row is name,value or name,x,y; got {_shown(row)}",
                                 file=name, line=reader.line_num)
            cells = [c.strip() for c in row[1:3] if c.strip()]
            rows.append((row[0].strip(), cells[0] if len(cells) == 1 else cells))
    except csv.Error as e:
        raise InputError(f"not CSV ({e})", file=name, line=reader.line_num) from None
    return rows


def _number(value: object) -> float:
    """A value read as a number (a bool is not one).

    Raises
    ------
    ValueError
        If it is not one.
    """
    if isinstance(value, bool):
        raise ValueError
    return float(value)


def _shown(value: object) -> str:
    """A value as a message quotes it, cut short."""
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "…"


def _off(name: str, value: float, expected: float) -> str:
    """How far ``value`` is from ``expected``, in per cent where that reads."""
    share = (value - expected) / expected * 100 if expected else math.inf
    if math.isfinite(share) and abs(share) < 1e6:
        return f"{name} is {share:+.1f} % off"
    return f"{name} is {value:.4g}, where {expected:.4g} belongs"


def grade_answers(exercise: str, sol, path: Path, drafting: Drafting = DRAFTING) -> Grade:
    """Grade the answers in ``path`` against the position ``sol``'s quantities, at
    ``drafting``'s precision."""
    answers = read_answers(path)
    out = Grade(exercise, file_name(path))
    # A student gives a centre where the exercise's file puts it.
    quantities = {n: q.in_file_axes(sol.exercise.mechanism) for n, q in sol.quantities.items()}
    held = _Held(sol, drafting)
    unasked = []
    for name, value in answers.items():
        q = quantities.get(name)
        if q is None:
            unasked.append(name)
            continue
        tol = held.tolerance(name, q)
        pair = q.reference.get("vector") or q.reference.get("point")
        if isinstance(value, tuple):
            if pair is None:
                out.items.append(Item(name, "wrong magnitude", q.reference.get("value"),
                                      list(value), tol, f"{name} is a number, not a pair"))
                continue
            out.items.append(_pair_verdict(name, q, value, pair, tol))
            continue
        if "value" not in q.reference:
            out.items.append(Item(name, "wrong position", q.reference.get("point"), value,
                                  tol, f"{name} is a point: give it as [x, y]"))
            continue
        expected = q.reference["value"]
        item = Item(name, "correct", expected, value, tol)
        if abs(value - expected) > tol:
            signed = "vector" not in q.reference and name.startswith(("omega", "alpha", "T"))
            if signed and abs(value + expected) <= tol:
                item.verdict, item.message = "wrong sense", f"{name} has the wrong sign"
            else:
                item.verdict = "wrong magnitude"
                item.message = _off(name, value, expected)
        out.items.append(item)
    for name in quantities:
        if name not in answers and ("value" in quantities[name].reference
                                    or "point" in quantities[name].reference):
            ref = quantities[name].reference
            out.items.append(Item(name, "missing", ref.get("value", ref.get("point")), None,
                                  held.tolerance(name, quantities[name]),
                                  f"{name} is asked and not answered"))
    if unasked:
        out.notes.append(f"answers to what is not asked at this position, not graded: "
                         f"{', '.join(unasked)[:200]}")
    return out


class _Held:
    """The drafting tolerance (SI) each quantity of a position is held to: its vector's on
    the exercise's polygons, or a centre's on its space diagram (:func:`.drafting.
    tolerance`)."""

    def __init__(self, sol, drafting: Drafting):
        from tarsim.constructions.linkages.acceleration_polygon import drawn_acceleration_polygon
        from tarsim.constructions.linkages.velocity_polygon import drawn_velocity_polygon

        work, self.drafting = sol.work, drafting
        mech = work.mechanism
        self.polygons, self.scales = {}, {}
        for kind, make, per_cm in (
                ("V", drawn_velocity_polygon, work.scales.velocity_polygon),
                ("A", drawn_acceleration_polygon, work.scales.acceleration_polygon)):
            if kind == "A" and not work.has("acceleration polygon"):
                continue
            poly = make(work)
            stated = 10.0 / (per_cm * mech.units.metres) if per_cm else None
            self.polygons[kind] = poly
            self.scales[kind] = exercise_scale(stated, [poly.vector(n) for n in poly.tips])
        self.space = 10.0 / (work.scales.space * mech.units.metres)   # paper mm per metre

    def tolerance(self, name: str, q) -> float:
        """How far (SI) an answer to ``name`` may be from ``q``'s reference."""
        cond = max(q.conditioning, LEAST_CONDITIONING)
        if "point" in q.reference:
            return self.drafting.pen / cond / self.space
        ref = q.reference
        size = math.hypot(*ref["vector"]) if "vector" in ref else abs(ref.get("value", 0.0))
        kind, span = self._drawn_as(name)
        if kind is None:                      # drawn on no polygon: a vector LENGTH long
            rel = (self.drafting.pen / LENGTH + math.tan(self.drafting.angle)) / cond
            return max(rel, self.drafting.floor) * size
        scale = self.scales[kind] * span      # paper mm per unit of the answer
        held = tolerance(size * scale, cond, self.drafting) / scale
        tip = self._tip(name, kind)
        if tip is not None:                   # a tip cut from two lines: as on a drawing
            cut = bands(self.polygons[kind], tip, Frame(scale, 0.0, 1.0),
                        Frame(scale, 0.0, 1.0).place(self.polygons[kind].vector(tip)),
                        self.drafting.pen, self.drafting.angle, LEAST_CONDITIONING)
            held = held if cut is None else reach(cut) / scale
        return max(held, self.drafting.floor * size)

    def _tip(self, name: str, kind: str) -> str | None:
        """The tip of the polygon ``kind`` whose vector the answer ``name`` is (V_B: B)."""
        point = name[2:] if name[1:2] == "_" else ""
        tips = self.polygons[kind].tips
        return point if point in tips else None

    def _drawn_as(self, name: str) -> tuple[str | None, float]:
        """Which polygon ``name`` is read off ("V" or "A"), and the span (m) a rate is read
        over (1 for a velocity or an acceleration itself)."""
        for prefix, kind in (("omega", "V"), ("alpha", "A")):
            if name.startswith(prefix) and name[len(prefix):].isdigit() and kind in \
                    self.polygons:
                span = self.polygons[kind].spans.get(int(name[len(prefix):]), 0.0)
                return (kind, span) if span > 0.0 else (None, 1.0)
        kind = name[:1]
        if name[1:2] == "_" and kind in self.polygons:
            return kind, 1.0
        return None, 1.0


def _pair_verdict(name: str, q, value: tuple[float, float], pair, tol: float) -> Item:
    """A vector or a point given by its two components, against the expected ``pair``,
    within ``tol`` (SI) of it."""
    ex, ey = pair
    miss = math.hypot(value[0] - ex, value[1] - ey)
    item = Item(name, "correct", [ex, ey], list(value), tol)
    if miss > tol:
        size = math.hypot(ex, ey)
        if "vector" in q.reference and math.hypot(value[0] + ex, value[1] + ey) <= tol:
            item.verdict, item.message = "wrong sense", f"{name} points the other way"
        elif "point" in q.reference:
            item.verdict = "wrong position"
            item.message = f"{name} is {miss:.4g} m from where it belongs"
        else:
            item.verdict = "wrong direction"
            share = 100 * miss / size if size else math.inf
            item.message = f"{name} is {share:.1f} % of its size off" if share < 1e6 else \
                f"{name} is {miss:.4g} from where it belongs"
    return item
