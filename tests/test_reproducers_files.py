"""Reproducers of faults in reading files and writing folders, each held to what it must do.

``tests/reproducers/*.sh`` are the scripts that first showed them; each test below builds
the same input, or kills the same run, in Python, and then runs the script itself where
the tools it needs are present.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import sys
import time
import tracemalloc
from pathlib import Path

import pytest
from click.testing import CliRunner

import tarsim
from tarsim.constructions.errors import InputError
from tarsim.exercises.catalog import bundled
from tarsim.exercises.cli import cli
from tarsim.exercises.toml_depth import MOST_DEPTH
from tarsim.graphics.export import MANIFEST

ROOT = Path(__file__).parent.parent
HERE = Path(__file__).parent / "reproducers"
TARSIM = f"{sys.executable} -m tarsim"
"""The command as the scripts' ``T``: this Python's tarsim, wherever its PATH points."""

STAGING = re.compile(r"\.tarsim-[a-z0-9_]{8}")


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args], prog_name="tarsim",
                              catch_exceptions=False)


def script(name: str, *args: str, tmp_path: Path) -> str:
    """Run the reproducer script ``name`` from the project's root, its temporary folders
    under ``tmp_path``; its output."""
    env = {**os.environ, "T": TARSIM, "TMPDIR": str(tmp_path)}
    done = subprocess.run(["sh", str(HERE / name), *args], cwd=ROOT, env=env, check=False,
                          capture_output=True, text=True, timeout=300)
    return done.stdout + done.stderr


# ----- dos-toml-deep-dotted-key.sh --------------------------------------------------------------
DEPTH = 50_000


def test_dos_toml_deep_dotted_key(tmp_path):
    """The bundled four-bar with a last line whose key is 50,000 parts deep (100 kB): tomllib,
    quadratic in a dotted key, ran past 120 s and gigabytes on it (8,000 parts: 2.8 s and
    414 MB). It is refused before tomllib reads it, at the dot that takes it past
    MOST_DEPTH: the key lies in the file's last table, [h] parts deep, so the dot after its
    (MOST_DEPTH − h)th part, at column 2 (MOST_DEPTH − h) of the line after the file's last."""
    four_bar = bundled()["four-bar"].read_text(encoding="utf-8")
    path = tmp_path / "deep-dotted.toml"
    path.write_text(four_bar + "\n" + ".".join(["a"] * DEPTH) + " = 1\n", encoding="utf-8")
    assert path.stat().st_size > 100_000
    line = four_bar.count("\n") + 2
    h = re.findall(r"^\[([^\]]+)\]", four_bar, re.M)[-1].count(".") + 1
    column = 2 * (MOST_DEPTH - h)
    says = (f"{path}:{line}:{column}: nests arrays or tables too deeply to read: past "
            f"{MOST_DEPTH} keys, tables and arrays deep (an exercise needs 4)")
    tracemalloc.start()
    start = time.perf_counter()
    with pytest.raises(InputError) as info:
        tarsim.load(str(path))
    took = time.perf_counter() - start
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert str(info.value) == says
    # A linear pass over 100 kB takes milliseconds; a second leaves room for a busy machine.
    # The text is 100 kB; tomllib's nested tables for 8,000 parts alone took 414 MB.
    assert took < 1.0 and peak < 10_000_000, (took, peak)

    result = run("check", path)
    assert result.exit_code == 1 and result.stderr == f"Error: {says}\n", result.output

    if not (shutil.which("timeout") and os.access("/usr/bin/time", os.X_OK)):
        return                                    # the script's tools are not here
    out = script("dos-toml-deep-dotted-key.sh", str(DEPTH), tmp_path=tmp_path)
    assert re.search(rf"^Error: .*deep-dotted\.toml:{line}:{column}: nests arrays or tables too"
                     " deeply", out, re.M), out
    m, s = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\d+):([\d.]+)",
                     out).groups()
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", out).group(1))
    # The whole command, Python and numpy started: about 0.3 s and 35 MB here.
    assert 60 * int(m) + float(s) < 10 and rss < 300_000, out


# ----- kill-in-commit.sh ------------------------------------------------------------------------
KILLED = """
import os, signal, sys
from tarsim.exercises.cli import cli
out, n, seen = os.path.realpath(sys.argv[1]), int(sys.argv[2]), []
real = os.replace
def replace(src, dst, *args, **kwargs):
    if os.path.realpath(os.path.dirname(os.fspath(dst))) == out:
        seen.append(dst)
        if len(seen) == n:
            os.kill(os.getpid(), signal.SIGKILL)
    return real(src, dst, *args, **kwargs)
os.replace = replace
cli(["solve", "crank-shaper", "-o", out, "--no-pdf"])
"""
"""The commit of ``tarsim solve crank-shaper`` killed (SIGKILL, which nothing can catch) at
its n-th rename into the folder, as strace's fault injection kills it."""


def names(folder: Path) -> set[str]:
    return {p.name for p in folder.iterdir()}


@pytest.mark.slow
def test_kill_in_commit(tmp_path):
    """A run killed during its commit's renames leaves part of the new solution beside the
    old one, and its staging folder; the next run into the folder leaves the new solution
    whole, as a run into an empty folder writes it, the user's file kept, and no staging
    folder."""
    out, fresh = tmp_path / "kill-commit", tmp_path / "fresh"
    assert run("solve", "four-bar", "-o", out, "--no-pdf").exit_code == 0
    (out / "mine.txt").write_text("mine\n", encoding="utf-8")
    old = names(out)
    # The 8th rename: the manifest naming old and new, then 7 of crank-shaper's 12 files.
    killed = subprocess.run([sys.executable, "-c", KILLED, str(out), "8"], check=False,
                            capture_output=True, timeout=300)
    assert killed.returncode == -signal.SIGKILL, killed.stderr
    left = names(out)
    staged = {n for n in left if STAGING.fullmatch(n)}
    assert len(staged) == 1 and old <= left       # killed mid-commit: the old beside the new

    assert run("solve", "crank-shaper", "-o", out, "--no-pdf").exit_code == 0
    assert run("solve", "crank-shaper", "-o", fresh, "--no-pdf").exit_code == 0
    after = {p.name: p.read_bytes() for p in out.iterdir()}
    assert not {n for n in after if STAGING.fullmatch(n)}
    assert after.pop("mine.txt") == b"mine\n"
    assert after == {p.name: p.read_bytes() for p in fresh.iterdir()}


@pytest.mark.slow
def test_kill_in_commit_script(tmp_path):
    """The script itself: strace kills the solve at the commit's 12th rename(2)."""
    if shutil.which("strace") is None:
        pytest.skip("kill-in-commit.sh needs strace (apt-get install strace)")
    out = script("kill-in-commit.sh", tmp_path=tmp_path)
    killed, _, rerun = out.partition("after a rerun:")
    if not any(STAGING.fullmatch(name) for name in killed.split()):
        pytest.skip(f"strace could not kill the run here: {out.strip().splitlines()[-1:]}")
    assert rerun.split() == [MANIFEST], out
