"""Write ``report.md`` and its plots: the method table, the error-against-time plots, the suite,
and every other chapter's rows.

:func:`write_report` is what ``tarsim bench`` calls. It runs the four parts, each
behind a progress bar the caller may give, and writes ``<out>/report.md`` with the
plots in ``<out>/report/``, linked from it.
"""

from __future__ import annotations

import contextlib
import datetime
import math
import time
from collections.abc import Callable
from pathlib import Path

import mpmath
import numpy

from .chapter_report import STUDIES, render_chapters, run_chapters
from .methods import cases, method_table
from .mpref import DPS
from .stiff import BOUND_ULPS, run_case, stiff_cases
from .timing import machine
from .tradeoffs import newton_tolerance, pen_precision, precision, shapely_circles, sweep_step

__all__ = ["write_report", "Bar"]

Bar = Callable[[int, str], contextlib.AbstractContextManager]
"""``bar(length, label)``: a context manager whose value has ``update(n)`` (click's
progressbar is one)."""


class _Quiet:
    def update(self, n: int) -> None:
        """Nothing to show."""


def _no_bar(length: int, label: str) -> contextlib.AbstractContextManager:
    return contextlib.nullcontext(_Quiet())


def _e(x: float) -> str:
    """An error or a conditioning in a table: 1.2e-15, 0 for exact, — for none."""
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "—"
    if x == 0:
        return "0"
    return f"{x:.1e}"


def write_report(out: Path, *, quick: bool = False, bar: Bar | None = None) -> Path:
    """Run the benchmark and write ``out/report.md`` and ``out/report/*.svg``.

    ``quick`` runs the bundled exercises at their stated positions only, the ends of
    each stiff sweep and fewer plot points: seconds, for CI and tests.
    """
    bar = bar or _no_bar
    out = Path(out)
    plots = out / "report"
    plots.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    started = machine()

    all_cases = cases(quick)
    with bar(len(all_cases), "methods vs references") as b:
        rows = method_table(all_cases, repeat=1 if quick else 3, progress=b.update)

    suite = stiff_cases(quick)
    stiff_rows = []
    with bar(len(suite), "stiff and extreme cases") as b:
        for case in suite:
            stiff_rows += run_case(case)
            b.update(1)

    studies = []
    runs = [lambda: pen_precision(plots, samples=4000 if quick else 20000),
            lambda: newton_tolerance(plots), lambda: shapely_circles(plots, quick=quick),
            lambda: sweep_step(plots, quick=quick), lambda: precision(plots, quick=quick)]
    with bar(len(runs), "error against run time") as b:
        for run in runs:
            studies.append(run())
            b.update(1)

    with bar(len(STUDIES), "every chapter's extremes") as b:
        chapters = run_chapters(plots, quick=quick, progress=b.update)

    text = _render(rows, stiff_rows, studies, quick=quick, machine_line=started,
                   seconds=time.perf_counter() - t0, plots=plots.relative_to(out))
    text += "\n" + "\n".join(render_chapters(chapters, plots.relative_to(out))) + "\n"
    path = out / "report.md"
    path.write_text(text, encoding="utf-8")
    return path


