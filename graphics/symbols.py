"""Textbook kinematic symbols (after ISO 3952), drawn on paper in millimetres.

Hatching is explicit line geometry clipped with shapely, so it stays crisp in PNG
as well as PDF; arrowheads are filled polygons, not SVG markers.
"""

from __future__ import annotations

import math

from shapely.geometry import LineString, MultiLineString, Polygon

from .figure import Circle, Figure, Path, Text, arc_points
from .hiding import hidden

__all__ = [
    "PIN_RADIUS",
    "draw_pin",
    "draw_dimension",
    "draw_ground_pivot",
    "draw_hatched_band",
    "draw_guide",
    "draw_curved_guide",
    "draw_curved_slot",
    "draw_block",
    "draw_arrowhead",
    "draw_turning_arrow",
    "mark_angle",
    "draw_arrow",
    "draw_badge",
    "badge_radius",
    "ground_footprint",
    "unit",
]

PIN_RADIUS = 1.25
_HATCH_PITCH = 1.3


def unit(v: tuple[float, float]) -> tuple[float, float]:
    """Normalise a paper vector."""
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n)


def draw_pin(fig: Figure, at: tuple[float, float]) -> None:
    """A revolute pair: a small open circle at the joint centre."""
    fig.add(Circle(at, PIN_RADIUS, "pin"))


def draw_hatched_band(fig: Figure, a: tuple[float, float], b: tuple[float, float],
                      side: tuple[float, float], depth: float = 2.0) -> Polygon:
    """Hatch a band of ``depth`` mm beside segment ``ab`` on ``side``; return its outline."""
    sx, sy = unit(side)
    band = Polygon([a, b, (b[0] + depth * sx, b[1] + depth * sy),
                    (a[0] + depth * sx, a[1] + depth * sy)])
    return _hatch(fig, band)


def draw_hatched_arc(fig: Figure, centre: tuple[float, float], radius: float, start: float,
                     sweep: float, *, inward: bool, depth: float = 2.0) -> Polygon:
    """Hatch a band of ``depth`` mm along an arc (paper angles, rad), inside the circle or
    outside it: a fixed circular profile, ground as a straight face is. Returns its outline."""
    edge = arc_points(centre, radius, start, sweep)
    back = arc_points(centre, radius - depth if inward else radius + depth, start + sweep,
                      -sweep)
    return _hatch(fig, Polygon(edge + back))


def _hatch(fig: Figure, band: Polygon, lines: list | None = None) -> Polygon:
    """Draw ``lines`` clipped to ``band`` (by default 45° hatching across it); return it."""
    if lines is None:
        x0, y0, x1, y1 = band.bounds
        # 45° lines x + y = c on paper (they rise to the right, as "/").
        step = _HATCH_PITCH * math.sqrt(2.0)
        lines = []
        c = x0 + y0 + step / 2
        while c < x1 + y1:
            lines.append(((c - y0 + 1.0, y0 - 1.0), (c - y1 - 1.0, y1 + 1.0)))
            c += step
    clipped = MultiLineString(lines).intersection(band)
    for seg in getattr(clipped, "geoms", [clipped]):
        if isinstance(seg, LineString) and not seg.is_empty and seg.length > 0.2:
            fig.add(Path(tuple(seg.coords), "hatch"))
    return band


def ground_footprint(at: tuple[float, float], down: tuple[float, float]) -> Polygon:
    """The paper area a ground pivot occupies (for label placement)."""
    dx, dy = unit(down)
    px, py = -dy, dx
    h, w = 4.6, 4.4
    return Polygon([(at[0] + w * px, at[1] + w * py), (at[0] - w * px, at[1] - w * py),
                    (at[0] - w * px + (h + 2.2) * dx, at[1] - w * py + (h + 2.2) * dy),
                    (at[0] + w * px + (h + 2.2) * dx, at[1] + w * py + (h + 2.2) * dy)])


