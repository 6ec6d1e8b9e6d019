"""A frame guide laid as the books lay a shaper's ram line: "through the extreme positions
of Q", Q a point of the slotted lever.

The lever's limit positions do not depend on what it drives, so they are found on the
mechanism without it: the guide's own link (the ram), then every link left hanging by a
point nothing else holds (the link from Q to the ram), are taken away, and the lever's two
reversals found on what is left (:func:`~tarsim.constructions.reference.limits.limit_reference`).
The guide passes through Q at both; it keeps the angle the file gives it, which must be the
direction from one place of Q to the other, else the file is refused saying the angle the
two places lie at.
"""

from __future__ import annotations

import math
from dataclasses import replace

from tarsim.constructions.errors import TarsimError
from tarsim.constructions.model import Drive, Mechanism
from tarsim.constructions.reference.limits import limit_reference
from tarsim.constructions.reference.solver import solve_positions

__all__ = ["through_extremes"]


def through_extremes(mech: Mechanism, guides: list[tuple[int, str, dict]], fail) -> Mechanism:
    """``mech`` with each guide of ``guides`` (its sliding link, the point Q, where the file
    says so) laid through Q's two extreme places; ``fail(message, **where)`` makes the
    error for a guide that cannot be laid so."""
    for link, q, where in guides:
        slide = next(s for s in mech.slides if s.link == link and s.guide_link == 1)
        lever, rest = _lever_alone(mech, link, q)
        if lever is None:
            raise fail(f"{q} is on no link turning about a frame pivot once link {link} and "
                       "what hangs from it are taken away: a guide through its extreme "
                       "positions needs a lever that swings", key="through", **where)
        try:
            turns = limit_reference(rest, link=lever).crank_angles
        except TarsimError as e:
            raise fail(f"link {lever}, which carries {q}, has no two extreme positions: {e}",
                       key="through", **where) from None
        d = rest.drive
        (x1, y1), (x2, y2) = (solve_positions(rest.with_drive(
            Drive(d.link, t, d.omega, d.alpha)))[q] for t in turns)
        chord = math.atan2(y2 - y1, x2 - x1)
        along = slide.direction
        size = max(math.hypot(x2 - x1, y2 - y1), mech.units.metres)
        off = abs((x2 - x1) * along[1] - (y2 - y1) * along[0])
        if off > 1e-9 * size:
            raise fail(f"the extreme positions of {q} lie on a line at "
                       f"{math.degrees(chord) % 180:.6g}° from +x, not along the guide's "
                       "angle: give that angle", key="through", **where)
        placed = replace(slide, through=((x1 + x2) / 2, (y1 + y2) / 2))
        mech = replace(mech, slides=tuple(placed if s is slide else s for s in mech.slides))
    return mech


def _lever_alone(mech: Mechanism, link: int, q: str) -> tuple[int | None, Mechanism]:
    """The link that carries ``q`` and turns about a frame pivot, and the mechanism without
    ``link`` and every link that then hangs by a point no other link holds."""
    gone = {link}
    while True:
        links = [k for k in mech.links if k.number not in gone]
        held = {}
        for k in links:
            for n in k.names:
                held[n] = held.get(n, 0) + 1
        slid = {s.point for s in mech.slides if s.link not in gone and s.guide_link not in gone}
        hanging = [k.number for k in links if k.number != 1 and not set(k.names) & set(
            mech.link(1).names) and any(held[n] == 1 and n not in slid for n in k.names)]
        if not hanging:
            break
        gone |= set(hanging)
    frame = set(mech.link(1).names)
    levers = [k.number for k in links if q in k.names and k.number != 1
              and set(k.names) & frame]
    kept = {k.number for k in links}
    rest = replace(mech, links=tuple(links),
                   slides=tuple(s for s in mech.slides if s.link in kept and s.guide_link in kept),
                   branches={p: b for p, b in mech.branches.items()
                             if any(p in k.names for k in links)})
    return (levers[0] if levers else None), rest
