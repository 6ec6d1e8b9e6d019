"""A rotor's masses given as the older books give them, as weights in N ("three weights of
60 N, 80 N and 100 N ... find the balance weight"): each read as its mass W/g, g = 9.81 m/s²,
and the balancing mass found given back as its weight too (``weight_<plane>``, N).

g divides every mass alike, so it cancels from the balance: W_B·r_B = |Σ Wᵢrᵢ e^{iθᵢ}|.
"""

from __future__ import annotations

from typing import Any

from tarsim.constructions.loads import GRAVITY
from tarsim.constructions.narration import numeral, words
from ..checked import Checked
from ..table_file import Tables

__all__ = ["GRAVITY", "mass_or_weight", "refuse_weights", "weight_checked", "weight_line",
           "weights_line"]


def mass_or_weight(t: Tables, entry: dict, table: str, i: int, what: str) -> tuple[float, bool]:
    """``entry``'s mass in kg, from its ``mass`` (kg) or its ``weight`` (N, over g), and
    whether it was given as a weight; both given are refused at the weight's line."""
    if "weight" not in entry:
        return t.number(entry, "mass", table, f"{what}'s mass", i), False
    if "mass" in entry:
        raise t.fail(f"{what} gives its mass (kg) or its weight (N), not both", table, "weight", i)
    return t.number(entry, "weight", table, f"{what}'s weight", i) / GRAVITY, True


def refuse_weights(t: Tables, why: str) -> None:
    """A weight where the file's masses are not read as a balanced rotor's (an engine, a
    rotor with unknowns) is refused at its line, saying ``why``."""
    for table in ("mass", "balance"):
        for i, entry in enumerate(t.entries(table)):
            if "weight" in entry:
                raise t.fail(f"weight = … (N) is taken in a rotor balanced by [[balance]] planes "
                             f"or asked its unbalance, not {why}: give mass = … (kg)", table,
                             "weight", i)


def weights_line() -> str:
    """The step that turns the file's weights into masses."""
    return words("the weights are in N: each mass is m = W/g, g = {g} m/s², and each balancing "
                 "mass is given back as its weight W = m·g", g=numeral(GRAVITY, "g"))


def weight_line(plane: str, mass: float, radius: str) -> str:
    """A balancing mass found, said as the books ask it, a balance weight in N."""
    return words("the balance weight in plane {plane}: {weight} N at {radius}", plane=plane,
                 weight=numeral(mass * GRAVITY), radius=radius)


def weight_checked(plane: str, found: float, ref: float, where: dict[str, Any],
                   there: dict[str, Any], method: str) -> dict[str, Checked]:
    """``weight_<plane>``: the balancing mass found (kg) as its weight m·g (N), beside the
    reference's."""
    return {f"weight_{plane}": Checked({"value": found * GRAVITY, "unit": "N", **where},
                                       {"value": ref * GRAVITY, **there}, method=method)}
