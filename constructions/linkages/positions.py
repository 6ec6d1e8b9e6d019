"""Where each point is, as the compass found it: the position analysis the course starts with.

The assembly locates every point by arcs and lines, one dyad after another (see
:mod:`.assembly`); a position asked (``pos_B``) is read off the step that put the
point there, with that step's conditioning, and is drawn on the kinematic diagram of
its position.
"""

from __future__ import annotations

from .. import asks as A
from ..checks import Answer, FigureSpec
from ..errors import InputError

__all__ = ["answer_position", "POSITIONS_FIGURE"]

POSITIONS_FIGURE = FigureSpec("positions", "Positions by compass", "positions by compass",
                              kind="positions")
"""The kinematic diagram with the arcs and lines that placed the asked points."""


def answer_position(work, ask: A.Position) -> Answer:
    """The point's place, from the arcs or lines the assembly drew it with.

    Raises
    ------
    InputError
        If the mechanism has no such point.
    """
    asm = work.assembly
    ref = asm.points.get(ask.point)
    if ref is None:
        raise InputError(f"there is no point {ask.point} to give the position of; the "
                         f"points are {', '.join(asm.points)}")
    x, y = asm.xy(ask.point)
    return Answer(ask, {"point": [x + 0.0, y + 0.0]}, asm[ref].conditioning,
                  "compass (assembly)", refs=(ref,), figures=(POSITIONS_FIGURE,))
