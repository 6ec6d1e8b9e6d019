"""An engine's part of its problem sheet (:mod:`.handout`): the layout of a single-cylinder,
V or radial engine, each cylinder's line of stroke from the crank shaft's centre and the
crank at the angle the file gives, directions only, as the books sketch it beside the
question; nothing the solution finds."""

from __future__ import annotations

import math
from collections.abc import Sequence

from tarsim.constructions.narration import numerals, words

from .figure import Circle, Figure, Path, Text
from .scales import draw_caption

__all__ = ["draw_engine_layout"]

_CRANK = 22.0     # the crank's length in the layout, mm: it gives directions only
_LINE = 48.0      # a line of stroke's length from O, mm


def draw_engine_layout(title: str, lines: Sequence[tuple[str, float]],
                       crank: float | None, *, reference: str) -> Figure:
    """Draw each cylinder's line of stroke from O (its name at its end) and the crank at
    ``crank`` (rad, counter-clockwise from the reference line, None: not given), the
    angle marked; directions only, no scale.

    Parameters
    ----------
    title
        The caption's heading.
    lines
        Each cylinder's name and its line's angle (rad, counter-clockwise from the reference
        line, drawn to the right).
    crank
        The crank's angle given, or None.
    reference
        What the reference line is, said ("the centre line"): the caption names it.

    Examples
    --------
    A V-twin at 90°, its crank 30° from the centre line:

    >>> fig = draw_engine_layout("V", [("1", math.pi / 4), ("2", -math.pi / 4)],
    ...                          math.radians(30), reference="the centre line")
    >>> sorted(t.text for t in fig.items if getattr(t, "text", "").startswith("cyl."))
    ['cyl. 1', 'cyl. 2']
    """
    fig = Figure(0.0, 0.0, title=title)
    if all(abs(math.remainder(a, 2 * math.pi)) > 1e-9 for _, a in lines):
        fig.add(Path(((0.0, 0.0), (_LINE + 8.0, 0.0)), "reference"))   # else cylinder 1's
    for name, a in lines:
        u = (math.cos(a), -math.sin(a))              # paper y runs down
        fig.add(Path(((0.0, 0.0), (_LINE * u[0], _LINE * u[1])), "construction"))
        at = ((_LINE + 3.0) * u[0], (_LINE + 3.0) * u[1] + 1.0)
        anchor = "start" if u[0] > 0.2 else "end" if u[0] < -0.2 else "middle"
        fig.add(Text(at, words("cyl. {number}", number=numerals(name)), 3.0, anchor, False))
    if crank is not None:
        u = (math.cos(crank), -math.sin(crank))
        tip = (_CRANK * u[0], _CRANK * u[1])
        fig.add(Path(((0.0, 0.0), tip), "link"))
        fig.add(Circle(tip, 0.9, "pin"))
        if abs(math.remainder(crank, 2 * math.pi)) > math.radians(3.0):
            fig.arc((0.0, 0.0), 0.6 * _CRANK, 0.0, crank, "dimension")
            # beyond the arc's middle, set off the reference line it starts from
            mid, r = crank / 2, 0.6 * _CRANK + 3.5
            y = -r * math.sin(mid)
            fig.add(Text((r * math.cos(mid), y - 1.0 if y <= 0 else y + 2.5), "θ", 3.0,
                         "start"))
    fig.add(Circle((0.0, 0.0), 0.8, "dot"))
    # O in the widest gap between the lines, the crank and the reference line
    rays = sorted({0.0} | {a % (2 * math.pi) for _, a in lines}
                  | ({crank % (2 * math.pi)} if crank is not None else set()))
    width, start = max(((rays[(i + 1) % len(rays)] - a) % (2 * math.pi) or 2 * math.pi, a)
                       for i, a in enumerate(rays))
    mid = start + width / 2
    fig.add(Text((4.0 * math.cos(mid), -4.0 * math.sin(mid) + 1.0), "O", 3.0, "middle"))
    draw_caption(fig, title, [words("the cylinders' lines and the crank, θ from {reference}; "
                                    "directions only", reference=words(reference))],
                 per_cm=None, unit="mm")
    return fig
