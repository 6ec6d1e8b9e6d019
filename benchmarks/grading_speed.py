"""How long a class takes to grade: 300 students' drawings of the crank-shaper through
``tarsim grade CLASS --workers N``, on one process and on two, with feedback PDFs and
without, and what ``grade`` costs a drawing alone.

Run:  python benchmarks/grading_speed.py [--drawings 300] [--repeat 3] [--profile 20]

The class is the one tests/grading_corpus.py makes, of the crank-shaper alone and all asked
its second position (t = 2.34 s), as a course sets one exercise: a fifth each written as
Inkscape, GeoGebra, LibreOffice Draw, a CAD program and a hand write SVG; about half carry a
student's mistake (a few are drawings of the first position), some the space diagram with
its instant centres, some tarsim's worked page.

First ``grade`` alone, in this process, against one solve: each drawing's median over the
runs. Then the command, each run in a fresh process (the bytecode cache warm, as an
installed package has it) and timed end to end from here; inside it, the time in the
grading (``grade_many``: each drawing read and matched, the exercise solved once on each
process, the grades sent back), in the reports (``class_folder``: overlays, pages, PDFs,
grades.csv, summary.svg) and in the writing (``write_folder``); the rest is the start.
Medians of ``--repeat`` runs, the settings taken in turn so a change in the machine's load
falls on each. Printed with them: the machine, its load before and after, and the cores
other processes kept busy during each command (/proc/stat's busy time less the command's
own CPU), for two workers gain only where a core is free. ``--profile N`` adds cProfile's
N costliest functions of one pass of ``grade`` over the class.
"""

from __future__ import annotations

import argparse
import cProfile
import json
import os
import pickle
import pstats
import random
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections import Counter
from multiprocessing.reduction import ForkingPickler
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]

import tarsim  # noqa: E402
from benchmarks.speed import machine  # noqa: E402
from tarsim.constructions.errors import TarsimError  # noqa: E402
from tarsim.exercises.grading.drawing import read_drawing  # noqa: E402
from tarsim.exercises.grading.grade import grade  # noqa: E402
from tarsim.exercises.linkages.solution import solve_positions  # noqa: E402
import grading_corpus as corpus  # noqa: E402

EXERCISE = "crank-shaper"

_TIMED = """
import json, sys, time
from tarsim.exercises import cli
from tarsim.exercises.grading import batch, report
from tarsim.graphics import export
took = {}
def add(phase, t):
    took[phase] = took.get(phase, 0.0) + time.perf_counter() - t
def timed(module, name, phase):
    f = getattr(module, name)
    def run(*a, **k):
        t = time.perf_counter()
        try:
            return f(*a, **k)
        finally:
            add(phase, t)
    setattr(module, name, run)
def timed_iter(module, name, phase):
    f = getattr(module, name)
    def run(*a, **k):
        t = time.perf_counter()
        yield from f(*a, **k)
        add(phase, t)
    setattr(module, name, run)
timed_iter(batch, "grade_many", "grading")
timed(report, "class_folder", "reports")
timed(export, "write_folder", "writing")
try:
    cli.cli.main(sys.argv[2:], prog_name="tarsim", standalone_mode=False)
finally:
    with open(sys.argv[1], "w") as f:
        json.dump(took, f)
"""
"""``tarsim`` itself, with the three phases of a class timed where the CLI calls them."""


def make_class(folder: Path, n: int, position: int) -> Counter:
    """Write ``n`` drawings of the crank-shaper asked at ``position`` (from 1) into
    ``folder``, a fifth by each program; return what they are (sheets, mistakes)."""
    corpus.EXERCISES = ((EXERCISE, 1.0),)      # the corpus mixes three; a class has one
    seen: Counter = Counter()
    tried = Counter()
    for i in range(n):
        program = corpus.PROGRAMS[i % len(corpus.PROGRAMS)]
        while True:                             # the corpus asks either position: keep one
            tried[program] += 1
            if tried[program] > 20 * n:
                raise SystemExit(f"the corpus draws no {EXERCISE} at position {position}")
            rng = random.Random(f"speed/{program}/{tried[program]}")
            svg, key = corpus.make_drawing(rng, program)
            if key["position"] == position:
                break
        (folder / f"{program}-{i:03}.svg").write_text(svg, encoding="utf-8")
        seen[key["sheet"]] += 1
        seen["with a mistake"] += bool(key["mistakes"])
        seen["of another position"] += "position_matched" in key
    return seen


