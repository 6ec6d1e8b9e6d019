"""A whole class's drawings graded at once, on several processes if asked.

Every file of the class folder gets a row in grades.csv: one that is not a drawing (a
picture, a PDF) says what to hand in instead, and one unreadable drawing does not stop the
batch, its row saying why. Each drawing's grade goes into a folder of its own, named for it
(:func:`folder_for`): no two drawings share one, whatever their names. Nothing is read from
outside the class folder (a link out of it gets a row saying so), and the class is written
as one set (:func:`tarsim.graphics.export.write_folder`), every clash with what is already
in the output folder found before anything is written.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import socket
from collections.abc import Callable, Iterator
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path

from tarsim.constructions.errors import InputError, TarsimError
from tarsim.graphics.export import MANIFEST
from .drawing import file_name, printable
from .grade import Grade, grade

__all__ = ["ClassFile", "class_files", "not_a_drawing", "grade_many", "folder_for", "GRADABLE"]

GRADABLE = (".svg", ".svgz", ".json", ".csv")
"""The files a class folder is graded from (in any case: ``.SVG`` too)."""

_RESERVED = {"con", "prn", "aux", "nul", *(f"{p}{d}" for p in ("com", "lpt") for d in range(10))}
"""Names Windows keeps for its devices, which no folder may take."""


@dataclass(frozen=True)
class ClassFile:
    """A file of a class folder: its ``path`` there, the ``folder`` its grade goes into,
    and why it is not graded (``refused``), if it is not."""

    path: Path
    folder: str
    refused: str = ""

    @property
    def name(self) -> str:
        """The file's name in the class folder, as grades.csv gives it."""
        return file_name(self.path)


def folder_for(name: str) -> str:
    """The output folder of the drawing named ``name``.

    A plain name (lower-case letters, digits, ``-`` and ``_``, then ``.svg``) gives its
    stem. Any other gives its letters and digits (``_`` for the rest), a dot, and the first
    ten hex digits of the SHA-256 of the whole name. A plain folder has no dot and the others
    differ in their hash, so no two names share a folder, on a file system that tells
    case apart or one that does not; and a name always gets the same folder, whatever else
    the class holds.

    >>> folder_for("ali-2.svg"), folder_for("a b.svg"), folder_for("..svg")
    ('ali-2', 'a_b.71729b77b9', 'drawing.d4e2061cd7')
    """
    dot = name.rfind(".")
    stem, suffix = (name[:dot], name[dot:]) if dot > 0 else (name, "")
    if suffix == ".svg" and re.fullmatch(r"[a-z0-9_-]{1,64}", stem) and stem not in _RESERVED:
        return stem
    readable = re.sub(r"[^\w-]+", "_", stem).strip("_")[:40] or "drawing"
    if readable.lower() in _RESERVED:
        readable += "_"
    digest = hashlib.sha256(name.encode("utf-8", "surrogateescape")).hexdigest()[:10]
    return f"{readable}.{digest}"


def class_files(folder: Path, *, skip: Path | None = None) -> list[ClassFile]:
    """Every file directly in ``folder``, by name: each gradable one to be graded, and each
    other one with why it is not (:func:`not_a_drawing`), so that none is passed over
    without a word. A link is read only when it leads to a file inside the folder. Left
    out are hidden files that are no drawing (``.DS_Store``; a hidden ``.svg`` is graded),
    what tarsim wrote there itself (its manifest, staging folders, and the files and
    folders the manifest lists) and the folder ``skip`` (the output folder, when it is
    inside the class's).

    Raises
    ------
    InputError
        If the folder cannot be read, or holds nothing to grade.
    """
    try:
        root = folder.resolve()
        entries = sorted(folder.iterdir())
        ours = _written_by_tarsim(folder)
        skip = skip.resolve() if skip is not None else None
    except OSError as e:
        raise InputError(f"cannot be read ({e.strerror or e})", file=printable(str(folder))
                         ) from None
    out = []
    for path in entries:
        if path.name in ours or path.name == MANIFEST or path.name.startswith(".") and \
                path.suffix.lower() not in GRADABLE:
            continue
        if path.is_symlink():
            refused = (not_a_drawing(path) if path.suffix.lower() not in GRADABLE
                       else _link_refused(path, root))
        elif skip is not None and path.is_dir() and path.resolve() == skip:
            continue
        else:
            refused = not_a_drawing(path)
        out.append(ClassFile(path, folder_for(path.name), refused))
    if not out:
        raise InputError("no files in it to grade (.svg drawings, or .json or .csv tables "
                         "of answers)", file=printable(str(folder)))
    return out


_PICTURES = {".png": "a PNG", ".jpg": "a JPEG", ".jpeg": "a JPEG", ".gif": "a GIF",
             ".bmp": "a BMP", ".tif": "a TIFF", ".tiff": "a TIFF", ".webp": "a WebP",
             ".heic": "an HEIC", ".heif": "an HEIF"}
"""Pictures: pixels, from which no point can be read to a pen's width."""

_OTHERS = {".pdf": "a PDF", ".ps": "a PostScript file", ".eps": "an EPS file",
           ".ggb": "a GeoGebra file", ".odg": "a LibreOffice Draw file",
           ".dxf": "a DXF file", ".dwg": "a DWG file", ".doc": "a Word file",
           ".docx": "a Word file", ".odt": "a Writer file", ".ai": "an Illustrator file"}
