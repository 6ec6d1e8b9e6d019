"""Where a user waits: the command line's start, a whole solve, and drawing each solution.

Run:  python benchmarks/speed.py [--repeat 5] [--targets]

Medians of ``--repeat`` runs on this machine, stated at the top with its CPU and load.
First the targets, each beside its bound or its peer, in one run (``--targets``: these
alone):

- in a fresh process each: ``tarsim solve four-bar --no-pdf`` (beside the floor, Python
  starting and importing numpy); ``tarsim grade`` of one student's drawing of the
  crank-shaper (made as tests/grading_corpus.py makes a class's, without a PDF);
  ``tarsim solve crank-shaper`` with its PDFs, and the most memory it holds (the largest
  resident set of it and its workers); ``tarsim view crank-shaper`` (720 frames);
- in this process: the bundled figures fitted to A4, laid out once each, beside the
  rule followed on drawn figures (benchmarks/fitting_speed.py);
- in this process: the four-bar's worked page, laid out and written as SVG, beside
  matplotlib drawing the same page (every line, circle and label of it, placed where
  tarsim placed them) and writing its SVG, if matplotlib is installed (it is not a
  dependency of tarsim);
- the sweep against pylinkage is sweep_speed.py's.

Then:

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


def peak_memory(command: list[str]) -> float:
    """The most memory ``command`` holds, in MiB: the largest resident set of it and its
    workers, as the kernel counts it for a child and its own children."""
    probe = ("import resource, subprocess, sys; subprocess.run(sys.argv[1:], check=True, "
             "stdout=subprocess.DEVNULL); "
             "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")
    with tempfile.TemporaryDirectory() as folder:
        out = subprocess.run([sys.executable, "-c", probe, *command], cwd=folder, check=True,
                             capture_output=True, text=True).stdout
    return int(out.split()[-1]) / 1024


def one_drawing(folder: Path) -> Path:
    """A student's drawing of the crank-shaper at its second position, as an exporting
    program writes it (tests/grading_corpus.py, as grading_speed.py makes a class)."""
    from benchmarks.grading_speed import make_class

    folder.mkdir(parents=True)
    make_class(folder, 1, 2)
    return next(iter(sorted(folder.glob("*.svg"))))


def matplotlib_svg(fig) -> bytes:
    """``fig`` (a tarsim Figure) drawn by matplotlib and written as SVG: each path, circle
    and label where tarsim placed it, in its stroke and size."""
    import io

    from matplotlib.figure import Figure as MplFigure
    from matplotlib.patches import Circle as MplCircle

    from tarsim.graphics.figure import STYLES, Circle, Path as FigPath, Text

    mm = 1 / 25.4
    out = MplFigure(figsize=(fig.width * mm, fig.height * mm))
    ax = out.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, fig.width)
    ax.set_ylim(fig.height, 0)
    ax.set_axis_off()
    pt = 72 / 25.4
    for item in fig.items:
        style = STYLES.get(getattr(item, "style", ""))
        colour = style.stroke if style is not None and style.stroke else "#000"
        width = (style.width if style is not None else 0.25) * pt
        if isinstance(item, FigPath):
            xs = [p[0] for p in item.points] + ([item.points[0][0]] if item.closed else [])
            ys = [p[1] for p in item.points] + ([item.points[0][1]] if item.closed else [])
            ax.plot(xs, ys, color=colour, linewidth=width)
        elif isinstance(item, Circle):
            fill = style.fill if style is not None and style.fill else "none"
            ax.add_patch(MplCircle(item.centre, item.radius, edgecolor=colour, facecolor=fill,
                                   linewidth=width))
        elif isinstance(item, Text):
            ax.text(*item.at, item.text + item.sub + item.tail, fontsize=item.size * pt,
                    ha={"start": "left", "end": "right"}.get(item.anchor, "center"),
                    va="center", style="italic" if item.italic else "normal")
    buf = io.BytesIO()
    out.savefig(buf, format="svg")
    return buf.getvalue()


def _sketches(name: str, stem: str | None = None) -> list:
    """The figures of ``name``'s first position, ready to draw (those of ``stem`` alone)."""
    sol = tarsim.solve(tarsim.load(name)).positions[0]
    return [s for s in solution_files._figures(sol) if stem is None or s.stem == stem]