def _busy() -> float:
    """Seconds every core of this machine has been busy since it started (Linux's
    /proc/stat; nan elsewhere)."""
    try:
        with open("/proc/stat") as f:
            ticks = [int(x) for x in f.readline().split()[1:]]
    except (OSError, ValueError):
        return float("nan")
    idle = ticks[3] + ticks[4]                  # idle and waiting on the disk
    return (sum(ticks[:8]) - idle) / os.sysconf("SC_CLK_TCK")


def _children_cpu() -> float:
    """Seconds of CPU this process's finished children (and theirs) have used."""
    t = os.times()
    return t.children_user + t.children_system


def cli_runs(folder: Path, position: int, repeat: int, tmp: Path) -> dict:
    """Each setting's median seconds end to end and in each phase, and the cores other
    processes kept busy meanwhile: {(workers, pdf): {...}}."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    settings = [(w, pdf) for pdf in (False, True) for w in (1, 2)]
    runs: dict = {s: [] for s in settings}

    def run(workers: int, pdf: bool) -> dict:
        out, took = tmp / "graded", tmp / "took.json"
        shutil.rmtree(out, ignore_errors=True)
        cmd = [sys.executable, "-c", _TIMED, str(took), "grade", EXERCISE, str(folder), "-o",
               str(out), "--position", str(position), "--workers", str(workers),
               "--pdf" if pdf else "--no-pdf"]
        busy, mine, t = _busy(), _children_cpu(), time.perf_counter()
        subprocess.run(cmd, check=True, capture_output=True, env=env, cwd=tmp)
        wall = time.perf_counter() - t
        others = (_busy() - busy) - (_children_cpu() - mine)
        phases = {"wall": wall, **json.loads(took.read_text()), "others": others / wall}
        phases["start"] = phases["wall"] - phases["grading"] - phases["reports"] \
            - phases["writing"]
        return phases
    run(1, False)                               # writes the bytecode cache
    for _ in range(repeat):
        for s in settings:
            runs[s].append(run(*s))
    return {s: {k: statistics.median(r[k] for r in rs) for k in rs[0]}
            for s, rs in runs.items()}


def one_drawing(drawing: Path, position: int, repeat: int, tmp: Path) -> float:
    """Median seconds of ``tarsim grade`` of one drawing, with its PDF, end to end."""
    cmd = [sys.executable, "-m", "tarsim.exercises", "grade", EXERCISE, str(drawing), "-o",
           str(tmp / "one"), "--position", str(position)]
    times = []
    for _ in range(repeat + 1):
        shutil.rmtree(tmp / "one", ignore_errors=True)
        t = time.perf_counter()
        subprocess.run(cmd, check=True, capture_output=True, cwd=tmp)
        times.append(time.perf_counter() - t)
    return statistics.median(times[1:])


def grade_alone(drawings: list[Path], position: int, repeat: int):
    """Each drawing's median seconds in ``grade`` against one solve and in ``read_drawing``
    (the part that reads its SVG), its grade (its one-line refusal if refused), and the
    solve's seconds."""
    ex = tarsim.load(EXERCISE)
    t = time.perf_counter()
    positions = solve_positions(ex)
    solve = time.perf_counter() - t

    def graded(d: Path):
        try:
            return grade(ex, d, position - 1, positions)
        except TarsimError as e:
            return str(e)
    graded(drawings[0])                         # its modules imported, untimed
    took: dict = {(job, d): [] for job in (graded, read_drawing) for d in drawings}
    grades = {}
    for _ in range(repeat):
        for d in drawings:
            for job in (graded, read_drawing):
                t = time.perf_counter()
                try:
                    out = job(d)
                except TarsimError:
                    out = None
                took[job, d].append(time.perf_counter() - t)
                if job is graded:
                    grades[d] = out
    med = {k: statistics.median(v) for k, v in took.items()}
    return ({d: med[graded, d] for d in drawings}, {d: med[read_drawing, d] for d in drawings},
            grades, solve)


def sent_back(grades: dict) -> tuple[float, float, float]:
    """What a worker's grades cost on their way back to the main process, as
    ``ProcessPoolExecutor`` sends them: mean KB, and ms to pickle and to unpickle one."""
    results = [(str(d), g) for d, g in grades.items()]
    t = time.perf_counter()
    data = [bytes(ForkingPickler.dumps(r)) for r in results]
    dumps = time.perf_counter() - t
    t = time.perf_counter()
    back = [pickle.loads(b) for b in data]      # kept, as the main process keeps them
    loads = time.perf_counter() - t
    del back
    n = len(results)
    return sum(map(len, data)) / n / 1e3, 1e3 * dumps / n, 1e3 * loads / n


