"""The course's chapters as the application reads, solves, draws and lists them.

Each chapter's package in this layer (``linkages``, ``gears``, ``cams``, ``balancing``,
``forces``: the flywheel) gives one :class:`Chapter` as its ``CHAPTER``, and
:data:`REGISTERED` names the packages in the order ``tarsim list`` shows them. The catalog,
:func:`tarsim.solve` and every command walk this registry and name no chapter, so a new
chapter is its package in each layer and one word here.

A file is read and parsed once: its top-level tables say whose it is (:func:`chapter_for`),
and that chapter reads the tables already parsed.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cache
from importlib import import_module
from pathlib import Path
from typing import Any

__all__ = ["Chapter", "Listing", "REGISTERED", "chapters", "chapter_of", "chapter_for",
           "read_file", "listing"]

REGISTERED = ("linkages", "gears", "cams", "balancing", "forces")
"""The chapters' packages, in the order ``tarsim list`` shows their bundled exercises."""


class Chapter:
    """One chapter: how its file is told and read, solved, drawn, and listed.

    A subclass sets the attributes and gives the methods; each method imports what it
    needs when it runs, so that finding a file's chapter loads no solver. An exercise
    says which chapter it is of by its class's ``chapter``, this chapter's :attr:`key`.
    """

    key: str
    """The chapter's package name, which its exercises carry as ``chapter``."""
    kind: str
    """One of its exercises, as a refusal speaks of it: "a gear train"."""
    folders: tuple[str, ...]
    """The catalog's folders of its bundled exercises ("" is the catalog's own)."""
    tables: tuple[str, ...] = ()
    """The top-level tables, any one of which makes a file this chapter's; none for the
    chapter of every other file (the linkages)."""
    no_angle: str | None = None
    """Why ``--angle`` means nothing to its exercises; None when it turns the input."""

    def read(self, text: str, filename: str, exercise_id: str, data: dict[str, Any]) -> Any:
        """The exercise of a file, from its ``text`` and the tables ``data`` parsed from it.

        Raises
        ------
        InputError
            Naming file:line and what to fix.
        """
        raise NotImplementedError

    def set_up(self, exercise: Any, *, paper: str, angle: float | None = None) -> Any:
        """The exercise as a command asks it: set on ``paper``, its input at ``angle`` (in
        the file's angle unit) if given. A chapter without an input angle ignores
        ``angle``; its figures are drawn for ``paper``."""
        return replace(exercise, paper=paper)

    def solve(self, exercise: Any, *, allow_undercut: bool = False) -> Any:
        """The solution, with ``write(folder, pdf=…)``, ``lines()`` for the terminal and
        ``check()``; ``allow_undercut`` lets a cam that undercuts be drawn."""
        raise NotImplementedError

    def drawing(self, exercise: Any) -> Any:
        """The one figure ``tarsim draw`` makes of the exercise."""
        raise NotImplementedError

    def title(self, exercise: Any) -> str:
        """The exercise's name, as ``tarsim list`` gives it."""
        return exercise.name

    def asks(self, exercise: Any) -> str:
        """What the exercise finds, in a few words, for ``tarsim list``."""
        raise NotImplementedError


@dataclass(frozen=True)
class Listing:
    """A bundled exercise as ``tarsim list`` shows it."""

    title: str
    origin: str | None
    """Where it comes from (the file's ``source``), if it says."""
    asks: str


@cache
def chapters() -> tuple[Chapter, ...]:
    """Every registered chapter, in :data:`REGISTERED`'s order."""
    return tuple(import_module(f"{__package__}.{key}").CHAPTER for key in REGISTERED)


def chapter_of(exercise: Any) -> Chapter:
    """The chapter an exercise (as :func:`read_file` makes it) is of."""
    return next(c for c in chapters() if c.key == exercise.chapter)


def chapter_for(data: dict[str, Any]) -> Chapter:
    """The chapter whose file has the top-level tables ``data``: the first whose tables it
    has, else the one that takes every other file."""
    marked = [c for c in chapters() if any(t in data for t in c.tables)]
    return (marked or [c for c in chapters() if not c.tables])[0]


def _parsed(path: Path) -> tuple[str, dict[str, Any]]:
    from .toml_source import read_source, read_toml

    text = read_source(path)
    return text, read_toml(text, str(path))


def read_file(path: str | Path, exercise_id: str) -> Any:
    """The exercise of the file at ``path``, read and parsed once, by its chapter.

    Raises
    ------
    InputError
        If it cannot be read or is not a valid exercise, naming file:line.
    """
    text, data = _parsed(Path(path))
    return chapter_for(data).read(text, str(path), exercise_id, data)


def listing(path: str | Path, exercise_id: str) -> Listing:
    """How ``tarsim list`` shows the exercise at ``path``.

    Raises
    ------
    InputError
        If it cannot be read.
    """
    text, data = _parsed(Path(path))
    origin = data.get("source")
    chapter = chapter_for(data)
    ex = chapter.read(text, str(path), exercise_id, data)
    return Listing(chapter.title(ex), str(origin) if origin else None, chapter.asks(ex))
