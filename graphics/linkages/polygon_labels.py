"""The names on a velocity or acceleration polygon: its tips, its vectors and its lines.

Each is set after everything is drawn, with its step numbers, clear of the ink:

* a tip is its lower-case letter in italic (b, a₄, b′), set in the widest gap
  between the lines and arrows that meet there, its step numbers beyond it, and
  nearer it than any other arrow's tip (labelled or not), as a reader takes a name
  for the point marked nearest it; it may cross a thin working line rather than
  stand off where it would name another; coincident points share one label
  ("o_v ≡ b");
* a vector's label (``V_B/A``, ``Aⁿ_B/A``) stands beside its own stretch of shaft,
  on the polygon's outer side; arrows drawn one over another share one label
  ("V_A₂ = V_A₄"), and a vector of no length is written "Aⁿ_B/A = 0" beside its
  point;
* a working line's numbers stand by the middle of the stretch no arrow covers.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import TYPE_CHECKING

from tarsim.constructions import geometry as g
from tarsim.constructions.record import Step

from ..labels import LABEL
from ..symbols import unit
from ..typeset import typeset
from .name_leaders import lead_last_to_shaft

if TYPE_CHECKING:
    from .polygon_panel import _PolygonPanel

__all__ = ["label_points", "label_vectors", "number_lines", "ZERO", "HERE", "CROSSABLE"]

ZERO = 0.05         # a vector shorter than this on paper (mm) is drawn as "= 0"
HERE = 1e-6         # paper points closer than this (mm) are one
CROSSABLE = 0.02    # what covering a thin working line costs a label, against 1 for ink
_TINY = 1.0         # a vector shorter than this (mm) is named as the point it nearly is:
                    # beside so short a shaft a name is as near every arrow from its pole
_NEAR = (1.0, 1.6, 2.4, 3.4, 4.6)   # a vector's label stays this many gaps from its shaft
_FARTHER = (6.0, 8.0, 11.0, 15.0)   # ...unless every spot there covers another label
_ON_LABEL = 0.05 * LABEL   # a tiny vector's name covers no more beside it (0.05 mm² of
                    # another label, 0.5 mm² of a line) before it stands off farther
_CROSSING = 20.0 * CROSSABLE    # a point's name crosses this much (20 mm², two working
                    # lines under a label) before it stands off in a farther ring, where a
                    # reader would take it for another point's
_SHORT = 8.0        # mm: an arrow shorter than this may have its name round its ends


def _numbered(polygon: _PolygonPanel, steps: Iterable[Step]) -> list[int]:
    return [polygon.numbers[s.id] for s in steps if s.id in polygon.numbers]


def label_points(polygon: _PolygonPanel) -> None:
    """Each point's name and numbers; coincident points share one label ("o_v ≡ b")."""
    groups: list[list[Step]] = []
    for step in polygon.steps:
        out = step.output
        if not isinstance(out, g.Point) or out.is_at_infinity:
            continue
        grp = next((grp for grp in groups if polygon.coincide(grp[0].output.xy, out.xy)), None)
        if grp is None:
            groups.append([step])
        else:
            grp.append(step)
    polygon.placer.name_points(polygon.view(grp[0].output.xy) for grp in groups
                               if any(s.label for s in grp))
    # A reader takes a name for the nearest point marked: it stands nearer its own than
    # any arrow's tip, labelled or not, and the ends of arrows moved into lanes.
    hidden = polygon.hidden()
    polygon.placer.name_points(
        {end for s, a, b in polygon.vectors() if s.id not in hidden and math.dist(a, b) >= ZERO
         for end, at in zip((a, b), polygon.drawn[s.id][2:])
         if end is b or math.dist(end, at) > HERE})
    for grp in groups:
        at = polygon.view(grp[0].output.xy)
        names = list(dict.fromkeys(typeset(s.label) for s in grp if s.label))
        text, sub, tail = _joined(names) if names else ("", "", "")
        rays = polygon.rays_at(at)
        with polygon.fig.for_steps(*(s.id for s in grp)):
            polygon.placer.place_numbered(text, at, _numbered(polygon, grp), sub=sub,
                                          tail=tail,
                                          prefer=_free_direction(at, rays, polygon.centre),
                                          gap=1.0, size=3.8, farther=_FARTHER,
                                          crossing=_CROSSING, own=at if names else None,
                                          beside=True)


