"""How long a class takes to grade: one drawing end to end, and a folder of generated
drawings graded on one process and on two, in the same run.

Run:  python benchmarks/grading_speed.py [--drawings 200] [--repeat 3]

The drawings are tarsim's own crank-shaper polygons at t = 2.34 s, turned, mirrored, moved
and with a Coriolis component reversed at random (``tests/drawings.py``), as the tests make
them. Medians of ``--repeat`` runs; the machine and its load are printed first.
"""

from __future__ import annotations

import argparse
import random
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import tarsim  # noqa: E402
from benchmarks.speed import machine  # noqa: E402
from tarsim.exercises.grading.batch import grade_many  # noqa: E402
from tarsim.exercises.solution import solve_positions  # noqa: E402
from tests.drawings import Style, drawing  # noqa: E402


def main(argv: list[str] | None = None) -> None:
    """Print the single drawing's time and the class's on one process and two."""
    args = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    args.add_argument("--drawings", type=int, default=200)
    args.add_argument("--repeat", type=int, default=3)
    a = args.parse_args(argv)
    print(machine(a.repeat))
    sol = solve_positions(tarsim.load("crank-shaper"))[1]
    rng = random.Random(1)
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp) / "class"
        folder.mkdir()
        for k in range(a.drawings):
            style = Style(kind=rng.choice("va"), turn=rng.uniform(-180, 180),
                          mirror=rng.random() < 0.3, moved={"B": (rng.uniform(-3, 3), 0.0)},
                          writer=rng.choice(["inkscape", "geogebra"]))
            (folder / f"s{k:03}.svg").write_text(drawing(sol, style), encoding="utf-8")
        one = folder / "s000.svg"
        cli = [sys.executable, "-m", "tarsim.exercises", "grade", "crank-shaper"]

        def wall(args):
            t = time.perf_counter()
            subprocess.run(cli + args, check=True, capture_output=True)
            return time.perf_counter() - t
        single = statistics.median(wall([str(one), "-o", f"{tmp}/one", "--position", "2"])
                                   for _ in range(a.repeat))
        print(f"tarsim grade, one drawing, end to end: {single:.2f} s")
        drawings = sorted(folder.glob("*.svg"))
        for workers in (1, 2):
            times = []
            for _ in range(a.repeat):
                t = time.perf_counter()
                for _ in grade_many("crank-shaper", drawings, 1, workers):
                    pass
                times.append(time.perf_counter() - t)
            med = statistics.median(times)
            print(f"{a.drawings} drawings on {workers} process(es): {med:.2f} s "
                  f"({1e3 * med / a.drawings:.1f} ms a drawing)")


if __name__ == "__main__":
    main()