"""Files a drawing program or a word processor writes, which tarsim does not read."""


def not_a_drawing(path: Path) -> str:
    """Why the file ``path`` of a class folder is not graded, saying what to hand in
    instead; "" if it is a file tarsim grades.

    >>> not_a_drawing(Path("ali.png"))
    'a PNG is a picture, not a drawing: export the drawing as SVG'
    """
    suffix = path.suffix.lower()
    if path.is_dir():
        return "a folder, not a drawing: put the drawings in it in the class folder itself"
    if path.exists() and not path.is_file():
        return "not read: not a file (a pipe or a device)"
    if suffix in GRADABLE:
        return ""
    if suffix in _PICTURES:
        return f"{_PICTURES[suffix]} is a picture, not a drawing: export the drawing as SVG"
    if suffix in _OTHERS:
        return f"{_OTHERS[suffix]} is not read: export the drawing as SVG"
    if suffix in (".zip", ".tar", ".gz", ".7z", ".rar"):
        return f"an archive ({suffix}) is not opened: unpack its drawings into the class folder"
    kind = f"a {printable(suffix)} file" if suffix else "a file with no ending"
    return (f"{kind} is not a drawing: hand in an .svg drawing, or a .json or .csv table of "
            "answers")


def _link_refused(path: Path, root: Path) -> str:
    """Why the link ``path`` in the class folder ``root`` is not read, or "" if it leads to
    a file inside it."""
    try:
        target = path.resolve(strict=True)
    except (OSError, RuntimeError):          # it leads nowhere, or round in a loop
        return "not read: a link that leads to no file"
    if not target.is_relative_to(root):
        return f"not read: a link to {printable(os.readlink(path))[:80]}, outside the class folder"
    return "" if target.is_file() else "not read: a link to something that is not a file"


def _written_by_tarsim(folder: Path) -> set[str]:
    """The names in ``folder`` the manifest there lists (see :func:`tarsim.graphics.export.
    write_folder`), a file or the folder it is in; none if it has no manifest or it cannot
    be read, the safe side."""
    try:
        names = json.loads((folder / MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return set()
    if not isinstance(names, list):
        return set()
    return {n.split("/")[0] for n in names if isinstance(n, str)}


_SOLVED: dict[str, tuple] = {}
"""Each exercise solved once per process: a class is graded against one solve."""


def _one(job: tuple[str, int, str]) -> tuple[str, Grade | str]:
    """Grade one file; a file that cannot be graded gives its one-line reason."""
    source, position, drawing = job
    from ..catalog import load
    from ..linkages.solution import solve_positions

    try:
        if source not in _SOLVED:
            ex = load(source)
            _SOLVED[source] = (ex, solve_positions(ex))
        ex, positions = _SOLVED[source]
        return drawing, grade(ex, drawing, position, positions)
    except TarsimError as e:
        return drawing, str(e)


def grade_many(source: str, drawings: list[Path], position: int = 0, workers: int = 1,
               done: Callable[[], None] | None = None,
               scheduler: str | None = None) -> Iterator[tuple[str, Grade | str]]:
    """Each drawing's grade (or why it could not be graded), in the drawings' order;
    ``done`` is called as each finishes. With ``scheduler`` (a Dask distributed scheduler's
    address) the batch runs on that cluster, whose workers must be able to read the
    drawings' paths. The paths sent are absolute (and the exercise's, if it is a file), for
    a worker runs in a folder of its own, not this process's."""
    if Path(source).is_file():
        source = str(Path(source).absolute())
    jobs = [(source, position, str(Path(d).absolute())) for d in drawings]
    if scheduler:
        yield from _on_cluster(jobs, scheduler, done)
        return
    if workers <= 1:
        for job in jobs:
            result = _one(job)
            if done:
                done()
            yield result
        return
    # Some drawings a round trip: a drawing is graded in milliseconds, as long as one trip.
    chunk = max(1, min(16, len(jobs) // (4 * workers)))
    with ProcessPoolExecutor(max_workers=workers) as pool:
        for result in pool.map(_one, jobs, chunksize=chunk):
            if done:
                done()
            yield result


def _on_cluster(jobs, scheduler: str, done) -> Iterator[tuple[str, Grade | str]]:
    """The jobs graded on a Dask cluster, in order.

    Raises
    ------
    TarsimError
        If Dask is not installed (the ``dask`` extra) or the scheduler cannot be reached.
    """
    try:
        from distributed import Client
    except ImportError:
        raise TarsimError("--scheduler needs Dask: pip install 'tarsim[dask]'") from None
    host, _, port = scheduler.removeprefix("tcp://").rpartition(":")
    try:
        if host and port.isdigit():            # a refused port is said at once, not in 10 s
            socket.create_connection((host, int(port)), timeout=5).close()
        client = Client(scheduler, timeout="10s")
    except (OSError, TimeoutError) as e:
        raise TarsimError(f"cannot reach the Dask scheduler at {scheduler}: "
                          f"{getattr(e, 'strerror', None) or e}") from None
    with client:
        futures = client.map(_one, jobs, pure=False)
        for future in futures:
            result = future.result()
            if done:
                done()
            yield result
