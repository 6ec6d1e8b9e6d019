"""A mechanism's name in other languages: the ``[names]`` table of any exercise file.

A figure's title opens with the mechanism's name, as its file gives it. A file written for
Persian readers names it in Persian too (``[names] fa = "…"``); a solution drawn in Persian
then titles its figures and steps with that name. Every kind of exercise file (a linkage,
a gear train, a cam, a rotor) reads the table here and keeps it as ``names``.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from tarsim.constructions.errors import InputError
from .toml_source import SourceMap

__all__ = ["read_names", "named_in"]

_LANGUAGES = ("fa",)
"""The languages other than English that have words (constructions/phrases)."""


def read_names(data: dict[str, Any], where: SourceMap, filename: str
               ) -> tuple[tuple[str, str], ...]:
    """The file's ``[names]``, by language; () if it has none.

    Raises
    ------
    InputError
        At its line, for a language with no words or a name that is not one line of text.
    """
    names = data.get("names", {})
    if not isinstance(names, dict):
        raise InputError("names is a table of the mechanism's name in other languages: "
                         '[names] fa = "…"', file=filename, line=where.key("names"))
    for lang, name in names.items():
        line = where.key(lang, "names") or where.header("names")
        if lang not in _LANGUAGES:
            raise InputError(f"names.{lang}: there are words for {', '.join(_LANGUAGES)} "
                             "only; remove it", file=filename, line=line)
        if not isinstance(name, str) or not name.strip() or any(ord(c) < 32 for c in name):
            raise InputError(f"names.{lang} must be one line of text, the mechanism's name",
                             file=filename, line=line)
    return tuple(names.items())


def named_in(exercise: Any, lang: str) -> Any:
    """``exercise`` with its mechanism named in ``lang`` (Persian with Latin digits takes the
    Persian name) if its file gives a name in it; as it is otherwise. Each kind of exercise
    says where its name is kept (``renamed``)."""
    name = dict(getattr(exercise, "names", ())).get(lang.partition("_")[0])
    return exercise if name is None else exercise.renamed(name)


def renamed_field(exercise: Any, name: str) -> Any:
    """The exercise with its own ``name`` field set: a cam's and a rotor's ``renamed``."""
    return replace(exercise, name=name)
