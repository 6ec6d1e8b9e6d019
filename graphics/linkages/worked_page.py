"""A worked-solution page: the space diagram and the polygons side by side, then the results.

Each panel arrives as a finished figure with its own caption and scale bar, so it
is placed on the page by translation only, never rescaled: a scale bar that
measured true on its own figure measures true on the page. The panels keep their
order (the space diagram first, at the top left); of the ways to lay them out in
rows or columns, the most compact one that fits the sheet is taken, and if none
fits, the smallest page that holds them (the page grows, the panels never shrink).
The results table and the notes follow under the panels. On a sheet too small for
them all (A4), they run on over as many sheets as they need
(:func:`compose_worked_sheets`), each holding as many as it can, in order. A panel that
stands alone on a sheet after the first is drawn again at the finest of the course's
scales that sheet holds (its scale stated anew), so that a run-on sheet is not left mostly
white. A right-to-left page reads from the right: its panels stand from the right margin.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace
from itertools import product

from tarsim.constructions.errors import TarsimError
from tarsim.constructions.narration import right_to_left, words

from ..figure import Figure, Path, Text, text_width
from ..fitting import labels_on_lines
from ..rtl import is_rtl, reading
from ..paper import Paper, standard
from ..typeset import spoken_numbers, typeset
from ..wrapping import wrap_formulas

__all__ = ["compose_worked_page", "compose_worked_sheets", "holds_panel", "holds_together",
           "A3", "Regrow"]

A3 = (420.0, 297.0)
"""An A3 landscape sheet, mm: the page a worked solution is kept to when it fits."""

_MARGIN = 10.0      # white round the page, mm
_GAP = 6.0          # between panels, mm
_TITLE = 5.0        # the page title's size, mm
_CELL = 3.2         # table text size, mm
_ROW = 5.6          # table row pitch, mm
_PAD = 6.0          # white between table columns, mm
_NOTE = 3.2         # note text size, mm
_NOTE_WIDTH = 250.0  # the longest line of a note, mm: a long one runs on over lines
_WORDS = 50.0       # the widest a table's words stand in a narrow table, mm

Box = tuple[float, float, float, float]

Regrow = Callable[[Callable[[Figure], bool]], Figure]
"""A panel drawn again for a sheet it stands on alone: given whether a drawing of it is
held there, the panel at the finest scale held (:func:`~tarsim.graphics.fitting.fit`)."""


# ----- the public function ----------------------------------------------------------------
def compose_worked_page(title: str, panels: Sequence[Figure], table: Sequence[Sequence[str]],
                        notes: Sequence[str] = ()) -> Figure:
    """Set ``panels`` on one page at their own scale, with the results ``table`` under them.

    Parameters
    ----------
    title
        The page's heading.
    panels
        Finished figures (each with its caption and scale bar), the space
        diagram first; they keep this order, reading left to right and down.
    table
        Rows of cells as text, the header first: "quantity | construction |
        analytic | relative error". A quantity is typeset ("V_B" with a true
        subscript); a column of numbers is set flush right, one of words flush
        left.
    notes
        Lines under the table ("α2 not given: taken as 0").

    Returns
    -------
    Figure
        The page: A3 landscape when everything fits, larger when it does not.

    Raises
    ------
    TarsimError
        If there are no panels, or a row of the table has not as many cells as
        its header.

    See Also
    --------
    graphics.polygon_panel.draw_polygon_panel : a velocity or acceleration polygon.
    graphics.scene.draw_scene : the space diagram with its construction.

    Examples
    --------
    Two small panels sit side by side on an A3 sheet, the table under them:

    >>> square = Figure(50.0, 50.0, [Path(((0.0, 0.0), (50.0, 50.0)), "link")])
    >>> page = compose_worked_page("Two panels", [square, square],
    ...                            [("quantity", "construction"), ("V_B", "1 m/s")])
    >>> page.width, page.height
    (420.0, 297.0)
    >>> sorted(p.points[0] for p in page.items if getattr(p, "style", "") == "frame")
    [(10.0, 20.0), (66.0, 20.0)]
    """
    results = _results(panels, table, notes)
    return _sheet(spoken_numbers(title), panels, results, A3)


def compose_worked_sheets(title: str, panels: Sequence[Figure], table: Sequence[Sequence[str]],
                          notes: Sequence[str] = (), sheet: tuple[float, float] = A3,
                          regrow: Sequence[Regrow | None] = ()) -> list[Figure]:
    """The panels and the results of :func:`compose_worked_page` over as few sheets of
    ``sheet`` (width, height in mm, upright; each may be turned) as hold them, in order:
    each sheet takes as many of what is left as it holds, the results last. A panel no
    sheet holds has a grown sheet of its own. Every sheet after the first is titled
    "(continued)". A panel alone on a sheet after the first (the results beside it or
    not) whose ``regrow`` (by its place in ``panels``; None or missing: kept) is given is
    drawn again as big as that sheet, upright or turned, holds it (:func:`_regrown`).

    >>> square = Figure(150.0, 150.0, [Path(((0.0, 0.0), (150.0, 150.0)), "link")])
    >>> sheets = compose_worked_sheets("Two panels", [square, square],
    ...                                [("quantity", "construction"), ("V_B", "1 m/s")],
    ...                                sheet=(210.0, 297.0))
    >>> [(s.width, s.height) for s in sheets]          # A4 on its side: a square a sheet
    [(297.0, 210.0), (297.0, 210.0)]
    """
    title = spoken_numbers(title)
    results = _results(panels, table, notes)
    items: list[Figure] = [*panels, results]
    later = words("{title} (continued)", title=title)
    groups, i = [], 0
    while i < len(items):
        j, size = _most_held(items[i:], sheet, title if not groups else later)
        groups.append((items[i:i + j], size))
        i += j
    groups = _balanced(groups, sheet, later)
    sheets = []
    for k, (group, size) in enumerate(groups):
        last = k == len(groups) - 1
        drawn = group[:-1] if last else group
        if k and len(drawn) == 1:
            at = next(i for i, p in enumerate(panels) if p is drawn[0])
            again = regrow[at] if at < len(regrow) else None
            if again is not None:
                shown = [results, _draw_results(table, notes, narrow=True)] if last else [None]
                drawn, size, foot = _regrown(again, drawn[0], shown, sheet, later, size)
                results = foot if last else results
        sheets.append(_sheet(title if not k else later, drawn, results if last else None,
                             size))
    return sheets


def _regrown(again: Regrow, panel: Figure, results: Sequence[Figure | None],
             sheet: tuple[float, float], title: str, size: tuple[float, float]
             ) -> tuple[list[Figure], tuple[float, float], Figure | None]:
    """A lone ``panel`` (with the results beside or under it, if given: set as ``results``
    offers, wide then narrow) drawn ``again`` as big as a sheet of ``sheet``, on its side
    or upright, holds it under ``title``: the biggest, with the results it was held with,
    or ``panel`` on its sheet of ``size`` with the first results where none draws it
    bigger. An upright sheet narrower than a wide table may hold the panel drawn bigger
    above the table with its long words run on over two lines."""
    best, at, kept = panel, size, results[0]
    for each, foot_fig in product(((max(sheet), min(sheet)), (min(sheet), max(sheet))),
                                  results):
        room = _room(each, title)
        foot = (foot_fig.width, foot_fig.height) if foot_fig is not None else (0.0, 0.0)

        def holds(fig: Figure, room=room, foot=foot) -> bool:
            _, (w, h) = _choose_layout([(fig.width, fig.height)], foot, room)
            return w <= room[0] + 1e-9 and h <= room[1] + 1e-9

        fig = again(holds)
        if holds(fig) and fig.width * fig.height > best.width * best.height + 1e-6 and \
                labels_on_lines(fig) <= labels_on_lines(panel):
            best, at, kept = fig, each, foot_fig
    return [best], at, kept


def _balanced(groups: list[tuple[list[Figure], tuple[float, float]]],
              sheet: tuple[float, float], title: str
              ) -> list[tuple[list[Figure], tuple[float, float]]]:
    """``groups`` with a results table left alone on the last sheet given the panels
    before it that sheet also holds (the last of the sheet before, while that keeps one):
    a table stands beside a figure where one fits, not on a sheet of its own."""
    while len(groups) > 1 and len(groups[-1][0]) == 1 and len(groups[-2][0]) > 1:
        moved = [groups[-2][0][-1], *groups[-1][0]]
        j, size = _most_held(moved, sheet, title)
        if j < len(moved):
            break
        before, at = groups[-2]
        groups = [*groups[:-2], (before[:-1], at), (moved, size)]
    return groups


def _results(panels: Sequence[Figure], table: Sequence[Sequence[str]],
             notes: Sequence[str]) -> Figure:
    """The results table and notes as a figure, once the panels and the rows are checked."""
    if not panels:
        raise TarsimError("a worked page needs at least one panel to show")
    if any(len(row) != len(table[0]) for row in table):
        bad = next(i for i, row in enumerate(table) if len(row) != len(table[0]))
        raise TarsimError(f"row {bad} of the results table has {len(table[bad])} cells, but the "
                          f"header has {len(table[0])}; give every row as many")
    return _draw_results(table, notes)


def _title_lines(title: str, size: tuple[float, float]) -> list[str]:
    """The page's title broken to the width of a sheet of ``size`` within its margins,
    never inside a formula."""
    return wrap_formulas(title, _TITLE, size[0] - 2 * _MARGIN,
                         measure=lambda t: Text((0.0, 0.0), t, _TITLE, weight="bold").width)


def _top(title: str, size: tuple[float, float]) -> float:
    """Where the panels start on a sheet of ``size``: under its title's lines."""
    return _MARGIN + (len(_title_lines(title, size)) + 1) * _TITLE


