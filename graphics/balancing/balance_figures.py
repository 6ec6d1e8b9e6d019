"""Balancing figures as 001 ch. 7 draws them: the space diagram (end view and side view)
and the vector polygons, each closed by its balancing (or unbalanced) side.

A polygon's vectors are drawn head to tail, each an arrow with its mass's name at its
middle; the closing side runs heavy from the last tip back to the start, with its size
and angle. The end view draws each mass on its radial line at its radius; the side view
the shaft, each mass's plane and the balancing planes, with their axial positions.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace

from tarsim.constructions.narration import numerals, right_to_left, unit_words, words
from tarsim.constructions.record import Construction, Ref
from ..figure import Circle, Figure, Path, Text, clear_of, text_width
from ..drafts import label_placer
from ..fitting import to_sheet
from ..labels import LabelPlacer, paper_angle
from ..linkages.lanes import lanes, moved
from ..scales import draw_caption, nice_per_cm
from ..symbols import draw_arrow
from .crank_view import CrankView, draw_crank_view

__all__ = ["draw_polygon", "draw_end_view", "draw_side_view"]

_ROOM = 120.0     # paper (mm) the polygon's or view's extent is fitted to
_REFERENCE_PAST = 8.0   # mm the 0° radius runs past a mass's circle that lies along it
_MASS = 1.6       # radius (mm) of a mass's circle in the end view
_LANE = 6.0       # mm between vectors on one line drawn side by side: room for a name
                  # between two lanes, nearer its own arrow than the next
_LEADING = 4.2    # mm between the two lines of a closing side's size broken after its comma


def draw_polygon(c: Construction, tips: Sequence[tuple[str, Ref]], closing: Ref, title: str,
                 unit: str, reading: tuple[str, str, str], notes: Sequence[str] = (),
                 names: dict[str, str] | None = None, clockwise: bool = False,
                 per: float = 1.0, cranks: CrankView | None = None,
                 per_cm: float | None = None) -> Figure:
    """The polygon whose tips are ``tips`` in order from its pole, closed by ``closing``;
    its sizes in ``unit``, ``per`` of it to the construction's unit, the closing side read
    as ``reading`` (text, subscript, and the words after it: "(m r)", "A", " = 1.39 kg·m
    at 3.9°"); with ``clockwise`` its angles are drawn clockwise (the construction's
    mirror image). An engine's m·r is drawn to the newtons its reading is given in, ``per``
    = ω², at a round scale of newtons; ``cranks``, the end view of its cranks that its
    vectors are laid along, is set beside it (:func:`.crank_view.draw_crank_view`).

    Vectors on one line that would cover one another (a polygon folded flat, or closing
    over its own sides) are drawn side by side in lanes, as the linkage polygons draw
    them, each true in length and direction with a leader back to its points. It is drawn
    at ``per_cm``, by default the nice scale that fits its room, fitted to the sheet it is
    drawn on.
    """
    given = dict(locals())          # every argument, to draw it again at another scale
    names = names or {}
    start = c[closing].inputs[1]
    points = [c.output(start).xy] + [c.output(r).xy for _, r in tips]
    xs, ys = [x for x, _ in points], [y for _, y in points]
    extent = max(max(xs) - min(xs), max(ys) - min(ys), 1e-12)
    if per_cm is None:
        return to_sheet(lambda at: draw_polygon(**{**given, "per_cm": at}),
                        nice_per_cm(extent * per, _ROOM))
    k = 10.0 * per / per_cm

    up = 1.0 if clockwise else -1.0      # paper y runs down: counter-clockwise is −y

    def paper(xy) -> tuple[float, float]:
        return xy[0] * k, up * xy[1] * k

    fig = Figure(0.0, 0.0, title=title)
    centre = [paper(p) for p in points]          # the corners, to keep words outside
    pole = paper(points[0])
    fig.add(Circle(pole, 0.7, "dot"))
    sides = []                                   # (name, tail, tip, the side out)
    prev = pole
    for turn, ((name, _), xy) in enumerate(zip(tips, points[1:])):
        tip = paper(xy)
        if math.dist(prev, tip) > 0.3:
            # a flat polygon retraces its own line: its names go above and below in turn
            sides.append((names.get(name, name), prev, tip,
                          _outward(prev, tip, centre, 1.0, up=turn % 2 == 0)))
        prev = tip
    closes = math.dist(prev, pole) > 0.3
    ends = [(a, b) for _, a, b, _ in sides] + ([(prev, pole)] if closes else [])
    drawn_in = lanes(ends, [False] * len(sides) + [True] * closes, step=_LANE, nested=False)
    names_at = []
    for i, ((name, a, b, side), lane) in enumerate(zip(sides, drawn_in)):
        if not lane:
            side = _clear_side(i, ends, drawn_in, side)
        tail, tip, side = _in_lane(fig, a, b, lane, side)
        draw_arrow(fig, tail, tip, "vector")
        names_at.append((name, tail, tip, side))
    if closes:
        tail, tip, closing_side = _in_lane(fig, prev, pole, drawn_in[-1],
                                           _outward(prev, pole, centre, 1.0, up=False))
        draw_arrow(fig, tail, tip, "vector_result")
    # Every name is set clear of the drawn polygon and of the names set before it, each
    # beside its own arrow: a flat polygon's arrows lie on one line, over one another.
    placer = label_placer(fig)   # drafting: as on a blank page
    placer.block_drawn()
    first, last = paper(points[1]), paper(points[-1])
    away = (2 * pole[0] - first[0] - last[0], 2 * pole[1] - first[1] - last[1])
    placer.place("o", pole, prefer=paper_angle(away), size=3.0, gap=1.6)
    for name, tail, tip, side in names_at:
        mid = ((tail[0] + tip[0]) / 2, (tail[1] + tip[1]) / 2)
        placer.place(name, mid, prefer=paper_angle(side), spread=math.pi / 2, size=2.8,
                     italic=False, gap=1.2, rings=(1.0, 1.6, 2.4, 3.4, 4.6), own=(tail, tip))
    if closes:
        mid = ((tail[0] + tip[0]) / 2, (tail[1] + tip[1]) / 2)
        _place_reading(placer, mid, reading, closing_side)
    else:
        _place_reading(placer, pole, reading, (0.0, 1.0))       # under the names
    # A polygon that closes on itself has no closing side to point to.
    if cranks is not None:
        draw_crank_view(fig, cranks)
    said = words("head to tail, each parallel to its radial line; the heavy side closes it") \
        if closes else words("head to tail, each parallel to its radial line")
    legend = (("vector", "the vectors"),) + ((("vector_result", "the closing side"),)
                                            if closes else ())
    draw_caption(fig, title, [said], per_cm=per_cm, unit=unit, legend=legend, notes=notes)
    return fig


def _clear_side(i: int, ends, lanes: Sequence[int], side: tuple[float, float]):
    """The side for the name of arrow ``i``, left on its points: away from the arrows moved
    into lanes beside it (on its carrier and overlapping it), if they are all on one side."""
    (a, b) = ends[i]
    n = math.dist(a, b)
    u = ((b[0] - a[0]) / n, (b[1] - a[1]) / n)
    beside = set()
    for (p, q), lane in zip(ends, lanes):
        if not lane or any(abs((e[0] - a[0]) * u[1] - (e[1] - a[1]) * u[0]) > 0.05
                           for e in (p, q)):
            continue
        s, t = sorted(((e[0] - a[0]) * u[0] + (e[1] - a[1]) * u[1]) for e in (p, q))
        if min(t, n) - max(s, 0.0) > 0.5:
            v = ((q[0] - p[0]) / math.dist(p, q), (q[1] - p[1]) / math.dist(p, q))
            # moved lane·(−v_y, v_x): on the side of a's normal (−u_y, u_x) that v·u says
            beside.add(1 if (v[0] * u[0] + v[1] * u[1]) * _way(p, q, lane) > 0 else -1)
    if len(beside) != 1:
        return side
    away = -beside.pop()                  # in lanes of a's own normal's sign: the other way
    return (-u[1] * away, u[0] * away)


def _way(a: tuple[float, float], b: tuple[float, float], lane: int) -> int:
    """``lane`` as :func:`.lanes.moved` takes it for the arrow a → b: lanes are counted on
    one side of a carrier whichever way its arrows run (so that arrows running back along
    it, given lanes 1 and −1, stand on two sides of it, not one), its left as it runs
    rightwards on the paper (or down it)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    return lane if dx > 1e-9 or (abs(dx) <= 1e-9 and dy > 0) else -lane


