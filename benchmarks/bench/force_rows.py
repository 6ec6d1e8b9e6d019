"""Force polygons: a three-force member whose lines are near parallel, and an engine near its
dead centre, the graphical forces against closed forms and the kinetostatic reference.

- **near-parallel lines**: the bundled four-bar with a load P on its coupler
  (``four-bar-coupler-load``): the rocker carries nothing, so the coupler is a three-force
  member whose pin forces meet P's line where the rocker's line does. P is turned to within
  δ of the rocker's line O4B, so the lines meet far off (at infinity for δ = 0), while the
  forces stay finite: the moments about A give the rocker's pull s along u = O4B/|O4B|,
  s = −(Q − A)×P / ((B − A)×u), then F_23 = −P − s·u and T2 = (A − O2)×F_23;
- **near a dead centre**: a massless slider-crank (crank 60 mm, rod 240 mm) with a gas
  force of 5 kN on its piston, the crank θ from its inner dead centre: the rod pushes
  F = 5000/cos β along it, and the crank's torque T2 = −F·r sin θ·x_P/l shrinks with θ.

Each closed form is taken at 50 digits (mpmath) of the positions tarsim's analytic solver
gives (what the file states, solved), and the kinetostatic reference
(``constructions/reference/kinetostatics.py``, what ``tarsim solve`` checks against) is
measured against it too. The tolerance stated is 16 u over the construction's own
conditioning (``results.json``'s), as the linkage suite bounds its constructions.
"""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

import mpmath

import tarsim
from tarsim.constructions.reference import solver

from .chapter_rows import EPS, ChapterStudy, Row
from .svgplot import Curve, write_plot
from .timing import median_time

__all__ = ["coupler_load_file", "engine_file", "coupler_truth", "engine_truth", "force_study"]

_COUPLER = """name = "coupler load, {label}"
[units]
length = "mm"
[frame]
O2 = [0, 0]
O4 = [300, 0]
[[link]]
number = 2
points = ["O2", "A"]
lengths = {{ O2A = 100 }}
[[link]]
number = 3
points = ["A", "B"]
lengths = {{ AB = 250 }}
[[link]]
number = 4
points = ["O4", "B"]
lengths = {{ O4B = {rocker!r} }}
[input]
link = 2
angle = {theta!r}
omega = 10
[assembly]
B = "left"
[ask]
find = ["F_23", "T2"]
methods = ["polygon"]
[forces]
gravity = false
[[force]]
link = 3
point = [150, 40]
force = [{fx!r}, {fy!r}]
name = "P"
"""

_ENGINE = """name = "engine {theta:g}° from dead centre"
[units]
length = "m"
[frame]
O = [0, 0]
[[link]]
number = 2
points = ["O", "A"]
lengths = {{ OA = 0.06 }}
[[link]]
number = 3
points = ["A", "P"]
lengths = {{ AP = 0.24 }}
[[link]]
number = 4
points = ["P"]
[[slider]]
link = 4
point = "P"
on = 1
through = "O"
angle = 0
[input]
link = 2
angle = {theta!r}
omega = 200
[assembly]
P = "forward"
[ask]
find = ["F_34", "T2"]
methods = ["polygon"]
[forces]
gravity = false
[[force]]
link = 4
point = "P"
force = [-5000, 0]
name = "gas force"
"""


def _write(folder: Path, name: str, text: str) -> Path:
    path = folder / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def coupler_load_file(folder: Path, delta_deg: float) -> Path:
    """The coupler-load four-bar with P (500 N) turned δ from the rocker's line O4B."""
    mech = tarsim.load("four-bar-coupler-load").mechanism
    places = solver.solve_positions(mech)
    (bx, by), (ox, oy) = places["B"], places["O4"]
    along = math.atan2(by - oy, bx - ox) + math.radians(delta_deg)
    return _write(folder, f"coupler-{delta_deg:g}", _COUPLER.format(
        label=f"P within {delta_deg:g}° of the rocker's line", rocker=200, theta=60,
        fx=500 * math.cos(along), fy=500 * math.sin(along)))


