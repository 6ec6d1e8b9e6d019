"""Timing and the machine: medians of repeated runs, and the line that says where they ran."""

from __future__ import annotations

import os
import platform
import statistics
import time
from collections.abc import Callable

__all__ = ["median_time", "machine"]


def median_time(fn: Callable[[], object], repeat: int = 200) -> float:
    """Median wall time of ``fn()`` in microseconds (a median shrugs off a stray slow run)."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times) * 1e6


def machine() -> str:
    """The CPU model, cores, Python and the load average: what a timing means depends on it."""
    model = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            model = next(line.split(":", 1)[1].strip() for line in f
                         if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    load = ", ".join(f"{x:.2f}" for x in os.getloadavg()) if hasattr(os, "getloadavg") else "?"
    return (f"{model}, {os.cpu_count()} cores, {platform.system()}, "
            f"{platform.python_implementation()} {platform.python_version()}, "
            f"load average {load}")
