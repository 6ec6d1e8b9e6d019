"""The files and words of a sweep: its plots, its tables and what the command line prints.

:mod:`exercises.sweep` finds the numbers; this module only shows them, in the
file's units, with the refined extremes and the graphical checks beside the curves.
"""

from __future__ import annotations

import csv
import io
import math
import re
from pathlib import Path

from tarsim.constructions.model import Mechanism
from tarsim.constructions.narration import Word, numerals, speaking, unit_words, words
from tarsim.graphics.export import figure_pdf, write_folder
from tarsim.graphics.figure import Figure
from tarsim.graphics.plot import CURVE_STYLES, PlotMark, Series, draw_line_plot
from tarsim.graphics.svg import to_svg

from .sweep import KEYS, KINDS, Event, Output, Sample, Sweep, angle_text, number_text

__all__ = ["sweep_figures", "sweep_csv", "points_csv", "sweep_to_files", "write_sweep",
           "format_sweep"]


# ----- units and words ---------------------------------------------------------------------
def _unit(mech: Mechanism, kind: str) -> tuple[float, str, str]:
    """(SI per unit, unit for people, unit for a CSV header) of a kind of value."""
    u = mech.units
    length = u.length
    return {"length": (u.metres, length, length),
            "velocity": (u.metres, f"{length}/s", f"{length}/s"),
            "acceleration": (u.metres, f"{length}/s²", f"{length}/s^2"),
            "angle": (1.0, "rad", "rad") if u.angle == "rad" else (math.pi / 180, "°", "deg"),
            "omega": ((math.tau / 60, "rpm", "rpm") if u.angular_velocity == "rpm"
                      else (1.0, "rad/s", "rad/s")),
            "alpha": (1.0, "rad/s²", "rad/s^2")}[kind]


def _in_units(mech: Mechanism, key: str, value: float) -> float:
    return value / _unit(mech, KINDS[key])[0] + 0.0


def _shown(mech: Mechanism, key: str, value: float) -> str:
    """A value in the file's unit with its unit: "679.134 mm", "42.2004°" (in the spoken
    language's digits and unit names)."""
    unit = _unit(mech, KINDS[key])[1]
    return (f"{numerals(number_text(_in_units(mech, key, value)))}"
            f"{'' if unit == '°' else ' '}{unit_words(unit)}")


def _angle(mech: Mechanism, angle: float) -> str:
    """:func:`~.sweep.angle_text` in the spoken language's digits and unit names."""
    text = angle_text(mech, angle)
    return numerals(text[:-4]) + " " + unit_words("rad") if text.endswith(" rad") else \
        numerals(text)


def _link(mech: Mechanism, number: int) -> str:
    """A link as the figures name it: "link 4 (lever)", its name said in the spoken language."""
    link = mech.link(number)
    return words("link {n} ({name})", n=link.number, name=words(link.name)) if link.name \
        else words("link {n}", n=link.number)


def _words(sw: Sweep) -> tuple[str, str]:
    """What the output is, in words: ("B", " along its guide (+x)") or ("link 4 (lever)", "")."""
    out, mech = sw.output, sw.exercise.mechanism
    if out.kind == "link":
        return _link(mech, out.link), ""
    if out.kind == "point":
        return out.point, ""
    dx, dy = out.direction
    named = {(1.0, 0.0): "+x", (-1.0, 0.0): "−x", (0.0, 1.0): "+y", (0.0, -1.0): "−y"}
    way = named.get((round(dx, 12) + 0.0, round(dy, 12) + 0.0))
    way = way or numerals(number_text(math.degrees(math.atan2(dy, dx)))) + "°"
    return out.point, words(" along its guide ({way})", way=way)


def _turning(sw: Sweep) -> str:
    """"360 positions from θ2 = 90°, ω2 = 1 rad/s cw, α2 = 0"."""
    mech = sw.exercise.mechanism
    d = mech.drive
    factor, unit, _ = _unit(mech, "omega")
    sense = "cw" if d.omega < 0 else "ccw"
    zero = numerals("0")
    w = words("ω_{link} = {value} {unit} {sense}", link=d.link,
              value=numerals(number_text(abs(d.omega) / factor)), unit=unit_words(unit),
              sense=Word(sense)) if d.omega else f"ω_{d.link} = {zero}"
    a = f"α_{d.link} = {numerals(number_text(d.alpha))} {unit_words('rad/s²')}" if d.alpha \
        else f"α_{d.link} = {zero}"
    return words("{n} positions from θ_{link} = {angle}, {w}, {a}", n=numerals(
        str(len(sw.samples))), link=d.link, angle=_angle(mech, d.angle), w=w, a=a)


