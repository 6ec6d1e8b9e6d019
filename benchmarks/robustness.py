"""Robustness: random inputs of every chapter, and hostile files, through the API and the CLI.

Run:  python benchmarks/robustness.py --cases 100000 --seed 1 --jobs 2 --out /tmp/robustness

Measured on: 2-core AMD EPYC (x86_64), Linux, Python 3.11; see benchmarks/README.md for the
last counts.

The contract: every input either solves to finite numbers that all pass their check against
the analytic solver, and that an independent closed form does not contradict, or is refused
with one TarsimError line that says what and where. Each chapter has a generator in tests/
that makes its files the way textbooks and programs make them, degenerate and malformed
ones among them, and a runner with its own oracle:

- linkages (tests/random_mechanisms.py: four-bars, slider-cranks, slotted levers, six-bars,
  contacts; a four-bar's and a slider-crank's loop equations, tests/closed_forms.py);
- gear trains (tests/random_trains.py: speed ratios from the tooth numbers, exactly);
- cams (tests/random_cams.py: the extremes by a fine evaluation of the laws);
- rotors and engines (tests/random_rotors.py: the residual force and couple);
- loads and flywheels (tests/random_loads.py: the power balance T·ω = Σ F·v);
- drawings for grading (tests/random_drawings.py: SVG as Inkscape, LibreOffice, GeoGebra, a
  CAD program and a hand write it, and hostile SVG).

Each case runs in a worker process, so a case that hangs past ``--timeout`` seconds is killed
and counted. A case is one of

- ok: solved, every check passed, the oracle agrees, every number written finite;
- refused: a TarsimError whose line names the file:line, a link, a point or a position (or
  what a chapter names: a gear, a segment, a mass, a plane, an element), with no number of
  more than 6 significant figures;
- refused-unclear: a TarsimError line that does not;
- refused-valid: a file the oracle answers, refused (gear trains);
- check-failed: solved, but a construction disagrees with the analytic solver;
- wrong: solved and checked, but the chapter's closed form contradicts a printed answer;
- other: anything else: a traceback, a non-finite number, a message of several lines, nan
  or inf in a file written (one case in ``--render-every`` draws its figures; a drawing
  always writes grade.svg), a hang, or a refusal the CLI (one refused case in
  ``--cli-every``) does not give as one ``Error:`` line naming the file, exit 1, nothing
  written. Must be 0, as must wrong.

Counts are printed by chapter and by family; every case that is neither ok nor refused is
saved as ``OUT/<outcome>/<n>.toml`` (or .svg) with ``<n>.txt`` (its line, traceback or failed
checks), and ``OUT/summary.json`` holds the counts and the distinct messages, numbers masked.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing as mp
import platform
import random
import re
import shutil
import sys
import tempfile
import time
from collections import Counter, defaultdict
from multiprocessing.connection import wait
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from random_inputs import CHAPTERS, chapter_module, runner, suffix  # noqa: E402
from random_mechanisms import HOSTILE, Outcome  # noqa: E402

KINDS = ("ok", "refused", "refused-unclear", "refused-valid", "check-failed", "wrong", "other")
"""Every outcome, in the order the table prints them."""

SAVED = ("refused-unclear", "refused-valid", "check-failed", "wrong", "other")
"""The outcomes whose cases are written out for inspection."""


def case_text(seed: int, n: int, chapters: tuple[str, ...]) -> tuple[str, str, str | bytes]:
    """Case ``n`` of the run ``seed``: its chapter, its family and its file, the same on every
    machine."""
    rng = random.Random(f"{seed}:{n}")
    chapter = rng.choices(chapters, weights=[CHAPTERS[c][2] for c in chapters])[0]
    family, text = chapter_module(chapter).generate(rng)
    return chapter, family, text


def cli_refusal(chapter: str, path: Path, folder: Path) -> str | None:
    """What is wrong with how ``tarsim`` refuses the file at ``path``, or None: one
    ``Error:`` line naming the file, exit 1, nothing written."""
    from click.testing import CliRunner

    from tarsim.exercises.cli import cli

    out = folder / f"{path.stem}-out"
    args = (["grade", "crank-shaper", str(path), "-o", str(out)] if chapter == "drawings" else
            ["solve", str(path), "-o", str(out), "--no-pdf"])
    result = CliRunner().invoke(cli, args, catch_exceptions=True)
    err = result.stderr if result.exception is None or isinstance(result.exception,
                                                                  SystemExit) else ""
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        return f"the CLI raised {type(result.exception).__name__}: {result.exception}"
    if result.exit_code == 0:
        return None                     # the CLI answers what the API refused: not a refusal
    why = []
    if result.exit_code != 1:
        why.append(f"exit {result.exit_code}")
    if not (err.startswith("Error: ") and err.count("\n") == 1):
        why.append("not one Error: line")
    if str(path) not in err and path.name not in err:
        why.append("does not name the file")
    if out.exists():
        why.append("wrote its output folder")
    return f"the CLI's refusal: {', '.join(why)}: {err.strip()[:200]}" if why else None


def _worker(conn, folder: str) -> None:
    """Solve the cases sent down ``conn`` one by one and send back each outcome."""
    runners = {c: runner(c) for c in CHAPTERS}
    while True:
        job = conn.recv()
        if job is None:
            return
        n, chapter, text, render, cli = job
        start = time.perf_counter()
        path = Path(folder) / f"case-{n}{suffix(chapter)}"
        got = runners[chapter](text, path, render=render)
        if cli and got.outcome == "refused":
            wrong = cli_refusal(chapter, path, Path(folder))
            if wrong:
                got = Outcome("other", wrong, got.message)
        conn.send((n, got.__dict__, time.perf_counter() - start))


class _Pool:
    """Worker processes, each fed one case at a time, so a hung case can be killed alone."""

    def __init__(self, jobs: int, folder: str):
        self.folder = folder
        self.ctx = mp.get_context("spawn")
        self.workers = [self._start() for _ in range(jobs)]

    def _start(self) -> dict:
        parent, child = self.ctx.Pipe()
        proc = self.ctx.Process(target=_worker, args=(child, self.folder), daemon=True)
        proc.start()
        return {"proc": proc, "conn": parent, "job": None, "since": 0.0}

    def run(self, jobs, timeout: float, render_timeout: float):
        """Yield ``(n, outcome dict, seconds)`` for each job ``(n, text, render)``; a job
        past ``timeout`` seconds (``render_timeout`` for one that draws its figures) is a
        hang."""
        jobs = iter(jobs)
        more = True
        while True:
            for w in self.workers:
                if w["job"] is None and more:
                    job = next(jobs, None)
                    if job is None:
                        more = False
                        break
                    w["job"], w["since"] = job, time.monotonic()
                    w["conn"].send(job)
            busy = [w for w in self.workers if w["job"] is not None]
            if not busy:
                return
            ready = wait([w["conn"] for w in busy], timeout=1.0)
            now = time.monotonic()
            for i, w in enumerate(self.workers):
                if w["job"] is None:
                    continue
                if w["conn"] in ready:
                    try:
                        n, got, seconds = w["conn"].recv()
                    except EOFError:    # the worker died (a crash in C, out of memory)
                        n, got, seconds = w["job"][0], {
                            "outcome": "other", "message": "the worker process died",
                            "detail": f"exit code {w['proc'].exitcode}", "failures": []}, 0.0
                        self.workers[i] = self._start()
                    else:
                        w["job"] = None
                    yield n, got, seconds
                elif now - w["since"] > (render_timeout if w["job"][2] else timeout):
                    n, limit = w["job"][0], render_timeout if w["job"][2] else timeout
                    w["proc"].kill()
                    w["proc"].join()
                    self.workers[i] = self._start()
                    yield n, {"outcome": "other", "message": f"hangs: over {limit:g} s",
                              "detail": "", "failures": []}, now - w["since"]

    def close(self) -> None:
        """Stop every worker."""
        for w in self.workers:
            try:
                w["conn"].send(None)
            except OSError:
                pass
            w["proc"].join(timeout=5)
            if w["proc"].is_alive():
                w["proc"].kill()


def pattern(message: str) -> str:
    """A message with its file, numbers and quoted values masked, to group like ones."""
    m = re.sub(r"\S*case--?\d+\.(toml|svg)(:\d+)*", "FILE", message)
    m = re.sub(r"(?<!\w)'[^']*'(?!\w)", "'…'", m)
    m = re.sub(r"[-+−]?\d[\d,]*(\.\d+)?([eE][-+−]?\d+)?", "#", m)
    return m


class _Progress:
    """tqdm on stderr if it is installed, else a counter line."""

    def __init__(self, total: int):
        self.total, self.done, self.start = total, 0, time.monotonic()
        try:
            from tqdm import tqdm
        except ImportError:
            self.bar = None
        else:
            self.bar = tqdm(total=total, file=sys.stderr, unit="case")
        self.tty = sys.stderr.isatty()

    def update(self, counts: Counter) -> None:
        """One more case done; ``counts`` so far by outcome."""
        self.done += 1
        if self.bar is not None:
            self.bar.update()
            self.bar.set_postfix({k: counts[k] for k in KINDS if counts[k]}, refresh=False)
            return
        step = max(self.total // 100, 1)
        if self.tty or self.done % step == 0 or self.done == self.total:
            rate = self.done / max(time.monotonic() - self.start, 1e-9)
            line = (f"{self.done}/{self.total}  {rate:.1f}/s  "
                    + "  ".join(f"{k}={counts[k]}" for k in KINDS if counts[k]))
            print(("\r" if self.tty else "") + line, end="" if self.tty else "\n",
                  file=sys.stderr, flush=True)

    def close(self) -> None:
        """End the bar or the line."""
        if self.bar is not None:
            self.bar.close()
        elif self.tty:
            print(file=sys.stderr)


def main(argv: list[str] | None = None) -> int:
    """Run the cases, print the counts, save the cases to look at; 1 if any is wrong or
    other."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", type=int, default=300, help="random cases (default 300)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=2, help="worker processes")
    ap.add_argument("--chapters", default=",".join(CHAPTERS),
                    help=f"which chapters, comma-separated (default all: {', '.join(CHAPTERS)})")
    ap.add_argument("--out", default="/tmp/robustness", help="folder for the saved cases")
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds before a case hangs")
    ap.add_argument("--render-timeout", type=float, default=600.0,
                    help="seconds before a case that draws its figures hangs: placing the "
                         "labels of a few dozen figures takes some seconds, more on a "
                         "crowded random mechanism")
    ap.add_argument("--render-every", type=int, default=200,
                    help="draw every N-th case's files to look for nan/inf (0: never)")
    ap.add_argument("--cli-every", type=int, default=20,
                    help="refuse every N-th case through the CLI too (0: never)")
    ap.add_argument("--no-hostile", action="store_true", help="leave out the hostile files")
    args = ap.parse_args(argv)
    chapters = tuple(c.strip() for c in args.chapters.split(",") if c.strip())
    unknown = [c for c in chapters if c not in CHAPTERS]
    if unknown:
        ap.error(f"unknown chapter {', '.join(unknown)}; choose from {', '.join(CHAPTERS)}")

    out = Path(args.out)
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    families: dict[int, tuple[str, str]] = {}
    texts: dict[int, str | bytes] = {}

    def jobs():
        if not args.no_hostile and "linkages" in chapters:
            for k, (cls, variants) in enumerate(HOSTILE.items()):
                for j, (variant, data) in enumerate(variants.items()):
                    n = -(100 * k + j + 1)
                    families[n], texts[n] = ("linkages", f"hostile:{cls}/{variant}"), data
                    yield n, "linkages", data, False, True
        for n in range(args.cases):
            chapter, family, texts[n] = case_text(args.seed, n, chapters)
            families[n] = chapter, family
            render = args.render_every > 0 and n % args.render_every == 0
            cli = args.cli_every > 0 and n % args.cli_every == 0
            yield n, chapter, texts[n], render, cli

    hostile = 0 if args.no_hostile or "linkages" not in chapters else sum(
        map(len, HOSTILE.values()))
    total = args.cases + hostile
    counts: Counter = Counter()
    by_chapter: dict[str, Counter] = defaultdict(Counter)
    by_family: dict[tuple[str, str], Counter] = defaultdict(Counter)
    patterns: dict[str, dict[str, dict]] = defaultdict(dict)
    slowest: list[tuple[float, int]] = []
    progress = _Progress(total)
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="tarsim-robustness-") as folder:
        pool = _Pool(args.jobs, folder)
        try:
            for n, got, seconds in pool.run(jobs(), args.timeout, args.render_timeout):
                outcome = got["outcome"]
                chapter, family = families[n]
                counts[outcome] += 1
                by_chapter[chapter][outcome] += 1
                by_family[chapter, family.split(":")[0]][outcome] += 1
                slowest = sorted(slowest + [(seconds, n)], reverse=True)[:5]
                if outcome != "ok":
                    key = f"{chapter}: {pattern(got['message'])}"
                    seen = patterns[outcome].setdefault(key, {"count": 0, "example": n,
                                                              "message": got["message"]})
                    seen["count"] += 1
                if outcome in SAVED:
                    _save(out / outcome, n, f"{chapter}/{family}", texts[n], got,
                          suffix(chapter))
                texts.pop(n, None)
                progress.update(counts)
        finally:
            pool.close()
            progress.close()
    elapsed = time.monotonic() - started

    kinds = [k for k in KINDS if k in ("ok", "refused", "check-failed", "wrong", "other")
             or counts[k]]
    print(f"\n{sum(counts.values())} cases in {elapsed:.0f} s ({args.jobs} jobs, seed {args.seed})")
    print(f"{'':<28}" + "".join(f"{k:>16}" for k in kinds))
    for chapter in chapters:
        print(f"{chapter:<28}" + "".join(f"{by_chapter[chapter][k]:>16}" for k in kinds))
        for (c, family), got in sorted(by_family.items()):
            if c == chapter:
                print(f"  {family:<26}" + "".join(f"{got[k]:>16}" for k in kinds))
    print(f"{'all':<28}" + "".join(f"{counts[k]:>16}" for k in kinds))
    for outcome in SAVED:
        for key, seen in sorted(patterns[outcome].items(), key=lambda kv: -kv[1]["count"])[:15]:
            print(f"{outcome:<16}{seen['count']:>6}  {key[:150]}  (e.g. {seen['example']})")
    print(f"saved to {out}/")
    summary = {
        "command": " ".join(["python", "benchmarks/robustness.py", *sys.argv[1:]]),
        "machine": f"{platform.machine()}, {platform.system()}, Python "
                   f"{platform.python_version()}",
        "seconds": round(elapsed, 1),
        "slowest": [{"case": n, "seconds": round(s, 2)} for s, n in slowest],
        "counts": {k: counts[k] for k in KINDS},
        "by_chapter": {c: {k: by_chapter[c][k] for k in KINDS} for c in chapters},
        "by_family": {f"{c}/{f}": {k: got[k] for k in KINDS}
                      for (c, f), got in sorted(by_family.items())},
        "patterns": {o: sorted(p.values(), key=lambda s: -s["count"])
                     for o, p in patterns.items()},
    }
    (out / "summary.json").write_text(json.dumps(summary, indent=2, ensure_ascii=False) + "\n",
                                      encoding="utf-8")
    return 1 if counts["other"] or counts["wrong"] else 0


def _save(folder: Path, n: int, family: str, text: str | bytes, got: dict,
          suffix: str) -> None:
    """Write case ``n``'s file and what it gave into ``folder``."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / f"{n}{suffix}").write_bytes(text if isinstance(text, bytes)
                                          else text.encode("utf-8", "surrogatepass"))
    report = [f"family: {family}", f"outcome: {got['outcome']}", f"message: {got['message']}"]
    if got.get("detail"):
        report += ["", got["detail"]]
    if got.get("failures"):
        report += ["", json.dumps(got["failures"], indent=2)]
    (folder / f"{n}.txt").write_text("\n".join(report) + "\n", encoding="utf-8")


if __name__ == "__main__":
    sys.exit(main())