def _room(size: tuple[float, float], title: str = "") -> tuple[float, float]:
    """What a sheet of ``size`` holds under its ``title``, within its margins."""
    return size[0] - 2 * _MARGIN, size[1] - _top(title, size) - _MARGIN


def holds_panel(sheet: tuple[float, float], panel: Figure) -> bool:
    """Whether a sheet of ``sheet`` (mm, upright; it may be turned) holds ``panel`` under its
    title: a worked page's panel drawn too big for it is drawn again smaller."""
    return any(panel.width <= r[0] + 1e-9 and panel.height <= r[1] + 1e-9
               for r in (_room((max(sheet), min(sheet))), _room((min(sheet), max(sheet)))))


def holds_together(sheet: tuple[float, float], panels: Sequence[Figure], title: str = ""
                   ) -> bool:
    """Whether one sheet of ``sheet`` (mm, upright; it may be turned) holds every one of
    ``panels`` under ``title``: a worked page's space diagram is drawn bigger only while
    the polygon beside it still shares its sheet."""
    return _most_held([*panels, Figure(0.0, 0.0)], sheet, title)[0] == len(panels) + 1


def _most_held(items: Sequence[Figure], sheet: tuple[float, float], title: str = ""
               ) -> tuple[int, tuple[float, float]]:
    """How many of ``items`` (panels, the results last) one sheet holds, the most first,
    and the sheet's size, on its side or upright: landscape first, as panels sit side by
    side. One at least, on a sheet grown for it if it must be."""
    sizes = [(max(sheet), min(sheet)), (min(sheet), max(sheet))]
    for j in range(len(items), 0, -1):
        group = items[:j]
        ends = j == len(items)
        panels = group[:-1] if ends else group
        foot = (group[-1].width, group[-1].height) if ends else (0.0, 0.0)
        for size in sizes:
            room = _room(size, title)
            _, (w, h) = _choose_layout([(p.width, p.height) for p in panels] or [(0.0, 0.0)],
                                       foot, room)
            if w <= room[0] + 1e-9 and h <= room[1] + 1e-9:
                return j, size
    return 1, sizes[0]


