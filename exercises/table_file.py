"""What the chapter files (cams, rotors, loads) share in reading their TOML tables: a failure
placed at its file:line, lists of tables with only the settings they know, numbers of a
size a figure can hold, and the units a file states.
"""

from __future__ import annotations

import math
from typing import Any

from tarsim.constructions.errors import InputError
from tarsim.constructions.units import LENGTH_UNITS
from .file_numbers import file_number
from .toml_source import SourceMap, read_toml

__all__ = ["SPEEDS", "Tables"]

SPEEDS = {"rpm": 2 * math.pi / 60, "rad/s": 1.0}
"""The speed units a chapter file may state, as rad/s each."""


class Tables:
    """A file's tables (``data``) and where each key stands in its text, for reading them
    one setting at a time."""

    def __init__(self, data: dict[str, Any], where: SourceMap, filename: str,
                 keys: dict[str, tuple[str, ...]]):
        self.data, self.where, self.filename, self.keys = data, where, filename, keys

    @classmethod
    def read(cls, text: str, filename: str, kind: str, top: tuple[str, ...],
             keys: dict[str, tuple[str, ...]], data: dict[str, Any] | None = None) -> Tables:
        """Parse ``text`` (unless ``data`` gives its tables, parsed already), refusing a
        top-level table or setting not in ``top``.

        Raises
        ------
        InputError
            For malformed TOML or an unknown table, naming file:line.
        """
        out = cls(read_toml(text, filename) if data is None else data, SourceMap(text),
                  filename, keys)
        for k in out.data:
            if k not in top:
                raise out.fail(f"unknown table or setting '{k}' in a {kind} file; expected "
                               f"{', '.join(top)}", key=k)
        return out

    def fail(self, message: str, table: str | None = None, key: str | None = None,
             index: int = 0) -> InputError:
        """The error for ``table``'s ``key`` (its ``index``-th entry), at its line."""
        line = (self.where.key(key, table, index) if key else None) or (
            self.where.header(table, index) if table else None)
        return InputError(message, file=self.filename, line=line)

    def entries(self, table: str) -> list[dict[str, Any]]:
        """The ``[[table]]`` entries (a single ``[table]`` counts as one), each holding only
        the settings :attr:`keys` names for it."""
        raw = self.data.get(table, [])
        raw = [raw] if isinstance(raw, dict) else raw
        if not isinstance(raw, list) or not all(isinstance(t, dict) for t in raw):
            raise self.fail(f"[[{table}]] must be a list of tables", table)
        for i, t in enumerate(raw):
            for k in t:
                if k not in self.keys[table]:
                    raise self.fail(f"unknown setting '{k}' in [{table}]; expected "
                                    f"{', '.join(self.keys[table])}", table, k, i)
        return raw

    def number(self, t: dict, key: str, table: str, what: str, index: int = 0,
               default: float | None = None) -> float:
        """``t[key]``, a number of a size a figure can hold (:func:`file_number`)."""
        try:
            return file_number(t.get(key, default), what)
        except ValueError as e:
            raise self.fail(str(e), table, key, index) from None

    def units(self, length: str, speed: str) -> tuple[str, str]:
        """The ``[units]`` length and speed, ``length`` and ``speed`` if not stated."""
        units = self.data.get("units", {})
        if not isinstance(units, dict):
            raise self.fail('[units] is a table: length = "mm", speed = "rpm"', None, "units")
        length, speed = units.get("length", length), units.get("speed", speed)
        if length not in LENGTH_UNITS:
            raise self.fail(f"unknown length unit '{length}'; use {', '.join(LENGTH_UNITS)}",
                            "units", "length")
        if speed not in SPEEDS:
            raise self.fail(f"unknown speed unit '{speed}'; use rpm or rad/s", "units",
                            "speed")
        return length, speed