def _in_lane(fig: Figure, a: tuple[float, float], b: tuple[float, float], lane: int,
             side: tuple[float, float]):
    """The arrow a → b moved into ``lane`` (:func:`.lanes.moved`), with a leader from each
    moved end back to its point; its tail, tip and the side its name goes (its lane's, away
    from the line, when it is moved)."""
    if not lane:
        return a, b, side
    tail, tip = moved((a, b), _way(a, b, lane), _LANE)
    for true, end in ((a, tail), (b, tip)):
        fig.add(Path((true, end), "leader"))
    n = math.dist(a, tail)
    return tail, tip, ((tail[0] - a[0]) / n, (tail[1] - a[1]) / n)


def _place_reading(placer: LabelPlacer, at: tuple[float, float],
                   reading: tuple[str, str, str], side: tuple[float, float]) -> None:
    """The closing side's size set clear of everything, beside ``at`` on ``side``: on one
    line, or broken after its comma where one line finds no clear spot (a long reading
    by a steep closing side crosses the vectors beside it)."""
    best = None
    for texts in _readings(reading):
        x0, y0, x1, y1 = _bounds(texts)
        c, cost = placer.spot(x1 - x0, y1 - y0, at, prefer=paper_angle(side), gap=1.6,
                              rings=(1.0, 1.6, 2.3, 3.2, 4.5, 6.0, 8.5, 12.0, 17.0))
        if best is None or cost < best[0] - 1e-9:
            best = cost, c, texts, (x0, y0, x1, y1)
        if cost <= 1e-9:
            break
    _, (cx, cy), texts, (x0, y0, x1, y1) = best
    dx, dy = cx - (x0 + x1) / 2, cy - (y0 + y1) / 2
    for t in texts:
        placer.fig.add(replace(t, at=(t.at[0] + dx, t.at[1] + dy)))
    placer.block_label((x0 + dx, y0 + dy, x1 + dx, y1 + dy))


