"""The files of a worked solution: one figure per construction, steps.md and results.json.

Each answer names the figures it is drawn in (:class:`~tarsim.constructions.checks.FigureSpec`);
a figure shows only the slice of its answers: the centres figure the centres asked
(or needed for an ω), each velocity figure its own method's lines and the centres
it uses, the worked page the polygons. The numbers beside the drawn lines are the
step numbers of steps.md, both the slice's own numbering. Everything is made in
memory first, then written as one set (:func:`~tarsim.graphics.export.write_folder`),
so an error leaves the folder as it was.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property, partial
from pathlib import Path

from tarsim.constructions.asks import (EFFORTS, Distance, Equivalent, MechanicalAdvantage, Ratio,
                                       Rubbing, TransmissionAngle, parse_ask, symbol)
from tarsim.constructions.checks import WHOLE, FigureSpec, Quantity
from tarsim.constructions.linkages.limit_positions import drawn_limits
from tarsim.constructions.narration import (Number, Word, measure_words, narrate, numerals, phrase,
                                            render, significant, speaking, spoken, words)
from tarsim.constructions.errors import CheckMismatch
from tarsim.constructions.record import Panel, Slice
from tarsim.constructions.linkages.velocity_drawing import method_words
from tarsim.graphics.export import RenderError, cairo_missing, figure_pdf
from tarsim.graphics.figure import Figure
from tarsim.graphics.figure_kinds import FigureOrder, comes_last, plan_figure
from tarsim.graphics.svg import stacked_svg, to_svg
from tarsim.graphics.workers import draw_each
from tarsim.graphics.paper import paper, room

from ..solution_folder import write_solution
from .exercise_file import Exercise
from .results_json import results_document, results_json
from .solution import Overall, Solution, notes_under, solve_overall, solve_positions

__all__ = ["SolutionFigure", "WorkedSolution", "solve_worked", "overall_text", "solve_all",
           "figure_parts", "heading_in",
           "solve_to_files", "answer_line", "method_words"]


DRAFTING = 4
"""Significant figures of a number set on a figure: what a drawing can be read to."""


@dataclass
class SolutionFigure:
    """One figure of a solution: its file stem, its heading, what it shows."""

    stem: str
    heading: str
    figure: Figure
    svg: str
    """The figure as an SVG document, written where it was drawn."""
    pdf: bytes | None
    """Its PDF (a page a sheet), when it was drawn to be written with PDFs."""
    shown: Slice | None
    """What the figure shows of the space diagram's construction, narrated in steps.md."""
    panels: tuple[tuple[str, Panel, Slice], ...] = ()
    """For a worked page: each polygon's heading, panel and slice, narrated in turn (a
    fourth item marks a part the figure does not draw)."""
    owner: Solution | None = None
    """The position the figure belongs to (None: the mechanism as a whole)."""


@dataclass
class _Sketch:
    """A figure before it is drawn: all but the drawing, which :func:`draw_each` runs."""

    stem: str
    heading: str
    draw: Callable[[], Figure]
    shown: Slice | None
    panels: tuple[tuple[str, Panel, Slice], ...] = ()
    owner: Solution | None = None

    @property
    def weight(self) -> int:
        """What drawing it is expected to cost: its steps, each a label to place."""
        return sum(len(s.steps()) for s in [self.shown, *(p[2] for p in self.panels)] if s)