def _event_lines(sw: Sweep, figure: int) -> list[str]:
    """What a figure says of the refined zeros: 0 position, 1 velocity, 2 acceleration."""
    if sw.output.kind == "point" or sw.rotates:
        return []
    mech = sw.exercise.mechanism
    (pkey, *_), (vkey,), (akey,) = KEYS[sw.output.kind]
    p, v, a = (sw.output.symbol(k) for k in (pkey, vkey, akey))
    th = f"θ_{mech.drive.link}"
    zero = numerals("0")

    def at(e: Event, key: str) -> str:
        return f"{_shown(mech, key, e.values[key])} ({th} = {_angle(mech, e.angle)})"

    def where(events: list[Event]) -> str:
        return f"{th} = " + words(", ").join(_angle(mech, e.angle) for e in events)

    v_zero = [e for e in sw.events if e.key == vkey]
    a_zero = [e for e in sw.events if e.key == akey]
    lines = []
    if figure == 0:
        items = [(e.angle, e.values) for e in v_zero] + [(s.angle, s.values) for s in sw.solved]
        low, high = (f(items, key=lambda it: it[1][pkey]) for f in (min, max))
        both = all(any(e.angle == it[0] for e in v_zero) for it in (low, high))
        what = "stroke" if sw.output.kind == "slider" else "swing"
        if high[1][pkey] - low[1][pkey] <= 1e-12 * max(1.0, abs(high[1][pkey])):
            return [words("{p} stays {value}", p=p, value=_shown(mech, pkey, high[1][pkey]))]
        lines.append(words("{p} from {low} to {high}{where}: {what} {span}", p=p,
                           low=at(Event(vkey, *low), pkey), high=at(Event(vkey, *high), pkey),
                           where=words(", where {v} = {zero}", v=v, zero=zero) if both else "",
                           what=Word(what),
                           span=_shown(mech, pkey, high[1][pkey] - low[1][pkey])))
    if v_zero and figure == 1:
        lines.append(words("{v} = {zero} at {where}, where {p} is extreme", v=v, zero=zero,
                           where=where(v_zero), p=p))
    if a_zero and figure == 1:
        low, high = (f(a_zero, key=lambda e: e.values[vkey]) for f in (min, max))
        lines.append(words("{v} peaks at {low} and {high}, where {a} = {zero}", v=v,
                           low=at(low, vkey), high=at(high, vkey), a=a, zero=zero))
    if a_zero and figure == 2:
        lines.append(words("{a} = {zero} at {where}, where {v} peaks", a=a, zero=zero,
                           where=where(a_zero), v=v))
    return lines


def _gaps(sw: Sweep) -> list[str]:
    """Runs of skipped positions as "θ2 = 170°…190°: cannot assemble: …" (the first reason)."""
    mech = sw.exercise.mechanism
    out, run = [], []
    for s in (*sw.samples, Sample(0.0, {"end": 0.0})):
        if not s.values:
            run.append(s)
            continue
        if run:
            span = _angle(mech, run[0].angle)
            if len(run) > 1:
                span += f"…{_angle(mech, run[-1].angle)}"
            out.append(words("θ_{link} = {span} ({n} skipped): {reason}", link=mech.drive.link,
                             span=span, n=numerals(str(len(run))), reason=run[0].reason))
            run = []
    return out


