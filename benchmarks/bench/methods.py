"""The method table: each method's error against both references, its conditioning and time.

Every bundled exercise (``tarsim list``) is taken at its stated positions, and (unless
quick) at every 30° of its input's turn, and every method that applies is run on it:
position by compass, the centres by Kennedy, V of every moving point by radius
rotation, parallel lines and components, both polygons, and the limit positions
(once per exercise: they do not depend on the position). Each number read off a
construction is measured against the float64 solver and against the 50-digit mpmath
reference (:mod:`.readings`); the float64 solver is measured against mpmath too.
"""

from __future__ import annotations

import math
import statistics
from dataclasses import dataclass, field

from tarsim.constructions.errors import AssemblyError, TarsimError
from tarsim.constructions.model import Mechanism
from tarsim.exercises.catalog import bundled, load

from .mpref import Unmodelled, at_angle
from .readings import METHODS, FloatReference, MpReference, Reading, error, run_method

__all__ = ["Case", "cases", "MethodRow", "method_table"]


@dataclass(frozen=True)
class Case:
    """A mechanism at one position, named for the report; ``stated`` if the exercise's own."""

    label: str
    mechanism: Mechanism
    stated: bool


QUICK = ("four-bar", "offset-slider-crank", "inverted-slider-crank", "six-link-homework-1")
"""One exercise of each kind, which between them ask every method: the quick run's."""


def cases(quick: bool) -> list[Case]:
    """The bundled exercises at their stated positions, and (not quick) every 30°; quick,
    only those of :data:`QUICK`."""
    out = []
    for name in QUICK if quick else bundled():
        ex = load(name)
        drives = [p.drive for p in ex.positions] or [ex.mechanism.drive]
        for d in drives:
            out.append(Case(f"{name} θ={math.degrees(d.angle):.4g}°",
                            ex.mechanism.with_drive(d), True))
        if not quick:
            for deg in range(0, 360, 30):
                out.append(Case(f"{name} θ={deg}°", at_angle(ex.mechanism, math.radians(deg)),
                                False))
    return out


@dataclass
class MethodRow:
    """One method's errors (vs float64 solver, vs mpmath), conditioning and times."""

    method: str
    vs_float: list[float] = field(default_factory=list)
    vs_mp: list[float] = field(default_factory=list)
    float_vs_mp: list[float] = field(default_factory=list)
    conditioning: list[float] = field(default_factory=list)
    seconds: list[float] = field(default_factory=list)
    refused: list[str] = field(default_factory=list)
    cases: int = 0

    @staticmethod
    def _finite(xs):
        return [x for x in xs if math.isfinite(x)]

    def stats(self) -> dict:
        """Largest and median of each column (nan where empty)."""
        def mx(xs):
            xs = self._finite(xs)
            return max(xs) if xs else math.nan

        def med(xs):
            xs = self._finite(xs)
            return statistics.median(xs) if xs else math.nan
        return {"max_float": mx(self.vs_float), "med_float": med(self.vs_float),
                "max_mp": mx(self.vs_mp), "med_mp": med(self.vs_mp),
                "max_ref": mx(self.float_vs_mp),
                "min_cond": min(self.conditioning, default=math.nan),
                "med_cond": med(self.conditioning),
                "time_us": med(self.seconds) * 1e6, "readings": len(self.vs_mp),
                "refused": len(self.refused), "cases": self.cases}


def _size(places: dict) -> float:
    xy = list(places.values())
    return max(math.dist(p, q) for p in xy for q in xy)


def method_table(all_cases: list[Case], *, repeat: int = 3, progress=None) -> list[MethodRow]:
    """Run every method on every case; ``progress(n)`` is told of each case done."""
    rows = {m: MethodRow(m) for m in METHODS}
    for case in all_cases:
        mech = case.mechanism
        try:
            fref = FloatReference(mech)
        except (AssemblyError, TarsimError):
            if progress:
                progress(1)
            continue                    # the position cannot be assembled: not a case
        try:
            mref = MpReference(mech, fref.places)
        except (ArithmeticError, Unmodelled):
            mref = None
        size = _size(fref.places)
        for method in METHODS:
            if method == "limit positions" and not case.stated:
                continue
            run = run_method(method, mech, repeat)
            row = rows[method]
            row.refused += [f"{case.label}: {why}" for why in run.refused]
            if not run.readings:
                continue
            row.cases += 1
            row.seconds.append(run.seconds)
            for ref in (fref, mref):
                if ref is not None:
                    ref.drawn_limits = run.limits
            for r in run.readings:
                f = fref.value(r.key)
                m = mref.value(r.key) if mref is not None else None
                row.vs_float.append(error(r, f, size))
                row.vs_mp.append(error(r, m, size))
                if f is not None:
                    row.float_vs_mp.append(error(Reading(r.key, f, 1.0, r.scale), m, size))
                row.conditioning.append(r.conditioning)
        if progress:
            progress(1)
    return list(rows.values())
