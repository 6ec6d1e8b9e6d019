"""The independent reference for a cam's profile: the pitch curve, the profile and its
checks in closed form.

The cam turns through θ in the sense σ (+1 counter-clockwise). In the frame that stands
still, the follower's trace point (knife edge or roller centre) is at P(θ) and moves along
u(θ):

- a **translating** follower, its line a distance e right of the cam centre (e < 0 left):
  P = (e, s₀ + y), u = (0, 1), s₀ = √(R_p² − e²), R_p the prime radius;
- an **oscillating** follower on a pivot A with an arm l: P = A + l·(cos ψ, sin ψ),
  ψ = ψ₀ + κ·y/l, u = κ·J(cos ψ, sin ψ), where κ = ±1 turns the arm away from the cam and y
  is the arc the trace point swings through.

Held in the cam's frame (the inversion) the point is p = R(−σθ)·P. Its derivatives are
those of P with the turning added, q₁ = P′ − σJP and q₂ = P″ − 2σJP′ − P (J turns +90°),
so the pitch curve's radius of curvature is ρ = |q₁|³ / (−σ q₁ × q₂) (positive where it is
convex), its normal σJq₁/|q₁| outward, the roller profile p − r·n, and the pressure angle
the angle between that normal and u. A flat face square to a translating follower's
motion touches at x = σy′ on the face, and the profile's radius there is r_b + y + y″.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .cam_laws import Motion, motion

__all__ = ["Follower", "Station", "follower_motion", "segment_motion", "station", "station_at",
           "pressure_angle_translating"]

Vec = tuple[float, float]


@dataclass(frozen=True)
class Follower:
    """The follower: ``kind`` knife-edge, roller or flat-faced, its roller ``radius`` (m),
    and how it moves: ``offset`` e for a translating one, or a ``pivot`` (m, from the cam
    centre) and ``arm`` for an oscillating one."""

    kind: str = "knife-edge"
    radius: float = 0.0
    offset: float = 0.0
    pivot: Vec | None = None
    arm: float = 0.0

    @property
    def oscillating(self) -> bool:
        """The follower swings on a pivot."""
        return self.pivot is not None


@dataclass(frozen=True)
class Station:
    """The cam's profile at one cam angle, in the cam's frame (m, rad)."""

    theta: float
    pitch: Vec
    """The trace point: the roller's centre, the knife edge, the face's foot on its axis."""
    profile: Vec
    """Where the follower touches the cam."""
    normal: Vec
    """The profile's outward unit normal at the touch."""
    motion: Vec
    """The way the follower's trace point moves as it lifts (unit)."""
    pressure_angle: float
    """Between the normal and the follower's motion (rad, signed); 0 for a flat face."""
    rho: float
    """The radius of curvature of the pitch curve (for a flat face, of the profile);
    positive where convex."""
    face_offset: float = 0.0
    """A flat face: the touch's distance along the face from the follower's axis (m)."""


def follower_motion(segments, theta: float) -> Motion:
    """The follower's lift (from the base circle) and its coefficients at cam angle θ;
    ``segments`` in turn, each with its kind (rise, dwell, return), angle, lift and law."""
    theta %= 2 * math.pi
    lift, start = 0.0, 0.0
    for s in segments:
        # At a join (to rounding) the later segment's: its y″ where y″ jumps.
        if theta < start + s.angle - 1e-12 or s is segments[-1]:
            return segment_motion(s, lift, theta - start)
        lift += s.lift if s.kind == "rise" else -s.lift if s.kind == "return" else 0.0
        start += s.angle
    raise AssertionError("unreachable")


def segment_motion(s, height: float, t: float, *, piece: int | None = None) -> Motion:
    """The follower's lift and its coefficients ``t`` (rad) into the segment ``s``, which
    starts at ``height`` above the base circle; ``piece`` as :func:`.cam_laws.motion` takes
    it (a piece's own formula, for its one-sided limits)."""
    if s.kind == "dwell":
        return Motion(height, 0.0, 0.0, 0.0)
    m = motion(s.law, s.lift, s.angle, t, rise=s.kind == "rise", blend=s.blend,
               split=s.split, piece=piece)
    base = height - (s.lift if s.kind == "return" else 0.0)
    return Motion(base + m.y, m.y1, m.y2, m.y3)


def _turn(v: Vec, a: float) -> Vec:
    c, s = math.cos(a), math.sin(a)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])


def _j(v: Vec) -> Vec:
    return (-v[1], v[0])


def _cross(a: Vec, b: Vec) -> float:
    return a[0] * b[1] - a[1] * b[0]


def prime_radius(base_radius: float, f: Follower) -> float:
    """The prime circle: the base circle grown by the roller's radius."""
    return base_radius + (f.radius if f.kind == "roller" else 0.0)


