"""The follower's displacement diagram as a textbook draws it: the construction inked.

Cam angle runs across and lift up, both to scale, each scale stated (the cam angle's in
degrees a centimetre). The figure draws the base line with the cam angle every 30°, each
ordinate up to the curve, the working lines the construction inked (projections across,
the divided line and its parallels, the runs along the diagonal) and its arcs (the
semicircles, the cycloid's circles), the constructed points numbered, and the curve
through them (the law's, so it runs smooth between them).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from tarsim.constructions.cams.displacement import Displacement
from tarsim.constructions.narration import numerals, unit_words, words
from ..figure import Circle, Figure, Path, Text, arc_points
from ..drafts import label_placer
from ..fitting import to_sheet
from ..scales import draw_caption, nice_per_cm
from ..symbols import draw_dimension

__all__ = ["draw_displacement_figure"]

_ROOM = (165.0, 60.0)      # paper (mm) a turn and the greatest lift are fitted to
_UP_LEFT, _UP_RIGHT = 2.36, 0.79    # a point number's first way out (rad): up the page


def draw_displacement_figure(d: Displacement, curve: list[tuple[float, float]], title: str,
                             unit: str, metre: float, *, arm: float = 0.0,
                             asked: Sequence[tuple[float, float, str]] = (),
                             per_cm: float | None = None) -> Figure:
    """The diagram ``d`` with the smooth ``curve`` (cam angle in rad, lift in m) through its
    points; lengths stated in ``unit`` (``metre`` metres each). For a swinging ``arm`` the
    lift is the arc its end swings through, and the swing is stated in degrees too.
    ``asked`` are the points read at asked cam angles (rad, lift, label), each ringed and
    named."""
    c = d.construction
    top = max(y for _, y in curve) or 1.0
    width = 2 * math.pi * d.per_rad
    if per_cm is None:          # the scale that fits A4's room, fitted to the sheet
        return to_sheet(lambda at: draw_displacement_figure(
            d, curve, title, unit, metre, arm=arm, asked=asked, per_cm=at),
            max(nice_per_cm(width / metre, _ROOM[0]), nice_per_cm(top / metre, _ROOM[1])))
    k = 10.0 / (per_cm * metre)                    # paper mm per drawing metre

    def paper(xy) -> tuple[float, float]:
        return xy[0] * k, -xy[1] * k

    fig = Figure(0.0, 0.0, title=title)
    right = width * k
    fig.add(Path(((0.0, 0.0), (right, 0.0)), "link"))            # the base line
    # The tick labels go below any circle of the construction drawn about the base line.
    below = max([r for _, _, r in _circles(d, paper) if r > 0] + [0.0])
    for deg in range(0, 361, 30):
        x = math.radians(deg) * d.per_rad * k
        fig.add(Path(((x, 0.0), (x, 1.5)), "dimension"))
        fig.add(Text((x, max(4.5, below + 3.5)), numerals(f"{deg}°"), 2.8, "middle", False))
    for start, end in d.strokes:
        fig.add(Path((paper(c.output(start).xy), paper(c.output(end).xy)), "construction"))
    for (cx, cy), r, start, sweep in _arcs(d, paper):
        fig.add(Path(tuple(arc_points((cx, cy), r, start, sweep)), "construction"))
    numbers: list[tuple[str, tuple[float, float], float]] = []
    for segment in d.curves:
        ys = [paper(c.output(ref).xy)[1] for _, ref in segment]
        for i, (_, ref) in enumerate(segment):
            x, y = paper(c.output(ref).xy)
            fig.add(Path(((x, 0.0), (x, y)), "reference"))          # its ordinate
            fig.add(Circle((x, y), 0.6, "dot"))
            if 0 < i < len(segment) - 1:
                # Above the curve, on the side it comes down from, first.
                rising = ys[i + 1] < ys[i - 1]               # paper y runs down
                numbers.append((numerals(str(i)), (x, y), _UP_LEFT if rising else _UP_RIGHT))
    if top > 0:
        mid = draw_dimension(fig, (right, 0.0), (right, -top * k), (1.0, 0.0), 6.0)
        fig.add(Text((mid[0] + 1.5, mid[1]), f"{numerals(f'{top / metre:.4g}')} "
                     f"{unit_words(unit)}", 2.8, "start", False))
        if arm:
            fig.add(Text((mid[0] + 1.5, mid[1] + 4.0), words(
                "(a swing of {angle}°)", angle=numerals(f"{math.degrees(top / arm):.4g}")),
                2.8, "start", False))
    fig.add(Path(tuple(paper((t * d.per_rad, y)) for t, y in curve), "vector_result"))
    for theta, y, label in asked:
        # Ringed on the curve, its ordinate run down and named in a row under the angles.
        x, py = paper((theta * d.per_rad, y))
        fig.add(Path(((x, 0.0), (x, py)), "construction"))
        fig.add(Circle((x, py), 1.2, "plot_mark"))
        fig.add(Text((x, max(4.5, below + 3.5) + 4.5), label, 2.8, "middle", False))
    # The numbers last, each clear of every line drawn (the curve, the ordinates, the
    # construction's working lines) and nearer its own point than any other.
    placer = label_placer(fig)   # drafting: as on a blank page
    placer.block_drawn()
    placer.name_points(at for _, at, _ in numbers)
    for text, at, prefer in numbers:
        placer.place(text, at, prefer=prefer, spread=1.2, gap=1.2, size=2.6,
                     italic=False, own=at)
    draw_caption(fig, title, [words("cam angle across, lift up; each segment's construction")
                              if not arm else words(
                                  "cam angle across, the arc the arm's end swings up ({arm} "
                                  "{unit} × the swing)", arm=numerals(f"{arm / metre:g}"),
                                  unit=unit_words(unit))],
                 per_cm=per_cm, unit=unit, scale_name="Lift scale",
                 second=("Cam angle scale", 360.0 / (right / 10.0), "°"),
                 legend=(("vector_result", "displacement"), ("construction",
                                                             "construction lines"),
                         ("reference", "ordinates")))
    return fig


def _arcs(d: Displacement, paper):
    """Each inked arc on paper: centre, radius, start angle and sweep."""
    c = d.construction
    out = []
    for centre, first, sweep in d.arcs:
        cx, cy = paper(c.output(centre).xy)
        fx, fy = paper(c.output(first).xy)
        out.append(((cx, cy), math.hypot(fx - cx, fy - cy), math.atan2(-(fy - cy), fx - cx),
                    sweep))
    return out


def _circles(d: Displacement, paper):
    """The arcs drawn about a point of the base line: how far below it each reaches."""
    return [(cx, cy, r + cy) for (cx, cy), r, _, sweep in _arcs(d, paper)
            if abs(cy) < 1e-9 and abs(sweep) > math.pi]
