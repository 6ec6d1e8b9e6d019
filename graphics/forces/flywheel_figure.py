"""The flywheel's figures: a turning-moment diagram given as T(θ), its mean line, its areas
shaded with their joules and the shaft's greatest acceleration and retardation marked (for
an engine against a machine, the excess T_e − T_m beside the two torques given); or,
for a diagram given by its areas, the energy at each intercept, its highest and lowest
marked ΔE apart; or, for a flywheel given with no diagram, its energy ½·I·ω² against its
speed, the greatest and least speeds marked ΔE apart."""

from __future__ import annotations

import math
from typing import Any

from tarsim.constructions.narration import numerals, unit_words, words
from tarsim.graphics.figure import Figure
from tarsim.graphics.hiding import shown_answer
from tarsim.graphics.plot import PlotMark, Series, draw_line_plot, nice_ticks

__all__ = ["torque_figure", "energy_figure", "energy_fills", "speed_figure"]


def _short(x: float) -> str:
    """A number for a label: four figures, but no exponent on a torque of tens of thousands."""
    s = f"{x:.4g}"
    return f"{x:.0f}" if "e" in s and 1 <= abs(x) < 1e9 else s


def _signed(energy: float, unit: str) -> str:
    """An area's label: its sign, four figures and its unit."""
    return f"{numerals(('+' if energy > 0 else '−') + _short(abs(energy)))} {unit}"