def draw_ground_pivot(fig: Figure, at: tuple[float, float],
                      down: tuple[float, float] = (0.0, 1.0)) -> Polygon:
    """A fixed pivot: pin on a small triangle whose hatched base faces ``down``."""
    dx, dy = unit(down)
    px, py = -dy, dx
    h, half = 4.6, 3.0
    base = (at[0] + h * dx, at[1] + h * dy)
    tri = ((at[0] + 0.0, at[1] + 0.0), (base[0] + half * px, base[1] + half * py),
           (base[0] - half * px, base[1] - half * py))
    fig.add(Path(tri, "ground", closed=True))
    a = (base[0] + 4.4 * px, base[1] + 4.4 * py)
    b = (base[0] - 4.4 * px, base[1] - 4.4 * py)
    draw_hatched_band(fig, a, b, (dx, dy))
    fig.line(a, b, "ground_base")
    draw_pin(fig, at)
    return ground_footprint(at, down)


def draw_guide(fig: Figure, a: tuple[float, float], b: tuple[float, float],
               side: tuple[float, float]) -> Polygon:
    """A fixed straight guide from ``a`` to ``b``, hatched on ``side``."""
    band = draw_hatched_band(fig, a, b, side, depth=1.8)
    fig.line(a, b, "guide")
    return band


def draw_curved_guide(fig: Figure, centre: tuple[float, float], radius: float, start: float,
                      sweep: float, side: float) -> Polygon:
    """A fixed circular guide about ``centre`` (paper angles, rad, CCW as seen).

    It is hatched outside the arc for ``side`` > 0 and inside it otherwise, as
    :func:`draw_guide` hatches a straight one on its far side. The strokes lean 45°
    to the radius, not to the page, so none runs along the arc where it curves.
    """
    depth = math.copysign(1.8, side)
    rim = arc_points(centre, radius, start, sweep)
    back = arc_points(centre, radius + depth, start + sweep, -sweep)
    step = _HATCH_PITCH * math.sqrt(2.0) / radius
    strokes = []
    for i in range(int(abs(sweep) / step) + 2):
        a = start + math.copysign(i * step, sweep)
        p = (centre[0] + radius * math.cos(a), centre[1] - radius * math.sin(a))
        # Out along the radius by the depth and on along the arc by as much: 45°.
        q = (p[0] + 1.5 * depth * (math.cos(a) - math.sin(a)),
             p[1] - 1.5 * depth * (math.sin(a) + math.cos(a)))
        strokes.append((p, q))
    band = _hatch(fig, Polygon(rim + back), strokes)
    fig.add(Path(tuple(rim), "guide"))
    return band


def draw_curved_slot(fig: Figure, centre: tuple[float, float], radius: float, start: float,
                     sweep: float, half_width: float, style: str = "link") -> Polygon:
    """A curved slot: its outline ``half_width`` either side of the arc, with round ends.

    The ends are half circles about the arc's ends, as a milled slot has.
    """
    turn = math.copysign(math.pi, sweep)
    end = start + sweep
    ends = [(centre[0] + radius * math.cos(a), centre[1] - radius * math.sin(a))
            for a in (start, end)]
    ring = (arc_points(centre, radius + half_width, start, sweep)
            + arc_points(ends[1], half_width, end, turn)
            + arc_points(centre, radius - half_width, end, -sweep)
            + arc_points(ends[0], half_width, start + math.pi, turn))
    fig.add(Path(tuple(ring), style, closed=True))
    return Polygon(ring)


def draw_block(fig: Figure, centre: tuple[float, float], along: tuple[float, float],
               length: float = 9.0, height: float = 5.0, lift: float = 0.0) -> Polygon:
    """A slider block centred ``lift`` mm off ``centre`` across ``along``; return its outline."""
    ux, uy = unit(along)
    nx, ny = -uy, ux
    cx, cy = centre[0] + lift * nx, centre[1] + lift * ny
    l2, h2 = length / 2, height / 2
    corners = tuple((cx + sx * l2 * ux + sy * h2 * nx, cy + sx * l2 * uy + sy * h2 * ny)
                    for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1)))
    fig.add(Path(corners, "block", closed=True))
    return Polygon(corners)


