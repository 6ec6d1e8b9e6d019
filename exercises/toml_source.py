"""A file's text and its TOML tables, read with errors that say file:line.

Every reader of a tarsim file (a mechanism, an exercise, a gear train, a cam, a rotor)
starts here: :func:`read_source` reads the text, capped in size and decoded as UTF-8;
:func:`read_toml` parses it, placing a syntax error at its line and column; and a
:class:`SourceMap` finds the line of a table or key, which tomllib does not keep.
``_CONTROL`` matches the characters no free text of a file may hold.
"""

from __future__ import annotations

import re
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from tarsim.constructions.errors import InputError
from .toml_depth import check_depth

__all__ = ["read_source", "read_toml", "SourceMap", "MOST_BYTES"]

MOST_BYTES = 1_000_000
"""The largest file tarsim reads. A textbook mechanism takes a few kilobytes; the cap is
read, not trusted to a file's stated size, so a device or a pipe cannot run it out of
memory."""

_CONTROL = re.compile("[\x00-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")
"""Control characters, and the bidirectional overrides that reorder what a figure shows."""


def read_source(path: str | Path) -> str:
    """The text of the file at ``path``.

    Raises
    ------
    InputError
        If it cannot be read, or is not UTF-8 text (naming the line of the first bad byte).
    """
    path = Path(path)
    try:
        with path.open("rb") as f:
            data = f.read(MOST_BYTES + 1)
        if len(data) > MOST_BYTES:
            raise InputError(f"is larger than {MOST_BYTES // 1000:,} kB, the most tarsim reads; "
                             "a mechanism file takes a few kB", file=str(path))
        return data.decode("utf-8-sig")        # a byte-order mark, as Notepad saves, read past
    except UnicodeDecodeError as e:
        raise InputError(f"is not UTF-8 text (byte 0x{e.object[e.start]:02x}); save it as UTF-8",
                         file=str(path), line=e.object[:e.start].count(b"\n") + 1) from None
    except OSError as e:
        raise InputError(f"cannot read the file: {e.strerror or e}", file=str(path)) from None


def read_toml(text: str, filename: str) -> dict[str, Any]:
    """The tables of a TOML text; an InputError at file:line if it is not valid TOML, or
    nests deeper than tomllib reads in good time (:mod:`.toml_depth`)."""
    check_depth(text, filename)
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise _toml_error(e, text, filename) from None
    except RecursionError:
        raise InputError("nests arrays or tables too deeply to read as a mechanism",
                         file=filename) from None


def _toml_error(e: tomllib.TOMLDecodeError, text: str, filename: str) -> InputError:
    msg = str(e)
    m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
    if m:
        return InputError(f"not valid TOML: {msg[:m.start()].strip()}", file=filename,
                          line=int(m.group(1)), column=int(m.group(2)))
    m = re.search(r"\(at end of document\)", msg)
    # The file ended too soon: point at its last character.
    return InputError(f"not valid TOML: {msg[:m.start()].strip() if m else msg}", file=filename,
                      line=text.count("\n") + 1, column=len(text) - text.rfind("\n"))


@dataclass
class SourceMap:
    """Finds the line of a table or key, since tomllib keeps no positions."""

    text: str

    def __post_init__(self) -> None:
        self.lines = self.text.splitlines()

    def header(self, table: str, index: int = 0) -> int | None:
        """Line (1-based) of the ``index``-th ``[table]`` or ``[[table]]`` header."""
        pat = re.compile(r"^\s*\[\[?\s*" + re.escape(table) + r"\s*\]\]?\s*(#.*)?$")
        hits = [i + 1 for i, line in enumerate(self.lines) if pat.match(line)]
        return hits[index] if index < len(hits) else None

    def key(self, key: str, table: str | None = None, index: int = 0) -> int | None:
        """Line of ``key`` inside the ``index``-th ``table`` (or the top level)."""
        start = self.header(table, index) if table else 0
        if table and start is None:
            # Written inline (``input = { … }``): the line that opens it.
            return self._assignment(table)
        pat = re.compile(r"(^|[\s{,])" + re.escape(key) + r"\s*=")
        for i in range(start or 0, len(self.lines)):
            line = self.lines[i]
            if i >= (start or 0) + (1 if table else 0) and re.match(r"^\s*\[", line):
                break
            if pat.search(line.split("#", 1)[0]):
                return i + 1
        if not table:
            return self.header(key) or self._assignment(key)
        return start

    def _assignment(self, key: str) -> int | None:
        pat = re.compile(r"^\s*" + re.escape(key) + r"\s*=")
        return next((i + 1 for i, line in enumerate(self.lines) if pat.match(line)), None)
