"""An in-line engine's forces and couples at a crank angle the file asks (``at``: crank 1's
angle from the inner dead centre), read off the polygons: each closing side is −R of the
resultant that turns with the shaft, and what acts along the line of stroke is R's
projection on it, Re(R·e^{ik(θ − θ₁)}) (k = 1 primary, 2 secondary), beside the reference's
sum of the cylinders' cos terms (:func:`~tarsim.constructions.reference.balance.engine_along`).
"""

from __future__ import annotations

import math

from tarsim.constructions.balancing.engine import engine_kinds
from tarsim.constructions.narration import numeral, words
from tarsim.constructions.reference.balance import engine_along
from ..checked import Checked

__all__ = ["at_checked", "at_lines", "at_misses"]


def _drawn(s) -> dict[str, float]:
    """Each kind along the stroke at θ, projected off its polygon's closing side."""
    p, e = s.engine_polygons, s.exercise.engine
    out = {}
    for kind in engine_kinds(e):
        k = 1 if kind.startswith("primary") else 2
        if kind in p.balanced:
            out[kind] = 0.0
            continue
        seg = p.construction.output(p.closing[kind])
        (sx, sy), (ex, ey) = seg.start.xy, seg.end.xy
        turn = k * (e.at - e.cranks[0])
        # R = −(closing side); Re(R·e^{i·turn})
        out[kind] = -((ex - sx) * math.cos(turn) - (ey - sy) * math.sin(turn)) * e.speed ** 2
    return out


def at_checked(s) -> dict[str, Checked]:
    """``primary_force_at_theta`` and the rest, where the file asks a crank angle."""
    e = s.exercise.engine
    if not e.at_given:
        return {}
    want = engine_along(e, e.at)
    return {f"{kind.replace(' ', '_')}_at_theta": Checked(
        {"value": got, "unit": "N·m" if kind.endswith("couple") else "N",
         "theta_deg": math.degrees(e.at)}, {"value": want[kind]},
        method=f"{kind} polygon's closing side on the line of stroke")
        for kind, got in _drawn(s).items()}


def at_misses(s, agree: float) -> list[tuple[str, float]]:
    """Each value along the stroke against the reference's, relative to the sizes summed."""
    e = s.exercise.engine
    if not e.at_given:
        return []
    want = engine_along(e, e.at)
    size = max(e.each) * e.crank * e.speed ** 2 * len(e.cranks) * max(
        1.0, max(abs(z) for z in e.planes))
    return [(f"{kind} at θ", abs(got - want[kind]) / size) for kind, got in _drawn(s).items()
            if abs(got - want[kind]) > agree * size]


def at_lines(s) -> list[str]:
    """One line of what acts along the stroke at the crank angle asked."""
    e = s.exercise.engine
    if not e.at_given:
        return []
    got = _drawn(s)
    return [words("with crank 1 at {angle}° from the i.d.c., along the line of stroke: {values}",
                  angle=numeral(math.degrees(e.at), "g"),
                  values=", ".join(f"{words(kind)} {numeral(v)} "
                                   f"{'N·m' if kind.endswith('couple') else 'N'}"
                                   for kind, v in got.items()))]
