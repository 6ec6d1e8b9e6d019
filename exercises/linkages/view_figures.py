"""The figures of the interactive page: the exercise's own, as its solution draws them,
serialised for the page to draw and to step through and to turn.

Each figure of the exercise's first position that numbers steps is drawn as `tarsim
solve` draws it, in English and in Persian, and written primitive by primitive
(:func:`~tarsim.graphics.figure_data.figure_data`). Each primitive carries what the page
needs of it, and nothing says what it is:

* ``s``: the numbered steps it is drawn for, ``[part, number, …]`` as steps.md numbers
  them (none: it stands on every step, as the mechanism does);
* ``l``: the layer a reader may hide it with: ``kennedy`` or ``construction`` lines,
  ``labels`` or step ``numbers``;
* ``m``: what it stands on, ``[view, [P, Q, R, …]]`` (:mod:`~tarsim.graphics.figure_anchors`),
  found by drawing the figure again a little further on, with ``at``, a text's anchor;
  the page moves it with the named points each frame sends. Without ``m`` it is shown at
  the exercise's own position only.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from copy import copy
from dataclasses import replace
from functools import partial
from typing import Any

from tarsim.constructions import geometry as g
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.linkages.kennedy import locate_centres
from tarsim.constructions.narration import narrate, speaking, words
from tarsim.constructions.record import Panel, Role, Slice
from tarsim.graphics.figure import Circle, Figure, Path, Text
from tarsim.graphics.figure_anchors import EXACT, Named, anchors
from tarsim.graphics.figure_data import figure_data, number
from tarsim.graphics.linkages.scene import draw_scene
from .exercise_file import Exercise
from .solution import Overall, Solution, solve_positions
from .view_frames import _flat
from .view_paper import mark_paper

__all__ = ["PageFigures", "named_points", "solved_at", "NEXT", "FAR", "AFAR"]

NEXT = 0.05
"""Degrees further on the input turns for the second drawing a figure's primitives are
matched against: little enough that every label and symbol is chosen as at the position
itself, enough that the links turn by more than rounding."""

FAR = 15.0
"""Degrees further on for a third drawing: it tells what turns with a link that stands
still at the exercise's position (a slotted lever at its limit) from what does not turn.
It is also the drawing the page turns (:func:`_turning`): at the exercise's own position a
construction may have collapsed (a point already on the line it is swung onto, two lines
drawn as one), and what is drawn there cannot say how it moves; FAR on it stands apart.
That drawing is matched against its own drawings a little and FAR further on."""

_LAYERS = {"kennedy": "kennedy", "working": "construction", "compass": "construction",
           "gauge": "construction", "normal": "construction", "construction": "construction"}
"""The layer of a primitive by its style: the working lines a reader may hide."""


class PageFigures:
    """The figures of ``sol`` (the exercise ``ex`` solved at its first position) that
    number steps, as the page shows them; the mechanism alone if none does.

    Each is drawn at the position, a little on and :data:`FAR` on, and the drawing FAR on
    again a little and FAR further on, by :meth:`jobs` (to be run beside the frames, on
    every core), and then serialised by :meth:`figures`. ``names``
    are the named points of each view the frames send, ``sense`` the way the input turns
    (±1), ``room`` the drawing's room the solution chose its scales for.
    """

    def __init__(self, ex: Exercise, sol: Solution, names: dict[str, list[str]], sense: float,
                 room: tuple[float, float], languages: tuple[str, ...]):
        self.ex, self.languages = ex, languages
        self.sols = [sol, *(_further(sol, sense * step, room)
                            for step in (NEXT, FAR, FAR + NEXT, 2 * FAR))]
        self.named = [named_points(s, names) if s is not None else None for s in self.sols]
        # What each job draws: a language and a drawing (at the position, a little on,
        # FAR on and a little further; 2·FAR on in the first language only, for it tells
        # the symbols apart, which are drawn alike in every language).
        self.todo = [(lang, k) for lang in languages for k, s in enumerate(self.sols)
                     if s is not None and (k < 4 or lang == languages[0])]

    def jobs(self) -> list[Callable[[], dict[str, Figure]]]:
        """A job for each drawing: it returns the figures by stem."""
        return [partial(_figures_in, self.ex, self.sols[k], lang) for lang, k in self.todo]

    def figures(self, done: list[dict[str, Figure]]) -> list[dict[str, Any]]:
        """The figures as the page shows them, from what the jobs drew (in their order)."""
        from .solution_files import figure_parts

        drawn: dict[str, dict[str, list]] = {}
        for (lang, k), figs in zip(self.todo, done):
            for stem, fig in figs.items():
                drawn.setdefault(stem, {}).setdefault(lang, [None] * 5)[k] = fig
        first = self.languages[0]
        for by_lang in drawn.values():
            for lang in self.languages[1:]:
                by_lang.setdefault(lang, [None] * 5)[4] = by_lang.get(first, [None] * 5)[4]
        out = []
        for stem, heading, parts in figure_parts(self.sols[0]):
            by_lang = drawn.get(stem, {})
            if any(by_lang.get(lang, [None])[0] is None for lang in self.languages) or \
                    not any(shown.numbered(panel) for _, panel, shown in parts):
                continue
            out.append(_figure(stem, heading, parts, by_lang, self.named, self.languages,
                               _angle(self.sols[2])))
        return out or [_bare(self.sols, self.named, self.languages)]


def _angle(sol: Solution | None) -> float | None:
    """The input's angle (rad) ``sol`` is drawn at; None for no solution."""
    return None if sol is None else sol.exercise.mechanism.drive.angle


