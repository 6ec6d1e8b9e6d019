"""The cam's profile laid out by inversion, as a textbook prints it.

To scale about the cam's centre O: the base circle, the prime, offset or pivot circle,
each station's follower line numbered at its rest point (an oscillating arm's station
numbered at its pivot, with the arc the arm's end swings through there, from the prime
circle to the roller's centre, as a textbook swings it; not the arm itself, whose lines
would cross one another over the profile), the follower drawn at
each station (the knife edge's point, the roller's circle, a stretch of the face), the
pitch curve and, inked heavy, the profile. The cam's turning is shown by an arrow at O,
the steepest pressure angle by the normal n and the follower's path there, and
any undercut station by a ring.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from tarsim.constructions.cams.inversion import Layout
from tarsim.constructions.cams.survey import Survey
from tarsim.constructions.narration import numerals, words
from ..figure import Circle, Figure, Path, Text, arc_points
from ..drafts import label_placer
from ..hiding import shown_answer
from ..fitting import to_sheet
from ..labels import paper_angle
from ..scales import draw_caption, nice_per_cm
from ..symbols import draw_arrow, draw_turning_arrow, mark_angle

__all__ = ["draw_cam_layout"]

_ROOM = 150.0          # paper (mm) the cam's greatest reach across is fitted to
_WINDOW = 1.0          # the curves are drawn within this many _ROOMs of O each way (the
                       # room grown as the figure is, drawn for a bigger sheet)

_CLEAR = 5.0           # mm round O that the follower's lines leave clear for its name
_FACE = 10.0           # mm a flat face reaches at least either side of the follower's line
_ARC_PAST = 3.0        # mm an arm's arc runs past its rest point and its roller's centre

_CIRCLE_STYLE = {"base": "dimension", "prime": "reference", "offset": "reference",
                 "pivot": "kennedy"}
"""How each circle about the cam's centre is drawn: the base circle thin and solid, the
others dashed, the pivot circle apart from the prime circle its arms reach."""


def draw_cam_layout(layout: Layout, s: Survey, title: str, unit: str, metre: float,
                    notes: Sequence[str] = (), per_cm: float | None = None) -> Figure:
    """The layout ``layout`` with the closed-form curves of ``s``; lengths stated in
    ``unit`` (``metre`` metres each), at ``per_cm`` (by default the scale that fits its
    room, fitted to the sheet it is drawn on)."""
    c, f = layout.construction, layout.follower
    reach = max(max(math.hypot(*st.pitch) for st in s.stations) + f.radius,
                math.hypot(*f.pivot) + f.arm if f.oscillating else 0.0)
    if per_cm is None:
        return to_sheet(lambda at: draw_cam_layout(layout, s, title, unit, metre, notes, at),
                        nice_per_cm(2 * reach / metre, _ROOM))
    k = 10.0 / (per_cm * metre)
    window = _WINDOW * max(_ROOM, 2 * reach * k)

    def paper(xy) -> tuple[float, float]:
        return xy[0] * k, -xy[1] * k

    fig = Figure(0.0, 0.0, title=title)
    o = (0.0, 0.0)
    numbers: list[tuple[str, tuple[float, float], float]] = []   # text, where, which way
    for name, ref in layout.circles.items():
        fig.add(Circle(o, c.output(ref).radius * k, _CIRCLE_STYLE[name]))
    for p, st in zip(layout.places, s.places):
        rest, trace = paper(c.output(p.rest).xy), paper(c.output(p.trace).xy)
        past = 0.0 if f.oscillating else f.radius * k + 2.0
        if f.oscillating:
            start = paper(c.output(p.pivot).xy)
            fig.add(Circle(start, 0.5, "dot"))
            fig.add(Path(_arm_arc(start, rest, trace), "compass"))
        else:
            start = o if not f.offset or f.kind == "flat-faced" else \
                paper(c.output(p.axis).anchor())
            # a line from O stops short of it, leaving O and its name clear
            root = _beyond(trace, o, -_CLEAR) if start == o else start
            fig.add(Path((root, _beyond(start, trace, past)), "construction"))
        fig.add(Circle(rest, 0.45, "dot"))
        if f.oscillating:                         # beyond the arm's pivot
            tag, way = start, (start[0] - o[0], start[1] - o[1])
        elif abs(p.theta - s.steepest.theta) < 1e-9 and abs(s.steepest.pressure_angle) > 1e-9:
            tag, way = rest, (rest[0] - trace[0], rest[1] - trace[1])   # the arrows run outside
        else:                                     # beyond the end of the follower's line
            tag, way = _beyond(start, trace, past), (trace[0] - start[0], trace[1] - start[1])
        numbers.append((numerals(str(p.number)), tag, paper_angle(way)))
        if f.kind == "roller":
            fig.add(Circle(trace, f.radius * k, "node_circle"))
        elif f.kind == "flat-faced":
            # The face from its foot past the touch, a few mm beyond each.
            run = min(abs(st.face_offset) * k, window)
            if run > 1e-9:
                d = _unit((st.profile[0] - st.pitch[0], st.pitch[1] - st.profile[1]))
            else:
                along = c.output(p.follower).direction
                d = (along[0], -along[1])
            # At least _FACE each side of the follower's line: a face touching on that line
            # lies along the profile's tangent, and a stub of it would hide under the
            # profile (an eccentric's at its highest and lowest stations).
            back, ahead = _FACE, max(run + 4.0, _FACE)
            fig.add(Path(((trace[0] - back * d[0], trace[1] - back * d[1]),
                          (trace[0] + ahead * d[0], trace[1] + ahead * d[1])),
                         "node_circle"))
        fig.add(Circle(trace, 0.55, "dot"))
    if f.kind != "flat-faced":
        _draw_curve(fig, [paper(st.pitch) for st in s.stations], window,
                    "normal" if f.kind == "roller" else "link")
    _draw_curve(fig, [paper(st.profile) for st in s.stations], window, "link")
    fig.add(Circle(o, 0.8, "dot"))
    sense = 1.0 if s.sigma > 0 else -1.0
    base = c.output(layout.circles["base"]).radius * k
    inner = max(abs(f.offset) * k, 0.0)
    mid = draw_turning_arrow(fig, o, 0.5 * (inner + base) if inner else 0.4 * base,
                             math.radians(200), sense * math.radians(70))
    fig.add(Text((mid[0] - 2.5, mid[1]), "ω", 3.0, "end", False))
    _mark_steepest(fig, s, paper, k)
    # The station numbers last, each out along its own line and clear of every line drawn
    # (the pressure angle's arrows and arc too).
    placer = label_placer(fig)   # drafting: as on a blank page
    placer.block_drawn()
    # O in the widest gap between the lines about it, within the clear round it.
    placer.place("O", o, prefer=_widest_gap(fig, o), spread=math.pi, gap=0.6, size=3.0,
                 italic=False)
    for text, at, way in numbers:
        placer.place(text, at, prefer=way, spread=1.0, gap=1.2, size=2.6, italic=False)
    for st in _ringed(s):
        at = paper(st.profile)                   # or, where it runs off far, its trace point
        fig.add(Circle(at if max(map(abs, at)) <= window else paper(st.pitch), 2.2,
                       "normal"))
    legend = [("link", _cam_term("profile (the pitch curve)" if f.kind == "knife-edge"
                                 else "profile")),
              ("dimension", _cam_term("base circle"))]
    if f.kind == "roller":
        legend.append(("normal", "pitch curve"))
    for name in layout.circles:
        if name != "base":
            legend.append((_CIRCLE_STYLE[name], f"{name} circle"))
    legend.append(("compass", "the arc of the arm's end at each station") if f.oscillating
                  else ("construction", "the follower's line at each station"))
    if f.kind != "knife-edge":
        legend.append(("node_circle", "the roller at each station" if f.kind == "roller"
                       else "the face at each station"))
    draw_caption(fig, title, [words("the cam held still, the follower turned the other way")],
                 per_cm=per_cm, unit=unit,
                 legend=legend, notes=notes)
    return fig


def _cam_term(text: str) -> str:
    """A term as a cam's figure says it where a gear's says it otherwise (a gear's base
    circle is دایرهٔ مبنا, a cam's دایرهٔ پایه): the catalogue keys it "cam: <term>"."""
    key = f"cam: {text}"
    said = words(key)
    return text if said == key else said


def _mark_steepest(fig: Figure, s: Survey, paper, k: float) -> None:
    """At the steepest station: the follower's motion and the profile's normal, the angle
    between them marked."""
    st = s.steepest
    if abs(st.pressure_angle) < 1e-9:
        return
    at = paper(st.pitch)
    n, u = (st.normal[0], -st.normal[1]), (st.motion[0], -st.motion[1])
    length = 14.0
    tip_n = (at[0] + length * n[0], at[1] + length * n[1])
    tip_u = (at[0] + length * u[0], at[1] + length * u[1])
    draw_arrow(fig, at, tip_n, "arrow")
    draw_arrow(fig, at, tip_u, "dimension")
    fig.add(Text((tip_n[0] + 2.4 * n[0], tip_n[1] + 2.4 * n[1] + 1.0), "n", 2.8, "middle"))
    a_n, a_u = math.atan2(-n[1], n[0]), math.atan2(-u[1], u[0])
    sweep = math.remainder(a_n - a_u, 2 * math.pi)
    mid = mark_angle(fig, at, 9.0, min(a_u, a_u + sweep), max(a_u, a_u + sweep))
    # The reading beyond the arc, on the side away from the cam.
    out = _unit((mid[0] - at[0], mid[1] - at[1]))
    spot = (at[0] + (length + 4.0) * out[0], at[1] + (length + 4.0) * out[1])
    reading = words("φ max = {phi}° at θ = {theta}°",
                    phi=numerals(f"{abs(math.degrees(st.pressure_angle)):.1f}"),
                    theta=numerals(f"{math.degrees(st.theta):.4g}"))
    if shown_answer(reading):
        fig.add(Text(spot, reading, 2.8, "start" if out[0] >= 0 else "end", False))


def _draw_curve(fig: Figure, points: list[tuple[float, float]], edge: float,
                style: str) -> None:
    """A closed curve through ``points`` (paper mm), as far as it stays near the cam: an
    undercut profile's loops, or a flat face's touch on a steep segment, can run off
    far beyond the sheet, and are drawn to where they leave the window about O (``edge``
    mm from it each way)."""
    inside = [max(abs(x), abs(y)) <= edge for x, y in points]
    if all(inside):
        fig.add(Path(tuple(points), style, closed=True))
        return
    start = inside.index(False)                  # begin the walk just past a point outside
    run: list[tuple[float, float]] = []
    for i in range(start, start + len(points) + 1):
        j = i % len(points)
        if inside[j]:
            run.append(points[j])
        elif run:
            if len(run) > 1:
                fig.add(Path(tuple(run), style))
            run = []
    if len(run) > 1:
        fig.add(Path(tuple(run), style))


def _ringed(s: Survey, most: int = 6):
    """The stations ringed in each undercut span: its worst, and up to ``most`` of the
    drawn stations inside it, spread along it."""
    out = []
    for span in s.undercut:
        inside = [st for st in s.stations
                  if span.start <= st.theta <= span.end
                  or span.start <= st.theta + 2 * math.pi <= span.end]
        out += inside[:: max(1, len(inside) // most)] + [span.worst]
    return out


def _arm_arc(pivot: tuple[float, float], rest: tuple[float, float],
             trace: tuple[float, float]) -> tuple[tuple[float, float], ...]:
    """The arc the arm's end swings through at one station, as a textbook draws it: about
    the station's ``pivot``, from the roller's centre at rest on the prime circle to its
    centre there (``trace``), and :data:`_ARC_PAST` beyond each (paper mm, y down)."""
    r = math.dist(pivot, rest)
    a = math.atan2(-(rest[1] - pivot[1]), rest[0] - pivot[0])
    b = math.atan2(-(trace[1] - pivot[1]), trace[0] - pivot[0])
    sweep = math.remainder(b - a, 2 * math.pi)
    way = 1.0 if sweep >= 0 else -1.0
    past = _ARC_PAST / r
    return tuple(arc_points(pivot, r, a - way * past, sweep + 2 * way * past))


def _widest_gap(fig: Figure, o: tuple[float, float]) -> float:
    """The paper angle (rad, y up) mid-way across the widest gap between the lines drawn
    from near ``o``, where its name stands clear of them."""
    rays = sorted({round(math.atan2(-(q[1] - o[1]), q[0] - o[0]) % (2 * math.pi), 9)
                   for item in fig.items if isinstance(item, Path) and len(item.points) == 2
                   and item.style == "construction"
                   and math.dist(item.points[0], o) <= _CLEAR + 1e-6
                   for q in item.points[1:]})
    if not rays:
        return math.radians(-60.0)
    gaps = [((rays[(i + 1) % len(rays)] - a) % (2 * math.pi) or 2 * math.pi, a)
            for i, a in enumerate(rays)]
    width, at = max(gaps)
    return at + width / 2


def _unit(v: tuple[float, float]) -> tuple[float, float]:
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n)


def _beyond(a: tuple[float, float], b: tuple[float, float], by: float) -> tuple[float, float]:
    d = _unit((b[0] - a[0], b[1] - a[1]))
    return (b[0] + by * d[0], b[1] + by * d[1])