@dataclass
class WorkedSolution:
    """A solved exercise: its answers, its figures, its steps, and the files they make.

    ``overall`` answers what is asked of the mechanism as a whole and
    ``positions`` each position's; the figures are drawn when first wanted.
    """

    exercise: Exercise
    overall: Overall
    positions: list[Solution]

    @cached_property
    def pages(self) -> list[SolutionFigure]:
        """Every figure in order: the whole mechanism's first, then each position's (their
        stems ending in the position's slug when there are several: ``worked-t-2.34s``)."""
        return self._drawn(pdf=False)

    def _drawn(self, *, pdf: bool) -> list[SolutionFigure]:
        """The figures drawn, each written as SVG and (with ``pdf``) converted to PDF by the
        worker that drew it: a figure's whole making in one job, shared out over the cores
        at once."""
        sketches = _overall_figures(self.exercise, self.overall)
        for sol in self.positions:
            suffix = f"-{sol.position.slug}" if len(self.positions) > 1 else ""
            sketches += _figures(sol, suffix)
        lang = spoken()       # each worker draws in the language the solution is asked in
        drawn = draw_each([partial(_drawn_in, lang, s.draw, pdf) for s in sketches],
                          [s.weight for s in sketches])
        return [SolutionFigure(s.stem, s.heading, *made, s.shown, s.panels, s.owner)
                for s, made in zip(sketches, drawn)]

    @property
    def results(self) -> dict:
        """The results.json document: every quantity beside its analytic reference (SI)."""
        return results_document(self.positions, self.exercise, self.overall.quantities)

    @property
    def figures(self) -> dict[str, Figure]:
        """Each figure by its file stem (``centres``, ``V_B-radius-rotation``, ``worked``)."""
        return {f.stem: f.figure for f in self.pages}

    @property
    def failures(self) -> list[Quantity]:
        """The quantities whose construction disagrees with the analytic reference."""
        return ([q for q in self.overall.quantities.values() if not q.passed]
                + [q for sol in self.positions for q in sol.failures])

    @property
    def passed(self) -> bool:
        """True when every constructed number agrees with the analytic one."""
        return not self.failures

    def steps(self, lang: str | None = None) -> str:
        """steps.md: the numbered steps of every figure, in ``lang`` (default: the language
        being spoken), then the results."""
        ex, overall, lang = self.exercise, self.overall, lang or spoken()
        mine = [f for f in self.pages if f.owner is None]
        parts = [_overall_markdown(ex, overall, mine, lang)] if overall.quantities else []
        several = len(self.positions) > 1
        for sol in self.positions:
            figures = [f for f in self.pages if f.owner is sol]
            parts.append(_steps_markdown(sol, figures, heading=several, lang=lang))
        return _steps_title(ex, lang) + "\n".join(parts)

    def files(self, lang: str | None = None) -> dict[str, str]:
        """Every file as text, by name: each figure's SVG, solution.svg with all of them,
        steps.md (in ``lang``) and results.json."""
        files = {f"{f.stem}.svg": f.svg for f in self.pages}
        if self.pages:
            files["solution.svg"] = stacked_svg([f.figure for f in self.pages],
                                                [f.svg for f in self.pages])
        files["steps.md"] = self.steps(lang)
        files["results.json"] = results_json(self.positions, self.exercise,
                                             self.overall.quantities)
        return files

    def write(self, folder: str | Path, *, pdf: bool = True, lang: str | None = None
              ) -> list[Path]:
        """Write every file into ``folder`` (made if missing), with a PDF of each figure when
        ``pdf`` and steps.md in ``lang``, as :func:`write_solution` does; return the paths
        written.

        Raises
        ------
        RenderError
            If the folder cannot be made or written, holds a file of one of these names
            that tarsim did not write, or PDF is asked and libcairo2 is missing.
        """
        if pdf and "pages" not in self.__dict__:
            missing = cairo_missing()     # loaded once, before the workers are forked
            if missing:
                raise RenderError(missing)
            self.pages = self._drawn(pdf=True)
        made = {f"{f.stem}.pdf": f.pdf for f in self.pages if f.pdf}
        return write_solution(self.files(lang), folder, pdf=pdf, made=made,
                              figures={f"{f.stem}.pdf": f.figure for f in self.pages})

    def view(self, step_deg: float = 0.5):
        """The interactive page of this exercise (``tarsim view``): its ``.save(path)``
        writes it, and a notebook shows it."""
        from tarsim.graphics.view_page import ViewPage, view_html
        from .view import view_data

        return ViewPage(view_html(view_data(self.exercise, step_deg=step_deg)))

    def _repr_html_(self) -> str:
        """In a notebook: the interactive page, steps and crank (see :meth:`view`)."""
        return self.view()._repr_html_()

    def lines(self) -> list[str]:
        """What the terminal shows of the solution: each answer in the file's units, each
        position's notes, and each figure too big for the exercise's paper."""
        ex, units = self.exercise, self.exercise.mechanism.units
        out = [answer_line(name, q, units, whole=True)
               for name, q in self.overall.quantities.items()]
        for sol in self.positions:
            if len(self.positions) > 1:
                out.append(f"at {sol.position.label}:")
            out += [answer_line(name, qq.in_file_axes(ex.mechanism), units)
                    for name, q in sol.quantities.items()
                    for qq in (q, *q.alternatives.values())]
            out += [f"note: {note}" for note in sol.notes]
        at = ("at the exercise's scale" if ex.mechanism.scale
              else "even at the coarsest scale it is drawn at")
        out += [f"note: {stem} {at} is {w:.0f} × {h:.0f} mm, more than {ex.paper} holds; its "
                "page is that size (--paper A3 may hold it)"
                for stem, (w, h) in self.oversize().items()]
        return out

    def check(self) -> None:
        """Raise :class:`CheckMismatch` naming every quantity that failed its check."""
        if self.failures:
            raise CheckMismatch([q.name for q in self.failures])

    def oversize(self) -> dict[str, tuple[float, float]]:
        """Each figure a sheet of the exercise's paper does not hold (drawn at a scale the
        exercise states), with its page's size (mm)."""
        sheet = paper(self.exercise.paper)
        fits = {(sheet.width, sheet.height), sheet.turned}
        return {f.stem: (s.width, s.height) for f in self.pages
                for s in (f.figure.sheets or [f.figure])
                if (round(s.width, 1), round(s.height, 1)) not in fits}


