"""The ``tarsim`` command line: a thin click layer over the library.

Each command parses its arguments, makes one library call, writes its output and
turns a :class:`~tarsim.constructions.errors.TarsimError` into one line on stderr;
no traceback reaches the user. The exit status is 1 for bad input, 2 for a bad
option or argument (click's usage error) and 3 when a constructed number fails its
check against the analytic solution.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import click

from tarsim.constructions.errors import CheckMismatch
from tarsim.constructions.narration import speaking, spoken

from . import cli_common as common
from .cli_files import list_, new
from .cli_handout import handout
from .cli_serve import serve

__all__ = ["cli"]


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="tarsim")
@click.option("-v", "--verbose", is_flag=True,
              help="After an error's line, say the story behind it (the error it arose from).")
def cli(verbose):
    """Graphical kinematics of planar mechanisms, drawn as textbook figures.

    FILE is an exercise file (TOML, see docs/howto/) or the id
    of a bundled example; `tarsim list` shows the bundled ones.

    \b
    Example:
      tarsim draw four-bar -o four-bar.svg
      tarsim check crank-shaper --angle -44.072
      tarsim --verbose solve my-linkage.toml
    """


@cli.command()
@common.source
@click.option("-o", "--output", "output", required=True, type=click.Path(dir_okay=False),
              help="Figure to write: .svg, .pdf or .png (PDF and PNG need libcairo2).")
@common.angle
@common.paper
@common.speaks
@common.fails_cleanly
def draw(source, output, angle, paper, lang, digits):
    """Draw the kinematic diagram of FILE at its input position.

    Every joint is located by compass construction (arcs and lines, one dyad
    after another) and drawn in textbook style: hatched ground pivots, pins,
    slider blocks on guides, link numbers, the input's θ and ω, and a scale bar
    that measures true on the printed PDF. A gear train is drawn in side view;
    a cam as its profile laid out by inversion (an undercut one with the
    trouble ringed); a rotor as its space diagram (an engine as its primary
    force polygon, or a single cylinder's forces against crank angle).

    \b
    Example:
      tarsim draw four-bar -o four-bar.pdf
      tarsim draw my-linkage.toml -o fig.svg --angle 120
      tarsim draw planetary-q4 -o q4.svg
      tarsim draw oscillating-roller -o cam.pdf
      tarsim draw four-bar -o four-bar-fa.pdf --lang fa
    """
    from tarsim.graphics.export import write_figure
    from tarsim.graphics.paper import drawn_on, on_sheet, paper as sheet

    loaded, chapter = common.loaded(source, angle)
    with speaking(common.language(lang, digits, loaded)), drawn_on(sheet(paper)):
        ex = chapter.set_up(loaded.named_in(spoken()), paper=paper, angle=common.finite(angle))
        fig = on_sheet(chapter.drawing(ex), sheet(paper))
        click.echo(f"wrote {write_figure(fig, output)}")


@cli.command()
@common.source
@common.angle
@common.fails_cleanly
def check(source, angle):
    """Compare every joint's construction with the analytic solution.

    Prints each joint's position as the compass construction found it and as
    the independent vector-loop solver found it, their relative error (to the
    mechanism's size) and the construction's conditioning (1 is well posed, near
    0 is a near-tangent or near-parallel cut), with Grübler's degrees of freedom
    and, for a four-bar, its Grashof class.

    \b
    Example:
      tarsim check four-bar
      tarsim check crank-shaper --angle -44.072
    """
    from .linkages.report import check_positions, format_check

    click.echo(format_check(check_positions(common.linkage(source, angle).mechanism)))


@cli.command()
@common.source
@click.option("-o", "--output", "out_dir", type=click.Path(), default=None,
              metavar="DIR", help="Folder for the solution (default: <id>-solution/ here).")
@common.angle
@click.option("--pdf/--no-pdf", default=True, show_default=True,
              help="Also write a PDF of each figure (needs libcairo2).")
@click.option("--format", "formats", type=click.Choice(["svg", "pdf", "png"],
                                                        case_sensitive=False),
              multiple=True, metavar="[svg|pdf|png]",
              help="What to write beside each figure's SVG (always written), once for each: "
                   "pdf (the default), png, or both. PDF and PNG need libcairo2.")
@click.option("--dpi", type=click.IntRange(50, 1200), default=200, show_default=True,
              help="The PNGs' resolution; each PNG states it, so it is placed at its true "
                   "size in mm.")
@common.paper
@click.option("--allow-undercut", is_flag=True,
              help="A cam whose roller undercuts it, or whose flat face meets a concave "
                   "profile: draw it with the trouble ringed instead of refusing it.")
@common.hide
@common.speaks
@common.fails_cleanly
def solve(source, out_dir, angle, pdf, formats, dpi, paper, allow_undercut, hide, lang, digits):
    """Solve an exercise by graphical construction and check every number.

    FILE is a mechanism file whose [ask] table names what to find (see
    docs/howto/linkages.md), or a bundled id. Instant centres come from
    inspection and Kennedy's theorem (the circle diagram); angular velocities from the
    centres; point velocities by radius rotation, parallel lines or
    components; relative velocities, accelerations, α and Coriolis
    components from the velocity and acceleration polygons. Each
    construction is drawn with numbered steps, and each number is compared
    with the independent analytic solver.

    \b
    Writes into DIR (each figure as .svg, and as .pdf unless --no-pdf, or
    as --format asks: --format png --dpi 300 for a slide's PNGs):
      centres, circle-diagram, V_<P>-<method>
                     the instant centres and each velocity construction
      worked         space diagram, velocity and acceleration polygons and
                     the results table on one page (when polygons are asked)
      positions      the compass arcs that placed each asked point (pos_B)
      equivalent-linkage   a contact's equivalent link or slot (equiv_R)
      klein          Klein's construction of a slider-crank's piston (method klein)
      limits         the limit positions by compass (time ratio, stroke)
      mechanism      the mechanism alone (when nothing is asked at a position)
      solution       every figure in one file (a page each in the PDF)
      steps.md       the numbered steps, matching the numbers on the figures
      results.json   every quantity (SI) with its analytic reference and error
      .tarsim-manifest.json   what this solve wrote (the next one replaces it)
    With several positions ([ask] at = [...]) each figure's name ends in the
    position (worked-t-2.34s.svg); --angle solves one angle instead. Each
    figure is set on one sheet of --paper, upright or on its side; a worked
    page that one sheet cannot hold runs on over two or more (a page each in
    its PDF, one under another in its SVG).

    A gear-train file ([[gear]] tables) is solved as the notes do it: speeds
    in exact fractions through an ordinary train, or by the tabular method
    in a planetary one, each checked by the Willis equations; it writes
    table (or train-value), train (the train in side view), kutzbach (a
    planetary train's velocity diagram) and mesh (the involute mesh, with
    [involute]). A cam file ([cam], [follower] and [[segment]] tables) gets
    the follower's displacement diagram by construction, its velocity and
    acceleration diagrams, and the profile laid out by inversion (profile,
    with the pressure angle and curvature at each station in profile-table);
    a roller that undercuts the cam is refused unless --allow-undercut. A
    balancing file ([rotor] or [engine]) gets its force polygon (and couple
    polygon for two planes) closed on the balancing masses, or an engine's
    primary and secondary forces and couples.

    \b
    Example:
      tarsim solve four-bar -o four-bar-solution
      tarsim solve crank-shaper -o shaper      # θ2 = 90° and t = 2.34 s
      tarsim solve my-exercise.toml --angle 120 --no-pdf
      tarsim solve four-bar --format png --dpi 300   # SVG and PNG, no PDF
      tarsim solve whitworth --paper A3          # figures on A3 sheets (A4 by default)
      tarsim solve eccentric-flat-face --paper A3   # a cam's figures drawn for A3
      tarsim solve planetary-q1                  # the notes' planetary Q1
      tarsim solve eccentric-flat-face           # the notes' §3.20 cam
      tarsim solve notes-example-1               # 001 ch. 7 Example 1, corrected
      tarsim solve crank-shaper --lang fa        # figures and steps.md in Persian
      tarsim solve crank-shaper --hide answers,badges,checks   # clean figures for a slide

    The exit status is 3 if any constructed number disagrees with the analytic
    one beyond the tolerance its conditioning allows (the files are written all
    the same, so the disagreement can be seen); 1 for bad input.
    """
    from tarsim.graphics.export import cairo_missing, output_folder
    from tarsim.graphics.hiding import hiding

    loaded, chapter = common.loaded(source, angle)
    with speaking(common.language(lang, digits, loaded)), hiding(hide):
        ex = chapter.set_up(loaded.named_in(spoken()), paper=paper, angle=common.finite(angle))
        out = Path(out_dir or f"{ex.id}-solution")
        with output_folder(out):      # a folder that cannot be written fails before the solve
            solved = chapter.solve(ex, allow_undercut=allow_undercut)
            formats = {f.lower() for f in formats} or {"pdf"}
            pdf = pdf and "pdf" in formats
            reason = cairo_missing() if pdf else None
            png = dpi if "png" in formats else None   # asked by name: refused without cairo
            written = solved.write(out, pdf=pdf and reason is None, png_dpi=png)
    with speaking("en"):              # the terminal's lines are English
        common.report(solved, written, out, reason)


@cli.command()
@common.source
@click.option("-o", "--output", "out_dir", type=click.Path(), default=None,
              metavar="DIR", help="Folder for the sweep (default: <id>-sweep/ here).")
@click.option("--of", "of", default=None, metavar="NAME",
              help="The output: V_B or A_B (point B), omega4, alpha4 or theta4 (link 4). "
                   "Default: the first V_/A_ the exercise asks, else the point on a frame "
                   "slider guide, else ω of the highest-numbered link.")
@click.option("--steps", type=click.IntRange(4, 100000), default=360, show_default=True,
              help="Equal steps of the input angle over the revolution.")
@click.option("--pdf/--no-pdf", default=True, show_default=True,
              help="Also write a PDF of each plot (needs libcairo2).")
@common.speaks
@common.fails_cleanly
def sweep(source, out_dir, of, steps, pdf, lang, digits):
    """Check the graphical solution against the output's curves over a revolution.

    Turns the input through one revolution in equal steps (from the [input]
    angle, the way ω turns) and solves each position with the independent
    analytic solver: the output's position, velocity and acceleration, or a
    link's θ, ω and α. A position that cannot be assembled, or a dead point,
    is a gap in the curves and a row in the table that says why. The positions
    the exercise solves by construction ([ask] at, or the [input] angle) are
    marked on the curves with the constructed values, and the table beside
    them gives each one's distance from the curve. Where the velocity is zero
    the position is extreme (the stroke of a ram, the swing of a lever); where
    the acceleration is zero the velocity peaks: both are found to the
    solver's precision, not the step's. This is a linkage's: a cam, a gear
    train, a rotor or engine and a flywheel give their answers over a turn (the
    greatest values and where they come) from `tarsim solve`.

    A file with loads ([[mass]], [[force]], [[couple]]) gets the turning-moment
    diagram too: the driving torque round the turn from every link's Newton–Euler
    equations, checked at each step by the balance of power; its mean, the
    energy areas between curve and mean, the greatest fluctuation of energy,
    and the flywheel for [forces] speed_fluctuation (or the C_s a given
    flywheel allows).

    \b
    Writes into DIR:
      sweep.csv              one row per step (angle, t, position, V, A)
      sweep-points.csv       graphical values against the curve's
      sweep-position.svg, sweep-velocity.svg, sweep-acceleration.svg (and .pdf)
      turning-moment.svg, turning-moment.csv   with loads: T and every joint force

    \b
    Example:
      tarsim sweep crank-shaper -o shaper-sweep
      tarsim sweep four-bar --of omega4 --steps 720 --no-pdf
      tarsim sweep my-linkage.toml --of V_C
    """
    from .linkages.sweep_run import run_sweep
    from tarsim.graphics.export import cairo_missing, output_folder

    ex = common.linkage(source)

    with speaking(common.language(lang, digits, ex)):
        ex = ex.named_in(spoken())
        reason = cairo_missing() if pdf else None
        out = Path(out_dir or f"{ex.id}-sweep")
        with output_folder(out):      # a folder that cannot be written fails before the sweep
            swept = run_sweep(ex, steps, of=of, bar=common.bar if sys.stderr.isatty() else None)
            written = swept.write(out, pdf=pdf and reason is None)
        common.report(swept, written, out, reason)


@cli.command()
@click.option("--quick", is_flag=True,
              help="Stated positions only, the ends of each stiff sweep, fewer plot points: "
                   "seconds, for CI and tests.")
@click.option("-o", "--out", "out_dir", type=click.Path(file_okay=False), default=None,
              metavar="DIR", help="Folder for report.md and report/*.svg "
                                  "(default: the checkout's benchmarks/).")
def bench(quick, out_dir):
    """Report each method's error against its run time, and the stiff cases.

    Runs every graphical method (position by compass, centres by Kennedy,
    radius rotation, parallel lines, components, both polygons, the limit
    positions) on the bundled exercises and measures each number against
    the analytic solver and a 50-digit mpmath reference, with its
    conditioning and run time; plots error against run time where a knob
    trades one for the other (the pen and the drawing's size, Newton's
    tolerance, polygon circles, a sweep's step, the working precision); and
    runs the stiff and extreme suite (toggles, near-parallel Kennedy lines,
    centres at infinity, extreme lengths and ω, dead centres, Coriolis as
    ω → 0); and gives every other chapter its rows and extremes against
    closed forms (nearly cancelling gear trains, cams at a 90° pressure
    angle and a vanishing radius of curvature, force polygons near parallel
    lines and dead centres, nearly balanced rotors, the flywheel's step). It
    runs from a source checkout, with the test extra installed.

    \b
    Writes into DIR:
      report.md        the method table, the plots' headlines, the suite,
                       the chapters' rows
      report/*.svg     error against run time, one plot per knob and chapter

    \b
    Example:
      tarsim bench --quick -o /tmp/bench
      tarsim bench                      # the full report, into benchmarks/
    """
    # The checkout is the package's own source (an editable install), or the folder it is
    # run in, or one above it (an install from the checkout, run inside it).
    here = Path.cwd().resolve()
    root = next((r for r in (Path(__file__).resolve().parents[1], here, *here.parents)
                 if (r / "benchmarks" / "bench" / "__init__.py").is_file()), None)
    if root is None:
        raise click.ClickException("tarsim bench runs from a source checkout: run it inside "
                                   "the repository, whose benchmarks/ folder it needs "
                                   "(pip install '.[test]' there)")
    if str(root) not in sys.path:
        sys.path.insert(0, str(root))
    try:
        from benchmarks.bench import write_report
    except ImportError as e:
        raise click.ClickException(f"tarsim bench needs the test extra ({e.name} is missing): "
                                   "pip install -e '.[test]'") from None

    out = Path(out_dir) if out_dir else root / "benchmarks"
    try:
        path = write_report(out, quick=quick, bar=common.bar if sys.stderr.isatty() else None)
    except OSError as e:
        raise click.ClickException(f"cannot write the report into {out}: "
                                   f"{e.strerror or e}") from None
    plots = sorted((out / "report").glob("*.svg"))
    click.echo(f"wrote {path} and {len(plots)} plots in {out / 'report'}/")


@cli.command()
@click.argument("source", metavar="EXERCISE")
@click.argument("drawing", metavar="DRAWING", type=click.Path(exists=True))
@click.option("-o", "--out", "out_dir", type=click.Path(file_okay=False), required=True,
              metavar="DIR", help="Folder for grade.json, grade.svg and feedback.html (a "
                                  "class: a folder each, grades.csv and summary.svg).")
@click.option("--position", type=click.IntRange(min=1), default=1, show_default=True,
              help="Which of the exercise's positions the drawing is of ([ask] at = [...]).")
@click.option("--roster", type=click.Path(exists=True, dir_okay=False), default=None,
              metavar="FILE.csv",
              help="A class's students: a CSV file, a header row and then a row a student, "
                   "its columns headed id (or 'student id', 'student number', 'id number'), "
                   "name (or 'full name', 'student') and file (or 'file name', 'drawing'), "
                   "in any case. A student with no file gets a row 'no drawing handed in'; "
                   "a file no row names gets a row saying so.")
@click.option("--pattern", metavar="PATTERN", default=None,
              help="Read each file's student off its name: {id} and {name} stand for them, "
                   "* for any text, e.g. '{id}_{name}.svg'; with no ending ('{id}_{name}') "
                   "the name is matched less its ending, so any kind of file fits. With "
                   "--roster, for the students whose file the roster does not give.")
@click.option("--pdf/--no-pdf", default=True, show_default=True,
              help="Write feedback.pdf beside each feedback.html (needs libcairo2).")
@click.option("--workers", type=click.IntRange(min=1), default=1, show_default=True,
              help="Processes to grade a class on.")
@click.option("--scheduler", metavar="ADDRESS", default=None,
              help="Grade a class on a Dask distributed cluster (tcp://host:8786), for a "
                   "course too big for one machine; needs pip install 'tarsim[dask]'.")
@common.speaks
@common.fails_cleanly
def grade(source, drawing, out_dir, position, roster, pattern, pdf, workers, scheduler, lang,
          digits):
    """Grade a student's drawing against tarsim's own solution, item by item.

    DRAWING is an SVG (or .svgz) as Inkscape, GeoGebra, LibreOffice Draw or a
    CAD program exports it, its poles and tips labelled as the course writes
    them (o or o_v and a, b, a4 for velocities; o′ or o_a and a′, a′₄ or a₄′
    for accelerations; tarsim's a₂ ≡ a₄), or a JSON or CSV table of answers
    ({"V_B": 0.233}), or a folder of them: a whole class. A space diagram on
    the sheet (points as the exercise names them, O2, A; centres I13 or 13)
    is graded too, and sets the polygons' orientation (else the sheet's
    axes do): a polygon drawn the other way round is wrong, not turned. The
    scale is the one written on the drawing ("1 cm = 0.5 m/s"), else the
    drawing's own from the input's tip, unless the exercise's [grading]
    requires its own (scale = "required").

    A tip is held within each line it is cut from by a pen of 0.5 mm and a
    set square of 0.5° (or the exercise's [grading]), over the line's
    conditioning; a number in a table by the same rule. Verdicts: correct,
    follows from an earlier error (drawn rightly from a wrong tip; scores
    unless [grading] follow = false), reversed Coriolis, swapped, wrong
    sense, wrong magnitude, wrong direction, wrong position (a centre),
    missing. Construction points (n′) and unasked answers are noted, not
    charged; a drawing of another position is said to be. The score is the
    share of the points scored.

    \b
    Writes into DIR:
      grade.json     the score and each item: verdict, expected, found,
                     tolerance, advice
      grade.svg      the drawing in grey, tarsim's polygons over it in blue,
                     each wrong item ringed in red and explained under it
      feedback.html  the student's page: the overlay, the score, and each
                     item's verdict, tolerance and advice (and feedback.pdf)
    For a folder: a folder of those for each drawing (its name's stem when
    that is plain, else a readable form of it and a short hash, so no two
    share one), grades.csv (a row for every file: one that is not a drawing
    says what to hand in instead, one that cannot be read why, a link out of
    the folder that it is not read; and with --roster, a row for each
    student who handed in nothing), summary.svg (the scores' histogram and
    each item's error rate) and, the students known (--roster or --pattern),
    moodle.csv and canvas.csv for their gradebooks' import. Nothing is
    written if a place they go is taken by a file tarsim did not write.

    \b
    Example:
      tarsim grade four-bar ali.svg -o graded/ali
      tarsim grade crank-shaper answers.json -o graded/answers
      tarsim grade four-bar class/ -o graded --workers 2
      tarsim grade four-bar class/ -o graded --roster students.csv
      tarsim grade four-bar class/ -o graded --pattern '{id}_{name}.svg'
      tarsim grade four-bar class/ -o graded --scheduler tcp://127.0.0.1:8786
    """
    from .catalog import load
    from .grading.class_grades import grade_class
    from .grading.grade import grade as grade_one
    from .grading.report import grade_files, grade_table
    from tarsim.graphics.export import cairo_missing, write_folder

    if pdf and cairo_missing():
        click.echo("note: feedback.pdf is not written, for libcairo2 is not installed "
                   "(Debian/Ubuntu: apt-get install libcairo2); feedback.html is", err=True)
        pdf = False
    with speaking(common.language(lang, digits, None)):     # the overlay's and the page's words
        path = Path(drawing)
        if not path.is_dir():
            if roster or pattern:
                raise click.UsageError("--roster and --pattern find the students of a "
                                       "class folder; DRAWING is one file")
            g = grade_one(load(source), path, position - 1)
            click.echo(grade_table(g))
            files = grade_files(g, position=position - 1, pdf=pdf)
            write_folder(files, out_dir)
            click.echo(f"wrote {', '.join(files)} to {out_dir}/")
            return
        graded = grade_class(source, path, out=Path(out_dir), position=position - 1,
                             roster=roster, pattern=pattern, pdf=pdf, workers=workers,
                             scheduler=scheduler, bar=common.bar)
        write_folder(graded.files, out_dir)                # all of it, or nothing
        click.echo(graded.summary(out_dir))


@cli.command()
@common.source
@click.option("-o", "--output", "output", type=click.Path(dir_okay=False), default=None,
              metavar="PAGE", help="The page to write (default: <id>-view.html here).")
@click.option("--step", "step", type=click.FloatRange(0.05, 10.0), default=0.5,
              show_default=True, help="Degrees between frames of the revolution.")
@common.fails_cleanly
def view(source, output, step):
    """Write an interactive page: step through the construction, turn the crank.

    One self-contained HTML file (inline SVG, script and data; no network, no
    server) that opens from disk in any current browser:

    \b
      - each figure of the exercise's first position, as `solve` draws it,
        its construction step by step (previous, next, play, a slider),
        numbered as steps.md numbers them, the current step highlighted and
        the earlier ones dimmed, in English or Persian;
      - the input turned through a revolution (a slider, or drag the crank
        pin): the figure moves with the joints, instant centres and polygon
        tips, with the output's curve and a cursor. Every frame is drawn by
        tarsim's constructions and checked against the analytic solver; a
        frame that fails or cannot be assembled says so, and limit positions
        and dead points are marked on the slider;
      - layers to show or hide, zoom (wheel) and pan (drag), and a button that
        downloads the frame shown as SVG.

    \b
    Example:
      tarsim view crank-shaper -o shaper.html
      tarsim view four-bar --step 1
    """
    from .linkages.view import frame_outcomes, view_data
    from tarsim.graphics.export import write_text
    from tarsim.graphics.view_page import view_html

    ex = common.linkage(source)
    target = Path(output or f"{ex.id}-view.html")
    if sys.stderr.isatty():
        with click.progressbar(length=round(360 / step), label="frames",
                               file=sys.stderr) as bar:
            data = view_data(ex, step_deg=step, progress=bar.update)
    else:
        data = view_data(ex, step_deg=step)
    html = view_html(data)
    write_text(target, html)
    frames = frame_outcomes(data["frames"])
    click.echo(f"wrote {target} ({len(html.encode()) / 1e6:.2f} MB, {len(data['frames'])} "
               f"frames: {len(frames['checked'])} checked, {len(frames['lost'])} out of reach "
               f"or beyond the construction, {len(frames['failing'])} failing their check)")
    if frames["failing"]:
        raise CheckMismatch([f"the frame at {math.degrees(f['angle']):.1f}°"
                             for f in frames["failing"]][:5])


cli.add_command(list_)
cli.add_command(new)
cli.add_command(handout)
cli.add_command(serve)
