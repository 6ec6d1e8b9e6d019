"""The figure model: paper-space primitives in millimetres, with named styles.

Everything is placed on paper (x right, y down, 1 unit = 1 mm) before any SVG
is written, so label collision checks and the scale bar work in the units a ruler
measures. A :class:`View` maps world metres to paper for one panel.
"""

from __future__ import annotations

import math
import pathlib
import re
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from functools import lru_cache

from .rtl import is_rtl, joined

__all__ = ["Style", "STYLES", "View", "Path", "Circle", "Text", "Figure", "FONT", "text_width",
           "wrap_text",
           "SUB_SIZE", "SUB_DROP", "arc_points", "clip_line", "ray_to_edge", "span_line",
           "stack_pages", "stack_layout", "PAGE_GAP", "shelve"]

FONT = "DejaVu Serif"
"""One family that covers Latin, Greek, subscripts and ⊥ ∥ ∞ (cairosvg has no fallback)."""


@dataclass(frozen=True, slots=True)
class Style:
    """Stroke and fill of a primitive; widths in mm."""

    stroke: str | None = "#000"
    width: float = 0.25
    fill: str | None = None
    dash: tuple[float, ...] = ()
    cap: str = "round"
    join: str = "round"


STYLES: dict[str, Style] = {
    "link": Style(width=0.6),
    "plate": Style(width=0.6),
    "plate_fill": Style(stroke=None, fill="#e8e8e8"),
    "pin": Style(width=0.35, fill="#fff"),
    "ground": Style(width=0.35, fill="#fff"),
    "ground_base": Style(width=0.4, cap="butt"),
    "hatch": Style(width=0.2, cap="butt"),
    "block": Style(width=0.45, fill="#fff", join="miter", cap="butt"),
    "guide": Style(width=0.4, cap="butt"),
    "construction": Style(width=0.18, dash=(3.0, 1.0, 0.6, 1.0)),
    "centre_line": Style(width=0.45, dash=(6.0, 1.2, 0.8, 1.2), cap="butt"),   # chain, thick
    # Scene layers (graphics.scene): each kind of working line reads differently in
    # black and grey alone.
    "kennedy": Style(width=0.2, dash=(4.0, 1.0, 0.7, 1.0)),
    "normal": Style(width=0.28, dash=(6.0, 1.5)),
    "gauge": Style(width=0.22, stroke="#555"),
    "working": Style(width=0.18, stroke="#444", dash=(1.6, 1.0)),
    "compass": Style(width=0.18, stroke="#444"),
    "vector": Style(width=0.35, cap="butt"),
    "vector_result": Style(width=0.55, cap="butt"),
    "vector_dashed": Style(width=0.35, dash=(2.2, 1.0), cap="butt"),
    "edge_arrow": Style(width=0.3, cap="butt"),
    "dot": Style(stroke=None, fill="#000"),
    "badge": Style(width=0.18, fill="#fff"),
    "chord": Style(width=0.4),
    "chord_secondary": Style(width=0.4, dash=(2.2, 1.3), cap="butt"),
    "chord_current": Style(width=0.6, dash=(2.2, 1.3), cap="butt"),
    "triangle": Style(stroke=None, fill="#e4e4e4"),
    "triangle_alt": Style(stroke=None, fill="#cdcdcd"),
    "node_circle": Style(width=0.25, stroke="#777"),
    "reference": Style(width=0.18, dash=(1.5, 1.0)),
    "leader": Style(width=0.15, dash=(0.5, 0.7)),
    "dimension": Style(width=0.2),
    "arrow": Style(width=0.35),
    "arrowhead": Style(stroke=None, fill="#000"),
    "scale": Style(width=0.3, cap="butt"),
    "scale_fill": Style(width=0.3, fill="#000", cap="butt", join="miter"),
    "frame": Style(width=0.25, stroke="#999"),
    "page_rule": Style(width=0.25, stroke="#999", dash=(3.0, 2.0)),
    "text": Style(stroke=None, fill="#000"),
    # Plots against crank angle (graphics.plot).
    "plot_frame": Style(width=0.3, cap="butt", join="miter"),
    "plot_tick": Style(width=0.25, cap="butt"),
    "plot_grid": Style(width=0.12, stroke="#b8b8b8", cap="butt"),
    "plot_zero": Style(width=0.25, cap="butt"),
    "plot_curve": Style(width=0.5),
    "plot_curve_dashed": Style(width=0.35, dash=(3.0, 1.2), cap="butt"),
    "plot_curve_dotted": Style(width=0.35, stroke="#555", dash=(0.6, 0.9)),
    "plot_curve_dash_dot": Style(width=0.4, dash=(4.0, 1.2, 0.8, 1.2), cap="butt"),
    "plot_curve_grey": Style(width=0.9, stroke="#999"),
    "plot_mark": Style(width=0.3, fill="#fff"),
    "plot_leader": Style(width=0.15, cap="butt"),
}


