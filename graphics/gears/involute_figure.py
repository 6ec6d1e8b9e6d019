"""The involute mesh as a figure: the zone where the teeth meet, drawn large.

The line of centres stands upright, the pinion below and the wheel above, and the window
holds three teeth of each gear either side of the pitch point, each flank an involute of
its base circle (:mod:`.involute_teeth`), with the construction's points of the profile
through P dotted on it. The gears' circles cross the window as arcs, each named: pitch
circles chain-dotted, base circles thin dashed, addendum (and root) circles thin and
solid; the line of centres heavy chain-dotted, the common tangent dotted. The line of
action is solid, the path of contact heavy along it, the arc of contact dimensioned on
the pinion's pitch circle, and the pressure angle marked at P between the common tangent
and the line of action.
"""

from __future__ import annotations

import math

from tarsim.constructions.gears.involute import InvoluteMesh
from tarsim.constructions.gears.train import GearTrain
from tarsim.constructions.narration import numerals, unit_words, words
from ..figure import Circle, Figure, Path
from ..drafts import label_placer
from ..fitting import to_sheet
from ..hiding import shown_answer
from ..labels import LabelPlacer, paper_angle
from ..scales import draw_caption, nice_per_cm
from ..symbols import draw_arrowhead, mark_angle
from ..typeset import subscript
from .involute_teeth import Teeth

__all__ = ["draw_involute_figure", "mesh_teeth", "TEETH_EACH_SIDE"]

_ROOM = (250.0, 130.0)    # paper (mm) the window is fitted to: A4 on its side
TEETH_EACH_SIDE = 3
"""Teeth of each gear drawn either side of the pitch point."""

_STYLE = {"pitch": "construction", "base": "reference", "addendum": "gauge", "root": "gauge"}
"""How each circle is drawn: pitch circles chain-dotted as centre lines, base circles thin
dashed, addendum and root circles thin and solid."""

_SHOWN = range(-TEETH_EACH_SIDE, TEETH_EACH_SIDE)
"""The teeth drawn, numbered the way each gear's first flank turns: tooth 0, whose flank
passes through P, and two more on that side of P; three on the other."""

_NEAR = 3.0
"""Paper (mm): a line's name set farther than this from it is joined to it by a leader."""

_NAMED = ("pitch", "base", "addendum")
_INNER = {"base": 0, "pitch": 1, "addendum": 2}
"""The circles named on the figure, each gear's."""


def mesh_teeth(mesh: InvoluteMesh) -> dict[int, Teeth]:
    """Each gear's teeth, by gear number, from the drawn mesh: the flank through P starts
    where the construction's string leaves the base circle and turns the way it does."""
    out = {}
    c = mesh.construction
    for k, n in enumerate(mesh.centres, start=2):
        cx, cy = mesh.centres[n]
        prof = [c.output(r).xy for r in mesh.profiles[n]]
        turn = math.remainder(math.atan2(prof[-1][1] - cy, prof[-1][0] - cx)
                              - math.atan2(prof[0][1] - cy, prof[0][0] - cx), 2 * math.pi)
        rb, rs = mesh.radii[f"base{k}"], mesh.radii[f"pitch{k}"]
        out[n] = Teeth((cx, cy), round(2 * math.pi * rs / mesh.circular_pitch), rb, rs,
                       mesh.radii[f"addendum{k}"], mesh.radii[f"root{k}"], mesh.starts[n],
                       1.0 if turn > 0 else -1.0)
    return out


