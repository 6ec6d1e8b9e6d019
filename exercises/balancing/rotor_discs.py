"""A rotor's masses given as the books give eccentrics and discs, by material and size
("eccentrics 80 mm in diameter and 20 mm thick, density 7200 kg/m³"): a ``[[mass]]`` with
``density`` (kg/m³), ``diameter`` and ``thickness`` (the file's length unit) is a solid disc
of mass m = ρ·πd²/4·t, and the worked steps say so for each.

Only a rotor balanced by planes, or asked its unbalance, reads them: an engine's masses and
a rotor's unknowns are given in kg.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from tarsim.constructions.narration import numeral, words
from ..table_file import Tables

__all__ = ["Disc", "disc_lines", "read_disc", "refuse_discs"]

_SIZES = ("diameter", "thickness")


@dataclass(frozen=True)
class Disc:
    """A mass given as a solid disc: its name, density (kg/m³), diameter and thickness (m)."""

    name: str
    density: float
    diameter: float
    thickness: float

    @property
    def mass(self) -> float:
        """The disc's mass, ρ·πd²/4·t (kg)."""
        return self.density * math.pi * self.diameter ** 2 / 4 * self.thickness


def read_disc(t: Tables, entry: dict, i: int, name: str, metre: float) -> Disc | None:
    """Mass ``name``'s disc where its entry gives a ``density`` (None where it gives its mass
    or weight); a density beside a mass, or without both sizes, is refused at its line."""
    sizes = [k for k in _SIZES if k in entry]
    if "density" not in entry:
        if sizes:
            raise t.fail(f"mass {name}'s {sizes[0]} sizes a disc given by its density: add "
                         "density = … (kg/m³), or leave it out", "mass", sizes[0], i)
        return None
    given = [k for k in ("mass", "weight") if k in entry]
    if given:
        raise t.fail(f"mass {name} gives its {given[0]} or its density (a disc of it), not "
                     "both: leave one out", "mass", "density", i)
    missing = [k for k in _SIZES if k not in entry]
    if missing:
        raise t.fail(f"mass {name}'s density makes it a solid disc, m = ρ·πd²/4·t: give its "
                     f"{' and '.join(missing)} too (in the file's length unit)", "mass",
                     "density", i)
    values = {}
    for key in ("density", *_SIZES):
        v = t.number(entry, key, "mass", f"mass {name}'s {key}", i)
        if not v > 0:
            raise t.fail(f"mass {name}'s {key} must be positive, got {v:g}", "mass", key, i)
        values[key] = v
    return Disc(name, values["density"], values["diameter"] * metre,
                values["thickness"] * metre)


def refuse_discs(t: Tables, why: str) -> None:
    """A disc's density where the file's masses are not a rotor's balanced by planes (an
    engine, a rotor with unknowns) is refused at its line, saying ``why``."""
    for i, entry in enumerate(t.entries("mass")):
        for key in ("density", *_SIZES):
            if key in entry:
                raise t.fail(f"{key} (a mass given as a solid disc) is taken in a rotor "
                             f"balanced by [[balance]] planes or asked its unbalance, not "
                             f"{why}: give mass = … (kg)", "mass", key, i)


def disc_lines(discs: tuple[Disc, ...], length) -> list[str]:
    """The step that turns each disc's density and size into its mass; ``length`` says a
    length (m) in the file's unit."""
    return [words("mass {name} is a solid disc of density {density} kg/m³, {diameter} in "
                  "diameter and {thickness} thick: m = ρ·πd²/4·t = {mass} kg", name=d.name,
                  density=numeral(d.density, "g"), diameter=length(d.diameter),
                  thickness=length(d.thickness), mass=numeral(d.mass)) for d in discs]
