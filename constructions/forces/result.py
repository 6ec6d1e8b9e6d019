"""What the force polygons found: each joint force, each block's couple, the driving torque
and the engine's efforts, with the steps each was read off; and each link as a free body,
every force on it gathered from the polygons, for the free-body figure.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..model import Mechanism
from ..record import Ref

__all__ = ["Forces", "free_bodies"]

Vec = tuple[float, float]


@dataclass
class Forces:
    """The drawn force analysis: each joint force (N, on link ``on`` from ``by``) as read off
    its polygon, each block's couple (N·m), the driving torque (N·m, CCW +), the scale, and
    the steps that are each answer."""

    scale: float
    joints: dict[str, Vec] = field(default_factory=dict)
    couples: dict[str, float] = field(default_factory=dict)
    torque: float = 0.0
    refs: dict[str, tuple[Ref, ...]] = field(default_factory=dict)
    inertia: dict[int, tuple[Vec, float]] = field(default_factory=dict)
    """Each massive link's inertia force (N) and couple (N·m), as read off the polygon."""
    every: tuple[Ref, ...] = ()
    """Every step of the analysis, for its figure and its steps: each answer shows it all."""
    loads: dict[int, list[tuple[Vec, Vec, float, str]]] = field(default_factory=dict)
    """Each moving link's known loads (where, force N, couple N·m, name): its inertia force
    and couple, its weight, the external forces and couples."""
    efforts: dict[str, float] = field(default_factory=dict)
    """The engine's efforts as the textbooks name them (:class:`~.asks.Effort`)."""
    bodies: dict[int, list[tuple[Vec, Vec, float, str]]] = field(default_factory=dict)
    """Each moving link as a free body: every force on it (where, force N, couple N·m, its
    name), the loads and the joints' forces as the polygons found them."""
    rounding: dict[str, float] | None = field(default_factory=dict)
    """What the rounding of the inertia loads read off the acceleration polygon makes of
    each answer (N, N·m), by :mod:`~.rounding`; None where it is without bound."""


def free_bodies(mech: Mechanism, out: Forces, at, known) -> dict[int, list]:
    """Every force on each moving link: its loads, each joint's force on it (F_ab on b, its
    reaction on a) and each block's couple, with the driving torque on the input."""
    where = {f"F_{by}{on}": point for point, by, on in mech.pin_pairs}
    where |= {f"F_{s.guide_link}{s.link}": s.point for s in mech.slides}
    bodies = {k: list(v) for k, v in known.items()}
    for name, f in out.joints.items():
        by, on = int(name[2]), int(name[3])
        p = at[where[name]]
        if on != 1:
            bodies[on].append((p, f, 0.0, name))
        if by != 1:
            bodies[by].append((p, (-f[0], -f[1]), 0.0, f"F_{on}{by}"))
    for name, m in out.couples.items():
        by, on = int(name[2]), int(name[3])
        p = at[where[f"F_{by}{on}"]]
        bodies[on].append((p, (0.0, 0.0), m, name))
        if by != 1:
            bodies[by].append((p, (0.0, 0.0), -m, f"T_{on}{by}"))
    d = mech.drive.link
    bodies[d].append((at[mech.link(d).names[0]], (0.0, 0.0), out.torque, f"T{d}"))
    return bodies