def _sheet(title: str, panels: Sequence[Figure], results: Figure | None,
           size: tuple[float, float]) -> Figure:
    """One sheet of ``size`` (grown to the smallest standard sheet that holds them if it
    must be, :func:`~tarsim.graphics.paper.standard`): the title, the panels framed, then
    the results if given."""
    top = _top(title, size)
    foot = (results.width, results.height) if results is not None else (0.0, 0.0)
    sizes = [(p.width, p.height) for p in panels] or [(0.0, 0.0)]
    spots, (w, h) = _choose_layout(sizes, foot, _room(size, title))
    needs = (w + 2 * _MARGIN, top + h + _MARGIN)
    if needs[0] > size[0] + 1e-9 or needs[1] > size[1] + 1e-9:
        size = standard(*needs, Paper("", min(size), max(size)))
    page = Figure(size[0], size[1], title=title)
    reads = reading(page.width)
    for k, line in enumerate(_title_lines(title, size)):
        page.add(Text((reads.x(_MARGIN), _MARGIN + _TITLE / 2 + k * _TITLE), line, _TITLE,
                      reads.anchor, italic=False, weight="bold"))
    if reads.rtl:     # read from the right: the first panel stands at the top right,
        across = size[0] - 2 * _MARGIN     # from the right margin
        spots = [(across - x - p[0], y) for (x, y), p in zip(spots, sizes + [foot])]
    for panel, (x, y) in zip(panels, spots):
        _place_panel(page, panel, (_MARGIN + x, top + y), frame=True)
    if results is not None:
        x, y = spots[-1]
        _place_panel(page, results, (_MARGIN + x, top + y), frame=False)
    return page


