"""Identical planets listed as gears of their own: the redundant constraint they are.

Two planets on one arm with the same teeth (and module), on no shaft, meshing the same
main-axis gears the same way, turn alike: the second adds a mesh pair that Grübler counts
as one constraint too many ("held twice over"), though the train moves. Such a copy is
folded into the first, counted as ``planets = 2`` counts it (equally spaced, the assembly
condition checked), and turns as the first does.
"""

from __future__ import annotations

from dataclasses import replace

from ..errors import InputError
from ..narration import Phrase, phrase
from .train import GearTrain

__all__ = ["fold_twins"]


def fold_twins(train: GearTrain, planets_given: bool
               ) -> tuple[GearTrain, tuple[tuple[int, int], ...], tuple[Phrase, ...]]:
    """``train`` with each identical planet folded into the first of its kind; the
    (copy, first) pairs; and the steps that say so.

    Raises
    ------
    InputError
        If ``[arm] planets`` is given and is not the number of identical planets listed.
    """
    if not train.planetary:
        return train, (), ()
    shafted = {m for shaft in train.shafts for m in shaft}
    kinds: dict[tuple, list[int]] = {}
    for g in train.gears:
        if g.carrier is None or g.number in shafted:
            continue
        meshes = []
        for m in train.meshes:
            if g.number in (m.a, m.b):
                other = m.b if m.a == g.number else m.a
                meshes.append((other, m.internal))
        if any(train.gear(o).carrier is not None for o, _ in meshes):
            continue                     # a planet meshing a planet: not a plain copy
        kinds.setdefault((g.carrier, g.teeth, g.module, tuple(sorted(meshes))), []).append(
            g.number)
    twins = [(copy, group[0]) for group in kinds.values() for copy in group[1:]]
    if not twins:
        return train, (), ()
    counts = {len(group) for group in kinds.values() if len(group) > 1}
    copies = max(counts)
    if planets_given and train.planets != copies:
        raise InputError(f"the arm {train.arm} lists {copies} identical planets as gears but "
                         f"says planets = {train.planets}: leave out planets or make it "
                         f"{copies}", file=train.source or None)
    gone = {c for c, _ in twins}
    folded = replace(train, gears=tuple(g for g in train.gears if g.number not in gone),
                     meshes=tuple(m for m in train.meshes if m.a not in gone
                                  and m.b not in gone),
                     planets=copies)
    steps = tuple(phrase("gears.twin", copy=c, first=f, n=copies) for c, f in twins)
    return folded, tuple(twins), steps
