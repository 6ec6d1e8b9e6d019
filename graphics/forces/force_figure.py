"""The force polygons as a textbook prints them: each link's polygon in a panel of its own at
a force scale that fits it, stated on the panel; each load an arrow head to tail, the two
lines that close a polygon crossing at x, and a polygon closed by its last side drawn heavy
(the frame's force on the crank, the crank's on a block); under them a key to every name.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence

from tarsim.constructions import geometry as g
from tarsim.constructions.narration import words
from tarsim.constructions.record import Construction, Panel, Role
from tarsim.constructions.scales import nice
from ..figure import Circle, Figure, Path, Text, shelve
from ..labels import LabelPlacer
from ..scales import draw_caption, nice_per_cm, scale_text
from ..symbols import draw_arrow
from .force_key import draw_key

__all__ = ["draw_force_figure", "in_lane", "runs_along", "typeset_force"]

_PANEL = (150.0, 110.0)
"""The most paper (mm) one polygon takes, across and up: two stand side by side on a
landscape sheet."""

_LONGEST = 40.0
"""Paper (mm) a polygon's longest side is drawn at least where its panel allows: a side of
a few millimetres shows neither its direction nor its length."""

_ROW = 240.0
"""The widest a row of polygons runs (mm) before the next row starts."""

_GAP = 14.0
"""Paper (mm) between two polygons' panels, and between rows."""


def draw_force_figure(c: Construction, scale: float, title: str,
                      notes: Sequence[str] = ()) -> Figure:
    """The FORCE panel of ``c`` (drawn at ``scale`` drawing metres per newton), each link's
    polygon in a panel of its own at a force scale that fits it, stated on the panel: one
    scale for all would draw a block's few newtons as a dot beside a lever's hundreds."""
    steps = [s for s in c if s.panel is Panel.FORCE]
    panels = [_draw_polygon(c, mark, group, scale) for mark, group in _polygons(steps)]
    fig = shelve([p for p in panels if p is not None], _ROW, _GAP, title)
    draw_caption(fig, title, [words("each link's loads head to tail; a polygon closed by two "
                                    "lines crossing at x, or by its heavy closing side")],
                 per_cm=None, unit="N", legend=(("vector", "a force"),
                                                ("vector_result", "a closing side"),
                                                ("construction", "a line of known "
                                                                 "direction")),
                 notes=notes)
    draw_key(fig, [t for t in fig.items if isinstance(t, Text)
                   and (t.owner or t.text.startswith("= "))])    # names, and second names
    return fig


def _polygons(steps) -> list:
    """The FORCE steps in polygons, each (its titled mark, its steps): a polygon runs from
    the mark naming its links to the next such mark."""
    out: list = []
    for s in steps:
        if s.verb == "mark" and s.label:
            out.append((s, []))
        elif out:
            out[-1][1].append(s)
    return out


def polygon_scale(longest: float, across: float, up: float) -> float:
    """The force scale (N a paper cm, 1, 2 or 5 × 10^k) of a polygon whose longest side is
    ``longest`` newtons and which spans ``across`` by ``up``: its longest side
    :data:`_LONGEST` mm at least, unless the polygon would then outgrow :data:`_PANEL`.

    >>> polygon_scale(0.98, 0.98, 0.98), polygon_scale(45.0, 20.0, 45.0)
    (0.2, 10.0)
    """
    per_cm = nice(longest * 10.0 / _LONGEST, up=False)
    return max(per_cm, nice_per_cm(across, _PANEL[0]), nice_per_cm(up, _PANEL[1]))


def polygon_fit(joins, scale: float) -> tuple[list[float], list[float], float]:
    """A force polygon's sides' ends (drawing m, across and up) and the 1-2-5 force scale
    (N a paper cm) that fits it (:func:`polygon_scale`): the panel draws it so, and the
    problem sheet sizes its empty frame to the same."""
    ends = [p for s in joins for p in (s.output.start.xy, s.output.end.xy)]
    xs, ys = [x for x, _ in ends], [y for _, y in ends]
    longest = max(math.dist(s.output.start.xy, s.output.end.xy) for s in joins) / scale
    per_cm = polygon_scale(max(longest, 1e-300), max(max(xs) - min(xs), 1e-300) / scale,
                           max(max(ys) - min(ys), 1e-300) / scale)
    return xs, ys, per_cm


