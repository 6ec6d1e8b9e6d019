"""The sheet a figure is printed on: A4 (the default), A3 or US letter.

A figure is drawn at its scale first, then set on the sheet, upright or turned,
whichever holds it, and centred there; the page is the sheet itself, so a figure
printed at 100 % measures true with a ruler. The drawing areas its scales are chosen
for (:func:`room`) grow with the sheet, so a bigger sheet draws the mechanism bigger.
"""

from __future__ import annotations

from dataclasses import dataclass

from tarsim.constructions.errors import InputError
from tarsim.constructions.scales import ROOM
from .figure import Figure, _shifted

__all__ = ["Paper", "PAPERS", "paper", "room", "on_sheet", "sheet_size"]


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


def on_sheet(fig: Figure, sheet: Paper) -> Figure:
    """``fig`` centred on ``sheet`` (upright or turned, :func:`sheet_size`), the page the
    sheet; a figure neither way holds keeps its own page (it is never shrunk)."""
    size = sheet_size(fig, sheet)
    if size is None:
        return fig
    dx, dy = (size[0] - fig.width) / 2, (size[1] - fig.height) / 2
    return Figure(size[0], size[1], [_shifted(it, dx, dy) for it in fig.items], title=fig.title,
                  views={name: v.moved(dx, dy) for name, v in fig.views.items()})