def _readings(reading: tuple[str, str, str]) -> list[list[Text]]:
    """The closing side's size as one line, then, where its words have a comma, as two
    lines broken after it, each centred."""
    out = [_reading((0.0, 0.0), reading)]
    text, sub, tail = reading
    head, comma, rest = next(((text[:k], text[k], text[k + 1:]) for k, ch in enumerate(text)
                              if ch in ",،"), ("", "", ""))
    if comma and not sub and not tail:
        lines = (head + comma, rest.strip())
        out.append([Text((0.0, (k - 0.5) * _LEADING), line, 3.0, "middle", False, "normal")
                    for k, line in enumerate(lines)])
    return out


def _bounds(texts: Sequence[Text]) -> tuple[float, float, float, float]:
    """The box that holds all of ``texts``."""
    boxes = [t.box() for t in texts]
    return (min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes),
            max(b[3] for b in boxes))


def _reading(at: tuple[float, float], reading: tuple[str, str, str]) -> list[Text]:
    """The closing side's size, centred on ``at``: its symbol (text and subscript) and the
    words after it.

    Right-to-left words after a symbol are set as two runs, the symbol at the right and
    the words to its left, so the symbol reads first and keeps its brackets whole. (The
    shared runs, :func:`~.rtl_runs.lay_runs`, would set "(m r)_A = ۰٫۳" apart as a formula,
    its unit on the far side of the symbol; here the size reads on into its unit.)
    """
    text, sub, tail = reading
    if not (right_to_left() and sub and tail):
        return [Text(at, text, 3.0, "middle", False, "normal", sub, tail)]
    symbol = Text((0.0, 0.0), text, 3.0, "start", False, "normal", sub)
    words_after = tail.strip()
    gap = 1.5 * text_width(" ", 3.0)
    width = symbol.width + gap + text_width(words_after, 3.0)
    left = at[0] - width / 2
    return [Text((left + width - symbol.width, at[1]), text, 3.0, "start", False, "normal",
                 sub),
            Text((left, at[1]), words_after, 3.0, "start", False)]


