"""What the server refuses, and a refusal as the page reads it: one line and where.

Every answer that is not a solution is ``{"error": line, "where": {...}}`` with a 4xx or
5xx status. The line is the one ``tarsim solve`` prints after ``Error:``, led by the file
it concerns as the command line leads it; ``where`` names the part of the mechanism the
error is about (a link, a joint, a setting of the file), so that the page can show the
error beside what caused it.
"""

from __future__ import annotations

import re
from typing import Any

from tarsim.constructions.errors import (AssemblyError, GeometryError, IllConditioned,
                                         InputError, TarsimError)
from tarsim.graphics.atomic_files import RenderError

__all__ = ["Refused", "status_of", "refusal", "placed", "where"]

_LINK = re.compile(r"^link (\d+)\b")
"""How an InputError's key names a numbered [[link]] table: "link 3, lengths"."""
_SAID_LINK = re.compile(r"\blink (\d+)\b")


class Refused(TarsimError):
    """A request the server will not answer as asked: outside its folder, too big, unknown."""

    def __init__(self, message: str, status: int):
        self.status = status
        super().__init__(message)


def status_of(error: TarsimError) -> int:
    """The HTTP status of ``error``: a refusal's own, 503 for a figure format that needs
    libcairo2 where it is missing, else 422 (the exercise cannot be solved as sent)."""
    if isinstance(error, Refused):
        return error.status
    if isinstance(error, RenderError) and "cairo" in str(error):
        return 503
    return 422


def placed(error: TarsimError, name: str, text: str | None = None) -> tuple[str, int | None]:
    """``error``'s line as ``tarsim solve NAME`` prints it, and the line of the file it
    names: an error of solving is led by the file ``name`` (and, for one of assembly, the
    line of ``text`` it concerns); an error of input names its own file already.

    >>> placed(AssemblyError("link 3 cannot reach", link=3), "my.toml")
    ('my.toml: link 3 cannot reach', None)
    """
    from ..linkages.mechanism_file import line_of

    solving = (isinstance(error, (AssemblyError, GeometryError, IllConditioned))
               or type(error) is TarsimError or isinstance(error, InputError) and not error.file)
    if not solving or name in str(error):
        return str(error), getattr(error, "line", None)
    line = line_of(error, name, text) if isinstance(error, AssemblyError) and text else None
    return (f"{name}:{line}: {error}" if line else f"{name}: {error}"), line


def where(error: TarsimError) -> dict[str, Any]:
    """The part of the mechanism ``error`` names: ``{"link": 3}``, ``{"joint": "B"}``,
    ``{"field": "input.angle"}`` (a file's key), or ``{}``; with ``line`` where the file's
    line is known.

    >>> where(AssemblyError("link 3 cannot reach", link=3, joint="B"))
    {'link': 3, 'joint': 'B'}
    >>> where(InputError("must be positive", file="x.toml", line=19, key="link 3, lengths"))
    {'link': 3, 'field': 'link 3, lengths', 'line': 19}
    """
    out: dict[str, Any] = {}
    if isinstance(error, AssemblyError):
        if error.link is not None:
            out["link"] = error.link
        if error.joint:
            out["joint"] = error.joint
    elif isinstance(error, InputError):
        if error.key and (m := _LINK.match(error.key)):
            out["link"] = int(m.group(1))
        if error.key:
            out["field"] = error.key
        if error.line is not None:
            out["line"] = error.line
    if not out and not isinstance(error, Refused) and (m := _SAID_LINK.search(str(error))):
        out["link"] = int(m.group(1))             # best effort: the link the line names
    return out


def refusal(error: TarsimError, name: str = "", text: str | None = None
            ) -> tuple[int, dict[str, Any]]:
    """The status and JSON body of ``error``, its line placed in the file ``name``."""
    line, at = placed(error, name, text) if name else (str(error), None)
    part = where(error)
    if at is not None:
        part["line"] = at
    return status_of(error), {"error": line, "where": part}
