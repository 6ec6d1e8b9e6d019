"""The sheet a figure is printed on: A4 (the default), A3 or US letter.

A figure is drawn at its scale first, then set on the sheet, upright or turned,
whichever holds it, and centred there; the page is the sheet itself, so a figure
printed at 100 % measures true with a ruler. The drawing areas its scales are chosen
for (:func:`room`) grow with the sheet, so a bigger sheet draws the mechanism bigger.
A figure no sheet of the paper asked for holds (one drawn at a scale the exercise
states) is set on the smallest bigger standard sheet that holds it (:func:`grown`):
every page a printer takes.

A chapter that draws its figures without a sheet in mind (a gear train's, a cam's, a
rotor's, a flywheel's) draws them :func:`drawn_on` the sheet they are to be printed on:
each figure then fits its scale to that sheet (:func:`~tarsim.graphics.fitting.to_sheet`).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass

from tarsim.constructions.errors import InputError
from tarsim.constructions.scales import ROOM
from .figure import Figure, _shifted

__all__ = ["Paper", "PAPERS", "BIGGER", "paper", "room", "on_sheet", "sheet_size", "grown",
           "standard", "sheet_name", "filled", "MARGIN", "drawn_on", "sheet_drawn_on"]


@dataclass(frozen=True)
class Paper:
    """A sheet, upright: its name and its width and height in mm."""

    name: str
    width: float
    height: float

    @property
    def turned(self) -> tuple[float, float]:
        """Its width and height on its side (landscape)."""
        return self.height, self.width


PAPERS = {p.name: p for p in (Paper("A4", 210.0, 297.0), Paper("A3", 297.0, 420.0),
                              Paper("letter", 215.9, 279.4))}
"""The sheets a figure may be set on, by name."""

BIGGER = {"A4": ("A3", "A2", "A1", "A0"), "A3": ("A2", "A1", "A0"),
          "letter": ("tabloid", "A2", "A1", "A0")}
"""The standard sheets, smallest first, a figure too big for a paper is set on instead."""

_GROWN = {p.name: p for p in (Paper("A2", 420.0, 594.0), Paper("A1", 594.0, 841.0),
                              Paper("A0", 841.0, 1189.0), Paper("tabloid", 279.4, 431.8))}

_BASE = PAPERS["A4"]


def paper(name: str) -> Paper:
    """The sheet called ``name`` (any case).

    Raises
    ------
    InputError
        If there is no such sheet, naming those there are.

    >>> paper("a3").width
    297.0
    """
    for key, sheet in PAPERS.items():
        if key.lower() == name.lower():
            return sheet
    raise InputError(f"unknown paper '{name}'; choose one of {', '.join(PAPERS)}")


def room(sheet: Paper, area: tuple[float, float] = ROOM) -> tuple[float, float]:
    """A drawing area chosen for A4 (``area``, mm), grown or shrunk for ``sheet`` as the
    sheet's shorter fit to A4: an A3 sheet draws √2 times as big.

    >>> [round(v, 1) for v in room(PAPERS["A3"])]
    [212.1, 183.8]
    """
    k = min(sheet.width / _BASE.width, sheet.height / _BASE.height)
    return area[0] * k, area[1] * k


def sheet_size(fig: Figure, sheet: Paper) -> tuple[float, float] | None:
    """The sheet's size, upright or turned, that holds ``fig``: the one that leaves it the
    wider white border (a wide figure goes landscape); None if neither holds it."""
    sizes = [s for s in ((sheet.width, sheet.height), sheet.turned)
             if fig.width <= s[0] + 1e-9 and fig.height <= s[1] + 1e-9]
    return max(sizes, key=lambda s: min(s[0] - fig.width, s[1] - fig.height), default=None)


def grown(fig: Figure, sheet: Paper) -> Paper:
    """``sheet`` if it holds ``fig``, else the smallest standard sheet bigger than it that
    does (:data:`BIGGER`): a figure is never shrunk, its page grows a sheet size.

    >>> grown(Figure(228.0, 236.0), PAPERS["A4"]).name
    'A3'
    """
    bigger = [PAPERS.get(name) or _GROWN[name] for name in BIGGER.get(sheet.name, BIGGER["A4"])]
    for each in (sheet, *bigger):
        if sheet_size(fig, each) is not None:
            return each
    return each


_DRAWN_ON: ContextVar[Paper | None] = ContextVar("drawn_on", default=None)


@contextmanager
def drawn_on(sheet: Paper) -> Iterator[None]:
    """Draw the figures made within for ``sheet``: each fitted to it, not to A4's room."""
    token = _DRAWN_ON.set(sheet)
    try:
        yield
    finally:
        _DRAWN_ON.reset(token)


def sheet_drawn_on() -> Paper | None:
    """The sheet figures are being drawn for (:func:`drawn_on`), if one is."""
    return _DRAWN_ON.get()


MARGIN = 10.0
"""The white a printer may leave round a sheet (mm): what is left is the sheet's usable area."""


def filled(page: Figure) -> float:
    """How much of its sheet's usable area (the sheet less :data:`MARGIN` round it) a page
    fills: the box of all its ink over that area.

    >>> from tarsim.graphics.figure import Path
    >>> square = Path(((10.0, 10.0), (148.5, 10.0), (148.5, 200.0), (10.0, 200.0)), "link")
    >>> round(filled(Figure(297.0, 210.0, [square])), 2)    # the left half, margin to margin
    0.5
    """
    x0, y0, x1, y1 = page.bounds()
    return (x1 - x0) * (y1 - y0) / ((page.width - 2 * MARGIN) * (page.height - 2 * MARGIN))


def sheet_name(width: float, height: float) -> str:
    """The name of the standard sheet ``width`` × ``height`` mm is, either way up (its size
    in mm if none is).

    >>> sheet_name(420.0, 297.0), sheet_name(100.0, 50.0)
    ('A3', '100 × 50 mm')
    """
    for sheet in (*PAPERS.values(), *_GROWN.values()):
        if sorted((round(width, 1), round(height, 1))) == sorted((sheet.width, sheet.height)):
            return sheet.name
    return f"{width:.0f} × {height:.0f} mm"


def standard(width: float, height: float, sheet: Paper) -> tuple[float, float]:
    """The page, upright or turned, of the smallest standard sheet from ``sheet`` up
    (:func:`grown`) that holds ``width`` × ``height`` mm.

    >>> standard(298.7, 210.0, PAPERS["A4"])
    (420.0, 297.0)
    """
    return sheet_size(Figure(width, height), grown(Figure(width, height), sheet)) or (
        width, height)


def on_sheet(fig: Figure, sheet: Paper) -> Figure:
    """``fig`` centred on ``sheet`` (upright or turned, :func:`sheet_size`), the page the
    sheet; a figure neither way holds is set on the smallest bigger standard sheet that
    holds it (:func:`grown`: it is never shrunk)."""
    size = sheet_size(fig, grown(fig, sheet))
    if size is None:
        return fig
    dx, dy = (size[0] - fig.width) / 2, (size[1] - fig.height) / 2
    return Figure(size[0], size[1], [_shifted(it, dx, dy) for it in fig.items], title=fig.title,
                  views={name: v.moved(dx, dy) for name, v in fig.views.items()})