def _render(rows, stiff_rows, studies, *, quick, machine_line, seconds, plots) -> str:
    lines = [
        "# tarsim bench: error against run time, and the stiff and extreme cases",
        "",
        f"Written by `tarsim bench{' --quick' if quick else ''}` on "
        f"{datetime.date.today().isoformat()}, in {seconds:.0f} s.",
        f"Machine: {machine_line}; numpy {numpy.__version__}, mpmath {mpmath.__version__}.",
        "Times are medians of repeated runs in one process"
        f"{' (quick: one run each)' if quick else ' (3 runs per case)'}.",
        "",
        "## 1. Each method against the analytic solver and a 50-digit reference",
        "",
        "Every bundled exercise (`tarsim list`) at its stated positions"
        + ("" if quick else ", and at every 30° of its input's turn") +
        ", through every method that applies. Each number read off a construction is "
        "measured against the float64 analytic solver (what `tarsim solve` checks against) "
        f"and against an independent mpmath reference: Newton on the loop equations at {DPS} "
        "digits, derivatives by differences of converged solutions, good to 50 digits or "
        "more (some 40 within 1e-9 rad of a toggle; `benchmarks/bench/mpref.py`). It "
        "solves the mechanism exactly as the file's float64 numbers state it. Errors are "
        "relative as `tarsim solve` "
        "measures them: a joint or a centre to the mechanism's size (a far centre to its "
        "distance, one at infinity by angle), a vector or a rate to the larger of itself "
        "and the input's, the time ratio and stroke to themselves. *Conditioning* is the "
        "construction's own, compounded along the acts a number rests on (1 is a clean "
        "cut, near 0 a near-tangent or near-parallel one). The time is one run of the "
        "method on an assembled mechanism (position by compass: the assembly itself; the "
        "limit positions: from the file's mechanism).",
        "",
        "| method | numbers (positions) | refused | largest vs solver | median vs solver "
        "| largest vs mpmath | median vs mpmath | solver vs mpmath (largest) "
        "| worst conditioning | median conditioning | median time (µs) |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in rows:
        s = r.stats()
        lines.append(f"| {r.method} | {s['readings']} ({s['cases']}) | {s['refused']} | "
                     f"{_e(s['max_float'])} | {_e(s['med_float'])} | {_e(s['max_mp'])} | "
                     f"{_e(s['med_mp'])} | {_e(s['max_ref'])} | {s['min_cond']:.2g} | "
                     f"{s['med_cond']:.2g} | {s['time_us']:.0f} |")
    lines += ["", "*Refused* counts numbers a method declined, each with its one-line reason:", ""]
    for r in rows:
        for why in r.refused:
            lines.append(f"- {r.method}, {why}")
    lines += ["", "## 2. Error against run time", ""]
    for s in studies:
        name = s.file.name
        lines += [f"### {name[:-4].replace('-', ' ')}", "",
                  f"![{name}]({plots.as_posix()}/{name})", "",
                  f"Shows {s.shows}. **{s.headline[0].upper() + s.headline[1:]}.**", ""]
        if name == "sweep-step.svg":
            lines += [f"![sweep-time.svg]({plots.as_posix()}/sweep-time.svg)", ""]
        if s.table:
            lines += ["| " + " | ".join(s.columns) + " |",
                      "|---" + "|---:" * (len(s.columns) - 1) + "|"]
            lines += ["| " + " | ".join(_cell(v) for v in row) + " |" for row in s.table]
            lines.append("")
    lines += _stiff_table(stiff_rows)
    return "\n".join(lines) + "\n"


def _cell(v) -> str:
    """A table cell: a label as it is, a number to three figures."""
    return v if isinstance(v, str) else f"{v:.3g}"


def _stiff_table(rows) -> list[str]:
    ok = sum(r.within for r in rows)
    refused = sum(r.refused is not None for r in rows)
    ref_over = [r for r in rows if r.solver_worst is not None]
    slips = [(r.solver_worst[1], r) for r in ref_over]
    largest = ""
    if slips:
        slip, r = max(slips, key=lambda x: x[0])
        largest = (f" Its largest slip is {_key(r.solver_worst[0])} = {_e(slip)} on "
                   f"\"{r.case.label}\", where the construction is {_e(r.err_mp)} off.")
    out = [
        "## 3. The stiff and extreme suite",
        "",
        "Each case is a tarsim mechanism at one position, run through the real "
        "constructions (`benchmarks/bench/stiff.py`). A row is one method on one case: the "
        "number where the construction stands furthest from the mpmath reference against "
        f"the bound **{BOUND_ULPS} eps / conditioning**, the "
        "conditioning being the construction's own, compounded along the acts the number "
        "rests on (for the acceleration polygon, times the velocity polygon's worst, as "
        "`tarsim solve` checks it). *within?* is the construction's error against that "
        "bound; a refusal is within when it is the expected one-line message. The "
        "float64 solver is measured on the same number, and the note names its own worst "
        "number of the method where that is beyond the bound.",
        "",
        f"{ok} of {len(rows)} rows within (including {refused} expected refusals); "
        f"the float64 solver is beyond the bound in {len(ref_over)} rows.{largest}",
        "",
        "| group | case | method | number | conditioning | construction vs mpmath "
        "| solver vs mpmath | bound | within? | note |",
        "|---|---|---|---|---:|---:|---:|---:|---|---|",
    ]
    for r in rows:
        c = r.case
        if r.refused is not None:
            note = f"refused: {r.refused}"
            out.append(f"| {c.group} | {c.label} | {r.method} | — | — | — | — | — | "
                       f"{'yes' if r.within else '**no**'} | {note.replace('|', '/')} |")
            continue
        notes = []
        if not r.within:
            notes.append("construction beyond its bound")
        if r.solver_worst is not None:
            key, slip, bound = r.solver_worst
            notes.append(f"the float64 solver is beyond the bound on {_key(key)}: {_e(slip)} "
                         f"(bound {_e(bound)})")
        if r.bound > 1:
            notes.append("bound > 1: the conditioning leaves no digit guaranteed")
        out.append(f"| {c.group} | {c.label} | {r.method} | {_key(r.key)} | "
                   f"{_e(r.conditioning)} | {_e(r.err_mp)} | {_e(r.err_float)} | "
                   f"{_e(r.bound)} | {'yes' if r.within else '**no**'} | {'; '.join(notes)} |")
    return out + [""]


def _key(key: tuple) -> str:
    """A reading's name as the course writes it: B, I13, V_B, ω3, α4, A_cor_A, time ratio."""
    kind = key[0]
    if kind == "P":
        return key[1]
    if kind == "I":
        return f"I{key[1]}{key[2]}"
    if kind in ("V", "A"):
        return f"{kind}_{key[1]}{key[2] if key[2] is not None else ''}"
    if kind == "w":
        return f"ω{key[1]}"
    if kind == "a":
        return f"α{key[1]}"
    if kind == "cor":
        return f"A_cor_{key[1]}"
    return {"TR": "time ratio", "S": "stroke"}[kind]
