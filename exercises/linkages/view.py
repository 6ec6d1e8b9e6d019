"""The data of the interactive page (``tarsim view``): the construction's steps, and the
mechanism turned through a revolution by construction, each frame checked.

A student learns a construction by watching it grow, and a mechanism by turning it. The
page (:mod:`~tarsim.graphics.view_page`) draws both from what this module gathers:

* **steps**: each figure of the exercise's first position, its steps numbered as steps.md
  numbers them, with what each draws (in world or polygon coordinates) and its words in
  English and, when the catalogue has them, Persian;
* **frames**: the input turned in equal steps (0.5° by default) from the exercise's own
  angle, the way ω turns. At each, the joints are placed by compass, the instant centres
  found by Kennedy's theorem, and both polygons drawn, by tarsim's constructions; each
  frame is checked against the analytic solver and says so. A position that cannot be
  assembled is a frame that says why; nothing is interpolated.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import Any

from tarsim.constructions import geometry as g
from tarsim.constructions.linkages.acceleration_polygon import draw_acceleration_polygon
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.linkages.centres import pair_label
from tarsim.constructions.checks import tolerance
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.linkages.kennedy import locate_centres
from tarsim.constructions.measures import Angle, Dimension
from tarsim.constructions.model import Mechanism
from tarsim.constructions.narration import LANGUAGES, narrate, speaking, words
from tarsim.constructions.record import Kind, Panel, Role
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.centres import (MoveTogether, centre_error, instant_centre,
                                                    shared_pin)
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tarsim.graphics.workers import draw_each
from .exercise_file import Exercise
from tarsim.constructions.linkages.given_rate import convert

__all__ = ["view_data", "FRAME_CHECK"]

FRAME_CHECK = 1e-9
"""The largest relative distance of a frame's joint or polygon tip from the analytic
solver's, beside the mechanism's size or the polygon's largest vector: the construction
agrees to rounding (1e-15 or so) wherever it is well conditioned, so more than this is a
wrong frame, not noise. A centre is held to the tolerance its own conditioning allows."""

_PANELS = {Panel.SPACE: "space", Panel.VELOCITY: "velocity", Panel.ACCELERATION: "acceleration"}


def view_data(ex: Exercise, *, step_deg: float = 0.5,
              progress: Callable[[int], None] | None = None) -> dict[str, Any]:
    """Everything the page shows, as plain data for its JSON.

    Raises
    ------
    TarsimError
        If the exercise cannot be solved at its own position (as ``solve`` says).
    """
    from .solution import solve_positions
    from .solution_files import figure_parts
    from .sweep import sweep_exercise

    if not 0.05 <= step_deg <= 10.0:
        raise TarsimError(f"the frames' step is 0.05° to 10°, not {step_deg:g}°")
    sol = solve_positions(ex)[0]
    mech = sol.assembly.mechanism              # with the input's rates as drawn
    if mech.given is not None:
        mech = convert(mech)[1]
    figures = [_figure(stem, heading, parts) for stem, heading, parts in figure_parts(sol)]
    n = round(360.0 / step_deg)
    sense = -1.0 if mech.drive.omega < 0 else 1.0
    angles = [mech.drive.angle + sense * math.radians(step_deg) * k for k in range(n)]
    scales = _scales(mech)
    chunks = [angles[k::_CHUNKS] for k in range(_CHUNKS)]
    done = draw_each([lambda c=c: [_frame(mech, a, scales) for a in c] for c in chunks])
    frames: list[dict] = [{}] * n
    for k, chunk in enumerate(done):
        frames[k::_CHUNKS] = chunk
    if progress is not None:
        progress(n)
    sweep = sweep_exercise(replace(ex, positions=ex.positions[:1]), n)
    return {
        "title": {lang: ex.named_in(lang).mechanism.name for lang in ("en", "fa")},
        "units": {"length": mech.units.length, "angle": mech.units.angle},
        "input": {"link": mech.drive.link, "omega": mech.drive.omega,
                  "angle": mech.drive.angle, "step": sense * math.radians(step_deg)},
        "points": list(mech.point_names),
        "links": _links(mech, frames[0]),
        "ground": [p for p in mech.point_names if 1 in mech.links_at(p)],
        "slides": [s.point for s in mech.slides if s.contact is None],
        "guides": _guides(mech, frames[0]),
        "wheels": [{"point": c.circle.centre, "radius": c.circle.radius}
                   for c in _contacts(mech) if c.circle.centre],
        "centres": _centre_names(sol),
        "scales": scales,
        "tips": {"velocity": _tip_names(frames, "v"), "acceleration": _tip_names(frames, "a")},
        "figures": figures,
        "ui": {lang: _ui(lang) for lang in _PAGE_LANGUAGES},
        "frames": frames,
        "plot": _plot(sweep),
        "marks": _marks(sweep),
    }


def _contacts(mech: Mechanism) -> list:
    """The circle-on-face and circle-on-circle contacts (a wheel, a roller), once each."""
    out = []
    for joint in (*mech.slides, *mech.arcs):
        if joint.contact is not None and joint.contact not in out:
            out.append(joint.contact)
    return out


def _guides(mech: Mechanism, first: dict) -> list[dict[str, Any]]:
    """The frame's straight guides and faces, as lines (a point on each and its direction):
    a slider's guide, and the ground a wheel rolls on."""
    out = [{"through": list(s.through), "direction": list(s.direction)}
           for s in mech.slides if s.guide_link == 1 and s.contact is None]
    at = dict(zip(mech.point_names, zip(first.get("p", [])[::2], first.get("p", [])[1::2])))
    for c in _contacts(mech):
        face = c.face
        if face.link == 1 and face.through in at and face.angle is not None:
            out.append({"through": list(at[face.through]),
                        "direction": [math.cos(face.angle), math.sin(face.angle)]})
    return out


