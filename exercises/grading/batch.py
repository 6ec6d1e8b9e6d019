"""A whole class's drawings graded at once, on several processes if asked.

One unreadable drawing does not stop the batch: its row in grades.csv says why, and the
others are graded. Each drawing's grade goes into a folder of its own, named for it
(:func:`folder_for`): no two drawings share one, whatever their names. Nothing is read from
outside the class folder (a link out of it gets a row saying so), and every clash with what
is already in the output folder is found before anything is written (:func:`plan_class`).
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

from ...constructions.errors import InputError, TarsimError
from ...graphics.export import MANIFEST
from .drawing import file_name, printable
from .grade import Grade, grade

__all__ = ["ClassFile", "class_files", "grade_many", "folder_for", "GRADABLE"]

GRADABLE = (".svg", ".json", ".csv")
"""The files a class folder is graded from."""

_RESERVED = {"con", "prn", "aux", "nul", *(f"{p}{d}" for p in ("com", "lpt") for d in range(10))}
"""Names Windows keeps for its devices, which no folder may take."""


@dataclass(frozen=True)
class ClassFile:
    """A gradable file of a class folder: its ``path`` there, the ``folder`` its grade goes
    into, and why it is not read (``refused``), if it is not."""

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


def class_files(folder: Path) -> list[ClassFile]:
    """The gradable files directly in ``folder``, by name: a link is read only when it
    leads to a file inside the folder, and the files tarsim wrote there itself (its
    manifest, and those it lists) are not drawings.

    Raises
    ------
    InputError
        If the folder cannot be read, or holds no gradable file.
    """
    try:
        root = folder.resolve()
        entries = sorted(folder.iterdir())
        ours = _written_by_tarsim(folder)
    except OSError as e:
        raise InputError(f"cannot be read ({e.strerror or e})", file=printable(str(folder))
                         ) from None
    out = []
    for path in entries:
        if path.suffix.lower() not in GRADABLE or path.name in ours or \
                path.name == MANIFEST:
            continue
        refused = ""
        if path.is_symlink():
            refused = _link_refused(path, root)
        elif not path.is_file():              # a folder, a pipe, a device: not a drawing
            continue
        out.append(ClassFile(path, folder_for(path.name), refused))
    if not out:
        raise InputError("no .svg, .json or .csv drawings in it", file=printable(str(folder)))
    return out


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
    """The names the manifest in ``folder`` lists (see :func:`tarsim.graphics.export.
    write_folder`); none if it has none or it cannot be read, the safe side."""
    try:
        names = json.loads((folder / MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return set()
    return {n for n in names if isinstance(n, str)} if isinstance(names, list) else set()


_SOLVED: dict[str, tuple] = {}
"""Each exercise solved once per process: a class is graded against one solve."""


def _one(job: tuple[str, int, str]) -> tuple[str, Grade | str]:
    """Grade one file; a file that cannot be graded gives its one-line reason."""
    source, position, drawing = job
    from ..catalog import load
    from ..solution import solve_positions

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
    drawings' paths."""
    jobs = [(source, position, str(d)) for d in drawings]
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
    with ProcessPoolExecutor(max_workers=workers) as pool:
        for result in pool.map(_one, jobs):
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
