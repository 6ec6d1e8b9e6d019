"""draw_each: independent figures drawn on every core give what drawing them in turn gives."""

import os
import threading

import pytest

import tarsim
from tarsim.constructions.errors import AssemblyError
from tarsim.graphics import workers
from tarsim.graphics.svg import to_svg


def _pid_and(value):
    return lambda: (os.getpid(), value)


def test_results_come_back_in_order_from_other_processes(monkeypatch):
    monkeypatch.setattr(workers, "_cores", lambda: 2)
    if not workers._forks():
        pytest.skip("this platform or process does not fork workers")
    done = workers.draw_each([_pid_and(k) for k in range(6)])
    assert [v for _, v in done] == list(range(6))
    assert os.getpid() not in {pid for pid, _ in done}       # each drawn by a worker
    # Started heaviest first, given back in the order asked.
    weighed = workers.draw_each([_pid_and(k) for k in range(6)], [10, 50, 20, 90, 0, 30])
    assert [v for _, v in weighed] == list(range(6))
    assert os.getpid() not in {pid for pid, _ in weighed}


@pytest.mark.parametrize("weights, in_turn", [([60.0, 5.0], True), ([5.0] * 4, True),
                                              ([40.0, 40.0, 1.0], False)])
def test_jobs_the_cores_would_not_finish_sooner_are_done_in_turn(monkeypatch, weights,
                                                                 in_turn):
    """On two cores a pool saves the sum less the longest job, or half the sum: 5, 10 and
    40.5 ms here, against a pool's own POOL_COST (40 ms). Only the last is worth forking
    for."""
    monkeypatch.setattr(workers, "_cores", lambda: 2)
    if not workers._forks():
        pytest.skip("this platform or process does not fork workers")
    assert workers.POOL_COST == 40.0
    done = workers.draw_each([_pid_and(k) for k in range(len(weights))], weights)
    assert [v for _, v in done] == list(range(len(weights)))
    assert ({pid for pid, _ in done} == {os.getpid()}) == in_turn


def test_a_failing_job_raises_its_own_error_here(monkeypatch):
    monkeypatch.setattr(workers, "_cores", lambda: 2)

    def fails():
        raise AssemblyError("link 3 cannot reach B", link=3)

    with pytest.raises(AssemblyError, match="link 3 cannot reach B"):
        workers.draw_each([_pid_and(0), fails, _pid_and(2)])


def test_no_fork_while_another_thread_runs(monkeypatch):
    monkeypatch.setattr(workers, "_cores", lambda: 2)
    stop = threading.Event()
    other = threading.Thread(target=stop.wait)
    other.start()
    try:
        done = workers.draw_each([_pid_and(k) for k in range(3)])
    finally:
        stop.set()
        other.join()
    assert {pid for pid, _ in done} == {os.getpid()}


@pytest.mark.slow
def test_the_figures_are_the_same_drawn_on_one_core_or_on_two(monkeypatch):
    ex = tarsim.load("velocity-homework-292")
    monkeypatch.setattr(workers, "_cores", lambda: 2)
    shared = [to_svg(p.figure) for p in tarsim.solve(ex).pages]
    monkeypatch.setattr(workers, "_cores", lambda: 1)
    alone = [to_svg(p.figure) for p in tarsim.solve(ex).pages]
    assert len(shared) > 2 and shared == alone