def label_vectors(polygon: _PolygonPanel) -> None:
    """Each vector's label beside its own stretch of shaft; a null one as "… = 0".

    The shortest go first: they have the least shaft to choose a place by. Arrows
    drawn one over another (V_A₂ and V_A₄ when the block does not slide) share one
    label, "V_A₂ = V_A₄"; one moved into a lane is labelled on its lane's side.
    """
    drawn = polygon.vectors()
    polygon.placer.name_vectors((a, b) for s, a, b in drawn
                                if s.label and math.dist(a, b) >= _TINY)
    polygon.placer.name_points(_middle(a, b) for s, a, b in drawn
                               if s.label and ZERO <= math.dist(a, b) < _TINY)
    twins: list[list[tuple[Step, tuple[float, float], tuple[float, float]]]] = []
    for v in drawn:
        same = next((t for t in twins if math.dist(t[0][1], v[1]) < ZERO
                     and math.dist(t[0][2], v[2]) < ZERO
                     and math.dist(v[1], v[2]) >= ZERO), None)
        if same is None:
            twins.append([v])
        else:
            same.append(v)
    for group in sorted(twins, key=lambda t: math.dist(t[0][1], t[0][2])):
        with polygon.fig.for_steps(*(s.id for s, _, _ in group)):
            _label_vector(polygon, group, drawn)


def _label_vector(polygon: _PolygonPanel, group: list, drawn: list) -> None:
    """One vector's label (or the one label of arrows drawn one over another)."""
    step, a, b = group[0]
    names = list(dict.fromkeys(typeset(s.label) for s, _, _ in group if s.label))
    text, sub = names[0] if names else ("", "")
    numbers = _numbered(polygon, (s for s, _, _ in group))
    if math.dist(a, b) < ZERO:
        rays = polygon.rays_at(a)
        polygon.placer.place_numbered(text, a, numbers, sub=sub,
                                      tail=" = 0" if text else "",
                                      prefer=_free_direction(a, rays, polygon.centre), gap=1.6,
                                      size=3.2)
        return
    d = unit((b[0] - a[0], b[1] - a[1]))
    normal = math.atan2(d[0], d[1])       # the paper normal (−dy, dx) as a paper angle
    true_a = polygon.drawn[step.id][2]
    away = (a[0] + b[0]) / 2 - polygon.centre[0], (a[1] + b[1]) / 2 - polygon.centre[1]
    if math.dist(a, true_a) > HERE:      # in a lane: its side is the lane's
        away = (a[0] - true_a[0], a[1] - true_a[1])
    if away[0] * math.cos(normal) - away[1] * math.sin(normal) < 0:
        normal += math.pi                  # the outer side of the polygon first
    others = [(p, q) for s, p, q in drawn if all(s is not t for t, _, _ in group)]
    anchors = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
               for t in _own_stretch(a, b, others)]
    # A short arrow has little shaft to stand beside: its name may go round its ends.
    spread = math.pi / 3
    # So short an arrow is found by its name only beside it: farther rings only
    # where every spot beside it covers another label.
    dot = math.dist(a, b) < _TINY
    before = len(polygon.fig.items)
    polygon.placer.place_numbered(text, anchors, numbers, sub=sub, also=tuple(names[1:]),
                                  prefer=(normal, normal + math.pi), spread=spread,
                                  gap=1.0, size=3.4, rings=_NEAR, farther=_FARTHER,
                                  crossing=_ON_LABEL if dot else 0.0,
                                  own=None if not text else _middle(a, b) if dot
                                  else (a, b))
    if not dot:     # a name set off in a farther ring, where short arrows crowd, is led to
        lead_last_to_shaft(polygon.fig, polygon.placer, (a, b), before)


