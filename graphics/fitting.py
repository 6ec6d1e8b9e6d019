"""Fit a figure to its sheet by the scale it is drawn at, laying it out once.

The solve chooses each figure's space scale for the room a sheet leaves a drawing
(:func:`~tarsim.graphics.paper.room`), before anything is drawn; only the drawing knows
how much its labels, symbols and caption add. A figure the sheet does not hold at that
scale is drawn a nice step (1, 2, 5 × 10ᵏ) coarser, and one it holds may be drawn a step
finer, to fill it (:func:`chosen_scale` gives the rule). Growing, the steps are the
course's (1, 2, 2.5, 4, 5 × 10ᵏ, :func:`finer`): from 5 the next 1-2-5 step draws 2.5 times
as big, which a sheet often cannot hold where it holds 1.25 or 2 times as big. A scale the
exercise states is kept: its figure is drawn once, on a bigger page if it must be.

The rule is followed on drafts (:mod:`~tarsim.graphics.drafts`): the figure drawn whole
with its labels placed as on a blank page, in a quarter to a third of the drawing's
time. Only at the scale the rule chooses are the labels placed among the ink. A draft's
size is the figure's but for the few millimetres a label pushed off its first spot
takes, so the figure is drawn at the scale the rule, followed on drawn figures, would
choose, but where that rule's choice turns on those millimetres.

Each draft foretells the figure's size at a coarser scale (:func:`foretold`): the
drawing under the caption shrinks with the scale, the caption and margins keep their
size. Labels and symbols in the drawing keep their size too, and the frame of a scene
takes in more of its far points at a coarser scale, so the figure takes at least what
is foretold: a coarser step that cannot be held even so is not drafted.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from tarsim.constructions.scales import nice

from .drafts import drafting
from shapely import STRtree
from shapely.geometry import LineString, box

from .figure import Figure, Path, Text
from .paper import Paper, sheet_drawn_on, sheet_size

__all__ = ["fit", "chosen_scale", "foretold", "held_by", "finer", "to_sheet", "labels_on_lines",
           "COARSER", "FINER", "TRIED", "DRAFTING"]

COARSER = 3
"""The most nice steps coarser a figure the sheet refuses is drawn at."""

FINER = 4
"""The most drafting steps finer a figure the sheet holds is grown to (:func:`finer`)."""

DRAFTING = (1.0, 2.0, 2.5, 4.0, 5.0)
"""The scales a figure grows by, × 10ᵏ to the centimetre: 2.5 beside the 1-2-5 steps, as
a drawing office's 1:2.5 and 1:25 stand beside 1:2 and 1:5, and 4, as the course's slotted
lever is drawn at "1 cm = 4 cm" (lecture notes, part 2, exercise P-37)."""

TRIED = 0.8
"""A finer step is tried only if the sheet holds this share of the figure foretold at it
(:func:`foretold`): its labels, which keep their size, may still take it past the sheet."""

Holds = Callable[[Figure], bool]
Draw = Callable[[float], Figure]


def fit(draw: Draw, per_cm: float, holds: Holds, *, fixed: bool = False, grow: bool = False,
        draft: Draw | None = None) -> Figure:
    """Draw ``draw`` at ``per_cm`` (the space scale, file units per paper cm), or at the
    nice scale nearest it that ``holds`` takes, placing its labels once.

    The scale is the one :func:`chosen_scale` finds on the figure's drafts; the figure
    is then drawn at it. Should its labels take it past what holds it, where its draft
    was held, it is drawn a nice step coarser, up to the coarsest step the rule draws
    at (:data:`COARSER` steps coarser than ``per_cm``), until it is held.

    Parameters
    ----------
    draw
        The figure at a space scale.
    per_cm
        The scale the solve chose.
    holds
        Whether a figure fits where it goes (:func:`held_by` a sheet, or a worked page's
        room for a panel); a bigger figure is never held where a smaller one is not.
    fixed
        The scale is the exercise's: draw once, at it.
    grow
        Try finer scales too.
    draft
        The figure's size at a scale, foretold cheaply; by default ``draw`` drawn
        :func:`~tarsim.graphics.drafts.drafting`.
    """
    if fixed:
        return draw(per_cm)
    at = chosen_scale(draft or _drafted(draw), per_cm, holds, grow=grow)
    fig = draw(at)
    coarsest = per_cm
    for _ in range(COARSER):
        coarsest = nice(coarsest * 1.01)
    while not holds(fig) and at < coarsest:
        at = nice(at * 1.01)
        fig = draw(at)
    return fig


def chosen_scale(size: Draw, per_cm: float, holds: Holds, *, grow: bool = False) -> float:
    """The scale the rule chooses for a figure whose size at a scale is ``size``.

    The rule, step by step: a figure ``holds`` refuses is taken a nice step coarser, up
    to :data:`COARSER` times, until it is held (the last, held or not), then as far back
    by the drafting steps between (:func:`finer`) as it is still held. One held at its
    first scale is, with ``grow``, taken a drafting step finer (:func:`finer`) while it is
    still held, up to :data:`FINER` times, so the drawing fills its sheet; a step is tried
    only if :data:`TRIED` of the figure foretold at it is held.

    A coarser step the figure cannot be held at, as :func:`foretold` from the last size
    looked at, is passed by unlooked at. Growing is not foretold: the most a finer figure
    may take is foretold too loosely (its labels counted as growing) to pass a step by,
    so each step is tried on the figure as it is.
    """
    fig = size(per_cm)
    if not holds(fig):
        return _between(size, _coarser(size, fig, per_cm, holds), holds)
    return _finer(size, fig, per_cm, holds) if grow else per_cm


def _drafted(draw: Draw) -> Draw:
    def draft(per_cm: float) -> Figure:
        with drafting():
            return draw(per_cm)
    return draft


def _coarser(size: Draw, fig: Figure, at: float, holds: Holds) -> float:
    """The first of the coarser steps that is held, else the last; a step the figure
    cannot be held at, as foretold from the last looked at, is not looked at."""
    per_cm = at
    for k in range(COARSER):
        per_cm = nice(per_cm * 1.01)
        if k < COARSER - 1 and not holds(foretold(fig, at, per_cm)):
            continue
        fig, at = size(per_cm), per_cm
        if holds(fig):
            break
    return at


def _between(size: Draw, at: float, holds: Holds) -> float:
    """The finest drafting scale (:func:`finer`) between ``at``, a nice step the figure was
    taken coarser to, and the nice step before it, which was refused, that still holds it:
    from a refused 1 cm = 20 mm, 50 is tried at 40 and 25 too."""
    refused = nice(at * 0.99, up=False)
    while (step := finer(at)) > refused * (1 + 1e-9):
        if not holds(size(step)):
            break
        at = step
    return at


def finer(per_cm: float) -> float:
    """The next drafting scale (:data:`DRAFTING`) finer than ``per_cm``: less to the
    centimetre, so the figure is drawn bigger.

    >>> finer(50.0), finer(40.0), finer(25.0), finer(20.0), finer(0.1)
    (40.0, 25.0, 20.0, 10.0, 0.05)
    """
    k = math.floor(math.log10(per_cm)) + 1
    ladder = [m * 10.0 ** e for e in (k - 2, k - 1, k) for m in DRAFTING]
    return float(f"{max(v for v in ladder if v < per_cm * (1 - 1e-9)):.12g}")


def _finer(size: Draw, fig: Figure, at: float, holds: Holds) -> float:
    """The scale grown to by finer drafting steps while each is tried and held."""
    for _ in range(FINER):
        per_cm = finer(at)
        if not holds(_grown(fig, at, per_cm)):
            break
        bigger = size(per_cm)
        if not holds(bigger):
            break
        fig, at = bigger, per_cm
    return at


def _grown(fig: Figure, at: float, per_cm: float) -> Figure:
    """:data:`TRIED` of ``fig`` (drawn at ``at``) as :func:`foretold` at ``per_cm``, its
    drawing grown and its caption kept: the test a finer step passes to be tried. Grown
    whole, a figure whose caption is a large part of it was not tried at a step its sheet
    holds (the Grashof double-crank's mechanism at 1 cm = 5 mm)."""
    grown = foretold(fig, at, per_cm)
    return Figure(grown.width * TRIED, grown.height * TRIED)


def foretold(fig: Figure, at: float, per_cm: float) -> Figure:
    """The size ``fig``, drawn at ``at``, is foretold to take at ``per_cm``: its drawing
    (the whole figure, where it does not say which part that is) grown or shrunk by
    ``at / per_cm``, its caption and margins as they are. At a coarser scale the figure
    takes no less (see the module's note).

    >>> f = Figure(120.0, 100.0, drawing=(100.0, 60.0))
    >>> g = foretold(f, 10.0, 20.0)          # twice as coarse: the drawing half as big
    >>> g.width, g.height
    (70.0, 70.0)
    """
    k = at / per_cm
    w, h = fig.drawing or (fig.width, fig.height)
    return Figure(fig.width + w * (k - 1), fig.height + h * (k - 1))


def to_sheet(draw: Draw, per_cm: float) -> Figure:
    """``draw`` at ``per_cm``, the scale a figure of its own chose; or, where figures are
    :func:`~tarsim.graphics.paper.drawn_on` a sheet, :func:`fit` to that sheet: grown by
    the drafting steps while it holds the figure, or coarser where it does not. A figure
    grown whose labels lie over more of its lines (:func:`labels_on_lines`) than at
    ``per_cm`` is taken back a step at a time till they do not.

    A gear train's, a cam's, a rotor's figure is drawn this way, so ``--paper A3`` draws
    it as big as A3 holds it, as a linkage's is."""
    sheet = sheet_drawn_on()
    if sheet is None:
        return draw(per_cm)
    holds = held_by(sheet)
    at = chosen_scale(_drafted(draw), per_cm, holds, grow=True)
    if at >= per_cm * (1 - 1e-9):       # not grown: as the rule draws it
        return fit(draw, per_cm, holds, grow=True)
    base = draw(per_cm)
    crossed = labels_on_lines(base)
    while at < per_cm * (1 - 1e-9):
        fig = draw(at)
        if holds(fig) and labels_on_lines(fig) <= crossed:
            return fig
        at = _coarser_step(at)
    return base


def _coarser_step(per_cm: float) -> float:
    """The next drafting scale coarser than ``per_cm`` (the inverse of :func:`finer`).

    >>> _coarser_step(10.0), _coarser_step(40.0), _coarser_step(25.0)
    (20.0, 50.0, 40.0)
    """
    k = math.floor(math.log10(per_cm))
    ladder = [m * 10.0 ** e for e in (k, k + 1) for m in DRAFTING]
    return float(f"{min(v for v in ladder if v > per_cm * (1 + 1e-9)):.12g}")


def labels_on_lines(fig: Figure) -> int:
    """How many of ``fig``'s texts lie over one of its lines (an open path), by more than
    a graze (0.05 mm²): a figure drawn bigger whose labels its placer found less room for
    is not taken for the one it replaces."""
    strokes = [LineString(p.points).buffer(0.1) for p in fig.items
               if isinstance(p, Path) and not p.closed and len(p.points) >= 2]
    if not strokes:
        return 0
    tree = STRtree(strokes)
    out = 0
    for t in fig.items:
        if isinstance(t, Text) and t.text.strip():
            label = box(*t.box())
            out += any(label.intersection(strokes[i]).area > 0.05
                       for i in tree.query(label))
    return out


def held_by(sheet: Paper) -> Holds:
    """Whether a figure fits on ``sheet``, upright or on its side.

    >>> from tarsim.graphics.paper import PAPERS
    >>> held_by(PAPERS["A4"])(Figure(280.0, 200.0))
    True
    """
    return lambda fig: sheet_size(fig, sheet) is not None
