"""The force polygons as a textbook prints them: each load an arrow head to tail at the
force scale, the two lines that close the dyad's polygon crossing at x, and the crank's
polygon closed by the frame's force, heavy.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from ..constructions import geometry as g
from ..constructions.record import Construction, Panel, Role
from .figure import Circle, Figure, Path, Text, clip_line
from .scales import draw_caption, nice_per_cm
from .symbols import draw_arrow

__all__ = ["draw_force_figure"]

_ROOM = (240.0, 150.0)   # paper (mm) the polygons are fitted to: across, up


def draw_force_figure(c: Construction, scale: float, title: str,
                      notes: Sequence[str] = ()) -> Figure:
    """The FORCE panel of ``c``, drawn at ``scale`` drawing metres per newton."""
    steps = [s for s in c if s.panel is Panel.FORCE]
    joins = [s for s in steps if s.verb == "join"]
    ends = [p for s in joins for p in (s.output.start.xy, s.output.end.xy)]
    xs, ys = [x for x, _ in ends], [y for _, y in ends]
    across = max(max(xs) - min(xs), 1e-12) / scale                        # newtons
    up = max(max(ys) - min(ys), 1e-12) / scale
    per_cm = max(nice_per_cm(across, _ROOM[0]), nice_per_cm(up, _ROOM[1]))
    k = 10.0 / (per_cm * scale)                                          # paper mm a drawing m

    def paper(xy) -> tuple[float, float]:
        return xy[0] * k, -xy[1] * k

    fig = Figure(0.0, 0.0, title=title)
    # The closing lines run across the dyad's polygon only (the joins before the crank's).
    first = [s for s in joins if not s.id.startswith(("force:v:2", "force:v:frame"))] or joins
    dyad = [p for s in first for p in (s.output.start.xy, s.output.end.xy)]
    box = (min(x for x, _ in dyad) * k - 6.0, -max(y for _, y in dyad) * k - 6.0,
           max(x for x, _ in dyad) * k + 6.0, -min(y for _, y in dyad) * k + 6.0)
    for s in steps:
        if s.verb == "parallel_through" and isinstance(s.output, g.Line):
            a, d = s.output.anchor(), s.output.direction
            seg = clip_line((a[0] * k, -a[1] * k), (d[0], -d[1]), -1e9, 1e9, box)
            if seg:
                fig.add(Path(seg, "construction"))
    for s in joins:
        a, b = paper(s.output.start.xy), paper(s.output.end.xy)
        if math.dist(a, b) < 0.3:
            continue
        draw_arrow(fig, a, b, "vector_result" if s.role is Role.RESULT else "vector")
        if s.label and math.dist(a, b) > 4.0:      # a shorter one is named in the steps
            mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
            n = math.dist(a, b)
            side = ((b[1] - a[1]) / n * 3.2, -(b[0] - a[0]) / n * 3.2)
            text, sub, tail = _split(s.label)
            fig.add(Text((mid[0] + side[0], mid[1] + side[1]), text, 2.8, "middle", False,
                         "normal", sub, tail))
    for s in steps:
        if s.verb == "intersect_lines":
            at = paper(s.output.xy)
            fig.add(Circle(at, 0.7, "dot"))
            fig.add(Text((at[0] + 2.0, at[1] - 2.0), "x", 3.0, "start", True))
    draw_caption(fig, title, ["every load head to tail; the dyad's polygon closed by the "
                              "two lines crossing at x, the crank's by the frame's force"],
                 per_cm=per_cm, unit="N", legend=(("vector", "a force"),
                                                  ("vector_result", "the frame's force on "
                                                                    "the crank"),
                                                  ("construction", "a closing line")),
                 notes=notes, scale_name="Force scale")
    return fig


def _split(label: str) -> tuple[str, str, str]:
    """A force's name as printed: "F_23ᵗ" is F with 23 below and ᵗ after, "Fi3" is F with
    i3 below, "W3" W with 3 below; other names as they are."""
    if label.startswith("F_"):
        body = label[2:]
        tail = body[-1] if body[-1:] in ("ᵗ", "ⁿ") else ""
        return "F", body[:len(body) - len(tail)], tail
    if label[:2] == "Fi" and label[2:].isdigit():
        return "F", label[1:], ""
    if label[:1] in "WP" and label[1:].isdigit():
        return label[0], label[1:], ""
    return label, "", ""
