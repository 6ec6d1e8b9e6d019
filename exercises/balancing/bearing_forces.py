"""The forces on a rotor's bearings as the books ask them ("the dynamic forces on the
bearings", "the out-of-balance forces at the bearings"), in N where the speed is given.

- A rotor balanced in two planes: each plane's balancing product turning at ω, m·r·ω², is
  the out-of-balance force the masses put on that plane before the balance masses are
  added, opposite the balancing mass (``force_A``); said to be on a bearing only where the
  file says the plane is a bearing's (``[[balance]] bearing = true``).
- A rotor with no balancing plane, its bearings named in ``[rotor] bearings = { L = 0,
  R = 800 }``: the out-of-balance force R and couple C read off its polygons are shared
  between the bearings by moments about one of them, F_R = ω²·C_L/(z_R − z_L) with
  C_L = C + R·(z_C − z_L), and F_L = ω²·R − F_R (``force_L``, ``force_R``).

Each is held to the reference's two-plane sums (:func:`two_planes`, the bearings' loads the
products' opposites): Σ mᵢrᵢ(zᵢ − z_L)/(z_R − z_L) and Σ mᵢrᵢ(z_R − zᵢ)/(z_R − z_L).
"""

from __future__ import annotations

import math

from tarsim.constructions.narration import numeral, words
from tarsim.constructions.reference.balance import two_planes
from ..checked import Checked

__all__ = ["bearing_checked", "bearing_lines", "bearing_misses", "plane_force_checked",
           "plane_force_lines"]

AGREE = 1e-12
"""How near (relative to the sizes summed) a bearing's force must come to its sum."""


def _angle(v: tuple[float, float]) -> float:
    return math.degrees(math.atan2(v[1], v[0])) % 360.0


def _loads(s) -> dict[str, tuple[float, float]]:
    """Each plane's out-of-balance load (kg·m, × ω² for N): its balancing product reversed,
    as the polygons drew it."""
    return {p.name: tuple(-c for c in s.balance.product(p.name))
            for p in s.exercise.rotor.planes if p.name not in s.balance.none}


_ON = {True: "the out-of-balance force on a bearing in plane {plane}: m·r·ω² = {force} N at "
             "{angle}° (ω = {speed} rad/s)",
       False: "the out-of-balance force in plane {plane}, the masses' force and couple shared "
              "between the two planes: m·r·ω² = {force} N at {angle}° (ω = {speed} rad/s)"}
"""Each plane's force, on a bearing where the file says the plane is a bearing's."""


def plane_force_lines(s) -> list[str]:
    """A two-plane balance's force in each plane, where the speed is given (a rotor's: an
    engine's balance planes are its wheels, whose hammer blow is asked), said to be on a
    bearing where the file names the plane a bearing's."""
    r = s.exercise.rotor
    if len(r.planes) != 2 or r.speed is None or s.exercise.engine is not None:
        return []
    bearings = s.exercise.bearing_planes
    return [words(_ON[name in bearings], plane=name,
                  force=numeral(math.hypot(*v) * r.speed ** 2), angle=numeral(_angle(v), ".2f"),
                  speed=numeral(r.speed)) for name, v in _loads(s).items()]


def plane_force_checked(s) -> dict[str, Checked]:
    """``force_<plane>`` (N): each plane's balancing product × ω², beside the closed form's."""
    r = s.exercise.rotor
    if len(r.planes) != 2 or r.speed is None or s.exercise.engine is not None:
        return {}
    w2 = r.speed ** 2
    return {f"force_{name}": Checked(
        {"value": math.hypot(*v) * w2, "unit": "N", "angle_deg": _angle(v)},
        {"value": math.hypot(*s.expected[name]) * w2}, method="couple and force polygons")
        for name, v in _loads(s).items()}


def _drawn(r, u) -> dict[str, tuple[float, float]]:
    """Each bearing's load (kg·m) from the polygons' resultant force R and couple C."""
    (a, za), (b, zb) = r.bearings
    force = u.resultant("force")
    if "couple" in u.closing:
        c, about = u.resultant("couple"), u.about
    else:                   # every mass in one plane: no couple about it
        c, about = (0.0, 0.0), r.masses[0].plane
    at_a = tuple(c[i] + force[i] * (about - za) for i in (0, 1))
    on_b = tuple(v / (zb - za) for v in at_a)
    return {a: tuple(force[i] - on_b[i] for i in (0, 1)), b: on_b}


def _sums(r) -> dict[str, tuple[float, float]]:
    """Each bearing's load (kg·m) by the closed form: the two-plane products reversed."""
    (a, za), (b, zb) = r.bearings
    in_a, in_b = two_planes(r.masses, za, zb)
    return {a: (-in_a[0], -in_a[1]), b: (-in_b[0], -in_b[1])}


def _size(r) -> float:
    """The size a bearing's load rounds at: Σ|mᵢrᵢ|·(1 + (|zᵢ| + |z_L|)/(z_R − z_L))."""
    (_, za), (_, zb) = r.bearings
    return math.fsum(m.mass * m.radius * (1 + (abs(m.plane) + abs(za)) / abs(zb - za))
                     for m in r.masses)


def bearing_lines(r, u, length) -> list[str]:
    """Each named bearing's out-of-balance force (N), where ``[rotor] bearings`` names them."""
    if not r.bearings:
        return []
    w2 = r.speed ** 2
    places = dict(r.bearings)
    return [words("bearing {name} at {place}: the out-of-balance force {force} N at {angle}°, "
                  "the force and the couple shared between the bearings by moments",
                  name=name, place=length(places[name]), force=numeral(math.hypot(*v) * w2),
                  angle=numeral(_angle(v), ".2f")) for name, v in _drawn(r, u).items()]


def bearing_checked(r, u) -> dict[str, Checked]:
    """``force_<bearing>`` (N) with its angle, beside the closed form's."""
    if not r.bearings:
        return {}
    w2, want = r.speed ** 2, _sums(r)
    return {f"force_{name}": Checked(
        {"value": math.hypot(*v) * w2, "unit": "N", "angle_deg": _angle(v),
         "plane": dict(r.bearings)[name]},
        {"value": math.hypot(*want[name]) * w2}, method="force and couple polygons' moments")
        for name, v in _drawn(r, u).items()}


def bearing_misses(r, u) -> list[tuple[str, float]]:
    """Each bearing's load from the polygons against its sum, relative to the sizes summed."""
    if not r.bearings:
        return []
    want, size = _sums(r), _size(r)
    return [(f"bearing {name}", miss) for name, v in _drawn(r, u).items()
            if (miss := math.dist(v, want[name]) / size) > AGREE]
