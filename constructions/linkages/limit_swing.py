"""The angle a rocker or slotted lever swings through between its limit positions (the
books' "angle of oscillation"), read with the protractor on the limit positions already
drawn: the angle at its pivot between its two limit places. Of a crank and slotted lever,
whose two limits stand alike either side of the line of centres, the lever's inclination
to that line too ("the inclination of the slotted bar with the vertical").
"""

from __future__ import annotations

import math

from ..checks import Answer
from ..errors import InputError
from ..measures import measure_angle
from ..narration import Number, phrase
from ..record import Role

__all__ = ["swing_answer", "SWING_WHY_NOT"]

SWING_WHY_NOT = ("swing_<k> is asked of the rocker of a crank-rocker or the lever of a crank "
                 "and slotted lever, whose limit positions are drawn; link {k} is neither")
"""Why a link has no angle of swing to read."""


def _unsigned(sweep: float) -> float:
    """The lesser of the two angles a measured sweep leaves between its arms (rad)."""
    s = abs(sweep) % (2 * math.pi)
    return min(s, 2 * math.pi - s)


def swing_answer(work, ask, lp, figure) -> Answer:
    """Measure the swing at the pivot between the lever's (rocker's) two limit places, and a
    slotted lever's inclination to the line of centres, on ``lp``'s drawing (``figure``)."""
    if lp.output != ask.link or lp.held is None:
        raise InputError(SWING_WHY_NOT.format(k=ask.link))
    asm, m = lp.assembly, work.mechanism
    pivot, (first, second) = lp.pivot, lp.held
    names = [asm[r].label for r in lp.held]
    at = asm.points[pivot]

    def read(p: str, q: str) -> tuple[float, float]:
        """The lesser angle p·pivot·q and the sense (+1 ccw, −1 cw) that sweeps it."""
        ccw = measure_angle(asm.output(at), asm.output(p), asm.output(q), 1.0)[0].sweep
        return _unsigned(ccw), 1.0 if ccw <= math.pi else -1.0

    (swing, sense), ref = read(first, second), "limit:swing"
    arms = ()
    if lp.kind == "crank-rocker":               # the rocker at each limit (a lever's is drawn)
        arms = tuple(f"limit:arm{i}" for i in range(2))
        for arm, end in zip(arms, lp.held):
            if arm not in asm:
                asm.draw(arm, "line_through", at, end)
    if ref not in asm:
        asm.draw(ref, "measure_angle", at, first, second, turn=sense, role=Role.RESULT,
                 label="swing", phrase=phrase("limits.swing_angle", a=names[0], pivot=pivot,
                                              b=names[1], link=ask.link,
                                              degrees=Number(math.degrees(swing), ".2f")))
    value, refs = {"value": swing}, (*lp.steps, *arms, ref)
    if lp.kind == "slotted lever":
        crank = m.link(m.drive.link).names[0]
        (tilt, sense), ref = read(asm.points[crank], first), "limit:tilt"
        if ref not in asm:
            asm.draw(ref, "measure_angle", at, asm.points[crank], first, turn=sense,
                     role=Role.RESULT,
                     phrase=phrase("limits.inclination", a=names[0], pivot=pivot, c=crank,
                                   degrees=Number(math.degrees(tilt), ".2f")))
        value["inclination"] = tilt
        refs += (ref,)
    return Answer(ask, value, lp.conditioning, f"limit positions by compass (protractor at "
                  f"{pivot})", refs=refs, figures=(figure,))