TOGGLE_DEG = math.degrees(math.acos((100 ** 2 + 300 ** 2 - 370 ** 2) / (2 * 100 * 300)))
"""The crank angle (°) where a rocker of 120 mm stands in line with the 250 mm coupler
(|O4A| = 370 mm): the crank's limit, where the transmission angle reaches 180°."""


def toggle_file(folder: Path, before_deg: float) -> Path:
    """The coupler-load four-bar with a 120 mm rocker, the crank ``before_deg`` short of its
    toggle: the rocker's line runs nearly along the coupler, through A's side of B."""
    return _write(folder, f"toggle-{before_deg:g}", _COUPLER.format(
        label=f"{before_deg:g}° before the toggle", rocker=120,
        theta=TOGGLE_DEG - before_deg, fx=300.0, fy=-400.0))


def engine_file(folder: Path, theta_deg: float) -> Path:
    """The massless engine with its crank ``theta_deg`` from the inner dead centre."""
    return _write(folder, f"engine-{theta_deg:g}", _ENGINE.format(theta=theta_deg))


def coupler_truth(ex) -> dict[str, object]:
    """F_23 (vector) and T2 of the coupler-load four-bar in closed form, at 50 digits of its
    solved positions and its load."""
    mech = ex.mechanism
    places = solver.solve_positions(mech)
    force = ex.loads.forces[0]
    with mpmath.workdps(50):
        mp = {k: (mpmath.mpf(x), mpmath.mpf(y)) for k, (x, y) in places.items()}
        a, b, o2, o4 = mp["A"], mp["B"], mp["O2"], mp["O4"]
        ab = (b[0] - a[0], b[1] - a[1])
        length = mpmath.hypot(*ab)
        e = (ab[0] / length, ab[1] / length)
        lx, ly = (mpmath.mpf(v) for v in force.point)
        q = (a[0] + lx * e[0] - ly * e[1], a[1] + lx * e[1] + ly * e[0])
        p = tuple(mpmath.mpf(v) for v in force.force)
        rocker = (b[0] - o4[0], b[1] - o4[1])
        u = (rocker[0] / mpmath.hypot(*rocker), rocker[1] / mpmath.hypot(*rocker))

        def cross(r, f):
            return r[0] * f[1] - r[1] * f[0]
        s = -cross((q[0] - a[0], q[1] - a[1]), p) / cross(ab, u)
        f23 = (-p[0] - s * u[0], -p[1] - s * u[1])
        t2 = cross((a[0] - o2[0], a[1] - o2[1]), f23)
    return {"F_23": f23, "T2": t2}


def engine_truth(ex) -> dict[str, object]:
    """F_34 (vector) and T2 of the massless engine in closed form, at 50 digits of its crank
    angle as tarsim holds it."""
    mech = ex.mechanism
    with mpmath.workdps(50):
        r, rod, th = mpmath.mpf(0.06), mpmath.mpf(0.24), mpmath.mpf(mech.drive.angle)
        ax, ay = r * mpmath.cos(th), r * mpmath.sin(th)
        xp = ax + mpmath.sqrt(rod * rod - ay * ay)
        ex_, ey = (xp - ax) / rod, -ay / rod
        k = 5000 / ex_
        t2 = -k * ay * xp / rod
    return {"F_34": (k * ex_, k * ey), "T2": t2}


def _error(got: dict, want) -> float:
    """A vector's or a scalar's relative error against its closed form."""
    with mpmath.workdps(50):
        if isinstance(want, tuple):
            gx, gy = got["vector"]
            return float(mpmath.hypot(mpmath.mpf(gx) - want[0], mpmath.mpf(gy) - want[1])
                         / mpmath.hypot(*want))
        return float(abs(mpmath.mpf(got["value"]) - want) / abs(want))