def _links(mech: Mechanism, first: dict) -> list[dict[str, Any]]:
    """Each link as the page draws it: through its own points and, for a slotted link, the
    points that slide in it, in order along it (at the exercise's position)."""
    at = dict(zip(mech.point_names, zip(first["p"][::2], first["p"][1::2]))) \
        if "p" in first else {}
    out = []
    for k in mech.links:
        own = [p for p, _ in k.points]
        if len(own) > 2 and at:      # a plate: its outline in order round it, not crossed
            cx = sum(at[p][0] for p in own) / len(own)
            cy = sum(at[p][1] for p in own) / len(own)
            own.sort(key=lambda p: math.atan2(at[p][1] - cy, at[p][0] - cx))
        sliding = [s.point for s in mech.slides if s.guide_link == k.number != 1
                   and s.point not in own]
        if sliding and at:
            sliding.sort(key=lambda p: math.dist(at[own[0]], at[p]))
        out.append({"number": k.number, "points": own + sliding})
    return out


_CHUNKS = 8
"""The frames are drawn in this many interleaved chunks, shared out to the cores."""


def _scales(mech: Mechanism) -> dict[str, float]:
    """The polygons' scales at the exercise's position, held through the turn so that the
    polygons do not jump in size from frame to frame."""
    asm = assemble(mech)
    vp = draw_velocity_polygon(asm)
    ap = draw_acceleration_polygon(asm, vp)
    return {"v": vp.scale, "a": ap.scale}


def _frame(mech: Mechanism, angle: float, scales: dict[str, float]) -> dict[str, Any]:
    """One position by construction, checked: joints, centres and both polygons' tips."""
    m = mech.with_drive(replace(mech.drive, angle=angle))
    try:
        asm = assemble(m)
        vp = draw_velocity_polygon(asm, scales["v"])
        ap = draw_acceleration_polygon(asm, vp, scales["a"])
        kin = solver.solve(m)
    except (TarsimError, ArithmeticError) as e:       # a position not reached, a dead point
        return {"angle": angle, "why": str(e).split("\n")[0]}
    try:
        cs = locate_centres(asm)
    except TarsimError as e:     # Kennedy cannot reach a centre here: the rest still stands
        cs, lost = None, str(e).split("\n")[0]
    joints = {p: asm.point(p).xy for p in m.point_names}
    size = max(math.dist(a, b) for a in joints.values() for b in joints.values()) or 1.0
    worst = max(math.dist(joints[p], kin.points[p]) for p in joints) / size
    frame: dict[str, Any] = {"angle": angle, "p": _flat(joints[p] for p in m.point_names)}
    for key, poly, truth in (("v", vp, kin.velocities), ("a", ap, kin.accelerations)):
        tips = {name: asm.output(ref).xy for name, ref in poly.tips.items()}
        pole = asm.output(poly.pole).xy
        frame[key] = {name: _round(xy) for name, xy in tips.items()}
        frame[key + "o"] = _round(pole)
        read = {n: poly.vector(n) for n in tips if n in truth}
        big = max([math.hypot(*v) for v in truth.values()] + [1e-300])
        worst = max([worst] + [math.dist(read[n], truth[n]) / big for n in read])
    centres, miss = {}, 0.0
    for c in (cs.secondaries + cs.primaries) if cs is not None else ():
        p = cs.point(*c.pair)
        centres[c.label] = None if p.is_at_infinity else _round(p.xy)
        try:
            ref = instant_centre(kin, *c.pair, pin=shared_pin(m, *c.pair))
        except MoveTogether:        # every point is a centre of the two: nothing to check
            continue
        err = centre_error(p, ref, size)
        if err > tolerance(cs.conditioning(*c.pair)):
            miss = max(miss, err)
    frame["c"] = centres
    if cs is None:
        frame["centres"] = lost
    frame["ok"] = worst <= FRAME_CHECK and miss == 0.0
    if not frame["ok"]:
        frame["why"] = (f"its construction is {worst:.1g} off the analytic solution"
                        if worst > FRAME_CHECK else
                        f"an instant centre is {miss:.1g} off its analytic position")
    return frame


