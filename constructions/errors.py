"""The error classes of tarsim: every failure a user can cause is one of these.

Each ``__str__`` is a single line that says what is wrong, where, and how to fix
it; the command line prints it after ``Error:`` and exits 1, or 3 for a
:class:`CheckMismatch` (2 is click's, for a bad option). An error writing a figure
is :class:`tarsim.graphics.export.RenderError`, a kind of :class:`TarsimError`.
"""

from __future__ import annotations

import re

__all__ = [
    "TarsimError",
    "InputError",
    "GeometryError",
    "NoIntersection",
    "DegenerateInput",
    "AssemblyError",
    "CheckMismatch",
    "IllConditioned",
]


_POSITION = re.compile(r"θ\d+ = |\bt = ")
"""How a line names a position of the input: "θ2 = 90°", "t = 2.34 s"."""


class TarsimError(Exception):
    """Root of every error tarsim raises on purpose; the CLI catches only this.

    Its line is short; ``detail`` is the longer story behind it (the error it arose from),
    which ``tarsim --verbose`` prints on a second line.
    """

    detail: str = ""

    def because(self, cause: Exception) -> TarsimError:
        """The same error, with ``cause``'s line (and its own story) as its detail."""
        inner = getattr(cause, "detail", "")
        self.detail = f"{cause}" + (f" ({inner})" if inner else "")
        return self

    def at(self, where: str) -> TarsimError:
        """The same error, said to have happened at ``where`` (one of an exercise's
        positions): the same class and attributes, ``where`` leading its line (a line
        that already names the place, or a position of its own, is left as it is)."""
        if where not in str(self) and not _POSITION.search(str(self)):
            self.args = (f"at {where}: {self}",)
        return self

    def in_file(self, path: str) -> TarsimError:
        """The same error, led by the file it concerns as a whole (``path: …``)."""
        if path not in str(self):
            self.args = (f"{path}: {self}",)
        return self


class InputError(TarsimError):
    """A mechanism or exercise file is malformed or names something unknown."""

    def __init__(self, message: str, *, file: str | None = None,
                 line: int | None = None, column: int | None = None,
                 key: str | None = None):
        self.message = message
        self.file = file
        self.line = line
        self.column = column
        self.key = key
        super().__init__(str(self))

    def in_file(self, path: str) -> InputError:
        """As :meth:`TarsimError.in_file`, where no file is named yet."""
        if self.file is None:
            self.file = path
            self.args = (str(self),)
        return self

    def at(self, where: str) -> InputError:
        """As :meth:`TarsimError.at`; the file and line still lead the line."""
        if where not in self.message:
            self.message = f"at {where}: {self.message}"
            self.args = (str(self),)
        return self

    def __str__(self) -> str:
        where = ""
        if self.file:
            where = self.file
            if self.line is not None:
                where += f":{self.line}"
                if self.column is not None:
                    where += f":{self.column}"
            where += ": "
        key = f"[{self.key}] " if self.key else ""
        return f"{where}{key}{self.message}"


class GeometryError(TarsimError):
    """A drafting act has no answer for the objects it was given."""


class NoIntersection(GeometryError):
    """Two carriers do not meet; ``margin`` says by how much they miss."""

    def __init__(self, message: str, margin: float):
        self.margin = margin
        super().__init__(message)


class DegenerateInput(GeometryError):
    """The inputs of a drafting act are degenerate (coincident points, parallel lines)."""


class AssemblyError(TarsimError):
    """The mechanism cannot be put together at this input position."""

    def __init__(self, message: str, *, link: int | None = None,
                 joint: str | None = None, angle_deg: float | None = None):
        self.link = link
        self.joint = joint
        self.angle_deg = angle_deg
        super().__init__(message)


class BranchError(AssemblyError):
    """A point's branch (its [assembly] entry) is missing, or does not apply where it is."""


class DeadPoint(AssemblyError):
    """The input stands at a dead point: the position assembles but ω (or α) is undefined."""


class IllConditioned(TarsimError):
    """A construction too ill-conditioned here to vouch for the number it reads off.

    ``name`` is the quantity, ``method`` how it was drawn, ``conditioning`` the worst
    along its construction and ``miss`` how far it stands from the analytic value,
    relative to the quantity's scale; ``by_reference`` when the analytic value itself is
    what rounding has lost.
    """

    def __init__(self, message: str, *, name: str, method: str, conditioning: float,
                 miss: float, by_reference: bool = False):
        self.name = name
        self.method = method
        self.conditioning = conditioning
        self.miss = miss
        self.by_reference = by_reference
        super().__init__(message)


class CheckMismatch(TarsimError):
    """A constructed number disagrees with the analytic one beyond its tolerance."""

    def __init__(self, names: list[str]):
        self.names = list(dict.fromkeys(names))
        super().__init__(f"{', '.join(self.names)} disagree{'s' if len(self.names) == 1 else ''} "
                         "with the analytic solution beyond tolerance")
