"""The meshes between two gears that do not mesh: the books' "distance between the centres of
A and D" of a simple train, its gears drawn in one line.

A simple train's first and last gears are joined through idlers, each on its own fixed axis;
the books ask the distance between their centres with the gears laid in one straight line,
so it is the sum of the pairs' centre distances along the chain. Only such a chain is taken:
external meshes through gears that turn about fixed axes, each on a shaft of its own, so
that the line is the books' and not one of many.
"""

from __future__ import annotations

from .train import GearTrain, Mesh

__all__ = ["mesh_chain"]


def mesh_chain(train: GearTrain, a: int, b: int) -> tuple[Mesh, ...] | None:
    """The external meshes from gear ``a`` to gear ``b`` through lone idlers, in order; None
    when the two are not joined so (a compound shaft, a planet or a ring on the way)."""
    def lone(n: int) -> bool:
        return train.gear(n).carrier is None and len(train.body(n)) == 1

    if not (lone(a) and lone(b)):
        return None
    seen, paths = {a}, [(a, ())]
    while paths:
        at, path = paths.pop(0)
        for mesh in train.meshes:
            if mesh.internal or at not in (mesh.a, mesh.b):
                continue
            other = mesh.b if mesh.a == at else mesh.a
            if other == b:
                return (*path, mesh)
            if other not in seen and lone(other):
                seen.add(other)
                paths.append((other, (*path, mesh)))
    return None