def solve_worked(ex: Exercise) -> WorkedSolution:
    """Solve ``ex`` as a whole and at each position; its figures are drawn when wanted.

    Raises
    ------
    TarsimError
        If the mechanism cannot be assembled or a construction breaks down, saying
        which and where.
    """
    where = room(paper(ex.paper))        # the figures' room on the sheet sets the scales
    overall = solve_overall(ex, room=where)
    return WorkedSolution(ex, overall,
                          solve_positions(ex, room=where) if ex.position_asks else [])


def solve_to_files(ex: Exercise) -> tuple[list[Solution], dict[str, str]]:
    """Solve ``ex`` and render every file, in memory: ``{file name: text}``."""
    worked = solve_worked(ex)
    return worked.positions, worked.files()


def solve_all(ex: Exercise) -> tuple[list[Solution], Overall, dict[str, str]]:
    """Solve ``ex`` and render every file in memory (see :func:`solve_worked`)."""
    worked = solve_worked(ex)
    return worked.positions, worked.overall, worked.files()


def _drawn_in(lang: str, draw: Callable[[], Figure], pdf: bool
              ) -> tuple[Figure, str, bytes | None]:
    """``draw()`` with its words in ``lang`` (a forked worker is told, not left to inherit);
    the figure written as SVG and, with ``pdf``, its PDF (a page a sheet)."""
    with speaking(lang):
        fig = draw()
        svg = to_svg(fig)
    return fig, svg, figure_pdf(fig.sheets or [fig]) if pdf else None


# ----- figures ---------------------------------------------------------------------------
def _specs(answers) -> list[tuple[FigureSpec, list]]:
    """Each figure the answers are drawn in, with its answers: the space diagram's figures in
    the order they are first drawn, then the worked page."""
    out: dict[str, tuple[FigureSpec, list]] = {}
    for a in answers:
        for spec in a.figures:
            out.setdefault(spec.stem, (spec, []))[1].append(a)
    return sorted(out.values(), key=lambda sa: comes_last(sa[0]))


def _figures(sol: Solution, suffix: str = "") -> list[_Sketch]:
    """Sketch each figure of a position, as its kind plans it from the answers it holds."""
    ex = sol.exercise
    out = []
    for spec, answers in _specs(sol.answers):
        plan = plan_figure(FigureOrder(
            spec, tuple(answers), sol.work, ex.mechanism, paper(ex.paper),
            where=sol.position.label if sol.position else None, said=_said,
            notes=partial(notes_under, sol), table=partial(_results_table, sol)))
        out.append(_Sketch(spec.stem + suffix, spec.heading, plan.draw, plan.shown,
                           plan.panels, sol))
    return out


def _said(heading: str) -> str:
    """A figure's heading in the language being spoken."""
    return heading_in(heading, spoken())


def _results_table(sol: Solution) -> list[tuple[str, ...]]:
    """The worked page's results table: its header, then a row per quantity and method."""
    m = sol.exercise.mechanism
    table = [tuple(words(h) for h in ("quantity", "method", "construction", "analytic",
                                       "relative error"))]
    for qname, q in sol.quantities.items():
        q = q.in_file_axes(m)
        for qq in (q, *q.alternatives.values()):
            table.append((symbol(qname), words(method_words(qq.method)),
                          _show(qq.value, m.units, qname, DRAFTING),
                          _show(qq.reference, m.units, qname, DRAFTING), f"{qq.rel_error:.1e}"))
    return table


