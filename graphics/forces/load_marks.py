"""The marks a force figure draws for loads over a drawing, and their names: a couple as a
turning arrow (couples at one point on circles one inside the other), and the names of
forces and couples, each set by what it names and clear of the drawing."""

from __future__ import annotations

import math

from shapely.geometry import Point as SPoint

from tarsim.constructions.narration import numerals, unit_words, words
from ..figure import Figure
from ..hiding import shown_answer
from .force_figure import typeset_force
from ..labels import LabelPlacer
from ..symbols import draw_turning_arrow

__all__ = ["draw_couple", "name_loads", "amount", "said_name", "too_small"]

Turn = tuple[tuple[float, float], tuple[float, float], str, str, float]
"""A drawn couple: its centre, the middle of its arc, its name, what follows the name, and
its radius (paper mm)."""

Arrow = tuple[tuple[float, float], tuple[float, float], str, str]
"""A drawn force: its tail and head (paper mm), its name, what follows the name."""


def draw_couple(fig: Figure, at: tuple[float, float], couple: float, name: str,
                turns: list[Turn], radius: float) -> None:
    """A turning arrow of ``couple``'s sense about ``at``, on a circle ``radius`` mm, or
    2.5 mm wider for each couple drawn there before; added to ``turns``."""
    r = radius + 2.5 * sum(math.dist(at, t[0]) < 0.5 for t in turns)
    mid = draw_turning_arrow(fig, at, r, math.radians(30),
                             math.copysign(math.radians(240), couple))
    turns.append((at, mid, name.replace("Fi", "Mi"), f" = {amount(abs(couple), '.4g', 'N·m')}",
                  r))


def amount(value: float, spec: str, unit: str) -> str:
    """A force's or couple's size and unit as the language being spoken writes them:
    "5000 N", "۵۰۰۰ نیوتن"."""
    return f"{numerals(format(value, spec))} {unit_words(unit)}"


def too_small(items: list[tuple[str, float, str, int]]) -> list[str]:
    """The note listing the loads too small to draw, each (name, size, unit, link), in the
    language being spoken; none when there are none."""
    if not items:
        return []
    said = [words("{name} = {size} on link {link}", name=said_name(name),
                  size=shown_answer(amount(size, ".3g", unit), "…"), link=link)
            for name, size, unit, link in items]
    return [words("Too small to draw: {items}.", items=words(", ").join(said))]


def said_name(name: str) -> str:
    """A load's name in a line of text: a symbol (Fi2, W3, F54) as it is, a name in words
    ("gas force") in the language being spoken."""
    text, sub, _ = typeset_force(name)
    return name if sub else text


def keep_clear(placer: LabelPlacer, arrows: list[Arrow], turns: list[Turn]) -> None:
    """Tell ``placer`` of the arrows and couples drawn, so that every name keeps clear of
    them and each stands nearest what it names."""
    for centre, _, _, _, r in turns:
        placer.block(SPoint(centre).buffer(r + 0.6))
    placer.name_vectors((a, b) for a, b, _, _ in arrows)
    placer.name_points([mid for _, mid, _, _, _ in turns])


def name_loads(placer: LabelPlacer, arrows: list[Arrow], turns: list[Turn], size: float,
               farther: tuple[float, ...], along: bool = False) -> None:
    """Name each force beside its head, ahead of it (or, ``along``, beside the outer part of
    its shaft where its head is crowded: arrows that meet at a joint leave little room
    ahead of each), and each couple beside its arc, out from its centre; ``farther`` rings
    when nothing near is clear."""
    for tail, head, name, said in arrows:
        text, sub, tail_text = typeset_force(name)
        ahead = math.atan2(tail[1] - head[1], head[0] - tail[0])   # the arrow's paper angle
        anchors, prefer = head, ahead
        if along:
            anchors = [head] + [(tail[0] + t * (head[0] - tail[0]),
                                 tail[1] + t * (head[1] - tail[1])) for t in (0.7, 0.5)]
            prefer = (ahead, ahead + math.pi / 2, ahead - math.pi / 2)
        placer.place_numbered(text, anchors, [], sub=sub, tail=tail_text + said, size=size,
                              gap=1.0, prefer=prefer, spread=math.pi / 2, own=(tail, head),
                              farther=farther)
    for centre, mid, name, said, _ in turns:
        text, sub, tail_text = typeset_force(name)
        out = math.atan2(centre[1] - mid[1], mid[0] - centre[0])
        placer.place_numbered(text, mid, [], sub=sub, tail=tail_text + said, size=size,
                              gap=1.0, prefer=out, spread=math.pi / 2, own=mid,
                              farther=farther)
