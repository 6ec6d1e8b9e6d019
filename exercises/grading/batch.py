"""A whole class's drawings graded at once, on several processes if asked.

One unreadable drawing does not stop the batch: its row in grades.csv says why, and the
others are graded. Each student's files go into a folder named for the drawing, made safe:
whatever a file's name says, nothing is written outside the chosen folder.
"""

from __future__ import annotations

import re
import socket
from collections.abc import Callable, Iterator
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from ...constructions.errors import TarsimError
from .grade import Grade, grade

__all__ = ["drawings_in", "grade_many", "folder_for", "GRADABLE"]

GRADABLE = (".svg", ".json", ".csv")
"""The files a class folder is graded from."""


def drawings_in(folder: Path) -> list[Path]:
    """The gradable files directly in ``folder``, by name."""
    return sorted(p for p in folder.iterdir() if p.is_file() and p.suffix.lower() in GRADABLE)


def folder_for(drawing: Path) -> str:
    """A student's folder name: the drawing's stem, with anything but letters, digits, dot,
    dash and underscore made an underscore (never "." or "..").

    >>> folder_for(Path("../x/ali rezaei (2).svg"))
    'ali_rezaei__2_'
    """
    name = re.sub(r"[^A-Za-z0-9._-]", "_", drawing.stem).strip(".") or "drawing"
    return name


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