def _figures_in(ex: Exercise, sol: Solution, lang: str) -> dict[str, Figure]:
    """The figures ``sol`` is drawn in, by stem, as `tarsim solve --lang` draws them in
    ``lang``: titled with the mechanism's name in it, if its file gives one."""
    ex, sol = ex.named_in(lang), replace(sol, exercise=sol.exercise.named_in(lang))
    with speaking(lang):
        return {f.stem: f.figure for f in _pages(ex, sol)}


def named_points(sol: Solution, names: dict[str, list[str]]) -> Named:
    """The named points of each view where ``sol`` draws them: its joints and the instant
    centres, its polygons' poles and tips, and the points of its constructions named by
    their refs, in the order of ``names``."""
    asm = sol.assembly
    space = {n: asm.xy(n) for n in asm.mechanism.point_names}
    try:
        cs = locate_centres(assemble(asm.mechanism))
        for c in cs.primaries + cs.secondaries:
            p = cs.point(*c.pair)
            space[c.label] = None if p.is_at_infinity else p.xy
    except TarsimError:                      # Kennedy cannot reach them here
        pass
    out = {"space": [space.get(n, _built(asm, n)) for n in names["space"]]}
    for view, poly in (("velocity", sol.velocity_polygon),
                       ("acceleration", sol.acceleration_polygon)):
        if poly is not None:
            at = {n: asm.output(ref).xy for n, ref in poly.tips.items()}
            at["pole"] = asm.output(poly.pole).xy
            out[view] = [at.get(n, _built(asm, n)) for n in names[view]]
    return out


def _built(asm, ref: str) -> tuple[float, float] | None:
    """The point a step of ``asm``'s record made, by its ref (a name the frames send for
    a point of the exercise's own constructions); None if the record has no such point
    there, or it is at infinity."""
    out = asm.output(ref) if ref in asm else None
    return out.xy if isinstance(out, g.Point) and not out.is_at_infinity else None


def _pages(ex: Exercise, sol: Solution) -> list:
    """The figures ``sol`` is drawn in, as `tarsim solve` draws them, in the language
    spoken."""
    from .solution_files import WorkedSolution

    return WorkedSolution(ex, Overall(), [sol]).pages


