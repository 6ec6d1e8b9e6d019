"""Position by compass against the analytic solver: run time, and error near toggle.

Run:  python benchmarks/position_accuracy.py

Part 1 times one position of each bundled example by construction (the recorded
compass acts) and by the analytic solver (closed-form guess + Newton on the full
loop equations), as medians of repeated runs in one process, and reports their
ratio and the largest disagreement.

Part 2 drives a four-bar towards its toggle (coupler and rocker collinear, where
the two arcs that locate B become tangent) and reports, for each distance from
toggle, the construction's conditioning and the disagreement between the two
solutions. The error should grow like eps / conditioning, never faster, and the
exact toggle should fail with a clear error rather than NaN.
"""

from __future__ import annotations

import math
import platform
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from benchmarks.bench.timing import median_time  # noqa: E402
from tarsim.constructions.reference import solver  # noqa: E402
from tarsim.constructions.linkages.assembly import assemble  # noqa: E402
from tarsim.constructions.errors import TarsimError  # noqa: E402
from tarsim.exercises.catalog import bundled  # noqa: E402
from tarsim.exercises.linkages.mechanism_file import load_mechanism, parse_mechanism  # noqa: E402
from tests.common import four_bar_toml  # noqa: E402


def disagreement(mech) -> tuple[float, float]:
    """The largest distance between compass and analytic joints, relative and absolute."""
    asm = assemble(mech)
    ref = solver.solve_positions(mech)
    names = mech.point_names
    size = max(math.dist(asm.xy(a), asm.xy(b)) for a in names for b in names)
    err = max(math.dist(asm.xy(n), ref[n]) for n in names) / size
    return err, min(s.conditioning for s in asm)


def part1() -> None:
    """Print one position by compass and by the solver: their times and disagreement."""
    print("## 1. One position: construction vs analytic (median of 200 runs)\n")
    print(f"{'example':<22}{'construction µs':>17}{'analytic µs':>13}{'ratio':>8}"
          f"{'max rel. error':>16}")
    for name, path in bundled().items():
        mech = load_mechanism(path)
        tc = median_time(lambda mech=mech: assemble(mech))
        ta = median_time(lambda mech=mech: solver.solve_positions(mech))
        err, _ = disagreement(mech)
        print(f"{name:<22}{tc:>17.1f}{ta:>13.1f}{tc / ta:>8.2f}{err:>16.1e}")




def part2() -> None:
    """Print the disagreement as the four-bar nears its toggle."""
    print("\n## 2. Approaching toggle: four-bar 100/AB/200 on 300 mm at θ2 = 180°\n")
    print("At θ2 = 180°, |O4A| = 400 mm; with AB = 200 + δ the arcs about A and O4 touch")
    print("at δ = 0 (coupler and rocker collinear).\n")
    print(f"{'δ (mm)':>10}{'conditioning':>15}{'rel. error':>13}{'eps/cond':>12}")
    for k in range(1, 15):
        delta = 10.0 ** (2 - k)
        mech = parse_mechanism(four_bar_toml(coupler=200 + delta, angle=180), "toggle.toml")
        try:
            err, cond = disagreement(mech)
        except TarsimError as e:
            print(f"{delta:>10.0e}  {type(e).__name__}: {e}")
            continue
        print(f"{delta:>10.0e}{cond:>15.2e}{err:>13.1e}{2.2e-16 / cond:>12.1e}")
    mech = parse_mechanism(four_bar_toml(coupler=200, angle=180), "toggle.toml")
    for label, fn in (("construction", assemble), ("analytic positions", solver.solve_positions),
                      ("analytic velocities", solver.solve)):
        try:
            fn(mech)
            print(f"exact toggle, {label}: solved (tangent arcs meet once)")
        except TarsimError as e:
            print(f"exact toggle, {label}: {type(e).__name__}: {e}")


if __name__ == "__main__":
    print(f"# Position accuracy and cost\n\nmachine: {platform.processor() or platform.machine()}, "
          f"{platform.system()}, Python {platform.python_version()}\n")
    part1()
    part2()