def _round(xy: tuple[float, float]) -> list[float]:
    """A point as the page keeps it: a tenth of a micrometre of the drawing, far below what
    a screen shows, and few enough digits to keep 720 frames small."""
    return [round(xy[0], 7) + 0.0, round(xy[1], 7) + 0.0]


def _flat(points) -> list[float]:
    return [v for xy in points for v in _round(xy)]


def _tip_names(frames: list[dict], key: str) -> list[str]:
    for f in frames:
        if key in f:
            return list(f[key])
    return []


def _centre_names(sol) -> list[dict[str, Any]]:
    """Each centre, and for those found by Kennedy the two lines (pairs of centres) that
    crossed at it: drawn as the Kennedy lines of every frame."""
    cs = locate_centres(assemble(sol.assembly.mechanism))
    out = []
    for c in cs.primaries + cs.secondaries:
        i, j = c.pair
        lines = [[pair_label(i, k), pair_label(k, j)] for k in c.triangles if k is not None][:2]
        out.append({"label": c.label, "lines": lines})
    return out


def _figure(stem: str, heading: str, parts) -> dict[str, Any]:
    """A figure's steps, numbered per panel as steps.md numbers them, each with what it
    draws; an unnumbered step (a point an arc named) goes with the numbered one before."""
    out = []
    for title, panel, shown in parts:
        numbered = {s.id: k for k, s in shown.numbered(panel)}
        steps, current = [], 0
        for step in shown.steps(panel):
            if step.role is Role.GIVEN and panel is Panel.SPACE:
                continue                # the mechanism itself, which the page draws anyway
            current = numbered.get(step.id, current)
            drawn = _drawn(step.output)
            said = {lang: narrate(step, lang) for lang in _PAGE_LANGUAGES} \
                if step.id in numbered else None
            if drawn is None and said is None:
                continue
            steps.append({"n": current, "said": said, "draw": drawn, "label": step.label,
                          "layer": "kennedy" if step.kind is Kind.KENNEDY_LINE else
                          "construction"})
        out.append({"title": {lang: _said_title(title, lang) for lang in _PAGE_LANGUAGES},
                    "panel": _PANELS.get(panel, "space"), "steps": steps})
    return {"stem": stem, "heading": {lang: _said_title(heading, lang)
                                      for lang in _PAGE_LANGUAGES}, "parts": out}


_PAGE_LANGUAGES = ("en", "fa")
assert set(_PAGE_LANGUAGES) <= set(LANGUAGES)


_UI = ("space diagram", "velocity polygon", "acceleration polygon", "figure", "play",
       "download this frame (SVG)", "Kennedy lines", "construction lines", "labels",
       "step numbers")
"""The page's own words (its panels, controls and layers), said from the catalogue."""


def _ui(lang: str) -> dict[str, str]:
    with speaking(lang):
        return {w: words(w) for w in _UI}


def _said_title(title: str, lang: str) -> str:
    from .solution_files import heading_in

    with speaking(lang):
        return heading_in(title, lang)


def _drawn(out: Any) -> dict[str, Any] | None:
    """What a step puts on the figure, as the page draws it; None for what it cannot."""
    if isinstance(out, g.Point):
        return None if out.is_at_infinity else {"pt": _round(out.xy)}
    if isinstance(out, g.Segment):
        return {"seg": _round(out.start.xy) + _round(out.end.xy)}
    if isinstance(out, Dimension):
        return {"seg": _round(out.start.xy) + _round(out.end.xy), "dim": True}
    if isinstance(out, g.Line):
        if out.is_at_infinity:
            return None
        (dx, dy) = out.direction
        base = (-out.a * out.c, -out.b * out.c)          # the foot from the origin
        return {"line": _round(base) + [round(dx, 9), round(dy, 9)]}
    if isinstance(out, g.Circle):
        return {"circle": _round(out.centre.xy) + [round(out.radius, 7)]}
    if isinstance(out, Angle):
        return {"angle": _round(out.vertex.xy) + [round(out.start, 6), round(out.sweep, 6),
                                                  round(out.reach, 7)]}
    return None


def _plot(sweep) -> dict[str, Any]:
    """The output's velocity round the turn (the analytic curve the sweep gives), for the
    page's plot and its cursor."""
    from .sweep import KEYS

    key = KEYS[sweep.output.kind][1][0]          # the speed, signed along a guide or not
    return {"symbol": sweep.output.symbol(key), "key": key,
            "unit": "rad/s" if sweep.output.kind == "link" else "m/s",
            "values": [round(s.values[key], 9) if s.values else None for s in sweep.samples]}


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