def _further(sol: Solution, degrees: float, room) -> Solution | None:
    """``sol``'s exercise solved with its input turned ``degrees`` on (or back, where it
    cannot go on), as :func:`solved_at`; None where it can go neither way."""
    drive = sol.exercise.mechanism.drive
    for way in (1.0, -1.0):
        out = solved_at(sol, drive.angle + way * math.radians(degrees), room)
        if out is not None:
            return out
    return None


def solved_at(sol: Solution, angle: float, room) -> Solution | None:
    """``sol``'s exercise solved with its input at ``angle`` (rad), its space diagram and
    the velocities drawn on it at ``sol``'s scales, so that its drawing and its record
    are ``sol``'s at another angle; None where it cannot be."""
    ex, scales = sol.exercise, sol.work.scales
    m = replace(ex.mechanism, scale=scales.space).with_drive(
        replace(ex.mechanism.drive, angle=angle))
    try:
        return solve_positions(replace(ex, mechanism=m, positions=(),
                                       velocity_per_cm=ex.velocity_per_cm or scales.velocity),
                               room=room)[0]
    except TarsimError:
        return None


def _figure(stem: str, heading: str, parts: list, by_lang: dict, named, languages,
            angle: float | None) -> dict[str, Any]:
    """One figure: its parts' numbered steps in every language, and its drawing in each."""
    from .solution_files import heading_in

    steps = {}                               # a step's ref → [part, number]
    out_parts = []
    for p, (title, panel, shown) in enumerate(parts):
        numbered = {s.id: n for n, s in shown.numbered(panel)}
        current = 0
        for step in shown.steps(panel):
            if step.role is Role.GIVEN and panel is Panel.SPACE:
                continue                     # the mechanism itself, drawn on every step
            current = numbered.get(step.id, current)
            steps[step.id] = [p, current]
        out_parts.append({
            "title": {lang: heading_in(title, lang) for lang in languages},
            "steps": [{"n": n, "said": {lang: narrate(s, lang) for lang in languages}}
                      for n, s in shown.numbered(panel)]})
    return {"stem": stem, "heading": {lang: heading_in(heading, lang) for lang in languages},
            "parts": out_parts,
            "drawn": {lang: _both(figs, named, steps, lang, angle)
                      for lang, figs in by_lang.items()}}


def _both(figs: list[Figure | None], named: list, steps: dict[str, list[int]], lang: str,
          angle: float | None) -> dict[str, Any]:
    """A figure at the exercise's position, with its drawing FAR on as ``turning``:
    ``figs`` and ``named`` are the five drawings in ``lang`` and their named points
    (:class:`PageFigures`), ``angle`` the input's there (rad)."""
    out = _drawn(figs[:3], named[:3], steps)
    turning = _turning(figs[0], figs[2:], named[2:], lang, angle)
    if turning is not None:
        out["turning"] = turning
    return out


def _turning(home: Figure, figs: list[Figure | None], named: list, lang: str,
             angle: float) -> dict[str, Any] | None:
    """The figure drawn :data:`FAR` on (``figs[0]``, then it a little and FAR further on),
    as the page shows it while the input turns: moved so that its space diagram stands
    where ``home`` draws it, each primitive with what it stands on, and the named points
    it stands on there (``named``: ``named[0]``'s, as a frame sends them), and the input's
    ``angle`` there. None if it cannot be drawn there."""
    if figs[0] is None or named[0] is None:
        return None
    fig = copy(figs[0])
    a, b = home.views.get("space"), fig.views.get("space")
    if a is not None and b is not None and math.isclose(a.scale, b.scale, rel_tol=1e-9):
        fig.shift(a.origin[0] - b.origin[0], a.origin[1] - b.origin[1])
    out = _drawn([fig, *figs[1:]], named, {})
    out["named"] = {view: _flat(points) for view, points in named[0].items()}
    out["angle"] = angle
    _afar(out["items"], fig, named[0])
    with speaking(lang):
        panels = _panels(fig, named[0], out["items"])
    if panels:
        out["panels"] = panels
    return out


