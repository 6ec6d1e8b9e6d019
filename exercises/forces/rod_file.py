"""Read a connecting rod given alone, as the books give it for its equivalent dynamical
system: ``[rod]`` with its mass, the length between its pins' centres, its centre of mass
a distance from a named pin, its radius of gyration (or I about G), and, for the correction
couple, its angular acceleration with its sense. No crank, position or speed is needed.

```toml
[units]
length = "mm"

[rod]
mass = 2                    # kg
length = 250                # between the centres of the gudgeon pin and the crank pin
ends = ["P", "A"]           # the gudgeon pin's name and the crank pin's (these by default)
centre = 100                # G's distance from the pin centre_from names
centre_from = "P"           # the gudgeon pin by default
radius_of_gyration = 110    # k about G; or inertia = 0.0242 (kg·m²), or a pendulum
                            # test: oscillations = { count = 35, seconds = 60, about = "P",
                            # bore = 60 } (hung on a knife edge in P's bore)
alpha = 23000               # rad/s², the rod's angular acceleration
alpha_sense = "cw"          # or "ccw"; without it, alpha is + counter-clockwise
one_mass_at = "P"           # the pin the equivalent system's first mass is at

[ask]
find = ["equivalent_masses", "pin_masses", "equivalent_inertia", "correction_couple"]
```

Every failure is one line naming file:line.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass
from typing import Any, ClassVar

from tarsim.constructions.forces.equivalent import RodLine
from tarsim.constructions.units import LENGTH_UNITS
from ..names import named_in, read_names, renamed_field
from ..table_file import Tables
from .pendulum import pendulum_inertia

__all__ = ["ROD_ASKS", "RodExercise", "parse_rod"]

ROD_ASKS = ("equivalent_masses", "pin_masses", "equivalent_inertia", "correction_couple",
            "rod_radius_of_gyration")
"""What a ``[rod]`` file may ask: the two masses with one at a pin (and where the other
stands), the two at the pins, the moment of inertia of those two against the rod's, their
correction couple (α given), and k = √(I/m)."""

_NEEDS_INERTIA = ("equivalent_masses", "equivalent_inertia", "correction_couple",
                  "rod_radius_of_gyration")

_TOP = ("name", "names", "source", "description", "units", "rod", "ask")
_KEYS = {"rod": ("mass", "length", "ends", "centre", "centre_from", "radius_of_gyration",
                 "inertia", "oscillations", "alpha", "alpha_sense", "one_mass_at"),
         "ask": ("find",)}


@dataclass(frozen=True)
class RodExercise:
    """A connecting rod alone and what is asked of its equivalent dynamical system (SI)."""

    chapter: ClassVar[str] = "forces"

    id: str
    name: str
    source: str
    description: str
    rod: RodLine
    """The rod along its line of centres, the gudgeon pin at 0 (m, kg, kg·m²)."""
    given_inertia: bool
    """Whether the file gives the rod's I about G (else k, or neither)."""
    ends: tuple[str, str]
    """The gudgeon pin's name and the crank pin's."""
    centre_from: str
    """The pin the file measures G from."""
    one_mass_at: str
    """The pin the equivalent system's first mass is at."""
    find: tuple[str, ...]
    alpha: float | None = None
    """The rod's angular acceleration (rad/s², + counter-clockwise)."""
    length_unit: str = "mm"
    names: tuple[tuple[str, str], ...] = ()
    pendulum: tuple[float, float, str, bool] | None = None
    """The pendulum test I_G came from: its period (s), G's distance below the point of
    suspension (m), the pin it hung from, and whether on a knife edge in its bore."""
    paper: str = "A4"
    """The sheet its figures are drawn for and set on (``graphics.paper.PAPERS``),
    as ``--paper`` sets it."""

    @property
    def second(self) -> str:
        """The name of the point the equivalent system's second mass stands at."""
        return next(n for n in ("D", "Q", "D'", "Q'") if n not in self.ends)

    @property
    def crank_first(self) -> bool:
        """Whether the equivalent system's first mass is at the crank pin."""
        return self.one_mass_at == self.ends[1]

    def named_in(self, lang: str) -> RodExercise:
        """The same exercise named in ``lang``, if its file does."""
        return named_in(self, lang)

    renamed = renamed_field


