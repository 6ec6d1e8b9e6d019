"""Each moving link alone with every force on it, as the textbooks draw free bodies.

The links are drawn to the space diagram's scale, side by side in their numbers' order,
each as it stands (a block as a small square); every force is an arrow from its point of
action at one force scale, named at its head, and every couple a turning arrow with its
moment. The loads come from the file and the acceleration polygon, the joint forces from
the force polygons: each body's forces add to nothing.
"""

from __future__ import annotations

import math

from .figure import Figure, Path, Text, clear_of
from .scales import draw_caption, nice_per_cm
from .symbols import draw_arrow, draw_turning_arrow

__all__ = ["draw_free_bodies"]

_ARROW = 30.0        # paper mm the largest force is drawn at most
_SMALL = 0.02
"""Forces under this share of the largest are listed under the figure, not drawn: an arrow
of under a millimetre shows nothing."""


def draw_free_bodies(mech, at: dict, bodies: dict, title: str, unit: str) -> Figure:
    """Each link of ``bodies`` (link → [(where, force N, couple N·m, name)]) drawn from its
    points ``at`` (world m), at a space scale that gives the longest link 40 mm."""
    links = sorted(bodies)
    spans = [max([math.dist(p, q) for p in _reach(mech, k, at, bodies)
                  for q in _reach(mech, k, at, bodies)] + [0.0]) for k in links]
    metre = mech.units.metres
    per_cm = nice_per_cm(max(spans + [1e-9]) / metre, 60.0)
    k_space = 10.0 / (per_cm * metre)                  # paper mm a metre
    biggest = max([math.hypot(*f) for b in bodies.values() for _, f, _, _ in b] + [1e-300])
    force_cm = nice_per_cm(biggest, _ARROW)             # newtons a paper cm
    k_force = 10.0 / force_cm
    fig = Figure(0.0, 0.0, title=title)
    x = 0.0
    small: list[str] = []
    for link in links:
        names = mech.link(link).names
        pts = [at[n] for n in names]
        acting = [w for w, _, _, _ in bodies[link]]
        every = pts + acting
        cx = sum(p[0] for p in every) / len(every)
        cy = sum(p[1] for p in every) / len(every)

        def paper(xy, cx=cx, cy=cy, x=x):
            return (x + (xy[0] - cx) * k_space, -(xy[1] - cy) * k_space)
        if len(pts) >= 2:
            fig.add(Path(tuple(paper(p) for p in pts), "link", closed=len(pts) > 2))
        elif any(s.guide_link == link for s in mech.slides):
            # A lever that carries only its pivot: the bar from it along its slot, as far as
            # the forces on it reach.
            far = max(acting, key=lambda w: math.dist(w, pts[0]))
            fig.add(Path((paper(pts[0]), paper(far)), "link"))
        else:
            (px, py) = paper(pts[0])
            fig.add(Path(((px - 3, py - 2), (px + 3, py - 2), (px + 3, py + 2), (px - 3, py + 2)),
                         "block", closed=True))
        for n, p in zip(names, pts):
            fig.add(Text((paper(p)[0] - 1.5, paper(p)[1] + 3.5), n, 2.6, "end", True))
        lowest = max(paper(p)[1] for p in pts)
        taken: list[tuple[float, float, float, float]] = []   # the names set on this body
        for where, f, couple, name in bodies[link]:
            tail = paper(where)
            size = math.hypot(*f)
            if size > _SMALL * biggest:
                head = (tail[0] + f[0] * k_force, tail[1] - f[1] * k_force)
                draw_arrow(fig, tail, head, "vector")
                u = ((head[0] - tail[0]) / math.dist(tail, head),
                     (head[1] - tail[1]) / math.dist(tail, head))
                text, sub, tail_text = _name(name)
                label = Text((head[0] + 2.5 * u[0], head[1] + 2.5 * u[1] + 1.0), text, 2.6,
                             "start" if u[0] >= 0 else "end", False, "normal", sub,
                             f"{tail_text} = {size:.4g} N")
                spot = clear_of(label, taken).at
                fig.add(clear_of(label, taken, keep=True))
                lowest = max(lowest, head[1], spot[1])
            elif size > 0:
                small.append(f"{name.replace('_', '')} = {size:.3g} N on link {link}")
            if abs(couple) > 1e-12 * max(biggest, 1.0):
                mid = draw_turning_arrow(fig, tail, 5.0, math.radians(30),
                                         math.copysign(math.radians(240), couple))
                text, sub, tail_text = _name(name.replace("Fi", "Mi"))
                fig.add(clear_of(Text((mid[0] - 2.0, mid[1] - 3.0), text, 2.6, "end", False,
                                    "normal", sub, f"{tail_text} = {abs(couple):.4g} N·m"),
                               taken, keep=True))
        fig.add(Text((x, lowest + 9.0), f"link {link}", 3.0, "middle", False, "bold"))
        x += max(spans[links.index(link)] * k_space, 10.0) + 2 * _ARROW + 40.0
    notes = [f"Too small to draw: {', '.join(small)}."] if small else []
    draw_caption(fig, title, ["each link alone with every force on it; its forces add to "
                              "nothing"], per_cm=per_cm, unit=unit, scale_name="Scale",
                 second=("Force scale", force_cm, "N"), notes=notes)
    return fig


def _reach(mech, link: int, at: dict, bodies: dict) -> list:
    """The points a body's drawing spans: its own and those its forces act at."""
    return [at[n] for n in mech.link(link).names] + [w for w, _, _, _ in bodies[link]]


def _name(name: str) -> tuple[str, str, str]:
    """A force's name as printed: F_23 is F with 23 below, Fi3 F with i3 below, W3 W with 3
    below, T2 T with 2 below; other names as they are."""
    if name[:2] in ("F_", "T_"):
        return name[0], name[2:], ""
    if name[:2] in ("Fi", "Mi") and name[2:].isdigit():
        return name[0], name[1:], ""
    if name[:1] in "WTP" and name[1:].isdigit():
        return name[0], name[1:], ""
    return name, "", ""
