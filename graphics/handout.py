"""The problem sheet an instructor hands out: the mechanism as given, what is asked, and an
empty frame at its scale for each polygon the student is to draw, with no answer on it.

The sheet is made of the parts a worked page is made of (:mod:`.linkages.worked_page`):
finished panels, each with its own caption and scale bar, set side by side and never
rescaled, so that every scale bar measures true on the printed sheet. What a handout adds
is two kinds of panel: the statement (the data given and the quantities asked, in the
course's words and symbols) and the empty frame of a polygon, sized to hold the polygon
the solution draws at the same scale, its pole marked where the solution's stands, so that
a drawing made in it lies over the solution's as a grader overlays them.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

from tarsim.constructions.errors import TarsimError

from .figure import Circle, Figure, Path, Text
from .linkages.worked_page import compose_worked_sheets
from .rtl import reading
from .scales import draw_caption

__all__ = ["Line", "draw_statement", "draw_empty_polygon", "compose_handout", "FRAME_MARGIN",
           "FRAME_STYLE"]

FRAME_STYLE = "plot_frame"
"""A polygon's frame is drawn as a plot's is, black, apart from the grey frames of a page's
panels."""

FRAME_MARGIN = 8.0
"""White (mm) between the polygon the frame is sized for and the frame, each side."""

_SIZE = 3.4         # the statement's text size, mm
_PITCH = 5.6        # its line pitch, mm
_INDENT = 4.0       # a line under a heading is set in by this much, mm
_POLE = 1.0         # the pole's dot's radius, mm (as a polygon panel draws it)


@dataclass(frozen=True, slots=True)
class Line:
    """One line of the statement: ``text`` as the language says it, after a ``symbol`` (its
    text and true subscript, ``("V", "B")``) if it names one; a ``heading`` is set bold,
    flush with the margin, and the lines under it are set in."""

    text: str
    symbol: tuple[str, str] | None = None
    heading: bool = False


def draw_statement(lines: Sequence[Line], *, width: float | None = None) -> Figure:
    """Set the statement's ``lines`` as a panel (origin top-left), read as the language
    spoken reads: from the right margin in Persian, a symbol first on its line either way.

    Parameters
    ----------
    lines
        The headings ("Given", "Find") and the lines under each.
    width
        The panel's width (mm); by default its longest line's.

    Returns
    -------
    Figure
        The panel, its size that of its lines with a margin of 4 mm.

    Raises
    ------
    TarsimError
        If there is no line to set.

    Examples
    --------
    >>> fig = draw_statement([Line("Given", heading=True), Line("O₂A = 100 mm"),
    ...                       Line(", the velocity of B", symbol=("V", "B"))])
    >>> [(t.text, t.sub) for t in fig.items]
    [('Given', ''), ('O₂A = 100 mm', ''), ('V', 'B'), (', the velocity of B', '')]
    """
    if not lines:
        raise TarsimError("a problem statement needs a line to say")
    margin = 4.0
    rows = []
    for ln in lines:
        symbol = Text((0.0, 0.0), ln.symbol[0], _SIZE, sub=ln.symbol[1]) if ln.symbol else None
        said = Text((0.0, 0.0), ln.text, _SIZE, italic=False,
                    weight="bold" if ln.heading else "normal")
        rows.append((ln, symbol, said))
    needed = max((0.0 if ln.heading else _INDENT) + (sym.width if sym else 0.0) + said.width
                 for ln, sym, said in rows)
    fig = Figure(round(max(width or 0.0, needed + 2 * margin), 1), 0.0)
    reads = reading(fig.width)
    y = margin + _SIZE / 2
    for ln, sym, said in rows:
        if ln.heading and y > margin + _SIZE:
            y += 0.5 * _PITCH           # a heading stands off what comes before it
        at = margin + (0.0 if ln.heading else _INDENT)
        if sym is not None:             # a symbol reads left to right, wherever it stands
            fig.add(replace(sym, at=(reads.x(at), y), anchor=reads.anchor))
            at += sym.width
        fig.add(replace(said, at=(reads.x(at), y), anchor=reads.anchor))
        y += _PITCH
    fig.height = round(y - _PITCH + _SIZE / 2 + margin + 4.0, 1)
    return fig


def draw_empty_polygon(title: str, *, reach: tuple[float, float, float, float],
                       per_cm: float, unit: str, scale_name: str,
                       pole: tuple[str, str], cranks=None) -> Figure:
    """Draw the empty frame a polygon is to be drawn in, at its scale, its pole marked.

    Parameters
    ----------
    title
        The caption's heading ("Velocity polygon").
    reach
        How far the polygon reaches from its pole (mm on paper, x right and y down):
        left, up, right and down, each 0 or more. The frame holds that with
        :data:`FRAME_MARGIN` to spare each side.
    per_cm
        The scale, file units per paper cm (a stated one keeps its statement).
    unit
        The unit the scale is stated in ("mm/s").
    scale_name
        What opens the scale statement ("Velocity scale").
    pole
        The pole's name as text and subscript: ``("o", "v")``.
    cranks
        An engine's :class:`~.balancing.crank_view.CrankView`, set beside the frame as the
        solution sets it beside its polygon (the cranks' directions the polygon is laid
        along); None for none.

    Returns
    -------
    Figure
        The frame with its pole, its caption, the scale statement and its bar.

    Raises
    ------
    TarsimError
        If a reach is negative or not a number.

    Examples
    --------
    A polygon reaching 60 mm right of its pole and 20 mm up and down:

    >>> fig = draw_empty_polygon("Velocity polygon", reach=(0.0, 20.0, 60.0, 20.0),
    ...                          per_cm=5.0, unit="mm/s", scale_name="Velocity scale",
    ...                          pole=("o", "v"))
    >>> frame = next(p for p in fig.items if getattr(p, "style", "") == FRAME_STYLE)
    >>> xs, ys = zip(*frame.points)
    >>> max(xs) - min(xs), max(ys) - min(ys)
    (76.0, 56.0)
    >>> "Velocity scale 1 cm = 5 mm/s" in [getattr(t, "text", "") for t in fig.items]
    True
    """
    if not all(r >= 0.0 for r in reach):       # a NaN is refused too
        raise TarsimError(f"a polygon's reach from its pole must be 0 or more mm; got {reach}")
    x0, y0 = -reach[0] - FRAME_MARGIN, -reach[1] - FRAME_MARGIN
    x1, y1 = reach[2] + FRAME_MARGIN, reach[3] + FRAME_MARGIN
    fig = Figure(0.0, 0.0)
    fig.add(Path(((x0, y0), (x1, y0), (x1, y1), (x0, y1)), FRAME_STYLE, closed=True))
    fig.add(Circle((0.0, 0.0), _POLE, "dot"))
    fig.add(Text((2.0, -2.6), pole[0], 3.5, "start", sub=pole[1]))
    if cranks is not None:
        from .balancing.crank_view import draw_crank_view

        draw_crank_view(fig, cranks)
    draw_caption(fig, title, [], per_cm=per_cm, unit=unit, scale_name=scale_name)
    return fig


def compose_handout(title: str, panels: Sequence[Figure], notes: Sequence[str] = (), *,
                    sheet: tuple[float, float]) -> list[Figure]:
    """Set ``panels`` (the mechanism, the statement, the frames) on as few sheets of
    ``sheet`` (mm, upright; each may be turned) as hold them, each at its own scale, with
    ``notes`` at the foot; as a worked page's panels are set, and with no results table.
    """
    return compose_worked_sheets(title, panels, [], notes, sheet=sheet)
