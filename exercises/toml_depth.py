"""Bound how deep a TOML text nests before it is parsed.

tomllib's time and memory grow with the square of a dotted key's length: a 100 kB file
whose last line is a key 50,000 parts deep runs for minutes and takes gigabytes before it
is read. One linear pass over the text measures how deep each value would sit (the parts
of its table header, of its dotted key, and the arrays and inline tables around it) and
refuses the file at the first one deeper than :data:`MOST_DEPTH`, naming its line. The
pass follows TOML's strings (basic, literal, multi-line) and comments, so a dot, a bracket
or a brace inside one is not counted. It is no parser: what it passes, tomllib still reads
and may refuse.
"""

from __future__ import annotations

import re

from tarsim.constructions.errors import InputError

__all__ = ["MOST_DEPTH", "check_depth"]

MOST_DEPTH = 32
"""The deepest a value may sit in a file: the parts of its table's header and its key, and
each array and inline table it is in, counted together. A textbook exercise's deepest
value sits 4 deep (a ``[[link]]`` entry's ``lengths = { O2A = … }``: link, the entry,
lengths, O2A); the rest leave room for any table written inline. A dotted key of 32 parts
costs tomllib microseconds, where 50,000 cost it minutes."""

_KEY, _VALUE, _HEADER, _REST = range(4)
"""Where the pass is: reading a key, a value, a ``[table]`` header, or the rest of a line
whose statement has ended (a comment, or text tomllib will refuse)."""

# The next character that matters in each place; everything between is skipped in C.
_AT_KEY = re.compile(r"\"\"\"|'''|[\"'#\n\[\]{}.=,]")
_IN_TABLE = re.compile(r"\"\"\"|'''|[\"'#\n\[\]{},]")  # a value in an inline table
_IN_ARRAY = re.compile(r"\"\"\"|'''|[\"'#\[\]{}]")     # commas and lines do not matter
_AT_TOP = re.compile(r"\"\"\"|'''|[\"'#\n\[{]")        # a value at the top level
_AT_REST = re.compile(r"\"\"\"|'''|[\"'#\n]")          # only where the line ends matters
_BASIC = re.compile(r'[^"\\\n]*(?:\\.[^"\\\n]*)*"?')      # after the opening quote
_LITERAL = re.compile(r"[^'\n]*'?")
_BLANK = re.compile(r"[ \t]*")


def check_depth(text: str, filename: str) -> None:
    r"""Refuse ``text`` if any value in it sits deeper than :data:`MOST_DEPTH`.

    Linear in the text's length, and it stops at the first value too deep.

    Raises
    ------
    InputError
        Naming ``filename`` and the line where the depth is passed.

    Examples
    --------
    >>> check_depth("[a.b]\nc = { d = [1, 2] }  # 1 and 2 sit 5 deep: a, b, c, d, [i]", "f")
    >>> check_depth("x." * 40 + "y = 1", "f.toml")
    Traceback (most recent call last):
    ...
    tarsim.constructions.errors.InputError: f.toml:1:64: nests arrays or tables too deeply ...
    """
    stack: list[tuple[str, int]] = []   # the open arrays and inline tables, with their depths
    mode, parts, base, header = _KEY, 1, 0, 0
    line_start, pos, end = 0, 0, len(text)
    while pos < end:
        if mode == _VALUE and stack:
            pattern = _IN_ARRAY if stack[-1][0] == "[" else _IN_TABLE
        else:
            pattern = (_AT_KEY if mode in (_KEY, _HEADER) else _AT_TOP if mode == _VALUE
                       else _AT_REST)
        m = pattern.search(text, pos)
        if m is None:
            return
        token, at, pos = m.group(), m.start(), m.end()
        if token in ('"""', "'''"):
            pos = _after_multiline(text, pos, token)
        elif token == '"':
            pos = _BASIC.match(text, pos).end()
        elif token == "'":
            pos = _LITERAL.match(text, pos).end()
        elif token == "#":
            pos = text.find("\n", pos)
            pos = end if pos < 0 else pos
        elif token == "\n":
            if not stack:               # a statement ends: the next line starts a key
                mode, parts, base, line_start = _KEY, 1, header, pos
            elif stack[-1][0] == "{":   # not allowed inside an inline table: tomllib says so
                mode = _REST
        elif mode == _HEADER:
            if token == ".":
                parts += 1
                if parts > MOST_DEPTH:
                    raise _too_deep(text, at, filename)
            elif token == "]":          # what the table holds sits one deeper still
                header, mode = parts, _REST
                if parts + 1 > MOST_DEPTH:
                    raise _too_deep(text, at, filename)
            else:
                mode = _REST
        elif mode == _KEY:
            if token == ".":
                parts += 1
            elif token == "=":
                mode, depth = _VALUE, base + parts
                if depth > MOST_DEPTH:
                    raise _too_deep(text, at, filename)
            elif token == "[" and not stack and _BLANK.fullmatch(text, line_start, at):
                # A [table] header, or an [[array of tables]] (its entry one level deeper).
                mode, parts, base = _HEADER, 1, 0
                if text.startswith("[", pos):
                    pos, parts = pos + 1, 2
            elif token == "}" and stack and stack[-1][0] == "{":
                stack.pop()             # an empty inline table, or a trailing comma
                mode = _VALUE if stack else _REST
            else:
                mode = _REST            # not TOML: tomllib will say where
            if base + parts > MOST_DEPTH:
                raise _too_deep(text, at, filename)
        elif mode == _REST:
            pass
        elif token in "[{":
            depth = stack[-1][1] + 1 if stack and stack[-1][0] == "[" else base + parts
            if depth + 1 > MOST_DEPTH:  # what it holds sits one deeper still
                raise _too_deep(text, at, filename)
            stack.append((token, depth))
            if token == "{":
                mode, parts, base = _KEY, 1, depth
        elif token in "]}":
            if stack and stack[-1][0] == ("[" if token == "]" else "{"):
                stack.pop()
            if not stack:
                mode = _REST
            elif stack[-1][0] == "{":
                base = stack[-1][1]
        elif token == ",":              # in an inline table: the next key
            mode, parts, base = _KEY, 1, stack[-1][1]


def _after_multiline(text: str, pos: int, quote: str) -> int:
    """The position after a multi-line string that opened with ``quote`` just before
    ``pos``: past its closing quotes and the up to two quotes of its content that may run
    into them; the end of the text if it never closes."""
    while True:
        close = text.find(quote, pos)
        if close < 0:
            return len(text)
        if quote == '"""':
            before = close
            while text[before - 1] == "\\":
                before -= 1
            if (close - before) % 2:    # an escaped quote: the string goes on
                pos = close + 1
                continue
        pos = close + 3
        for _ in range(2):
            if text.startswith(quote[0], pos):
                pos += 1
        return pos


def _too_deep(text: str, at: int, filename: str) -> InputError:
    return InputError(f"nests arrays or tables too deeply to read: past {MOST_DEPTH} keys, tables "
                      "and arrays deep (an exercise needs 4)", file=filename,
                      line=text.count("\n", 0, at) + 1, column=at - text.rfind("\n", 0, at))