def _draw_polygon(c: Construction, mark, group, scale: float) -> Figure | None:
    """One polygon at a scale of its own, its title and scale over it; None if it draws
    nothing."""
    joins = [s for s in group if s.verb == "join"]
    if not joins:
        return None
    xs, ys, per_cm = polygon_fit(joins, scale)
    k = 10.0 / (per_cm * scale)                                          # paper mm a drawing m
    left, top = min(xs), max(ys)

    def paper(xy) -> tuple[float, float]:
        return (xy[0] - left) * k, (top - xy[1]) * k

    fig = Figure(0.0, 0.0)
    with fig.for_steps(mark.id):
        _draw_sides(fig, c, group, paper)
        origin = paper(c.output(mark.inputs[0]).xy)
        x0, y0, _, _ = fig.bounds()
        fig.add(Text((min(x0, origin[0]), y0 - 10.0), _polygon_title(mark.label), 3.0,
                     "start", False, "bold"))
        fig.add(Text((min(x0, origin[0]), y0 - 5.0),
                     f"{words('Force scale')} {scale_text(per_cm, 'N')}", 2.8, "start", False))
    return fig


def _draw_sides(fig: Figure, c: Construction, group, paper) -> None:
    """A polygon's forces head to tail, the lines that close it and where they cross, each
    force named beside its own shaft."""
    # Each closing line runs from the tip it is drawn through to a little past the crossing
    # it makes, not across the whole sheet.
    crossings = [paper(s.output.xy) for s in group if s.verb == "intersect_lines"]
    for s in group:
        if s.verb == "parallel_through" and isinstance(s.output, g.Line) and crossings:
            start = paper(c.output(s.inputs[0]).xy)
            cross = min(crossings, key=lambda x: math.dist(x, start))
            d = (cross[0] - start[0], cross[1] - start[1])
            n = math.hypot(*d)
            if n < 1e-9:
                continue
            u = (d[0] / n, d[1] / n)
            fig.add(Path(((start[0] - 5.0 * u[0], start[1] - 5.0 * u[1]),
                          (cross[0] + 5.0 * u[0], cross[1] + 5.0 * u[1])), "construction"))
    named, drawn = [], []
    for s in group:
        if s.verb != "join":
            continue
        a, b = paper(s.output.start.xy), paper(s.output.end.xy)
        if math.dist(a, b) < 0.3:
            continue
        twin = next((k for k, (p, q, _) in enumerate(named)
                     if math.dist(p, a) < _SAME and math.dist(q, b) < _SAME), None)
        if twin is not None and s.label:
            # The same arrow to the pen's precision (F_T when F_32 is all crank effort):
            # drawn once and named "F_32 = F_T".
            p, q, labels = named[twin]
            named[twin] = (p, q, labels + (s.label,))
            continue
        a, b = in_lane(a, b, drawn)
        drawn.append((a, b))
        draw_arrow(fig, a, b, "vector_result" if s.role is Role.RESULT else "vector")
        if s.label and math.dist(a, b) > 1.5:      # a shorter one is named in the steps
            named.append((a, b, (s.label,)))
    crosses = [(paper(s.output.xy), s.label or "x") for s in group
               if s.verb == "intersect_lines"]
    for at, _ in crosses:
        fig.add(Circle(at, 0.7, "dot"))
    _name_forces(fig, named, crosses)


def _polygon_title(label: str) -> str:
    """A polygon's name ("link 2", "links 3, 4") in the language being spoken; a link's
    number is its name in every language."""
    one = re.fullmatch(r"link (\S+)", label)
    if one:
        return words("link {link}", link=one[1])
    two = re.fullmatch(r"links (\S+), (\S+)", label)
    if two:
        return words("links {i}, {j}", i=two[1], j=two[2])
    return label


_SAME = 0.8
"""Paper (mm) within which two arrows' ends coincide: one arrow, two names."""

_LANE = 2.0
"""Paper (mm) an arrow is moved aside when it would run along one drawn before it."""


