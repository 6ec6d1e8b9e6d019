"""Error against run time wherever a knob trades one for the other: five studies, five plots.

Each study measures, writes its SVG with :func:`.svgplot.write_plot` and returns a
:class:`Study`: the plot's file, what it shows and its headline, for the report.

- :func:`pen_precision`: the graphical method's own error, a student measuring the
  drawn velocity polygon with a pen of given precision, against the figure's size;
- :func:`newton_tolerance`: the analytic reference, Newton at several tolerances
  against the closed form;
- :func:`shapely_circles`: circle–circle cuts from shapely polygon buffers at several
  ``quad_segs``, against the analytic kernel;
- :func:`sweep_step`: a sweep's angular step against the error of the extremes it finds;
- :func:`precision`: float64 against mpmath at several digits.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from tarsim.constructions import geometry as g
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.limits import limit_reference
from tarsim.constructions.reference.turn import solve_turn
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tarsim.exercises.catalog import load

from .mpref import at_angle, mp_solve
from .readings import EPS
from .timing import median_time
from .svgplot import Curve, Guide, write_plot

__all__ = ["Study", "pen_precision", "newton_tolerance", "shapely_circles", "sweep_step",
           "precision"]

@dataclass(frozen=True)
class Study:
    """One plot: its file, what it shows, its headline, and the numbers behind it."""

    file: Path
    shows: str
    headline: str
    columns: tuple[str, ...] = ()
    table: tuple[tuple, ...] = ()


def _rows(labels, pts, *extra) -> tuple[tuple, ...]:
    """A plot's points as table rows (label, time, error), then ``extra`` rows."""
    return tuple((lab, t, e) for lab, (t, e) in zip(labels, pts)) + extra


# ----- 1. the pen ----------------------------------------------------------------------------
def pen_precision(out: Path, *, samples: int = 20000, seed: int = 1) -> Study:
    """Monte Carlo of a student drawing and measuring the bundled four-bar's velocity polygon.

    The student lays off o_v a (the crank pin's V_A, ⟂ O2A) at the drawing scale, draws
    through a the line ⟂ AB and through o_v the line ⟂ O4B, cuts them at b and measures
    o_v b. Each laid-off or measured length is off by up to ± the pen's precision
    (uniform), each drawn direction by up to ± the protractor's. The polygon's directions
    and lengths are tarsim's own velocity polygon (exact to rounding). The figure's size
    is the polygon's longest side. Reported: the 95th percentile of |V_B| read off the
    figure against the true one.
    """
    mech = load("four-bar").mechanism
    vp = draw_velocity_polygon(assemble(mech), 1.0)
    va, vb = np.array(vp.vector("A")), np.array(vp.vector("B"))
    true = float(np.hypot(*vb))
    extent = max(np.hypot(*va), true, np.hypot(*(vb - va)))          # m/s
    ang_a = math.atan2(va[1], va[0])
    ang_ab = math.atan2(*(vb - va)[::-1])
    ang_b = math.atan2(vb[1], vb[0])
    rng = np.random.default_rng(seed)
    sizes = [2.0, 3.0, 4.0, 5.0, 7.0, 10.0, 14.0, 20.0, 28.0, 40.0]           # cm
    pens = (("pen 0.25 mm, angles ±0.5°", 0.025, 0.5), ("pen 0.5 mm, angles ±0.5°", 0.05, 0.5),
            ("pen 0.5 mm, exact angles (set square)", 0.05, 0.0),
            ("pen 0.25 mm, exact angles (set square)", 0.025, 0.0))
    curves, need = [], {}
    for label, pen_cm, deg in pens:
        pts = []
        for size in sizes:
            k = size / extent                                               # cm per m/s
            u = rng.uniform(-1, 1, (4, samples))
            da, dab, db = (np.radians(deg) * u[i] for i in range(3))
            la = np.hypot(*va) * k + pen_cm * rng.uniform(-1, 1, samples)
            a = la * np.array([np.cos(ang_a + da), np.sin(ang_a + da)])
            d1 = np.array([np.cos(ang_ab + dab), np.sin(ang_ab + dab)])
            d2 = np.array([np.cos(ang_b + db), np.sin(ang_b + db)])
            # a + s d1 = t d2  →  t = cross(a, d1) / cross(d2, d1)
            t = (a[0] * d1[1] - a[1] * d1[0]) / (d2[0] * d1[1] - d2[1] * d1[0])
            read = (np.abs(t) + pen_cm * u[3]) / k
            pts.append((size, float(np.percentile(np.abs(read - true) / true, 95))))
        curves.append(Curve(label, tuple(pts)))
        need[label] = _first_below(pts, 0.01)
    path = write_plot(out / "pen-precision.svg",
                      "Reading V_B off a drawn velocity polygon (four-bar, θ2 = 60°)",
                      "size of the velocity polygon on paper (cm)",
                      "relative error of |V_B|, 95th percentile", curves,
                      guides=[Guide(0.01, "1 % target")],
                      note=f"Monte Carlo, {samples} drawings per point; lengths and angles "
                           "off by up to ± the stated precision (uniform).")
    exact = [(pen, need[lab]) for lab, pen, deg in pens if deg == 0.0]
    rough = [(pen, need[lab], c.points[-1][1]) for (lab, pen, deg), c in zip(pens, curves)
             if deg > 0.0]
    head = ("; ".join(f"{_cm(v)} with a {pen * 10:g} mm pen" for pen, v in exact)
            + " when the directions are exact (set square); with directions off by ±0.5°, "
            + "; ".join(f"{_cm(v)} with a {pen * 10:g} mm pen (at 40 cm: {e:.1%})"
                        for pen, v, e in rough))
    return Study(path, "the error a reader gets measuring the drawn velocity polygon, against "
                       "the size it is drawn at and the pen's precision",
                 f"1 % (95th percentile) needs a velocity polygon at least {head}",
                 ("pen and angles", *(f"{s:g} cm" for s in sizes)),
                 tuple((lab, *[p[1] for p in c.points]) for (lab, *_), c in zip(pens, curves)))