def _rows(label: str, path: Path, truth, repeat: int) -> tuple[list[Row], dict]:
    ex = tarsim.load(path)
    solution = tarsim.solve(ex)
    got = solution.results["positions"][0]["quantities"]
    want = truth(ex)
    t = median_time(lambda: tarsim.solve(tarsim.load(path)).results, repeat)
    rows, errors = [], {}
    for name, exact in want.items():
        q = got[name]
        cond = q["conditioning"]
        err = _error(q, exact)
        ref = _error(q["reference"], exact)
        tol = 16 * EPS / 2 / cond
        rows.append(Row(label, f"{name}, force polygons", cond, err, tol, t,
                        f"the kinetostatic reference is {ref:.1e} off"
                        + ("; tolerance ≥ 1: no digit guaranteed" if tol >= 1 else "")))
        errors[name] = (cond, err, ref)
    return rows, errors


def force_study(out: Path, *, quick: bool = False) -> ChapterStudy:
    """Rows for δ from 30° to 1e-9° (the coupler) and θ from 30° to 1e-7° (the engine), with
    a plot of each number's error against its conditioning."""
    deltas = (30.0, 1e-7) if quick else (30.0, 0.3, 1e-3, 1e-5, 1e-7, 1e-9)
    befores = (1.0, 1e-6) if quick else (10.0, 1.0, 0.1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7)
    thetas = (30.0, 1e-6) if quick else (30.0, 0.3, 1e-3, 1e-5, 1e-7)
    repeat = 1 if quick else 5
    rows: list[Row] = []
    curves: dict[str, list] = {}
    families = (("near parallel", deltas, lambda d: f"coupler, P within {d:g}° of O4B",
                 coupler_load_file, coupler_truth),
                ("toggle", befores, lambda b: f"coupler, crank {b:g}° before the toggle",
                 toggle_file, coupler_truth),
                ("dead centre", thetas, lambda t: f"engine, crank {t:g}° from dead centre",
                 engine_file, engine_truth))
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for family, values, label, write, truth in families:
            for v in values:
                r, errs = _rows(label(v), write(folder, v), truth, repeat)
                rows += r
                # The plot: each case's worse number, the polygons' and the reference's.
                cond = min(c for c, _, _ in errs.values())
                for way, k in (("polygons", 1), ("kinetostatic reference", 2)):
                    worst = max(e[k] for e in errs.values())
                    curves.setdefault(f"{family}: {way}", []).append((cond, max(worst, 1e-17)))
    path = write_plot(out / "forces-conditioning.svg",
                      "Force polygons: near-parallel lines and a dead centre",
                      "the construction's conditioning (results.json)",
                      "relative error against the closed form",
                      [Curve(k, tuple(v), line=False) for k, v in curves.items()],
                      note="Each case's worse of its two numbers; errors below 1e-17 are "
                           "drawn at 1e-17; tolerance 16u / conditioning.")
    t2 = [r for r in rows if r.case.startswith("engine") and r.number.startswith("T2")]
    par = [r for r in rows if r.case.startswith("coupler, P") and r.number.startswith("F_23")]
    tog = [r for r in rows if "toggle" in r.case and r.number.startswith("F_23")]
    loose = sum(r.tolerance >= 1 for r in rows)
    head = (f"{sum(r.within for r in rows)} of {len(rows)} rows within 16u / conditioning "
            f"({loose} of them with a tolerance ≥ 1: the compounded conditioning guarantees "
            f"no digit there); F_23 on the coupler stays within "
            f"{max(r.error for r in par):.0e} with P {deltas[-1]:g}° from the rocker's line "
            f"(the polygon takes moments, not the far meeting point), and within "
            f"{max(r.error for r in tog):.0e} at {befores[-1]:g}° before the toggle, where the "
            f"forces grow as 1/sin μ; the crank torque near the dead "
            f"centre keeps {max(r.error for r in t2):.0e} at {thetas[-1]:g}° (conditioning "
            f"{min(r.conditioning for r in t2):.0e})")
    return ChapterStudy("Force polygons", "closed forms at 50 digits of the solved positions",
                        "conditioning", head, tuple(rows), path)