# ----- layout -----------------------------------------------------------------------------------
def _choose_layout(sizes: list[tuple[float, float]], foot: tuple[float, float],
                   room: tuple[float, float]
                   ) -> tuple[list[tuple[float, float]], tuple[float, float]]:
    """Where each panel and then the results (``foot``) go, and the extent of them all.

    Every split of the panels, in order, into rows (each read left to right) or
    into columns (each read down) is tried. The results come last: at the end of
    the last row, under the last panel (beside a taller one), or under everything.
    The layout that grows the page least past ``room`` wins (none, if it fits); of
    those, the one whose shape suits the room best (it would fit the smallest copy of
    the room), then the most compact. Returns the top-left corner of each panel, then
    of the results.
    """
    best = None
    for across, under in ((True, False), (True, True), (False, False)):
        items = sizes + [foot] if across and not under else sizes
        for cuts in product((False, True), repeat=len(items) - 1):
            spots, extent = _shelves(items, _split(list(range(len(items))), cuts), across)
            if under:               # the results under the last panel, in the room a
                x, y = spots[-1]    # taller one beside it leaves
                below = y + sizes[-1][1] + _GAP
                spots.append((x, below))
                extent = (max(extent[0], x + foot[0]), max(extent[1], below + foot[1]))
            elif not across:        # the results under the columns, flush left
                below = extent[1] + (_GAP if foot[1] > 0 else 0.0)
                spots.append((0.0, below))
                extent = (max(extent[0], foot[0]), below + foot[1])
            page = max(room[0], extent[0]) * max(room[1], extent[1])
            fill = max(extent[0] / room[0], extent[1] / room[1])
            key = (round(page, 6), round(fill, 9), round(extent[0] * extent[1], 6))
            if best is None or key < best[0]:
                best = (key, spots, extent)
    return best[1], best[2]


def _split(items: list[int], cuts: tuple[bool, ...]) -> list[list[int]]:
    """Cut ``items`` into runs: a True cut starts a new run after that item."""
    groups = [[items[0]]]
    for item, cut in zip(items[1:], cuts):
        if cut:
            groups.append([item])
        else:
            groups[-1].append(item)
    return groups


def _shelves(sizes: list[tuple[float, float]], groups: list[list[int]], across: bool
             ) -> tuple[list[tuple[float, float]], tuple[float, float]]:
    """Lay out ``groups`` as rows (``across``) or as columns; panels top- or left-aligned."""
    k = 0 if across else 1            # the axis a group runs along
    spots = [(0.0, 0.0)] * len(sizes)
    offset, extent = 0.0, 0.0
    for group in groups:
        run = 0.0
        for i in group:
            spots[i] = (run, offset) if across else (offset, run)
            run += sizes[i][k] + _GAP
        depth = max(sizes[i][1 - k] for i in group)
        extent = max(extent, run - _GAP)
        offset += depth + _GAP
    offset -= _GAP
    return spots, ((extent, offset) if across else (offset, extent))


def _place_panel(page: Figure, panel: Figure, at: tuple[float, float], *, frame: bool) -> None:
    """Copy ``panel`` onto ``page`` with its top-left corner ``at``, in a thin ``frame``.

    A copy is moved, never scaled, so the panel's scale bar still measures true.
    """
    copy = Figure(panel.width, panel.height, list(panel.items), views=dict(panel.views))
    copy.shift(*at)
    x, y = at
    if frame:
        page.add(Path(((x, y), (x + panel.width, y), (x + panel.width, y + panel.height),
                       (x, y + panel.height)), "frame", closed=True))
    page.items.extend(copy.items)
    page.views.update(copy.views)


