"""Write a figure to .svg, .pdf or .png, or a folder of files, all or nothing.

SVG needs no system library. A figure's PDF is drawn straight from it with cairo
(:mod:`.pdf`); PNG, and PDF of SVG text, go through cairosvg. Both are imported only
when asked for; without libcairo2 the user gets one line saying so. A
file is written to a temporary name beside the target and renamed into place, so
a failure leaves nothing half-written; a folder's files (:func:`write_folder`) are
all staged first and moved in only when every one is written.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

try:
    import fcntl
except ImportError:               # not on Windows: folders are then written unlocked
    fcntl = None

from ..constructions.errors import TarsimError

from .figure import Figure
from .rtl import for_cairo
from .svg import to_svg

__all__ = ["RenderError", "FORMATS", "MANIFEST", "write_figure", "write_text", "write_folder",
           "check_folder", "output_folder", "svg_to", "cairo_missing", "figure_pdf"]

FORMATS = ("svg", "pdf", "png")

MANIFEST = ".tarsim-manifest.json"
"""The hidden file in an output folder naming the files tarsim wrote there (a JSON list)."""

_STAGE = ".tarsim-"


class RenderError(TarsimError):
    """A figure or file cannot be written: an unknown format, no libcairo, a folder that fails."""

_NO_CAIRO = ("PDF and PNG output need the cairo library (libcairo2), which is not installed: "
             "install it (Debian/Ubuntu: apt-get install libcairo2) or write .svg instead")


def cairo_missing() -> str | None:
    """The one-line reason PDF/PNG cannot be made here, or None when they can; cairo's
    bindings are loaded, for workers forked after this to inherit."""
    try:
        import cairocffi  # noqa: F401, PLC0415  (it loads libcairo2, or fails to)
    except (ImportError, OSError):
        return _NO_CAIRO
    return None


def svg_to(svg: str, fmt: str, *, dpi: float = 200.0) -> bytes:
    """Convert SVG text to PDF or PNG bytes with cairosvg.

    Raises
    ------
    RenderError
        If cairosvg or libcairo2 is missing.
    """
    try:
        import cairosvg  # noqa: PLC0415  (lazy: SVG output must not need libcairo)
    except (ImportError, OSError):
        raise RenderError(_NO_CAIRO) from None
    data = for_cairo(svg).encode("utf-8")      # Persian shaped: cairosvg cannot shape it
    if fmt == "pdf":
        return cairosvg.svg2pdf(bytestring=data)
    if fmt == "png":
        return cairosvg.svg2png(bytestring=data, dpi=dpi, background_color="white")
    raise RenderError(f"cannot convert to '{fmt}'; choose one of {', '.join(FORMATS)}")


def figure_pdf(pages: list[Figure]) -> bytes:
    """A PDF of ``pages`` (a figure's sheets, or every figure of a solution), a page each
    at its own size and true scale, drawn from the figures themselves
    (:mod:`~graphics.pdf`).

    Raises
    ------
    RenderError
        If libcairo2 is missing.
    """
    if missing := cairo_missing():
        raise RenderError(missing)
    from .pdf import draw_pdf  # noqa: PLC0415

    return draw_pdf(pages)


def write_figure(fig: Figure | str, path: str | Path) -> Path:
    """Write ``fig`` (a Figure or SVG text) to ``path``; the suffix picks the format.

    Raises
    ------
    RenderError
        For an unknown suffix, a missing libcairo2, or a path that cannot be written.
    """
    path = Path(path)
    fmt = path.suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise RenderError(f"cannot write '{path.name}': the name must end in "
                          f"{', '.join('.' + f for f in FORMATS)}")
    if fmt == "pdf" and not isinstance(fig, str):
        data = figure_pdf([fig])
    else:
        svg = fig if isinstance(fig, str) else to_svg(fig)
        data = svg.encode("utf-8") if fmt == "svg" else svg_to(svg, fmt)
    _write_atomically(path, data)
    return path


def write_text(path: str | Path, data: str | bytes) -> Path:
    """Write text (UTF-8) or bytes to one file ``path`` atomically (a folder's set of files
    goes through :func:`write_folder`).

    Raises
    ------
    RenderError
        If the path cannot be written.
    """
    path = Path(path)
    _write_atomically(path, data.encode("utf-8") if isinstance(data, str) else data)
    return path


def _write_atomically(path: Path, data: bytes) -> None:
    folder = path.parent if str(path.parent) else Path(".")
    if not folder.is_dir():
        raise RenderError(f"cannot write '{path}': the folder '{folder}' does not exist")
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=folder)
    except OSError as e:
        raise RenderError(f"cannot write '{path}': {e.strerror}") from None
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)  # mkstemp makes 0600; a figure is an ordinary file
        os.replace(tmp, path)
    except OSError as e:
        Path(tmp).unlink(missing_ok=True)
        raise RenderError(f"cannot write '{path}': {e.strerror}") from None


# ----- a folder of files: all or nothing, and never the user's ---------------------------
def check_folder(path: str | Path) -> None:
    """Make the folder ``path`` (parents too) and prove it writable, before a long solve.

    Raises
    ------
    RenderError
        If the folder cannot be made or written, or ``path`` is a file.
    """
    _prepare(Path(path))


@contextmanager
def output_folder(path: str | Path) -> Iterator[Path]:
    """Check the folder ``path`` as :func:`check_folder` does; if the body then fails, remove
    the folders the check made while they are still empty, so a failed solve leaves none.

    Raises
    ------
    RenderError
        If the folder cannot be made or written, or ``path`` is a file.
    """
    path = Path(path)
    made = _prepare(path)
    try:
        yield path
    except BaseException:
        _remove_empty(made)
        raise


def write_folder(files: dict[str, str | bytes], out_dir: str | Path) -> list[Path]:
    """Write ``files`` (name: text or bytes) into ``out_dir`` as one set; return their paths.

    All are written to a hidden staging folder inside ``out_dir`` first, so a full disk
    leaves the folder as it was. Under an exclusive lock on the folder, the files are then
    renamed into place, those the previous run listed in :data:`MANIFEST` and this one does
    not write are removed, and the manifest is rewritten: the folder holds one solution,
    the last run's whole. A file of the same name that tarsim did not write is never
    replaced: the run is refused before anything moves.

    Raises
    ------
    RenderError
        If the folder cannot be made or written, or holds a file of one of these names
        that tarsim did not write.
    """
    out = Path(out_dir)
    for name in files:
        if not _plain_name(name) or name == MANIFEST or name.startswith(_STAGE):
            raise RenderError(f"cannot write '{name}': not a plain file name")
    _prepare(out, probe=False)
    names = list(files)
    try:
        stage = Path(tempfile.mkdtemp(prefix=_STAGE, dir=out))
    except OSError as e:
        raise RenderError(f"cannot write into the folder '{out}': {e.strerror}") from None
    try:
        for name, data in files.items():
            try:
                _put(stage / name, data.encode("utf-8") if isinstance(data, str) else data)
            except OSError as e:
                raise RenderError(f"cannot write '{out / name}': {e.strerror}") from None
        with _locked(out):
            _commit(stage, out, names)
    finally:
        shutil.rmtree(stage, ignore_errors=True)
    return [out / name for name in names]


def _commit(stage: Path, out: Path, names: list[str]) -> None:
    """Move the staged files into ``out``; the caller holds the folder's lock."""
    old = _read_manifest(out)
    for name in names:
        if name not in old and os.path.lexists(out / name):
            raise RenderError(f"cannot write '{out / name}': a file of that name is already "
                              "there and tarsim did not write it; move it or choose another "
                              "folder with -o")
    # The manifest first lists old and new, so a run killed halfway leaves every file it
    # moved known as tarsim's; the one listing this run's files alone comes last.
    _write_manifest(stage / f"{_STAGE}both", out, [*old, *names])
    try:
        for name in names:
            os.replace(stage / name, out / name)
    except OSError as e:
        raise RenderError(f"cannot write '{out / name}': {e.strerror}") from None
    kept = []
    for name in sorted(old.difference(names)):
        try:
            (out / name).unlink(missing_ok=True)
        except OSError:                        # a folder now, say: listed, a later run retries
            kept.append(name)
    _write_manifest(stage / f"{_STAGE}new", out, [*names, *kept])


def _write_manifest(tmp: Path, out: Path, names: list[str]) -> None:
    """Replace the manifest atomically with the sorted ``names``, written first to ``tmp``."""
    try:
        _put(tmp, (json.dumps(sorted(set(names)), indent=0) + "\n").encode("utf-8"))
        os.replace(tmp, out / MANIFEST)
    except OSError as e:
        raise RenderError(f"cannot write '{out / MANIFEST}': {e.strerror}") from None


def _put(path: Path, data: bytes) -> None:
    """Write a new file (mode 0666 less the umask, as any file the user makes)."""
    with open(path, "xb") as f:
        f.write(data)


def _read_manifest(out: Path) -> set[str]:
    """The names the last run wrote; none if there is no manifest or it cannot be read
    (then every file there counts as the user's, which is the safe side)."""
    try:
        names = json.loads((out / MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return set()
    if not isinstance(names, list):
        return set()
    return {n for n in names if isinstance(n, str) and _plain_name(n) and n != MANIFEST}


def _plain_name(name: str) -> bool:
    """True for a file name with no folder in it, so a manifest cannot reach outside."""
    return name not in ("", ".", "..") and "/" not in name and os.sep not in name \
        and (os.altsep is None or os.altsep not in name)


@contextmanager
def _locked(out: Path) -> Iterator[None]:
    """Hold an exclusive lock on the folder itself: concurrent runs commit one at a time."""
    if fcntl is None:
        yield
        return
    try:
        fd = os.open(out, os.O_RDONLY)
    except OSError as e:
        raise RenderError(f"cannot write into the folder '{out}': {e.strerror}") from None
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)                           # closing the last fd releases the lock


def _prepare(out: Path, *, probe: bool = True) -> list[Path]:
    """Make ``out`` and any missing parents, and with ``probe`` create and remove a file in
    it; return the folders made, outermost first."""
    try:
        if out.exists() and not out.is_dir():
            raise RenderError(f"cannot write into '{out}': it is a file, not a folder")
        missing = []
        folder = out
        while not folder.is_dir() and folder != folder.parent:
            missing.append(folder)
            folder = folder.parent
    except OSError as e:                       # a parent that may not be searched
        raise RenderError(f"cannot make the folder '{out}': {e.strerror}") from None
    made: list[Path] = []
    try:
        for folder in reversed(missing):
            try:
                folder.mkdir()
            except FileExistsError:
                if not folder.is_dir():
                    raise RenderError(f"cannot make the folder '{out}': '{folder}' is a file"
                                      ) from None
                continue                       # made meanwhile by someone else: not ours
            except OSError as e:
                raise RenderError(f"cannot make the folder '{out}': {e.strerror}") from None
            made.append(folder)
        if probe:
            try:
                fd, tmp = tempfile.mkstemp(prefix=_STAGE, dir=out)
                os.close(fd)
                os.unlink(tmp)
            except OSError as e:
                raise RenderError(f"cannot write into the folder '{out}': {e.strerror}"
                                  ) from None
    except RenderError:
        _remove_empty(made)
        raise
    return made


def _remove_empty(made: list[Path]) -> None:
    """Remove the folders ``made`` (outermost first) while empty: a filled one is kept."""
    for folder in reversed(made):
        try:
            folder.rmdir()
        except OSError:
            break
