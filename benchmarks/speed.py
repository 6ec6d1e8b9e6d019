"""Where a user waits: the command line's start, a whole solve, and drawing each solution.

Run:  python benchmarks/speed.py [--repeat 3]

Medians of ``--repeat`` runs on this machine, stated at the top with its load:

- ``tarsim --help`` and ``tarsim solve four-bar --no-pdf``, end to end, each in a fresh
  process (the start of Python and the imports included);
- for every bundled exercise, the solve (constructions and checks, no figures) and then
  the drawing of every figure and file (``WorkedSolution.files()``), in one process.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import tarsim  # noqa: E402
from tarsim.exercises.catalog import bundled  # noqa: E402


def wall(command: list[str], repeat: int) -> float:
    """Median wall time of ``command`` in a fresh process, in seconds."""
    times = []
    with tempfile.TemporaryDirectory() as folder:
        for _ in range(repeat):
            t0 = time.perf_counter()
            subprocess.run(command, cwd=folder, check=True, stdout=subprocess.DEVNULL)
            times.append(time.perf_counter() - t0)
    return statistics.median(times)


def in_process(name: str, repeat: int) -> tuple[float, float]:
    """Median seconds to solve ``name`` and then to draw its files."""
    solve, draw = [], []
    for _ in range(repeat):
        t0 = time.perf_counter()
        worked = tarsim.solve(tarsim.load(name))
        t1 = time.perf_counter()
        worked.files()
        draw.append(time.perf_counter() - t1)
        solve.append(t1 - t0)
    return statistics.median(solve), statistics.median(draw)


def main(argv: list[str] | None = None) -> None:
    """Print the machine, the end-to-end commands and the per-exercise table."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args(argv)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(f"{platform.machine()}, {platform.system()}, Python {platform.python_version()}, "
          f"{os.cpu_count()} cores, load {load:.2f}; medians of {args.repeat}")
    tarsim_cli = [sys.executable, "-m", "tarsim"]
    print(f"tarsim --help                     {wall(tarsim_cli + ['--help'], args.repeat):6.2f} s")
    solve = tarsim_cli + ["solve", "four-bar", "-o", "out", "--no-pdf"]
    print(f"tarsim solve four-bar --no-pdf    {wall(solve, args.repeat):6.2f} s")
    print(f"\n{'exercise':<26}{'solve (s)':>10}{'draw (s)':>10}")
    for name in bundled():
        s, d = in_process(name, args.repeat)
        print(f"{name:<26}{s:>10.3f}{d:>10.2f}")


if __name__ == "__main__":
    main()
