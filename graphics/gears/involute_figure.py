"""The involute mesh as a figure: the zone where the teeth meet, drawn large.

The window holds the line of action from one tangency point to the other, the path of
contact and both tooth profiles; the gears' circles cross it as arcs (pitch circles
dash-dotted as centre lines, base circles dashed, addendum and root circles thin grey), the
line of centres runs across it toward O2 and O3. The line of action is solid, the path of
contact heavy, the pressure angle marked at P between the common tangent and the line of
action.
"""

from __future__ import annotations

import math

from tarsim.constructions.gears.involute import InvoluteMesh
from tarsim.constructions.gears.train import GearTrain
from tarsim.constructions.narration import numerals, unit_words, words
from ..figure import Figure, Path, Circle
from ..labels import LabelPlacer
from ..scales import draw_caption, nice_per_cm
from ..symbols import mark_angle
from ..typeset import subscript

__all__ = ["draw_involute_figure"]

_ROOM = (190.0, 120.0)     # paper (mm) the window is fitted to
_STYLE = {"pitch": "construction", "base": "reference", "addendum": "gauge", "root": "gauge"}
"""How each circle is drawn: pitch circles dash-dotted as centre lines, base circles dashed,
addendum and root circles thin."""


def draw_involute_figure(train: GearTrain, mesh: InvoluteMesh, title: str) -> Figure:
    """The mesh zone of ``mesh`` at a nice scale, with its caption."""
    c = mesh.construction
    keys = ["P", "A", "B", "T2", "T3"] + [r for pts in mesh.profiles.values() for r in pts]
    pts = [c.output(k).xy for k in keys]
    x0, x1 = min(p[0] for p in pts), max(p[0] for p in pts)
    y0, y1 = min(p[1] for p in pts), max(p[1] for p in pts)
    pad = 0.12 * max(x1 - x0, y1 - y0)
    x0, x1, y0, y1 = x0 - pad, x1 + pad, y0 - pad, y1 + pad
    per_cm = max(nice_per_cm((x1 - x0) * 1e3, _ROOM[0]), nice_per_cm((y1 - y0) * 1e3, _ROOM[1]))
    k = 10.0 / per_cm * 1e3                       # paper mm per metre

    def paper(xy) -> tuple[float, float]:
        return xy[0] * k, -xy[1] * k

    def inside(xy) -> bool:
        return x0 <= xy[0] <= x1 and y0 <= xy[1] <= y1

    fig = Figure(0.0, 0.0, title=title)
    placer = LabelPlacer(fig)
    # The circles, as arcs through the window.
    for ref, radius in mesh.radii.items():
        centre = c.output("O2" if ref.endswith("2") else "O3").xy
        run: list[tuple[float, float]] = []
        for i in range(2001):
            t = 2 * math.pi * i / 2000
            xy = (centre[0] + radius * math.cos(t), centre[1] + radius * math.sin(t))
            if inside(xy):
                run.append(paper(xy))
            elif run:
                _line(fig, placer, run, _STYLE[ref.rstrip("23")])
                run = []
        if run:
            _line(fig, placer, run, _STYLE[ref.rstrip("23")])
    # The line of centres across the window, toward O2 and O3.
    y = 0.0
    left, right = paper((x0, y)), paper((x1, y))
    fig.add(Path((left, right), "working"))
    for name, at, side in ((c['O2'].label, left, math.pi), (c['O3'].label, right, 0.0)):
        placer.place(words("to {centre}", centre=subscript(name)), at, prefer=side, spread=0.5,
                     gap=1.0, size=3.0, italic=False)
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
    _line(fig, placer, [a_tan, b_tan], "working")
    a, b = paper(c.output("A").xy), paper(c.output("B").xy)
    fig.add(Path((a, b), "vector_result"))
    placer.block_segment(a, b, 1.0)
    # The pressure angle at P, from the common tangent to the line of action.
    up = math.atan2(-(b_tan[1] - p[1]), b_tan[0] - p[0])
    act = math.atan2(-(t3[1] - p[1]), t3[0] - p[0])
    mid = mark_angle(fig, p, 9.0, up, act)
    placer.place("φ", mid, prefer=(up + act) / 2, gap=1.0, size=3.2)
    # The tooth profiles, each through P.
    for refs in mesh.profiles.values():
        prof = [paper(c.output(r).xy) for r in refs]
        _line(fig, placer, prof, "link")
    for ref in ("P", "A", "B", "T2", "T3", "S2", "S3", "P1"):
        at = paper(c.output(ref).xy)
        if not inside(c.output(ref).xy):
            continue
        fig.add(Circle(at, 0.6, "dot"))
        placer.block_segment(at, at, 1.2)
    for ref in ("P", "A", "B", "T2", "T3", "S2", "S3", "P1"):
        if inside(c.output(ref).xy):
            placer.place(subscript(c[ref].label), paper(c.output(ref).xy),
                         prefer=(0.8, 2.4, -0.8, -2.4), gap=1.2, size=3.2)
    pa, wa = (train.gear(n) for n in mesh.centres)
    draw_caption(fig, train.name,
                 [words("module {module} {mm}, {z1} and {z2} teeth, pressure angle {angle}°",
                        module=numerals(f"{float(pa.module) * 1e3:g}"), mm=unit_words("mm"),
                        z1=numerals(str(pa.teeth)), z2=numerals(str(wa.teeth)),
                        angle=numerals(f"{math.degrees(mesh.pressure_angle):.4g}")),
                  words("path of contact AB = {path} {mm}, contact ratio {ratio}",
                        path=numerals(f"{mesh.path * 1e3:.4g}"), mm=unit_words("mm"),
                        ratio=numerals(f"{mesh.contact_ratio:.4g}"))],
                 per_cm=per_cm, unit="mm",
                 legend=(("construction", "pitch circles"), ("reference", "base circles"),
                         ("gauge", "addendum and root circles"), ("vector", "line of action"),
                         ("working", "line of centres, common tangent"),
                         ("vector_result", "path of contact"), ("link", "tooth profiles")))
    return fig


def _line(fig: Figure, placer: LabelPlacer, pts, style: str) -> None:
    if len(pts) >= 2:
        fig.add(Path(tuple(pts), style))
        placer.block_path(list(pts), 0.3)