@dataclass(frozen=True, slots=True)
class View:
    """Map world metres to paper mm: ``paper = origin + scale · (x, −y)``."""

    scale: float
    origin: tuple[float, float]

    def __call__(self, xy: tuple[float, float]) -> tuple[float, float]:
        """Map a world point (m) to paper (mm)."""
        return (self.origin[0] + self.scale * xy[0], self.origin[1] - self.scale * xy[1])

    def direction(self, d: tuple[float, float]) -> tuple[float, float]:
        """A world direction as a paper direction (y flips)."""
        return (d[0], -d[1])

    def moved(self, dx: float, dy: float) -> View:
        """The view of a drawing moved by (dx, dy) mm on its paper."""
        return View(self.scale, (self.origin[0] + dx, self.origin[1] + dy))


@dataclass(frozen=True, slots=True)
class Path:
    """A polyline, or a closed polygon."""

    points: tuple[tuple[float, float], ...]
    style: str
    closed: bool = False
    steps: tuple[str, ...] = ()
    """The record's steps this draws (:meth:`Figure.for_steps`); none for what every step
    stands on (the mechanism, a caption)."""


@dataclass(frozen=True, slots=True)
class Circle:
    """A circle on paper."""

    centre: tuple[float, float]
    radius: float
    style: str
    steps: tuple[str, ...] = ()
    """The record's steps this draws, as a :class:`Path`'s."""


@dataclass(frozen=True, slots=True)
class Text:
    """A label; ``anchor`` is start, middle or end; ``at`` is the visual centre-left/middle/right.

    ``sub`` is set after ``text`` as a true subscript (smaller, dropped below the
    baseline): ``Text(at, "V", sub="A")`` prints V with subscript A; ``tail``
    follows the subscript back on the baseline ("V_B by radius rotation"). ``owner`` is
    what the label names, by its points (one for a point, tail and tip for a vector), kept
    so that a figure can be held to a label standing nearer its own than any other.
    """

    at: tuple[float, float]
    text: str
    size: float = 3.5
    anchor: str = "middle"
    italic: bool = True
    weight: str = "normal"
    sub: str = ""
    tail: str = ""
    owner: tuple[tuple[float, float], ...] | None = None
    steps: tuple[str, ...] = ()
    """The record's steps this names or numbers, as a :class:`Path`'s."""

    @property
    def width(self) -> float:
        """Approximate advance width on paper, the subscript and tail included."""
        bold = 1.1 if self.weight == "bold" else 1.0
        if is_rtl(self.text + self.sub + self.tail):    # all of it in DejaVu Sans, as set
            parts = ((self.text, self.size), (self.sub, SUB_SIZE * self.size),
                     (self.tail, self.size))
            return sum(_rtl_width(t, bold > 1.0) * s for t, s in parts if t)
        return bold * (text_width(self.text, self.size) + text_width(self.sub, SUB_SIZE * self.size)
                       + text_width(self.tail, self.size))

    def box(self) -> tuple[float, float, float, float]:
        """Approximate extent (x0, y0, x1, y1) on paper, for collision checks."""
        w = self.width
        x, y = self.at
        x0 = x - w / 2 if self.anchor == "middle" else (x - w if self.anchor == "end" else x)
        h = self.size * 0.75
        drop = SUB_DROP * self.size if self.sub else 0.0
        return (x0, y - h / 2, x0 + w, y + h / 2 + drop)


