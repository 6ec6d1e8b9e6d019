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
from dataclasses import replace
from functools import partial
from typing import Any

from tarsim.constructions.errors import TarsimError
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.linkages.kennedy import locate_centres
from tarsim.constructions.narration import narrate, speaking
from tarsim.constructions.record import Panel, Role, Slice
from tarsim.graphics.figure import Circle, Figure, Path, Text
from tarsim.graphics.figure_anchors import Named, anchors
from tarsim.graphics.figure_data import figure_data, number
from tarsim.graphics.linkages.scene import draw_scene
from .exercise_file import Exercise
from .solution import Overall, Solution, solve_positions

__all__ = ["PageFigures", "named_points", "NEXT", "FAR"]

NEXT = 0.05
"""Degrees further on the input turns for the second drawing a figure's primitives are
matched against: little enough that every label and symbol is chosen as at the position
itself, enough that the links turn by more than rounding."""

FAR = 15.0
"""Degrees further on for a third drawing, in the first language only (the symbols are
drawn alike in every language): it tells what turns with a link that stands still at the
exercise's position (a slotted lever at its limit) from what does not turn."""

_LAYERS = {"kennedy": "kennedy", "working": "construction", "compass": "construction",
           "gauge": "construction", "normal": "construction", "construction": "construction"}
"""The layer of a primitive by its style: the working lines a reader may hide."""


class PageFigures:
    """The figures of ``sol`` (the exercise ``ex`` solved at its first position) that
    number steps, as the page shows them; the mechanism alone if none does.

    Each is drawn at the position, a little on and farther on, by :meth:`jobs` (to be run
    beside the frames, on every core), and then serialised by :meth:`figures`. ``names``
    are the named points of each view the frames send, ``sense`` the way the input turns
    (±1), ``room`` the drawing's room the solution chose its scales for.
    """

    def __init__(self, ex: Exercise, sol: Solution, names: dict[str, list[str]], sense: float,
                 room: tuple[float, float], languages: tuple[str, ...]):
        self.ex, self.languages = ex, languages
        self.sols = [sol, *(_further(sol, sense * step, room) for step in (NEXT, FAR))]
        self.named = [named_points(s, names) if s is not None else None for s in self.sols]
        # What each job draws: a language and a drawing (at the position, a little on,
        # farther on: that one in the first language only, for it serves them all).
        self.todo = [(lang, k) for lang in languages for k, s in enumerate(self.sols)
                     if s is not None and (k < 2 or lang == languages[0])]

    def jobs(self) -> list[Callable[[], dict[str, Figure]]]:
        """A job for each drawing: it returns the figures by stem."""
        return [partial(_figures_in, self.ex, self.sols[k], lang) for lang, k in self.todo]

    def figures(self, done: list[dict[str, Figure]]) -> list[dict[str, Any]]:
        """The figures as the page shows them, from what the jobs drew (in their order)."""
        from .solution_files import figure_parts

        drawn: dict[str, dict[str, list]] = {}
        for (lang, k), figs in zip(self.todo, done):
            for stem, fig in figs.items():
                drawn.setdefault(stem, {}).setdefault(lang, [None] * 3)[k] = fig
        first = self.languages[0]
        for by_lang in drawn.values():
            for lang in self.languages[1:]:
                by_lang.setdefault(lang, [None] * 3)[2] = by_lang.get(first, [None] * 3)[2]
        out = []
        for stem, heading, parts in figure_parts(self.sols[0]):
            by_lang = drawn.get(stem, {})
            if any(by_lang.get(lang, [None])[0] is None for lang in self.languages) or \
                    not any(shown.numbered(panel) for _, panel, shown in parts):
                continue
            out.append(_figure(stem, heading, parts, by_lang, self.named, self.languages))
        return out or [_bare(self.sols, self.named, self.languages)]


def _figures_in(ex: Exercise, sol: Solution, lang: str) -> dict[str, Figure]:
    """The figures ``sol`` is drawn in, by stem, as `tarsim solve --lang` draws them in
    ``lang``: titled with the mechanism's name in it, if its file gives one."""
    ex, sol = ex.named_in(lang), replace(sol, exercise=sol.exercise.named_in(lang))
    with speaking(lang):
        return {f.stem: f.figure for f in _pages(ex, sol)}


def named_points(sol: Solution, names: dict[str, list[str]]) -> Named:
    """The named points of each view where ``sol`` draws them: its joints and the instant
    centres, and its polygons' poles and tips, in the order of ``names``."""
    asm = sol.assembly
    space = {n: asm.xy(n) for n in asm.mechanism.point_names}
    try:
        cs = locate_centres(assemble(asm.mechanism))
        for c in cs.primaries + cs.secondaries:
            p = cs.point(*c.pair)
            space[c.label] = None if p.is_at_infinity else p.xy
    except TarsimError:                      # Kennedy cannot reach them here
        pass
    out = {"space": [space.get(n) for n in names["space"]]}
    for view, poly in (("velocity", sol.velocity_polygon),
                       ("acceleration", sol.acceleration_polygon)):
        if poly is not None:
            at = {n: asm.output(ref).xy for n, ref in poly.tips.items()}
            at["pole"] = asm.output(poly.pole).xy
            out[view] = [at.get(n) for n in names[view]]
    return out


def _pages(ex: Exercise, sol: Solution) -> list:
    """The figures ``sol`` is drawn in, as `tarsim solve` draws them, in the language
    spoken."""
    from .solution_files import WorkedSolution

    return WorkedSolution(ex, Overall(), [sol]).pages


def _further(sol: Solution, degrees: float, room) -> Solution | None:
    """``sol``'s exercise solved with its input turned ``degrees`` on (or back, where it
    cannot go on); None where it can go neither way."""
    drive = sol.exercise.mechanism.drive
    for way in (1.0, -1.0):
        m = sol.exercise.mechanism.with_drive(
            replace(drive, angle=drive.angle + way * math.radians(degrees)))
        try:
            return solve_positions(replace(sol.exercise, mechanism=m, positions=()),
                                   room=room)[0]
        except TarsimError:
            continue
    return None


def _figure(stem: str, heading: str, parts: list, by_lang: dict, named, languages
            ) -> dict[str, Any]:
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
            "drawn": {lang: _drawn(figs, named, steps) for lang, figs in by_lang.items()}}


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
            drawn[lang] = _drawn([draw(s, lang) for s in sols], named, {})
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
    return figure_data(fig, more)


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