def number_lines(polygon: _PolygonPanel) -> None:
    """Each line's numbers beside its middle, or the middle of the stretch no arrow covers.

    Its ends are where the tips and their numbers crowd, so a number there
    would be read as a point's.
    """
    arrows = [(p, q) for _, p, q in polygon.vectors() if math.dist(p, q) >= ZERO]
    for steps, (a, b) in polygon.lines:
        d = unit((b[0] - a[0], b[1] - a[1]))
        normal = math.atan2(d[0], d[1])
        anchors = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
                   for t in _own_stretch(a, b, arrows)]
        with polygon.fig.for_steps(*(s.id for s in steps)):
            polygon.placer.place_numbered("", anchors, _numbered(polygon, steps),
                                          prefer=(normal, normal + math.pi),
                                          spread=math.pi / 4, gap=0.6, farther=_FARTHER)


def _free_direction(at: tuple[float, float], rays: list[tuple[float, float]],
                    centre: tuple[float, float]) -> float:
    """Find the paper angle (rad, as :meth:`LabelPlacer.spot` takes it) for a point's label.

    ``rays`` are the paper directions of the lines and arrows leaving ``at``; a
    label in the middle of a wide gap between them reads clear of all. Of two
    gaps about as wide, the one opening away from the polygon's ``centre`` wins:
    inside, the vectors' labels need the room.
    """
    away = (at[0] - centre[0], at[1] - centre[1])
    outward = math.atan2(-away[1], away[0]) if math.hypot(*away) > 1e-6 else None
    if not rays:
        return math.pi / 4 if outward is None else outward
    angles = sorted({round(math.atan2(-dy, dx), 9) for dx, dy in rays})   # paper y runs down
    if len(angles) == 1:
        return angles[0] + math.pi
    gaps = [((angles[(k + 1) % len(angles)] - a) % (2 * math.pi), a)
            for k, a in enumerate(angles)]

    def score(gap: tuple[float, float]) -> float:
        width, start = gap
        lean = 0.0 if outward is None else math.cos(start + width / 2 - outward)
        return width * (1.0 + 0.5 * lean)

    width, start = max(gaps, key=score)
    return start + width / 2


def _joined(names: list[tuple[str, str]]) -> tuple[str, str, str]:
    """One label for coincident points, "o_v ≡ b": text, subscript and tail.

    The pole, whose name has a true subscript, leads; the others follow it
    written out.
    """
    names = sorted(names, key=lambda name: not name[1])
    (text, sub), rest = names[0], names[1:]
    tail = "".join(f" ≡ {t}{s}" for t, s in rest)
    return (text, sub, tail) if sub else (text + tail, "", "")


def _own_stretch(a: tuple[float, float], b: tuple[float, float],
                 others: list[tuple[tuple[float, float], tuple[float, float]]]) -> list[float]:
    """Where along ``a → b`` (fractions, best first) its label can name it alone.

    Vectors drawn along one line overlap (V_A₄ within V_B₄, both from o_v): the
    longer one's label goes on the stretch no other arrow covers, so each label
    sits by its own arrow. An arrow wholly covered takes its middle.
    """
    length = math.dist(a, b)
    d = ((b[0] - a[0]) / length, (b[1] - a[1]) / length)
    covered = []
    for p, q in others:
        # Another arrow on the same carrier: both its ends within a hair of a → b's line.
        if all(abs((e[0] - a[0]) * d[1] - (e[1] - a[1]) * d[0]) < 0.05 for e in (p, q)):
            s, t = sorted(((e[0] - a[0]) * d[0] + (e[1] - a[1]) * d[1]) / length for e in (p, q))
            covered.append((s, t))
    free = [(0.0, 1.0)]
    for s, t in covered:
        free = [piece for lo, hi in free
                for piece in ((lo, min(hi, s)), (max(lo, t), hi)) if piece[1] - piece[0] > 1e-9]
    lo, hi = max(free, key=lambda f: f[1] - f[0], default=(0.0, 1.0))
    if (hi - lo) * length < 6.0:
        lo, hi = 0.0, 1.0
    mid = (lo + hi) / 2
    return [mid + k * (hi - lo) for k in (0.0, -0.15, 0.15, -0.3, 0.3, -0.4, 0.4)]


def _middle(a: tuple[float, float], b: tuple[float, float]) -> tuple[float, float]:
    return (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
