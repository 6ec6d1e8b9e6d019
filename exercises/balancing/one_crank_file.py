"""Read an engine whose cylinders all work on one crank: a V of two (``[engine] vee``, the
angle between their lines) or a radial engine (``[engine] radial``, the number of cylinders
evenly round the crank shaft)."""

from __future__ import annotations

import math

from ..table_file import Tables

__all__ = ["read_radial", "read_vee"]


def read_vee(t: Tables, one: dict) -> float:
    """A V engine's angle between its two cylinders' lines (rad), 0 where the file gives
    none; its two cylinders share one crank (more, evenly round, are a radial engine)."""
    if "vee" not in one:
        return 0.0
    if "radial" in one:
        raise t.fail("an engine is a V of two cylinders (vee = …) or a radial one (radial = "
                     "the number of cylinders), not both", "engine", "radial")
    v = t.number(one, "vee", "engine", "the V's angle")
    if not 0 < v < 180:
        raise t.fail(f"the V's angle between its cylinders' lines is between 0° and 180°, got "
                     f"{v:g}", "engine", "vee")
    _one_crank(t, one, "a V engine's two cylinders")
    return math.radians(v)


def read_radial(t: Tables, one: dict) -> int:
    """A radial engine's number of cylinders, evenly round the crank shaft, 0 where the file
    gives none."""
    if "radial" not in one:
        return 0
    n = one["radial"]
    if isinstance(n, bool) or not isinstance(n, int) or n < 3:
        raise t.fail(f"radial is the number of cylinders, evenly round the crank shaft: 3 or "
                     f"more (two on one crank are a V, vee = …), got {n!r:.20}", "engine",
                     "radial")
    _one_crank(t, one, "a radial engine's cylinders")
    return n


def _one_crank(t: Tables, one: dict, what: str) -> None:
    """Cylinders on one crank take no [[cylinder]] tables, and no balance mass or firing
    order: their resultant forces are found unbalanced."""
    if t.entries("cylinder"):
        raise t.fail(f"{what} work on one crank: leave out the [[cylinder]] tables",
                     "cylinder", None, 0)
    other = [k for k in ("balanced", "revolving", "balance_radius", "balance_mass",
                         "firing_order", "strokes") if k in one] + (
        ["balance"] if t.entries("balance") else [])
    if other:
        kind = "a V engine" if what.startswith("a V") else "a radial engine"
        raise t.fail(f"{other[0]} is not taken for {kind}: its resultant forces are found "
                     "unbalanced; leave it out", "engine" if other[0] != "balance" else "balance",
                     other[0] if other[0] != "balance" else None)
