"""A compound train designed pair by pair, as the books design it: "a reduction of 36 : 1
in two equal steps, no pinion to have fewer than 16 teeth".

Each pair's ratio is N_driven/N_driver alone, so a pair given its ratio and a least count
is designed on its own (:func:`pair_teeth`): its smaller gear takes the least count, or
the fewest above it that make the other whole. "Equal steps" (:func:`equal_steps`) share
the overall ratio among the k pairs between the two members named, each taking its k-th
root, which must be rational for whole teeth to give it.
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction

from ..errors import InputError
from ..narration import Phrase, phrase
from .tabular import fraction_text
from .train import GearTrain

__all__ = ["equal_steps", "is_pair", "pair_teeth"]

Ratio = tuple[tuple[int, int], Fraction]


def is_pair(train: GearTrain, of: tuple[int, int]) -> bool:
    """True where ``of`` names the two gears of one mesh."""
    return any({m.a, m.b} == set(of) for m in train.meshes)


def _path(train: GearTrain, x: int, y: int) -> list[tuple[int, int]] | None:
    """The meshes crossed from member ``x`` to member ``y``, each as (driver, driven), a
    shaft crossed free; None where no chain of meshes joins them."""
    todo, seen = [(x, [])], {x}
    while todo:
        here, path = todo.pop(0)
        if here in train.body(y):
            return path
        for g in train.body(here):
            for m in train.meshes:
                if g in (m.a, m.b):
                    other = m.b if g == m.a else m.a
                    if other not in seen:
                        seen.add(other)
                        todo.append((other, [*path, (g, other)]))
    return None


def _root(value: Fraction, k: int) -> Fraction | None:
    """The exact rational k-th root of ``value``, or None where it is irrational."""
    def whole(n: int) -> int | None:
        r = round(n ** (1 / k))
        return next((c for c in (r - 1, r, r + 1) if c >= 0 and c ** k == n), None)

    top, bottom = whole(value.numerator), whole(value.denominator)
    return None if top is None or bottom is None else Fraction(top, bottom)


def equal_steps(train: GearTrain, of: tuple[int, int], value: Fraction
                ) -> tuple[list[Ratio], Phrase]:
    """The pairs' ratios of |ω_x/ω_y| = ``value`` in equal steps, driver over driven, and
    the step that says them.

    Raises
    ------
    InputError
        If no chain of meshes joins the two, or the k-th root is not rational (no file
        named: the reader gives its line).
    """
    x, y = of
    path = _path(train, x, y)
    if not path:
        raise InputError(f"no meshes join members {x} and {y} to share their ratio "
                         "in equal steps: name two members of a compound train")
    k = len(path)
    root = _root(value, k)
    if root is None:
        raise InputError(f"ω{x}/ω{y} = {fraction_text(value)} in {k} equal steps "
                         f"needs each pair {float(value) ** (1 / k):.6g}, not a ratio of whole "
                         "teeth: give each pair's ratio in a [[ratio]] of its own")
    pairs = ", ".join(f"|ω{a}/ω{b}| = {fraction_text(root)}" for a, b in path)
    return [(p, root) for p in path], phrase(
        "gears.equal_steps", x=x, y=y, value=fraction_text(value), k=k,
        root=fraction_text(root), pairs=pairs)


def pair_teeth(train: GearTrain, of: tuple[int, int], value: Fraction, least: int
               ) -> tuple[GearTrain, tuple[Phrase, ...]]:
    """One pair's teeth from its ratio |ω_a/ω_b| = N_b/N_a = ``value``: the smaller, if
    unknown, takes ``least`` or the fewest above it that make the other whole; a count
    given fixes the other.

    Raises
    ------
    InputError
        If the counts given do not make the ratio whole.
    """
    a, b = of
    small, big, r = (a, b, value) if value >= 1 else (b, a, 1 / value)
    teeth = {g: train.gear(g).teeth for g in (a, b)}
    steps: list[Phrase] = []
    if teeth[small] is None and teeth[big] is None:
        n = next(n for n in range(least, least + r.denominator + 1)
                 if (n * r).denominator == 1)
        teeth[small] = n
        steps.append(phrase("gears.teeth_least", g=small, least=least, teeth=n))
    if teeth[big] is None:
        g, teeth[big] = big, teeth[small] * r
        expr = f"N{big}/{teeth[small]}" if big == b else f"{teeth[small]}/N{big}"
    elif teeth[small] is None:
        g, teeth[small] = small, teeth[big] / r
        expr = f"{teeth[big]}/N{small}" if small == a else f"N{small}/{teeth[big]}"
    else:
        return train, ()
    if Fraction(teeth[g]).denominator != 1:
        raise InputError(f"the speed ratio ω{a}/ω{b} = {fraction_text(value)} gives gear {g} "
                         f"{float(teeth[g]):g} teeth, not a whole number: check the ratio and "
                         "the teeth", file=train.source or None)
    steps.append(phrase("gears.teeth_ratio", x=a, y=b, value=fraction_text(value), g=g,
                        expr=expr, teeth=int(teeth[g])))
    return _with(train, teeth), tuple(steps)


def _with(train: GearTrain, teeth: dict[int, int | Fraction]) -> GearTrain:
    return replace(train, gears=tuple(replace(g, teeth=int(teeth[g.number]))
                                      if g.number in teeth else g for g in train.gears))
