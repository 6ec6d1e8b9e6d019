"""The data of the interactive page (``tarsim view``): the exercise's figures as its
solution draws them, and the mechanism turned through a revolution by construction, each
frame checked.

A student learns a construction by watching it grow, and a mechanism by turning it. The
page (:mod:`~tarsim.graphics.view_page`) draws both from what this module gathers, and
draws nothing of its own:

* **figures**: each figure of the exercise's first position, as `tarsim solve` draws it,
  in English and Persian, primitive by primitive, each with the step it is drawn for (as
  steps.md numbers them) and the named points it stands on (:mod:`.view_figures`);
* **frames**: the input turned in equal steps (0.5° by default) from the exercise's own
  angle, the way ω turns. Each sends the named points of each view (the joints and
  centres, each polygon's pole and tips), which the figure's primitives stand on: the
  constructions of one position redone at the frame's angle, and checked against the
  analytic solution of the whole turn (:mod:`.view_frames`). A position that cannot be
  assembled is a frame that says why; nothing is interpolated.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import Any

from tarsim.constructions.linkages.acceleration_polygon import draw_acceleration_polygon
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.linkages.kennedy import locate_centres
from tarsim.constructions.model import Mechanism
from tarsim.constructions.narration import LANGUAGES, speaking, words
from tarsim.constructions.reference.turn import solve_turn
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tarsim.graphics.figure_data import FONTS, style_data
from tarsim.graphics.paper import paper, room
from tarsim.graphics.workers import draw_each
from .exercise_file import Exercise
from tarsim.constructions.linkages.given_rate import convert
from .view_figures import PageFigures, solved_at
from .view_fit import frame_fits
from .view_paper import home_points
from .view_readout import plotted, readout
from .view_frames import (FRAME_CHECK, Template, constructed, construction_points,
                          frame_outcomes, truth_of_turn)

__all__ = ["view_data", "frame_outcomes", "FRAME_CHECK"]

def view_data(ex: Exercise, *, step_deg: float = 0.5,
              progress: Callable[[int], None] | None = None) -> dict[str, Any]:
    """Everything the page shows, as plain data for its JSON.

    Raises
    ------
    TarsimError
        If the exercise cannot be solved at its own position (as ``solve`` says).
    """
    from .solution import solve_positions
    from .sweep import sweep_exercise

    if not 0.05 <= step_deg <= 10.0:
        raise TarsimError(f"the frames' step is 0.05° to 10°, not {step_deg:g}°")
    where = room(paper(ex.paper))
    first = replace(ex, positions=ex.positions[:1])
    sol = solve_positions(first, room=where)[0]
    mech = sol.assembly.mechanism              # with the input's rates as drawn
    if mech.given is not None:
        mech = convert(mech)[1]
    n = round(360.0 / step_deg)
    sense = -1.0 if mech.drive.omega < 0 else 1.0
    angles = [mech.drive.angle + sense * math.radians(step_deg) * k for k in range(n)]
    scales = _scales(mech, sol)
    names = _names(mech, scales)
    core = {view: len(points) for view, points in names.items()}
    for view, refs in construction_points(sol).items():
        names[view] += refs

    def solved(angle: float):
        return sol if angle == angles[0] else solved_at(sol, angle, where)

    template = Template.chosen(mech, angles, scales, names, solved)
    turn = solve_turn(mech, angles)

    def frames_of(ks: range) -> list[dict]:
        out = []
        for k in ks:
            f = template.frame(angles[k], truth_of_turn(turn, k)) \
                if template is not None and turn.ok[k] else None
            out.append(f if f is not None else constructed(mech, angles[k], scales, names,
                                                           solved))
        return out

    chunks = [range(k, n, _CHUNKS) for k in range(_CHUNKS)]
    pages = PageFigures(first, sol, names, sense, where, _PAGE_LANGUAGES)
    drawings = pages.jobs()
    def curve() -> list:
        return _marks(sweep_exercise(first, n))

    # The frames, the figures' drawings and the output's curve share the cores, the
    # longest first.
    done = draw_each([lambda c=c: frames_of(c) for c in chunks] + drawings + [curve],
                     [len(c) * _FRAME for c in chunks] + [_DRAWING] * len(drawings) + [_CURVE])
    frames: list[dict] = [{}] * n
    for k, chunk in enumerate(done[:_CHUNKS]):
        frames[k::_CHUNKS] = chunk
    if progress is not None:
        progress(n)
    figures = pages.figures(done[_CHUNKS:-1])
    marks = done[-1]
    names = _pruned(names, core, frames, figures)
    for f in figures:
        turning = f["drawn"][_PAGE_LANGUAGES[0]].get("turning")
        if turning is not None and turning.get("panels"):
            f["fit"] = frame_fits(turning["panels"], frames, scales, mech.units,
                                  _PAGE_LANGUAGES)
    used = {it[1] for f in figures for d in f["drawn"].values() for it in d["items"]
            if it[1]}
    return {
        "title": {lang: ex.named_in(lang).mechanism.name for lang in ("en", "fa")},
        "units": {"length": mech.units.length, "angle": mech.units.angle},
        "input": {"link": mech.drive.link, "symbol": f"θ{mech.drive.link}",
                  "slug": f"theta{mech.drive.link}", "omega": mech.drive.omega,
                  "angle": mech.drive.angle, "step": sense * math.radians(step_deg)},
        "names": names,
        "drag": _drag(mech, names),
        "scales": scales,
        "styles": style_data(used),
        "fonts": FONTS,
        "figures": figures,
        "ui": {lang: _ui(lang) for lang in _PAGE_LANGUAGES},
        "frames": frames,
        "plot": plotted(first, mech, turn),
        "readout": readout(first, mech, turn),
        "home": home_points(mech, names),
        "marks": marks,
    }


_CHUNKS = 8
"""The frames are drawn in this many interleaved chunks, shared out to the cores."""

_DRAWING = 100
"""What drawing one position's figures costs, in ms."""