def _outward(a, b, corners, by: float, *, up: bool) -> tuple[float, float]:
    """A step of ``by`` square to the side a → b of the closed polygon through ``corners``,
    out of it: the polygon's turning (its signed area) says which side is out; a flat
    polygon's words go up or down, as asked."""
    d = (b[0] - a[0], b[1] - a[1])
    n = math.hypot(*d)
    side = (d[1] / n, -d[0] / n)
    ring = list(corners) + [corners[0]]
    area = sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(ring, ring[1:])) / 2
    scale = max(abs(v) for p in corners for v in p) or 1.0
    if abs(area) < 1e-9 * scale * scale:
        sign = -1.0 if (side[1] > 0) == up else 1.0        # paper y runs down: up is −y
    else:
        sign = 1.0 if area > 0 else -1.0
    return (sign * side[0] * by, sign * side[1] * by)


def draw_end_view(c: Construction, masses: Sequence[tuple[str, float, str]], title: str,
                  unit: str, metre: float, found: Sequence[tuple[str, float, float]] = (),
                  notes: Sequence[str] = (), found_word: str = "a balancing mass found",
                  clockwise: bool = False, per_cm: float | None = None) -> Figure:
    """The end view: the shaft's centre O and each mass (step ``P<name>``) on its radial
    line; ``masses`` gives each (name, radius in m, its label), ``found`` each balancing
    mass (label, angle in rad, radius in m), drawn dashed; with ``clockwise`` the angles
    run clockwise (the construction's mirror image). At ``per_cm``, by default the scale
    that fits its room, fitted to the sheet it is drawn on."""
    up = 1.0 if clockwise else -1.0      # paper y runs down: counter-clockwise is −y
    reach = max([r for _, r, _ in masses] + [r for _, _, r in found]) or 1.0
    if per_cm is None:
        return to_sheet(lambda at: draw_end_view(c, masses, title, unit, metre, found, notes,
                                                 found_word, clockwise, at),
                        nice_per_cm(2.4 * reach / metre, _ROOM * 0.8))
    k = 10.0 / (per_cm * metre)
    fig = Figure(0.0, 0.0, title=title)
    fig.add(Circle((0.0, 0.0), 0.9, "dot"))
    # "O" in the widest gap between the radial lines (the 0° one among them).
    radii = _radii(c, masses, found)
    rays = sorted({0.0} | {a % (2 * math.pi) for _, a in radii})
    # One ray alone (every mass on the reference radius) leaves the whole turn.
    gaps = [((rays[(i + 1) % len(rays)] - a) % (2 * math.pi) if len(rays) > 1 else 2 * math.pi,
             a) for i, a in enumerate(rays)]
    width, at = max(gaps)
    mid = at + width / 2
    fig.add(Text((4.2 * math.cos(mid), up * 4.2 * math.sin(mid) + 1.0), "O", 3.0, "middle",
                 True))
    # The 0° radius, short; where a mass lies along it, run on past that mass's circle so
    # it shows, and kept clear of the names.
    on_it = [r * k for r, a in radii if abs(math.remainder(a, 2 * math.pi)) < math.radians(2.0)]
    length = max(on_it) + _MASS + _REFERENCE_PAST if on_it else reach * k * 0.35
    fig.add(Path(((0.0, 0.0), (length, 0.0)), "reference"))
    taken: list = [(max(on_it) + _MASS, -0.6, length, 0.6)] if on_it else []
    for name, _, label in masses:
        x, y = c.output(f"P{name}").xy
        at = (x * k, up * y * k)
        fig.add(Path(((0.0, 0.0), at), "link"))
        fig.add(Circle(at, _MASS, "pin"))
        d = math.hypot(*at) or 1.0
        out = (at[0] / d, at[1] / d)
        fig.add(clear_of(Text((at[0] + 4.5 * out[0], at[1] + 4.5 * out[1] + 1.0), label,
                              2.8, "start" if out[0] > 0.2 else "end" if out[0] < -0.2
                              else "middle", False), taken, keep=True,
                         step=(1.5 * out[0], 1.5 * out[1] or 1.5)))
    for label, angle, radius in found:
        at = (radius * k * math.cos(angle), up * radius * k * math.sin(angle))
        fig.add(Path(((0.0, 0.0), at), "normal"))
        fig.add(Circle(at, _MASS, "badge"))
        out = (math.cos(angle), up * math.sin(angle))
        fig.add(clear_of(Text((at[0] + 4.5 * out[0], at[1] + 4.5 * out[1] + 1.0), label,
                              2.8, "start" if out[0] > 0.2 else "end" if out[0] < -0.2
                              else "middle", False), taken, keep=True,
                         step=(1.5 * out[0], 1.5 * out[1] or 1.5)))
    draw_caption(fig, title, [words("end view: each mass on its radial line, angles from the "
                                    "reference radius (the short dashed one), "
                                    "clockwise") if clockwise else
                              words("end view: each mass on its radial line, angles from the "
                                    "reference radius (the short dashed one), "
                                    "counter-clockwise")],
                 per_cm=per_cm, unit=unit, notes=notes,
                 legend=(("link", "a mass"),) + ((("normal", found_word),)
                                                 if found else ()))
    return fig