def _ticks(period: float) -> list[tuple[float, str]]:
    step = 30.0 if period <= 360 else 60.0
    return [(k * step, numerals(f"{k * step:g}")) for k in range(int(period // step) + 1)]


def torque_figure(sol: Any) -> Figure:
    """T against the crank angle over the cycle, with the mean and the areas."""
    ex = sol.exercise
    if ex.machine is not None:
        return _excess_figure(sol)
    r = sol.reading
    period = math.degrees(ex.cycle)
    pts = tuple((math.degrees(t), v) for t, v in r.samples) + ((period, r.samples[0][1]),)
    torque = unit_words("N·m")
    curve = words("resisting torque") if ex.resisting else words("turning moment")
    series = [Series(curve, pts),
              Series(words("mean {value} {unit}", value=shown_answer(numerals(_short(r.mean)), "…"),
                           unit=torque),
                     ((0.0, r.mean), (period, r.mean)), "plot_curve_dashed")]
    if ex.single:                   # one cylinder's diagram, the curve the sum of them
        one = [(math.degrees(t), v) for t, v in ex.single] + [(period, ex.single[0][1])]
        series.append(Series(words("one cylinder's, {n} added", n=numerals(str(len(ex.phases)))),
                             tuple(one), "plot_curve_dotted"))
    fills, tags = energy_fills([p[0] for p in pts[:-1]], [p[1] for p in pts[:-1]], r.mean,
                               [math.degrees(c) for c in r.intercepts], period)
    notes = [words("ΔE = {energy} {unit}, the greatest fluctuation of energy: the highest energy "
                   "less the lowest, adding the areas in turn (shaded light where the machine "
                   "takes more than the mean, dark where less)" if ex.resisting else
                   "ΔE = {energy} {unit}, the greatest fluctuation of energy: the highest energy "
                   "less the lowest, adding the areas in turn (shaded light where the driver "
                   "gives more than the mean, dark where less)",
                   energy=shown_answer(numerals(_short(r.delta_e)), "…"), unit=unit_words("J"))]
    marks = []
    if "greatest_acceleration" in sol.checked:
        labels = ("α min", "α max") if ex.resisting else ("α max", "α min")
        for key, label in zip(("greatest", "least"), labels):
            marks += [PlotMark(math.degrees(theta), t, label) for theta, t in sol.extremes[key]]
        notes.append(words("α max and α min: the shaft's greatest acceleration and retardation, "
                           "where the resisting torque is lowest and highest over the whole "
                           "cycle" if ex.resisting else
                           "α max and α min: the shaft's greatest acceleration and retardation, "
                           "where T is highest and lowest over the whole cycle"))
    return draw_line_plot(
        words("Resisting-torque diagram") if ex.resisting else words("Turning-moment diagram"),
        words("crank angle θ (°)"), f"T ({torque})", series,
        marks, x_range=(0.0, period), x_ticks=_ticks(period), notes=notes, fills=fills,
        tags=tags, mark_legend=words("the shaft's extremes") if marks else "",
        subtitle=ex.name)


def _excess_figure(sol: Any) -> Figure:
    """An engine's turning moment T_e and a machine's resisting torque T_m, both given, and
    what drives the flywheel, the excess T_e − T_m about its mean of 0, its areas shaded."""
    ex, r = sol.exercise, sol.reading
    period = math.degrees(ex.cycle)
    thetas = [t for t, _ in r.samples] + [ex.cycle]
    degrees = [math.degrees(t) for t in thetas]
    shift = ex.machine_mean                  # the reading's diagram is T_e − T_m + its mean
    excess = [v - shift for _, v in r.samples]
    excess.append(excess[0])
    torque = unit_words("N·m")
    series = [Series(words("excess torque T_e − T_m"), tuple(zip(degrees, excess))),
              Series(words("engine's turning moment T_e"),
                     tuple((d, ex.formula(t)) for d, t in zip(degrees, thetas)),
                     "plot_curve_dotted"),
              Series(words("machine's resisting torque T_m"),
                     tuple((d, ex.machine(t)) for d, t in zip(degrees, thetas)),
                     "plot_curve_dash_dot"),
              Series(words("mean {value} {unit}", value=numerals("0"), unit=torque),
                     ((0.0, 0.0), (period, 0.0)), "plot_curve_dashed")]
    fills, tags = energy_fills(degrees[:-1], excess[:-1], 0.0,
                               [math.degrees(c) for c in r.intercepts], period)
    notes = [words("ΔE = {energy} {unit}, the greatest fluctuation of energy: the highest energy "
                   "less the lowest, adding the areas of T_e − T_m in turn (shaded light where "
                   "the engine gives more than the machine takes, dark where less)",
                   energy=shown_answer(numerals(_short(r.delta_e)), "…"), unit=unit_words("J"))]
    marks = []
    if "greatest_acceleration" in sol.checked:
        for key, label in (("greatest", "α max"), ("least", "α min")):
            marks += [PlotMark(math.degrees(theta), t - shift, label)
                      for theta, t in sol.extremes[key]]
        notes.append(words("α max and α min: the shaft's greatest acceleration and retardation, "
                           "where T_e − T_m is highest and lowest over the whole cycle"))
    return draw_line_plot(
        words("Excess-torque diagram"), words("crank angle θ (°)"), f"T ({torque})", series,
        marks, x_range=(0.0, period), x_ticks=_ticks(period), notes=notes, fills=fills,
        tags=tags, mark_legend=words("the shaft's extremes") if marks else "",
        subtitle=ex.name)


def energy_figure(sol: Any) -> Figure:
    """The energy above its value at the first intercept, at each intercept in turn."""
    ex, r = sol.exercise, sol.reading
    levels = [0.0]
    for a in r.areas:
        levels.append(levels[-1] + a)
    pts = tuple((float(i), e) for i, e in enumerate(levels))
    n = len(r.areas)
    marks = [PlotMark(r.highest, levels[int(r.highest)], words("highest")),
             PlotMark(r.lowest, levels[int(r.lowest)], words("lowest"))]
    joule = unit_words("J")
    tags = [((i + 0.5), (levels[i] + levels[i + 1]) / 2, shown_answer(_signed(a, joule)))
            for i, a in enumerate(r.areas)]
    return draw_line_plot(
        words("Energy at the intercepts"), words("intercept, in order"),
        f"E ({joule})", [Series(words("energy above the first intercept's"), pts)], marks,
        x_range=(0.0, float(n)), x_ticks=[(float(i), numerals(str(i))) for i in range(n + 1)],
        notes=[words("ΔE = {energy} {unit}, the greatest fluctuation of energy: the highest "
                     "energy less the lowest",
                     energy=shown_answer(numerals(_short(r.delta_e)), "…"), unit=joule)],
        tags=tags, mark_legend=words("the highest and lowest energy"), subtitle=ex.name)


def speed_figure(sol: Any) -> Figure:
    """The flywheel's energy ½·I·ω² against its speed (in the file's unit), its greatest and
    least speeds marked: the energy between them is ΔE."""
    ex, q = sol.exercise, sol.checked
    per = sol.per_speed_unit               # rad/s in the file's unit of speed
    high, low = q["speed_max"].value["value"], q["speed_min"].value["value"]
    inertia = sol.inertia
    margin = high - low
    start, end = max(low - 2 * margin, 0.0) / per, (high + 2 * margin) / per
    n = 120
    pts = tuple((x, inertia * (x * per) ** 2 / 2 / 1000)
                for x in (start + (end - start) * k / n for k in range(n + 1)))
    kilojoule = unit_words("kJ")
    speed = unit_words(ex.speed_unit)
    marks = [PlotMark(w / per, inertia * w * w / 2 / 1000, label)
             for w, label in ((high, "ω1"), (low, "ω2"))]
    ticks = [(x, numerals(_short(x))) for x in nice_ticks(start, end) if start <= x <= end]
    return draw_line_plot(
        words("The flywheel's energy against its speed"), words("speed ({unit})", unit=speed),
        f"E ({kilojoule})", [Series(words("½·I·ω², I = {inertia} kg·m²",
                                          inertia=shown_answer(numerals(_short(inertia)), "…")),
                                    pts),
                             *(Series(words("{name} = {energy} {unit}", name=name,
                                            energy=shown_answer(numerals(_short(e)), "…"),
                                            unit=kilojoule),
                                      ((start, e), (end, e)), "plot_curve_dashed")
                               for name, e in (("E1", marks[0].y), ("E2", marks[1].y)))],
        marks, x_range=(start, end), x_ticks=ticks, include_zero=False,
        notes=[words("ΔE = ½·I·(ω1² − ω2²) = {energy} {unit}: the energy the flywheel gives "
                     "up from its greatest speed ω1 to its least ω2",
                     energy=shown_answer(numerals(_short(sol.reading.delta_e)), "…"),
                     unit=unit_words("J"))],
        mark_legend=words("the greatest and least speeds"), subtitle=ex.name)


def energy_fills(degrees: list[float], torques: list[float], mean: float,
                 cuts: list[float], period: float, label=None):
    """Each area's outline between the curve (at ``degrees`` over a ``period``) and the
    ``mean``, cut at the intercepts ``cuts`` (°), and its label (J), written by ``label``
    (its sign, four figures and J by default), with the area's outlines (two for one
    wrapped across the period's end, labelled once) so that the plot sets it inside them."""
    label = label or (lambda area: _signed(area, unit_words("J")))
    degrees = list(degrees) + [period]
    torques = list(torques) + [torques[0]]
    cuts = sorted(c % period for c in cuts)
    fills, tags = [], []
    for k, a in enumerate(cuts):
        b = cuts[k + 1] if k + 1 < len(cuts) else cuts[0] + period
        # between the cuts, and at a cut that falls on a jump its value inside the area:
        # the last at the cut it starts from, the first at the one it ends on
        inner, start, end = [], None, None
        for turn in (0.0, period):
            for d, t in zip(degrees, torques):
                if a < d + turn < b:
                    inner.append((d + turn, t))
                elif d + turn == a:
                    start = (a, t)
                elif d + turn == b and end is None:
                    end = (b, t)
        pts = [(a, mean)] + [p for p in (start,) if p] + inner + [p for p in (end,) if p] + \
            [(b, mean)]
        area = sum((x1 - x0) * ((y0 + y1) / 2 - mean)
                   for (x0, y0), (x1, y1) in zip(pts, pts[1:])) * math.pi / 180
        pieces = _split(pts, mean, period)
        fills += [("triangle" if area > 0 else "triangle_alt", p) for p in pieces]
        big = max(pieces, key=lambda p: p[-1][0] - p[0][0])
        peak = max(big, key=lambda p: abs(p[1] - mean))
        tags.append(((big[0][0] + big[-1][0]) / 2, (peak[1] + mean) / 2,
                     shown_answer(label(area)), pieces))
    return fills, tags


def _split(pts, mean: float, period: float):
    """An area's outline cut at the cycle's end: the part past it goes back to its start."""
    inside = [p for p in pts if p[0] <= period]
    past = [(x - period, y) for x, y in pts if x >= period]
    out = []
    if len(inside) > 1:
        if past:
            inside.append((period, past[0][1]))
        out.append(inside + [(inside[-1][0], mean)])
    if len(past) > 1:
        out.append([(0.0, mean), (0.0, past[0][1])] + past)
    return out
