"""The class at a glance: summary.svg beside grades.csv, the histogram of the scores and
each item's error rate.

The histogram counts the graded drawings in ten bins of ten per cent (the last holds
100 %), each bar's count written on it. An item's error rate is the share of the drawings
graded on it where it was not correct (missing, wrong, or following from an earlier
error: a follow-through is drawn in its own shade, as it may still score), worst first,
with how many of how many beside the bar; a label that names nothing asked ("extra") is
one bar of its own, the share of drawings with any. The words are in the language spoken.
"""

from __future__ import annotations

from dataclasses import dataclass

from tarsim.constructions.narration import Number, numerals, right_to_left, words
from tarsim.graphics.rtl import RTL_FONT, is_rtl
from .grade import Grade
from .overlay import AMBER, BLUE, FOLLOWS, RED, named, sans_width

__all__ = ["summary_svg", "histogram", "error_rates", "Rate", "SUMMARY"]

SUMMARY = "summary.svg"
"""The class's plot, in the output folder beside grades.csv."""

_W, _LEFT, _RIGHT = 180.0, 22.0, 10.0
"""The plot's width and its margins (mm)."""

_PLOT_H, _BAR_H = 55.0, 5.0
"""The histogram's height, and an item's bar's (mm)."""


def histogram(grades: list[Grade]) -> list[int]:
    """How many of ``grades`` score in each tenth: [0, 10), …, [80, 90), [90, 100].

    >>> from .grade import Grade, Item
    >>> histogram([Grade("x", "a.svg", [Item("b", "correct")]), Grade("x", "b.svg")])
    [1, 0, 0, 0, 0, 0, 0, 0, 0, 1]
    """
    counts = [0] * 10
    for g in grades:
        counts[min(9, int(g.score // 10))] += 1
    return counts


@dataclass(frozen=True)
class Rate:
    """An item's errors over a class: drawings graded on it, not correct, and of those how
    many follow from an earlier error."""

    name: str
    graded: int
    wrong: int
    follows: int = 0

    @property
    def share(self) -> float:
        """Per cent of the drawings graded on it where it was not correct."""
        return 100.0 * self.wrong / self.graded if self.graded else 0.0


def error_rates(grades: list[Grade]) -> list[Rate]:
    """Each item's :class:`Rate`, worst first (then by name), and last, if any drawing
    labels something not asked, the share of drawings with an extra."""
    rates: dict[str, list[int]] = {}
    extra = 0
    for g in grades:
        extra += any(i.verdict == "extra" for i in g.items)
        for i in g.items:
            if i.verdict == "extra":
                continue
            r = rates.setdefault(i.name, [0, 0, 0])
            r[0] += 1
            r[1] += i.verdict != "correct"
            r[2] += i.verdict == FOLLOWS
    out = sorted((Rate(n, *r) for n, r in rates.items()), key=lambda r: (-r.share, r.name))
    if extra:
        out.append(Rate(words("extra"), len(grades), extra))
    return out


def summary_svg(grades: list[Grade], exercise: str, unread: int = 0) -> str:
    """summary.svg of a class's ``grades`` (``unread``: files that got no grade)."""
    from tarsim.graphics.svg_tree import Drawing

    rtl = right_to_left()
    rates = error_rates(grades)
    height = 30.0 + _PLOT_H + 30.0 + 14.0 + max(1, len(rates)) * (_BAR_H + 2.0) + 16.0
    dwg = Drawing(size=(f"{_W}mm", f"{height:.1f}mm"),
                           viewBox=f"0 0 {_W} {height:.1f}", profile="full", debug=False,
                           direction="ltr")
    dwg.add(dwg.rect((0, 0), (_W, height), fill="#fff"))
    ink = dwg.add(dwg.g(font_family="DejaVu Sans", font_size=3.2, fill="#222"))

    def say(text: str, at, anchor: str = "start", **style):
        if is_rtl(text):
            style |= {"direction": "rtl", "font_family": RTL_FONT,
                      "text_anchor": {"start": "end", "end": "start"}.get(anchor, anchor)}
        else:
            style |= {"text_anchor": anchor}
        ink.add(dwg.text(text, insert=at, **style))

    def heading(text: str, y: float, **style):
        say(text, (_W - _RIGHT, y), "end", **style) if rtl else say(text, (_LEFT - 12, y),
                                                                       **style)
    mean = sum(g.score for g in grades) / len(grades) if grades else 0.0
    heading(words("{exercise}: {graded} drawings graded, mean score {mean} %",
                  exercise=named(exercise), graded=Number(len(grades), "d"),
                  mean=Number(mean, ".0f")), 9.0, font_size=4.4, font_weight="bold")
    if unread:
        heading(words("{unread} files could not be graded (see grades.csv)",
                      unread=Number(unread, "d")), 15.0, font_size=3.0, fill="#555")
    y = _histogram(dwg, ink, say, heading, histogram(grades), 24.0)
    _rates(dwg, ink, say, heading, rates, y + 14.0, len(grades))
    return dwg.tostring()


def _histogram(dwg, ink, say, heading, counts: list[int], top: float) -> float:
    """The histogram from ``top``: bars, their counts, both axes; the y under it."""
    heading(words("Scores"), top, font_size=3.8, font_weight="bold")
    x0, x1 = _LEFT, _W - _RIGHT
    base = top + 6.0 + _PLOT_H
    peak = max(max(counts), 1)
    step = max(1, -(-peak // 5))                     # at most six ticks up the axis
    per = _PLOT_H / (step * -(-peak // step))
    bars = ink.add(dwg.g(id="histogram"))
    width = (x1 - x0) / 10
    for k, n in enumerate(counts):
        left = x0 + k * width
        bars.add(dwg.rect((left + 0.6, base - n * per), (width - 1.2, n * per), fill=BLUE,
                          class_="bar"))
        if n:
            bars.add(dwg.text(numerals(str(n)), insert=(left + width / 2, base - n * per - 1.2),
                              text_anchor="middle", font_size=3.0, class_="count"))
    axes = ink.add(dwg.g(stroke="#222", stroke_width=0.3))
    axes.add(dwg.line((x0, base), (x1, base)))
    axes.add(dwg.line((x0, base), (x0, base - _PLOT_H)))
    for k in range(11):
        x = x0 + k * width
        axes.add(dwg.line((x, base), (x, base + 1.2)))
        say(numerals(str(10 * k)), (x, base + 4.6), "middle", font_size=2.8)
    for v in range(0, step * -(-peak // step) + 1, step):
        axes.add(dwg.line((x0 - 1.2, base - v * per), (x0, base - v * per)))
        say(numerals(str(v)), (x0 - 2.0, base - v * per + 1.0), "end", font_size=2.8)
    say(words("score (%)"), ((x0 + x1) / 2, base + 10.0), "middle", font_size=3.2)
    label = words("drawings")
    ink.add(dwg.text(label, insert=(x0 - 12.0, base - _PLOT_H / 2), text_anchor="middle",
                     font_size=3.2, transform=f"rotate(-90 {x0 - 12.0} {base - _PLOT_H / 2})",
                     **({"direction": "rtl", "font_family": RTL_FONT} if is_rtl(label)
                        else {})))
    return base + 10.0


def _rates(dwg, ink, say, heading, rates: list[Rate], top: float, graded: int) -> None:
    """Each item's error rate as a bar from ``top``: the item's name, the bar (follow-
    throughs in their own shade), and "wrong of graded" beside it."""
    heading(words("Each item's error rate (share of drawings where it was not correct)"),
            top, font_size=3.8, font_weight="bold")
    if not rates:
        heading(words("no drawing could be graded"), top + 8.0, fill="#555")
        return
    names = max(sans_width(r.name, 3.2) for r in rates)
    x0 = _LEFT + max(0.0, names - _LEFT + 14.0)
    x1 = _W - _RIGHT - 22.0
    scale = ink.add(dwg.g(stroke="#bbb", stroke_width=0.2))
    bottom = top + 5.0 + len(rates) * (_BAR_H + 2.0)
    for pct in range(0, 101, 25):
        x = x0 + (x1 - x0) * pct / 100
        scale.add(dwg.line((x, top + 3.0), (x, bottom)))
        say(words("{pct} %", pct=Number(pct, "d")), (x, bottom + 4.0), "middle",
            font_size=2.6)
    bars = ink.add(dwg.g(id="error-rates"))
    for k, r in enumerate(rates):
        y = top + 5.0 + k * (_BAR_H + 2.0)
        say(r.name, (x0 - 2.0, y + _BAR_H - 1.2), "end", font_size=3.2)
        own = (r.wrong - r.follows) / r.graded if r.graded else 0.0
        follows = r.follows / r.graded if r.graded else 0.0
        bars.add(dwg.rect((x0, y), ((x1 - x0) * own, _BAR_H), fill=RED, class_="rate"))
        if follows:
            bars.add(dwg.rect((x0 + (x1 - x0) * own, y), ((x1 - x0) * follows, _BAR_H),
                              fill=AMBER, class_="follows"))
        say(words("{share} % ({wrong} of {graded})", share=Number(r.share, ".0f"),
                  wrong=Number(r.wrong, "d"), graded=Number(r.graded, "d")),
            (x0 + (x1 - x0) * r.share / 100 + 1.5, y + _BAR_H - 1.2), font_size=2.8)
    key = [(RED, words("graded wrong"))] + ([(AMBER, words(FOLLOWS))]
                                            if any(r.follows for r in rates) else [])
    x = x0
    for colour, text in key:                         # the bars' colours, under the scale
        ink.add(dwg.rect((x, bottom + 7.4), (3.0, 3.0), fill=colour))
        say(text, (x + 4.5, bottom + 10.0), font_size=2.8)
        x += 4.5 + sans_width(text, 2.8) + 6.0