def draw_involute_figure(train: GearTrain, mesh: InvoluteMesh, title: str,
                         per_cm: float | None = None) -> Figure:
    """The mesh zone of ``mesh`` at ``per_cm`` (by default the nice scale that fits its
    room, fitted to the sheet it is drawn on), with its caption."""
    c = mesh.construction
    teeth = mesh_teeth(mesh)
    outlines = {n: t.outline(_SHOWN) for n, t in teeth.items()}
    keys = ["P", "A", "B", "T2", "T3"]
    pts = [c.output(k).xy for k in keys] + [p for o in outlines.values() for p in o]
    x0, x1 = min(p[0] for p in pts), max(p[0] for p in pts)
    y0, y1 = min(p[1] for p in pts), max(p[1] for p in pts)
    pad = 0.06 * max(x1 - x0, y1 - y0)
    x0, x1, y0, y1 = x0 - pad, x1 + pad, y0 - pad, y1 + pad
    # The line of centres (world x) upright on the paper: world y runs across.
    if per_cm is None:
        return to_sheet(lambda at: draw_involute_figure(train, mesh, title, at),
                        max(nice_per_cm((y1 - y0) * 1e3, _ROOM[0]),
                            nice_per_cm((x1 - x0) * 1e3, _ROOM[1])))
    k = 10.0 / per_cm * 1e3                       # paper mm per metre

    def paper(xy) -> tuple[float, float]:
        return -xy[1] * k, -xy[0] * k

    def inside(xy) -> bool:
        return x0 <= xy[0] <= x1 and y0 <= xy[1] <= y1

    fig = Figure(0.0, 0.0, title=title)
    placer = label_placer(fig)   # drafting: as on a blank page
    names = {n: c["O2" if i == 0 else "O3"].label for i, n in enumerate(mesh.centres)}
    ends: dict[str, list] = {}            # each circle's arcs, from either end
    for ref, radius in mesh.radii.items():
        centre = c.output("O2" if ref.endswith("2") else "O3").xy
        runs = _window_arcs(centre, radius, inside)
        for run in runs:
            _line(fig, placer, [paper(p) for p in run], _STYLE[ref.rstrip("23")])
        ends[ref] = [[paper(q) for q in run[::step]] for run in runs
                     for step in (1, -1)]
    # The line of centres across the window, toward O2 and O3.
    low, high = paper((x0, 0.0)), paper((x1, 0.0))
    fig.add(Path((low, high), "centre_line"))
    placer.block_segment(low, high, 0.6)
    # The line of action, the common tangent, the path of contact.
    t2, t3 = paper(c.output("T2").xy), paper(c.output("T3").xy)
    _line(fig, placer, [t2, t3], "vector")
    p = paper(c.output("P").xy)
    u = paper(c.output("U").xy)
    du = (u[0] - p[0], u[1] - p[1])
    n = math.hypot(*du) or 1.0
    reach = 0.45 * math.dist(t2, t3)
    a_tan = (p[0] - reach * du[0] / n, p[1] - reach * du[1] / n)
    b_tan = (p[0] + reach * du[0] / n, p[1] + reach * du[1] / n)
    _line(fig, placer, [a_tan, b_tan], "leader")
    a, b = paper(c.output("A").xy), paper(c.output("B").xy)
    fig.add(Path((a, b), "vector_result"))
    placer.block_segment(a, b, 1.0)
    # The teeth, and the construction's points of each profile through P on them.
    for n, outline in outlines.items():
        _line(fig, placer, [paper(q) for q in outline], "link")
        for ref in mesh.profiles[n][1:]:
            fig.add(Circle(paper(c.output(ref).xy), 0.35, "dot"))
    arc_mid = _arc_of_contact(fig, placer, mesh, teeth, paper, k)
    # The pressure angle at P, from the common tangent to the line of action.
    up = math.atan2(-(b_tan[1] - p[1]), b_tan[0] - p[0])
    act = math.atan2(-(t3[1] - p[1]), t3[0] - p[0])
    up = min((up, up + math.pi), key=lambda a: abs(math.remainder(act - a, 2 * math.pi)))
    mid = mark_angle(fig, p, 9.0, up, up + math.remainder(act - up, 2 * math.pi))
    for ref in ("P", "A", "B", "T2", "T3", "S2", "S3", "P1"):
        at = paper(c.output(ref).xy)
        if inside(c.output(ref).xy):
            fig.add(Circle(at, 0.6, "dot"))
            placer.block_segment(at, at, 1.2)
    placer.place("φ", mid, prefer=paper_angle((mid[0] - p[0], mid[1] - p[1])), gap=1.0,
                 size=3.2, rings=(1.0, 1.6, 2.3, 3.2, 4.5))
    for ref in ("P", "A", "B", "T2", "T3", "S2", "S3", "P1"):
        if inside(c.output(ref).xy):
            at = paper(c.output(ref).xy)
            placer.place(subscript(c[ref].label), at, prefer=(0.8, 2.4, -0.8, -2.4), gap=1.2,
                         size=3.2, own=at)
    # The named lines: each circle near where it leaves the window, the line of action
    # beyond B, the path of contact beside AB, the arc of contact beside its arc.
    for ref, (spots, way) in _circle_spots(ends).items():
        gear = list(mesh.centres)[0 if ref.endswith("2") else 1]
        # a leader, not nearness, ties a name to its circle where circles run close
        _name(placer, words(f"{ref.rstrip('23')} circle {{gear}}", gear=numerals(str(gear))),
              spots, way, None)
    side = paper_angle((-(t3[1] - t2[1]), t3[0] - t2[0]))
    _name(placer, words("line of action"), [_along(b, t3, f) for f in (0.6, 0.4, 0.8)]
          + [_along(a, t2, f) for f in (0.6, 0.4, 0.8)], (side, side + math.pi), (t2, t3))
    _name(placer, words("path of contact"), [_along(p, a, f) for f in (0.6, 0.4, 0.8)]
          + [_along(p, b, f) for f in (0.6, 0.4, 0.8)], (side + math.pi, side), (a, b))
    _name(placer, words("arc of contact"), [arc_mid], (-math.pi / 2,), arc_mid)
    for name, at, way in ((names[list(mesh.centres)[0]], low, -math.pi / 2),
                          (names[list(mesh.centres)[1]], high, math.pi / 2)):
        placer.place(words("to {centre}", centre=subscript(name)), at, prefer=way, spread=0.5,
                     gap=1.0, size=3.0, italic=False)
    pa, wa = (train.gear(n) for n in mesh.centres)
    draw_caption(fig, train.name,
                 [words("module {module} {mm}, {z1} and {z2} teeth, pressure angle {angle}°",
                        module=numerals(f"{float(pa.module) * 1e3:g}"), mm=unit_words("mm"),
                        z1=numerals(str(pa.teeth)), z2=numerals(str(wa.teeth)),
                        angle=numerals(f"{math.degrees(mesh.pressure_angle):.4g}")),
                  *[line for line in [shown_answer(words(
                      "path of contact AB = {path} {mm}, contact ratio {ratio}",
                      path=numerals(f"{mesh.path * 1e3:.4g}"), mm=unit_words("mm"),
                      ratio=numerals(f"{mesh.contact_ratio:.4g}")))] if line]],
                 per_cm=per_cm, unit="mm",
                 legend=(("construction", "pitch circles"), ("reference", "base circles"),
                         ("gauge", "addendum and root circles"),
                         ("centre_line", "line of centres"), ("leader", "common tangent"),
                         ("vector", "line of action"), ("vector_result", "path of contact"),
                         ("dimension", "arc of contact"),
                         ("link", "teeth, each flank an involute of its base circle")))
    return fig


