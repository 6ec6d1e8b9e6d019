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

from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property, partial
from pathlib import Path

from tarsim.constructions.asks import symbol
from tarsim.constructions.checks import WHOLE, FigureSpec, Quantity
from tarsim.constructions.linkages.limit_positions import drawn_limits
from tarsim.constructions.narration import measure_words, narrate, speaking, spoken, words
from tarsim.constructions.errors import CheckMismatch
from tarsim.constructions.record import Panel, Slice
from tarsim.constructions.linkages.velocity_drawing import method_words
from tarsim.graphics.export import RenderError, cairo_missing, figure_pdf
from tarsim.graphics.figure import Figure
from tarsim.graphics.figure_kinds import FigureOrder, comes_last, plan_figure
from tarsim.graphics.svg import stacked_svg, to_svg
from tarsim.graphics.workers import draw_each
from tarsim.graphics.paper import paper, room, sheet_name

from ..solution_folder import write_solution
from ..worked_document import Section, markdown, title
from .answer_text import DRAFTING, answer_line
from .answer_text import show as _show          # the figures' tables say answers as steps.md does
from .exercise_file import Exercise
from .results_json import results_document, results_json
from .solution import Overall, Solution, notes_under, solve_overall, solve_positions
from .worked_steps import heading_in, overall_sections, position_sections, time_ratio

# heading_in stays public here, where the figures and the interactive page say headings.
__all__ = ["SolutionFigure", "WorkedSolution", "solve_worked", "solve_all", "figure_parts",
           "heading_in", "solve_to_files", "method_words"]



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
    def weight(self) -> float:
        """What drawing it is expected to cost, in ms: some 8 for the figure and 1.4 a step,
        each a label to place (measured over the bundled exercises: 1.2–2.2 ms a step)."""
        steps = sum(len(s.steps()) for s in [self.shown, *(p[2] for p in self.panels)] if s)
        return 8.0 + 1.4 * steps


@dataclass
class WorkedSolution:
    """A solved exercise: its answers, its figures, its steps, and the files they make.

    ``overall`` answers what is asked of the mechanism as a whole and
    ``positions`` each position's; the figures are drawn when first wanted.
    """

    exercise: Exercise
    overall: Overall
    positions: list[Solution]
    only: frozenset[str] | None = None
    """The stems of the figures to draw (None: every one): a page showing one figure asks
    for that one alone as the input turns, and steps.md then narrates it alone."""

    @cached_property
    def pages(self) -> list[SolutionFigure]:
        """Every figure in order: the whole mechanism's first, then each position's (their
        stems ending in the position's slug when there are several: ``worked-t-2.34s``)."""
        return self._drawn(pdf=False)

    def stems(self) -> list[str]:
        """Every figure's stem, in order, whether or not it is drawn (:attr:`only`)."""
        return [s.stem for s in self._sketches()]

    def _sketches(self) -> list[_Sketch]:
        sketches = _overall_figures(self.exercise, self.overall)
        for sol in self.positions:
            suffix = f"-{sol.position.slug}" if len(self.positions) > 1 else ""
            sketches += _figures(sol, suffix)
        return sketches

    def _drawn(self, *, pdf: bool) -> list[SolutionFigure]:
        """The figures drawn, each written as SVG and (with ``pdf``) converted to PDF by the
        worker that drew it: a figure's whole making in one job, shared out over the cores
        at once."""
        sketches = [s for s in self._sketches() if self.only is None or s.stem in self.only]
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

    def document(self) -> list[Section]:
        """steps.md's sections: the mechanism as a whole, then each position."""
        ex, overall = self.exercise, self.overall
        out = [title(ex.mechanism.name)]
        if overall.quantities:
            out += overall_sections(ex, overall, [f for f in self.pages if f.owner is None])
        for sol in self.positions:
            out += position_sections(sol, [f for f in self.pages if f.owner is sol],
                                     heading=len(self.positions) > 1)
        return out

    def steps(self, lang: str | None = None) -> str:
        """steps.md: the numbered steps of every figure, in ``lang`` (default: the language
        being spoken), then the results."""
        return markdown(self.document(), lang or spoken())

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

    def write(self, folder: str | Path, *, pdf: bool = True, lang: str | None = None,
              png_dpi: float | None = None) -> list[Path]:
        """Write every file into ``folder`` (made if missing), with a PDF of each figure when
        ``pdf``, a PNG of each at ``png_dpi``, and steps.md in ``lang``, as
        :func:`write_solution` does; return the paths written.

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
        return write_solution(self.files(lang), folder, pdf=pdf, made=made, png_dpi=png_dpi,
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
            # a position found from the file's data (a piston's travel) is an answer too
            if len(self.positions) > 1 or (sol.position and sol.position.turned):
                out.append(f"at {sol.position.label}:")
            out += [answer_line(name, qq.in_file_axes(ex.mechanism), units)
                    for name, q in sol.quantities.items()
                    for qq in (q, *q.alternatives.values())]
            out += [f"note: {note}" for note in sol.notes]
        at = ("at the exercise's scale" if ex.mechanism.scale
              else "even at the coarsest scale it is drawn at")
        out += [f"note: {stem} {at} is more than {ex.paper} holds: it is set on "
                f"{sheet_name(w, h)} ({w:.0f} × {h:.0f} mm)"
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
    return narrate(time_ratio(m, lp), lang)


# ----- steps.md -------------------------------------------------------------------------
def figure_parts(sol: Solution) -> list[tuple[str, str, list]]:
    """Each figure of a position, undrawn: its stem, its heading and its parts (a title,
    the panel, the slice of the record it shows), as steps.md narrates them."""
    out = []
    for f in _figures(sol):
        parts = [(f.heading, Panel.SPACE, f.shown)] if f.shown else []
        out.append((f.stem, f.heading, parts + [p[:3] for p in f.panels]))
    return out
