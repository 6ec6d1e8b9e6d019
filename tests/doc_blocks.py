"""The fenced blocks of a Markdown page, read as the session a reader would type.

A page of the README or of ``docs/`` teaches by example, and an example that no longer
does what it says is worse than none. So each page is run as a reader would run it, top
to bottom, in a folder of its own:

- a ```` ```sh ```` block is a list of commands, one a line (a ``\\`` continues one), each
  of which must succeed;
- a ```` ```console ```` block shows commands after ``$ `` and, under each, what it
  prints; the print is compared as doctest compares, ``...`` standing for any text;
- a block right after ``<!-- file: NAME -->`` is a file the reader saves as NAME before
  the commands that follow use it;
- a block right after ``<!-- not run: REASON -->`` is left alone (the set-up commands,
  which CI runs as they are; a cluster's), and the reason is said in the source.

Other blocks (``toml`` without a file name, ``json``, ``pycon``) are read, not run here.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

__all__ = ["Block", "blocks", "commands", "console_pairs"]

_FENCE = re.compile(
    r"(?:<!--\s*(?P<directive>file|not run):\s*(?P<arg>.*?)\s*-->\s*\n)?"
    r"^```(?P<lang>[\w-]*)[^\n]*\n(?P<body>.*?)^```\s*$", re.S | re.M)


@dataclass(frozen=True)
class Block:
    """One fenced block: its language, its text, the line it opens on, its directive."""

    lang: str
    body: str
    line: int
    file: str | None = None      # the name the reader saves it as
    skip: str | None = None      # why it is not run

    def where(self, page: Path) -> str:
        return f"{page.name}:{self.line}"


def blocks(text: str) -> list[Block]:
    """Every fenced block of a page, in order."""
    found = []
    for m in _FENCE.finditer(text):
        line = text.count("\n", 0, m.start("lang")) + 1
        directive, arg = m.group("directive"), m.group("arg")
        found.append(Block(m.group("lang"), m.group("body"), line,
                           file=arg if directive == "file" else None,
                           skip=arg if directive == "not run" else None))
    return found


def commands(body: str) -> list[str]:
    """The commands of an ``sh`` block: comments and blank lines out, ``\\`` lines joined."""
    out, pending = [], ""
    for raw in body.splitlines():
        line = pending + raw
        if line.rstrip().endswith("\\"):
            pending = line.rstrip()[:-1] + " "
            continue
        pending = ""
        if line.strip() and not line.lstrip().startswith("#"):
            out.append(line.strip())
    return out


def console_pairs(body: str) -> list[tuple[str, str]]:
    """A ``console`` block as (command, the text it prints) pairs."""
    pairs: list[tuple[str, list[str]]] = []
    for line in body.splitlines():
        if line.startswith("$ "):
            pairs.append((line[2:].strip(), []))
        elif pairs:
            pairs[-1][1].append(line)
    return [(cmd, "\n".join(out).rstrip() + "\n" if any(out) else "") for cmd, out in pairs]
