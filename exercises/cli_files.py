"""The commands over exercise files themselves rather than their solutions: ``list`` shows
the bundled ones, ``new`` starts one of your own."""

from __future__ import annotations

from pathlib import Path

import click

from tarsim.constructions.errors import TarsimError

from . import cli_common as common
from .templates import FOLDERS, KINDS, folder, template

__all__ = ["list_", "new"]


@click.command(name="list")
def list_():
    """List the bundled examples: their ids, where they come from, what they ask.

    They come chapter by chapter: the linkages, their loads, the gear
    trains, the cams, balancing and the flywheel. Give an id wherever a
    command takes FILE, or copy the file from the package's catalog
    folder as a start of your own (`tarsim new` writes a commented one).

    \b
    Example:
      tarsim list
    """
    from .catalog import everything
    from .chapters import listing

    found = everything()
    pad = max(map(len, found), default=0) + 2
    for name, path in found.items():
        try:
            shown = listing(path, name)
        except TarsimError as e:
            click.echo(f"{name:<{pad}}(cannot be read: {e})")
            continue
        click.echo(f"{name:<{pad}}{shown.title}")
        if shown.origin:
            click.echo(f"{'':<{pad}}from {shown.origin}")
        click.echo(f"{'':<{pad}}asks: {shown.asks}")


def _listing_kinds(fn):
    """Put each kind and what it holds into ``fn``'s docstring, where ``{kinds}`` is."""
    rows = [f"{kind:<10}{what}" for kind, what in KINDS.items()]
    fn.__doc__ = fn.__doc__.replace("{kinds}", "\n      ".join(rows))
    return fn


@click.command()
@click.argument("kind", type=click.Choice(list(KINDS)), metavar="KIND")
@click.option("-o", "--output", type=click.Path(allow_dash=True),
              default=None, metavar="FILE",
              help="Where to write it (default: my-KIND.toml here, class/ for the class; "
                   "- for the terminal).")
@click.option("--force", is_flag=True, help="Replace FILE (the class's folder) if it exists.")
@common.fails_cleanly
@_listing_kinds
def new(kind, output, force):
    """Write a commented starting file of KIND that solves as it stands.

    Solve it at once to see what it gives, then change its numbers and
    what it asks; each key is explained beside it, and the guides in
    docs/howto/ give the rest.

    \b
    KIND is one of:
      {kinds}

    \b
    Example:
      tarsim new linkage -o my-linkage.toml     # then: tarsim solve my-linkage.toml
      tarsim new cam -o -            # print it instead
      tarsim new class -o class      # then: tarsim grade crank-shaper class --position 2
    """
    from tarsim.graphics.atomic_files import RenderError, write_text

    if kind in FOLDERS:
        out = Path(output or kind)
        if output == "-" or (out.exists() and not out.is_dir()):
            raise RenderError(f"the {kind} is a folder of drawings: give -o FOLDER")
        if out.is_dir() and any(out.iterdir()) and not force:
            raise RenderError(f"'{out}' holds files already: give another -o FOLDER, or "
                              "--force to write into it")
        # each drawing on its own, as a student's file comes: grade reads a folder that
        # tarsim wrote as a whole (its manifest) as output, never as drawings to grade
        out.mkdir(parents=True, exist_ok=True)
        written = [write_text(out / name, data) for name, data in folder(kind).items()]
        click.echo(f"wrote {len(written)} drawings to {out}/: grade them with  "
                   f"tarsim grade crank-shaper {out} --position 2 -o graded")
        return
    text = template(kind)
    if output == "-":
        click.echo(text, nl=False)
        return
    path = Path(output or f"my-{kind}.toml")
    if path.exists() and not force:
        raise RenderError(f"'{path}' exists already: give another -o FILE, or --force to "
                          "replace it")
    write_text(path, text)
    click.echo(f"wrote {path}: solve it with  tarsim solve {path}")

