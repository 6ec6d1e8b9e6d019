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
    noise = AGREE * 2 * e.reciprocating * e.speed ** 2 * e.crank
    return tuple(0.0 if abs(c) <= noise else c for c in vee_forces(e, e.at)[k])


def _rows(e) -> list[tuple[str, float, float, float | None, float]]:
    """(name, at θ, greatest, the crank angle it first comes at or None, the least) of the
    primary and, with a rod, the secondary resultant, as summed along the lines."""
    at = vee_forces(e, e.at)
    most = vee_greatest(e)
    rows = []
    for k, name in enumerate(("primary", "secondary")):
        if at[k] is None:
            continue
        size, where = most[k]
        least = math.hypot(*vee_forces(e, math.radians(90.0 if where == 0.0 else 0.0)
                                       / (1 + k))[k])
        flat = size - least <= FLAT * size
        rows.append((name, math.hypot(*at[k]), size, None if flat else where, least))
    return rows


def _closed(e) -> dict[str, tuple[float, float]]:
    """Each resultant at θ and its greatest, by the closed forms."""
    a = e.vee / 2
    f = 2 * e.reciprocating * e.speed ** 2 * e.crank
    at = vee_resultants(e, e.at)
    out = {"primary": (at[0], f * max(math.cos(a) ** 2, math.sin(a) ** 2))}
    if e.rod is not None:
        out["secondary"] = (at[1], f / (e.rod / e.crank) * max(
            abs(math.cos(a) * math.cos(2 * a)), abs(math.sin(a) * math.sin(2 * a))))
    return out


def vee_checked(e) -> dict[str, Checked]:
    """``primary_resultant`` at θ, ``primary_max`` and ``primary_max_at`` (and the
    secondary's with a rod), beside the closed forms."""
    want = _closed(e)
    q = {}
    method = "the cylinders' forces summed along their lines"
    for name, at, size, where, _ in _rows(e):
        along, across = _components(e, 0 if name == "primary" else 1)
        q[f"{name}_resultant"] = Checked(
            {"value": at, "unit": "N", "along": along, "across": across,
             "at_deg": math.degrees(e.at)}, {"value": want[name][0]}, method=method)
        q[f"{name}_max"] = Checked({"value": size, "unit": "N",
                                    **({"constant": True} if where is None else {})},
                                   {"value": want[name][1]}, method=method)
        if where is not None:
            q[f"{name}_max_at"] = Checked({"value": where, "unit": "deg",
                                           "every_deg": 180.0 if name == "primary" else 90.0})
    return q


def vee_misses(e) -> list[tuple[str, float]]:
    """Each resultant summed along the lines against its closed form."""
    size = 2 * e.reciprocating * e.speed ** 2 * e.crank
    want = _closed(e)
    out = []
    for name, at, most, _, _ in _rows(e):
        miss = max(abs(at - want[name][0]), abs(most - want[name][1])) / size
        if miss > AGREE:
            out.append((f"{name} resultant", miss))
    return out


def vee_lines(e) -> list[str]:
    """The forces at θ, and each resultant's greatest and where it comes."""
    out = []
    for name, at, size, where, _ in _rows(e):
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
    return out


def vee_figure(e) -> Figure:
    """The resultant primary and secondary forces against crank angle, marked at θ."""
    xs = [float(d) for d in range(0, 361, 2)]
    styles = {"primary": "plot_curve", "secondary": "plot_curve_dashed"}
    series, marks = [], []
    newton = unit_words("N")
    for k, (name, at, _, _, _) in enumerate(_rows(e)):
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