# ----- the results table --------------------------------------------------------------------
def _cell(text: str, first: bool, bold: bool) -> Text:
    """Set a cell: a quantity typeset with its subscript, a Coriolis term as 2ω × v with
    the subscript rel, anything else as given."""
    if first and not bold:
        head, sub = typeset(text)
        return Text((0.0, 0.0), head, _CELL, "start", italic=True, sub=sub)
    if not bold and "2ω×v_rel" in text and not is_rtl(text):     # (a subscript among
        # right-to-left words would split the cell into runs: it is kept as written there)
        head, _, tail = text.partition("2ω×v_rel")
        return Text((0.0, 0.0), f"{head}2ω × v", _CELL, "start", italic=False, sub="rel",
                    tail=tail)
    return Text((0.0, 0.0), text, _CELL, "start", italic=False, weight="bold" if bold else "normal")


def _numeric(table: Sequence[Sequence[str]], k: int) -> bool:
    """Tell whether column ``k`` holds numbers (set flush right) rather than words."""
    return k > 0 and all(row[k][:1] in _DIGITS and row[k] for row in table[1:] if row[0])


_DIGITS = "0123456789۰۱۲۳۴۵۶۷۸۹-−+."
"""What a number opens with, in Latin or Persian digits."""


def _column_widths(table: Sequence[Sequence[str]]) -> list[float]:
    if not table:
        return []
    return [max(_cell(row[k], k == 0, r == 0).width for r, row in enumerate(table))
            for k in range(len(table[0]))]


def _draw_results(table: Sequence[Sequence[str]], notes: Sequence[str],
                  narrow: bool = False) -> Figure:
    """Draw the results table and the notes under it as a figure of their own (origin
    top-left); ``narrow``, its long words run on over lines (:func:`_narrowed`)."""
    if narrow:
        table = _narrowed(table)
    fig = Figure(0.0, 0.0)
    y = _draw_table(fig, table, (0.0, 0.5 * _ROW)) + (2.0 if notes else 0.0) if table else 0.0
    lines = [line for note in notes
             for line in wrap_formulas(spoken_numbers(note), _NOTE, _NOTE_WIDTH)]
    widths = _column_widths(table)
    fig.width = max([sum(widths) + _PAD * max(len(widths) - 1, 0)]
                    + [text_width(n, _NOTE) for n in lines])
    reads = reading(fig.width)
    edge, anchor = reads.x(0.0), reads.anchor
    for line in lines:
        fig.add(Text((edge, y + 0.7 * _NOTE), line, _NOTE, anchor, italic=False))
        y += 1.4 * _NOTE
    fig.height = y
    return fig


def _narrowed(table: Sequence[Sequence[str]]) -> list[list[str]]:
    """``table`` with each word cell wider than :data:`_WORDS` run on over the rows after
    its own, broken between words, never inside a formula (a method's "(rolling contact:
    the contact point)"); the quantity and the columns of numbers are never broken."""
    out = [list(table[0])]
    for row in table[1:]:
        runs = [[text] if k == 0 or _numeric(table, k) else
                wrap_formulas(text, _CELL, _WORDS, measure=lambda t: _cell(t, False, False).width)
                for k, text in enumerate(row)]
        out += [[run[j] if j < len(run) else "" for run in runs]
                for j in range(max(map(len, runs)))]
    return out


def _draw_table(page: Figure, table: Sequence[Sequence[str]], at: tuple[float, float]) -> float:
    """Set the results ``table`` from ``at`` (the first row's centre line, left end).

    The header is bold over a thin rule; words read flush left, columns of
    numbers flush right. Returns the bottom of the last row.
    """
    widths = _column_widths(table)
    lefts = [at[0] + sum(widths[:k]) + _PAD * k for k in range(len(widths))]
    rtl = right_to_left()
    if rtl:     # a right-to-left table reads from the right: its first column stands there
        span = lefts[-1] + widths[-1] + at[0]
        lefts = [span - x - w for x, w in zip(lefts, widths)]
    y = at[1]
    for r, row in enumerate(table):
        for k, text in enumerate(row):
            t = _cell(text, k == 0, r == 0)
            if _numeric(table, k):
                page.add(Text((lefts[k] + widths[k], y), t.text, t.size, "end", False, t.weight))
            elif rtl:
                page.add(replace(t, at=(lefts[k] + widths[k], y), anchor="end"))
            else:
                page.add(replace(t, at=(lefts[k], y)))
        if r == 0:
            rule = y + 0.5 * _ROW
            page.add(Path(((min(lefts), rule), (max(x + w for x, w in zip(lefts, widths)), rule)),
                          "dimension"))
        y += _ROW
    return y - 0.5 * _ROW
