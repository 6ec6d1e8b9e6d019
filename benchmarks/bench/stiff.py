"""The stiff and extreme suite: the real constructions where geometry is nearly degenerate.

Each case is a :class:`~tarsim.constructions.model.Mechanism` at one position, run
through the methods that matter there, and judged against the 50-digit mpmath
reference (:mod:`.mpref`). A method's row reports its worst reading: the one whose
error stands highest against its bound ``10 eps / conditioning``, where the
conditioning is the construction's own, compounded along the acts the reading rests on
(the product of the sines of the crossing angles and the tangency margins of every
cut, as each step records it; an acceleration off the polygon carries both polygons'
worst, as ``tarsim solve`` checks it). The float64 analytic solver is measured
against mpmath on the same reading, so a reference that loses digits shows beside a
construction that keeps them: a row gives the construction's worst reading, and where
the solver is beyond the bound on any reading of the method, its worst one too. A case
tarsim refuses (a dead point) is reported with its one-line message; the suite says
which refusals are expected.

Groups: transmission angles towards 0° and 180° (to 1e-9 rad from the toggle), Kennedy
lines meeting at angles down to 1e-9 rad, centres at and near infinity, link-length
ratios 1e-6 … 1e6, ω from 1e-9 to 1e6 rad/s, dead and coincident centres, and Coriolis
as ω of the slotted link goes to 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from tarsim.constructions.errors import AssemblyError, TarsimError
from tarsim.constructions.model import Drive, Mechanism
from tarsim.constructions.reference import solver

from .mpref import Unmodelled
from .readings import EPS, FloatReference, MpReference, Reading, error, run_method
from tarsim.exercises.linkages.mechanism_file import parse_mechanism
from tests.common import four_bar, four_bar_toml, inverted_slider_crank, offset_slider_crank

__all__ = ["StiffCase", "StiffRow", "stiff_cases", "run_case", "parallel_angle", "BOUND_ULPS"]

BOUND_ULPS = 10
"""The bound is BOUND_ULPS × eps / conditioning."""

POSITION, CENTRES, RR = "position by compass", "centres by Kennedy", "radius rotation"
VP, AP, COMP = "velocity polygon", "acceleration polygon (with Coriolis)", "components"


@dataclass(frozen=True)
class StiffCase:
    """One case: its group, label, mechanism, the methods run, and what is expected.

    ``only`` keeps the readings of one kind (``"cor"``: the Coriolis components);
    ``refusal`` is the start of the message a refusal is expected to carry.
    """

    group: str
    label: str
    mechanism: Mechanism
    methods: tuple[str, ...]
    only: str | None = None
    refusal: str | None = None


@dataclass
class StiffRow:
    """One method on one case: its worst reading against both references, or its refusal."""

    case: StiffCase
    method: str
    key: tuple | None = None
    conditioning: float = math.nan
    err_mp: float = math.nan
    err_float: float = math.nan
    refused: str | None = None
    solver_worst: tuple | None = None
    """The float64 solver's own worst reading here, if beyond its bound: (key, error, bound)."""

    @property
    def bound(self) -> float:
        """BOUND_ULPS eps over the conditioning."""
        return BOUND_ULPS * EPS / self.conditioning if self.conditioning > 0 else math.inf

    @property
    def within(self) -> bool:
        """Within its bound, or refused with the expected message."""
        if self.refused is not None:
            return self.case.refusal is not None and self.refused.startswith(self.case.refusal)
        return self.err_mp <= self.bound


def _toggle_angle(crank, coupler, rocker, ground, extended: bool) -> float:
    """θ2 where coupler and rocker lie in line: |O4A| = rocker ± coupler."""
    d = rocker + coupler if extended else abs(rocker - coupler)
    return math.acos((crank ** 2 + ground ** 2 - d ** 2) / (2 * crank * ground))


def parallel_angle() -> float:
    """θ2 where the peers.md four-bar's crank and rocker are parallel (I13 at ∞), by
    bisection to the last bit on the float64 positions (only where the case sits)."""
    def cross(theta: float) -> float:
        pts = solver.solve_positions(four_bar(theta))
        (ax, ay), (bx, by), (ox, oy) = pts["A"], pts["B"], pts["O4"]
        return ax * (by - oy) - ay * (bx - ox)
    lo, hi = math.radians(100), math.radians(140)
    lo, hi = (lo, hi) if cross(lo) * cross(hi) < 0 else (math.radians(200), math.radians(300))
    while hi - lo > 1e-15:
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if cross(lo) * cross(mid) > 0 else (lo, mid)
    return (lo + hi) / 2


