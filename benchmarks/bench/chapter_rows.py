"""The chapters' rows of the report: each case's error against its stated tolerance and its
run time, and the study a chapter's rows make.

Every chapter beside the linkages (gear trains, cams, force polygons, balancing, the
flywheel) gives a :class:`ChapterStudy`: its rows, each a case with its conditioning, the
error of tarsim's number against a closed form, the tolerance that conditioning allows and
the median run time, and a plot of error against conditioning or run time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

import mpmath

__all__ = ["EPS", "Row", "ChapterStudy", "relative"]

EPS = 2.0 ** -52
"""float64's unit roundoff doubled (the spacing of floats at 1)."""


@dataclass(frozen=True)
class Row:
    """One case: what is measured, its conditioning (1 clean, towards 0 stiff; or, where a
    chapter states it so, the amplification κ ≥ 1), the error against the closed form, the
    tolerance allowed, the median time (µs) and a note."""

    case: str
    number: str
    conditioning: float
    error: float
    tolerance: float
    time_us: float
    note: str = ""

    @property
    def within(self) -> bool:
        """The error no larger than the tolerance."""
        return self.error <= self.tolerance


@dataclass(frozen=True)
class ChapterStudy:
    """A chapter's rows: its name, what is measured against what, the conditioning's
    column heading, the headline, the rows and the plot."""

    chapter: str
    against: str
    conditioning: str
    headline: str
    rows: tuple[Row, ...]
    plot: Path


def relative(got: float, want, scale=None) -> float:
    """|got − want| over |want| (or over ``scale``); ``want`` may be a Fraction or an mpmath
    number, and the difference is then taken exactly (or at its precision) before rounding."""
    if isinstance(want, Fraction):
        diff = float(abs(Fraction(got) - want))
    elif isinstance(want, mpmath.mpf):
        diff = float(abs(mpmath.mpf(got) - want))
    else:
        diff = abs(got - want)
    den = abs(float(want if scale is None else scale))
    return diff / den if den else (0.0 if diff == 0 else math.inf)
