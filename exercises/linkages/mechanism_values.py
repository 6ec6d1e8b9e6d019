"""The values of a mechanism file's tables: each read and checked, or refused at its file:line.

A :class:`TableReader` holds the file's tables and its :class:`~.toml_source.SourceMap`,
and reads numbers, lengths, points, angles, names and link numbers out of them, each
refused with an :class:`~tarsim.constructions.errors.InputError` that names the file,
the line and the key. It also reads the ``[units]`` the other values are taken in. The
tables themselves are read by subject: the frame and links
(:mod:`~.mechanism_links`), the sliders and contacts (:mod:`~.mechanism_joints`) and
the input (:mod:`~.mechanism_input`).
"""

from __future__ import annotations

import difflib
import math
import re
from typing import Any

from tarsim.constructions.errors import InputError
from tarsim.constructions.joints import Slide
from tarsim.constructions.model import GivenRate, Link
from tarsim.constructions.units import LENGTH_UNITS, Units
from ..file_numbers import LARGEST, RANGE, _float, arithmetic, in_range, radians_in_turn
from ..toml_source import _CONTROL, SourceMap

__all__ = ["TableReader"]

_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_']*$")


class TableReader:
    """A mechanism file's tables, read value by value; every refusal names its file:line.

    ``units`` and ``links`` are set as the file is read (the units first, the links once
    the frame and the ``[[link]]`` tables are), and the values after them are taken in
    those units, on those links.
    """

    def __init__(self, data: dict[str, Any], where: SourceMap, filename: str):
        self.d = data
        self.where = where
        self.file = filename
        self.given: GivenRate | None = None
        self.slides: tuple[Slide, ...] = ()
        """The straight slides, once read: a speed is given to a point on one."""
        self.units: Units
        self.links: dict[int, Link]
        self.file_origin = (0.0, 0.0)
        """The frame's first point as the file gives it, the model's (0, 0) (see :meth:`xy`)."""

    # ----- errors --------------------------------------------------------------
    def fail(self, message: str, *, table: str | None = None, index: int = 0,
             key: str | None = None) -> InputError:
        """The error to raise: ``message`` at the line of ``key`` in the ``index``-th
        ``table`` (or of that table's header), naming the table and key as a path."""
        line = (self.where.key(key, table, index) if key
                else self.where.header(table, index) if table else None)
        label = self._entry(table, index) if table else None
        if key:
            # A TOML path for a plain table ("input.link"); "link 3, AB" for a numbered one.
            sep = ", " if table in ("link", "slider", "contact") else "."
            # A key is the file's own text: a bidi override in it would reorder the line.
            key = _CONTROL.sub(lambda m: f"\\u{ord(m.group()):04x}", key)
            label = f"{label}{sep}{key}" if label else key
        return InputError(message, file=self.file, line=line, key=label)

    def _entry(self, table: str, index: int) -> str:
        """How an error names a table: "link 3" by its number, else "slider 2" by its place
        among the ``[[slider]]`` tables; a plain table by its name."""
        if table not in ("link", "slider", "contact"):
            return table
        entries = self.d.get(table)
        entry = entries[index] if isinstance(entries, list) and index < len(entries) else None
        number = entry.get("number") if isinstance(entry, dict) else None
        if table == "link" and isinstance(number, int) and not isinstance(number, bool):
            return f"link {number}"
        return f"{table} {index + 1}"

    def unknown(self, got: str, valid: list[str] | tuple[str, ...], what: str,
                **where) -> InputError:
        """The error for a name not among ``valid``, suggesting the nearest one."""
        close = difflib.get_close_matches(got, list(valid), n=1)
        hint = (f"; did you mean '{close[0]}'?" if close
                else f"; expected one of: {', '.join(valid)}")
        return self.fail(f"unknown {what} '{got}'{hint}", **where)

    def list_of(self, table: str) -> list[dict[str, Any]]:
        """The ``[[table]]`` tables, each a dict (none if the file has none)."""
        v = self.d.get(table, [])
        if not isinstance(v, list) or not all(isinstance(x, dict) for x in v):
            raise self.fail(f"write each {table} as its own [[{table}]] table", table=table)
        return v

    def table(self, name: str, required: bool) -> dict[str, Any]:
        """The ``[name]`` table (empty if absent and not ``required``)."""
        v = self.d.get(name)
        if v is None:
            if required:
                raise InputError(f"the file has no [{name}] table", file=self.file)
            return {}
        if not isinstance(v, dict):
            raise self.fail(f"[{name}] must be a table", key=name)
        return v

    def read_units(self) -> Units:
        """Read ``[units]``: the file's length, angle and angular-velocity units."""
        u = self.table("units", False)
        allowed = {"length": tuple(LENGTH_UNITS), "angle": ("deg", "rad"),
                   "angular_velocity": ("rad/s", "rpm")}
        for k, v in u.items():
            if k not in allowed:
                raise self.unknown(k, tuple(allowed), "unit setting", table="units", key=k)
            if v not in allowed[k]:
                raise self.unknown(str(v), allowed[k], f"{k} unit", table="units", key=k)
        return Units(u.get("length", "mm"), u.get("angle", "deg"),
                     u.get("angular_velocity", "rad/s"))

    # ----- values ----------------------------------------------------------------
    def number(self, v: Any, what: str, *, size: bool = False, bounded: bool = True,
               **where) -> float:
        """A finite number, no larger than :data:`LARGEST` if ``bounded``; with ``size`` (a
        length, a rate) none smaller than its reciprocal either, but 0. Arithmetic of
        numbers in a string ("120/2", the crank as half the stroke; "10*pi") is taken at
        its value."""
        exact = arithmetic(v, pi=True) if isinstance(v, str) else None
        if exact is not None:
            v = _float(exact)
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise self.fail(f"{what} must be a number, got {v!r}", **where)
        x = _float(v)
        if not math.isfinite(x):
            raise self.fail(f"{what} must be a finite number, got {v!r:.40}", **where)
        if (bounded and abs(x) > LARGEST) or (size and not in_range(x)):
            raise self.fail(f"{what} = {x:.4g} is out of the range tarsim takes ({RANGE})",
                            **where)
        return x

    def length(self, v: Any, what: str, **where) -> float:
        """A positive length in the file's unit, in metres."""
        x = self.number(v, what, size=True, **where)
        if x <= 0:
            raise self.fail(f"{what} must be a positive length, got {v:g}", **where)
        return x * self.units.metres

    def pair(self, v: Any, what: str, **where) -> tuple[float, float]:
        """A pair [x, y] of numbers, as the file gives it."""
        if not (isinstance(v, list) and len(v) == 2):
            raise self.fail(f"{what} must be a pair [x, y], got {v!r}", **where)
        return (self.number(v[0], what, **where), self.number(v[1], what, **where))

    def xy(self, v: Any, what: str, **where) -> tuple[float, float]:
        """A point the file places, in metres from the frame's first point.

        A line's equation, an intersection's rounding and every conditioning are measured
        from the origin, so a linkage drawn 1 km from it would lose digits, and could even
        pass a check it should fail, that the same linkage at the origin keeps. The model is
        therefore placed about its frame, moved in the file's own units before they are
        turned into metres, so that a file moved whole gives the same model to the bit
        wherever its numbers allow; ``Mechanism.origin`` says points back where the file
        put them.
        """
        (x, y), (ox, oy), s = self.pair(v, what, **where), self.file_origin, self.units.metres
        return ((x - ox) * s + 0.0, (y - oy) * s + 0.0)

    def angle(self, v: Any, what: str, **where) -> float:
        """Any finite angle: it is taken less whole turns (:func:`radians_in_turn`)."""
        return radians_in_turn(self.number(v, what, bounded=False, **where), self.units.angle)

    def text(self, v: Any, what: str, *, lines: bool = False, **where) -> str:
        """A free text (a name, a source): a string with no control character in it."""
        if not isinstance(v, str):
            raise self.fail(f"{what} must be a string, got {v!r:.40}", **where)
        bad = next((c for c in _CONTROL.findall(v) if not (lines and c in "\n\t")), None)
        if bad is not None:
            raise self.fail(f"{what} holds the control character U+{ord(bad):04X}; "
                            "remove it", **where)
        return v

    def name(self, v: Any, what: str, **where) -> str:
        """A point name: a letter, then letters, digits, ``_`` or ``'``."""
        if not (isinstance(v, str) and _NAME.match(v)):
            raise self.fail(f"{what} must be a point name such as \"A\" or \"O2\", got {v!r}",
                            **where)
        return v

    def link_number(self, v: Any, key: str, where: dict) -> int:
        """The number of a link the file has defined."""
        if isinstance(v, bool) or not isinstance(v, int):
            raise self.fail(f"{key} must be a link number, got {v!r}", key=key, **where)
        if v not in self.links:
            raise self.unknown(str(v), [str(n) for n in sorted(self.links)], "link",
                               key=key, **where)
        return v
