"""A radial engine solved: its cylinders' forces on one crank found by direct and reverse
cranks (:mod:`tarsim.constructions.balancing.radial`), beside the reference's sum along the
cylinders' own lines and its closed forms
(:func:`~tarsim.constructions.reference.balance.radial_constants`); what is printed, what
results.json gives, and the plot of the resultants against crank angle."""

from __future__ import annotations

import math

from tarsim.constructions.balancing.radial import radial_forces
from tarsim.constructions.narration import numeral, numerals, unit_words, words
from tarsim.constructions.reference.balance import radial_along_lines, radial_constants
from tarsim.graphics.figure import Figure
from tarsim.graphics.plot import PlotMark, Series, draw_line_plot
from ..checked import Checked

__all__ = ["radial_checked", "radial_figure", "radial_lines", "radial_misses"]

AGREE = 1e-12
"""How near (relative to n·m·ω²·r, the size the cranks' forces sum at) the cranks' sum must
come to the sum along the lines and the closed forms: a few roundings of 2n products."""

SAMPLES = tuple(math.radians(d) for d in range(0, 360, 2))
"""The crank angles the resultant's greatest and least are read at (the plot's)."""

KINDS = ("primary", "secondary")


def _scale(e) -> float:
    return e.radial * e.reciprocating * e.speed ** 2 * e.crank


def _quiet(e, v: tuple[float, float]) -> tuple[float, float]:
    """A resultant's components, each within the rounding of the cranks' sum taken as 0
    (the secondary of more than three cylinders)."""
    return tuple(0.0 if abs(c) <= AGREE * _scale(e) else c + 0.0 for c in v)


def _rows(e) -> list[tuple[str, tuple[float, float], float, float]]:
    """(name, the resultant's components at θ, its greatest, its least over a turn) of the
    primary and, with a rod, the secondary resultant, summed over the cranks."""
    at = radial_forces(e, e.at)
    turn = [radial_forces(e, x) for x in SAMPLES]
    rows = []
    for k, name in enumerate(KINDS):
        if at[k] is None:
            continue
        sizes = [math.hypot(*_quiet(e, f[k])) for f in turn]
        rows.append((name, _quiet(e, at[k]), max(sizes), min(sizes)))
    return rows


def _direction(v: tuple[float, float]) -> float | None:
    """A resultant's direction (degrees from cylinder 1's line, counter-clockwise, the crank's
    sense), None for a resultant of 0."""
    return None if v == (0.0, 0.0) else math.degrees(math.atan2(v[1], v[0])) % 360.0


def radial_checked(e) -> dict[str, Checked]:
    """``primary_resultant`` at θ (its components along and across cylinder 1's line and
    its direction), ``primary_max`` and ``primary_min`` over a turn, each ``"constant":
    true`` where they agree (and the secondary's with a rod), beside the reference."""
    want = radial_constants(e)
    lines = radial_along_lines(e, e.at)
    q = {}
    method = "the direct and reverse cranks' forces summed"
    for k, (name, at, most, least) in enumerate(_rows(e)):
        size = math.hypot(*at)
        flat = most - least <= AGREE * _scale(e)
        mark = {"constant": True} if flat else {}
        where = _direction(at)
        q[f"{name}_resultant"] = Checked(
            {"value": size, "unit": "N", "along": at[0], "across": at[1],
             "at_deg": math.degrees(e.at), **mark,
             **({} if where is None else {"direction_deg": where})},
            {"value": math.hypot(*lines[k]), "closed_form": want[k]}, method=method)
        q[f"{name}_max"] = Checked({"value": most, "unit": "N", **mark}, {"value": want[k]},
                                   method=method)
        q[f"{name}_min"] = Checked({"value": least, "unit": "N", **mark}, {"value": want[k]},
                                   method=method)
    return q


def radial_misses(e) -> list[tuple[str, float]]:
    """Each resultant summed over the cranks against its sum along the lines at θ, and its
    greatest and least against the closed form, which is of one size at every angle."""
    want = radial_constants(e)
    lines = radial_along_lines(e, e.at)
    out = []
    for k, (name, at, most, least) in enumerate(_rows(e)):
        miss = max(abs(at[0] - lines[k][0]), abs(at[1] - lines[k][1]),
                   abs(most - want[k]), abs(least - want[k])) / _scale(e)
        if miss > AGREE:
            out.append((f"{name} resultant", miss))
    return out


def radial_lines(e) -> list[str]:
    """Each resultant at θ, where it points, and whether it is one size at every angle."""
    out = []
    for name, at, most, _ in _rows(e):
        where = _direction(at)
        out.append(words(
            "radial engine, {count} cylinders {pitch}° apart on one crank, at θ = {angle}° "
            "from cylinder 1's line: the {kind} resultant {size} N ({along} N along that line, "
            "{across} N across it)", count=numeral(e.radial, "d"),
            pitch=numeral(360 / e.radial, "g"), angle=numeral(math.degrees(e.at), "g"),
            kind=words(name), size=numeral(math.hypot(*at)), along=numeral(at[0]),
            across=numeral(at[1])))
        # one size at every angle (the closed form; radial_misses holds the turn to it)
        out.append(words("the {kind} resultant is {size} N at every crank angle",
                         kind=words(name), size=numeral(most)))
        if where is not None:
            out.append(words(
                "the {kind} resultant points {direction}° from cylinder 1's line: "
                "{sense}", kind=words(name), direction=numeral(where, ".2f"),
                sense=words("along the crank, turning with it (the direct cranks)")
                if name == "primary" else words(
                    "at −2θ, turning at twice the crank's speed against it (the reverse "
                    "cranks)")))
    return out


def radial_figure(e) -> Figure:
    """The resultant primary and secondary forces against crank angle, marked at θ."""
    xs = [float(d) for d in range(0, 361, 2)]
    styles = {"primary": "plot_curve", "secondary": "plot_curve_dashed"}
    series, marks = [], []
    newton = unit_words("N")
    for k, (name, at, _, _) in enumerate(_rows(e)):
        series.append(Series(words(name), tuple(
            (x, math.hypot(*_quiet(e, radial_forces(e, math.radians(x))[k]))) for x in xs),
            styles[name]))
        size = math.hypot(*at)
        marks.append(PlotMark(math.degrees(e.at), size, f"{numerals(f'{size:.4g}')} {newton}"))
    return draw_line_plot(
        words("Resultant forces of the radial engine"), words("crank angle θ (°)"),
        f"F ({newton})", series, marks, x_range=(0.0, 360.0),
        x_ticks=[(float(d), numerals(f"{d}")) for d in range(0, 361, 30)],
        subtitle=words("{count} cylinders {pitch}° apart, θ from cylinder 1's line",
                       count=numerals(f"{e.radial}"), pitch=numerals(f"{360 / e.radial:g}")),
        mark_legend=words("at θ = {angle}°", angle=numerals(f"{math.degrees(e.at):g}")))