def _first_below(pts, target: float) -> float | None:
    """The size (log-interpolated) from which the error stays below ``target``."""
    for (s0, e0), (s1, e1) in zip(pts, pts[1:]):
        if e0 > target >= e1 and all(e <= target for _, e in pts[pts.index((s1, e1)):]):
            f = (math.log(e0) - math.log(target)) / (math.log(e0) - math.log(e1))
            return math.exp(math.log(s0) + f * (math.log(s1) - math.log(s0)))
    return pts[0][0] if all(e <= target for _, e in pts) else None


def _cm(v: float | None) -> str:
    return "no size up to 40 cm" if v is None else f"{v:.0f} cm long"


# ----- 2. Newton's tolerance -----------------------------------------------------------------
def _four_bar_closed(r1, r2, r3, r4, t2):
    """θ3, θ4 of the bundled four-bar's branch in closed form (the cosine rule on O4A)."""
    ax, ay = r2 * math.cos(t2) - r1, r2 * math.sin(t2)
    d = math.hypot(ax, ay)
    phi = math.atan2(ay, ax)
    beta = math.acos((d * d + r4 * r4 - r3 * r3) / (2 * d * r4))
    t4 = phi - beta
    bx, by = r1 + r4 * math.cos(t4), r4 * math.sin(t4)
    return math.atan2(by - r2 * math.sin(t2), bx - r2 * math.cos(t2)), t4


def _four_bar_newton(r1, r2, r3, r4, t2, start, tol):
    """Newton on the loop r2 e^{iθ2} + r3 e^{iθ3} − r4 e^{iθ4} − r1 = 0 until |F| ≤ tol·size."""
    t3, t4 = start
    for _ in range(100):
        f1 = r2 * math.cos(t2) + r3 * math.cos(t3) - r4 * math.cos(t4) - r1
        f2 = r2 * math.sin(t2) + r3 * math.sin(t3) - r4 * math.sin(t4)
        if max(abs(f1), abs(f2)) <= tol * r1:
            break
        j11, j12, j21, j22 = -r3 * math.sin(t3), r4 * math.sin(t4), r3 * math.cos(t3), \
            -r4 * math.cos(t4)
        det = j11 * j22 - j12 * j21
        t3 -= (f1 * j22 - f2 * j12) / det
        t4 -= (j11 * f2 - j21 * f1) / det
    return t3, t4


