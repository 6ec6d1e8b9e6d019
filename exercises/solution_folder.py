"""A solution's folder: its figures' SVG (and PDF), steps.md and results.json, written as one
set, all or nothing.

:func:`write_solution` writes any chapter's files. :class:`ChapterFiles` is what a
chapter's solution (a gear train's, a cam's, a rotor's) needs to say so that its files
are made as every other chapter's are: its figures, its document
(:mod:`..exercises.worked_document`) and its checked quantities
(:mod:`..exercises.checked`). A linkage's solution writes through the same two writers,
with figures drawn by workers of their own.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import partial
from pathlib import Path
from typing import Any

from tarsim.constructions.errors import CheckMismatch
from tarsim.constructions.narration import spoken
from tarsim.graphics.export import (RenderError, cairo_missing, figure_pdf, figure_pngs,
                                    write_folder)
from tarsim.graphics.figure import Figure
from tarsim.graphics.paper import drawn_on, on_sheet, paper
from tarsim.graphics.svg import to_svg
from tarsim.graphics.workers import draw_each

from .checked import Checked, results_document, results_text
from .worked_document import Section, markdown

__all__ = ["ChapterFiles", "write_solution"]


def write_solution(files: dict[str, str], out_dir: str | Path, *, pdf: bool = True,
                   figures: dict[str, Figure] | None = None,
                   made: dict[str, bytes] | None = None,
                   png_dpi: float | None = None) -> list[Path]:
    """Write the rendered files into ``out_dir`` (made if missing), with a PDF of each of
    ``figures`` (by its PDF's name; a page a sheet) and, at ``png_dpi``, a PNG of each
    sheet, all or nothing (see :func:`~tarsim.graphics.export.write_folder`).

    ``solution.pdf`` has those figures as its pages, in order. A figure whose PDF is
    already ``made`` (by its name) is not drawn again. The previous solution's files in
    the folder are replaced whole; a file there tarsim did not write is kept.

    Raises
    ------
    RenderError
        If the folder cannot be made or written, holds a file of one of these names that
        tarsim did not write, or PDF or PNG is asked and libcairo2 is missing (checked
        before anything is written).
    """
    pdfs: dict[str, bytes] = {}
    if (pdf or png_dpi) and figures:
        missing = cairo_missing()   # loaded here once, for every worker to inherit
        if missing:
            raise RenderError(missing)
    if png_dpi and figures:
        jobs = [partial(figure_pngs, fig, name.removesuffix(".pdf"), png_dpi)
                for name, fig in figures.items()]
        # a PNG costs about its pixels: an A4 sheet at 200 dpi some 0.1 s
        for drawn in draw_each(jobs, [len(fig.sheets or [fig]) * 100.0
                                      for fig in figures.values()]):
            pdfs.update(drawn)
    if pdf and figures:
        made = made or {}
        sheets = {name: fig.sheets or [fig] for name, fig in figures.items()}
        todo = [name for name in sheets if name not in made]
        jobs = [partial(figure_pdf, sheets[name]) for name in todo]
        # A sheet's PDF costs some 1 ms and 0.04 ms an item (measured on the bundled ones).
        drawn = dict(zip(todo, draw_each(jobs, [sum(1.0 + 0.04 * len(s.items)
                                                    for s in sheets[name]) for name in todo])))
        pdfs.update({name: made.get(name) or drawn[name] for name in sheets})
        pdfs["solution.pdf"] = figure_pdf([s for name in sheets for s in sheets[name]])
    return write_folder({**files, **pdfs}, out_dir)


class ChapterFiles:
    """The files of a chapter's solution, made as every chapter's are.

    A solution gives ``exercise`` (with its ``id``), ``figures`` (each by its file stem),
    :meth:`document` (what steps.md holds), :attr:`checked` (what results.json holds) and
    ``failures``; this class writes them.
    """

    exercise: Any
    figures: Mapping[str, Figure]
    failures: list[str]

    def document(self) -> list[Section]:
        """steps.md's sections, in the words of the language being spoken."""
        raise NotImplementedError

    @property
    def checked(self) -> dict[str, Checked]:
        """Every quantity results.json gives, by name."""
        raise NotImplementedError

    def steps(self) -> str:
        """steps.md, in the language being spoken."""
        return markdown(self.document(), spoken())

    @property
    def results(self) -> dict[str, Any]:
        """results.json's document: every quantity in SI beside its reference."""
        return results_document(self.exercise.id, self.checked)

    def sheets(self) -> dict[str, Figure]:
        """Each figure by its file stem, drawn for a sheet of the exercise's paper (A4
        unless it is set on another: ``--paper``) at the finest of its scales the sheet
        holds (:func:`~tarsim.graphics.fitting.to_sheet`) and centred on it, upright or
        turned, as its SVG and PDF print it: a page a printer takes."""
        sheet = paper(getattr(self.exercise, "paper", "A4"))
        with drawn_on(sheet):
            figures = self.figures
        return {stem: fig if fig.sheets else on_sheet(fig, sheet)
                for stem, fig in figures.items()}

    def files(self, sheets: Mapping[str, Figure] | None = None) -> dict[str, str]:
        """Every file as text, by name (the figures' from ``sheets``, if drawn already)."""
        sheets = self.sheets() if sheets is None else sheets
        files = {f"{stem}.svg": to_svg(fig) for stem, fig in sheets.items()}
        files["steps.md"] = self.steps()
        files["results.json"] = results_text(self.results)
        return files

    def check(self) -> None:
        """Raise :class:`CheckMismatch` naming every number that failed its check."""
        if self.failures:
            raise CheckMismatch(self.failures)

    def write(self, folder: str | Path, *, pdf: bool = True,
              png_dpi: float | None = None) -> list[Path]:
        """Write the files into ``folder`` (with a PDF of each figure when ``pdf``, a PNG of
        each at ``png_dpi``), all or nothing."""
        sheets = self.sheets()
        return write_solution(self.files(sheets), folder, pdf=pdf, png_dpi=png_dpi,
                              figures={f"{stem}.pdf": fig for stem, fig in sheets.items()})
