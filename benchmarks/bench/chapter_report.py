"""The report's section on every chapter beside the linkages: run each chapter's study and
write its rows.

Each study (``gear_rows``, ``cam_rows``, ``force_rows``, ``balance_rows``,
``flywheel_rows``, ``flywheel_input_rows``) measures tarsim's numbers on a chapter's stiff
and extreme cases against closed forms, beside a tolerance justified by the case's
conditioning, with median run times, and draws a plot.
"""

from __future__ import annotations

from pathlib import Path

from .balance_rows import balance_study
from .cam_rows import cam_study
from .chapter_rows import ChapterStudy
from .flywheel_input_rows import flywheel_input_study
from .flywheel_rows import flywheel_study
from .force_rows import force_study
from .gear_rows import gear_study

__all__ = ["STUDIES", "run_chapters", "render_chapters"]

STUDIES = (gear_study, cam_study, force_study, balance_study, flywheel_study,
           flywheel_input_study)
"""Each chapter's study, in the course's order."""


def run_chapters(plots: Path, *, quick: bool = False, progress=None) -> list[ChapterStudy]:
    """Run every chapter's study, its plot into ``plots``."""
    out = []
    for study in STUDIES:
        out.append(study(plots, quick=quick))
        if progress is not None:
            progress(1)
    return out


def _e(x: float) -> str:
    return "0" if x == 0 else f"{x:.1e}"


def render_chapters(studies: list[ChapterStudy], plots: Path) -> list[str]:
    """The report's section 4: each chapter's headline, plot and rows."""
    total = sum(len(s.rows) for s in studies)
    within = sum(r.within for s in studies for r in s.rows)
    lines = [
        "## 4. Every chapter: its rows and its extremes",
        "",
        "Each chapter's numbers on its own stiff and extreme cases, against a closed form "
        "(`benchmarks/bench/*_rows.py`). A row gives the error of tarsim's number, the "
        "tolerance its conditioning allows (stated in each study), whether the error is "
        "within it, and the median run time of what produced the number. A tolerance of 1 "
        "or more is shown as it is and flagged: such a row guarantees no digit.",
        "",
        f"{within} of {total} rows within their tolerance.",
        "",
    ]
    for s in studies:
        name = s.plot.name
        lines += [f"### {s.chapter}", "",
                  f"Against {s.against}. **{s.headline[0].upper() + s.headline[1:]}.**", "",
                  f"![{name}]({plots.as_posix()}/{name})", "",
                  f"| case | number | {s.conditioning} | error | tolerance | within? "
                  "| median time (µs) | note |",
                  "|---|---|---:|---:|---:|---|---:|---|"]
        for r in s.rows:
            lines.append(f"| {r.case} | {r.number} | {r.conditioning:.2g} | {_e(r.error)} | "
                         f"{_e(r.tolerance)} | {'yes' if r.within else '**no**'} | "
                         f"{r.time_us:.3g} | {r.note.replace('|', '/')} |")
        lines.append("")
    return lines