def _overall_figures(ex: Exercise, overall: Overall) -> list[_Sketch]:
    """The limit positions, when the time ratio or stroke is asked; the mechanism itself when
    nothing is asked at a position."""
    work, m = overall.work, ex.mechanism
    if work is None or not work.has("limits"):
        if ex.position_asks or work is None:
            return []
        spec, answers, notes = WHOLE, (), []
    else:
        lp = drawn_limits(work)
        notes = [_time_ratio_words(m, lp, spoken())]
        if lp.stroke is not None:
            notes.append(words("Stroke of {point}: {length}.", point=lp.point,
                               length=measure_words(m.units.length_drawn(lp.stroke))))
        answers = tuple(a for a in overall.answers if a.figures)
        spec = answers[0].figures[0]
    plan = plan_figure(FigureOrder(spec, answers, work, m, paper(ex.paper), said=_said,
                                   notes=lambda panel: notes))
    return [_Sketch(spec.stem, spec.heading, plan.draw, plan.shown, plan.panels)]


def _time_ratio_words(m, lp, lang: str = "en") -> str:
    """"The crank turns 222.2° (A″ to A′, cw) in the slow stroke and 137.8° in the quick one"."""
    a = m.link(m.drive.link).names[1]
    start, end = (f"{a}′", f"{a}″") if lp.slow_from == 0 else (f"{a}″", f"{a}′")
    sense = "ccw" if m.drive.omega >= 0 else "cw"
    slow, quick = Number(math.degrees(lp.slow), ".2f"), Number(math.degrees(lp.quick), ".2f")
    return narrate(phrase("md.time_ratio", slow=slow, quick=quick, start=start, end=end,
                          sense=Word(sense), ratio=Number(lp.time_ratio, ".4f")), lang)


def _overall_markdown(ex: Exercise, overall: Overall, figures: list[SolutionFigure],
                      lang: str = "en") -> str:
    """steps.md's part for the mechanism as a whole: the limit positions, then the answers."""
    lines = ["# " + narrate(phrase("md.whole"), lang), ""]
    lp = drawn_limits(overall.work) if overall.work.has("limits") else None
    for f in figures if lp is not None else ():
        lines += [f"## {heading_in(f.heading, lang)} (`{f.stem}.svg`)", ""]
        for number, step in f.shown.numbered():
            lines.append(f"{number}. {narrate(step, lang)}")
        lines += ["", _time_ratio_words(ex.mechanism, lp, lang), ""]
    lines += ["## " + narrate(phrase("md.results"), lang), "",
              narrate(phrase("md.whole_columns"), lang), "|---|---|---|---|---|"]
    for name, q in overall.quantities.items():
        method = narrate(q.said, lang) if q.said else render(Word(q.method), lang)
        lines.append(f"| {name} | {overall_text(name, q.value, ex.mechanism.units)} | "
                     f"{overall_text(name, q.reference, ex.mechanism.units)} | "
                     f"{q.rel_error:.2g} | {method} |")
    return "\n".join(lines) + "\n"


def overall_text(name: str, v: dict, units) -> str:
    """A whole-mechanism answer in the file's units, in the language spoken: "65 mm < AB <
    135 mm (crank-rocker)"."""
    def length(metres: float) -> str:
        return numerals(units.length_text(metres))

    if "class" in v and "low" in v:
        span, kind = name[len("range_"):], words(v["class"])
        if v["low"] == v["high"]:
            return words("{span} = {length} only ({kind})", span=span, length=length(v["low"]),
                         kind=kind)
        hi = "" if v["high"] is None else f" < {length(v['high'])}"
        return f"{length(v['low'])} < {span}{hi} ({kind})"
    if "here" in v:
        return words("{value} ({here} at this position)", value=numerals(str(v["value"])),
                     here=numerals(str(v["here"])))
    if "class" in v:
        return words(v["class"])
    if "point" in v:
        return length(v["value"])
    if "by_inspection" in v:
        return words("{value} ({inspection} by inspection, {kennedy} by Kennedy)",
                     value=numerals(str(v["value"])),
                     inspection=numerals(str(v["by_inspection"])),
                     kennedy=numerals(str(v["by_kennedy"])))
    if "slow_deg" in v:
        return numerals(f"{v['value']:.6g} ({v['slow_deg']:.5g}° / {v['quick_deg']:.5g}°)")
    return numerals(f"{v['value']}")