def newton_tolerance(out: Path) -> Study:
    """Newton on the four-bar's loop at tolerances 1e-2 … 4 eps, from a start 10° off, against
    the closed form and the float64 solver (closed form + Newton polish), all vs mpmath."""
    mech = load("four-bar").mechanism
    r1, r2, r3, r4, t2 = 0.3, 0.1, 0.25, 0.2, mech.drive.angle
    exact = mp_solve(mech, solver.solve_positions(mech)).points["B"]
    ex = (float(exact[0]), float(exact[1]))

    def err(t4):
        return math.dist((r1 + r4 * math.cos(t4), r4 * math.sin(t4)), ex) / r1 + 0.0

    closed = _four_bar_closed(r1, r2, r3, r4, t2)
    start = (closed[0] + math.radians(10), closed[1] - math.radians(10))
    pts, labels = [], []
    for tol in (1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14, 4 * EPS):
        t = median_time(lambda tol=tol: _four_bar_newton(r1, r2, r3, r4, t2, start, tol), 300)
        pts.append((t, max(err(_four_bar_newton(r1, r2, r3, r4, t2, start, tol)[1]), 1e-17)))
        labels.append("4ε" if tol < 1e-15 else f"{tol:.0e}")
    tc = median_time(lambda: _four_bar_closed(r1, r2, r3, r4, t2), 300)
    ec = max(err(closed[1]), 1e-17)
    ts = median_time(lambda: solver.solve_positions(mech), 100)
    es = max(math.dist(solver.solve_positions(mech)["B"], ex) / r1, 1e-17)
    curves = [Curve("Newton from a start 10° off, at tolerance |F| ≤ tol·O2O4", tuple(pts),
                    tuple(labels)),
              Curve("closed form (cosine rule)", ((tc, ec),), line=False),
              Curve("tarsim's solver: closed form + Newton polish (whole mechanism)",
                    ((ts, es),), line=False)]
    path = write_plot(out / "newton-tolerance.svg",
                      "Analytic reference: Newton's tolerance against the closed form",
                      "run time per position (µs)", "error of B against mpmath (/ O2O4)",
                      curves, note="Bundled four-bar at θ2 = 60°; errors below 1e-17 are "
                                   "drawn at 1e-17 (exact to the last bit).")
    return Study(path, "the analytic reference's error against its run time, Newton at "
                       "several tolerances beside the closed form",
                 f"the closed form is exact to {ec:.0e} in {tc:.1f} µs; Newton needs "
                 f"tolerance 1e-8 for {pts[4][1]:.0e} ({pts[4][0]:.1f} µs) and 4ε for "
                 f"{pts[-1][1]:.0e} ({pts[-1][0]:.1f} µs); the whole solver takes {ts:.0f} µs "
                 f"({es:.0e})", ("Newton tolerance", "time (µs)", "error"),
                 _rows(labels, pts, ("closed form", tc, ec), ("solver.solve_positions", ts, es)))


# ----- 3. shapely circles --------------------------------------------------------------------
def shapely_circles(out: Path, *, quick: bool = False) -> Study:
    """B of the bundled four-bar cut from two arcs: shapely buffers at several ``quad_segs``
    (the circles as polygons) against tarsim's analytic kernel, error and time."""
    from shapely.geometry import Point as SPoint

    mech = load("four-bar").mechanism
    places = solver.solve_positions(mech)
    exact = mp_solve(mech, places).points["B"]
    ex = (float(exact[0]), float(exact[1]))
    a, o4 = places["A"], places["O4"]
    size = 0.3

    def cut(q):
        c1 = SPoint(a).buffer(0.25, quad_segs=q).exterior
        c2 = SPoint(o4).buffer(0.2, quad_segs=q).exterior
        hits = c1.intersection(c2)
        return min(((p.x, p.y) for p in getattr(hits, "geoms", [hits])),
                   key=lambda p: math.dist(p, ex))

    pts, labels = [], []
    for q in ((2, 8, 32, 128, 512) if quick else (1, 2, 4, 8, 16, 32, 64, 128, 256, 1024, 4096)):
        t = median_time(lambda q=q: cut(q), 5 if q > 512 else 30)
        pts.append((t, math.dist(cut(q), ex) / size))
        labels.append(str(q))
    ka, ko = g.Point(*a), g.Point(*o4)

    def kernel():
        return g.intersect_circles(g.Circle(ka, 0.25), g.Circle(ko, 0.2), "left")[0]
    tk = median_time(kernel, 300)
    ek = max(math.dist(kernel().xy, ex) / size, 1e-17)      # exact: drawn at the floor
    curves = [Curve("shapely: two buffered circles cut (label: quad_segs)", tuple(pts),
                    tuple(labels)),
              Curve("tarsim's analytic kernel (intersect_circles)", ((tk, ek),), line=False)]
    path = write_plot(out / "shapely-circles.svg",
                      "Circle–circle cut: polygon circles (shapely) against the analytic kernel",
                      "run time per cut (µs)", "error of B against mpmath (/ O2O4)", curves,
                      note="The bundled four-bar's B, cut from the arcs about A and O4; "
                           "errors below 1e-17 are drawn at 1e-17.")
    best = pts[-1]
    return Study(path, "why the kernel is analytic: a polygon circle's error falls only as "
                       "1/quad_segs² while its time grows",
                 f"the kernel cuts B to {ek:.0e} in {tk:.1f} µs; shapely at quad_segs "
                 f"{labels[-1]} is {best[1]:.0e} off in {best[0]:.0f} µs",
                 ("quad_segs", "time (µs)", "error"), _rows(labels, pts, ("kernel", tk, ek)))


