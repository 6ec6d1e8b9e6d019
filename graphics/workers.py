"""Draw independent figures side by side, one process a core.

Placing a figure's labels is most of the time a solve takes, and a solution's figures do
not depend on each other. So where the platform forks (Linux), the jobs are shared out
to forked workers: a fork inherits the jobs as they are (closures over the solution, which
need no pickling) and only the finished results come back, pickled. Elsewhere, in a
process that runs other threads (a fork copies their locks mid-use), for one job, on a
one-core machine, or where the jobs' expected costs say the cores would save less than
the pool costs (:data:`POOL_COST`), the jobs run here in turn. Either way the results are
the same and in the same order.
"""

from __future__ import annotations

import os
import threading
from collections.abc import Callable
from typing import TypeVar

__all__ = ["draw_each"]

T = TypeVar("T")

POOL_COST = 40.0
"""What a pool costs in ms: forking its workers, and the results pickled back (30–50 ms
measured for a solution's figures on a 2-core machine, against their drawing in turn).
Jobs that the cores would finish no sooner than this run in turn: a big figure and a small
one, or a few small ones."""

_JOBS: list[Callable[[], object]] = []
"""The jobs of the pool being run, read by its forked workers."""


def _cores() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:          # not on Linux: then forking is not used anyway
        return os.cpu_count() or 1


def _forks() -> bool:
    import multiprocessing          # here: a command that draws in turn does not pay for it

    return ("fork" in multiprocessing.get_all_start_methods()
            and threading.active_count() == 1
            and multiprocessing.parent_process() is None)   # no pools inside workers


def _run(k: int):
    """Run job ``k`` in a worker; a failure comes back as None, to be run again at home,
    where it raises as itself (an exception need not survive pickling)."""
    try:
        return True, _JOBS[k]()
    except BaseException:          # noqa: BLE001 (any failure is re-raised by the parent)
        return False, None


def draw_each(jobs: list[Callable[[], T]], weights: list[float] | None = None) -> list[T]:
    """Return each job's result, in order, using every core where that is safe.

    Parameters
    ----------
    jobs : list of callables
        Independent jobs without arguments, each returning a picklable result (a
        :class:`~tarsim.graphics.figure.Figure`).
    weights : list of float, optional
        Each job's expected cost in ms: the heaviest are started first, so that a long one
        does not start last and keep one core busy while the others idle; and the pool is
        not forked for jobs that would finish less than :data:`POOL_COST` sooner on it
        than in turn (the longest, or their share of the cores, against their sum).
    """
    workers = min(len(jobs), _cores())
    if weights and workers >= 2:
        total = sum(weights)
        if total - max(max(weights), total / workers) < POOL_COST:
            workers = 1
    if workers < 2 or not _forks():
        return [job() for job in jobs]
    order = sorted(range(len(jobs)), key=lambda k: -weights[k]) if weights else range(len(jobs))
    import multiprocessing

    global _JOBS
    _JOBS = list(jobs)
    try:
        with multiprocessing.get_context("fork").Pool(workers) as pool:
            done = dict(zip(order, pool.map(_run, order, chunksize=1)))
    finally:
        _JOBS = []
    return [done[k][1] if done[k][0] else job() for k, job in enumerate(jobs)]
