"""A V engine solved: its two cylinders' forces on one crank summed along their lines
(:mod:`tarsim.constructions.balancing.vee`), beside the books' closed forms
(:func:`~tarsim.constructions.reference.balance.vee_resultants`); what is printed, what
results.json gives, and the plot of the resultants against crank angle."""

from __future__ import annotations

import math

from tarsim.constructions.balancing.vee import vee_forces, vee_greatest
from tarsim.constructions.narration import numeral, numerals, unit_words, words
from tarsim.constructions.reference.balance import vee_resultants
from tarsim.graphics.figure import Figure
from tarsim.graphics.plot import PlotMark, Series, draw_line_plot
from ..checked import Checked

__all__ = ["vee_checked", "vee_figure", "vee_lines", "vee_misses"]

AGREE = 1e-12
"""How near (relative to 2·m·ω²·r, the size the two vectors sum at) the summed forces must
come to the closed forms: a few roundings of two products."""

FLAT = 1e-12
"""A resultant whose greatest and least differ by no more than this (relative) stands at one
size at every crank angle (the primary of a V at 90°): it has no crank angle of its own."""


def _components(e, k: int) -> tuple[float, float]:
    """The resultant's components at θ, along and across the centre line, a rounding of
    the two vectors' sum taken as 0 (a V at 90° has no secondary along its centre line)."""
    return _quiet(e, vee_forces(e, e.at)[k])


def _quiet(e, v: tuple[float, float]) -> tuple[float, float]:
    """A resultant's components, each within the rounding of the two vectors' sum taken
    as 0."""
    noise = AGREE * 2 * e.reciprocating * e.speed ** 2 * e.crank
    return tuple(0.0 if abs(c) <= noise else c for c in v)


def _rows(e) -> list[tuple[str, float, float, float | None, float, float | None]]:
    """(name, at θ, greatest, the crank angle it first comes at or None, the least, the
    crank angle that first comes at or None) of the primary and, with a rod, the secondary
    resultant, as summed along the lines. The least is at the other end of the ellipse's
    axes from the greatest: a quarter turn of θ on (an eighth for the secondary's 2θ)."""
    at = vee_forces(e, e.at)
    most = vee_greatest(e)
    rows = []
    for k, name in enumerate(("primary", "secondary")):
        if at[k] is None:
            continue
        size, where = most[k]
        low = (90.0 if where == 0.0 else 0.0) / (1 + k)
        least = math.hypot(*_quiet(e, vee_forces(e, math.radians(low))[k]))
        flat = size - least <= FLAT * size
        rows.append((name, math.hypot(*at[k]), size, None if flat else where, least,
                     None if flat else low))
    return rows


def _closed(e) -> dict[str, tuple[float, float, float]]:
    """Each resultant at θ, its greatest and its least, by the closed forms: the ellipse's
    semi-axes, 2F·cos²α and 2F·sin²α (the secondary's 2(F/n)·|cos α·cos 2α| and
    2(F/n)·|sin α·sin 2α|)."""
    a = e.vee / 2
    f = 2 * e.reciprocating * e.speed ** 2 * e.crank
    at = vee_resultants(e, e.at)
    ends = (math.cos(a) ** 2, math.sin(a) ** 2)
    out = {"primary": (at[0], f * max(ends), f * min(ends))}
    if e.rod is not None:
        ends = (abs(math.cos(a) * math.cos(2 * a)), abs(math.sin(a) * math.sin(2 * a)))
        n = e.rod / e.crank
        out["secondary"] = (at[1], f / n * max(ends), f / n * min(ends))
    return out


def vee_checked(e) -> dict[str, Checked]:
    """``primary_resultant`` at θ, ``primary_max`` and ``primary_max_at``,
    ``primary_min`` and ``primary_min_at`` (and the secondary's with a rod), beside the
    closed forms; a resultant of one size at every angle has no ``_at``."""
    want = _closed(e)
    q = {}
    method = "the cylinders' forces summed along their lines"
    for name, at, size, where, least, low in _rows(e):
        along, across = _components(e, 0 if name == "primary" else 1)
        q[f"{name}_resultant"] = Checked(
            {"value": at, "unit": "N", "along": along, "across": across,
             "at_deg": math.degrees(e.at)}, {"value": want[name][0]}, method=method)
        q[f"{name}_max"] = Checked({"value": size, "unit": "N",
                                    **({"constant": True} if where is None else {})},
                                   {"value": want[name][1]}, method=method)
        q[f"{name}_min"] = Checked({"value": least, "unit": "N",
                                    **({"constant": True} if where is None else {})},
                                   {"value": want[name][2]}, method=method)
        every = 180.0 if name == "primary" else 90.0
        if where is not None:
            q[f"{name}_max_at"] = Checked({"value": where, "unit": "deg", "every_deg": every})
            q[f"{name}_min_at"] = Checked({"value": low, "unit": "deg", "every_deg": every})
    return q


def vee_misses(e) -> list[tuple[str, float]]:
    """Each resultant summed along the lines against its closed form."""
    size = 2 * e.reciprocating * e.speed ** 2 * e.crank
    want = _closed(e)
    out = []
    for name, at, most, _, least, _ in _rows(e):
        miss = max(abs(at - want[name][0]), abs(most - want[name][1]),
                   abs(least - want[name][2])) / size
        if miss > AGREE:
            out.append((f"{name} resultant", miss))
    return out


def vee_lines(e) -> list[str]:
    """The forces at θ, and each resultant's greatest and least and where they come."""
    out = []
    for name, at, size, where, least, low in _rows(e):
        along, across = _components(e, 0 if name == "primary" else 1)
        out.append(words("V engine, {vee}° between its lines, at θ = {angle}° from the centre "
                         "line: the {kind} resultant {size} N ({along} N along the centre "
                         "line, {across} N across it)", vee=numeral(math.degrees(e.vee), "g"),
                         angle=numeral(math.degrees(e.at), "g"), kind=words(name),
                         size=numeral(at), along=numeral(along), across=numeral(across)))
        out.append(words("the {kind} resultant is {size} N at every crank angle", kind=words(
            name), size=numeral(size)) if where is None else words(
            "the greatest {kind} resultant: {size} N, first at θ = {angle}°", kind=words(name),
            size=numeral(size), angle=numeral(where, "g")))
        if low is not None:
            out.append(words("the least {kind} resultant: {size} N, first at θ = {angle}°",
                             kind=words(name), size=numeral(least), angle=numeral(low, "g")))
    return out


def vee_figure(e) -> Figure:
    """The resultant primary and secondary forces against crank angle, marked at θ."""
    xs = [float(d) for d in range(0, 361, 2)]
    styles = {"primary": "plot_curve", "secondary": "plot_curve_dashed"}
    series, marks = [], []
    newton = unit_words("N")
    for k, (name, at, _, _, _, _) in enumerate(_rows(e)):
        series.append(Series(words(name), tuple(
            (x, math.hypot(*vee_forces(e, math.radians(x))[k])) for x in xs), styles[name]))
        marks.append(PlotMark(math.degrees(e.at), at, f"{numerals(f'{at:.4g}')} {newton}"))
    return draw_line_plot(
        words("Resultant forces of the V engine"), words("crank angle θ (°)"), f"F ({newton})",
        series, marks, x_range=(0.0, 360.0),
        x_ticks=[(float(d), numerals(f"{d}")) for d in range(0, 361, 30)],
        subtitle=words("{vee}° between the lines, θ from the centre line",
                       vee=numerals(f"{math.degrees(e.vee):g}")),
        mark_legend=words("at θ = {angle}°", angle=numerals(f"{math.degrees(e.at):g}")))
