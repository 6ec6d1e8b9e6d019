"""A connecting rod drawn to scale with its equivalent masses: the rod between its pins with
G marked; under it, the equivalent dynamical system (one mass at a pin, the other l2
beyond G) and the two masses at the pins, each mass a dot at its point with its kilograms,
each distance dimensioned, and a dashed line down through G, about which each row keeps
its moments."""

from __future__ import annotations

import math
from typing import Any

from tarsim.constructions.narration import measure_words, numeral, words
from tarsim.constructions.scales import nice_per_cm
from tarsim.constructions.units import LENGTH_UNITS
from tarsim.graphics.figure import Circle, Figure, Path, Text
from tarsim.graphics.hiding import shown_answer
from tarsim.graphics.fitting import to_sheet
from tarsim.graphics.scales import draw_caption
from tarsim.graphics.symbols import draw_dimension, draw_pin

__all__ = ["rod_figure"]

_LONGEST = 160.0
"""Paper (mm) the longest row is drawn at most: a portrait page's drawing width."""

_ROW = 30.0
"""Paper (mm) between the rows."""


def _mass_dot(fig: Figure, at: tuple[float, float], mass: float, biggest: float, label: str,
              name: str) -> None:
    """A mass as a dot whose area grows with it, its point's name under and its kilograms
    above."""
    r = 1.0 + 1.6 * math.sqrt(mass / biggest)
    fig.add(Circle(at, r, "dot"))
    fig.add(Text((at[0], at[1] - r - 2.2), label, 3.0, owner=(at,)))
    # beside the dimension's extension line down from the point, not on it
    fig.add(Text((at[0] + 1.6, at[1] + r + 3.2), name, 3.2, "start", owner=(at,)))


def _centre_mark(fig: Figure, at: tuple[float, float]) -> None:
    """The centre-of-mass symbol: a circle quartered, two opposite quarters filled."""
    r = 1.8
    fig.add(Circle(at, r, "pin"))
    for start in (0.0, math.pi):
        pts = [at] + [(at[0] + r * math.cos(start + f * math.pi / 2),
                       at[1] - r * math.sin(start + f * math.pi / 2)) for f in (0, .25, .5,
                                                                                .75, 1)]
        fig.add(Path(tuple(pts), "dot", closed=True))


def rod_figure(sol: Any, per_cm: float | None = None) -> Figure:
    """The rod and the masses that stand for it, at ``per_cm`` (by default the scale that
    fits its room, fitted to the sheet it is drawn on)."""
    ex, rod = sol.exercise, sol.exercise.rod
    unit = ex.length_unit
    metre = LENGTH_UNITS[unit]
    p, a = ex.ends
    e = sol.equivalent if "equivalent_masses" in ex.find else None
    x_d = None
    if e is not None:
        x_d = rod.centre - e.l2 if ex.crank_first else rod.centre + e.l2
    lo, hi = min(0.0, x_d if x_d is not None else 0.0), max(rod.length, x_d or 0.0)
    if per_cm is None:
        return to_sheet(lambda at: rod_figure(sol, at), nice_per_cm((hi - lo) / metre, _LONGEST))
    k = 10.0 / (per_cm * metre)                        # paper mm a metre

    def x(s: float) -> float:
        return (s - lo) * k

    def length(v: float) -> str:
        return measure_words(f"{v / metre:.6g} {unit}")

    title = words("Connecting rod and its equivalent masses")
    fig = Figure(0.0, 0.0, title=title)
    g = x(rod.centre)
    # the rod: its line of centres, its pins, G
    fig.add(Path(((x(0.0), 0.0), (x(rod.length), 0.0)), "link"))
    for s, name in ((0.0, p), (rod.length, a)):
        draw_pin(fig, (x(s), 0.0))
        fig.add(Text((x(s), -4.0), name, 3.5, owner=((x(s), 0.0),)))
    _centre_mark(fig, (g, 0.0))
    fig.add(Text((g, -4.0), "G", 3.5, owner=((g, 0.0),)))
    dim = draw_dimension(fig, (x(0.0), 0.0), (g, 0.0), (0.0, 1.0), offset=6.0)
    fig.add(Text((dim[0], dim[1] - 2.0), length(rod.to_gudgeon), 2.8, italic=False))
    dim = draw_dimension(fig, (g, 0.0), (x(rod.length), 0.0), (0.0, 1.0), offset=6.0)
    fig.add(Text((dim[0], dim[1] - 2.0), length(rod.to_crank), 2.8, italic=False))
    rows: list[tuple[str, list[tuple[float, float, str]],
                     list[tuple[float, float, str, str]]]] = []
    if e is not None:
        pin_x = rod.length if ex.crank_first else 0.0
        rows.append((words("equivalent dynamical system"),
                     [(pin_x, e.at_pin, ex.one_mass_at), (x_d, e.beyond, ex.second)],
                     [(pin_x, rod.centre, "l1", length(e.l1)),
                      (rod.centre, x_d, "l2", shown_answer(length(e.l2), "…"))]))
    if {"pin_masses", "equivalent_inertia", "correction_couple"} & set(ex.find):
        mp, ma = sol.at_pins
        rows.append((words("two masses at the pins"),
                     [(0.0, mp, p), (rod.length, ma, a)],
                     [(0.0, rod.centre, "l1", length(rod.to_gudgeon)),
                      (rod.centre, rod.length, "l3", length(rod.to_crank))]))
    biggest = max([m for _, ms, _ in rows for _, m, _ in ms] + [rod.mass])
    y = 0.0
    for name, masses, dims in rows:
        y += _ROW
        fig.add(Path(((x(lo), y), (x(hi), y)), "construction"))
        # set by its middle, which stands put whichever way the language reads
        label = Text((0.0, y + 1.0), name, 3.2, italic=False)
        fig.add(Text((x(lo) - 8.0 - label.width / 2, y + 1.0), name, 3.2, italic=False))
        for s, m, point in masses:
            _mass_dot(fig, (x(s), y), m, biggest, shown_answer(measure_words(f"{m:.4g} kg"), "…"),
                      point)
        for s0, s1, symbol, measure in dims:
            a0, a1 = sorted((x(s0), x(s1)))
            mid = draw_dimension(fig, (a0, y), (a1, y), (0.0, 1.0), offset=12.0)
            # the measure over the line, its symbol under it: neither language's order
            # then turns "l1 = 120 mm" about
            fig.add(Text((mid[0], mid[1] - 2.0), measure, 2.8, italic=False))
            fig.add(Text((mid[0], mid[1] + 2.8), symbol, 3.0))
    if rows:
        fig.add(Path(((g, 3.0), (g, y + 3.0)), "reference"))
    lines = [words("m = {mass} kg, k = {k}", mass=numeral(rod.mass, "g"),
                   k=length(math.sqrt(rod.inertia / rod.mass)))
             if rod.inertia > 0 else words("m = {mass} kg", mass=numeral(rod.mass, "g"))]
    if "correction_couple" in ex.find:
        lines += [line for line in [shown_answer(words(
            "correction couple {couple} N·m {sense}", couple=numeral(abs(sol.couple)),
            sense=sol.sense(sol.couple)))] if line]
    draw_caption(fig, title, lines, per_cm=per_cm, unit=unit, scale_name="Scale")
    return fig
