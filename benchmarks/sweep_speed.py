"""A turn of the crank at once: the vectorised analytic solver against the scalar loop and peers.

Run:  python benchmarks/sweep_speed.py [--positions 3600] [--repeat 15]

The bundled four-bar (exercises/catalog/four-bar.toml: O2A 100, AB 250, O4B 200,
O2O4 300 mm, ω2 = 10 rad/s) is solved at ``--positions`` equal steps of the crank,
positions, velocities and accelerations of every point, in one run:

- ``solve_turn``: tarsim's analytic solver vectorised over the positions
  (constructions/reference/turn.py);
- ``sweep_exercise``: all of what ``tarsim sweep`` computes around ``solve_turn`` (its
  curves, extremes refined, the stated position constructed and checked), B's curves
  read as the columns it keeps them in; and again with its steps then made one by one
  as ``Sample`` objects, which it makes only when they are first read (the files and
  the page read them: 3600 steps cost some 5 ms);
- the scalar loop: ``solver.solve`` once per position, as the sweep did before;
- pylinkage (``Mechanism.step_fast_with_kinematics``, its fastest path with
  velocities and accelerations): not a dependency of tarsim; skipped with one line
  if it is not installed (``pip install pylinkage``). Without numba (an optional
  dependency of pylinkage, said in a line) its kernels run as plain Python;
- a plain numpy closed form of this one four-bar (circle cut, then the 2 × 2
  velocity and acceleration loops by Cramer's rule): the floor for a solver that
  knows the mechanism in advance.

It prints the machine (cores, CPU, Python, numpy, load average), the median time of
``--repeat`` runs of each (the scalar loop: of at most 3), in ms for the whole turn
and µs per position, the ratios to ``solve_turn``, and how far each answer for B
(position, velocity, acceleration) lies from the scalar solver's; then how many times
pylinkage's time ``sweep_exercise`` is, in the same run (the target: 5).
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import os
import platform
import statistics
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import tarsim  # noqa: E402
from tarsim.constructions.reference import solver  # noqa: E402
from tarsim.constructions.reference.turn import solve_turn  # noqa: E402
from tarsim.exercises.linkages.sweep import sweep_exercise  # noqa: E402


def machine() -> str:
    """One line: cores, CPU model, Python, numpy and the load average."""
    model = "unknown CPU"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    load = "%.2f %.2f %.2f" % os.getloadavg() if hasattr(os, "getloadavg") else "n/a"
    return (f"{os.cpu_count()} cores, {model}, {platform.machine()}, Python "
            f"{platform.python_version()}, numpy {np.__version__}, load average {load}")


def median_time(run, repeat: int) -> tuple[float, object]:
    """Median seconds of ``repeat`` calls of ``run`` (after one warm-up) and its last result."""
    out = run()
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = run()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def scalar_loop(mech, angles) -> dict[str, np.ndarray]:
    """B's position, velocity and acceleration by ``solver.solve`` at each angle."""
    rows = []
    for a in angles.tolist():
        kin = solver.solve(mech.with_drive(replace(mech.drive, angle=a)))
        rows.append((kin.points["B"], kin.velocities["B"], kin.accelerations["B"]))
    return {k: np.array([r[i] for r in rows]) for i, k in enumerate("pva")}


def closed_form(angles, *, crank, coupler, rocker, ground, omega, alpha):
    """The four-bar by hand, vectorised: B left of A → O4, then ω3, ω4 and α3, α4."""
    c, s = np.cos(angles), np.sin(angles)
    ax, ay = crank * c, crank * s
    dx, dy = ground - ax, -ay                       # A → O4
    d2 = dx * dx + dy * dy
    along = (d2 + coupler ** 2 - rocker ** 2) / (2 * d2)
    h = np.sqrt(coupler ** 2 / d2 - along ** 2)
    bx, by = ax + along * dx - h * dy, ay + along * dy + h * dx
    r3x, r3y, r4x, r4y = bx - ax, by - ay, bx - ground, by
    vax, vay = -omega * ay, omega * ax              # v_A + ω3 × r3 = ω4 × r4
    det = -r3y * r4x + r3x * r4y
    w3 = (-vax * r4x - vay * r4y) / det
    w4 = (-r3y * vay - r3x * vax) / det
    aax = -alpha * ay - omega ** 2 * ax
    aay = alpha * ax - omega ** 2 * ay
    rx = aax - w3 ** 2 * r3x + w4 ** 2 * r4x        # a_A + α3 × r3 − ω3² r3 = α4 × r4 − ω4² r4
    ry = aay - w3 ** 2 * r3y + w4 ** 2 * r4y
    a3 = (-rx * r4x - ry * r4y) / det
    a4 = (-r3y * ry - r3x * rx) / det
    return {"p": np.stack([bx, by], 1), "v": np.stack([-w4 * r4y, w4 * r4x], 1),
            "a": np.stack([-a4 * r4y - w4 ** 2 * r4x, a4 * r4x - w4 ** 2 * r4y], 1),
            "w": (w3, w4, a3)}


