"""Line plots of a quantity against the input angle, in the textbook's look.

A plot is a framed box with ticks, light grid lines, a zero line, one or more
curves in black and grey (solid, dashed, dotted: they read apart without colour),
open-circle marks with their labels, and the axis labels with true subscripts.
The y axis label stands over the axis, so no text is turned. Everything is placed
in paper millimetres on a :class:`~graphics.figure.Figure`, like every other
figure of tarsim; nothing here knows about mechanisms.

Text given to this module marks a subscript with an underscore, as results.json
names quantities: ``"V_B (mm/s)"`` prints V with subscript B, ``"θ_2 (°)"`` θ
with subscript 2; each ``X_Y`` in a string is set this way.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np
from shapely.geometry import Polygon, box
from shapely.ops import nearest_points, unary_union

from tarsim.constructions.narration import numerals
from tarsim.constructions.scales import nice

from .figure import Circle, Figure, Path, Text, text_width, wrap_text
from .paper import MARGIN, sheet_drawn_on
from . import plot_spots as spots
from .plot_spots import MARK_R as _MARK_R
from .rtl import is_rtl, reading
from .rtl_runs import lay_runs, sign_left

__all__ = ["Series", "PlotMark", "nice_ticks", "smallest_shown", "tick_text", "rich_text",
           "draw_line_plot", "CURVE_STYLES"]

CURVE_STYLES = ("plot_curve", "plot_curve_dashed", "plot_curve_dotted", "plot_curve_dash_dot")
"""Curve styles in the order series take them: solid black, dashed black, dotted grey,
dash-dot black."""

_WIDTH = 170.0        # page width, mm (fits A4 portrait inside its margins)
_MARGIN = 10.0        # white round the page, mm
_PLOT_H = 82.0        # height of the plotting box, mm
_TICK = 1.5           # tick length, mm (inward)
_TITLE = 4.2          # title size, mm
_SUBTITLE = 3.4       # second title line, mm
_LABEL = 3.4          # axis labels, mm
_NUMBER = 2.9         # tick numbers, mm
_MARK_TEXT = 2.7      # a mark's label, mm
_NOTE = 3.0           # notes under the plot, mm
_ASPECT = 0.6         # a plotting box grown for its sheet is at most this tall to its width
_GRID = 0.3           # what a label across a grid line costs (a curve: 1; a ring out: 0.05)

Point = tuple[float, float]
Box = tuple[float, float, float, float]


@dataclass(frozen=True)
class Series:
    """One curve: its legend label and its points; ``None`` breaks the line (a gap)."""

    label: str
    points: tuple[Point | None, ...]
    style: str = "plot_curve"


@dataclass(frozen=True)
class PlotMark:
    """A value found another way, drawn as an open circle at (x, y); ``label`` may be ""."""

    x: float
    y: float
    label: str = ""


# ----- numbers -----------------------------------------------------------------------------
def nice_ticks(lo: float, hi: float, count: int = 6) -> list[float]:
    """Return ticks at a nice step (1, 2 or 5 × 10^k) that span ``lo`` … ``hi``.

    About ``count`` intervals; the first tick is at or below ``lo``, the last at
    or above ``hi``. An empty range is widened first.

    Examples
    --------
    >>> nice_ticks(-339.6, 339.6)
    [-400.0, -200.0, 0.0, 200.0, 400.0]
    >>> nice_ticks(0.0, 0.93)
    [0.0, 0.2, 0.4, 0.6, 0.8, 1.0]
    >>> nice_ticks(5.0, 5.0)
    [4.0, 4.5, 5.0, 5.5, 6.0]
    """
    if not (math.isfinite(lo) and math.isfinite(hi)):
        raise ValueError("ticks need a finite range")
    if hi < lo:
        lo, hi = hi, lo
    if hi - lo <= 1e-12 * max(abs(lo), abs(hi), 1e-300):
        pad = abs(lo) * 0.2 if lo else 1.0
        lo, hi = lo - pad, hi + pad
    step = nice((hi - lo) / max(count, 1))
    first, last = math.floor(lo / step + 1e-9), math.ceil(hi / step - 1e-9)
    return [float(f"{i * step:.12g}") + 0.0 for i in range(first, last + 1)]


_PEN = 0.1
"""Paper (mm) below which two heights on a plot read as one: a printer's and an eye's
resolution, under half the width of the thinnest curve drawn."""


def smallest_shown(lo: float, hi: float, *, include_zero: bool = True) -> float:
    """The least height a plot of values from ``lo`` to ``hi`` shows apart from another:
    what :data:`_PEN` of its plotting box stands for on its y axis (the axis as
    :func:`draw_line_plot` ticks it). A value nearer 0 than this is drawn on the zero line.

    Examples
    --------
    >>> round(smallest_shown(-383.0, 383.0), 4)           # ticks −400 … 400 over 82 mm
    0.9756
    """
    if include_zero:
        lo, hi = min(lo, 0.0), max(hi, 0.0)
    ticks = nice_ticks(lo, hi)
    return (ticks[-1] - ticks[0]) / _PLOT_H * _PEN


def tick_text(value: float, step: float) -> str:
    """A tick's number with as many decimals as the step needs, with a true minus.

    Examples
    --------
    >>> tick_text(-0.4000000000000001, 0.2), tick_text(300.0, 100.0), tick_text(-0.0, 0.05)
    ('−0.4', '300', '0.00')
    """
    decimals = max(0, -math.floor(math.log10(abs(step)) + 1e-9)) if step else 0
    text = f"{value:.{decimals}f}"
    if float(text) == 0.0:
        text = text.lstrip("-")
    return text.replace("-", "−")


# ----- text ----------------------------------------------------------------------------------
_SUB = re.compile(r"([^\s_]+)_(\w+)")
def rich_text(at: Point, text: str, size: float, anchor: str = "start", *,
              italic: bool = False, weight: str = "normal") -> list[Text]:
    """Set ``text`` at ``at``, each ``X_Y`` with Y as a true subscript.

    Returns the pieces, laid end to end: one :class:`Text` per subscript, the
    words after it in its tail (so no piece opens with a space, which SVG would
    drop). Right-to-left text (Persian) is laid in runs of one direction instead
    (:func:`~.rtl_runs.lay_runs`).

    Examples
    --------
    >>> [(t.text, t.sub, t.tail) for t in rich_text((0.0, 0.0), "V_B along x, θ_2 (°)", 3.0)]
    [('V', 'B', ' along x, '), ('θ', '2', ' (°)')]
    >>> [(t.text, t.sub, t.tail) for t in rich_text((0.0, 0.0), "t = 2 s", 3.0)]
    [('t = 2 s', '', '')]
    """
    matches = list(_SUB.finditer(text))
    if is_rtl(text):
        return _edge_held(lay_runs(at, _runs(text, matches), size, anchor, italic, weight),
                          at, anchor)
    if not matches:
        pieces = [(text, "", "")]
    else:
        pieces = []
        for i, m in enumerate(matches):
            head = (text[:m.start()] if i == 0 else "") + m.group(1)
            end = matches[i + 1].start() if i + 1 < len(matches) else len(text)
            pieces.append((head, m.group(2), text[m.end():end]))
    texts = [Text((0.0, 0.0), head, size, "start", italic, weight, sub, tail)
             for head, sub, tail in pieces]
    total = sum(t.width for t in texts)
    x = at[0] - (total / 2 if anchor == "middle" else total if anchor == "end" else 0.0)
    out = []
    for t in texts:
        out.append(Text((x, at[1]), t.text, size, "start", italic, weight, t.sub, t.tail))
        x += t.width
    return out


def _edge_held(texts: list[Text], at: Point, anchor: str) -> list[Text]:
    """Right-to-left runs as :func:`~.rtl_runs.lay_runs` lays them, each set by its left
    end, its estimated width from the line's right end; the run that ends the line at
    ``at`` set by that end instead (a line of one run by its anchor), so that a heading,
    legend entry or note set from the right margin ends on it whatever the viewer's shaping
    makes of its width: set by its left end, a note 2 % wider in the estimate than in cairo
    stopped 3 mm short of the margin the title ended on."""
    if anchor == "start":               # its last run already starts at ``at``
        return texts
    if len(texts) == 1 and not (texts[0].sub or texts[0].tail):
        return [replace(texts[0], at=(at[0], texts[0].at[1]), anchor=anchor)]
    if anchor == "end":
        k = max(range(len(texts)), key=lambda i: texts[i].box()[2])
        if not (texts[k].sub or texts[k].tail):
            texts[k] = replace(texts[k], at=(at[0], texts[k].at[1]), anchor="end")
    return texts


def _runs(text: str, matches: list[re.Match]) -> list[tuple[str, str, str]]:
    """``text``'s runs for :func:`~.rtl_runs.lay_runs`: its words, and each symbol with its
    subscript; a bracket opening before a symbol closes the words before it."""
    runs: list[tuple[str, str, str]] = []
    done = 0
    for m in matches:
        head = m.group(1)
        symbol = head.lstrip("([|")
        runs.append((text[done:m.start()] + head[:len(head) - len(symbol)], "", ""))
        runs.append((symbol, m.group(2), ""))
        done = m.end()
    runs.append((text[done:], "", ""))
    return runs


def _rich_width(text: str, size: float) -> float:
    """Width on paper of ``text`` set by :func:`rich_text`."""
    pieces = rich_text((0.0, 0.0), text, size)
    if is_rtl(text):                           # its runs have gaps between them
        return max(t.box()[2] for t in pieces) - min(t.box()[0] for t in pieces)
    return sum(t.width for t in pieces)


def _add_text(fig: Figure, at: Point, text: str, size: float, anchor: str = "start",
              **kw) -> None:
    for t in rich_text(at, text, size, anchor, **kw):
        fig.add(t)


# ----- the plot ------------------------------------------------------------------------------
def draw_line_plot(title: str, x_label: str, y_label: str, series: Sequence[Series],
                   marks: Sequence[PlotMark] = (), *, x_range: tuple[float, float],
                   x_ticks: Sequence[tuple[float, str]], subtitle: str = "",
                   notes: Sequence[str] = (), mark_legend: str = "",
                   include_zero: bool = True, y_ticks: Sequence[float] = (),
                   fills: Sequence[tuple[str, Sequence[Point]]] = (),
                   tags: Sequence[tuple] = (), size: tuple[float, float] | None = None
                   ) -> Figure:
    """Draw ``series`` against x in a framed plot, with ``marks`` as labelled open circles.

    Parameters
    ----------
    title, subtitle
        The heading (bold) and a line under it, ``X_Y`` subscripted.
    x_label, y_label
        Axis labels with units, ``"θ_2 (°)"``, ``"V_B (mm/s)"``; the y label stands
        over the axis.
    series
        The curves; a series' points outside ``x_range`` are clipped at its ends, so
        a periodic curve may run a step past each end. With more than one series,
        or marks and a ``mark_legend``, a legend follows the plot.
    marks
        Values found another way (the graphical solution), each an open circle with
        its label placed clear of the curves and of the other labels.
    x_range, x_ticks
        The x axis' extent and its ticks as (value, text).
    notes
        Lines under the plot.
    mark_legend
        The legend's words for the open circle ("solved graphically").
    include_zero
        Stretch the y axis to 0, so the zero line shows.
    y_ticks
        The y ticks, evenly spaced, when the caller knows them (0°, 90°, … 360° for
        a link that turns fully); by default nice ones that hold every value.
    fills
        Areas shaded under the curves, each (style, its outline in data coordinates):
        the energy areas of a turning-moment diagram.
    tags
        Words set centred at data points (x, y): each area's value. A tag may carry the
        outline of what it names, (x, y, words, outlines), each outline in data
        coordinates (an area wrapped across the plot's end is two): its words then stand
        inside it where they fit, else beside it with a leader into it, never on another
        tag's outline.
    size
        The page's width and the plotting box's height (mm); by default 170 and 82 mm,
        or, drawn for a sheet (:func:`~tarsim.graphics.paper.drawn_on`), as wide as the
        sheet on its side holds within its margins and as tall as it then holds.

    Returns
    -------
    Figure
        A page 170 mm wide (by default).

    Raises
    ------
    ValueError
        If no series has a point inside ``x_range``.

    Examples
    --------
    >>> xs = [i * 10.0 for i in range(37)]
    >>> s = Series("V_B", tuple((x, math.sin(math.radians(x))) for x in xs))
    >>> fig = draw_line_plot("Sine", "θ_2 (°)", "V_B (mm/s)", [s], [PlotMark(90.0, 1.0, "top")],
    ...                      x_range=(0.0, 360.0), x_ticks=[(0.0, "0"), (360.0, "360")])
    >>> fig.width, sum(1 for t in fig.items if isinstance(t, Text) and t.text == "top")
    (170.0, 1)
    """
    if size is None:
        args = dict(title=title, x_label=x_label, y_label=y_label, series=series, marks=marks,
                    x_range=x_range, x_ticks=x_ticks, subtitle=subtitle, notes=notes,
                    mark_legend=mark_legend, include_zero=include_zero, y_ticks=y_ticks,
                    fills=fills, tags=tags)
        return _sized(lambda at: draw_line_plot(**args, size=at))
    width, box_h = size
    x0, x1 = x_range
    runs = [(s, _clip_runs(s.points, x0, x1)) for s in series]
    ys = [p[1] for _, rs in runs for r in rs for p in r] + [m.y for m in marks]
    if not ys:
        raise ValueError("nothing to plot inside the x range")
    lo, hi = min(ys), max(ys)
    if include_zero:
        lo, hi = min(lo, 0.0), max(hi, 0.0)
    yt = [float(v) for v in y_ticks] if len(y_ticks) > 1 else nice_ticks(lo, hi)
    y0, y1 = yt[0], yt[-1]
    step = yt[1] - yt[0]
    y_texts = [numerals(tick_text(v, step)) for v in yt]
    # Right to left (Persian), the headings, legend and notes start from the right margin;
    # the axes stay as they are, the input's angle running left to right.
    reads = reading(width)
    edge, anchor = reads.x(_MARGIN), reads.anchor

    fig = Figure(width, 0.0)
    top = _MARGIN + _TITLE * 0.5
    _add_text(fig, (edge, top), title, _TITLE, anchor, weight="bold")
    if subtitle:
        top += _TITLE + 1.4
        _add_text(fig, (edge, top), subtitle, _SUBTITLE, anchor)
    number_w = max(text_width(t, _NUMBER) for t in y_texts)
    left = _MARGIN + number_w + 2.5
    right = width - _MARGIN - 2.0
    plot_top = top + _SUBTITLE + 9.0
    bottom = plot_top + box_h
    _add_text(fig, (left - 1.0, plot_top - 4.2), y_label, _LABEL, italic=False)

    def px(x: float) -> float:
        return left + (x - x0) / (x1 - x0) * (right - left)

    def py(y: float) -> float:
        return bottom - (y - y0) / (y1 - y0) * (bottom - plot_top)

    grid = [((px(x), plot_top), (px(x), bottom)) for x, _ in x_ticks if x0 < x < x1]
    grid += [((left, py(y)), (right, py(y))) for y in yt[1:-1] if y != 0.0]
    for a, b in grid:
        fig.line(a, b, "plot_grid")
    if y0 < 0.0 < y1:
        fig.line((left, py(0.0)), (right, py(0.0)), "plot_zero")
    fig.add(Path(((left, plot_top), (right, plot_top), (right, bottom), (left, bottom)),
                 "plot_frame", closed=True))
    for x, text in x_ticks:
        fig.line((px(x), bottom), (px(x), bottom - _TICK), "plot_tick")
        fig.line((px(x), plot_top), (px(x), plot_top + _TICK), "plot_tick")
        fig.add(Text((px(x), bottom + 3.6), sign_left(text), _NUMBER, "middle",
                     italic=False))
    # A mark on the y axis (a value at the plot's first x) stands between its tick and
    # number: the number steps aside by the mark's radius, or it touches the circle.
    on_axis = [py(m.y) for m in marks if abs(px(m.x) - left) < _MARK_R]
    for y, text in zip(yt, y_texts):
        fig.line((left, py(y)), (left + _TICK, py(y)), "plot_tick")
        fig.line((right, py(y)), (right - _TICK, py(y)), "plot_tick")
        aside = _MARK_R if any(abs(py(y) - m) < _NUMBER / 2 + _MARK_R for m in on_axis) else 0.0
        fig.add(Text((left - 1.8 - aside, py(y)), sign_left(text), _NUMBER, "end",
                     italic=False))
    y = bottom + 10.0
    _add_text(fig, ((left + right) / 2, y), x_label, _LABEL, "middle")

    for style, outline in fills:
        fig.add(Path(tuple((px(a), py(b)) for a, b in outline), style, closed=True))
    paper_runs = []
    for s, rs in runs:
        for r in rs:
            pts = tuple((px(a), py(b)) for a, b in r)
            paper_runs.append(pts)
            if len(pts) > 1:
                fig.add(Path(pts, s.style))
    # A mark's label keeps inside the ticks, off the frame and the ticks' ends.
    inner = _TICK + 0.4
    _draw_marks(fig, [(px(m.x), py(m.y), m.label) for m in marks], paper_runs,
                (left + inner, plot_top + inner, right - inner, bottom - inner), grid)
    _draw_tags(fig, [(px(t[0]), py(t[1]), t[2],
                      [[(px(a), py(b)) for a, b in o] for o in (t[3] if len(t) > 3 else ())])
                     for t in tags], paper_runs,
               (left + inner, plot_top + inner, right - inner, bottom - inner), grid)

    legend = [(s.style, s.label) for s in series] if len(series) > 1 else []
    if marks and mark_legend:
        legend.append(("plot_mark", mark_legend))
    x = width
    for style, label in legend:
        w = 18.0 + _rich_width(label, _NOTE)
        if x + w > width - _MARGIN + 6.0:
            x, y = _MARGIN, y + 6.5 if x == width else y + 5.0
        at = reads.x            # each sample from the reading edge: x is how far it has gone
        if style == "plot_mark":
            fig.add(Circle((at(x + 5.0), y), _MARK_R, style))
            _add_text(fig, (at(x + 8.0), y), label, _NOTE, anchor)
        else:
            fig.line((at(x), y), (at(x + 10.0), y), style)
            _add_text(fig, (at(x + 12.0), y), label, _NOTE, anchor)
        x += w
    for note in notes:
        for line in wrap_text(note, _NOTE, width - 2 * _MARGIN, indent="  ",
                              measure=_rich_width):
            y += 5.0
            _add_text(fig, (edge, y), line, _NOTE, anchor)
    fig.height = round(y + _MARGIN, 1)
    fig.title = title.replace("_", "")
    return fig


def _sized(draw) -> Figure:
    """A plot ``draw`` makes at a size (page width, plotting box height), at the size that
    fills the sheet figures are drawn on (:func:`~tarsim.graphics.paper.drawn_on`), within
    its margins, on its side: its headings, legend and notes keep their size; by default
    170 mm wide, its box 82 mm high."""
    sheet = sheet_drawn_on()
    if sheet is None:
        return draw((_WIDTH, _PLOT_H))
    wide = max(sheet.width, sheet.height) - 2 * MARGIN
    high = min(sheet.width, sheet.height) - 2 * MARGIN
    words = draw((wide, _PLOT_H)).height - _PLOT_H      # all but the box, at that width
    return draw((wide, max(_PLOT_H, min(high - words, _ASPECT * wide))))


def _clip_runs(points: Sequence[Point | None], x0: float, x1: float) -> list[list[Point]]:
    """Split at the breaks and keep what lies in x0 ≤ x ≤ x1, cutting segments at the edges."""
    runs: list[list[Point]] = []
    current: list[Point] = []
    prev: Point | None = None
    for p in (*points, None):
        if p is None or not (math.isfinite(p[0]) and math.isfinite(p[1])):
            if current:
                runs.append(current)
            current, prev = [], None
            continue
        inside = x0 <= p[0] <= x1
        if prev is not None and (x0 <= prev[0] <= x1) != inside:
            edge = x0 if min(p[0], prev[0]) < x0 else x1
            t = (edge - prev[0]) / (p[0] - prev[0])
            cut = (edge, prev[1] + t * (p[1] - prev[1]))
            if inside:
                current = [cut]
            else:
                current.append(cut)
                runs.append(current)
                current = []
        if inside:
            current.append(p)
        prev = p
    return [r for r in runs if r]


def _on_grid(boxes: np.ndarray, grid: Sequence[tuple[Point, Point]]) -> np.ndarray:
    """:data:`_GRID` for each grid line each of ``boxes`` lies across: a label is set off
    the light grid where it can be, as off a curve, but not at any cost."""
    if not grid:
        return np.zeros(len(boxes))
    lines = spots.segments([tuple(g) for g in grid])
    return _GRID * spots.overlaps(boxes, [], lines, (-math.inf, -math.inf, math.inf, math.inf))


def _draw_tags(fig: Figure, tags: list[tuple[float, float, str, list]],
               runs: list[tuple[Point, ...]], frame: Box,
               grid: Sequence[tuple[Point, Point]] = ()) -> None:
    """Each tag's words at its point, or moved the least (a line up or down, or to a side)
    to keep clear of the curves, the frame and the tags before it: an energy's value set
    at the middle of the segment it is the rise of would sit on that segment. A tag with
    outlines (an area) stands inside them where its words fit, else beside them, clear of
    every other tag's outline, with a leader into its own."""
    segments = spots.segments(runs)
    shapes = [unary_union([Polygon(o).buffer(0) for o in outlines if len(o) > 2])
              if outlines else None for _, _, _, outlines in tags]
    taken: list[Box] = []
    h = _NOTE
    for n, (x, y, text, _) in enumerate(tags):
        w = _rich_width(text, _NOTE)
        shifts = np.array([(0.0, 0.0)] + [(0.0, k * (h + 0.8)) for k in (-1, 1, -2, 2)]
                          + [(k * (w / 2 + 2.5), 0.0) for k in (1, -1)])
        cx, cy = x + shifts[:, 0], y + shifts[:, 1]
        boxes = np.stack([cx - w / 2 - 0.3, cy - h / 2 - 0.3, cx + w / 2 + 0.3,
                          cy + h / 2 + 0.3], axis=1)
        cost = spots.overlaps(boxes, taken, segments, frame) + 0.01 * np.hypot(*shifts.T) \
            + _on_grid(boxes, grid)
        own = shapes[n]
        leader = None
        if own is not None and not own.is_empty:
            others = [o for j, o in enumerate(shapes) if j != n and o is not None]
            cost += np.array([0.0 if own.contains(box(*b)) else 1.0 for b in boxes])
            if cost.min() >= 1.0:
                boxes, cost, leader = _beside(own, others, w, h, taken, segments, frame)
        i = int(np.argmin(cost))
        b = boxes[i]
        if leader is not None:
            start, end = leader[i]
            fig.line(start, end, "plot_leader")
        fig.add(Text((float(b[0] + b[2]) / 2, float(b[1] + b[3]) / 2), sign_left(text),
                     _NOTE, "middle", italic=False))
        taken.append(tuple(b.tolist()))


_BESIDE = (1.5, 3.0, 5.0, 8.0, 12.0)
"""How far (mm) beside an area too thin to hold its words they are tried, nearest first."""


def _beside(own, others, w: float, h: float, taken: list[Box], segments, frame: Box):
    """Boxes for words ``w`` × ``h`` beside the area ``own`` (above, below and to its
    sides, ever farther), their costs (the curves, frame and words they cover, any other
    area, and how far they stand) and each one's leader from its edge into the area."""
    x0, y0, x1, y1 = own.bounds
    inside = own.representative_point()
    mid = ((x0 + x1) / 2, (y0 + y1) / 2)
    centres = []
    for d in _BESIDE:
        centres += [(mid[0], y0 - d - h / 2), (mid[0], y1 + d + h / 2),
                    (x1 + d + w / 2, mid[1]), (x0 - d - w / 2, mid[1]),
                    (x1 + d + w / 2, y0 - d - h / 2), (x0 - d - w / 2, y0 - d - h / 2),
                    (x1 + d + w / 2, y1 + d + h / 2), (x0 - d - w / 2, y1 + d + h / 2)]
    c = np.array(centres)
    boxes = np.stack([c[:, 0] - w / 2 - 0.3, c[:, 1] - h / 2 - 0.3, c[:, 0] + w / 2 + 0.3,
                      c[:, 1] + h / 2 + 0.3], axis=1)
    cost = spots.overlaps(boxes, taken, segments, frame)
    leaders = []
    for k, b in enumerate(boxes):
        shape = box(*b)
        cost[k] += sum(shape.intersection(o).area > 0.01 for o in others)
        cost[k] += 2.0 * (shape.intersection(own).area > 0.01)
        cost[k] += 0.02 * shape.distance(own)
        # from a gap off the words' own box (ink, not the room kept round it) into the area
        cx, cy = (b[0] + b[2]) / 2, (b[1] + b[3]) / 2
        near, far = nearest_points(box(cx - w / 2, cy - 0.375 * h, cx + w / 2, cy + 0.375 * h),
                                   inside)
        d = max(math.hypot(far.x - near.x, far.y - near.y), 1e-9)
        gap = min(0.3, d / 2) / d
        leaders.append(((near.x + gap * (far.x - near.x), near.y + gap * (far.y - near.y)),
                        (far.x, far.y)))
    return boxes, cost, leaders


def _draw_marks(fig: Figure, marks: list[tuple[float, float, str]],
                runs: list[tuple[Point, ...]], frame: Box,
                grid: Sequence[tuple[Point, Point]] = ()) -> None:
    """Open circles at the marks; each label at the nearest clear spot round its circle,
    within ``frame``.

    The spots lie on rings ever farther out; a label set off its first ring gets a
    thin leader to its circle.
    """
    taken: list[Box] = [(x - _MARK_R, y - _MARK_R, x + _MARK_R, y + _MARK_R)
                        for x, y, _ in marks]
    for x, y, _ in marks:
        fig.add(Circle((x, y), _MARK_R, "plot_mark"))
    h = _MARK_TEXT
    segments = spots.segments(runs)
    ring = np.repeat(spots.RINGS, len(spots.WAYS))
    dx, dy = np.tile(np.array(spots.WAYS).T, len(spots.RINGS))
    for x, y, label in marks:
        if not label:
            continue
        w = _rich_width(label, _MARK_TEXT)
        cx = x + dx * (ring * (_MARK_R + 1.4) + w / 2)
        cy = y + dy * (ring * (_MARK_R + 0.9) + h / 2)
        boxes = np.stack([cx - w / 2 - 0.3, cy - h / 2 - 0.3, cx + w / 2 + 0.3, cy + h / 2 + 0.3],
                         axis=1)
        leaders = spots.leaders(x, y, boxes, ring)
        cost = spots.overlaps(boxes, taken, segments, frame) + 0.05 * ring + _on_grid(boxes, grid)
        # A leader across a curve reads as part of it: it costs as the box crossing one;
        # one through another mark's circle points at that mark.
        cost += spots.crossed(*leaders, segments)
        others = [(mx, my) for mx, my, _ in marks if (mx, my) != (x, y)]
        cost += spots.through_marks(*leaders, others)
        k = int(np.argmin(cost))
        best = tuple(boxes[k].tolist())
        cx, cy = (best[0] + best[2]) / 2, (best[1] + best[3]) / 2
        start, end = leaders[0][k], leaders[1][k]
        if np.isfinite(start).all():
            fig.line(tuple(start.tolist()), tuple(end.tolist()), "plot_leader")
        for t in rich_text((cx, cy), label, _MARK_TEXT, "middle"):
            fig.add(t)
        taken.append(best)