SUB_SIZE = 0.72
"""A subscript's size relative to its text."""

SUB_DROP = 0.28
"""How far (in ems of the text) a subscript's baseline drops below the text's."""


# Advance widths of DejaVu Serif in ems (measured from the font), grouped by width.
_ADVANCE_GROUPS = {
    0.23: "′", 0.25: "ᵗ", 0.27: "'", 0.31: "j", 0.32: " ,.il·", 0.34: "-/:;\\|ˢ", 0.35: "ᶜ",
    0.37: "f", 0.39: "()[]", 0.40: "!IJt₀₁₂₃₄₅₆₇₈₉²", 0.43: "ⁿ", 0.46: '"∥', 0.48: "r",
    0.50: "*_`°–", 0.51: "s", 0.53: "z",
    0.54: "?", 0.56: "cvxy", 0.59: "e", 0.60: "aoθ", 0.61: "k",
    0.64: "$0123456789bdghnpqu{}", 0.66: "LY", 0.67: "PT", 0.68: "α", 0.69: "FSZ",
    0.71: "X", 0.72: "AVΔ", 0.73: "BE", 0.75: "KR", 0.77: "C", 0.80: "DG", 0.82: "OQω",
    0.83: "∞", 0.84: "#+<=>U^~→≡−×", 0.86: "w", 0.87: "H", 0.88: "N", 0.89: "&",
    0.94: "⊥", 0.95: "%m", 1.00: "@—", 1.02: "M", 1.03: "W",
}
_ADVANCE = {ch: w for w, chars in _ADVANCE_GROUPS.items() for ch in chars}


def clear_of(label: Text, taken: list, *, keep: bool = False,
             step: tuple[float, float] = (0.0, 3.4)) -> Text:
    """``label`` moved by ``step`` at a time until its box meets none of the boxes
    ``taken``; with ``keep`` its box is taken too. For a few names round one drawing, where
    the label placer's search would be more than the figure needs."""
    for _ in range(200):
        x0, y0, x1, y1 = label.box()
        if not any(x0 < b[2] and b[0] < x1 and y0 < b[3] and b[1] < y1 for b in taken):
            break
        label = replace(label, at=(label.at[0] + step[0], label.at[1] + step[1]))
    if keep:
        taken.append(label.box())
    return label


def text_width(text: str, size: float, *, bold: bool = False) -> float:
    """Advance width of ``text`` in DejaVu Serif at ``size`` mm (0.62 em for unlisted glyphs);
    a right-to-left text in DejaVu Sans, the face it is set in, ``bold`` or not (a Latin
    label's bold is allowed for by its :class:`Text`).

    Examples
    --------
    >>> round(text_width("VI", 10.0), 2)
    11.2
    """
    if is_rtl(text):
        return _rtl_width(text, bold) * size
    return sum(_ADVANCE.get(ch, 0.62) for ch in text) * size


@lru_cache(maxsize=4096)
def _rtl_width(text: str, bold: bool) -> float:
    """Width (em) of a right-to-left label as it is drawn: its letters joined (each in the
    presentation form it takes beside its neighbours) and set in DejaVu Sans, whose
    advances are read from the font (:mod:`.sans_advances`)."""
    from .sans_advances import ADVANCE, BOLD, HINTING

    table = BOLD if bold else ADVANCE
    # A run of spaces is set as one, by the PDF and by a browser alike.
    return sum(table.get(ch, 0.62) for ch in re.sub(" +", " ", joined(text))) * (1.0 + HINTING)


