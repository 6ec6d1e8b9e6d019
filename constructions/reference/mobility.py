"""The mechanism's mobility as the loop equations count it: the check on Grübler.

Grübler's count (:meth:`~tarsim.constructions.model.Mechanism.mobility`) adds up
joints; here the constraints are differentiated at the mechanism's position and
the mobility is the nullity of their Jacobian. A redundant constraint (a
parallelogram's extra link) or a joint that does not constrain makes the two
differ.

At a change point (a parallelogram with its links in line) the Jacobian loses rank
for that instant: two assemblies meet there and the mobility is momentarily one
more. :func:`mobility_of` tells the two apart by turning the input to other angles,
where the linkage has its own mobility again.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ..errors import AssemblyError
from ..model import Mechanism
from .solver import SINGULAR_RCOND, constraint_jacobian, follow_branches

__all__ = ["mobility_by_rank", "Mobility", "mobility_of", "TURNS"]

TURNS = 12
"""Input angles, a whole turn apart divided evenly, at which :func:`mobility_of` looks."""


def mobility_by_rank(mech: Mechanism) -> int:
    """Return the mobility as the nullity of the loop equations' Jacobian at this position.

    The columns are the moving links' x, y, φ, the rows every joint's constraints
    without the input's.
    """
    jac = constraint_jacobian(mech)
    if jac.size == 0:
        return jac.shape[1]
    sv = np.linalg.svd(jac, compute_uv=False)
    rank = int(np.sum(sv > SINGULAR_RCOND * sv[0])) if sv[0] > 0.0 else 0
    return jac.shape[1] - rank


@dataclass(frozen=True)
class Mobility:
    """The linkage's mobility, and its mobility at the stated position (more at a change point)."""

    value: int
    here: int


def mobility_of(mech: Mechanism) -> Mobility:
    """The nullity at the stated position and the least over :data:`TURNS` input angles.

    Raises
    ------
    AssemblyError
        If the mechanism assembles at none of them.
    """
    mech = follow_branches(mech)
    d = mech.drive
    found = {}
    why = None
    for k in range(TURNS):
        turned = mech.with_drive(replace(d, angle=d.angle + 2 * math.pi * k / TURNS))
        try:
            found[k] = mobility_by_rank(turned)
        except AssemblyError as e:
            why = why or e
            continue
    if not found:
        raise AssemblyError(f"the mechanism assembles at none of {TURNS} input angles spread over "
                            f"a turn of link {d.link}, so it has no mobility to count",
                            link=d.link).because(why)
    return Mobility(min(found.values()), found.get(0, min(found.values())))