# ----- 4. sweep step -------------------------------------------------------------------------
def sweep_step(out: Path, *, quick: bool = False) -> Study:
    """The crank-shaper swept at N steps by the vectorised analytic solver (as ``tarsim sweep``
    does): the time ratio (the ram's
    velocity zeros, interpolated linearly between steps) and the peak |A_ram| (the largest
    sample), against their values found to the last bit."""
    mech = solver.follow_branches(load("crank-shaper").mechanism)
    d = mech.drive
    exact_tr = limit_reference(mech, point="B").time_ratio

    def state(theta):
        kin = solver.solve(at_angle(mech, theta))
        return kin.velocities["B"][0], abs(kin.accelerations["B"][0])

    def run(n, offset):
        """One sweep of ``n`` steps as ``tarsim sweep`` makes it (all positions at once)."""
        thetas = [d.angle + offset + math.tau * k / n for k in range(n + 1)]
        turn = solve_turn(mech, np.asarray(thetas))
        vs, acc = turn.velocities["B"][:, 0].tolist(), np.abs(turn.accelerations["B"][:, 0])
        zeros = [thetas[k] - vs[k] * (thetas[k + 1] - thetas[k]) / (vs[k + 1] - vs[k])
                 for k in range(n) if vs[k] * vs[k + 1] < 0]
        first = (zeros[1] - zeros[0]) % math.tau
        ratio = max(first, math.tau - first) / min(first, math.tau - first)
        k = int(np.argmax(acc))
        return ratio, max(acc), thetas[k]

    # Step counts that do not nest, each from several start angles (a sweep's samples fall
    # where they fall): the worst of them is what a user may get.
    steps = (37, 89, 359) if quick else (19, 37, 71, 181, 359, 719, 1433, 3607)
    offsets = (0.1234, 0.4321, 0.7777) if quick else (0.1234, 0.3141, 0.4321, 0.6180, 0.7777)
    results = {}
    for n in steps:
        t0 = time.perf_counter()
        runs = [run(n, o * math.tau / n) for o in offsets]
        results[n] = (runs, (time.perf_counter() - t0) / len(offsets))
    # The peak found to the last bit: golden-section search round the finest grid's best.
    runs, _ = results[steps[-1]]
    th, h = max(runs, key=lambda r: r[1])[2], math.tau / steps[-1]
    lo, hi = th - h, th + h
    phi = (math.sqrt(5) - 1) / 2
    while hi - lo > 1e-9:
        m1, m2 = hi - phi * (hi - lo), lo + phi * (hi - lo)
        if state(m1)[1] > state(m2)[1]:
            hi = m2
        else:
            lo = m1
    peak = state((lo + hi) / 2)[1]

    def worst(n, i, exact):
        return max(max(abs(r[i] - exact) / exact for r in results[n][0]), 1e-17)
    tr_pts = tuple((360 / n, worst(n, 0, exact_tr)) for n in steps)
    pk_pts = tuple((360 / n, worst(n, 1, peak)) for n in steps)
    t_pts = tuple((360 / n, results[n][1]) for n in steps)
    p1 = write_plot(out / "sweep-step.svg",
                    "Sweep step against the error of the extremes found (crank-shaper)",
                    "angular step of the sweep (°)", "relative error",
                    [Curve("time ratio (ram velocity zeros, linear interpolation)", tr_pts),
                     Curve("peak ram acceleration |A_B| (largest sample)", pk_pts)],
                    note=f"Worst of {len(offsets)} start angles. Exact: time ratio "
                         f"{exact_tr:.10f} (bisection), peak |A_B| {peak:.6f} m/s² "
                         "(golden section).")
    write_plot(out / "sweep-time.svg", "Sweep step against run time (crank-shaper)",
                    "angular step of the sweep (°)", "run time of the sweep (s)",
                    [Curve("the analytic solver over the turn (solve_turn)", t_pts)])
    one = next(n for n in steps if 360 / n <= 1.01)
    return Study(p1, "a sweep's angular step against the error of the extremes it finds "
                     "(sweep-step.svg) and its time (sweep-time.svg)",
                 f"a 1° sweep ({results[one][1] * 1e3:.1f} ms) finds the time ratio to "
                 f"{worst(one, 0, exact_tr):.0e} and the peak acceleration to "
                 f"{worst(one, 1, peak):.0e} at worst; both errors fall about as the step "
                 "squared",
                 ("step", "time ratio error", "peak |A_B| error", "time (s)"),
                 tuple((f"{360 / n:.3g}°", tr, pk, t[1]) for n, (_, tr), (_, pk), t in
                       zip(steps, tr_pts, pk_pts, t_pts)))