def wrap_text(text: str, size: float, width: float, *, indent: str = "",
              measure: Callable[[str, float], float] = text_width) -> list[str]:
    """Break ``text`` between words into lines no wider than ``width`` mm at ``size`` (a word
    wider than that stands alone); lines after the first open with ``indent``.

    >>> wrap_text("the slow stroke takes longer", 3.0, 30.0)
    ['the slow stroke', 'takes longer']
    """
    lines: list[str] = []
    for word in text.split():
        if lines and measure(f"{lines[-1]} {word}", size) <= width:
            lines[-1] += f" {word}"
        else:
            lines.append((indent if lines else "") + word)
    return lines or [""]


@dataclass
class Figure:
    """A page of primitives, drawn in insertion order (later on top)."""

    width: float
    height: float
    items: list[Path | Circle | Text] = field(default_factory=list)
    title: str = ""
    views: dict[str, View] = field(default_factory=dict)
    """Where each panel's world stands on the page, by the panel's name ("space",
    "velocity", …): the view its drawing was made by, moved with it, so that a point of
    the mechanism (or of a polygon) can be found on the figure again."""
    _steps: tuple[str, ...] = field(default=(), repr=False, compare=False)
    sheets: list[Figure] = field(default_factory=list)
    """A figure that runs over several sheets: each sheet, in order (a PDF prints a page
    each); its own items are them stacked (:func:`stack_pages`), for one SVG."""
    drawing: tuple[float, float] | None = None
    """The width and height (mm) of the drawing a caption was set under
    (:func:`~tarsim.graphics.scales.draw_caption`): the part of the figure that grows and
    shrinks with its scale, the caption and margins keeping their size."""

    def add(self, item: Path | Circle | Text) -> None:
        """Append a primitive."""
        self.items.append(replace(item, steps=self._steps)
                          if self._steps and not item.steps else item)

    @contextmanager
    def for_steps(self, *steps: str) -> Iterator[None]:
        """Mark what is added within as drawn for these steps of the record (by ref), so
        that a page can show the figure step by step; what is added outside stands on
        every step."""
        outer, self._steps = self._steps, tuple(steps)
        try:
            yield
        finally:
            self._steps = outer

    def save(self, path) -> pathlib.Path:
        """Write the figure to ``path``: .svg, .pdf or .png by its suffix (PDF and PNG need
        libcairo2), all or nothing.

        Raises
        ------
        RenderError
            For an unknown suffix, a missing libcairo2, or a path that cannot be written.
        """
        from .export import write_figure     # export draws on this module

        return write_figure(self, path)

    def _repr_svg_(self) -> str:
        """The figure as SVG, so that a notebook shows it."""
        from .svg import to_svg              # svg draws on this module

        return to_svg(self)

    def add_under(self, item: Path | Circle | Text) -> None:
        """Put a primitive beneath everything drawn so far: a tint that must hide no line."""
        self.items.insert(0, replace(item, steps=self._steps)
                          if self._steps and not item.steps else item)

    def line(self, p: tuple[float, float], q: tuple[float, float], style: str) -> None:
        """Add a straight segment."""
        self.add(Path((p, q), style))

    def bounds(self) -> tuple[float, float, float, float]:
        """Extent (x0, y0, x1, y1) of everything drawn, text boxes included."""
        xs: list[float] = []
        ys: list[float] = []
        for it in self.items:
            if isinstance(it, Path):
                xs += [p[0] for p in it.points]
                ys += [p[1] for p in it.points]
            elif isinstance(it, Circle):
                xs += [it.centre[0] - it.radius, it.centre[0] + it.radius]
                ys += [it.centre[1] - it.radius, it.centre[1] + it.radius]
            else:
                x0, y0, x1, y1 = it.box()
                xs += [x0, x1]
                ys += [y0, y1]
        return (min(xs), min(ys), max(xs), max(ys))

    def shift(self, dx: float, dy: float) -> None:
        """Move everything drawn by (dx, dy) mm."""
        self.items = [_shifted(it, dx, dy) for it in self.items]
        self.views = {name: v.moved(dx, dy) for name, v in self.views.items()}

    def arc(self, centre: tuple[float, float], r: float, a0: float, a1: float, style: str) -> None:
        """Add a circular arc on paper from angle a0 to a1 (radians, paper-CCW as seen)."""
        n = max(8, int(abs(a1 - a0) / (math.pi / 36)) + 1)
        pts = tuple((centre[0] + r * math.cos(a0 + (a1 - a0) * i / n),
                     centre[1] - r * math.sin(a0 + (a1 - a0) * i / n)) for i in range(n + 1))
        self.add(Path(pts, style))


