"""A spur gear's teeth drawn by the involute's construction, for the mesh figure.

Each flank is an involute of the base circle: at radius r its pressure angle φ has
cos φ = r_b / r, and its polar angle runs inv φ = tan φ − φ from where the string leaves
the base circle. The tooth is half the circular pitch thick at the standard pitch circle
(π·m/2, an angle π/N about the centre), so at radius r its half-angle is
π/(2N) + inv φ_s − inv φ, φ_s the pitch circle's pressure angle. Below the base circle
the flank runs radially down to the root circle; the tip is the addendum circle's arc (or
a point, where the flanks meet first); the teeth stand on the root circle's arcs.
Angles are counter-clockwise from +x about the gear's centre, lengths in metres.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["Teeth", "inv", "roll_angle"]

_FLANK = 48
"""Points along each involute flank, equally spaced along it: on a 10 mm module drawn full
size, each chord stays within a micrometre of the curve."""

_LAND = 0.02
"""Greatest angle (rad) between the points of a tip or root land's arc."""


def inv(phi: float) -> float:
    """The involute function, the polar angle an involute turns through to pressure angle φ.

    >>> round(inv(math.radians(20.0)), 6)
    0.014904
    """
    return math.tan(phi) - phi


def roll_angle(rb: float, r: float) -> float:
    """The string's unwound angle (rad) where the involute of radius ``rb`` reaches ``r``:
    tan φ, cos φ = rb / r.

    >>> round(roll_angle(3.0, 5.0), 12)
    1.333333333333
    """
    return math.sqrt(max(r * r - rb * rb, 0.0)) / rb


@dataclass(frozen=True)
class Teeth:
    """A gear's teeth about ``centre``: ``count`` teeth, base, standard pitch, addendum and
    root radii; ``start`` the polar angle where one flank leaves the base circle and
    ``sense`` (+1 or −1) the way that flank turns as it rises (its tooth lies that way)."""

    centre: tuple[float, float]
    count: int
    base: float
    pitch: float
    addendum: float
    root: float
    start: float
    sense: float

    @property
    def first(self) -> float:
        """The polar angle of the middle of the tooth whose flank starts at ``start``."""
        phi_s = math.acos(self.base / self.pitch)
        return self.start + self.sense * (inv(phi_s) + math.pi / (2 * self.count))

    def half_angle(self, r: float) -> float:
        """Half the tooth's angular thickness at radius ``r`` (radial below the base circle).

        >>> t = Teeth((0.0, 0.0), 20, 0.09397, 0.1, 0.11, 0.0875, 0.0, 1.0)
        >>> round(t.half_angle(0.1), 9) == round(math.pi / 40, 9)
        True
        """
        phi_s = math.acos(self.base / self.pitch)
        phi = math.acos(self.base / r) if r > self.base else 0.0
        return math.pi / (2 * self.count) + inv(phi_s) - inv(phi)

    def tip(self) -> float:
        """The radius the flanks reach: the addendum circle, or where they meet (a pointed
        tooth), found by bisection."""
        if self.half_angle(self.addendum) > 0:
            return self.addendum
        lo, hi = max(self.base, self.root), self.addendum
        for _ in range(60):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if self.half_angle(mid) > 0 else (lo, mid)
        return lo

    def flank_radii(self) -> list[float]:
        """The radii a flank is drawn through, from the root circle to the tip: the root
        and (where it lies below) the base circle, then equal steps along the involute."""
        tip = self.tip()
        low = max(self.base, self.root)
        t0, t1 = roll_angle(self.base, low), roll_angle(self.base, tip)
        # equal arc lengths (s = r_b·t²/2) along the involute
        out = [self.base * math.sqrt(1 + t * t) for t in
               (math.sqrt(t0 * t0 + (t1 * t1 - t0 * t0) * i / _FLANK)
                for i in range(_FLANK + 1))]
        return ([self.root] if self.root < self.base else []) + out

    def outline(self, which: range) -> list[tuple[float, float]]:
        """The outline of the teeth numbered ``which`` (0 the first, counting the way
        ``sense`` turns), in order of angle: each tooth's flanks and tip, joined by the
        root circle's arcs."""
        middles = sorted(self.first + self.sense * k * 2 * math.pi / self.count
                         for k in which)
        radii = self.flank_radii()
        tip = radii[-1]
        polar: list[tuple[float, float]] = []          # (r, angle)
        for i, psi in enumerate(middles):
            if i:
                polar += _arc(self.root, middles[i - 1] + self.half_angle(self.root),
                              psi - self.half_angle(self.root))[1:-1]
            polar += [(r, psi - self.half_angle(r)) for r in radii]
            polar += _arc(tip, psi - self.half_angle(tip), psi + self.half_angle(tip))[1:-1]
            polar += [(r, psi + self.half_angle(r)) for r in reversed(radii)]
        cx, cy = self.centre
        return [(cx + r * math.cos(a), cy + r * math.sin(a)) for r, a in polar]


def _arc(r: float, a: float, b: float) -> list[tuple[float, float]]:
    """Points (r, angle) of the arc of radius ``r`` from ``a`` to ``b``, both ends included."""
    n = max(1, math.ceil(abs(b - a) / _LAND))
    return [(r, a + (b - a) * i / n) for i in range(n + 1)]
