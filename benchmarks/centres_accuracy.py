"""Instant centres and velocities by construction against the analytic solver: time and error.

Run:  python benchmarks/centres_accuracy.py

Part 1 times, for each bundled example and the test files for curved and rolling
joints, the whole solve an exercise asks for
(assembly, every centre by Kennedy, the ω ratios, each velocity method) against
the analytic solution (positions, velocities and every centre from the velocity
fields), as medians in one process, with the worst relative error.

Part 2 turns a four-bar towards the position where crank and rocker are parallel,
where I13 runs off to infinity: the two Kennedy lines that cut it cross at a
vanishing angle. It reports the conditioning of I13 and its error, which should
stay below eps / conditioning, and the exact parallel position, where I13 is a
direction at infinity.
"""

from __future__ import annotations

import math
import platform
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from benchmarks.bench.stiff import parallel_angle  # noqa: E402
from benchmarks.bench.timing import median_time  # noqa: E402
from tarsim.constructions.reference import solver  # noqa: E402
from tarsim.constructions.reference.centres import centre_error, instant_centre, mechanism_size  # noqa: E402
from tarsim.constructions.linkages.assembly import assemble  # noqa: E402
from tarsim.constructions.linkages.kennedy import locate_centres  # noqa: E402
from tarsim.exercises.catalog import bundled  # noqa: E402
from tarsim.exercises.linkages.exercise_file import load_exercise  # noqa: E402
from tarsim.exercises.linkages.solution import solve_exercise  # noqa: E402
from tests.common import four_bar  # noqa: E402


def reference(mech) -> None:
    """The analytic side: kinematics and every centre from the velocity fields."""
    kin = solver.solve(mech)
    for i in mech.numbers:
        for j in mech.numbers:
            if i < j:
                try:
                    instant_centre(kin, i, j)
                except Exception:  # links at relative rest: the joint's centre holds
                    pass


def part1() -> None:
    """Print the centres of every bundled exercise beside the analytic ones, with run times."""
    print("Part 1: one position of each bundled exercise (medians of 30 runs, µs)")
    print(f"{'exercise':<34}{'construction':>14}{'analytic':>12}{'ratio':>8}"
          f"{'worst rel. error':>18}")
    data = Path(__file__).resolve().parents[1] / "tests" / "data"
    joints = {f"{n} (tests)": data / f"{n}.toml" for n in
              ("roller-cam", "curved-slot", "curved-guide-slider-crank", "rolling-wheel")}
    for name, path in {**bundled(), **joints}.items():
        ex = load_exercise(path, name.split()[0])
        if not ex.position_asks:
            continue                      # asks only of the mechanism as a whole
        t_c = median_time(lambda ex=ex: solve_exercise(ex), 30)
        t_a = median_time(lambda ex=ex: reference(ex.mechanism), 30)
        worst = max(q.rel_error for q in solve_exercise(ex).quantities.values())
        print(f"{name:<34}{t_c:>14.0f}{t_a:>12.0f}{t_c / t_a:>8.2f}{worst:>18.1e}")
    print("(the construction side also checks every number against its own analytic solve)")


def part2() -> None:
    """Print the error near a centre at infinity, as the Kennedy lines turn parallel."""
    theta0 = parallel_angle()
    print(f"\nPart 2: I13 of the peers.md four-bar as crank and rocker turn parallel "
          f"(at θ2 = {math.degrees(theta0):.10f}°)")
    print(f"{'θ2 − θ∥ (rad)':>14}{'conditioning':>14}{'|I13| (m)':>12}{'rel. error':>12}"
          f"{'eps/cond':>12}")
    for delta in (1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12):
        mech = four_bar(theta0 + delta, omega2=10.0)
        cs = locate_centres(assemble(mech))
        p, cond = cs.point(1, 3), cs.conditioning(1, 3)
        kin = solver.solve(mech)
        err = centre_error(p, instant_centre(kin, 1, 3), mechanism_size(kin))
        far = "∞" if p.is_at_infinity else f"{math.hypot(*p.xy):.3g}"
        bound = 2.2e-16 / cond if cond else math.inf
        print(f"{delta:>14g}{cond:>14.2e}{far:>12}{err:>12.1e}{bound:>12.1e}")


if __name__ == "__main__":
    print(f"machine: {platform.machine()}, {platform.system()}, Python {platform.python_version()}")
    part1()
    part2()
