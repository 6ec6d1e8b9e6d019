"""An exercise: a mechanism file plus an ``[ask]`` table saying what to find and how.

::

    [ask]
    find = ["centres", "omega3", "omega4", "V_D"]     # what the exercise asks for
    methods = ["radius-rotation", "components"]       # how to find each velocity

``find`` names quantities as results.json does: ``centres`` (all of them), a
single centre ``I24``, an angular velocity ``omega3``, a point's velocity ``V_D``.
``methods`` are the velocity constructions, each drawn as its own figure:
``radius-rotation``, ``parallel-line``, ``components``. A file without ``[ask]``
asks for every centre and the ω of every moving link.
"""

from __future__ import annotations

import difflib
import re
import tomllib
from dataclasses import dataclass
from pathlib import Path

from constructions.errors import InputError
from constructions.model import Mechanism

from .mechanism_file import SourceMap, _Reader, _toml_error

__all__ = ["Exercise", "load_exercise", "parse_exercise", "VELOCITY_METHODS"]

VELOCITY_METHODS = ("radius-rotation", "parallel-line", "components")
_ASK_KEYS = ("find", "methods")
_QUANTITY = re.compile(r"^(centres|I(\d)(\d)|I(\d+),(\d+)|omega(\d+)|V_([A-Za-z][A-Za-z0-9_']*))$")


@dataclass(frozen=True)
class Exercise:
    """What to solve: the mechanism, the quantities asked, the velocity methods to draw."""

    id: str
    mechanism: Mechanism
    find: tuple[str, ...]
    methods: tuple[str, ...]

    @property
    def centres(self) -> tuple[tuple[int, int], ...]:
        """The centres asked for, as link pairs; every pair when ``centres`` is asked."""
        if "centres" in self.find:
            n = sorted(self.mechanism.numbers)
            return tuple((a, b) for i, a in enumerate(n) for b in n[i + 1:])
        return tuple(_pair(q) for q in self.find if q.startswith("I"))

    @property
    def omegas(self) -> tuple[int, ...]:
        """Links whose angular velocity is asked."""
        return tuple(int(q[5:]) for q in self.find if q.startswith("omega"))

    @property
    def velocities(self) -> tuple[str, ...]:
        """Points whose velocity is asked."""
        return tuple(q[2:] for q in self.find if q.startswith("V_"))


def load_exercise(path: str | Path, exercise_id: str | None = None) -> Exercise:
    """Read an exercise file (a mechanism file, optionally with ``[ask]``).

    Raises
    ------
    InputError
        Naming file:line and the field, with the closest valid name.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise InputError(f"cannot read the file: {e.strerror or e}", file=str(path)) from None
    return parse_exercise(text, str(path), exercise_id or path.stem)


def parse_exercise(text: str, filename: str = "<string>", exercise_id: str = "exercise") -> Exercise:
    """Parse an exercise from TOML text (see :func:`load_exercise`)."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise _toml_error(e, text, filename) from None
    where = SourceMap(text)
    ask = data.pop("ask", None)
    mech = _Reader(data, where, filename).mechanism()
    return _read_ask(ask, mech, where, filename, exercise_id)


def _read_ask(ask, mech: Mechanism, where: SourceMap, filename: str, exercise_id: str) -> Exercise:
    def fail(message: str, key: str | None = None) -> InputError:
        line = where.key(key, "ask") if key else where.header("ask")
        return InputError(message, file=filename, line=line, key=f"ask.{key}" if key else "ask")

    if ask is None:
        moving = tuple(f"omega{n}" for n in sorted(mech.numbers) if n not in (1, mech.drive.link))
        return Exercise(exercise_id, mech, ("centres",) + moving, ("radius-rotation",))
    if not isinstance(ask, dict):
        raise fail("[ask] must be a table")
    for k in ask:
        if k not in _ASK_KEYS:
            close = _closest(k, _ASK_KEYS)
            hint = f"did you mean '{close}'?" if close else f"expected {' or '.join(_ASK_KEYS)}"
            raise fail(f"unknown setting '{k}' in [ask]; {hint}", k)
    find = ask.get("find")
    if not (isinstance(find, list) and find and all(isinstance(q, str) for q in find)):
        raise fail('[ask] needs find = [...], a list of quantities such as "centres", "I13", '
                   '"omega4", "V_D"', "find" if "find" in ask else None)
    valid = _valid_quantities(mech)
    for q in find:
        if q not in valid:
            close = _closest(q, sorted(valid))
            hint = (f"did you mean '{close}'?" if close
                    else 'use "centres", "I<i><j>", "omega<n>" or "V_<point>"')
            raise fail(f"cannot find '{q}' for this mechanism; {hint}", "find")
    methods = ask.get("methods", ["radius-rotation"])
    if not (isinstance(methods, list) and methods and all(isinstance(m, str) for m in methods)):
        raise fail('methods must be a list such as ["radius-rotation", "components"]', "methods")
    for m in methods:
        if m not in VELOCITY_METHODS:
            close = _closest(m, VELOCITY_METHODS)
            hint = f"did you mean '{close}'?" if close else f"use {', '.join(VELOCITY_METHODS)}"
            raise fail(f"unknown velocity method '{m}'; {hint}", "methods")
    return Exercise(exercise_id, mech, tuple(dict.fromkeys(find)), tuple(dict.fromkeys(methods)))


def _closest(got: str, valid) -> str | None:
    """The valid name nearest ``got``: a spelling neighbour, or one it abbreviates."""
    close = difflib.get_close_matches(got, list(valid), n=1)
    if close:
        return close[0]
    return next((v for v in valid if got and v.startswith(got)), None)


def _valid_quantities(mech: Mechanism) -> set[str]:
    nums = sorted(mech.numbers)
    out = {"centres"}
    for i, a in enumerate(nums):
        for b in nums[i + 1:]:
            out.add(f"I{a}{b}" if b < 10 else f"I{a},{b}")
    out |= {f"omega{n}" for n in nums if n != 1}
    out |= {f"V_{p}" for p in mech.point_names if set(mech.links_at(p)) != {1}}
    return out


def _pair(q: str) -> tuple[int, int]:
    m = _QUANTITY.match(q)
    if m.group(2):
        return int(m.group(2)), int(m.group(3))
    return int(m.group(4)), int(m.group(5))