def _window_arcs(centre, radius: float, inside) -> list[list[tuple[float, float]]]:
    """The runs of the circle about ``centre`` that lie in the window (world points)."""
    runs: list[list[tuple[float, float]]] = []
    run: list[tuple[float, float]] = []
    for i in range(2001):
        t = 2 * math.pi * i / 2000
        xy = (centre[0] + radius * math.cos(t), centre[1] + radius * math.sin(t))
        if inside(xy):
            run.append(xy)
        elif run:
            runs.append(run)
            run = []
    if run:
        runs.append(run)
    return [r for r in runs if len(r) >= 2]


def _circle_spots(ends: dict[str, list]) -> dict[str, tuple[list, tuple[float, float]]]:
    """Where each named circle may be named, and which ways: at the end of its arc at the
    window's edge, on the left for the pinion's and the right for the wheel's, then a few
    millimetres at a time back along it; beyond the end, or to either side of the arc."""
    out = {}
    # the inner circles first: a name set later clears the names and leaders set before
    for ref, runs in sorted(ends.items(), key=lambda e: _INNER.get(e[0][:-1], 9)):
        if ref.rstrip("23") not in _NAMED or not runs:
            continue
        pick = max if ref.endswith("3") else min
        run = pick(runs, key=lambda r: r[0][0])
        spots = [run[0]]
        for q in run[1:]:
            if math.dist(q, spots[-1]) >= 6.0 and len(spots) < 6:
                spots.append(q)
        a, b = run[0], run[1]
        out_way = paper_angle((a[0] - b[0], a[1] - b[1]))
        out[ref] = (spots, (out_way, out_way + math.pi / 2, out_way - math.pi / 2))
    return out