def draw_arrowhead(fig: Figure, tip: tuple[float, float], direction: tuple[float, float],
                   length: float = 2.6, width: float = 1.5, style: str = "arrowhead") -> None:
    """A filled, slightly barbed arrowhead with its point at ``tip``."""
    ux, uy = unit(direction)
    nx, ny = -uy, ux
    bx, by = tip[0] - length * ux, tip[1] - length * uy
    notch = (tip[0] - 0.75 * length * ux, tip[1] - 0.75 * length * uy)
    pts = (tip, (bx + width / 2 * nx, by + width / 2 * ny), notch,
           (bx - width / 2 * nx, by - width / 2 * ny))
    fig.add(Path(pts, style, closed=True))


def draw_turning_arrow(fig: Figure, centre: tuple[float, float], radius: float,
                       start: float, sweep: float, style: str = "arrow") -> tuple[float, float]:
    """An arc arrow about ``centre`` from paper angle ``start`` through ``sweep`` (rad, CCW +).

    Returns the arc's midpoint, where its label goes.
    """
    end = start + sweep
    fig.arc(centre, radius, start, end - math.copysign(0.6 / radius, sweep), style)
    tip = (centre[0] + radius * math.cos(end), centre[1] - radius * math.sin(end))
    # Tangent direction on paper (y down) for increasing angle, signed by sweep.
    s = 1.0 if sweep > 0 else -1.0
    tangent = (-math.sin(end) * s, -math.cos(end) * s)
    draw_arrowhead(fig, tip, tangent, length=2.3, width=1.4)
    mid = start + sweep / 2
    return (centre[0] + radius * math.cos(mid), centre[1] - radius * math.sin(mid))


def mark_angle(fig: Figure, centre: tuple[float, float], radius: float, start: float,
               end: float) -> tuple[float, float]:
    """Mark an angle with a thin arc from ``start`` to ``end`` (paper angles, rad); return its
    midpoint."""
    fig.arc(centre, radius, start, end, "dimension")
    mid = (start + end) / 2
    return (centre[0] + radius * math.cos(mid), centre[1] - radius * math.sin(mid))


def draw_dimension(fig: Figure, a: tuple[float, float], b: tuple[float, float],
                   side: tuple[float, float], offset: float = 7.0) -> tuple[float, float]:
    """A dimension line for the distance ``ab``: extension lines out to the ``side`` (a unit
    paper vector across ``ab``), the line ``offset`` mm out with a head at each end.

    Returns the line's midpoint, where its reading goes.
    """
    nx, ny = side
    p, q = ((x + offset * nx, y + offset * ny) for x, y in (a, b))
    for (x, y), (ex, ey) in ((a, p), (b, q)):
        fig.line((x + 1.2 * nx, y + 1.2 * ny), (ex + 1.6 * nx, ey + 1.6 * ny), "dimension")
    mid = ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)
    draw_arrow(fig, mid, q, "dimension", head=2.4, width=1.2)
    draw_arrow(fig, mid, p, "dimension", head=2.4, width=1.2)
    return mid


def draw_arrow(fig: Figure, tail: tuple[float, float], tip: tuple[float, float],
               style: str = "arrow", head: float = 2.6, width: float = 1.5) -> None:
    """A straight arrow: a shaft from ``tail`` stopping inside a filled head at ``tip``.

    The shaft ends in the head's notch, so a thick shaft never shows past the point.
    """
    d = (tip[0] - tail[0], tip[1] - tail[1])
    n = math.hypot(*d)
    if n == 0.0:
        return
    ux, uy = d[0] / n, d[1] / n
    stop = min(0.7 * head, n)
    fig.line(tail, (tip[0] - stop * ux, tip[1] - stop * uy), style)
    draw_arrowhead(fig, tip, (ux, uy), length=min(head, n), width=width)


def badge_radius(number: int) -> float:
    """Radius (mm) of the circle round a step number."""
    return 1.55 if number < 10 else 1.85


def draw_badge(fig: Figure, at: tuple[float, float], number: int) -> None:
    """A step number in a small circle, as a worked construction numbers its acts; none
    where the badges are hidden (:mod:`.hiding`), the labels standing where they stood."""
    if "badges" in hidden():
        return
    fig.add(Circle(at, badge_radius(number), "badge"))
    fig.add(Text(at, str(number), 2.1 if number < 10 else 1.95, italic=False))
