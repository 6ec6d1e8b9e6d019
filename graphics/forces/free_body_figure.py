"""Each moving link alone with every force on it, as the textbooks draw free bodies.

The links are drawn to the space diagram's scale, side by side in their numbers' order,
each as it stands (a block as a small square) with every point a force acts at named;
every force is an arrow from its point of action at the body's own force scale, stated
under it (a block's newtons beside a lever's hundreds), named beside its own arrow, and
every couple a turning arrow with its moment. A force too short for its body's scale is
drawn dashed at a stated length rather than left out. The loads come from the file and
the acceleration polygon, the joint forces from the force polygons: each body's forces add
to nothing.
"""

from __future__ import annotations

import math

from tarsim.constructions.checks import NOISE
from tarsim.constructions.narration import words
from ..figure import Figure, Path, Text, shelve
from .force_figure import in_lane, runs_along
from .force_key import draw_key
from ..labels import LabelPlacer
from .load_marks import amount, draw_couple, keep_clear, name_loads
from ..scales import draw_caption, nice_per_cm, scale_text
from ..symbols import draw_arrow
from ..typeset import typeset

__all__ = ["draw_free_bodies"]

_ARROW = 45.0        # paper mm a body's largest force is drawn at most
_SHORT = 10.0
"""Paper (mm) a force shorter than this at its body's scale is drawn at, dashed (the legend
says so): shorter, an arrow among those meeting at a joint is all head and shows neither
its direction nor that it is there, and its name finds no room clear of theirs. Every
arrow drawn to scale stays at least as long, so none looks smaller than a dashed one."""


def draw_free_bodies(mech, at: dict, bodies: dict, title: str, unit: str) -> Figure:
    """Each link of ``bodies`` (link → [(where, force N, couple N·m, name)]) drawn from its
    points ``at`` (world m), at a space scale that gives the longest link 80 mm, the bodies
    set in rows no wider than a landscape sheet."""
    links = sorted(bodies)
    spans = [max([math.dist(p, q) for p in _reach(mech, k, at, bodies)
                  for q in _reach(mech, k, at, bodies)] + [0.0]) for k in links]
    metre = mech.units.metres
    per_cm = nice_per_cm(max(spans + [1e-9]) / metre, _LONGEST)
    k_space = 10.0 / (per_cm * metre)                  # paper mm a metre
    biggest = max([math.hypot(*f) for b in bodies.values() for _, f, _, _ in b] + [1e-300])
    drawn = [_draw_body(mech, link, at, bodies[link], k_space, biggest) for link in links]
    fig = shelve(drawn, _ROW, _GAP, title)
    legend = [("vector", "a force, at its body's force scale")]
    if any(isinstance(t, Path) and t.style == "vector_dashed" for t in fig.items):
        legend.append(("vector_dashed", "a force too small for that scale, drawn 10 mm long"))
    draw_caption(fig, title, [words("each link alone with every force on it; its forces add "
                                    "to nothing")], per_cm=per_cm, unit=unit, scale_name="Scale",
                 legend=legend)
    draw_key(fig, [t for t in fig.items if isinstance(t, Text) and t.owner
                   and " = " in t.tail])        # the forces' and couples' names
    return fig


_LONGEST = 80.0
"""Paper (mm) the longest body is drawn at most: the bodies fill a landscape sheet in rows."""

_FARTHER = (10.0, 13.0, 17.0)
"""Rings (in gaps) a name may stand out to when none near what it names is clear."""

_ROW = 215.0
"""The widest a row of bodies runs (mm): a landscape A4's drawing width."""

_GAP = 14.0
"""Paper (mm) between two bodies, and between rows."""


