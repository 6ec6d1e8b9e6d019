"""``tarsim handout``: the problem sheet an instructor hands out before the solution.

A command of its own rather than an option of ``solve``: ``solve`` solves and checks, and
its options (PNG, an undercut cam, the exit status of a failed check) say nothing of a
sheet with no answer on it; the sheet goes to a folder of its own, so that a solution's
folder keeps the solution alone; and ``tarsim --help`` then lists it on a line of its own,
where an instructor looking for it finds it.
"""

from __future__ import annotations

from pathlib import Path

import click

from tarsim.constructions.narration import speaking, spoken

from . import cli_common as common

__all__ = ["handout"]


@click.command()
@common.source
@click.option("-o", "--output", "out_dir", type=click.Path(), default=None, metavar="DIR",
              help="Folder for handout.svg and handout.pdf (default: <id>-handout/ here).")
@common.angle
@click.option("--pdf/--no-pdf", default=True, show_default=True,
              help="Also write handout.pdf, a page a sheet (needs libcairo2).")
@common.paper
@common.speaks
@common.fails_cleanly
def handout(source, out_dir, angle, pdf, paper, lang, digits):
    """Write the problem sheet of FILE: the exercise as given, with no answer.

    The sheet holds the mechanism drawn to scale at its input position
    with its data (the fixed points, every link's lengths, the frame's
    guides, θ2, ω2 and α2, and its loads: masses, forces, couples), what
    is asked in the course's words and symbols (with the methods the file
    names), and an empty frame for each polygon to be drawn (velocity,
    acceleration, each link's force polygon): at the scale the solution
    draws it at (the exercise's, when it states one), with its scale
    statement and bar, the pole marked, sized to hold the polygon. No centre, vector or
    number the solution finds is on it; a position given by a time is
    given by its time alone. A gear train's sheet has the train drawn
    with its teeth, the input and what is asked, and the tabular method's
    table (an ordinary train's row of speeds) with its rows named and
    every cell empty; a rotor's has its side view, its table with the
    masses given and the products left empty, and the force (and couple)
    polygon's frame; a rotor with unknowns has its end view with each
    radial line given (an unknown mass a gap, a mass whose angle is asked
    left out), its table's unknown cells empty and what is asked of each
    mass; an engine has its cylinders' data, the end view of its cranks
    beside an empty frame for each polygon (a single-cylinder, V or
    radial engine: its lines of stroke and its crank); a cam's has its
    base circle with the follower at the start, its segments, and the
    displacement diagram's axes, empty, at the solution's scales (a cam
    of arcs: its base circle, lift, nose and angle of lift as given); a
    flywheel's has its T(θ) as the file gives it on the solution's axes,
    with no mean line and no area (one given by numbers alone: its data),
    and a connecting rod's the rod along its line of centres with P, G
    and A; each with what is asked in the course's words. Every bundled
    exercise has a sheet.

    \b
    Writes into DIR:
      handout.svg    the sheets, one under another
      handout.pdf    a page a sheet (unless --no-pdf)

    \b
    Example:
      tarsim handout crank-shaper -o shaper-handout
      tarsim handout four-bar --lang fa -o four-bar-handout-fa
      tarsim handout planetary-q1 -o q1-handout
      tarsim handout four-mass-shaft -o rotor-handout
      tarsim handout offset-knife-edge -o cam-handout
      tarsim handout punching-press -o press-handout
      tarsim handout inline-three --lang fa -o engine-handout-fa
      tarsim handout my-linkage.toml --paper A3 --no-pdf
    """
    from tarsim.graphics.export import cairo_missing, output_folder, write_folder

    from .handout import handout as problem_sheet

    loaded, chapter = common.loaded(source, angle)
    reason = cairo_missing() if pdf else None
    with speaking(common.language(lang, digits, loaded)):
        ex = chapter.set_up(loaded.named_in(spoken()), paper=paper, angle=common.finite(angle))
        out = Path(out_dir or f"{ex.id}-handout")
        with output_folder(out):
            files = problem_sheet(ex, chapter, paper_name=paper).files(pdf=pdf and reason is None)
            written = write_folder(files, out)
    click.echo(f"wrote {', '.join(p.name for p in written)} to {out}/")
    if reason:
        click.echo(f"PDF skipped: {reason}", err=True)
