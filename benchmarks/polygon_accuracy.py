"""Velocity and acceleration polygons against the analytic solver: time, error, stiff cases.

Run:  python benchmarks/polygon_accuracy.py

Part 1 times, for each mechanism with slots, curved slots and ternary links, the
assembly and both polygons (every tip, ω, α and Coriolis component) against the
analytic solution (positions by Newton, then the velocity and acceleration
systems), as medians in one process, with the worst relative error of every
tip, α and Coriolis component over a sweep of 12 positions.

Part 2 turns a four-bar towards its dead point (coupler and rocker in line), where
the two lines of b and b′ cross at a vanishing angle and ω4, α4 grow without
bound. It reports the conditioning of b′, the error, and eps / conditioning, the
error a drafting act can be held to; then the exact dead point, which is refused.

Part 3 turns the crank-shaper to the instants where Coriolis vanishes (the lever at
a limit, the crank on the line of centres) and reports the component's size.
"""

from __future__ import annotations

import math
import platform
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from benchmarks.bench.timing import median_time  # noqa: E402
from tarsim.constructions.reference import solver  # noqa: E402
from tarsim.constructions.linkages.acceleration_polygon import draw_acceleration_polygon  # noqa: E402
from tarsim.constructions.linkages.assembly import assemble  # noqa: E402
from tarsim.constructions.errors import AssemblyError  # noqa: E402
from tarsim.constructions.model import Drive  # noqa: E402
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon  # noqa: E402
from tarsim.exercises.linkages.mechanism_file import load_mechanism  # noqa: E402
from tests.common import (coupler_four_bar, crank_shaper, four_bar,  # noqa: E402
                          inverted_slider_crank, slotted_lever_p37)

DATA = Path(__file__).resolve().parents[1] / "tests" / "data"
EPS = sys.float_info.epsilon


def from_file(name: str, alpha: float):
    """A bundled mechanism, with its input's α set."""
    m = load_mechanism(DATA / f"{name}.toml")
    d = m.drive
    return lambda t: m.with_drive(Drive(d.link, t, d.omega or 1.0, alpha))


MECHANISMS = {
    "coupler four-bar": lambda t: coupler_four_bar(t, omega2=2.0),
    "crank-shaper": crank_shaper,
    "slotted lever P-37": lambda t: slotted_lever_p37(t, omega2=1.5, alpha2=-2.0),
    "inverted slider-crank": lambda t: inverted_slider_crank(t, omega2=-2.0, alpha2=3.0),
    "Watt six-bar": from_file("watt-six-bar", 1.5),
    "pin in a curved slot": from_file("curved-slot", 3.0),
    "roller on a circular cam": from_file("roller-cam", -4.0),
}


def polygons(mech):
    """Both polygons of ``mech``, drawn on one assembly."""
    asm = assemble(mech)
    vp = draw_velocity_polygon(asm)
    return asm, vp, draw_acceleration_polygon(asm, vp)


def worst_error(mech) -> float:
    """Worst relative error of every tip (and coincident point), α and Coriolis component."""
    _, _, ap = polygons(mech)
    kin = solver.solve(mech)
    d = mech.drive
    a_in = mech.input_acceleration
    worst = 0.0
    for key in ap.tips:
        if key in kin.accelerations:
            ref = kin.accelerations[key]
        else:
            i = len(key.rstrip("0123456789"))
            ref = solver.point_acceleration(kin, mech, int(key[i:]), key[:i])
        worst = max(worst, math.dist(ap.vector(key), ref) / max(math.hypot(*ref), a_in))
    scale = math.hypot(d.omega ** 2, d.alpha)
    for c, a in ap.rates.items():
        worst = max(worst, abs(a - kin.alphas[c]) / max(abs(kin.alphas[c]), scale))
    for joint in (*mech.slides, *mech.pin_arcs):
        if joint.point in ap.coriolis and joint.guide_link != 1:
            (px, py), (qx, qy) = (solver.point_velocity(kin, mech, j, joint.point)
                                  for j in (joint.link, joint.guide_link))
            w = kin.omegas[joint.guide_link]
            ref = (-2 * w * (py - qy), 2 * w * (px - qx))
            worst = max(worst, math.dist(ap.coriolis_of(joint.point), ref)
                        / max(math.hypot(*ref), a_in))
    return worst


def part1() -> None:
    """Print each mechanism's worst polygon error and the time to draw both polygons."""
    print("Part 1: assembly and both polygons vs the analytic solve (medians of 30 runs, µs)")
    print(f"{'mechanism':<28}{'polygons':>10}{'analytic':>10}{'ratio':>8}"
          f"{'worst rel. error (12 positions)':>33}")
    for name, build in MECHANISMS.items():
        mech = build(1.0)
        t_c = median_time(lambda mech=mech: polygons(mech), 30)
        t_a = median_time(lambda mech=mech: solver.solve(mech), 30)
        worst = 0.0
        for deg in range(0, 360, 30):
            try:
                worst = max(worst, worst_error(build(math.radians(deg))))
            except AssemblyError:
                pass
        print(f"{name:<28}{t_c:>10.0f}{t_a:>10.0f}{t_c / t_a:>8.2f}{worst:>33.1e}")


def dead_point() -> float:
    """θ2 where the triple-rocker O2A 200, AB 150, O4B 200, O2O4 300 mm has AB ∥ O4B."""
    return math.acos(1 / 16)


def toggle(theta: float):
    """The four-bar near its toggle, where the polygon's lines turn parallel."""
    return four_bar(theta, o4=(0.3, 0.0), crank=0.2, coupler=0.15, rocker=0.2, omega2=1.0)


def part2() -> None:
    """Print the polygon's error as the input nears the dead point."""
    print("\nPart 2: a triple-rocker turned towards its dead point θ* = acos(1/16)")
    print(f"{'θ* − θ2 (rad)':>14}{'cond(b′)':>12}{'α4 (rad/s²)':>14}{'rel. error':>12}"
          f"{'eps/cond':>11}")
    for off in (1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7):
        mech = toggle(dead_point() - off)
        asm, _, ap = polygons(mech)
        cond = asm[ap.tips["B"]].conditioning
        print(f"{off:>14.0e}{cond:>12.2e}{ap.rates[4]:>14.4g}{worst_error(mech):>12.1e}"
              f"{EPS / cond:>11.1e}")
    try:
        polygons(toggle(dead_point()))
        print("exact dead point: drawn (unexpected)")
    except AssemblyError as e:
        print(f"exact dead point: refused: {e}")


def part3() -> None:
    """Print the time per position of the polygons against the analytic solver's."""
    print("\nPart 3: crank-shaper where Coriolis vanishes (|2ω4·v_rel| in mm/s²)")
    r2, r1 = 0.18, 0.5
    for label, theta in (("crank on the line of centres", math.pi / 2),
                         ("lever at its right limit", -math.pi / 2 + math.acos(r2 / r1)),
                         ("lever at its left limit", -math.pi / 2 - math.acos(r2 / r1))):
        _, _, ap = polygons(crank_shaper(theta))
        a, b = (math.hypot(*ap.coriolis_of(p)) * 1e3 for p in "AB")
        print(f"  {label:<30} A: {a:.3g}   B: {b:.3g}")


if __name__ == "__main__":
    print(f"{platform.machine()}, {platform.python_implementation()} {platform.python_version()}")
    part1()
    part2()
    part3()