def stiff_cases(quick: bool = False) -> list[StiffCase]:
    """The suite; ``quick`` keeps the ends of each sweep and the known cases."""
    steps = (1e-3, 1e-9) if quick else (1e-1, 1e-3, 1e-5, 1e-7, 1e-9)
    out = []
    # Transmission angle → 180° (coupler and rocker extended) and → 0° (folded): the
    # crank turned towards the toggle, the side where the linkage still assembles.
    for mu, dims, ext in (("180°", dict(crank=0.2, coupler=0.15, rocker=0.2), True),
                          ("0°", dict(crank=0.2, coupler=0.1, rocker=0.25), False)):
        star = _toggle_angle(dims["crank"], dims["coupler"], dims["rocker"], 0.3, ext)
        for d in steps:
            out.append(StiffCase("toggle", f"μ → {mu}, {d:.0e} rad from toggle",
                                 four_bar(star - d if ext else star + d, omega2=1.0,
                                          alpha2=0.5, **dims), (POSITION, CENTRES, VP, AP)))
        out.append(StiffCase("toggle", f"μ = {mu} exactly (dead point)",
                             four_bar(star, omega2=1.0, **dims), (VP, AP), refusal="dead point"))
    # benchmarks/position_accuracy.py's toggle: AB = 200 + δ mm at θ2 = 180°, where the arcs
    # of B nearly touch. At δ = 1e-8 mm the centre I13 has conditioning 6.7e-11, and the
    # float64 reference's I34 (from the velocity fields) slips to ~3e-6.
    for delta in ((1e-8,) if quick else (1e-2, 1e-4, 1e-6, 1e-8)):
        m = parse_mechanism(four_bar_toml(coupler=200 + delta, angle=180), "toggle.toml")
        out.append(StiffCase("toggle", f"AB = 200 + {delta:.0e} mm at θ2 = 180°",
                             m.with_drive(Drive(2, m.drive.angle, 1.0, 0.0)),
                             (POSITION, CENTRES, VP)))
    # Kennedy lines O2A and O4B (for I13) meeting at a vanishing angle, then parallel.
    par = parallel_angle()
    for d in steps:
        out.append(StiffCase("Kennedy angle", f"I13: crank {d:.0e} rad from ∥ rocker",
                             four_bar(par + d, omega2=10.0), (CENTRES, RR)))
    out.append(StiffCase("at infinity", "I13 at ∞ (crank ∥ rocker)",
                         four_bar(par, omega2=10.0), (CENTRES, RR)))
    out.append(StiffCase("at infinity", "parallelogram θ2 = 90°: I13 at ∞, ω3 = 0",
                         four_bar(math.pi / 2, o4=(0.4, 0.0), crank=0.3, coupler=0.4,
                                  rocker=0.3, omega2=1.0), (CENTRES, VP, COMP)))
    out.append(StiffCase("at infinity", "offset slider-crank: I14 at ∞",
                         offset_slider_crank(math.radians(45), omega2=1.0), (CENTRES, RR)))
    # Link-length ratios: the crank against the frame.
    for rho in ((1e-6, 1e6) if quick else (1e-6, 1e-3, 1e3, 1e6)):
        dims = (dict(o4=(1.0, 0.0), crank=rho, coupler=1.2, rocker=1.0) if rho < 1 else
                dict(o4=(1.0 / rho, 0.0), crank=1.0, coupler=1.2, rocker=1.0))
        out.append(StiffCase("length ratio", f"crank/frame = {rho:.0e}",
                             four_bar(1.0, omega2=1.0, alpha2=1.0, **dims),
                             (POSITION, CENTRES, VP, AP)))
    # ω over 15 decades (α = ω²/2): the relative errors must not move.
    for w in ((1e-9, 1e6) if quick else (1e-9, 1e-3, 1.0, 1e6)):
        out.append(StiffCase("ω range", f"ω2 = {w:.0e} rad/s",
                             four_bar(1.0, omega2=w, alpha2=w * w / 2), (RR, VP, AP)))
    # Dead centres of a slider-crank (V_C = 0), where I13 = I34 and I24 = I12 coincide.
    for deg in (0.0, 180.0):
        out.append(StiffCase("dead centre", f"in-line slider-crank θ2 = {deg:g}°",
                             offset_slider_crank(math.radians(deg), offset=0.0, omega2=1.0,
                                                 alpha2=0.0), (CENTRES, VP, COMP, AP)))
    # Coriolis as ω4 → 0: the crank square to the slot (the lever at its limit).
    lim = math.acos(0.12 / 0.3)
    for d in (steps + (0.0,)):
        out.append(StiffCase("Coriolis ω → 0", f"inverted slider-crank {d:.0e} rad from "
                             "the lever's limit" if d else "inverted slider-crank at the "
                             "lever's limit (ω4 = 0)",
                             inverted_slider_crank(lim + d, omega2=2.0, alpha2=0.0), (AP,),
                             only="cor"))
    return out


def run_case(case: StiffCase, repeat: int = 1) -> list[StiffRow]:
    """Run each method of ``case``; report its worst reading, or its refusal."""
    mech = case.mechanism
    try:
        fref = FloatReference(mech)
    except (AssemblyError, TarsimError) as e:
        return [StiffRow(case, m, refused=str(e)) for m in case.methods]
    runs = {m: run_method(m, mech, repeat) for m in case.methods}
    readings_of = {m: [r for r in run.readings if case.only is None or r.key[0] == case.only]
                   for m, run in runs.items()}
    mref = None
    if any(readings_of.values()):        # a case every method refuses needs no reference
        try:
            mref = MpReference(mech, fref.places)
        except (ArithmeticError, Unmodelled, ZeroDivisionError):
            pass
    xy = list(fref.places.values())
    size = max(math.dist(p, q) for p in xy for q in xy)
    rows = []
    for method, run in runs.items():
        readings = readings_of[method]
        if not readings:
            rows.append(StiffRow(case, method, refused=(run.refused or ["no reading"])[0]))
            continue
        worst, slips = None, []
        for r in readings:
            m = mref.value(r.key) if mref is not None else None
            if m is None:
                continue
            f = fref.value(r.key)
            slip = math.nan if f is None else error(Reading(r.key, f, 1.0, r.scale), m, size)
            row = StiffRow(case, method, r.key, r.conditioning, error(r, m, size), slip)
            if worst is None or row.err_mp / row.bound > worst.err_mp / worst.bound:
                worst = row
            if slip > row.bound:
                slips.append((slip / row.bound, (r.key, slip, row.bound)))
        if worst is None:
            rows.append(StiffRow(case, method, refused="no mpmath reference"))
            continue
        worst.solver_worst = max(slips)[1] if slips else None
        rows.append(worst)
    return rows