def parse_rod(text: str, filename: str = "<string>", exercise_id: str = "rod",
              data: dict[str, Any] | None = None) -> RodExercise:
    """Parse a connecting rod given alone from TOML text; ``data``, the tables already
    parsed, spares a second parse.

    Raises
    ------
    InputError
        Naming file:line and what to fix.
    """
    t = Tables.read(text, filename, "connecting rod", _TOP, _KEYS, data)
    length_unit, _ = t.units("mm", "rad/s")
    for key in t.data.get("units", {}):
        if key != "length":
            raise t.fail(f"a rod file's [units] takes length alone, not {key}", "units", key)
    metre = LENGTH_UNITS[length_unit]
    if not isinstance(t.data.get("rod"), dict):
        raise t.fail("[rod] is one table: write [rod] with the rod's mass, length, centre "
                     "and radius_of_gyration", "rod")
    (r,) = t.entries("rod")

    def positive(key: str, what: str) -> float:
        if key not in r:
            raise t.fail(f"[rod] needs {key}, {what}", "rod")
        v = t.number(r, key, "rod", what)
        if not v > 0:
            raise t.fail(f"{what} must be positive, got {v:g}", "rod", key)
        return v

    mass = positive("mass", "the rod's mass (kg)")
    length = positive("length", f"the length between the pins' centres ({length_unit})")
    ends = r.get("ends", ["P", "A"])
    if not (isinstance(ends, list) and len(ends) == 2 and all(
            isinstance(e, str) and e.strip() and len(e) <= 8 for e in ends)
            and ends[0] != ends[1]):
        raise t.fail('ends names the gudgeon pin and the crank pin: ends = ["P", "A"]',
                     "rod", "ends")
    ends = (ends[0], ends[1])

    def pin(key: str) -> str:
        v = r.get(key, ends[0])
        if v not in ends:
            raise t.fail(f"{key} is one of the rod's pins, {ends[0]} (the gudgeon pin) or "
                         f"{ends[1]} (the crank pin); not {v!r:.20}", "rod", key)
        return v

    centre_from = pin("centre_from")
    c = positive("centre", f"G's distance from {centre_from} ({length_unit})")
    if not c < length:
        raise t.fail(f"G stands {c:g} {length_unit} from {centre_from}, not between the pins "
                     f"{length:g} {length_unit} apart: give centre < length", "rod", "centre")
    centre = c if centre_from == ends[0] else length - c
    given = [key for key in ("radius_of_gyration", "inertia", "oscillations") if key in r]
    if len(given) > 1:
        raise t.fail("give the rod's radius_of_gyration about G, its inertia or a pendulum "
                     "test (oscillations), one of them", "rod", given[1])
    inertia, pendulum = 0.0, None
    if "oscillations" in r:
        hung = _Hung(ends, length * metre)
        inertia, _, pendulum = pendulum_inertia(
            r["oscillations"], hung, mass, (centre * metre, 0.0), metre,
            lambda message: t.fail(message, "rod", "oscillations"))
    elif "radius_of_gyration" in r:
        k = positive("radius_of_gyration", f"the radius of gyration about G ({length_unit})")
        inertia = mass * (k * metre) ** 2
    elif "inertia" in r:
        inertia = positive("inertia", "the rod's moment of inertia about G (kg·m²)")
    alpha = None
    if "alpha" in r:
        alpha = t.number(r, "alpha", "rod", "the rod's angular acceleration (rad/s²)")
        sense = r.get("alpha_sense")
        if sense is not None:
            if sense not in ("cw", "ccw"):
                raise t.fail(f'alpha_sense is "cw" or "ccw", not {sense!r:.20}', "rod",
                             "alpha_sense")
            if alpha < 0:
                raise t.fail("alpha_sense gives the sense: write alpha's size alone, "
                             f"alpha = {-alpha:g}", "rod", "alpha")
            alpha = -alpha if sense == "cw" else alpha
    elif "alpha_sense" in r:
        raise t.fail("alpha_sense is the sense of the rod's alpha: give alpha = 23000 "
                     "(rad/s²) beside it", "rod", "alpha_sense")
    one = pin("one_mass_at")
    rod = RodLine(mass, length * metre, centre * metre, inertia)
    find = _read_find(t, inertia > 0.0, alpha)
    name = _text(t, "name", exercise_id)
    return RodExercise(exercise_id, name, _text(t, "source", ""), _text(t, "description", ""),
                       rod, "inertia" in r, ends, centre_from, one, find, alpha,
                       length_unit, read_names(t.data, t.where, filename), pendulum)


@dataclass(frozen=True)
class _Hung:
    """The rod as a pendulum test sees it (:func:`~.pendulum.pendulum_inertia`): its two pins
    on its line of centres, the gudgeon pin at 0."""

    names: tuple[str, str]
    length: float

    label = "the rod"

    def carries(self, point: str) -> bool:
        return point in self.names

    def local(self, point: str) -> tuple[float, float]:
        return (0.0 if point == self.names[0] else self.length, 0.0)


def _read_find(t: Tables, has_inertia: bool, alpha: float | None) -> tuple[str, ...]:
    """[ask] find, each a rod's ask that its data answer; every one they answer by default."""
    ask = t.data.get("ask")
    if ask is None:
        every = [q for q in ROD_ASKS if (has_inertia or q not in _NEEDS_INERTIA)
                 and (alpha is not None or q != "correction_couple")]
        return tuple(every)
    t.entries("ask")
    find = ask.get("find")
    if not (isinstance(find, list) and find and all(isinstance(q, str) for q in find)):
        raise t.fail(f"[ask] find is a list of {', '.join(ROD_ASKS)}", "ask",
                     "find" if "find" in ask else None)
    for q in find:
        if q not in ROD_ASKS:
            close = difflib.get_close_matches(q, ROD_ASKS, n=1)
            hint = f"did you mean '{close[0]}'?" if close else f"ask {', '.join(ROD_ASKS)}"
            raise t.fail(f"cannot find '{q}' for a connecting rod; {hint}", "ask", "find")
        if q in _NEEDS_INERTIA and not has_inertia:
            raise t.fail(f"{q} needs the rod's moment of inertia: give [rod] "
                         "radius_of_gyration (about G) or inertia", "ask", "find")
        if q == "correction_couple" and alpha is None:
            raise t.fail("correction_couple is (m·l1·l3 − m·k²)·α: give [rod] alpha = 23000 "
                         '(rad/s²) and alpha_sense = "cw" or "ccw"', "ask", "find")
    return tuple(dict.fromkeys(find))


def _text(t: Tables, key: str, default: str) -> str:
    v = t.data.get(key, default)
    if not isinstance(v, str) or any(ord(c) < 32 and c not in "\n\t" for c in v):
        raise t.fail(f"{key} must be text with no control character", key=key)
    return v