def pylinkage_run(angles, *, crank, coupler, rocker, ground, omega, alpha):
    """Turn pylinkage's four-bar through ``angles`` (equal steps), with its derivatives."""
    from pylinkage.mechanism import fourbar

    step = float(angles[1] - angles[0])
    mech = fourbar(crank=crank, coupler=coupler, rocker=rocker, ground=ground, omega=step,
                   initial_angle=float(angles[0]) - step, branch=1)
    mech.set_input_velocity(mech._driver_links[0], omega, alpha)
    pos, vel, acc = mech.step_fast_with_kinematics(iterations=len(angles))
    b = [j.id for j in mech.joints].index("coupler.1_rocker.0")
    return {"p": pos[:, b], "v": vel[:, b], "a": acc[:, b]}


def main(argv: list[str] | None = None) -> None:
    """Time the four ways and print the table."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--positions", type=int, default=3600)
    ap.add_argument("--repeat", type=int, default=15)
    args = ap.parse_args(argv)
    n = args.positions
    mech = tarsim.load("four-bar").mechanism
    d = mech.drive
    angles = d.angle + np.arange(n) * math.tau / n
    sizes = dict(crank=0.1, coupler=0.25, rocker=0.2, ground=0.3, omega=d.omega, alpha=d.alpha)
    print(machine())
    print(f"bundled four-bar, {n} positions with velocities and accelerations; medians of "
          f"{args.repeat} (the scalar loop: {min(3, args.repeat)})\n")

    def vectorised():
        t = solve_turn(mech, angles)
        return {"p": t.points["B"], "v": t.velocities["B"], "a": t.accelerations["B"]}

    exercise = tarsim.load("four-bar")

    def swept():
        """What ``tarsim sweep`` computes: the turn, its dead points and extremes refined,
        and the stated position constructed and checked against the curve; B's columns
        read as it keeps them."""
        c = sweep_exercise(exercise, n, of="V_B").curves
        return {"p": np.stack([c["x"], c["y"]], 1), "v": np.stack([c["vx"], c["vy"]], 1),
                "a": np.stack([c["ax"], c["ay"]], 1)}

    def stepped():
        """The same, its steps then made one by one, as the files and the page read them."""
        sweep = sweep_exercise(exercise, n, of="V_B")
        _ = sweep.samples           # made here, one by one
        c = sweep.curves
        return {"p": np.stack([c["x"], c["y"]], 1), "v": np.stack([c["vx"], c["vy"]], 1),
                "a": np.stack([c["ax"], c["ay"]], 1)}

    rows = [("tarsim solve_turn (vectorised)", *median_time(vectorised, args.repeat)),
            ("tarsim sweep_exercise (tarsim sweep's all)", *median_time(swept, args.repeat)),
            ("  the same, then its steps as Samples", *median_time(stepped, args.repeat))]
    rows.append(("tarsim solver.solve (scalar loop)",
                 *median_time(lambda: scalar_loop(mech, angles), min(3, args.repeat))))
    try:
        import pylinkage
    except ImportError:
        print("pylinkage is not installed (pip install pylinkage): its row is skipped")
    else:
        if importlib.util.find_spec("numba") is None:
            print("numba is not installed: pylinkage runs its njit kernels as plain Python")
        rows.append((f"pylinkage {pylinkage.__version__} step_fast_with_kinematics",
                     *median_time(lambda: pylinkage_run(angles, **sizes), args.repeat)))
    rows.append(("plain numpy closed form (this four-bar only)",
                 *median_time(lambda: closed_form(angles, **sizes), args.repeat)))
    scalar = rows[3][2]
    scale = {"p": 0.25, "v": mech.input_speed, "a": mech.input_acceleration}
    base = rows[0][1]
    print(f"{'':46}{'total ms':>10}{'µs/pos':>9}{'× vectorised':>14}   B vs scalar (p, v, a)")
    for name, seconds, out in rows:
        far = [float(np.max(np.abs(out[k] - scalar[k]))) / scale[k] for k in "pva"]
        print(f"{name:46}{seconds * 1e3:10.2f}{seconds / n * 1e6:9.2f}{seconds / base:14.3g}"
              f"   {far[0]:.0e}, {far[1]:.0e}, {far[2]:.0e}")
    peer = [seconds for name, seconds, _ in rows if name.startswith("pylinkage")]
    if peer:
        print(f"\npylinkage takes {peer[0] / rows[1][1]:.1f}× sweep_exercise's time "
              f"({peer[0] / rows[2][1]:.1f}× with its steps as Samples); the target is 5×")


if __name__ == "__main__":
    main()
