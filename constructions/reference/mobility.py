"""The mechanism's mobility as the loop equations count it: the check on Grübler.

Grübler's count (:meth:`~tarsim.constructions.model.Mechanism.mobility`) adds up
joints; here the constraints are differentiated at the mechanism's position and
the mobility is the nullity of their Jacobian. A redundant constraint (a
parallelogram's extra link) or a joint that does not constrain makes the two
differ.
"""

from __future__ import annotations

import numpy as np

from ..model import Mechanism
from .solver import SINGULAR_RCOND, constraint_jacobian

__all__ = ["mobility_by_rank"]


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
