"""Cams made of arcs, as the books work them: the circular-arc cam under a flat face and
the tangent cam under a roller, their dimensions and the follower's motion on the flank and
on the nose.

With r₁ the base circle, r₂ the nose, h the lift and α the angle of lift (the cam's turn
from the start of the lift to the apex), the nose centre stands d = r₁ + h − r₂ from O.

- **circular arc, flat face**: the flank's radius R from the triangle O P Q (P the flank's
  centre, 180° − α round from Q): (R − r₂)² = (R − r₁)² + d² + 2(R − r₁)·d cos α, so
  R = (r₁² + d² − r₂² − 2r₁d cos α)/2(r₁ − r₂ − d cos α); the face leaves the flank at
  sin φ = d sin α/(R − r₂). On the flank x = (R − r₁)(1 − cos θ), ẋ = ω(R − r₁) sin θ,
  ẍ = ω²(R − r₁) cos θ; on the nose x = r₂ + d cos(α − θ) − r₁, ẋ = ωd sin(α − θ),
  ẍ = −ω²d cos(α − θ).
- **tangent cam, roller r**: d cos α = r₁ − r₂ (the flanks tangent to both circles, their
  normal at α); the roller leaves the flank at tan φ = d sin α/(r₁ + r). On the flank
  x = (r₁ + r)(1 − cos θ)/cos θ, ẋ = ω(r₁ + r) sin θ/cos²θ,
  ẍ = ω²(r₁ + r)(2 − cos²θ)/cos³θ; on the nose, with ψ = α − θ and L = r₂ + r, the roller's
  centre is a slider-crank's piston: x = d cos ψ + √(L² − d² sin²ψ) − (r₁ + r),
  ẋ = ωd(sin ψ + d sin 2ψ/2√(L² − d² sin²ψ)),
  ẍ = −ω²d(cos ψ + (L²d cos 2ψ + d³ sin⁴ψ)/(L² − d² sin²ψ)^{3/2}).

- **circular arc, roller r (or knife edge, r = 0)**: on the flank the roller's centre is a
  slider-crank's piston, the crank OP = R − r₁ pointing away and the rod R + r: with
  k = R − r₁, L = R + r, S = √(L² − k² sin²θ), x = S − k cos θ − (r₁ + r),
  ẋ = ωk sin θ(1 − k cos θ/S), ẍ = ω²k(cos θ − k(S² cos 2θ + k² sin²θ cos²θ)/S³); it leaves
  the flank where its centre passes J = Q + (r₂ + r)·n, n the normal where flank meets nose
  (φ = α − the angle of OJ); on the nose, as under a tangent cam's roller.
- **eccentric disc, roller r or knife edge (r = 0)**: the whole turn is the nose: a disc
  of radius r₂ turning e = d off its centre drives the roller's centre as a slider-crank's
  piston, crank e and rod r₂ + r, from the lowest place (θ = 0, r₁ = r₂ − e) to the apex
  at α = 180°; the nose's formulas above hold with φ = 0.

The motion is symmetrical about the apex: the return mirrors the lift.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["ArcCam", "arc_motion"]


@dataclass(frozen=True)
class ArcCam:
    """A symmetrical cam of arcs (m, rad): ``kind`` "circular arc", "tangent" or
    "eccentric", under a flat face (``flat``) or a roller (``roller`` its radius, 0 for a
    knife edge)."""

    kind: str
    base: float
    nose: float
    lift: float
    alpha: float
    roller: float = 0.0
    flat: bool = False

    @property
    def d(self) -> float:
        """The distance from the cam's centre to the nose's."""
        return self.base + self.lift - self.nose

    @property
    def flank_radius(self) -> float:
        """A circular-arc cam's flank radius R (inf for a tangent cam's straight flank)."""
        if self.kind != "circular arc":
            return math.inf
        r1, r2, d, c = self.base, self.nose, self.d, math.cos(self.alpha)
        return (r1 * r1 + d * d - r2 * r2 - 2 * r1 * d * c) / (2 * (r1 - r2 - d * c))

    @property
    def phi(self) -> float:
        """The cam's turn over which the follower stays on the flank (rad)."""
        if self.kind == "eccentric":
            return 0.0
        if self.kind == "tangent":
            return math.atan2(self.d * math.sin(self.alpha), self.base + self.roller)
        if self.flat:
            return math.asin(self.d * math.sin(self.alpha) / (self.flank_radius - self.nose))
        big, a = self.flank_radius, self.alpha
        p = (-(big - self.base) * math.cos(a), -(big - self.base) * math.sin(a))
        gamma = math.atan2(-p[1], self.d - p[0])
        reach = self.nose + self.roller
        return a - math.atan2(reach * math.sin(gamma), self.d + reach * math.cos(gamma))


def arc_motion(cam: ArcCam, theta: float, omega: float, part: str | None = None
               ) -> tuple[float, float, float, str]:
    """The follower's lift, velocity and acceleration ``theta`` (rad) after the lift begins
    (0 to 2α, the return mirrored), the cam at ``omega`` (rad/s, its size), and the part it
    touches ("flank" or "nose"; on the join, the nose); ``part`` forces that part's formula
    (its one-sided value on the join).

    Examples
    --------
    A tangent cam whose lift begins 45° from the apex: leaving the base circle, the roller
    accelerates at ω²(r₁ + r).

    >>> cam = ArcCam("tangent", 0.03, 0.006, 0.024 / math.cos(math.pi / 4) - 0.024,
    ...              math.pi / 4, 0.015)
    >>> round(arc_motion(cam, 0.0, 10.0)[2], 12)
    4.5
    """
    back = theta > cam.alpha
    t = 2 * cam.alpha - theta if back else theta
    w = abs(omega)
    if part == "flank" or (part is None and t < cam.phi):
        if cam.kind == "tangent":
            k, c, s = cam.base + cam.roller, math.cos(t), math.sin(t)
            x, v, a = k * (1 - c) / c, w * k * s / c ** 2, w * w * k * (2 - c * c) / c ** 3
        elif cam.flat:
            k = cam.flank_radius - cam.base
            x, v, a = k * (1 - math.cos(t)), w * k * math.sin(t), w * w * k * math.cos(t)
        else:
            k, big = cam.flank_radius - cam.base, cam.flank_radius + cam.roller
            c, s = math.cos(t), math.sin(t)
            root = math.sqrt(big * big - (k * s) ** 2)
            x = root - k * c - cam.base - cam.roller
            v = w * k * s * (1 - k * c / root)
            a = w * w * k * (c - k * (root ** 2 * math.cos(2 * t) + (k * s * c) ** 2) / root ** 3)
        part = "flank"
    else:
        psi, d = cam.alpha - t, cam.d
        if not cam.flat:
            big = cam.nose + cam.roller
            root = math.sqrt(big * big - (d * math.sin(psi)) ** 2)
            x = d * math.cos(psi) + root - cam.base - cam.roller
            v = w * d * (math.sin(psi) + d * math.sin(2 * psi) / (2 * root))
            a = -w * w * d * (math.cos(psi) + (big * big * d * math.cos(2 * psi)
                                               + d ** 3 * math.sin(psi) ** 4) / root ** 3)
        else:
            x = cam.nose + d * math.cos(psi) - cam.base
            v, a = w * d * math.sin(psi), -w * w * d * math.cos(psi)
        part = "nose"
    return x, (-v if back else v), a, part
