"""A file of a solution, as the page downloads it: a figure's SVG, PDF or PNG, or steps.md,
each made as ``tarsim solve`` makes it."""

from __future__ import annotations

from dataclasses import replace
from pathlib import PurePosixPath

from tarsim.constructions.narration import speaking

from .refusals import Refused
from .solving import Asked, figures, solved_in

__all__ = ["download_file", "PNG_DPI"]

PNG_DPI = 200
"""A downloaded PNG's resolution, ``tarsim solve --format png``'s default; the PNG states it,
so it is placed at its true size."""


def download_file(asked: Asked, what: str, figure: object = None) -> tuple[bytes, str]:
    """The bytes of ``what`` (svg, pdf, png or steps) of the solution ``asked`` asks, with
    the file's name; ``figure`` names the figure (its stem) for svg, pdf and png.

    Raises
    ------
    Refused
        404 for a figure the solution does not draw, naming those it does.
    RenderError
        For PDF or PNG where libcairo2 is missing (the line ``solve`` prints).
    TarsimError
        As ``tarsim solve`` raises it for the file.
    """
    if what != "steps" and isinstance(figure, str):
        asked = replace(asked, figures=(figure,))          # that figure alone is drawn
    lang, ex, solved, _ = solved_in(asked)
    with speaking(lang):
        if what == "steps":
            return solved.steps().encode("utf-8"), f"{PurePosixPath(asked.name).stem}-steps.md"
        drawn = {stem: (svg, fig) for stem, _, svg, fig in figures(solved, asked.figures)}
        if figure not in drawn:
            names = solved.stems() if hasattr(solved, "stems") else [f[0] for f in figures(solved)]
            raise Refused(f"no figure '{str(figure):.60}' in this solution; it draws "
                          f"{', '.join(names) or 'none'}", 404)
        svg, fig = drawn[figure]
        if what == "svg":
            return svg.encode("utf-8"), f"{figure}.svg"
        from tarsim.graphics.export import figure_pdf, figure_pngs

        if what == "pdf":
            return figure_pdf(fig.sheets or [fig]), f"{figure}.pdf"
        name, png = next(iter(figure_pngs(fig, str(figure), PNG_DPI).items()))
        return png, name
