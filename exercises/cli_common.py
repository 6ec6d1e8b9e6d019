"""What the commands of :mod:`.cli` share: their options, the exercise each reads, and the
mapping of tarsim's errors to one line and an exit status (1 for bad input, 3 for a
failed check)."""

from __future__ import annotations

import functools
import math
import sys

import click

from tarsim.constructions.errors import (AssemblyError, CheckMismatch, GeometryError,
                                         IllConditioned, InputError, TarsimError)

__all__ = ["EXIT_CHECK_FAILED", "fails_cleanly", "linkage", "loaded", "finite", "source",
           "paper", "speaks", "language", "angle", "hide", "bar", "report"]


EXIT_CHECK_FAILED = 3
"""The exit status when a constructed number disagrees with the analytic one."""


class _CheckFailed(click.ClickException):
    exit_code = EXIT_CHECK_FAILED


def fails_cleanly(fn):
    """Map tarsim's errors to ``Error: …``: exit 3 for a failed check, else 1. An error of
    solving is led by the file it concerns (and the line, for one of assembly), when the
    command read a file; an error of input names its own file, one of output its folder."""
    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        try:
            return fn(*args, **kwargs)
        except CheckMismatch as e:
            raise _CheckFailed(str(e)) from None
        except TarsimError as e:
            # Not output (a RenderError), nor input its own file:line names.
            solving = (isinstance(e, (AssemblyError, GeometryError, IllConditioned))
                       or type(e) is TarsimError or isinstance(e, InputError) and not e.file)
            line = _placed(e, kwargs.get("source")) if solving else str(e)
            raise click.ClickException(line + _told(e)) from None
    return wrapper


def _told(error: TarsimError) -> str:
    """The story behind ``error``, on a line of its own, when ``--verbose`` asks for it."""
    ctx = click.get_current_context(silent=True)
    verbose = ctx is not None and ctx.find_root().params.get("verbose")
    return f"\n  {error.detail}" if verbose and error.detail else ""


def _placed(error: TarsimError, source: str | None) -> str:
    """``error``'s line, led by ``source`` and, for an error of assembly, the line of it
    that the error concerns."""
    from .catalog import resolve
    from .linkages.mechanism_file import line_of

    if not source or source in str(error):
        return str(error)
    try:
        path = resolve(source)
    except TarsimError:
        return str(error)
    if str(path) in str(error):             # it names the file itself
        return str(error)
    line = line_of(error, path) if isinstance(error, AssemblyError) else None
    return f"{source}:{line}: {error}" if line else f"{source}: {error}"


def linkage(source: str, angle: float | None = None):
    """The linkage exercise ``source`` names, at ``angle`` if given (file units); a file of
    another chapter is refused in one line, for the command that asks is the linkages'."""
    ex, chapter = loaded(source, None)
    if chapter.key != "linkages":
        raise InputError(f"{source} is {chapter.kind}: `tarsim solve {source}` solves it; this "
                         "command is for linkages")
    return chapter.set_up(ex, paper=ex.paper, angle=finite(angle))


def loaded(source: str, angle: float | None):
    """The exercise ``source`` names and its chapter, refusing ``--angle`` where the chapter
    has no input angle."""
    from .catalog import load
    from .chapters import chapter_of

    ex = load(source)
    chapter = chapter_of(ex)
    if angle is not None and chapter.no_angle:
        raise click.ClickException(chapter.no_angle)
    return ex, chapter


def finite(angle: float | None) -> float | None:
    """``--angle`` as given, refused in one line if it is not a finite number."""
    if angle is not None and not math.isfinite(angle):
        raise click.ClickException(f"--angle must be a finite number, as a file's angle is; "
                                   f"got {angle:g}")
    return angle


source = click.argument("source", metavar="FILE")
paper = click.option("--paper", type=click.Choice(["A4", "A3", "letter"], case_sensitive=False),
                      default="A4", show_default=True,
                      help="Sheet to set each figure on, in every chapter; its scales are "
                           "chosen to fill it (the finest of 1, 2, 2.5, 4, 5 × 10ᵏ it holds) "
                           "and a plot is drawn as wide as it. A figure drawn at a scale the "
                           "exercise states keeps it, on a bigger page if it must. Example: "
                           "--paper A3.")


def speaks(fn):
    """The --lang and --digits options of a command that writes figures or steps."""
    fn = click.option("--digits", type=click.Choice(["persian", "latin"]), default="persian",
                      show_default=True, help="The digits of numbers in Persian text.")(fn)
    return click.option("--lang", type=click.Choice(["en", "fa"]), default=None,
                        help="The language of the figures' words (captions, legends, scale "
                             "statements, titles) and of steps.md: en, or fa (Persian, in the "
                             "course notes' terms). Point and link names stay as the notes "
                             "write them (O2, A, I13). Default: the file's lang, else en.")(fn)


def language(lang: str | None, digits: str, loaded) -> str:
    """The catalogue a command speaks from: --lang, else the file's ``lang``, else English;
    Persian with --digits latin is its own catalogue."""
    lang = lang or getattr(loaded, "lang", "en")
    return "fa_latn" if lang == "fa" and digits == "latin" else lang


def _hidden_parts(ctx, param, value: str):
    """``--hide`` as the parts it names, a name none of them refused as a usage error."""
    from tarsim.graphics.hiding import parts_to_hide

    try:
        return parts_to_hide(value or "")
    except TarsimError as e:
        raise click.BadParameter(str(e)) from None


hide = click.option("--hide", default="", metavar="PARTS", callback=_hidden_parts,
                    help="Leave parts out of every figure, for a clean one on a slide or in a "
                         "book (comma-separated): answers (the results table's construction "
                         "and analytic columns, the stroke and time ratio under the limit "
                         "positions; a train's speeds, a cam's table and peaks, a balancing "
                         "mass found, a flywheel's energies, left as gaps to fill), badges "
                         "(the circled step numbers; every label stays where it stood), "
                         "checks (the table's construction, analytic and relative-error "
                         "columns). "
                         "Example: --hide answers,badges,checks.")

angle = click.option("--angle", type=float, default=None, metavar="ANGLE",
                      help="Input angle to use instead of the file's, in the file's angle unit.")


def bar(length: int, label: str):
    """A progress bar on stderr."""
    return click.progressbar(length=length, label=label, file=sys.stderr)


def report(done, written: list, out, reason: str | None) -> None:
    """What a command that writes a folder says: the result's lines, the files written and
    a PDF skipped (``reason``); then the exit status 3 if a number failed its check."""
    for line in done.lines():
        click.echo(line)
    click.echo(f"wrote {len(written)} files to {out}/")
    if reason:
        click.echo(f"PDF skipped: {reason}", err=True)
    done.check()
