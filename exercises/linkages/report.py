"""Put the construction beside the analytic solution: the numbers `tarsim check` prints.

Position errors are relative to the size of the mechanism (its largest distance
between two points), since a point near the origin has no size of its own.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from tarsim.constructions.reference import solver
from tarsim.constructions.reference.rotatability import GrashofResult, grashof_class
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.linkages.assembly_record import Assembly
from tarsim.constructions.model import Mechanism

__all__ = ["PointCheck", "PositionCheck", "check_positions", "format_check", "describe_grashof"]


@dataclass(frozen=True)
class PointCheck:
    """One joint: where the compass put it, where the vector loops put it."""

    name: str
    construction: tuple[float, float]
    analytic: tuple[float, float]
    rel_error: float
    conditioning: float


@dataclass(frozen=True)
class PositionCheck:
    """Every joint of one position, with the mechanism's mobility and Grashof class."""

    mechanism: Mechanism
    assembly: Assembly
    points: tuple[PointCheck, ...]
    size: float
    mobility: tuple[int, int, int, int]
    grashof: GrashofResult | None

    @property
    def worst(self) -> float:
        """The largest relative error over all joints."""
        return max(p.rel_error for p in self.points)


def check_positions(mech: Mechanism) -> PositionCheck:
    """Assemble ``mech`` by compass, solve it by vector loops, and compare every joint."""
    asm = assemble(mech)
    reference = solver.solve_positions(mech)
    names = mech.point_names
    xy = {n: asm.xy(n) for n in names}
    size = asm.size
    rows = []
    for n in names:
        c, a = xy[n], reference[n]
        step = asm[asm.points[n]]
        rows.append(PointCheck(n, c, a, math.dist(c, a) / size, step.conditioning))
    return PositionCheck(mech, asm, tuple(rows), size, mech.mobility(), grashof_class(mech))


def format_check(check: PositionCheck) -> str:
    """The report as text: a heading, one row per joint, and the verdict."""
    m = check.mechanism
    u = m.units
    d = m.drive
    k = u.metres
    dof, n, f1, f2 = check.mobility
    angle = u.angle_brief(d.angle)
    lines = [f"{m.name}  ({m.source})" if m.source else m.name,
             f"θ{d.link} = {angle}    DOF = {dof}  (Grübler: 3({n} − 1) − 2·{f1} − {f2})"]
    if check.grashof is not None:
        lines.append(f"Grashof: {describe_grashof(check.grashof, u)}")
    head = f"by construction ({u.length})"
    ref = f"analytic ({u.length})"
    lines.append("")
    lines.append(f"{'point':<7}{head:<30}{ref:<30}{'rel. error':>11}{'cond.':>9}")
    for p in check.points:
        (cx, cy), (ax, ay) = m.in_file_axes(p.construction), m.in_file_axes(p.analytic)
        c = _minus(f"({cx / k:.6f}, {cy / k:.6f})")
        a = _minus(f"({ax / k:.6f}, {ay / k:.6f})")
        lines.append(f"{p.name:<7}{c:<30}{a:<30}{p.rel_error:>11.1e}{p.conditioning:>9.3g}")
    lines.append("")
    lines.append(f"largest relative error {check.worst:.1e} "
                 f"(relative to the mechanism's size, {u.length_text(check.size)})")
    return "\n".join(lines)


def describe_grashof(g: GrashofResult, units) -> str:
    """One line: the class, the sums that decide it, and the shortest link."""
    ls = sorted(g.lengths)
    sl, pq = ls[0] + ls[3], ls[1] + ls[2]
    rel = "=" if g.kind == "change-point" else ("<" if sl < pq else ">")
    return (f"{g.kind}  (s + l = {units.length_text(sl)} {rel} p + q = {units.length_text(pq)};"
            f" shortest is link {g.shortest})")


def _minus(text: str) -> str:
    """Numbers set with a true minus (−), as every other output of tarsim sets them."""
    return text.replace("-", "−")