_FRAME = 0.3
"""What a frame costs, in ms: redone and checked (one constructed afresh takes some 3)."""

_CURVE = 40
"""What the output's curve costs, in ms: the turn swept and its limits found."""


def _scales(mech: Mechanism, sol) -> dict[str, float]:
    """The polygons' scales as the solution drew them (or as they would be drawn at the
    exercise's position), held through the turn so that the polygons do not jump in size
    from frame to frame, and their figures' primitives stand on their tips."""
    vp, ap = sol.velocity_polygon, sol.acceleration_polygon
    v = vp.scale if vp is not None else draw_velocity_polygon(assemble(mech)).scale
    if ap is None:
        asm = assemble(mech)
        ap = draw_acceleration_polygon(asm, draw_velocity_polygon(asm, v))
    return {"v": v, "a": ap.scale}


def _names(mech: Mechanism, scales: dict[str, float]) -> dict[str, list[str]]:
    """The named points of each view, in the order every frame sends them: the joints and
    the instant centres; each polygon's tips and its pole. The points the exercise's own
    constructions stand on follow them, by their refs
    (:func:`~.view_frames.construction_points`)."""
    asm = assemble(mech)
    vp = draw_velocity_polygon(asm, scales["v"])
    ap = draw_acceleration_polygon(asm, vp, scales["a"])
    cs = locate_centres(assemble(mech))
    return {"space": list(mech.point_names) + [c.label for c in cs.primaries + cs.secondaries],
            "velocity": list(vp.tips) + ["pole"], "acceleration": list(ap.tips) + ["pole"]}


def _pruned(names: dict[str, list[str]], core: dict[str, int], frames: list[dict],
            figures: list[dict]) -> dict[str, list[str]]:
    """``names`` with the points of the constructions no figure's primitive stands on
    left out, and the frames, the primitives' anchors and the drawings' own named points
    with them: the first ``core`` names of each view (the joints, centres and polygon
    tips) are always sent."""
    drawings = [d for f in figures for home in f["drawn"].values()
                for d in (home, home.get("turning")) if d is not None]
    stands = [more[key] for d in drawings for it in d["items"]
              if len(it) > 3 and (more := it[3]) for key in ("m", "a") if key in more]
    keep = {view: set(range(n)) for view, n in core.items()}
    for view, triples in stands:
        keep[view].update(k for k in triples if k >= 0)
    kept = {view: sorted(keep[view]) for view in names}
    new = {view: {k: i for i, k in enumerate(ks)} for view, ks in kept.items()}
    for view, triples in stands:
        triples[:] = [new[view][k] if k >= 0 else k for k in triples]

    def flat(at: dict[str, list]) -> dict[str, list]:
        return {view: [v for k in kept[view] for v in xy[2 * k:2 * k + 2]]
                for view, xy in at.items()}

    for f in frames:
        if "at" in f:
            f["at"] = flat(f["at"])
    for d in drawings:
        if "named" in d:
            d["named"] = flat(d["named"])
    return {view: [names[view][k] for k in ks] for view, ks in kept.items()}


def _drag(mech: Mechanism, names: dict[str, list[str]]) -> dict[str, Any]:
    """The point the reader drags to turn the input, and the pivot it turns about."""
    link = mech.link(mech.drive.link)
    own = [p for p, _ in link.points]
    pivot = next((p for p in own if 1 in mech.links_at(p)), own[0])
    pin = next(p for p in own if p != pivot)
    return {"view": "space", "about": names["space"].index(pivot),
            "handle": names["space"].index(pin)}


_PAGE_LANGUAGES = ("en", "fa")
assert set(_PAGE_LANGUAGES) <= set(LANGUAGES)


_UI = ("figure", "play", "download this frame (SVG)", "reset view", "Kennedy lines",
       "construction lines", "labels", "step numbers", "cw", "ccw", "{what} at {where}")
"""The page's own words (its controls and layers), said from the catalogue."""

_LOST = "instant centres"
"""What a frame's readout says Kennedy's theorem could not find there."""


def _ui(lang: str) -> dict[str, str]:
    with speaking(lang):
        return {**{w: words(w) for w in _UI}, "lost": words(_LOST)}


def _marks(sweep) -> list[dict[str, Any]]:
    """The slider's marks: where the output stands still (a limit position) and where
    the mechanism cannot be assembled or locks (a dead point)."""
    from .sweep import KEYS

    vkey = KEYS[sweep.output.kind][1][0]
    out = [{"angle": e.angle, "kind": "limit"} for e in sweep.events if e.key == vkey]
    for a, b in zip(sweep.samples, sweep.samples[1:] + sweep.samples[:1]):
        if bool(a.values) != bool(b.values):         # where the reach ends or begins
            out.append({"angle": (b if a.values else a).angle, "kind": "dead",
                        "why": (a.reason or b.reason).split(":")[0]})
    return out