# ----- 5. precision --------------------------------------------------------------------------
def precision(out: Path, *, quick: bool = False) -> Study:
    """ω3 of a four-bar 1e-7 rad from its toggle: float64 (construction, solver) against
    mpmath at several digits, each against mpmath at 200 digits; error against time."""
    from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon as dvp
    from .stiff import stiff_cases

    case = next(c for c in stiff_cases() if c.label == "μ → 180°, 1e-07 rad from toggle")
    mech = case.mechanism
    places = solver.solve_positions(mech)
    truth = mp_solve(mech, places, dps=200).omegas[3]
    pts, labels = [], []
    for dps in ((30, 50) if quick else (30, 40, 50, 60, 80, 120)):
        t0 = time.perf_counter()
        w = mp_solve(mech, places, dps=dps).omegas[3]
        pts.append((time.perf_counter() - t0, float(abs(w - truth) / abs(truth))))
        labels.append(f"{dps} digits")
    truth = float(truth)
    tf = median_time(lambda: solver.solve(mech), 30) * 1e-6
    ef = abs(solver.solve(mech).omegas[3] - truth) / abs(truth)
    tc = median_time(lambda: dvp(assemble(mech)), 30) * 1e-6
    ec = abs(dvp(assemble(mech)).rates[3] - truth) / abs(truth)
    path = write_plot(out / "precision.svg",
                      "Precision: float64 against mpmath (ω3, 1e-7 rad from a toggle)",
                      "run time (s)", "relative error of ω3 against 200 digits",
                      [Curve("mpmath reference (Newton + differences)", tuple(pts), tuple(labels)),
                       Curve("float64 analytic solver", ((tf, max(ef, 1e-17)),), line=False),
                       Curve("float64 velocity polygon (construction)", ((tc, max(ec, 1e-17)),),
                             line=False)],
                      note="The mpmath derivative step is 10^(−digits/4): its truncation, "
                           "not the digits, sets its error here.")
    return Study(path, "float64 against mpmath at several working precisions, near a toggle "
                       "where float64 loses digits",
                 f"float64 keeps {-math.log10(max(ef, 1e-17)):.1f} digits of ω3 here "
                 f"(solver {ef:.0e}, polygon {ec:.0e}, in {tf * 1e6:.0f} µs and "
                 f"{tc * 1e6:.0f} µs); the mpmath reference keeps "
                 f"{-math.log10(max(pts[-1][1], 1e-300)):.0f} digits at {labels[-1]} "
                 f"({pts[-1][0]:.2f} s)",
                 ("precision", "time (s)", "error of ω3"),
                 _rows(labels, pts, ("float64 solver", tf, ef), ("float64 polygon", tc, ec)))

