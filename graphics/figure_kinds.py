"""The kinds of figure an answer is drawn in, each with the drawing it registers.

A solution names each of its figures by a
:class:`~tarsim.constructions.checks.FigureSpec`, whose ``kind`` is one of
:data:`~tarsim.constructions.checks.FIGURE_KINDS`. A chapter's package of graphics
registers how it draws a kind (:func:`figure_kind`) in its ``figures`` module, which is
found and imported when a kind is first asked for: a new chapter's kinds are registered
by being there. From what the solution hands over (a :class:`FigureOrder`: the spec, the
answers the figure holds, the work they were drawn in, the sheet and the words the
solution says), a kind plans its figure (a :class:`FigurePlan`: the slice it shows,
which steps.md narrates, and how it is drawn, fitted to the sheet by
:func:`~tarsim.graphics.fitting.fit`). :func:`plan_figure` finds the kind's drawing, so
a solution names no kind.
"""

from __future__ import annotations

import pkgutil
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache
from importlib import import_module
from importlib.util import find_spec

from tarsim.constructions.checks import FIGURE_KINDS, Answer, FigureSpec
from tarsim.constructions.linkages.assembly_record import Assembly
from tarsim.constructions.methods import Work
from tarsim.constructions.model import Mechanism
from tarsim.constructions.narration import narrate, spoken, words
from tarsim.constructions.record import Panel, Slice, slice

from .figure import Figure
from .paper import Paper

__all__ = ["FigureOrder", "FigurePlan", "figure_kind", "plan_figure", "registered",
           "comes_last"]


@dataclass(frozen=True)
class FigureOrder:
    """What a solution hands a kind of figure to draw.

    The figure ``spec`` holds the ``answers``, drawn in ``work`` (the record of a
    position, or of the mechanism as a whole, and its scales); ``mechanism`` is the
    exercise's, as its file gives it (its name, units and any scale it states), and
    the figure is set on ``sheet``. ``where`` says the position, when the solution
    has several to tell apart; ``said`` puts a figure's heading into the language
    spoken; ``notes`` gives the words the solution sets under a panel's figure (by
    default the work's own notes); ``table`` the rows of the results table a worked
    page ends with.
    """

    spec: FigureSpec
    answers: tuple[Answer, ...]
    work: Work
    mechanism: Mechanism
    sheet: Paper
    where: str | None = None
    said: Callable[[str], str] = str
    notes: Callable[[Panel], list[str]] | None = None
    table: Callable[[], list[tuple[str, ...]]] | None = None

    @property
    def record(self) -> Assembly:
        """The mechanism's position, drawn by compass, with every construction's steps."""
        return self.work.assembly

    @property
    def stated(self) -> bool:
        """Whether the exercise states its space scale (a figure is drawn at it, unfitted)."""
        return bool(self.mechanism.scale)

    def shown(self, *, base=None, panel: Panel | None = None) -> Slice:
        """The slice of the answers' steps (those of ``panel`` only, if given), walked back
        to ``base`` (by default the steps that placed the position's points)."""
        c = self.record
        refs = [r for a in self.answers for r in a.refs if panel is None or c[r].panel is panel]
        arrows = [r for a in self.answers for r in a.arrows]
        return slice(c, list(dict.fromkeys(refs)),
                     base=c.position_steps if base is None else base,
                     arrows=list(dict.fromkeys(arrows)))

    def under(self, panel: Panel) -> list[str]:
        """The words set under the figure of ``panel``."""
        if self.notes is not None:
            return self.notes(panel)
        return [narrate(text, spoken()) for p, text in self.work.notes if p is panel]

    def title(self, what: str, *, placed: bool = True) -> str:
        """A figure's title in the language spoken: the mechanism's name, what the figure
        shows ("V_B by radius rotation") and, if ``placed``, the position it is drawn at
        when the solution has several."""
        name, what = self.mechanism.name, self.said(what)
        if not placed or self.where is None:
            return words("{name}: {what}", name=name, what=what)
        return words("{name}: {what} at {where}", name=name, what=what, where=self.where)


@dataclass(frozen=True)
class FigurePlan:
    """A figure before it is drawn: how to draw it, and what of the record it shows.

    ``shown`` is the slice of the space diagram's construction that steps.md narrates
    under the figure's heading; ``panels`` each further part's heading, panel and slice
    (a fourth item marks a part narrated though no figure of its own draws it).
    """

    draw: Callable[[], Figure]
    shown: Slice | None = None
    panels: tuple[tuple, ...] = ()


@dataclass(frozen=True)
class _Kind:
    plan: Callable[[FigureOrder], FigurePlan]
    last: bool


_KINDS: dict[str, _Kind] = {}


def figure_kind(kind: str, *, last: bool = False):
    """Register the decorated function as the way figures of ``kind`` are planned; one
    ``last`` (the worked page) comes after a position's other figures.

    Raises
    ------
    ValueError
        If ``kind`` is not one of :data:`~tarsim.constructions.checks.FIGURE_KINDS`, or
        is registered already.
    """
    if kind not in FIGURE_KINDS or kind in _KINDS:
        raise ValueError(f"{kind!r} is {'already registered' if kind in _KINDS else 'no kind'}"
                         f" of figure; the kinds are {', '.join(map(repr, FIGURE_KINDS))}")

    def register(plan: Callable[[FigureOrder], FigurePlan]):
        _KINDS[kind] = _Kind(plan, last)
        return plan
    return register


def registered() -> dict[str, Callable[[FigureOrder], FigurePlan]]:
    """Every kind of figure registered, with the function that plans it."""
    _register_all()
    return {kind: k.plan for kind, k in _KINDS.items()}


@cache
def _register_all() -> None:
    """Import the ``figures`` module of each package of graphics that has one."""
    for package in pkgutil.iter_modules(import_module(__package__).__path__):
        name = f"{__package__}.{package.name}.figures"
        if package.ispkg and find_spec(name) is not None:
            import_module(name)


def plan_figure(order: FigureOrder) -> FigurePlan:
    """Plan the figure ``order`` asks for, as its kind does."""
    return registered()[order.spec.kind](order)


def comes_last(spec: FigureSpec) -> bool:
    """Whether the figure of ``spec`` comes after a position's others: its kind is
    registered ``last`` (the worked page)."""
    _register_all()
    return _KINDS[spec.kind].last
