"""The files of a worked solution: one figure per construction, steps.md and results.json.

Each figure shows only the backward slice of what it answers: the centres figure
the centres asked (or needed for an ω), each velocity figure its own method's
lines and the centres it uses. The numbers beside the drawn lines are the step
numbers of steps.md, both taken from :func:`graphics.scene.numbered_steps`.
Everything is made in memory first, then written file by file atomically, so an
error leaves nothing half-written.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from constructions.centres import centre_ref
from constructions.errors import RenderError
from constructions.record import Ref, slice as backward_slice, toposort
from graphics.circle_diagram import draw_circle_diagram
from graphics.export import svg_to, write_text
from graphics.figure import Figure
from graphics.scene import draw_scene, numbered_steps
from graphics.svg import to_svg

from .exercise_file import Exercise
from .results_json import results_json
from .solution import Solution, solve_exercise

__all__ = ["SolutionFigure", "solve_to_files", "write_solution"]


@dataclass
class SolutionFigure:
    """One figure of a solution: its file stem, its heading, the steps it draws."""

    stem: str
    heading: str
    figure: Figure
    refs: list[Ref]


def solve_to_files(ex: Exercise) -> tuple[Solution, dict[str, str]]:
    """Solve ``ex`` and render every file, in memory: ``{file name: text}``."""
    sol = solve_exercise(ex)
    figures = _figures(sol)
    files = {f"{f.stem}.svg": to_svg(f.figure) for f in figures}
    files["steps.md"] = _steps_markdown(sol, figures)
    files["results.json"] = results_json([sol], ex.id)
    return sol, files


def write_solution(files: dict[str, str], out_dir: str | Path, *, pdf: bool = True) -> list[Path]:
    """Write the rendered files into ``out_dir`` (made if missing), with a PDF per SVG.

    Raises
    ------
    RenderError
        If the folder cannot be made or written, or PDF is asked and libcairo2 is
        missing (checked before anything is written).
    """
    out = Path(out_dir)
    pdfs = {}
    if pdf:
        pdfs = {name[:-4] + ".pdf": svg_to(text, "pdf") for name, text in files.items()
                if name.endswith(".svg")}
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise RenderError(f"cannot make the folder '{out}': {e.strerror}") from None
    written = [write_text(out / name, text) for name, text in files.items()]
    written += [write_text(out / name, data) for name, data in pdfs.items()]
    return written


# ----- figures ---------------------------------------------------------------------------
def _figures(sol: Solution) -> list[SolutionFigure]:
    ex, asm = sol.exercise, sol.assembly
    c = asm.construction
    name = ex.mechanism.name
    out: list[SolutionFigure] = []
    pairs = list(ex.centres)
    d = ex.mechanism.drive.link
    for n in ex.omegas:
        pairs += [(1, d)] if n == d else [(1, d), (1, n), tuple(sorted((d, n)))]
    if pairs:
        targets = [centre_ref(*p) for p in dict.fromkeys(pairs)]
        refs = _drawn(c, targets, sol.position_steps)
        heading = ("Instant centres" if ex.centres else "Centres for the angular velocities")
        fig = draw_scene(asm, refs, title=f"{name}: {heading.lower()}", notes=sol.notes)
        out.append(SolutionFigure("centres", heading, fig, refs))
        if ex.centres:
            out.append(SolutionFigure("circle-diagram", "Circle diagram",
                                      draw_circle_diagram(sol.centres), []))
    for r in sol.velocities:
        # The method's own vectors (V_A, V_I23) feed no later act, so no slice reaches
        # them: they are added from the method's list of what it drew.
        refs = _drawn(c, [r.vector, *r.steps], sol.position_steps)
        fig = draw_scene(asm, refs, title=f"{name}: V_{r.point} by {r.method}",
                         velocity_scale=r.scale)
        out.append(SolutionFigure(f"V_{r.point}-{r.method}", f"V_{r.point} by {r.method}",
                                  fig, refs))
    return out


def _drawn(c, targets: list[Ref], position_steps: frozenset[Ref]) -> list[Ref]:
    """The slice of ``targets`` in record order, less the position construction."""
    wanted = backward_slice(c, targets)
    return [s.id for s in toposort(c, wanted) if s.id not in position_steps]


# ----- steps.md -------------------------------------------------------------------------
def _steps_markdown(sol: Solution, figures: list[SolutionFigure]) -> str:
    ex = sol.exercise
    m = ex.mechanism
    d = m.drive
    lines = [f"# {m.name}: worked solution", ""]
    angle = f"{math.degrees(d.angle):.6g}°" if m.units.angle == "deg" else f"{d.angle:.6g} rad"
    sense = "ccw" if d.omega > 0 else "cw"
    lines += [f"Position: θ{d.link} = {angle}, ω{d.link} = {abs(d.omega):.6g} rad/s {sense}.", ""]
    c = sol.assembly.construction
    for f in figures:
        if not f.refs:
            continue
        lines += [f"## {f.heading} (`{f.stem}.svg`)", ""]
        for number, step in numbered_steps(c, f.refs):
            if step.sentence:
                lines.append(f"{number}. {step.sentence}")
        lines.append("")
    for note in sol.notes:
        lines.append(f"> {note}")
    lines += ["## Results", "",
              "| quantity | construction | analytic | relative error | method |",
              "|---|---|---|---|---|"]
    for name, q in sol.quantities.items():
        rows = [(name, q)] + [(f"{name} ({m_})", a) for m_, a in q.alternatives.items()]
        for label, qq in rows:
            lines.append(f"| {label} | {_show(qq.value, m.units)} | {_show(qq.reference, m.units)}"
                         f" | {qq.rel_error:.2g} | {qq.method} |")
    return "\n".join(lines) + "\n"


def _show(v: dict, units) -> str:
    """A quantity in the file's units, for the results table."""
    s = units.metres
    if "point" in v:
        x, y = v["point"]
        return f"({x / s:.6g}, {y / s:.6g}) {units.length}"
    if "undefined" in v:
        return "any point (no relative motion)"
    if v.get("at_infinity"):
        dx, dy = v["direction"]
        return f"at infinity, direction ({dx:.4f}, {dy:.4f})"
    if "vector" in v:
        x, y = v["vector"]
        return (f"{v['value'] / s:.6g} {units.length}/s at "
                f"{math.degrees(math.atan2(y, x)):.4g}°")
    return f"{v['value']:.6g} rad/s"