AFAR = 30.0
"""How far (paper mm) from the named point it stands on a primitive of the drawing the
page turns may be drawn. A name, a symbol or a line's overhang stands within some
millimetres of its point; what stands farther (a caption, a legend, a scale bar) is
placed by the drawing's extent, which moves with one point or another, and belongs to
the position it is drawn at alone: it is hidden while the input turns."""


def _afar(items: list[list], fig: Figure, named) -> None:
    """Leave what stands on nothing (:data:`AFAR` or more from its point) standing on
    nothing: ``items`` as :func:`~tarsim.graphics.figure_data.figure_data` writes
    ``fig``'s, ``named`` its named points by view."""
    for item in items:
        more = item[3] if len(item) > 3 else None
        if not more or "m" not in more:
            continue
        view, triples = more["m"]
        v, points = fig.views[view], named[view]
        at = more["at"] if item[0] == "t" else item[2][:2] if item[0] == "c" else item[2]
        for i, xy in enumerate(zip(at[::2], at[1::2])):
            p = points[triples[0 if len(triples) == 3 else 3 * i]]
            if p is None or math.dist(xy, v(p)) > AFAR:
                more.pop("m")
                break


def _panels(fig: Figure, named, items: list[list]) -> dict[str, list[float]]:
    """Each polygon panel of ``fig`` (the frame round a velocity or acceleration polygon)
    as the page redraws it at each frame's scale: ``[x0, y0, width, height, caption]``
    (paper mm), the frame as drawn and the height of the caption band at its foot. The
    frame (``fr``) and its caption (``f``: the view whose panel it is; ``sc``: the scale
    statement, said again at each frame's scale) keep to the panel, which grows or
    shrinks downward with its polygon; the rest of the panel moves with the polygon or,
    as the scale bar, is hidden."""
    out = {}
    for view, word in (("velocity", "Velocity scale"), ("acceleration", "Acceleration scale")):
        v, points = fig.views.get(view), (named or {}).get(view)
        if v is None or not points or points[-1] is None:
            continue
        pole = v(points[-1])
        frames = [(k, _box(it.points)) for k, it in enumerate(fig.items)
                  if isinstance(it, Path) and it.style == "frame"
                  and _inside(pole, _box(it.points))]
        if not frames:
            continue
        k, box = min(frames, key=lambda f: (f[1][2] - f[1][0]) * (f[1][3] - f[1][1]))
        statement = next((j for j, it in enumerate(fig.items) if isinstance(it, Text)
                          and it.text.startswith(words(word)) and _inside(it.at, box)), None)
        if statement is None:
            continue
        top = min(it.at[1] - it.size for it in fig.items
                  if isinstance(it, Text) and _inside(it.at, box)
                  and abs(it.at[1] - fig.items[statement].at[1]) < 1e-6)
        for j, it in enumerate(fig.items):
            if not _inside(_points_of(it)[0], box):
                continue
            more = dict(items[j][3]) if len(items[j]) > 3 and items[j][3] else {}
            if j == k:
                more.update(f=view, fr=1)
            elif isinstance(it, Text) and abs(it.at[1] - fig.items[statement].at[1]) < 1e-6:
                more.update(f=view, **({"sc": view} if j == statement else {}))
            elif "m" in more and more["m"][0] == view:
                continue
            else:                         # the scale bar: of the drawing's own scale
                more.pop("m", None)
            if j == k or "f" in more:
                more.pop("m", None)
            items[j] = items[j][:3] + ([more] if more else [])
        out[view] = [number(box[0]), number(box[1]), number(box[2] - box[0]),
                     number(box[3] - box[1]), number(box[3] - top + 5.0)]
    return out


def _box(points) -> tuple[float, float, float, float]:
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    return min(xs), min(ys), max(xs), max(ys)


def _inside(p: tuple[float, float], box: tuple[float, float, float, float]) -> bool:
    return box[0] <= p[0] <= box[2] and box[1] <= p[1] <= box[3]


def _points_of(item: Path | Circle | Text) -> tuple[tuple[float, float], ...]:
    if isinstance(item, Path):
        return item.points
    return (item.centre,) if isinstance(item, Circle) else (item.at,)


