"""Fit a figure to its sheet by the scale it is drawn at.

The solve chooses each figure's space scale for the room a sheet leaves a drawing
(:func:`~tarsim.graphics.paper.room`), before anything is drawn; only the drawing knows
how much its labels, symbols and caption add. So a figure is drawn at that scale first;
a figure the sheet does not hold is drawn a nice step (1, 2, 5 × 10ᵏ) coarser, and one
it holds may be drawn a step finer, to fill it (:func:`fit` gives the rule). A scale the
exercise states is kept: its figure is drawn once, on a bigger page if it must be.

Each drawing foretells the figure's size at a coarser scale (:func:`foretold`): the
drawing under the caption shrinks with the scale, the caption and margins keep their
size. Labels and symbols in the drawing keep their size too, and the frame of a scene
takes in more of its far points at a coarser scale, so the figure takes at least what
is foretold: a coarser step that cannot be held even so is not drawn to find out.
"""

from __future__ import annotations

from collections.abc import Callable

from tarsim.constructions.scales import nice

from .figure import Figure
from .paper import Paper, sheet_size

__all__ = ["fit", "foretold", "held_by", "COARSER", "FINER", "TRIED"]

COARSER = 3
"""The most nice steps coarser a figure the sheet refuses is drawn at."""

FINER = 2
"""The most nice steps finer a figure the sheet holds is grown to."""

TRIED = 0.8
"""A finer step is tried only if the sheet holds this share of the figure grown whole:
only the drawing grows, not its caption."""

Holds = Callable[[Figure], bool]


def fit(draw: Callable[[float], Figure], per_cm: float, holds: Holds, *,
        fixed: bool = False, grow: bool = False) -> Figure:
    """Draw ``draw`` at ``per_cm`` (the space scale, file units per paper cm), or at the
    nice scale nearest it that ``holds`` takes.

    The rule, step by step: a figure ``holds`` refuses is drawn a nice step coarser, up
    to :data:`COARSER` times, until it is held (the last drawn, held or not). One held at
    its first scale is, with ``grow``, drawn a nice step finer while it is still held, up
    to :data:`FINER` times, so the drawing fills its sheet; a step is tried only if
    :data:`TRIED` of the figure grown whole is held. With ``fixed`` (the exercise states
    the scale) it is drawn once.

    The scale that rule chooses is found with fewer drawings: from each drawing the
    figure's least size at the coarser steps is foretold (:func:`foretold`), and a step
    that is not held even so is passed by undrawn, so a figure too big for its sheet is
    drawn again at the step it is held at rather than at each step between. Growing is
    not foretold: the most a finer figure may take is foretold too loosely (its labels
    counted as growing) to pass a step by, so each step is tried on the figure as drawn.

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
        The scale is the exercise's: draw once.
    grow
        Try finer scales too.
    """
    fig = draw(per_cm)
    if fixed:
        return fig
    if not holds(fig):
        return _coarser(draw, fig, per_cm, holds)
    return _finer(draw, fig, per_cm, holds) if grow else fig


def _coarser(draw: Callable[[float], Figure], fig: Figure, at: float, holds: Holds) -> Figure:
    """The first of the coarser steps that is held, else the last; a step the figure
    cannot be held at, as foretold from the last drawing, is not drawn."""
    per_cm = at
    for k in range(COARSER):
        per_cm = nice(per_cm * 1.01)
        if k < COARSER - 1 and not holds(foretold(fig, at, per_cm)):
            continue
        fig, at = draw(per_cm), per_cm
        if holds(fig):
            break
    return fig


def _finer(draw: Callable[[float], Figure], fig: Figure, at: float, holds: Holds) -> Figure:
    """The figure grown by finer steps while each is tried and held."""
    for _ in range(FINER):
        per_cm = nice(at * 0.99, up=False)
        if not holds(_grown(fig, at, per_cm)):
            break
        bigger = draw(per_cm)
        if not holds(bigger):
            break
        fig, at = bigger, per_cm
    return fig


def _grown(fig: Figure, at: float, per_cm: float) -> Figure:
    """:data:`TRIED` of ``fig`` (drawn at ``at``) grown whole to ``per_cm``: the test a
    finer step passes to be tried."""
    k = TRIED * at / per_cm
    return Figure(fig.width * k, fig.height * k)


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


def held_by(sheet: Paper) -> Holds:
    """Whether a figure fits on ``sheet``, upright or on its side.

    >>> from tarsim.graphics.paper import PAPERS
    >>> held_by(PAPERS["A4"])(Figure(280.0, 200.0))
    True
    """
    return lambda fig: sheet_size(fig, sheet) is not None