def profile(drawings: list[Path], position: int, top: int) -> None:
    """The ``top`` functions of one pass of ``grade`` over the class as cProfile finds them,
    by their own time and by their time with what they call."""
    ex = tarsim.load(EXERCISE)
    positions = solve_positions(ex)
    prof = cProfile.Profile()
    prof.enable()
    for d in drawings:
        try:
            grade(ex, d, position - 1, positions)
        except TarsimError:
            pass
    prof.disable()
    for key in ("tottime", "cumulative"):
        print(f"\ncProfile of grade over the class, by {key}:")
        pstats.Stats(prof, stream=sys.stdout).strip_dirs().sort_stats(key).print_stats(top)


def main(argv: list[str] | None = None) -> None:
    """Print the class's times through the CLI and ``grade``'s cost a drawing."""
    args = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    args.add_argument("--drawings", type=int, default=300)
    args.add_argument("--position", type=int, default=2)
    args.add_argument("--repeat", type=int, default=3)
    args.add_argument("--profile", type=int, default=0, metavar="N")
    a = args.parse_args(argv)
    print(machine(a.repeat), f"(1, 5, 15 min: {', '.join(f'{x:.2f}' for x in os.getloadavg())})")
    with tempfile.TemporaryDirectory() as name:
        tmp = Path(name)
        folder = tmp / "class"
        folder.mkdir()
        seen = make_class(folder, a.drawings, a.position)
        drawings = sorted(folder.glob("*.svg"))
        n = len(drawings)
        print(f"class: {n} drawings of the {EXERCISE} at position {a.position}, "
              + ", ".join(f"{v} {k}" for k, v in sorted(seen.items())))
        each, reading, grades, solve = grade_alone(drawings, a.position, a.repeat)
        ms = sorted(1e3 * t for t in each.values())
        scores = [g.score for g in grades.values() if not isinstance(g, str)]
        print(f"\ngrade alone, against one solve ({1e3 * solve:.0f} ms): {n - len(scores)} "
              f"refused, mean score {statistics.fmean(scores):.1f} %")
        print(f"  ms a drawing: median {statistics.median(ms):.1f}, mean "
              f"{statistics.fmean(ms):.1f}, 90th percentile {ms[9 * n // 10]:.1f}, "
              f"most {ms[-1]:.1f}; of it reading the SVG (read_drawing), mean "
              f"{1e3 * statistics.fmean(reading.values()):.1f}")
        by = {p: [1e3 * t for d, t in each.items() if d.name.startswith(p)]
              for p in corpus.PROGRAMS}
        print("  mean ms by program: " + ", ".join(
            f"{p} {statistics.fmean(v):.1f}" for p, v in by.items() if v))
        kb, dumps, loads = sent_back(grades)
        print(f"  a grade sent back from a worker: {kb:.1f} KB, {dumps:.2f} ms to pickle "
              f"there, {loads:.2f} ms to unpickle in the main process")
        print(f"\ntarsim grade of one drawing with its PDF, end to end: "
              f"{one_drawing(drawings[0], a.position, a.repeat, tmp):.2f} s")
        print(f"\ntarsim grade of the class of {n} (s; drawings/s end to end and grading):")
        print("| workers | PDFs | end to end | start | grading | reports | writing "
              "| drawings/s | grading drawings/s | others' cores |")
        print("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
        med = cli_runs(folder, a.position, a.repeat, tmp)
        for (workers, pdf), m in med.items():
            print(f"| {workers} | {'yes' if pdf else 'no'} | {m['wall']:.2f} | "
                  f"{m['start']:.2f} | {m['grading']:.2f} | {m['reports']:.2f} | "
                  f"{m['writing']:.2f} | {n / m['wall']:.0f} | {n / m['grading']:.0f} | "
                  f"{m['others']:.2f} |")
        for pdf in (False, True):
            one, two = med[(1, pdf)], med[(2, pdf)]
            print(f"two workers over one, {'with' if pdf else 'without'} PDFs: end to end "
                  f"{two['wall'] / one['wall']:.2f}, grading {two['grading'] / one['grading']:.2f}"
                  f", reports {two['reports'] / one['reports']:.2f}")
        if a.profile:
            profile(drawings, a.position, a.profile)
    print(f"\nload after: {', '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