def _bare(sols: list[Solution], named, languages) -> dict[str, Any]:
    """The mechanism alone, as a figure of no steps: for an exercise that asks nothing a
    position's figure draws. ``sols`` are the exercise solved at its position, a little
    and farther on (None where it cannot be), as :class:`PageFigures` draws them."""
    from .solution_files import heading_in

    def draw(s: Solution | None, lang: str) -> Figure | None:
        return draw_scene(Slice(s.assembly, ()), title=s.exercise.named_in(lang).mechanism.name,
                          per_cm=sols[0].work.scales.space) if s is not None else None

    drawn = {}
    for lang in languages:
        with speaking(lang):
            drawn[lang] = _both([draw(s, lang) for s in sols], named, {}, lang, _angle(sols[2]))
    return {"stem": "mechanism", "parts": [], "drawn": drawn,
            "heading": {lang: heading_in("The mechanism", lang) for lang in languages}}


def _drawn(figs: list[Figure | None], named: list, steps: dict[str, list[int]]
           ) -> dict[str, Any]:
    """A figure serialised with what each primitive needs on the page: ``figs`` are it
    and it drawn a little and farther on (None where it is not), ``named`` their named
    points."""
    fig = figs[0]
    later = [(f, n) for f, n in zip(figs[1:], named[1:]) if f is not None and n is not None]
    near = figs[1] is not None and named[1] is not None
    stands = anchors(fig, [f for f, _ in later], [named[0]] + [n for _, n in later]) \
        if near else [None] * len(fig.items)
    more, badge = [], None
    for item, stand in zip(fig.items, stands):
        extra: dict[str, Any] = {}
        swing = _swing(item, fig, named[0])
        if swing is not None:
            extra["a"], stand = swing, None
        tags = sorted({tuple(steps[s]) for s in item.steps if s in steps})
        if tags:
            extra["s"] = [v for tag in tags for v in tag]
        layer = _layer(item, badge)
        if layer:
            extra["l"] = layer
        if stand is not None:
            extra["m"] = [stand[0], [v for triple in stand[1] for v in triple]]
            if isinstance(item, Text):
                extra["at"] = [number(item.at[0]), number(item.at[1])]
        badge = item if isinstance(item, Circle) and item.style == "badge" else None
        more.append(extra or None)
    return mark_paper(figure_data(fig, more), figs[1])


def _swing(item: Path | Circle | Text, fig: Figure, named) -> list | None:
    """A compass arc from one named point to another about a third, as ``[view, [C, S,
    E]]`` (their indices in the view's named points): the page draws it again from S to
    E about C at each frame, the shorter way, as the figure draws an arc through two
    points. None for any other primitive."""
    if not (isinstance(item, Path) and item.style == "compass" and len(item.points) > 2):
        return None
    for view, points in (named or {}).items():
        v = fig.views.get(view)
        if v is None:
            continue
        paper = [v(p) if p is not None else None for p in points]

        def at(xy, paper=paper) -> int | None:
            return next((k for k, p in enumerate(paper)
                         if p is not None and math.dist(p, xy) <= EXACT), None)

        s, e = at(item.points[0]), at(item.points[-1])
        if s is None or e is None or paper[s] == paper[e]:
            continue
        r = math.dist(paper[s], item.points[1])
        for c, p in enumerate(paper):
            if p is not None and all(abs(math.dist(p, q) - math.dist(p, paper[s])) <= EXACT
                                     for q in (*item.points, paper[e])) and r > 0:
                return [view, [c, s, e]]
    return None


def _layer(item: Path | Circle | Text, badge: Circle | None) -> str | None:
    """The layer a reader may hide ``item`` with: a working line's, a label's, or a step
    number's (a badge, and the number set in it just after)."""
    if isinstance(item, Text):
        if badge is not None and item.at == badge.centre:
            return "numbers"
        return "labels" if item.italic or item.owner or item.steps else None
    if isinstance(item, Circle) and item.style == "badge":
        return "numbers"
    return _LAYERS.get(item.style)
