"""Fit a figure to its sheet by the scale it is drawn at.

The solve chooses each figure's space scale for the room a sheet leaves a drawing
(:func:`~tarsim.graphics.paper.room`), before anything is drawn; only the drawing knows
how much its labels, symbols and caption add. So a figure is drawn at that scale first;
a figure the sheet does not hold is drawn a nice step (1, 2, 5 × 10ᵏ) coarser, and one
it holds may be drawn a step finer, to fill it (:func:`fit` gives the rule). A scale the
exercise states is kept: its figure is drawn once, on a bigger page if it must be.
"""

from __future__ import annotations

from collections.abc import Callable

from tarsim.constructions.scales import nice

from .figure import Figure
from .paper import Paper, sheet_size

__all__ = ["fit", "held_by"]


def fit(draw: Callable[[float], Figure], per_cm: float, holds: Callable[[Figure], bool], *,
        fixed: bool = False, grow: bool = False) -> Figure:
    """Draw ``draw`` at ``per_cm`` (the space scale, file units per paper cm), or at the
    nice scale nearest it that ``holds`` takes.

    A figure ``holds`` refuses is drawn a nice step coarser, up to three times, until it
    is held (the last drawn, held or not). One held at its first scale is, with ``grow``,
    drawn a nice step finer while it is still held, twice at most, so the drawing fills
    its sheet; only the drawing grows, not its caption, so a step is tried only if four
    fifths of the figure grown whole is held. With ``fixed`` (the exercise states the
    scale) it is drawn once.

    Parameters
    ----------
    draw
        The figure at a space scale.
    per_cm
        The scale the solve chose.
    holds
        Whether a figure fits where it goes (:func:`held_by` a sheet, or a worked page's
        room for a panel).
    fixed
        The scale is the exercise's: draw once.
    grow
        Try finer scales too.
    """
    fig = draw(per_cm)
    first = per_cm
    for _ in range(0 if fixed else 3):
        if holds(fig):
            break
        per_cm = nice(per_cm * 1.01)
        fig = draw(per_cm)
    for _ in range(2 if grow and not fixed and per_cm == first and holds(fig) else 0):
        finer = nice(per_cm * 0.99, up=False)
        k = 0.8 * per_cm / finer
        if not holds(Figure(fig.width * k, fig.height * k)):
            break
        bigger = draw(finer)
        if not holds(bigger):
            break
        fig, per_cm = bigger, finer
    return fig


def held_by(sheet: Paper) -> Callable[[Figure], bool]:
    """Whether a figure fits on ``sheet``, upright or on its side.

    >>> from tarsim.graphics.paper import PAPERS
    >>> held_by(PAPERS["A4"])(Figure(280.0, 200.0))
    True
    """
    return lambda fig: sheet_size(fig, sheet) is not None
