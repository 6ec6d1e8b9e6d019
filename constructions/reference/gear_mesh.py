"""The independent reference for an involute mesh: the textbook formulas, nothing drawn.

With base radii r_b = r cos φ (φ the pressure angle the teeth are cut at), addendum radii
r_a and the centre distance C, the working pressure angle is φ′ = acos((r_b2 + r_b3)/C),
the path of contact √(r_a2² − r_b2²) + √(r_a3² − r_b3²) − C sin φ′, the arc of contact
that over cos φ′, and the contact ratio the path over the base pitch π m cos φ. An addendum
circle reaching past the other gear's tangency point, r_a > √(r_b² + (C sin φ′)²), is
interference. The circular pitch is π m. A drawn tooth point at radius ρ lies on the
involute from its start S when its polar angle is S's less inv φ_ρ = tan φ_ρ − φ_ρ,
φ_ρ = acos(r_b/ρ).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["MeshReference", "mesh_reference", "involute_miss", "least_teeth"]


@dataclass(frozen=True)
class MeshReference:
    """The mesh's numbers by formula (lengths in m, angles in rad); ``interference`` names
    each gear whose tips reach past the other's tangency point into its flank."""

    pressure_angle: float
    circular_pitch: float
    path: float
    arc: float
    base_pitch: float
    contact_ratio: float
    interference: tuple[int, ...]


def mesh_reference(module: float, teeth: tuple[int, int], numbers: tuple[int, int],
                   pressure_angle_deg: float, addendum: float, centre_distance: float | None
                   ) -> MeshReference:
    """The mesh of gears ``numbers`` (teeth ``teeth``, one ``module`` in m)."""
    phi = math.radians(pressure_angle_deg)
    r = [module * n / 2 for n in teeth]
    rb = [x * math.cos(phi) for x in r]
    ra = [x + addendum * module for x in r]
    c = centre_distance if centre_distance is not None else r[0] + r[1]
    working = math.acos((rb[0] + rb[1]) / c)
    reach = c * math.sin(working)                   # T2T3, the whole line of action
    path = sum(math.sqrt(a * a - b * b) for a, b in zip(ra, rb)) - reach
    pitch = math.pi * module * math.cos(phi)
    over = tuple(numbers[k] for k in range(2)
                 if ra[k] > math.sqrt(rb[k] ** 2 + reach ** 2) * (1 + 1e-12))
    return MeshReference(working, math.pi * module, path, path / math.cos(working), pitch,
                         path / pitch, over)



def involute_miss(point: tuple[float, float], centre: tuple[float, float], base: float,
                  start: float) -> float:
    """How far (m, along the arc at its radius) a drawn point lies off the involute that
    starts at angle ``start`` on the base circle of radius ``base`` about ``centre``."""
    dx, dy = point[0] - centre[0], point[1] - centre[1]
    rho = math.hypot(dx, dy)
    phi = math.acos(min(1.0, base / rho))
    want = start - (math.tan(phi) - phi)
    return rho * abs(math.remainder(math.atan2(dy, dx) - want, math.tau))


def least_teeth(ratio: float, pressure_angle_deg: float, addendum: float = 1.0) -> int:
    """The fewest teeth a pinion may have, meshing with a gear ``ratio`` times as big, for
    no interference: N ≥ 2k/((1 + 2G) sin²φ) · (G + √(G² + (1 + 2G) sin²φ))."""
    s2 = math.sin(math.radians(pressure_angle_deg)) ** 2
    g = ratio
    return math.ceil(2 * addendum / ((1 + 2 * g) * s2) * (g + math.sqrt(g * g + (1 + 2 * g) * s2))
                     - 1e-9)