# ----- steps.md -------------------------------------------------------------------------
def _steps_title(ex: Exercise, lang: str = "en") -> str:
    return "# " + narrate(phrase("md.title", name=ex.mechanism.name), lang) + "\n\n"


def figure_parts(sol: Solution) -> list[tuple[str, str, list]]:
    """Each figure of a position, undrawn: its stem, its heading and its parts (a title,
    the panel, the slice of the record it shows), as steps.md narrates them."""
    out = []
    for f in _figures(sol):
        parts = [(f.heading, Panel.SPACE, f.shown)] if f.shown else []
        out.append((f.stem, f.heading, parts + [p[:3] for p in f.panels]))
    return out


def heading_in(text: str, lang: str) -> str:
    """A figure's or a part's heading in ``lang`` (English as it is): "V_B by radius
    rotation" is the quantity and its method."""
    what, by, method = text.partition(" by ")
    if by and " " not in what:
        return narrate(phrase("md.by", what=what, method=Word(method)), lang)
    return narrate(phrase("md.heading", heading=Word(text)), lang)


def _steps_markdown(sol: Solution, figures: list[SolutionFigure], *, heading: bool,
                    lang: str = "en") -> str:
    """One position's part of steps.md: its figures' numbered steps, then its results.

    ``heading`` puts the position's own heading first (several positions)."""
    m = sol.assembly.mechanism           # with the input's rates as drawn (converted, if given)
    d = m.drive
    angle = m.units.angle_brief(d.angle)
    sense = "ccw" if d.omega > 0 else "cw"
    at = narrate(phrase("md.at", where=sol.position.label), lang) if heading else ""
    lines = [f"# {at}", ""] if heading else []
    lines += [narrate(phrase("md.position", link=str(d.link), angle=angle,
                             omega=significant(abs(d.omega)), sense=Word(sense),
                             alpha=significant(d.alpha),
                             given=None if d.alpha_given else phrase("md.not_given")),
                      lang), ""]
    for f in figures:
        parts = [(f.heading, Panel.SPACE, f.shown)] if f.shown else []
        parts += list(f.panels)
        for title, panel, shown, *elsewhere in parts:
            numbered = list(shown.numbered(panel))
            if not numbered:                 # a panel the exercise draws nothing in
                continue
            # A part drawn in no figure of its own (the inertia loads' images on the
            # acceleration polygon) names no file.
            title = heading_in(title, lang)
            lines += [f"## {title}" if elsewhere else f"## {title} (`{f.stem}.svg`)", ""]
            lines += [f"{number}. {narrate(step, lang)}" for number, step in numbered]
            lines.append("")
    for note in sol.notes:
        lines.append(f"> {note}")
    lines += ["", "## " + narrate(phrase("md.results"), lang), "",
              narrate(phrase("md.columns"), lang), "|---|---|---|---|---|"]
    for name, q in sol.quantities.items():
        q = q.in_file_axes(m)
        rows = [(name, q)] + [(f"{name} ({m_})", a) for m_, a in q.alternatives.items()]
        for label, qq in rows:
            lines.append(f"| {label} | {_show(qq.value, m.units, name)} | "
                         f"{_show(qq.reference, m.units, name)} | {qq.rel_error:.2g} | "
                         f"{render(Word(method_words(qq.method)), lang)} |")
    return "\n".join(lines) + "\n"


def _direction(x: float, y: float) -> float:
    """A vector's angle in degrees, (−180°, 180°]: a leftward vector reads 180° whatever the
    sign of its rounding-noise y, and a direction within 1e-9° of 0 reads 0."""
    deg = math.degrees(math.atan2(y, x))
    if deg <= -180.0 + 1e-9:
        return 180.0
    return 0.0 if abs(deg) < 1e-9 else deg


