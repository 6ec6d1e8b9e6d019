"""The circle diagram: the bookkeeping of Kennedy's theorem as the lecture notes draw it.

The n links are n equally spaced, numbered points on a circle (link 1 at the top,
the rest clockwise); each instant centre is the chord joining its two links.
Centres known by inspection are solid chords; those found by Kennedy's theorem
are dashed and carry their number in the order of discovery (000-part1 §2.9).
Drawn up to a given discovery, the last centre found is heavier and its two
triangles are shaded, as the notes show the step being taken.
"""

from __future__ import annotations

import math

from shapely.geometry import LineString
from shapely.geometry import Point as SPoint

from tarsim.constructions.linkages.centres import Centre
from tarsim.constructions.narration import Number, words
from tarsim.constructions.record import Kind, Slice

from ..figure import Circle, Figure, Path, Text, text_width
from ..rtl import reading
from ..labels import LabelPlacer
from ..symbols import badge_radius, draw_badge
from ..typeset import typeset

__all__ = ["draw_circle_diagram", "triangle_text", "secondary_text"]

_R = 30.0           # the circle's radius, mm
_NODE = 0.95        # a link's point, mm
_NUMBER_OUT = 4.6   # link numbers stand this far outside the circle, mm
_MARGIN = 8.0


def triangle_text(centre: Centre) -> list[str]:
    """The triangles a centre was found from, as the notes write them: ``Δ123``.

    The triangle of pair (i, j) with third link k is written Δ i k j; a line that
    was a common normal at a slot or contact, not a triangle, is "common normal".
    """
    i, j = centre.pair
    return [words("common normal") if k is None else f"Δ{i}{k}{j}" for k in centre.triangles]


def secondary_text(centre: Centre) -> str:
    """One line of the discovery list: ``1. I13: Δ123, Δ143``."""
    return f"{centre.order}. {typeset(centre.label)[0]}: {', '.join(triangle_text(centre))}"


def draw_circle_diagram(shown: Slice, *, title: str, upto: int | None = None,
                        radius: float = _R) -> Figure:
    """Draw the circle diagram of the instant centres a slice of the record holds.

    Parameters
    ----------
    shown
        A slice holding every centre of the mechanism (the steps of kind
        ``CENTRE``, each about its :class:`~tarsim.constructions.linkages.centres.Centre`).
    title
        The mechanism's name, which heads the caption.
    upto
        Draw the diagram as it stands once this many centres have been found by
        Kennedy's theorem, the last of them with its two triangles shaded; all of
        them when None.
    radius
        The circle's radius (mm): the diagram has no scale, so it is drawn as big as its
        sheet suits.
    """
    centres = [s.about for s in shown if s.kind is Kind.CENTRE and isinstance(s.about, Centre)]
    links = sorted({k for c in centres for k in c.pair})
    n = len(links)
    primaries = [c for c in centres if c.primary]
    secondaries = sorted((c for c in centres if not c.primary), key=lambda c: c.order)
    found = [c for c in secondaries if upto is None or c.order <= upto]
    current = found[-1] if upto is not None and found else None
    fig = Figure(0.0, 0.0, title=f"{title}: circle diagram")
    node = {k: _node_at(i, n, radius) for i, k in enumerate(links)}

    # Node circle, then the shaded triangles of the centre being found, then chords.
    fig.add(Circle((0.0, 0.0), radius, "node_circle"))
    if current is not None:
        i, j = current.pair
        for shade, k in enumerate(current.triangles):
            if k is not None:
                fig.add(Path((node[i], node[k], node[j]), ("triangle", "triangle_alt")[shade % 2],
                             closed=True))
    chords: list[tuple[Centre, LineString]] = []
    for c in [*primaries, *found]:
        a, b = node[c.pair[0]], node[c.pair[1]]
        style = ("chord" if c.primary else
                 "chord_current" if c is current else "chord_secondary")
        fig.add(Path((a, b), style))
        chords.append((c, LineString([a, b])))
    for k, at in node.items():
        fig.add(Circle(at, _NODE, "dot"))
        ux, uy = at[0] / radius, at[1] / radius
        fig.add(Text((at[0] + _NUMBER_OUT * ux, at[1] + _NUMBER_OUT * uy), str(k), 3.8,
                     italic=False))
    _number_chords(fig, chords, node)
    _caption(fig, title, len(primaries), found, n, upto)
    return fig