def _radii(c: Construction, masses, found) -> list[tuple[float, float]]:
    """Each mass's and balancing mass's radius (m) and angle (rad) in the end view."""
    out = []
    for name, _, _ in masses:
        x, y = c.output(f"P{name}").xy
        out.append((math.hypot(x, y), math.atan2(y, x)))
    return out + [(radius, angle) for _, angle, radius in found]


def draw_side_view(planes: Sequence[tuple[str, float, str]], title: str, unit: str,
                   metre: float, found: str = "a balancing plane",
                   per_cm: float | None = None) -> Figure:
    """The side view: the shaft and each plane at its axial position; ``planes`` gives
    each (label, position in m, style: "link" for a mass's plane, "normal" for a
    balancing plane, or the plane found, as the legend's ``found`` names it). At
    ``per_cm``, by default the scale that fits its room, fitted to the sheet it is drawn
    on."""
    xs = [p for _, p, _ in planes]
    lo, hi = min(xs), max(xs)
    span = hi - lo or 1.0
    if per_cm is None:
        return to_sheet(lambda at: draw_side_view(planes, title, unit, metre, found, at),
                        nice_per_cm(span / metre, _ROOM))
    k = 10.0 / (per_cm * metre)
    fig = Figure(0.0, 0.0, title=title)
    fig.add(Path(((lo * k - 8.0, 0.0), (hi * k + 8.0, 0.0)), "link"))
    for i, (label, x, style) in enumerate(sorted(planes, key=lambda p: p[1])):
        fig.add(Path(((x * k, -12.0), (x * k, 12.0)), style))
        fig.add(Text((x * k, -15.0 - 4.0 * (i % 2)), label, 2.8, "middle", False))
        fig.add(Text((x * k, 16.5 + 4.0 * (i % 2)), numerals(f"{x / metre:g}"), 2.6, "middle",
                     False))
    draw_caption(fig, title, [words("side view: the planes along the shaft, positions in {unit}",
                                    unit=unit_words(unit))],
                 per_cm=per_cm, unit=unit,
                 legend=(("link", "a mass's plane"),) + ((("normal", found),) if any(
                     style != "link" for _, _, style in planes) else ()))
    return fig