def in_lane(a, b, drawn) -> tuple[tuple[float, float], tuple[float, float]]:
    """The arrow ``a`` → ``b``, moved :data:`_LANE` to its left (further, if need be) while
    its shaft would lie along one of the ``drawn`` segments for more than a millimetre, as
    two equal and opposite forces or a force and its own part are drawn in textbooks."""
    n = math.dist(a, b)
    if n == 0.0:
        return a, b
    u = ((b[0] - a[0]) / n, (b[1] - a[1]) / n)
    left = (u[1], -u[0])
    for _ in range(4):
        if not any(runs_along(a, b, p, q) for p, q in drawn):
            break
        a = (a[0] + _LANE * left[0], a[1] + _LANE * left[1])
        b = (b[0] + _LANE * left[0], b[1] + _LANE * left[1])
    return a, b


def runs_along(a, b, p, q, within: float = 0.8) -> bool:
    """Whether the arrow a–b lies on segment p–q (both its ends within ``within`` mm of the
    segment's line) for more than a millimetre of it: drawn there, it would hide."""
    n = math.dist(p, q)
    if n == 0.0:
        return False
    u = ((q[0] - p[0]) / n, (q[1] - p[1]) / n)
    off = [(x[0] - p[0]) * u[1] - (x[1] - p[1]) * u[0] for x in (a, b)]
    if max(abs(o) for o in off) > within:
        return False
    t = sorted((x[0] - p[0]) * u[0] + (x[1] - p[1]) * u[1] for x in (a, b))
    return min(t[1], n) - max(t[0], 0.0) > 1.0


def _name_forces(fig: Figure, named, crosses) -> None:
    """Name each force beside its own shaft, the shortest first (they have least room), and
    each crossing by its letter, every name clear of every line, head and other name."""
    placer = LabelPlacer(fig)
    placer.block_drawn()
    placer.name_vectors((a, b) for a, b, _ in named)
    placer.name_points([at for at, _ in crosses])
    for a, b, label in sorted(named, key=lambda v: math.dist(v[0], v[1])):
        n = math.dist(a, b)
        normal = math.atan2((b[0] - a[0]) / n, (b[1] - a[1]) / n)   # square to it, on paper
        anchors = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])) for t in _ALONG]
        text, sub, tail = typeset_force(label[0])
        also = tuple(typeset_force(more)[:2] for more in label[1:])
        # Beside an arrow in the next lane, a name stands on the far side from it.
        partner = next((p for p, q, _ in named if (p, q) != (a, b)
                        and runs_along(a, b, p, q, within=_LANE * 1.5)), None)
        sides = (normal, normal + math.pi)
        if partner is not None:
            away = (a[0] - partner[0]) * math.cos(normal) - (a[1] - partner[1]) * \
                math.sin(normal)
            sides = (normal,) if away > 0 else (normal + math.pi,)
        placer.place_numbered(text, anchors, [], sub=sub, tail=tail, size=2.8, gap=1.0,
                              prefer=sides, spread=math.pi / 3, own=(a, b), also=also)
    for at, letter in crosses:
        placer.place(letter, at, size=3.0, prefer=-math.pi / 4, own=at)


_ALONG = (0.5, 0.35, 0.65, 0.2, 0.8)
"""Where along its shaft a force's name is tried, the middle first."""


def typeset_force(name: str) -> tuple[str, str, str]:
    """A force's or a moment's name as printed, (letter, subscript, what follows on the
    baseline): F_23ᵗ is F with 23 below and ᵗ after, T_43 T with 43 below, Fi3 F with i3
    below (Mi3 the same for its couple), W3, P5 and T2 a letter with digits below, and a
    trailing prime follows; other names ("gas force") are set as they are, in the language
    being spoken if it has words for them (a name of the user's own stays as written).

    >>> typeset_force("F_23ᵗ"), typeset_force("Fi3′"), typeset_force("gas force")
    (('F', '23', 'ᵗ'), ('F', 'i3', '′'), ('gas force', '', ''))
    """
    tail = name[-1] if name[-1:] in ("ᵗ", "ⁿ", "′") else ""
    body = name[:len(name) - len(tail)]
    if body[:2] in ("F_", "T_"):
        return body[0], body[2:], tail
    if body[:3] == "Mf_":                   # a pin's friction couple, of 2 on 3: M with f23
        return "M", "f" + body[3:], tail
    if body[:2] in ("Fi", "Mi") and body[2:].isdigit():
        return body[0], body[1:], tail
    if body[:1] in "WPT" and body[1:].isdigit():
        return body[0], body[1:], tail
    return words(body) + tail, "", ""
