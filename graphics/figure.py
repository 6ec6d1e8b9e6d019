"""The figure model: paper-space primitives in millimetres, with named styles.

Everything is placed on paper (x right, y down, 1 unit = 1 mm) before any SVG
is written, so label collision checks and the scale bar work in the units a ruler
measures. A :class:`View` maps world metres to paper for one panel.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

__all__ = ["Style", "STYLES", "View", "Path", "Circle", "Text", "Figure", "FONT", "text_width"]

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
    "plate": Style(width=0.6, fill="#e8e8e8"),
    "pin": Style(width=0.35, fill="#fff"),
    "ground": Style(width=0.35, fill="#fff"),
    "ground_base": Style(width=0.4, cap="butt"),
    "hatch": Style(width=0.2, cap="butt"),
    "block": Style(width=0.45, fill="#fff", join="miter", cap="butt"),
    "guide": Style(width=0.4, cap="butt"),
    "construction": Style(width=0.18, dash=(3.0, 1.0, 0.6, 1.0)),
    "reference": Style(width=0.18, dash=(1.5, 1.0)),
    "dimension": Style(width=0.2),
    "arrow": Style(width=0.35),
    "arrowhead": Style(stroke=None, fill="#000"),
    "scale": Style(width=0.3, cap="butt"),
    "scale_fill": Style(width=0.3, fill="#000", cap="butt", join="miter"),
    "frame": Style(width=0.25, stroke="#999"),
    "text": Style(stroke=None, fill="#000"),
}


@dataclass(frozen=True, slots=True)
class View:
    """Map world metres to paper mm: ``paper = origin + scale · (x, −y)``."""

    scale: float
    origin: tuple[float, float]

    def __call__(self, xy: tuple[float, float]) -> tuple[float, float]:
        return (self.origin[0] + self.scale * xy[0], self.origin[1] - self.scale * xy[1])

    def direction(self, d: tuple[float, float]) -> tuple[float, float]:
        """A world direction as a paper direction (y flips)."""
        return (d[0], -d[1])


@dataclass(frozen=True, slots=True)
class Path:
    """A polyline, or a closed polygon, with optional SVG arc segments in ``d``."""

    points: tuple[tuple[float, float], ...]
    style: str
    closed: bool = False
    d: str | None = None


@dataclass(frozen=True, slots=True)
class Circle:
    """A circle on paper."""

    centre: tuple[float, float]
    radius: float
    style: str


@dataclass(frozen=True, slots=True)
class Text:
    """A label; ``anchor`` is start, middle or end; ``at`` is the visual centre-left/middle/right."""

    at: tuple[float, float]
    text: str
    size: float = 3.5
    anchor: str = "middle"
    italic: bool = True
    weight: str = "normal"

    def box(self) -> tuple[float, float, float, float]:
        """Approximate extent (x0, y0, x1, y1) on paper, for collision checks."""
        w = text_width(self.text, self.size)
        x, y = self.at
        x0 = x - w / 2 if self.anchor == "middle" else (x - w if self.anchor == "end" else x)
        h = self.size * 0.75
        return (x0, y - h / 2, x0 + w, y + h / 2)


def text_width(text: str, size: float) -> float:
    """Rough advance width of ``text`` in DejaVu Serif at ``size`` mm."""
    narrow = set("il.,:;'|!()[]₀₁₂₃₄₅₆₇₈₉ ")
    return sum(0.33 if ch in narrow else 0.62 for ch in text) * size


@dataclass
class Figure:
    """A page of primitives, drawn in insertion order (later on top)."""

    width: float
    height: float
    items: list[Path | Circle | Text] = field(default_factory=list)
    title: str = ""

    def add(self, item: Path | Circle | Text) -> None:
        """Append a primitive."""
        self.items.append(item)

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

    def arc(self, centre: tuple[float, float], r: float, a0: float, a1: float, style: str) -> None:
        """Add a circular arc on paper from angle a0 to a1 (radians, paper-CCW as seen)."""
        n = max(8, int(abs(a1 - a0) / (math.pi / 36)) + 1)
        pts = tuple((centre[0] + r * math.cos(a0 + (a1 - a0) * i / n),
                     centre[1] - r * math.sin(a0 + (a1 - a0) * i / n)) for i in range(n + 1))
        self.add(Path(pts, style))


def _shifted(it: Path | Circle | Text, dx: float, dy: float) -> Path | Circle | Text:
    if isinstance(it, Path):
        return Path(tuple((x + dx, y + dy) for x, y in it.points), it.style, it.closed, it.d)
    if isinstance(it, Circle):
        return Circle((it.centre[0] + dx, it.centre[1] + dy), it.radius, it.style)
    return Text((it.at[0] + dx, it.at[1] + dy), it.text, it.size, it.anchor, it.italic, it.weight)
