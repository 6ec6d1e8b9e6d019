"""The end view of an engine's cranks, set beside its polygon as the books draw it.

Khurmi's and Rattan's balancing chapters draw, beside each polygon, the crankshaft seen
from its end: from the shaft's centre O each crank a radius at its angle from the
reference line (the line of stroke, the crank at the inner dead centre), numbered with its
cylinder and its angle. The secondary polygons are laid off along the secondary cranks,
at 2θᵢ, and have their own view. Cranks at one angle (the in-line four's 1 and 4) are one
radius with one label. The view has no scale: it gives directions only.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from tarsim.constructions.narration import numerals, right_to_left, words
from ..figure import Circle, Figure, Path, Text
from ..hiding import shown_answer

__all__ = ["CrankView", "draw_crank_view", "RADIUS"]

RADIUS = 15.0
"""A crank's length in the view (paper mm): each the same, as the view gives directions."""

_PAST = 7.0       # mm the reference line runs past the cranks' circle
_GAP = 12.0       # mm between the view and the polygon beside it
_LABEL = 2.8      # a crank's label, mm
_HEADING = 3.0    # the view's heading, mm
_SAME = math.radians(0.5)   # cranks closer than this are drawn as one radius


@dataclass(frozen=True)
class CrankView:
    """What the view shows: its heading and each crank's (cylinder number, angle in rad,
    counter-clockwise from the reference line); the cylinders whose angles the solution
    found (``found``), an answer ``--hide answers`` leaves out."""

    heading: str
    cranks: tuple[tuple[str, float], ...]
    found: frozenset[str] = frozenset()


def _groups(cranks: Sequence[tuple[str, float]]) -> list[tuple[list[str], float]]:
    """The cranks by their direction, each direction once with its cylinders in order, the
    angle in [0, 2π)."""
    out: list[tuple[list[str], float]] = []
    for name, angle in cranks:
        a = angle % (2 * math.pi)
        for names, b in out:
            if abs(math.remainder(a - b, 2 * math.pi)) < _SAME:
                names.append(name)
                break
        else:
            out.append(([name], 0.0 if min(a, 2 * math.pi - a) < _SAME else a))
    return out


def _label(names: Sequence[str], angle: float, found: frozenset[str]) -> str:
    """A radius's label, "1, 4: 0°", in the spoken language; its number alone where its
    angle was found and answers are hidden."""
    joined = ("، " if right_to_left() else ", ").join(numerals(n) for n in names)
    degrees = math.degrees(angle) % 360.0
    said = words("{cranks}: {angle}°", cranks=joined,
                 angle=numerals(f"{degrees:.1f}".removesuffix(".0")))
    return shown_answer(said, joined) if found.intersection(names) else said


def _view(view: CrankView) -> Figure:
    """The view about O at (0, 0): the reference line, each radius with its pin and label,
    O in the widest gap between the radii, the heading over it all."""
    fig = Figure(0.0, 0.0)
    groups = _groups(view.cranks)
    fig.add(Path(((0.0, 0.0), (RADIUS + _PAST, 0.0)), "reference"))
    fig.add(Text((RADIUS + _PAST + 1.0, 0.0), words("i.d.c."), 2.4, "start", False))
    for names, a in groups:
        u = (math.cos(a), -math.sin(a))             # paper y runs down: counter-clockwise is −y
        tip = (RADIUS * u[0], RADIUS * u[1])
        fig.add(Path(((0.0, 0.0), tip), "link"))
        fig.add(Circle(tip, 0.9, "pin"))
        if abs(u[1]) < math.sin(math.radians(12.0)):
            # along the reference line (or opposite it): the label over the line
            at = (tip[0] + (1.5 if u[0] > 0 else -1.5), tip[1] - 2.6)
        else:
            at = (tip[0] + 2.6 * u[0], tip[1] + (2.6 + _LABEL / 2) * u[1])
        anchor = "start" if u[0] > 0.2 else "end" if u[0] < -0.2 else "middle"
        fig.add(Text(at, _label(names, a, view.found), _LABEL, anchor, False, owner=(tip,)))
    fig.add(Circle((0.0, 0.0), 0.8, "dot"))
    # the radii and the reference line, each direction once
    rays = sorted({0.0} | {a for _, a in groups})
    gaps = [((rays[(i + 1) % len(rays)] - a) % (2 * math.pi) or 2 * math.pi, a)
            for i, a in enumerate(rays)]
    width, start = max(gaps)
    mid = start + width / 2
    fig.add(Text((3.4 * math.cos(mid), -3.4 * math.sin(mid)), "O", 2.8, "middle", True,
                 owner=((0.0, 0.0),)))
    x0, y0, x1, _ = fig.bounds()
    fig.add(Text(((x0 + x1) / 2, y0 - 4.0), view.heading, _HEADING, "middle", False, "bold"))
    return fig


def draw_crank_view(fig: Figure, view: CrankView) -> tuple[float, float]:
    """Set ``view`` beside the drawing in ``fig``, on the side its reading starts from (the
    left, or the right in a right-to-left language: the cranks are drawn first, at step 1),
    its middle level with the drawing's; return where its centre O stands."""
    x0, y0, x1, y1 = fig.bounds()
    part = _view(view)
    a0, b0, a1, b1 = part.bounds()
    dx = x1 + _GAP - a0 if right_to_left() else x0 - _GAP - a1
    dy = (y0 + y1) / 2 - (b0 + b1) / 2
    part.shift(dx, dy)
    for item in part.items:
        fig.add(item)
    return dx, dy
