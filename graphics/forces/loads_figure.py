"""The space diagram with its loads, as a textbook sets out a force analysis before solving
it: the mechanism at its position, and on each link its weight, its inertia force and
couple, and the external forces and couples, every force an arrow from where it acts at
one force scale.

Each inertia force is drawn both ways the method allows: at the centre of mass G with its
inertia couple, and dashed as the one force that does the work of both, moved off G by
h = I·α/(m·a_G) to the side that gives the couple's sense. A load whose point stands beyond
the frame a scene grows to (a force far off its link, or h where a couple dwarfs its force)
is named under the figure instead, and the force scale fits the loads drawn.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from tarsim.constructions.narration import numerals, unit_words, words
from tarsim.constructions.record import Slice
from ..figure import Figure, View
from .force_figure import in_lane
from ..labels import LabelPlacer
from .load_marks import amount, draw_couple, keep_clear, name_loads, said_name, too_small
from ..scales import nice_per_cm
from ..linkages.scene import FRAME_CAP, FRAME_MIN, draw_scene
from ..symbols import draw_arrow

__all__ = ["draw_loads"]

_REACH = 0.45
"""The largest load is drawn at most this share of the mechanism's extent on paper."""

_NOISE = 1e-9
"""A force or couple this small beside the largest force (times the mechanism's size) is
the rounding of a zero: neither drawn nor listed."""

_FARTHER = (10.0, 13.0, 17.0, 22.0)
"""Rings (in gaps) a load's name may stand out to when none near its arrow is clear: on a
crowded joint a name a little off beats one over another."""

_SLIGHT = 1e-3
"""A couple under this share of the largest force times the mechanism's size would turn
nothing a reader can see: it is listed, not drawn as large as the real ones."""

_LEAST = 2.5
"""A force drawn shorter than this (paper mm) shows nothing: it is listed instead."""


def draw_loads(shown: Slice, loads: dict, *, title: str, per_cm: float | None = None
               ) -> Figure:
    """The mechanism of ``shown`` (a slice of a position's record) with ``loads`` (link →
    [(where m, force N, couple N·m, name)]) drawn on it."""
    biggest = max([math.hypot(*f) for ls in loads.values() for _, f, _, _ in ls] + [1e-300])

    c = shown.construction
    links = [(c.point(a).xy, c.point(b).xy) for k in c.mechanism.links if k.number != 1
             for a, b in zip(k.names, k.names[1:])]

    def overlay(view: View, fig: Figure, placer: LabelPlacer):
        taken = [(view(a), view(b)) for a, b in links]
        on = _on_drawing(view, [c.point(n).xy for n in c.mechanism.point_names])
        pts = [view(w) for ls in loads.values() for w, _, _, _ in ls if on(w)]
        xs, ys = [p[0] for p in pts] or [0.0], [p[1] for p in pts] or [0.0]
        extent = max(max(xs) - min(xs), max(ys) - min(ys), 40.0)
        # The force scale fits the loads drawn: one beyond the drawing is only named.
        drawn = max([math.hypot(*f) for ls in loads.values() for w, f, _, _ in ls if on(w)]
                    + [0.0]) or biggest
        force_cm = nice_per_cm(drawn, _REACH * extent)          # newtons a paper cm
        k = 10.0 / force_cm
        arrows, turns, small, afar = [], [], [], []
        for link, ls in sorted(loads.items()):
            inertia = {name: (w, f, c) for w, f, c, name in ls if name.startswith("Fi")}
            for where, f, couple, name in ls:
                point, size = view(where), math.hypot(*f)
                moment = biggest * extent / view.scale    # the largest force across it all
                if not on(where):
                    afar += [words("{name} = {size} on link {link}", name=said_name(said),
                                   size=amount(value, ".3g", unit), link=link)
                             for said, value, unit, least in (
                                 (name, size, "N", biggest),
                                 (name.replace("Fi", "Mi"), abs(couple), "N·m", moment))
                             if value > _NOISE * least]
                    continue
                if size * k >= _LEAST:
                    head = (point[0] + f[0] * k, point[1] - f[1] * k)
                    tail, head = in_lane(point, head, taken)     # beside a link, not on it
                    taken.append((tail, head))
                    draw_arrow(fig, tail, head, "vector")
                    arrows.append((tail, head, name, f" = {amount(size, '.4g', 'N')}"))
                elif size > _NOISE * biggest:
                    small.append((name, size, "N", link))
                if _NOISE * moment < abs(couple) <= _SLIGHT * moment:
                    small.append((name.replace('Fi', 'Mi'), abs(couple), "N·m", link))
                elif abs(couple) > _SLIGHT * moment:
                    draw_couple(fig, point, couple, name, turns, 4.5)
            for name, (where, f, couple) in inertia.items():
                offset = _offset(f, couple)
                if (offset is None or math.hypot(*f) * k < _LEAST or not on(where)
                        or abs(couple) <= _NOISE * biggest * extent / view.scale):
                    continue
                units = shown.construction.mechanism.units
                h = f"{numerals(format(math.hypot(*offset) / units.metres, '.3g'))} " \
                    f"{unit_words(units.length)}"
                if not on((where[0] + offset[0], where[1] + offset[1])):
                    afar.append(words("{name} (h = {h}) on link {link}", name=name + "′", h=h,
                                      link=link))
                    continue
                at = view((where[0] + offset[0], where[1] + offset[1]))
                head = (at[0] + f[0] * k, at[1] - f[1] * k)
                draw_arrow(fig, at, head, "vector_dashed")
                arrows.append((at, head, name + "′", f" (h = {h})"))
        for tail, head, _, _ in arrows:
            placer.block_path([tail, head])
        keep_clear(placer, arrows, turns)
        return lambda: _name(placer, arrows, turns, small, afar, force_cm)

    return draw_scene(shown, title=title, per_cm=per_cm, overlay=overlay)


