"""What the interactive page reads out at each frame, and the curve it plots under the
slider: numbers of the analytic solution of the whole turn, in the figures' units.

The figures and steps.md say a length in the file's unit (mm), a velocity in that unit a
second (mm/s), an angular velocity in rad/s; results.json keeps SI. The page says what the
figures say: each value here is in the figures' units, so the readout can be read beside
the drawing and steps.md, and the plot's axis says the same unit.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from tarsim.constructions.asks import Acceleration, Velocity
from tarsim.constructions.linkages.coincident import taken
from tarsim.constructions.model import Mechanism
from tarsim.constructions.reference.turn import Turn

from .exercise_file import Exercise
from .sweep_output import Output, curves_of, pick_output, scale_of

__all__ = ["readout", "plotted"]

FIGURES = 9
"""Significant figures a readout value is sent with: the page prints six, as steps.md
does, and nine leave its last one unmoved by the rounding."""


QUIET = 1e-9
"""A value below this share of its kind's scale (the input's ω, the crank pin's speed, …)
is rounding noise and is sent as 0: the analytic solver's 1e-14 mm/s² is the drawing's
0, as steps.md prints it."""


def _sent(values: np.ndarray, ok: np.ndarray, scale: float) -> list[float | None]:
    """``values`` rounded to :data:`FIGURES` significant figures, 0 where below
    :data:`QUIET` of ``scale``, None where the frame did not assemble."""
    return [(float(f"{v:.{FIGURES}g}") if abs(v) > QUIET * scale else 0.0)
            if good and math.isfinite(v) else None
            for v, good in zip(values.tolist(), ok.tolist())]


def readout(ex: Exercise, mech: Mechanism, turn: Turn) -> dict[str, Any]:
    """Each frame's ω and α of every moving link (rad/s, rad/s², counter-clockwise
    positive, as results.json signs them), and the point velocities and accelerations
    the exercise asks, as vectors in the figures' units (mm/s, mm/s²).

    ``turn`` is the analytic solution at the page's frames, ``mech`` the mechanism as
    the frames turn it (its input's ω and α as drawn). Returns ``{"turning": [{n, omega,
    alpha}], "asked": [{name, symbol, unit, x, y}]}``, a list a frame each (None where it
    does not assemble); the page's script, which names no part of a mechanism, reads
    them by these keys.
    """
    per = mech.units.metres
    w, al = scale_of(mech, "omega"), scale_of(mech, "alpha")
    turning = [{"n": n, "omega": _sent(turn.omegas[n], turn.ok, w),
              "alpha": _sent(turn.alphas[n], turn.ok, al)}
             for n in sorted(mech.numbers) if n != 1]
    asked = []
    for ask in ex.asks:
        if not isinstance(ask, (Velocity, Acceleration)):
            continue
        link, point = taken(mech, ask.point)
        v = isinstance(ask, Velocity)
        rate = turn.rates_on(link, point)[0 if v else 1] / per
        scale = scale_of(mech, "velocity" if v else "acceleration") / per
        asked.append({"name": ask.name, "symbol": ask.symbol,
                      "unit": f"{mech.units.length}/s" + ("" if v else "²"),
                      "x": _sent(rate[:, 0], turn.ok, scale),
                      "y": _sent(rate[:, 1], turn.ok, scale)})
    return {"turning": turning, "asked": asked}


def plotted(ex: Exercise, mech: Mechanism, turn: Turn) -> dict[str, Any]:
    """The curve under the slider: one signed rate of the output through the turn.

    What a textbook plots against the crank angle (Norton's and Shigley's velocity
    curves): a slider's velocity along its line of stroke, and otherwise the angular
    velocity of the output link, both signed, so that the curve crosses zero where the
    output reverses, at a limit position, and is smooth there. A point's speed |V| would
    be a curve of cusps at each reversal, and a point's velocity along a path of its own
    has no fixed sense to sign it by. The output is the one ``tarsim sweep`` takes by
    default: the first point whose velocity is asked (on a frame guide: a slider), else a
    point on a frame guide, else the highest-numbered link; a point that is not on a
    guide is plotted as the ω of the link that carries it about a frame pivot (B on a
    rocker), or of the highest-numbered link at it.
    """
    out = pick_output(ex)
    if out.kind == "point":
        at = [n for n in mech.links_at(out.point) if n != 1]
        pivoted = [n for n in at if any(1 in mech.links_at(p) for p, _ in mech.link(n).points)]
        out = Output("link", min(pivoted) if pivoted else max(at))
    values = curves_of(turn, out)["v" if out.kind == "slider" else "omega"]
    if out.kind == "slider":
        per = mech.units.metres
        return {"symbol": out.symbol("v"), "unit": f"{mech.units.length}/s",
                "values": _sent(values / per, turn.ok, scale_of(mech, "velocity") / per)}
    return {"symbol": f"ω{out.link}", "unit": "rad/s",
            "values": _sent(values, turn.ok, scale_of(mech, "omega"))}