def _shifted(it: Path | Circle | Text, dx: float, dy: float) -> Path | Circle | Text:
    if isinstance(it, Path):
        return Path(tuple((x + dx, y + dy) for x, y in it.points), it.style, it.closed,
                    it.steps)
    if isinstance(it, Circle):
        return Circle((it.centre[0] + dx, it.centre[1] + dy), it.radius, it.style, it.steps)
    owner = None if it.owner is None else tuple((x + dx, y + dy) for x, y in it.owner)
    return Text((it.at[0] + dx, it.at[1] + dy), it.text, it.size, it.anchor, it.italic, it.weight,
                it.sub, it.tail, owner, it.steps)


Box = tuple[float, float, float, float]


def arc_points(centre: tuple[float, float], r: float, start: float, sweep: float,
               chord: float = 1.2) -> list[tuple[float, float]]:
    """Points of a paper arc from angle ``start`` through ``sweep`` (rad, CCW as seen).

    Chords are about ``chord`` mm long, so a large arc stays round.

    Examples
    --------
    >>> pts = arc_points((0.0, 0.0), 10.0, 0.0, math.pi / 2)
    >>> [tuple(round(v, 12) + 0.0 for v in p) for p in (pts[0], pts[-1])]
    [(10.0, 0.0), (0.0, -10.0)]
    """
    n = max(8, min(720, int(abs(sweep) * r / chord) + 1))
    return [(centre[0] + r * math.cos(start + sweep * i / n),
             centre[1] - r * math.sin(start + sweep * i / n)) for i in range(n + 1)]


def clip_line(base: tuple[float, float], d: tuple[float, float], lo: float, hi: float,
              box: Box) -> tuple[tuple[float, float], tuple[float, float]] | None:
    """Clip the piece ``base + t·d``, ``lo ≤ t ≤ hi``, of a paper line to ``box`` (x0, y0, x1, y1).

    Working in the parameter keeps far ends (a centre kilometres off) exact.
    Returns the two ends, or None if nothing is left.

    Examples
    --------
    >>> clip_line((0.0, 5.0), (1.0, 0.0), -1e12, 1e12, (0.0, 0.0, 10.0, 10.0))
    ((0.0, 5.0), (10.0, 5.0))
    """
    for k in (0, 1):
        if abs(d[k]) < 1e-15:
            if not box[k] <= base[k] <= box[k + 2]:
                return None
            continue
        t0, t1 = (box[k] - base[k]) / d[k], (box[k + 2] - base[k]) / d[k]
        lo, hi = max(lo, min(t0, t1)), min(hi, max(t0, t1))
    if hi - lo <= 1e-9:
        return None
    return ((base[0] + lo * d[0], base[1] + lo * d[1]), (base[0] + hi * d[0], base[1] + hi * d[1]))


def ray_to_edge(start: tuple[float, float], u: tuple[float, float], box: Box
                ) -> tuple[float, float]:
    """Where the ray from ``start`` (inside ``box``) along ``u`` leaves the box.

    Examples
    --------
    >>> ray_to_edge((5.0, 5.0), (0.0, -1.0), (0.0, 0.0, 10.0, 10.0))
    (5.0, 0.0)
    """
    ts = [((box[k + 2] if u[k] > 0 else box[k]) - start[k]) / u[k]
          for k in (0, 1) if abs(u[k]) > 1e-12]
    t = max(0.0, min(ts)) if ts else 0.0
    return (start[0] + t * u[0], start[1] + t * u[1])