def targets(repeat: int) -> None:
    """Each target of the commands a user waits for, beside its bound or its peer."""
    cli = [sys.executable, "-m", "tarsim"]
    rows = []
    floor = wall([sys.executable, "-c", "import numpy"], repeat)
    four = wall(cli + ["solve", "four-bar", "-o", "out", "--no-pdf"], repeat)
    rows.append(("tarsim solve four-bar --no-pdf", f"{four:.2f} s", "< 0.35 s",
                 f"Python + numpy alone {floor:.2f} s", four < 0.35))
    with tempfile.TemporaryDirectory() as tmp:
        drawing = one_drawing(Path(tmp) / "class")
        graded = wall(cli + ["grade", "crank-shaper", str(drawing), "--position", "2", "-o",
                             "out", "--no-pdf"], repeat)
    rows.append(("tarsim grade, one drawing, no PDF", f"{graded:.2f} s", "< 0.35 s", "",
                 graded < 0.35))
    shaper = wall(cli + ["solve", "crank-shaper", "-o", "out"], repeat)
    rows.append(("tarsim solve crank-shaper, with PDF", f"{shaper:.2f} s", "< 1 s", "",
                 shaper < 1.0))
    memory = peak_memory(cli + ["solve", "crank-shaper", "-o", "out"])
    rows.append(("  its peak memory", f"{memory:.0f} MiB", "< 80 MiB", "", memory < 80))
    from benchmarks.fitting_speed import fitting_rows

    each = fitting_rows(repeat)
    fitted = [sum(r[k] for r in each) for k in
              ("figures", "layouts", "seconds", "drawn_layouts", "drawn_seconds")]
    rows.append((f"{fitted[0]} bundled figures fitted to A4", f"{fitted[1]}", "1 layout each",
                 f"drawn to fit: {fitted[3]} ({fitted[4] * 1e3:.0f} ms to "
                 f"{fitted[2] * 1e3:.0f})", fitted[1] == fitted[0]))
    view = wall(cli + ["view", "crank-shaper", "-o", "page.html"], repeat)
    rows.append(("tarsim view crank-shaper (720 frames)", f"{view:.2f} s", "< 1 s", "",
                 view < 1.0))
    for what, sketches in (("crank-shaper worked page", _sketches("crank-shaper", WORKED.stem)),
                           ("four-bar, its 5 figures", _sketches("four-bar"))):
        page = sum(median_time(lambda s=s: to_svg(s.draw()), repeat) for s in sketches)
        try:
            figs = [s.draw() for s in sketches]
            peer = sum(median_time(lambda f=f: matplotlib_svg(f), repeat) for f in figs)
        except ImportError:
            rows.append((what + ", layout + SVG", f"{page * 1e3:.0f} ms", "≤ ½ matplotlib",
                         "matplotlib is not installed", None))
            continue
        rows.append((what + ", layout + SVG", f"{page * 1e3:.0f} ms", "≤ ½ matplotlib",
                     f"matplotlib {peer * 1e3:.0f} ms (ratio {page / peer:.2f})",
                     page <= 0.5 * peer))
    print(f"\n{'target':<40}{'tarsim':>10}  {'bound':<16}{'peer':<42}met")
    for what, value, bound, peer, met in rows:
        print(f"{what:<40}{value:>10}  {bound:<16}{peer:<42}"
              f"{'-' if met is None else 'yes' if met else 'no'}")
    print("the 3600-position sweep against pylinkage: benchmarks/sweep_speed.py")


def main(argv: list[str] | None = None) -> None:
    """Print the machine, the targets, the end-to-end commands and the per-exercise
    tables."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--targets", action="store_true", help="the targets alone")
    args = ap.parse_args(argv)
    r = args.repeat
    print(machine(r))
    targets(r)
    if args.targets:
        return
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
