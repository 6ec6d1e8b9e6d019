"""Fitting a figure to its sheet: how often its labels are placed, and what fitting costs,
beside the same rule followed on drawn figures.

Run:  python benchmarks/fitting_speed.py [--repeat 5] [--lang en]

For every figure of every bundled exercise that is fitted to its sheet (its scale not
the exercise's own), in this process: the layouts (the figure drawn with its labels
placed) and the drafts (drawn with each label at its first spot, unpriced) that
``fit`` makes, and its median time; beside them, the rule followed on drawn figures,
every scale it looks at drawn with its labels placed (as fitting was before drafts),
its layouts and its median time, in the same run; and the figures whose scale the two
choose differently (none, where a draft foretells the figure's size closely enough).
:func:`fitting_rows` gives the rows, for benchmarks/speed.py to report.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import tarsim  # noqa: E402
from benchmarks.speed import median_time  # noqa: E402
from tarsim.constructions.narration import speaking  # noqa: E402
from tarsim.exercises.catalog import bundled  # noqa: E402
from tarsim.exercises.linkages import solution_files  # noqa: E402
from tarsim.graphics import drafts, fitting, workers  # noqa: E402
from tarsim.graphics.figure_kinds import registered  # noqa: E402
from tarsim.graphics.svg import to_svg  # noqa: E402

_COUNTS: Counter = Counter()


class _Laid(drafts.LabelPlacer):
    def __init__(self, fig):
        _COUNTS["layouts"] += 1
        super().__init__(fig)


class _Drafted(drafts.DraftPlacer):
    def __init__(self, fig):
        _COUNTS["drafts"] += 1
        super().__init__(fig)


def _fits(name: str, lang: str) -> list[tuple]:
    """The arguments of each call to ``fit`` that drawing ``name``'s figures makes with a
    scale of the solve's own (one the exercise states is drawn at it, unfitted)."""
    calls: list[tuple] = []
    fit = fitting.fit

    def record(draw, per_cm, holds, *, fixed=False, grow=False):
        if not fixed:
            calls.append((draw, per_cm, holds, grow))
        return fit(draw, per_cm, holds, fixed=fixed, grow=grow)

    registered()                    # every figures module imported, with its ``fit``
    users = [m for m in list(sys.modules.values())
             if getattr(m, "fit", None) is fit and m is not fitting]
    cores, workers._cores = workers._cores, lambda: 1       # drawn here, not in workers
    for m in users:
        m.fit = record
    try:
        _ = solution_files.solve_worked(tarsim.load(name).named_in(lang)).pages  # drawn
    finally:
        workers._cores = cores
        for m in users:
            m.fit = fit
    return calls


def _counted(job: Callable[[], object]) -> tuple[object, Counter]:
    """``job()`` and the layouts and drafts it made."""
    _COUNTS.clear()
    laid, drafted = drafts.LabelPlacer, drafts.DraftPlacer
    drafts.LabelPlacer, drafts.DraftPlacer = _Laid, _Drafted
    try:
        return job(), Counter(_COUNTS)
    finally:
        drafts.LabelPlacer, drafts.DraftPlacer = laid, drafted


def _drawn_rule(draw, per_cm, holds, grow) -> float:
    """The rule followed on drawn figures, each scale it looks at drawn once: the scale."""
    memo: dict[float, object] = {}

    def drawn(at: float):
        if at not in memo:
            memo[at] = draw(at)
        return memo[at]
    return fitting.chosen_scale(drawn, per_cm, holds, grow=grow)


def _one(draw, per_cm: float, holds, grow: bool, repeat: int) -> Counter:
    """One fitted figure: the layouts, drafts and median seconds of ``fit``; the layouts
    and median seconds of the rule followed on drawn figures; whether they differ."""
    def now():
        return fitting.fit(draw, per_cm, holds, grow=grow)

    def before():
        return _drawn_rule(draw, per_cm, holds, grow)
    fig, made = _counted(now)
    at, made_before = _counted(before)
    return Counter(layouts=made["layouts"], drafts=made["drafts"],
                   drawn_layouts=made_before["layouts"],
                   changed=int(to_svg(fig) != to_svg(draw(at))),
                   seconds=median_time(now, repeat), drawn_seconds=median_time(before, repeat))


def fitting_rows(repeat: int = 5, lang: str = "en") -> list[dict]:
    """For each bundled exercise with a fitted figure: its figures fitted, the layouts,
    drafts and median seconds of fitting them, the layouts and median seconds of the rule
    followed on drawn figures, and how many figures the two draw differently."""
    rows = []
    with speaking(lang):
        for name in [*bundled(), *bundled("forces")]:
            row = Counter()
            for call in _fits(name, lang):
                row.update(figures=1)
                row.update(_one(*call, repeat))
            if row:
                rows.append({"exercise": name, **row})
    return rows


def main(argv: list[str] | None = None) -> None:
    """Print each exercise's row and their sum."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--lang", default="en")
    args = parser.parse_args(argv)
    rows = fitting_rows(args.repeat, args.lang)
    print(f"{'exercise':28} figs  layouts drafts  ms   | drawn: layouts  ms  | changed")
    total = Counter()
    for r in rows:
        total.update({k: v for k, v in r.items() if k != "exercise"})
        print(f"{r['exercise']:28} {r['figures']:4} {r['layouts']:8} {r['drafts']:6} "
              f"{r['seconds'] * 1e3:5.1f} | {r['drawn_layouts']:14} {r['drawn_seconds'] * 1e3:5.1f}"
              f" | {r['changed']}")
    print(f"{'all':28} {total['figures']:4} {total['layouts']:8} {total['drafts']:6} "
          f"{total['seconds'] * 1e3:5.1f} | {total['drawn_layouts']:14} "
          f"{total['drawn_seconds'] * 1e3:5.1f} | {total['changed']}")


if __name__ == "__main__":
    main()