def span_line(base: tuple[float, float], d: tuple[float, float],
              stops: list[tuple[tuple[float, float], float]], lone: float) -> tuple[float, float]:
    """Find the stretch ``lo ≤ t ≤ hi`` of the paper line ``base + t·d`` that shows its points.

    A working line is drawn only as far as the points it carries (``stops``:
    each paper point with how far the line runs on past it), as a student draws
    just enough of it to make the cut; where points coincide at an end, the
    shortest overhang wins (a line stops under a pin's circle). A line through
    one point runs ``lone`` either side of it, one through none ``2·lone`` either
    side of ``base``. ``d`` is a unit vector.

    Examples
    --------
    >>> span_line((0.0, 0.0), (1.0, 0.0), [((2.0, 0.0), 4.0), ((10.0, 3.0), 1.0)], 12.0)
    (-2.0, 11.0)
    >>> span_line((0.0, 0.0), (0.0, 1.0), [((0.0, 5.0), 4.0)], 12.0)
    (-7.0, 17.0)
    """
    if not stops:
        return -2 * lone, 2 * lone
    ts = [(p[0] - base[0]) * d[0] + (p[1] - base[1]) * d[1] for p, _ in stops]
    if max(ts) - min(ts) < 1e-6:
        return ts[0] - lone, ts[0] + lone

    def reach(t: float) -> float:
        return min(over for u, (_, over) in zip(ts, stops) if abs(u - t) < 1e-6)

    return min(ts) - reach(min(ts)), max(ts) + reach(max(ts))


PAGE_GAP = 12.0
"""The space between stacked pages (mm), a rule drawn across its middle."""


def stack_layout(pages: list[Figure], gap: float = PAGE_GAP
                 ) -> tuple[float, float, list[float]]:
    """The tall sheet pages are stacked on: its width, its height and each page's top."""
    tops = [0.0]
    for page in pages[:-1]:
        tops.append(tops[-1] + page.height + gap)
    height = sum(p.height for p in pages) + gap * (len(pages) - 1)
    return max(p.width for p in pages), height, tops


def shelve(panels: list[Figure], row: float, gap: float, title: str = "") -> Figure:
    """Lay ``panels`` left to right in rows no wider than ``row`` (mm), a new row below the
    tallest of the last, ``gap`` between them: one figure of each at its own scale (a force
    polygon or a free body each to a scale that fits it)."""
    fig = Figure(0.0, 0.0, title=title)
    x = y = row_height = 0.0
    for panel in panels:
        x0, y0, x1, y1 = panel.bounds()
        if x > 0.0 and x + (x1 - x0) > row:
            x, y, row_height = 0.0, y + row_height + gap, 0.0
        panel.shift(x - x0, y - y0)
        fig.items += panel.items
        x += (x1 - x0) + gap
        row_height = max(row_height, y1 - y0)
    return fig


def stack_pages(pages: list[Figure], gap: float = PAGE_GAP) -> Figure:
    """Set whole figures one under another on one tall sheet, each at its own scale.

    A thin rule parts them; nothing is rescaled, so every scale bar still measures true.
    """
    width, height, tops = stack_layout(pages, gap)
    out = Figure(width, height, title=pages[0].title,
                 sheets=[s for p in pages for s in (p.sheets or [p])])
    for i, (page, top) in enumerate(zip(pages, tops)):
        if i:
            out.line((0.0, top - gap / 2), (width, top - gap / 2), "page_rule")
        out.items += [_shifted(it, 0.0, top) for it in page.items]
        out.views.update({name: v.moved(0.0, top) for name, v in page.views.items()})
    return out