def arm_start(base_radius: float, f: Follower) -> tuple[float, float]:
    """An oscillating follower's arm angle ψ₀ at rest on the prime circle, and κ, the sense
    of its swing away from the cam.

    The roller's centre rests where the arm's circle about the pivot cuts the prime circle,
    on the counter-clockwise side of the line from the cam centre to the pivot.

    Raises
    ------
    ValueError
        If the arm cannot reach the prime circle, or lies along the line to the pivot.
    """
    ax, ay = f.pivot
    d, r, arm = math.hypot(ax, ay), prime_radius(base_radius, f), f.arm
    if not abs(d - arm) < r < d + arm:
        raise ValueError(f"an arm of {arm:g} m on a pivot {d:g} m from the cam centre cannot "
                         f"reach the prime circle (radius {r:g} m)")
    # The cut of |C| = r and |C − A| = l, on the left of O → A.
    along = (d * d + r * r - arm * arm) / (2 * d)
    up = math.sqrt(max(r * r - along * along, 0.0))
    ux, uy = ax / d, ay / d
    c = (along * ux - up * uy, along * uy + up * ux)
    psi0 = math.atan2(c[1] - ay, c[0] - ax)
    e = (math.cos(psi0), math.sin(psi0))
    grow = f.pivot[0] * _j(e)[0] + f.pivot[1] * _j(e)[1]
    if abs(grow) < 1e-9 * d:
        raise ValueError("the arm lies along the line to the cam centre: it cannot lift")
    return psi0, math.copysign(1.0, grow)


def _trace(base_radius: float, f: Follower, m: Motion) -> tuple[Vec, Vec, Vec, Vec]:
    """P, P′, P″ and u in the still frame."""
    if f.oscillating:
        psi0, kappa = arm_start(base_radius, f)
        psi = psi0 + kappa * m.y / f.arm
        e = (math.cos(psi), math.sin(psi))
        je = _j(e)
        p = (f.pivot[0] + f.arm * e[0], f.pivot[1] + f.arm * e[1])
        p1 = (kappa * m.y1 * je[0], kappa * m.y1 * je[1])
        bend = m.y1 * m.y1 / f.arm
        p2 = (kappa * m.y2 * je[0] - bend * e[0], kappa * m.y2 * je[1] - bend * e[1])
        return p, p1, p2, (kappa * je[0], kappa * je[1])
    rp = prime_radius(base_radius, f)
    s0 = math.sqrt(rp * rp - f.offset * f.offset)
    return (f.offset, s0 + m.y), (0.0, m.y1), (0.0, m.y2), (0.0, 1.0)


def station(segments, base_radius: float, f: Follower, sigma: float, theta: float) -> Station:
    """The profile at cam angle ``theta`` for a cam turning in the sense ``sigma``."""
    return station_at(follower_motion(segments, theta), base_radius, f, sigma, theta)


def station_at(m: Motion, base_radius: float, f: Follower, sigma: float, theta: float
               ) -> Station:
    """The profile at cam angle ``theta`` where the follower's motion is ``m``."""
    back = -sigma * theta
    if f.kind == "flat-faced":
        touch = (sigma * m.y1, base_radius + m.y)
        foot = (0.0, base_radius + m.y)
        up = _turn((0.0, 1.0), back)
        return Station(theta, _turn(foot, back), _turn(touch, back), up, up, 0.0,
                       base_radius + m.y + m.y2, sigma * m.y1)
    p, p1, p2, u = _trace(base_radius, f, m)
    q1 = (p1[0] - sigma * _j(p)[0], p1[1] - sigma * _j(p)[1])
    jp1 = _j(p1)
    q2 = (p2[0] - 2 * sigma * jp1[0] - p[0], p2[1] - 2 * sigma * jp1[1] - p[1])
    speed = math.hypot(*q1)
    n = (sigma * _j(q1)[0] / speed, sigma * _j(q1)[1] / speed)
    bend = -sigma * _cross(q1, q2)
    rho = speed ** 3 / bend if bend else math.inf
    r = f.radius if f.kind == "roller" else 0.0
    touch = (p[0] - r * n[0], p[1] - r * n[1])
    # The pressure angle: from the follower's motion u to the normal the cam pushes along.
    # Signed as the textbook's tan φ = (y′ − σe)/(s₀ + y): positive when the cam's push
    # leans the follower's way of turning.
    angle = sigma * math.atan2(_cross(u, n), u[0] * n[0] + u[1] * n[1])
    return Station(theta, _turn(p, back), _turn(touch, back), _turn(n, back), _turn(u, back),
                   angle, rho)


def pressure_angle_translating(y: float, y1: float, base_radius: float, f: Follower,
                               sigma: float) -> float:
    """The textbook formula for a translating roller or knife edge:
    tan φ = (y′ − σe) / (s₀ + y), s₀ = √(R_p² − e²)."""
    rp = prime_radius(base_radius, f)
    s0 = math.sqrt(rp * rp - f.offset * f.offset)
    return math.atan((y1 - sigma * f.offset) / (s0 + y))