# ----- figures -------------------------------------------------------------------------------
def sweep_figures(sw: Sweep) -> dict[str, Figure]:
    """The position, velocity and acceleration plots: ``{file stem: figure}``."""
    mech = sw.exercise.mechanism
    out = sw.output
    deg = mech.units.angle != "rad"
    full = 360.0 if deg else math.tau
    link = mech.drive.link
    if deg:
        ticks = [(float(a), numerals(str(a))) for a in range(0, 361, 30)]
    else:
        names = ["0", "π/4", "π/2", "3π/4", "π", "5π/4", "3π/2", "7π/4", "2π"]
        ticks = [(i * math.pi / 4, numerals(t)) for i, t in enumerate(names)]

    def x_of(angle: float) -> float:
        return (math.degrees(angle) % 360.0) if deg else angle % math.tau

    order = sorted(sw.samples, key=lambda s: x_of(s.angle))
    who, along = _words(sw)
    title = mech.name or sw.exercise.id
    stems = ("sweep-position", "sweep-velocity", "sweep-acceleration")
    quantity = ("Position", "Velocity", "Acceleration")
    if out.kind == "link":
        quantity = ("Angle", "Angular velocity", "Angular acceleration")
    figures = {}
    for i, keys in enumerate(KEYS[out.kind]):
        if out.kind == "slider":
            keys = keys[:1]
        series = []
        for j, key in enumerate(keys):
            pts = [(x_of(s.angle), _in_units(mech, key, s.values[key])) if s.values else None
                   for s in order]
            first, last = pts[0], pts[-1]       # one turn: run a step past each end
            pts = ([(last[0] - full, last[1])] if last else []) + pts + \
                  ([(first[0] + full, first[1])] if first else [])
            if key == "theta" and sw.rotates:
                pts = _break_jumps(pts, full / 2)
            label = out.symbol(key)
            if out.kind == "point" and i > 0:
                label = {0: f"|{label}|", 1: words("x component"), 2: words("y component")}[j]
            series.append(Series(label, tuple(pts), CURVE_STYLES[j % len(CURVE_STYLES)]))
        marks, labelled = [], set()
        for key, angle, value, text in sw.marks:
            if key in keys:
                first = text not in labelled
                labelled.add(text)
                marks.append(PlotMark(x_of(angle), _in_units(mech, key, value),
                                      re.sub(r"θ(\d+)", r"θ_\1", text) if first else ""))
        unit = unit_words(_unit(mech, KINDS[keys[0]])[1])
        y_label = words(", ").join(out.symbol(k)
                                   for k in keys[:1 if out.kind != "point" or i else 2])
        sub = words(quantity[i] + " of {who}{along} over one turn of {link}", who=who,
                    along=along, link=_link(mech, link))
        notes = [words("{turning}; curves by the analytic (vector-loop) solver",
                       turning=_turning(sw))]
        notes += _event_lines(sw, i)
        notes += [words("gap at {gap}", gap=g) for g in _gaps(sw)][:3]
        worst = max((c.rel_error for c in sw.checks if c.key in keys), default=None)
        legend = "" if worst is None else words(
            "solved by construction (off the curve by {error} at most)",
            error=numerals(f"{worst:.0e}")) if worst else \
            words("solved by construction (on the curve exactly)")
        figures[stems[i]] = draw_line_plot(
            title, f"θ_{link} ({'°' if deg else unit_words('rad')})", f"{y_label} ({unit})",
            series, marks,
            x_range=(0.0, full), x_ticks=ticks, subtitle=sub, notes=notes, mark_legend=legend,
            include_zero=i > 0, y_ticks=[k * full / 4 for k in range(5)] if i == 0 and sw.rotates
            else ())
    return figures


def _break_jumps(pts, jump: float):
    """Break a curve where it jumps by more than ``jump`` (θ wrapping past 360°)."""
    out = []
    for p in pts:
        if p is not None and out and out[-1] is not None and abs(p[1] - out[-1][1]) > jump:
            out.append(None)
        out.append(p)
    return out


# ----- files ---------------------------------------------------------------------------------
def _ascii(out: Output, key: str) -> str:
    """A column's name for a CSV header: "V_B", "Vx_B", "omega4"."""
    if out.kind == "link":
        return f"{key}{out.link}"
    head = {"v": "V", "vx": "Vx", "vy": "Vy", "a": "A", "ax": "Ax", "ay": "Ay"}.get(key, key)
    return f"{head}_{out.point}"


def _csv(rows: list[list[str]]) -> str:
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerows(rows)
    return buf.getvalue()


def _cell(value: float) -> str:
    text = f"{value:.10g}"
    return "0" if float(text) == 0.0 else text


