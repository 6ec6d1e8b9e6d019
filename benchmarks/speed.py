"""Where a user waits: the command line's start, a whole solve, and drawing each solution.

Run:  python benchmarks/speed.py [--repeat 5]

Medians of ``--repeat`` runs on this machine, stated at the top with its CPU and load:

- end to end, each in a fresh process (the start of Python and the imports included, with
  the bytecode cache warm, as an installed package has it): ``tarsim --help``,
  ``tarsim solve four-bar --no-pdf``, and ``tarsim solve NAME`` with its PDFs for every
  bundled exercise;
- in one process, for every bundled exercise: the solve (constructions and checks), the
  drawing of its figures with each one's SVG on every core and on one (their ratio, taken
  in the same run), solution.svg with steps.md and results.json, and every file written
  with its PDF after the solve as ``tarsim solve`` makes them (each figure drawn, written
  as SVG and drawn as PDF by one job);
- each worked page (space diagram, polygons, table): its layout and SVG after the solve,
  and its PDF.
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
from tarsim.exercises.linkages import solution_files  # noqa: E402
from tarsim.constructions.linkages.velocity_polygon import WORKED  # noqa: E402
from tarsim.exercises.catalog import bundled, everything  # noqa: E402
from tarsim.graphics import workers  # noqa: E402
from tarsim.graphics.export import figure_pdf  # noqa: E402
from tarsim.graphics.svg import to_svg  # noqa: E402


def machine(repeat: int) -> str:
    """One line: CPU, cores, Python, load, and what the figures are medians of."""
    cpu = platform.machine()
    try:
        cpu = next(line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo")
                   if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    return (f"{cpu}, {workers._cores()} cores, {platform.system()}, Python "
            f"{platform.python_version()}, load {load:.2f}; medians of {repeat}")


def median_time(job, repeat: int) -> float:
    """Median seconds of ``job()`` over ``repeat`` runs."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        job()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def wall(command: list[str], repeat: int) -> float:
    """Median wall time of ``command`` in a fresh process, in seconds, after one warm-up run
    that writes the bytecode cache (this shell may forbid it: the children may not)."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    with tempfile.TemporaryDirectory() as folder:
        def run():
            subprocess.run(command, cwd=folder, check=True, stdout=subprocess.DEVNULL, env=env)
        run()
        return median_time(run, repeat)


def in_process(name: str, repeat: int) -> dict[str, float]:
    """Median seconds to solve ``name``, draw its figures with their SVG (every core, one
    core), make the rest of its text files, and make and write every file with PDFs."""
    ex = tarsim.load(name)
    worked = tarsim.solve(ex)
    out = {"solve": median_time(lambda: tarsim.solve(ex), repeat)}

    def draw():
        return solution_files.solve_worked(ex).pages     # the solve again, then the drawing
    out["draw"] = median_time(draw, repeat) - out["solve"]
    cores = workers._cores
    workers._cores = lambda: 1
    try:
        out["draw, 1 core"] = median_time(draw, repeat) - out["solve"]
    finally:
        workers._cores = cores
    out["svg"] = median_time(worked.files, repeat)      # the figures are drawn by now
    with tempfile.TemporaryDirectory() as folder:
        def write():
            solution_files.solve_worked(ex).write(Path(folder) / "out", pdf=True)
        out["all + pdf"] = median_time(write, repeat) - out["solve"]
    return out


def worked_pages(name: str, repeat: int) -> list[tuple[str, float, float]]:
    """Each worked page of ``name``: (position, layout + SVG seconds, PDF seconds)."""
    worked = tarsim.solve(tarsim.load(name))
    out = []
    for sol in worked.positions:
        for sketch in solution_files._figures(sol):
            if sketch.stem != WORKED.stem:
                continue
            layout = median_time(lambda s=sketch: to_svg(s.draw()), repeat)
            fig = sketch.draw()
            pdf = median_time(lambda f=fig: figure_pdf(f.sheets or [f]), repeat)
            out.append((sol.position.label if sol.position else "", layout, pdf))
    return out


def main(argv: list[str] | None = None) -> None:
    """Print the machine, the end-to-end commands and the per-exercise tables."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args(argv)
    r = args.repeat
    print(machine(r))
    cli = [sys.executable, "-m", "tarsim"]
    print(f"\n{'end to end, fresh process':<40}{'s':>8}")
    print(f"{'tarsim --help':<40}{wall(cli + ['--help'], r):>8.2f}")
    print(f"{'tarsim solve four-bar --no-pdf':<40}"
          f"{wall(cli + ['solve', 'four-bar', '-o', 'out', '--no-pdf'], r):>8.2f}")
    for name in bundled():
        print(f"{'tarsim solve ' + name:<40}{wall(cli + ['solve', name, '-o', 'out'], r):>8.2f}")
    # The other chapters: the loaded mechanisms' forces, gear trains, cams, balancing.
    for name in [n for n in everything() if n not in bundled()]:
        print(f"{'tarsim solve ' + name:<40}{wall(cli + ['solve', name, '-o', 'out'], r):>8.2f}")
    print(f"{'tarsim sweep crank-shaper-forces':<40}"
          f"{wall(cli + ['sweep', 'crank-shaper-forces', '-o', 'out'], r):>8.2f}")

    heads = ("solve", "draw", "draw, 1 core", "svg", "all + pdf")
    print(f"\n{'in one process (s)':<26}" + "".join(f"{h:>14}" for h in heads))
    for name in bundled():
        t = in_process(name, r)
        print(f"{name:<26}" + "".join(f"{t[h]:>14.3f}" for h in heads))

    print(f"\n{'worked page':<48}{'layout + SVG (ms)':>18}{'PDF (ms)':>10}")
    for name in bundled():
        for where, layout, pdf in worked_pages(name, r):
            print(f"{(name + ' ' + where):<48}{layout * 1e3:>18.0f}{pdf * 1e3:>10.0f}")


if __name__ == "__main__":
    main()