def _name(placer: LabelPlacer, arrows, turns, small, afar, force_cm: float):
    """Name every load beside its head and every couple beside its arc, once the diagram's
    own names are placed; the scale, legend and notes the caption takes (the loads too
    small to draw, and those that would stand beyond the drawing)."""
    page, placer.page = placer.page, None          # the loads may reach past the frame
    name_loads(placer, arrows, turns, 2.8, _FARTHER)
    placer.page = page
    legend = [("vector", "a load")]
    if any(name.endswith("′") for _, _, name, _ in arrows):
        legend.append(("vector_dashed", "an inertia force and couple as one force, offset h "
                                        "from G"))
    notes = too_small(small)
    if afar:
        notes.append(words("Beyond the drawing, so not drawn: {items}.",
                           items=words(", ").join(afar)))
    return ("Force scale", force_cm, "N"), legend, notes


def _on_drawing(view: View, mechanism: list[tuple[float, float]]
                ) -> Callable[[tuple[float, float]], bool]:
    """Whether a load's point (m) stands on the drawing: the mechanism's box grown to take it
    in stays within the frame a scene grows to for its own points (:data:`~.scene.FRAME_CAP`
    extents of the mechanism, or :data:`~.scene.FRAME_MIN` mm). A force at a point far
    off its link, or an inertia force moved off G by h = I·α/(m·a_G) where a couple dwarfs
    its force, would shrink the mechanism to a dot or stretch the page to reach it: it is
    named under the figure instead (an inertia force stays drawn at G with its couple)."""
    xs, ys = [p[0] for p in mechanism], [p[1] for p in mechanism]
    lo, hi = (min(xs), min(ys)), (max(xs), max(ys))
    cap = max(FRAME_CAP * max(hi[0] - lo[0], hi[1] - lo[1]), FRAME_MIN / view.scale)

    def on(p: tuple[float, float]) -> bool:
        return max(max(hi[0], p[0]) - min(lo[0], p[0]),
                   max(hi[1], p[1]) - min(lo[1], p[1])) <= cap * (1 + 1e-12)
    return on


def _offset(f, couple: float) -> tuple[float, float] | None:
    """Where one force ``f`` does the work of ``f`` at G and ``couple``: moved off G square
    to itself by |couple|/|f|, to the side whose moment about G is the couple."""
    size2 = f[0] * f[0] + f[1] * f[1]
    if couple == 0.0 or size2 == 0.0:
        return None
    k = couple / size2              # d × f = couple for d = k·(f_y, −f_x)
    return (k * f[1], -k * f[0])
