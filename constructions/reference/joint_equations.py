"""What each kind of joint is to the analytic reference: its rows of the loop equations, its
acts in the closed-form start, and the forces the statics gives it.

The reference may import the joint model but no method, so it keeps its own table keyed
by the joint's kind (:mod:`~tarsim.constructions.joint_kinds`). Each kind's rows are
words of a small vocabulary, :class:`Equation`, that :mod:`.loop_equations` and
:mod:`.batch_loops` evaluate and differentiate; each act is one of :class:`Act`, which
:mod:`.dyad_assembly` takes. A new kind of joint built of known constraints is one entry
of :data:`JOINT_EQUATIONS`; a new constraint is a word here and its formulas there.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum, StrEnum

from ..model import Mechanism

__all__ = ["Equation", "Act", "JointEquations", "JOINT_EQUATIONS", "equations_of",
           "joints_with", "acting", "layout"]


class Equation(StrEnum):
    """A row of the loop equations a joint adds (see :mod:`.loop_equations`)."""

    LINE = "line"
    """``cross(D, P − G) = 0``: the point on a straight line of the guide link."""
    TURN = "turn"
    """``φ_link − φ_guide − atan2(direction) = 0``: the link turns with its guide."""
    NO_SLIP = "no slip"
    """``D·(P − G) + σ r (φ_wheel − φ_face) = 0``: rolled along a face as far as turned."""
    DISTANCE = "distance"
    """``(|P − C|² − ρ²) / 2ρ = 0``: the point kept ρ from a point of the guide link."""
    ROLLED_ROUND = "rolled round"
    """``r (φ_wheel − φ_guide) − k β = 0``: turned as far as rolled round a circle."""


_PHASE = {Equation.LINE: 1, Equation.TURN: 1, Equation.NO_SLIP: 2, Equation.DISTANCE: 3,
          Equation.ROLLED_ROUND: 4}
"""The rows are laid out word by word in this order (a block's turn beside its line), each
word's rows in the order of the mechanism's joints, after the pins and before the input."""


class Act(IntEnum):
    """A closed-form act of :mod:`.dyad_assembly`, in the order each round tries them."""

    TURN_WITH_GUIDE = 1
    """A block's link takes its guide's angle, or the guide the block's."""
    ROLL_OUT = 2
    """A wheel's centre from its angle: as far along its face as it has rolled."""
    ROLL_ROUND = 3
    """A wheel's angle from how far its centre has gone round the circle it rolls on."""
    ROLL_BACK = 4
    """A wheel's angle from its centre: the distance rolled along its face over its radius."""


@dataclass(frozen=True)
class JointEquations:
    """A kind of joint as the reference sees it.

    ``rows`` are its equations (two for a lower pair, one for a higher pair); ``acts``
    what it does in the closed-form start beyond the lines and circles its point is cut
    from; ``reactions`` the forces the statics names for it ("F" square to its guide, "T"
    the couple of a block), or None where the statics of the joint is not written yet.
    """

    rows: tuple[Equation, ...]
    acts: tuple[Act, ...] = ()
    reactions: tuple[str, ...] | None = None


JOINT_EQUATIONS: dict[str, JointEquations] = {
    "block": JointEquations((Equation.LINE, Equation.TURN), (Act.TURN_WITH_GUIDE,), ("F", "T")),
    "slot": JointEquations((Equation.LINE,), reactions=("F",)),
    "face_contact": JointEquations((Equation.LINE,), reactions=("F",)),
    "rolling_on_face": JointEquations((Equation.LINE, Equation.NO_SLIP),
                                      (Act.ROLL_OUT, Act.ROLL_BACK)),
    "curved_slot": JointEquations((Equation.DISTANCE,)),
    "curved_block": JointEquations(()),
    "circle_contact": JointEquations((Equation.DISTANCE,)),
    "rolling_round": JointEquations((Equation.DISTANCE, Equation.ROLLED_ROUND),
                                    (Act.ROLL_ROUND,)),
}
"""Each kind of joint's rows, acts and reactions, by the kind's key."""


def equations_of(mech: Mechanism, joint) -> tuple[Equation, ...]:
    """The rows ``joint`` adds to ``mech``'s loop equations: its kind's, less the distance
    an arm already holds (:meth:`~tarsim.constructions.model.Mechanism.held`)."""
    rows = JOINT_EQUATIONS[joint.type.key].rows
    if mech.held(joint):
        return tuple(e for e in rows if e is not Equation.DISTANCE)
    return rows


def joints_with(mech: Mechanism, equation: Equation) -> tuple:
    """The joints of ``mech`` that add a row ``equation``, in the mechanism's order."""
    return tuple(j for j in (*mech.slides, *mech.arcs) if equation in equations_of(mech, j))


def acting(mech: Mechanism) -> dict[Act, tuple]:
    """The joints that take each closed-form act, by act in its order."""
    return {act: tuple(j for j in (*mech.slides, *mech.arcs)
                       if act in JOINT_EQUATIONS[j.type.key].acts) for act in Act}


def layout(mech: Mechanism) -> list[tuple[Equation, object]]:
    """Every joint's rows as ``(equation, joint)``, in the order the loop equations hold them
    (see :data:`_PHASE`); the pins' rows come before them and the input's after."""
    rows = [(e, j) for j in (*mech.slides, *mech.arcs) for e in equations_of(mech, j)]
    return sorted(rows, key=lambda r: _PHASE[r[0]])
