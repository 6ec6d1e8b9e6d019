"""Small log-scale line plots as SVG, for the report's error-against-run-time figures.

``graphics/plot.py`` draws tarsim's textbook plots on linear axes against the crank
angle; the benchmark's data span decades on both axes (errors from 1e-16 to 1e-1,
times from microseconds to seconds), so it needs log axes with decade ticks, which
that module does not draw. This one is deliberately small: a framed box, decade ticks
labelled 10ⁿ (or nice linear ticks), curves with markers, optional horizontal guide
lines, and the legend *below* the box so it never covers data.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import svgwrite

from tarsim.graphics.plot import nice_ticks, tick_text

__all__ = ["Curve", "Guide", "write_plot"]

_W, _H = 680, 430                 # px
_LEFT, _RIGHT, _TOP, _BOX_H = 78, 24, 46, 270
_COLOURS = ("#1f4e9c", "#c0392b", "#2e8b57", "#8e44ad", "#d35400", "#555555", "#0e8c8c")
_DASHES = ("", "6,3", "2,3", "8,3,2,3")
_SUPER = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


@dataclass(frozen=True)
class Curve:
    """One series: its legend label, points (x, y) and, optionally, a label at each point."""

    label: str
    points: tuple[tuple[float, float], ...]
    point_labels: tuple[str, ...] = ()
    line: bool = True


@dataclass(frozen=True)
class Guide:
    """A dashed horizontal line at ``y`` (a target, a bound), named in the legend."""

    y: float
    label: str


@dataclass
class _Axis:
    lo: float
    hi: float
    log: bool
    ticks: list[tuple[float, str]] = field(default_factory=list)

    @classmethod
    def fit(cls, values: Sequence[float], log: bool) -> _Axis:
        vals = [v for v in values if math.isfinite(v) and (v > 0 or not log)]
        if log:
            # A little room round the data, so no mark sits on the frame.
            low, high = math.log10(min(vals)), math.log10(max(vals))
            lo, hi = math.floor(low), math.ceil(high)
            lo -= low - lo < 0.12 * (hi - lo) ** 0.5       # room, if a mark would touch
            hi += hi - high < 0.12 * (hi - lo) ** 0.5
            hi = max(hi, lo + 1)
            if hi - lo <= 2:              # a short span: ticks at 1, 2, 5 × 10^k
                ticks = [(m * 10.0 ** k, f"{m * 10.0 ** k:g}") for k in range(lo, hi + 1)
                         for m in (1, 2, 5) if 10.0 ** lo <= m * 10.0 ** k <= 10.0 ** hi]
                return cls(10.0 ** lo, 10.0 ** hi, True, ticks)
            step = max(1, math.ceil((hi - lo) / 8))
            ticks = [(10.0 ** k, "10" + str(k).translate(_SUPER) if k not in (0, 1)
                      else ("1" if k == 0 else "10")) for k in range(lo, hi + 1, step)]
            return cls(10.0 ** lo, 10.0 ** hi, True, ticks)
        t = nice_ticks(min(vals), max(vals))
        step = t[1] - t[0]
        return cls(t[0], t[-1], False, [(v, tick_text(v, step)) for v in t])

    def at(self, v: float, a: float, b: float) -> float:
        """Map ``v`` to the pixel span a … b."""
        if self.log:
            f = (math.log10(v) - math.log10(self.lo)) / (math.log10(self.hi) - math.log10(self.lo))
        else:
            f = (v - self.lo) / (self.hi - self.lo)
        return a + f * (b - a)


def write_plot(path: Path, title: str, x_label: str, y_label: str, curves: Sequence[Curve], *,
               x_log: bool = True, y_log: bool = True, guides: Sequence[Guide] = (),
               note: str = "") -> Path:
    """Write a plot of ``curves`` to ``path`` (SVG); the legend and ``note`` go below it."""
    pts = [p for c in curves for p in c.points
           if math.isfinite(p[0]) and math.isfinite(p[1]) and (p[1] > 0 or not y_log)]
    xa = _Axis.fit([p[0] for p in pts], x_log)
    ya = _Axis.fit([p[1] for p in pts] + [g.y for g in guides], y_log)
    cols = 1 if any(len(c.label) > 36 for c in curves) else 2
    rows = math.ceil(len(curves) / cols) + (1 if guides else 0)
    height = _TOP + _BOX_H + 56 + 18 * rows + (18 if note else 0)
    d = svgwrite.Drawing(str(path), size=(f"{_W}px", f"{height}px"), profile="full",
                         viewBox=f"0 0 {_W} {height}")
    d.add(d.rect((0, 0), (_W, height), fill="white"))
    x0, x1, y0, y1 = _LEFT, _W - _RIGHT, _TOP + _BOX_H, _TOP
    font = dict(font_family="DejaVu Sans, Arial, sans-serif", font_size=12)
    d.add(d.text(title, insert=(12, 22), font_weight="bold", **{**font, "font_size": 14}))
    d.add(d.text(y_label, insert=(12, _TOP - 8), **font))
    for v, text in xa.ticks:
        x = xa.at(v, x0, x1)
        d.add(d.line((x, y0), (x, y1), stroke="#e3e3e3", stroke_width=0.8))
        d.add(d.text(text, insert=(x, y0 + 16), text_anchor="middle", **font))
    for v, text in ya.ticks:
        y = ya.at(v, y0, y1)
        d.add(d.line((x0, y), (x1, y), stroke="#e3e3e3", stroke_width=0.8))
        d.add(d.text(text, insert=(x0 - 6, y + 4), text_anchor="end", **font))
    d.add(d.rect((x0, y1), (x1 - x0, y0 - y1), fill="none", stroke="black", stroke_width=1))
    d.add(d.text(x_label, insert=((x0 + x1) / 2, y0 + 36), text_anchor="middle", **font))

    def inside(p) -> bool:
        return (math.isfinite(p[0]) and math.isfinite(p[1]) and (p[1] > 0 or not y_log)
                and (p[0] > 0 or not x_log))

    for g in guides:
        y = ya.at(g.y, y0, y1)
        d.add(d.line((x0, y), (x1, y), stroke="#888888", stroke_width=1,
                     stroke_dasharray="4,4"))
    legend_y = y0 + 58
    for i, c in enumerate(curves):
        colour, dash = _COLOURS[i % len(_COLOURS)], _DASHES[(i // len(_COLOURS)) % 4]
        xy = [(xa.at(p[0], x0, x1), ya.at(p[1], y0, y1)) for p in c.points if inside(p)]
        if c.line and len(xy) > 1:
            d.add(d.polyline(xy, fill="none", stroke=colour, stroke_width=1.6,
                             **({"stroke_dasharray": dash} if dash else {})))
        for (x, y), text in _merged(xy, c.point_labels):
            _marker(d, i, x, y, colour)
            if text:                     # to the left of a mark near the right edge
                left = x > x1 - 90
                d.add(d.text(text, insert=(x - 5 if left else x + 5, y - 5), fill=colour,
                             text_anchor="end" if left else "start",
                             **{**font, "font_size": 9}))
        lx = 20 + (i % cols) * (_W // 2)
        ly = legend_y + 18 * (i // cols)
        d.add(d.line((lx, ly - 4), (lx + 26, ly - 4), stroke=colour, stroke_width=1.6,
                     **({"stroke_dasharray": dash} if dash else {})))
        _marker(d, i, lx + 13, ly - 4, colour)
        d.add(d.text(c.label, insert=(lx + 34, ly), **font))
    if guides:
        ly = legend_y + 18 * math.ceil(len(curves) / cols)
        d.add(d.line((20, ly - 4), (46, ly - 4), stroke="#888888", stroke_dasharray="4,4"))
        d.add(d.text("; ".join(g.label for g in guides), insert=(54, ly), **font))
    if note:
        d.add(d.text(note, insert=(12, height - 10), fill="#444444", **{**font, "font_size": 11}))
    d.save()
    return path


def _merged(xy: list, labels: Sequence[str]) -> list:
    """The points, each with its label; points drawn on one spot share one joined label."""
    out: list = []
    for j, p in enumerate(xy):
        text = labels[j] if j < len(labels) else ""
        if out and math.dist(out[-1][0], p) < 2.0:
            out[-1] = (out[-1][0], ", ".join(t for t in (out[-1][1], text) if t))
        else:
            out.append((p, text))
    return out


def _marker(d, i: int, x: float, y: float, colour: str) -> None:
    """Marker ``i``: circle, square, triangle, diamond (they read apart in grey too)."""
    shape = i % 4
    if shape == 0:
        d.add(d.circle((x, y), 3.2, fill="white", stroke=colour, stroke_width=1.4))
    elif shape == 1:
        d.add(d.rect((x - 3, y - 3), (6, 6), fill="white", stroke=colour, stroke_width=1.4))
    elif shape == 2:
        d.add(d.polygon([(x, y - 3.8), (x + 3.4, y + 2.6), (x - 3.4, y + 2.6)], fill="white",
                        stroke=colour, stroke_width=1.4))
    else:
        d.add(d.polygon([(x, y - 4), (x + 4, y), (x, y + 4), (x - 4, y)], fill="white",
                        stroke=colour, stroke_width=1.4))
