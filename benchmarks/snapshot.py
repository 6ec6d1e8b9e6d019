"""Solve every bundled exercise in English and Persian into a folder, and compare two such
folders file by file: what a change to the code did to what users see.

A restructuring must leave every results.json, steps.md, SVG and the terminal's lines as
they were; a fix shows as the files it changes, to be named. Take a snapshot before the
change, another after, and compare:

    python benchmarks/snapshot.py take /tmp/before
    python benchmarks/snapshot.py take /tmp/after
    python benchmarks/snapshot.py compare /tmp/before /tmp/after

Each solve runs as the command line runs it (``tarsim solve <id> --no-pdf --lang …``), two
at a time; its exit status and output are kept beside its folder (``<id>-<lang>.log``),
with the folder's own path taken out so that two snapshots compare.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

LANGUAGES = ("en", "fa")
SKIPPED = {".tarsim-manifest.json"}
"""Files that record where and when a solve wrote, not what it found."""


def take(out: Path, tarsim: str) -> int:
    """Solve every bundled exercise in each language into ``out``; the number of solves."""
    from tarsim.exercises.catalog import everything

    out.mkdir(parents=True, exist_ok=True)
    jobs = [(i, lang) for i in everything() for lang in LANGUAGES]

    def solve(job: tuple[str, str]) -> None:
        exercise_id, lang = job
        folder = out / f"{exercise_id}-{lang}"
        run = subprocess.run([tarsim, "solve", exercise_id, "--no-pdf", "--lang", lang,
                              "-o", str(folder)], capture_output=True, text=True)
        log = f"exit {run.returncode}\n{run.stdout}\n{run.stderr}".replace(str(folder), "OUT")
        (out / f"{exercise_id}-{lang}.log").write_text(log, encoding="utf-8")

    with ThreadPoolExecutor(2) as pool:
        list(pool.map(solve, jobs))
    return len(jobs)


def compare(a: Path, b: Path) -> list[str]:
    """The files present in one snapshot alone, and those that differ byte for byte."""
    def files(root: Path) -> set[Path]:
        return {p.relative_to(root) for p in root.rglob("*")
                if p.is_file() and p.name not in SKIPPED}

    ours, theirs = files(a), files(b)
    out = [f"only in {a if p in ours else b}: {p}" for p in sorted(ours ^ theirs)]
    out += [f"differs: {p}" for p in sorted(ours & theirs)
            if (a / p).read_bytes() != (b / p).read_bytes()]
    return out


def main(argv: list[str] | None = None) -> int:
    """Take a snapshot, or compare two; the exit status is 1 if they differ."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    t = sub.add_parser("take", help="solve every bundled exercise into FOLDER")
    t.add_argument("folder", type=Path)
    t.add_argument("--tarsim", default=shutil.which("tarsim") or "tarsim",
                   help="the tarsim command to run (default: the one on PATH)")
    c = sub.add_parser("compare", help="compare two snapshots")
    c.add_argument("before", type=Path)
    c.add_argument("after", type=Path)
    args = parser.parse_args(argv)
    if args.command == "take":
        print(f"{take(args.folder, args.tarsim)} solves in {args.folder}")
        return 0
    found = compare(args.before, args.after)
    print("\n".join(found + [f"{len(found)} differences"]))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