def _arc_of_contact(fig: Figure, placer: LabelPlacer, mesh: InvoluteMesh,
                    teeth: dict, paper, k: float) -> tuple[float, float]:
    """Dimension the arc of contact on the pinion's pitch circle through P: the arc its
    pitch point turns through from A to B, AP / cos φ before P and PB / cos φ after, with
    its ends carried down inside the root circle; returns where on the dimension arc its
    name goes."""
    c = mesh.construction
    n = next(iter(mesh.centres))
    cx, cy = mesh.centres[n]
    px, py = c.output("P").xy
    r = math.hypot(px - cx, py - cy)
    at_p = math.atan2(py - cy, px - cx)
    (ax, ay), (bx, by), (tx, ty) = (c.output(q).xy for q in ("A", "B", "T2"))
    # The pinion turns so that contact runs from A to B: its sense is the sign of
    # T2 − O2 crossed with the direction A → B.
    sense = 1.0 if (tx - cx) * (by - ay) - (ty - cy) * (bx - ax) > 0 else -1.0
    cos_phi = math.cos(mesh.pressure_angle)
    before = math.hypot(px - ax, py - ay) / cos_phi / r
    after = math.hypot(bx - px, by - py) / cos_phi / r
    a0, a1 = at_p - sense * before, at_p + sense * after
    inner = teeth[n].root - 4.0 / k                  # 4 mm inside the root circle
    world = [(cx + inner * math.cos(a0 + (a1 - a0) * i / 60),
              cy + inner * math.sin(a0 + (a1 - a0) * i / 60)) for i in range(61)]
    arc = [paper(q) for q in world]
    fig.add(Path(tuple(arc), "dimension"))
    placer.block_path(arc, 0.3)
    for angle, end, nxt in ((a0, arc[0], arc[1]), (a1, arc[-1], arc[-2])):
        on = paper((cx + r * math.cos(angle), cy + r * math.sin(angle)))
        below = paper((cx + (inner - 2.0 / k) * math.cos(angle),
                       cy + (inner - 2.0 / k) * math.sin(angle)))
        fig.add(Path((on, below), "dimension"))          # the extension line
        placer.block_segment(on, below, 0.3)
        draw_arrowhead(fig, end, (end[0] - nxt[0], end[1] - nxt[1]), length=2.2, width=1.2)
    return arc[len(arc) // 4]             # its name off the line of centres


def _along(a, b, f: float) -> tuple[float, float]:
    return (a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]))


def _name(placer: LabelPlacer, text: str, anchors: list[tuple[float, float]],
          prefer: tuple[float, ...], own) -> None:
    """Name a line near the first of ``anchors`` with room, out to a dozen millimetres, a
    leader from the line to a name set farther than :data:`_NEAR` from it."""
    t = placer.place(text, anchors, prefer=prefer, spread=1.2, gap=1.0, size=2.8,
                     italic=False, rings=(1.0, 1.6, 2.3, 3.2, 4.5, 6.5, 9.0, 12.0), own=own)
    x0, y0, x1, y1 = t.box()
    at = min(anchors, key=lambda q: math.dist(q, _nearest((x0, y0, x1, y1), q)))
    edge = _nearest((x0, y0, x1, y1), at)
    if math.dist(at, edge) > _NEAR:
        placer.fig.add(Path((at, edge), "plot_leader"))
        placer.block_path([at, edge], 0.2)


def _nearest(box: tuple[float, float, float, float], q: tuple[float, float]
             ) -> tuple[float, float]:
    """The point of ``box`` nearest ``q``."""
    return (min(max(q[0], box[0]), box[2]), min(max(q[1], box[1]), box[3]))


def _line(fig: Figure, placer: LabelPlacer, pts, style: str) -> None:
    if len(pts) >= 2:
        fig.add(Path(tuple(pts), style))
        placer.block_path(list(pts), 0.3)

