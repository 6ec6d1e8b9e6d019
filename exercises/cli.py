"""The ``tarsim`` command line: a thin click layer over the library.

Each command parses its arguments, makes one library call, writes its output and
turns a :class:`~constructions.errors.TarsimError` into one line on stderr with a
non-zero exit; no traceback reaches the user.
"""

from __future__ import annotations

import functools
import math
from pathlib import Path

import click

from constructions.errors import TarsimError
from constructions.model import Drive, Mechanism

__all__ = ["cli"]


def _fails_cleanly(fn):
    """Map tarsim's errors to ``Error: …`` and exit code 1."""
    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        try:
            return fn(*args, **kwargs)
        except TarsimError as e:
            raise click.ClickException(str(e)) from None
    return wrapper


def _mechanism(source: str, angle: float | None) -> Mechanism:
    from exercises.catalog import resolve
    from exercises.mechanism_file import load_mechanism

    mech = load_mechanism(resolve(source))
    if angle is not None:
        d = mech.drive
        rad = angle if mech.units.angle == "rad" else math.radians(angle)
        mech = mech.with_drive(Drive(d.link, rad, d.omega, d.alpha, d.alpha_given))
    return mech


_source = click.argument("source", metavar="FILE")
_angle = click.option("--angle", type=float, default=None, metavar="ANGLE",
                      help="Input angle to use instead of the file's, in the file's angle unit.")


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="tarsim")
def cli():
    """Graphical kinematics of planar mechanisms, drawn as textbook figures.

    FILE is a mechanism file (TOML, see the README) or the id of a bundled
    example; `tarsim list` shows the bundled ones.

    \b
    Example:
      tarsim draw four-bar -o four-bar.svg
      tarsim check crank-shaper --angle -44.072
    """


@cli.command()
@_source
@click.option("-o", "--output", "output", required=True, type=click.Path(dir_okay=False),
              help="Figure to write: .svg, .pdf or .png (PDF and PNG need libcairo2).")
@_angle
@_fails_cleanly
def draw(source, output, angle):
    """Draw the kinematic diagram of FILE at its input position.

    Every joint is located by compass construction (arcs and lines, one dyad
    after another) and drawn in textbook style: hatched ground pivots, pins,
    slider blocks on guides, link numbers, the input's θ and ω, and a scale bar
    that measures true on the printed PDF.

    \b
    Example:
      tarsim draw four-bar -o four-bar.pdf
      tarsim draw my-linkage.toml -o fig.svg --angle 120
    """
    from constructions.assembly import assemble
    from graphics.diagram import draw_kinematic_diagram
    from graphics.export import write_figure

    mech = _mechanism(source, angle)
    path = write_figure(draw_kinematic_diagram(assemble(mech)), output)
    click.echo(f"wrote {path}")


@cli.command()
@_source
@_angle
@_fails_cleanly
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
    from exercises.report import check_positions, format_check

    click.echo(format_check(check_positions(_mechanism(source, angle))))


@cli.command(name="list")
def list_():
    """List the bundled examples: their ids and where they come from.

    \b
    Example:
      tarsim list
    """
    import tomllib

    from exercises.catalog import bundled

    for name, path in bundled().items():
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
        click.echo(f"{name:<22}{data.get('name', '')}")
        if data.get("source"):
            click.echo(f"{'':<22}from {data['source']}")