def sweep_csv(sw: Sweep) -> str:
    """The table, one row per step in the sweep's order, in the file's units."""
    mech = sw.exercise.mechanism
    out = sw.output
    d = mech.drive
    keys = [k for group in KEYS[out.kind] for k in group]
    if out.kind == "slider":
        keys = ["x", "y", "s", "v", "a"]
    elif out.kind == "point":
        keys = ["x", "y", "vx", "vy", "v", "ax", "ay", "a"]
    timed = d.omega != 0.0 and d.alpha == 0.0
    head = [f"theta{d.link} ({_unit(mech, 'angle')[2]})"] + (["t (s)"] if timed else [])
    head += [f"{_ascii(out, k)} ({_unit(mech, KINDS[k])[2]})" for k in keys]
    rows = [head + ["note"]]
    a_unit = _unit(mech, "angle")[0]
    for i, s in enumerate(sw.samples):
        angle = (s.angle % math.tau) / a_unit
        row = [_cell(float(f"{angle:.10g}") % (math.tau / a_unit))]
        if timed:
            row.append(_cell(i * abs(sw.step) / abs(d.omega)))
        if s.values:
            row += [_cell(_in_units(mech, k, s.values[k])) for k in keys] + [""]
        else:
            row += [""] * len(keys) + [s.reason]
        rows.append(row)
    return _csv(rows)


def points_csv(sw: Sweep) -> str:
    """The graphical values against the curve's, one row per position, quantity and method."""
    mech = sw.exercise.mechanism
    rows = [["position", f"theta{mech.drive.link} ({_unit(mech, 'angle')[2]})", "quantity",
             "method", "unit", "graphical", "curve", "rel_error"]]
    for c in sw.checks:
        unit = _unit(mech, KINDS[c.key])
        rows.append([c.position, _cell((c.angle % math.tau) / _unit(mech, "angle")[0]),
                     _ascii(sw.output, c.key), c.method, unit[2],
                     _cell(_in_units(mech, c.key, c.graphical)),
                     _cell(_in_units(mech, c.key, c.curve)), f"{c.rel_error:.2e}"])
    return _csv(rows)


def sweep_to_files(sw: Sweep, *, pdf: bool = False) -> dict[str, str | bytes]:
    """Render everything in memory: ``{file name: text or bytes}``.

    Raises
    ------
    RenderError
        If ``pdf`` is asked and libcairo2 is missing.
    """
    files: dict[str, str | bytes] = {"sweep.csv": sweep_csv(sw)}
    if sw.checks:
        files["sweep-points.csv"] = points_csv(sw)
    for stem, fig in sweep_figures(sw).items():
        files[f"{stem}.svg"] = to_svg(fig)
        if pdf:
            files[f"{stem}.pdf"] = figure_pdf([fig])
    return files


def write_sweep(files: dict[str, str | bytes], out_dir: str | Path) -> list[Path]:
    """Write the rendered files into ``out_dir`` (made if missing), all or nothing, replacing
    the previous run's (see :func:`~tarsim.graphics.export.write_folder`).

    Raises
    ------
    RenderError
        If the folder cannot be made or written, or holds a file of one of these names
        that tarsim did not write.
    """
    return write_folder(files, out_dir)


# ----- the report ----------------------------------------------------------------------------
def format_sweep(sw: Sweep) -> str:
    """What the command line prints: the turn, the refined extremes, the checks, the gaps.

    In English whatever language the figures are drawn in: it shares its words with them.
    """
    with speaking("en"):
        return _format_sweep(sw)


def _format_sweep(sw: Sweep) -> str:
    mech = sw.exercise.mechanism
    who, along = _words(sw)
    solved = len(sw.solved)
    lines = [f"{mech.name or sw.exercise.id}: {who}{along}",
             _plain(_turning(sw)) + f"; {solved} solved, {len(sw.samples) - solved} skipped"]
    lines += [_plain(line) for i in range(3) for line in _event_lines(sw, i)]
    lines += [f"gap at {_plain(g)}" for g in _gaps(sw)]
    if sw.checks:
        lines.append("")
        rows = [("position", "quantity", "method", "graphical", "curve", "rel. error")]
        rows += [(c.position, _plain(sw.output.symbol(c.key)), c.method,
                  _shown(mech, c.key, c.graphical), _shown(mech, c.key, c.curve),
                  f"{c.rel_error:.1e}") for c in sw.checks]
        lines += _aligned(rows)
    lines += [f"note: {n}" for n in sw.notes]
    return "\n".join(lines)


def _aligned(rows: list[tuple[str, ...]]) -> list[str]:
    """``rows`` as lines of columns each as wide as its widest entry, two spaces apart: a
    long number (−1.95352e+06 mm/s²) never runs into the next column."""
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    return ["  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip()
            for row in rows]


def _plain(text: str) -> str:
    """Drop the subscript marks for the terminal: "θ_2" → "θ2", "V_B" stays "V_B"."""
    return re.sub(r"([θωα])_(\d+)", r"\1\2", text)