def _node_at(index: int, n: int, radius: float = _R) -> tuple[float, float]:
    """Paper position of the index-th link's point: the first at the top, then clockwise."""
    a = math.pi / 2 - 2 * math.pi * index / n
    return (radius * math.cos(a), -radius * math.sin(a))


def _number_chords(fig: Figure, chords, node) -> None:
    """Put each dashed chord's discovery number on it, clear of the chords that cross it."""
    placer = LabelPlacer(fig)
    for at in node.values():
        placer.block(SPoint(at).buffer(_NODE + 3.0))
    for c, seg in chords:
        placer.block(seg.buffer(0.3), key=c.pair)
    for c, seg in chords:
        if c.primary:
            continue
        r = badge_radius(c.order)
        # From the middle outwards along the chord, in steps of about a badge's width.
        steps = max(2, int(0.3 * seg.length / (2 * r)))
        ts = sorted((0.5 + 0.4 * k / steps for k in range(-steps, steps + 1)),
                    key=lambda t: abs(t - 0.5))
        spots = [seg.interpolate(t, normalized=True) for t in ts]
        p = spots[placer.clearest([q.buffer(r + 0.35) for q in spots], ignore=c.pair)]
        draw_badge(fig, (p.x, p.y), c.order)
        placer.block(p.buffer(r + 0.2))


def _caption(fig: Figure, head: str, primaries: int, found: list[Centre], n: int,
             upto: int | None) -> None:
    x0, y0, x1, y1 = fig.bounds()
    total = n * (n - 1) // 2
    kennedy = total - primaries
    count = words("n = {n} links, N = n(n−1)/2 = {total} centres: {primaries} by inspection, "
                  "{kennedy} by Kennedy", n=Number(n, "d"), total=Number(total, "d"),
                  primaries=Number(primaries, "d"), kennedy=Number(kennedy, "d"))
    items = [secondary_text(c) for c in found]
    intro = (words("Found by Kennedy, in order (dashed chords):") if upto is None else
             words("Found by Kennedy, the first {found} of {kennedy}:",
                   found=Number(len(found), "d"), kennedy=Number(kennedy, "d")))
    col = max([text_width(t, 3.0) for t in items], default=0.0) + 6.0
    width = max(x1 - x0 + 2 * _MARGIN, text_width(head, 3.6) + 2 * _MARGIN,
                text_width(count, 3.2) + 2 * _MARGIN, text_width(intro, 3.2) + 2 * _MARGIN)
    cols = max(1, min(len(items), int((width - 2 * _MARGIN) // col))) if items else 1
    width = max(width, cols * col + 2 * _MARGIN)
    fig.shift(_MARGIN - x0 + (width - (x1 - x0) - 2 * _MARGIN) / 2, _MARGIN - y0)
    y = y1 - y0 + 2 * _MARGIN + 2.0
    # A right-to-left caption reads from the right margin, its columns from the right.
    reads = reading(width)
    edge, anchor, way = reads.x(_MARGIN), reads.anchor, reads.way
    fig.add(Text((edge, y), head, 3.6, anchor, italic=False, weight="bold"))
    y += 5.2
    fig.add(Text((edge, y), count, 3.2, anchor, italic=False))
    y += 5.2
    if items:
        fig.add(Text((edge, y), intro, 3.2, anchor, italic=False))
        y += 5.0
        rows = -(-len(items) // cols)
        for k, text in enumerate(items):
            r, c = k % rows, k // rows
            fig.add(Text((edge + way * c * col, y + r * 4.6), text, 3.0, anchor, italic=False))
        y += rows * 4.6
    fig.width = round(width, 1)
    fig.height = round(y + 2.0, 1)
