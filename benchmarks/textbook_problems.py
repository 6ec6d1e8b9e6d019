"""Textbook problems as the books state them: how many asked quantities tarsim takes
directly, and whether each answer is right.

Run:  python benchmarks/textbook_problems.py [--corpus tests/data/textbook]

Each problem (one TOML file) gives the book's wording, its asked quantities and, for
each, the closed form of its answer in SI (Python arithmetic with pi, sqrt, hypot, sin,
cos and radians, never tarsim's own number), and the tarsim exercise that states it.
An asked quantity with no ``name`` is one tarsim cannot yet be asked (its ``why`` says
so); ``field`` reads a part results.json gives beside a name's value (a slowest point's
distance ``along`` the link). Every exercise is solved as the command line solves it
(``tarsim solve --no-pdf``) and each answer is read from results.json and held to its
closed form (relative
``rel``, 1e-9 unless the problem says otherwise: an integral read off a drawing is
held to what its step allows).

It prints each asked quantity as ``stated`` (answered and right), ``wrong``, ``refused``
(tarsim refused the exercise: its one line), ``missing`` (solved, but results.json lacks
the name) or ``not stated``, then the share stated directly. tests/test_textbook_problems.py
holds every stated quantity to its closed form.
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

CORPUS = Path(__file__).resolve().parents[1] / "tests" / "data" / "textbook"

_NAMES = {"pi": math.pi, "sqrt": math.sqrt, "hypot": math.hypot, "sin": math.sin,
          "cos": math.cos, "tan": math.tan, "atan2": math.atan2, "radians": math.radians}


def closed_form(text: str) -> float:
    """The value of a closed form written in the corpus (arithmetic and _NAMES alone)."""
    # The names are globals, so a lambda that names its steps sees them too.
    return float(eval(compile(text, "<closed form>", "eval"),  # noqa: S307 (the corpus's own)
                      {"__builtins__": {}, **_NAMES}))


def _value(results: dict, name: str, position: int | None,
           field: str = "value") -> float | None:
    """``name``'s value (SI) in results.json: of the whole, or at ``position`` (from 1); or
    the part ``field`` results.json gives beside it (a slowest point's ``along``)."""
    where = results.get("quantities", {}) if position is None else \
        results["positions"][position - 1].get("quantities", {})
    entry = where.get(name)
    if entry is None or entry.get(field) is None:     # absent, or null (an infinite peak)
        return None
    return float(entry[field])


def outcomes(path: Path) -> list[tuple[str, str, str]]:
    """Each asked quantity of the problem at ``path``: (what, outcome, detail)."""
    problem = tomllib.loads(path.read_text(encoding="utf-8"))
    asked = problem["asked"]
    stated = [a for a in asked if "name" in a]
    out = [(a["what"], "not stated", a.get("why", "")) for a in asked if "name" not in a]
    if not stated:
        return out
    with tempfile.TemporaryDirectory() as tmp:
        exercise = Path(tmp) / f"{path.stem}.toml"
        exercise.write_text(problem["exercise"]["file"], encoding="utf-8")
        run = subprocess.run([sys.executable, "-m", "tarsim", "solve", str(exercise), "-o",
                              str(Path(tmp) / "out"), "--no-pdf"], capture_output=True,
                             text=True)
        if run.returncode not in (0, 3):
            line = (run.stderr.strip().splitlines() or ["(no message)"])[-1]
            return out + [(a["what"], "refused", line) for a in stated]
        results = json.loads((Path(tmp) / "out" / "results.json").read_text(encoding="utf-8"))
    for a in stated:
        got = _value(results, a["name"], a.get("position"), a.get("field", "value"))
        want = closed_form(a["expected"])
        if got is None:
            out.append((a["what"], "missing", a["name"]))
        elif abs(got - want) <= a.get("rel", 1e-9) * max(abs(want), 1e-300):
            out.append((a["what"], "stated", f"{a['name']} = {got:.6g}"))
        else:
            out.append((a["what"], "wrong", f"{a['name']} = {got:.9g}, the closed form "
                                            f"{want:.9g}"))
    return out


def main(argv: list[str] | None = None) -> None:
    """Print each problem's asked quantities and the share stated directly."""
    args = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    args.add_argument("--corpus", type=Path, default=CORPUS)
    a = args.parse_args(argv)
    counts: dict[str, int] = {}
    for path in sorted(a.corpus.glob("*.toml")):
        print(path.stem)
        for what, outcome, detail in outcomes(path):
            counts[outcome] = counts.get(outcome, 0) + 1
            print(f"  {outcome:<11} {what}: {detail}")
    total = sum(counts.values())
    rest = ", ".join(f"{k} {v}" for k, v in sorted(counts.items()) if k != "stated")
    print(f"\n{counts.get('stated', 0)} of {total} asked quantities stated directly "
          f"({100 * counts.get('stated', 0) / max(total, 1):.0f} %)" +
          (f"; {rest}" if rest else ""))


if __name__ == "__main__":
    main()