def _draw_body(mech, link: int, at: dict, forces: list, k_space: float,
               biggest: float) -> Figure:
    """One link alone: its outline, every force an arrow from where it acts at the body's
    own force scale and every couple a turning arrow, then all their names and the names of
    the points they act at, placed clear of the drawing and of each other, and under it the
    link's number and its force scale. A force of the rounding of a zero (beside the
    figure's ``biggest``) is no force at all."""
    names = mech.link(link).names
    pts = [at[n] for n in names]
    every = pts + [w for w, _, _, _ in forces]
    cx = sum(p[0] for p in every) / len(every)
    cy = sum(p[1] for p in every) / len(every)
    own_biggest = max([math.hypot(*f) for _, f, _, _ in forces] + [1e-300])
    force_cm = nice_per_cm(own_biggest, _ARROW)          # newtons a paper cm
    k_force = 10.0 / force_cm

    def paper(xy):
        return ((xy[0] - cx) * k_space, -(xy[1] - cy) * k_space)
    fig = Figure(0.0, 0.0)
    if len(pts) >= 2:
        fig.add(Path(tuple(paper(p) for p in pts), "link", closed=len(pts) > 2))
    elif any(s.guide_link == link for s in mech.slides):
        # A lever that carries only its pivot: the bar from it along its slot, as far as the
        # forces on it reach.
        far = max(every, key=lambda w: math.dist(w, pts[0]))
        fig.add(Path((paper(pts[0]), paper(far)), "link"))
    else:
        (px, py) = paper(pts[0])
        fig.add(Path(((px - 3, py - 2), (px + 3, py - 2), (px + 3, py + 2), (px - 3, py + 2)),
                     "block", closed=True))
    arrows, turns = [], []
    outline = [(p, q) for p, q in zip(fig.items[0].points, fig.items[0].points[1:])]
    reach = max([math.dist(p, q) for p in every for q in every] + [1e-9])
    for where, f, couple, name in forces:
        tail = paper(where)
        size = math.hypot(*f)
        if size > NOISE * biggest:               # a zero's rounding is no force at all
            long = size * k_force
            stretch = max(1.0, _SHORT / long)
            head = (tail[0] + f[0] * k_force * stretch, tail[1] - f[1] * k_force * stretch)
            if any(runs_along(tail, head, p, q, within=1.0) for p, q in outline):
                # Along the link it acts on (a two-force member's pull): drawn pushing at
                # its point from outside, clear of the link; one at a point inside the
                # link (its centre of mass) is set beside it instead.
                back = ((2 * tail[0] - head[0], 2 * tail[1] - head[1]), tail)
                if any(runs_along(*back, p, q, within=1.0) for p, q in outline):
                    tail, head = in_lane(tail, head, outline)
                else:
                    tail, head = back
            tail, head = in_lane(tail, head, [(a, b) for a, b, _, _ in arrows])
            draw_arrow(fig, tail, head, "vector" if stretch == 1.0 else "vector_dashed")
            arrows.append((tail, head, name, f" = {amount(size, '.4g', 'N')}"))
        if abs(couple) > NOISE * biggest * reach:
            draw_couple(fig, tail, couple, name, turns, 5.0)
    placer = LabelPlacer(fig)
    placer.block_drawn()
    points = _acting_points(names, pts, forces, at)
    placer.name_points([paper(p) for _, p in points])
    keep_clear(placer, arrows, turns)
    for n, p in points:
        text, sub = typeset(n)                  # O₂, as the space diagram names it
        placer.place(text, paper(p), size=2.6, prefer=3 * math.pi / 4, own=paper(p),
                     rings=(1.0, 1.6, 2.3, 3.2, 4.2), sub=sub)
    name_loads(placer, arrows, turns, 2.6, _FARTHER, along=True)
    x0, _, x1, y1 = fig.bounds()
    fig.add(Text(((x0 + x1) / 2, y1 + 6.0), words("link {link}", link=link), 3.0, "middle", False,
                 "bold"))
    fig.add(Text(((x0 + x1) / 2, y1 + 10.5), f"{words('Force scale')} "
                 f"{scale_text(force_cm, 'N')}", 2.6, "middle", False))
    return fig


def _acting_points(names, pts, forces, at: dict) -> list[tuple[str, tuple[float, float]]]:
    """The body's own points and every other point a force acts at, each (name, where):
    a joint's point by its name in the mechanism, a centre of mass (where a weight or an
    inertia force acts) as G with the link's number."""
    out = list(zip(names, pts))
    for where, _, _, name in forces:
        if any(math.dist(where, p) < 1e-12 for _, p in out):
            continue
        known = next((n for n, p in at.items() if math.dist(where, p) < 1e-12), None)
        if known is None:
            digits = name[2:] if name.startswith("Fi") else name[1:] if name[:1] == "W" else ""
            known = f"G{digits}" if digits.isdigit() else None
        if known is not None:
            out.append((known, where))
    return out


def _reach(mech, link: int, at: dict, bodies: dict) -> list:
    """The points a body's drawing spans: its own and those its forces act at."""
    return [at[n] for n in mech.link(link).names] + [w for w, _, _, _ in bodies[link]]