def _show(v: dict, units, name: str = "", figures: int = 6) -> str:
    """A quantity in the file's units, for the results tables; ``name`` tells its kind.

    Numbers are set to ``figures`` significant figures (a figure's table takes 4, drafting
    precision; steps.md 6) with a true minus, and a coordinate that is rounding noise
    beside the other (a centre at (−3e−14, −500)) is set as 0. The words and digits are the
    language being spoken; units keep their symbols (m/s, N·m), as tables print them.
    """
    def _num(x: float, spec: str = ".6g") -> str:
        return numerals(_number(x, spec))

    s = units.metres
    spec = f".{figures}g"
    if "point" in v:
        x, y = _quiet_pair(v["point"])
        at = f"({_num(x / s, spec)}, {_num(y / s, spec)}) {units.length}"
        # a point with its speed: the least velocity along a link
        return at if "value" not in v else words("{what} at {where}", what=(
            f"{_num(v['value'] / s, spec)} {units.length}/s"), where=at)
    if "undefined" in v:
        return words("any point (no relative motion)")
    if v.get("at_infinity"):
        dx, dy = _quiet_pair(v["direction"])
        return words("at infinity, direction ({dx}, {dy})", dx=_num(dx, '.4f'), dy=_num(dy, '.4f'))
    def pointing(what: str) -> str:
        """``what`` and the way its vector points: none for a nil one, which points nowhere."""
        x, y = v["vector"]
        if x == 0.0 and y == 0.0:
            return what
        return words("{what} at {where}", what=what, where=f"{_num(_direction(x, y), '.4g')}°")

    if "vector" in v and name.startswith("F_"):        # a joint force, in newtons
        return pointing(f"{_num(v['value'], spec)} N")
    if name.startswith("T") and name[1:2] in "_0123456789" and name != "T":
        w = v["value"]                                  # a couple or the driving torque
        return f"{_num(w, spec)} N·m{_sense(w)}"
    if name in EFFORTS:                                 # an engine's effort, signed
        return f"{_num(v['value'], spec)} {'N·m' if name == 'turning_moment' else 'N'}"
    if "vector" in v:
        per = "/s²" if name.startswith("A") else "/s"     # A_B, A_cor_B, An_B/A, A_slide_B
        return pointing(f"{_num(v['value'] / s, spec)} {units.length}{per}")
    w = v["value"]
    kind = type(parse_ask(name)) if name else None
    if kind in (Ratio, MechanicalAdvantage):
        return _num(w, spec)
    if kind in (Distance, Equivalent):
        return f"{_num(w / s, spec)} {units.length}"
    if kind is Rubbing:
        return f"{_num(w / s, spec)} {units.length}/s"
    if kind is TransmissionAngle:
        return f"{_num(math.degrees(w), spec)}°"
    return f"{_num(w, spec)} rad/s" + ("²" if name.startswith("alpha") else "") + _sense(w)


def _sense(w: float) -> str:
    """" (ccw)" or " (cw)" after a signed rate, in the language being spoken; "" for 0."""
    return f" ({words('ccw' if w > 0 else 'cw')})" if w else ""


def answer_line(name: str, q: Quantity, units, *, whole: bool = False) -> str:
    """One answer as ``solve`` prints it: the value with its unit and sense, then its check.
    ``whole`` marks an answer about the mechanism as a whole (DOF, time ratio, a range).

    >>> from types import SimpleNamespace as Q
    >>> from tarsim.constructions.units import Units
    >>> print(answer_line("omega3", Q(value={"value": -2.578}, rel_error=1.3e-16,
    ...                               tolerance=1e-9, method="velocity polygon"), Units("m")))
    ω3 = −2.578 rad/s (cw)               check ok 1.3e-16   velocity polygon
    """
    with speaking("en"):                    # the terminal's lines are English
        if not whole:
            answer = f"{symbol(name)} = {_show(q.value, units, name)}"
        elif name.startswith("range_"):    # the text names the span: "65 mm < AB < 135 mm"
            answer = overall_text(name, q.value, units)
        else:
            label = {"dof": "DOF", "grashof": "Grashof class",
                     "n_centres": "instant centres"}.get(name, name.replace("_", " "))
            answer = f"{label} = {overall_text(name, q.value, units)}"
    verdict = ("check ok" if q.rel_error <= q.tolerance else
               f"check FAILED (tolerance {q.tolerance:.1e})")
    return f"{answer:<36} {verdict} {q.rel_error:.1e}   {method_words(q.method)}"



def _quiet_pair(xy) -> tuple[float, float]:
    big = max(abs(xy[0]), abs(xy[1]))
    return tuple(0.0 if abs(c) <= 1e-9 * big else c for c in xy)


def _number(x: float, spec: str = ".6g") -> str:
    """``x`` as the tables print it: a true minus sign, and never "−0"."""
    text = format(x, spec)
    if text.startswith("-") and float(text) == 0.0:
        text = text[1:]
    return text.replace("-", "−")
