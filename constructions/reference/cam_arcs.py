"""The independent reference for cams made of arcs and lines: the follower's place read off
the cam's outline itself.

A circular-arc cam is a base circle (O, r₁), two flank arcs (P, R) and a nose arc (Q, r₂),
each flank tangent to both; a tangent cam has straight flanks tangent to both circles.
The cam is held in its own frame with the nose centre Q on +x. The follower's axis, as the
cam turns θ from the start of the lift, points at ψ = α − θ in that frame (α the angle of
lift: from the start of the lift to the apex).

The outline is found here from the tangencies alone: a flank circle's radius R by bisection
on |P − Q| = R − r₂ with P = −(R − r₁)·(cos α, sin α) (its touch with the base circle is
where the lift begins), a straight flank from the common tangent of the two circles. The
follower's place is then read off the outline without knowing which part it touches:

- a flat face square to the axis stands at the outline's support h(ψ) = max over the parts
  of each arc's or segment's farthest point along the axis;
- a roller's centre stands where the axis ray from O meets the outline grown by the
  roller's radius (each arc's radius grown, each segment moved out along its normal).

The textbook's formulas for the flank and the nose (:mod:`..cams.arc_cam`) are held to
these places and to their rates, found exactly by differentiating the touched part's place
implicitly (:func:`place_rates`); differences would lose up to 10⁻³ of ω²d where a knife edge
comes onto a small nose, its place there turning sharply.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["ArcOutline", "outline", "face_place", "roller_place", "place_rates"]

Vec = tuple[float, float]


@dataclass(frozen=True)
class Arc:
    """A circle arc: its centre, radius and the range of its outward normals (rad, from
    ``start`` turning counter-clockwise through ``sweep``)."""

    centre: Vec
    radius: float
    start: float
    sweep: float

    def holds(self, angle: float) -> bool:
        """Whether the outward normal at ``angle`` is on this arc."""
        return (angle - self.start) % (2 * math.pi) <= self.sweep + 1e-15


@dataclass(frozen=True)
class Flat:
    """A straight flank from ``a`` to ``b`` with its outward unit normal."""

    a: Vec
    b: Vec
    normal: Vec


@dataclass(frozen=True)
class ArcOutline:
    """A cam's outline: its arcs and straight flanks, and the flank circles' centre and
    radius where the flanks are arcs."""

    parts: tuple
    flank_centre: Vec | None = None
    flank_radius: float = math.inf


def _dot(a: Vec, b: Vec) -> float:
    return a[0] * b[0] + a[1] * b[1]


def flank_radius(r1: float, r2: float, d: float, alpha: float) -> float:
    """The flank circle's radius R by bisection on f(R) = |P − Q| − (R − r₂), P at
    −(R − r₁)·(cos α, sin α): f grows from R = r₁ (|O − Q| − (r₁ − r₂) = d − r₁ + r₂ > 0) and
    falls below 0 for R large enough where the flank can reach the nose at all.

    Raises
    ------
    ValueError
        If no flank circle touches both circles (the nose too far round).
    """
    def f(big: float) -> float:
        p = (-(big - r1) * math.cos(alpha), -(big - r1) * math.sin(alpha))
        return math.hypot(p[0] - d, p[1]) - (big - r2)
    lo, hi = r1, 2 * r1 + d
    while f(hi) > 0:
        hi *= 2
        if hi > 1e12 * (r1 + d):
            raise ValueError("no flank circle touches both the base and the nose circles")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        lo, hi = (mid, hi) if f(mid) > 0 else (lo, mid)
    return 0.5 * (lo + hi)


def outline(kind: str, r1: float, r2: float, d: float, alpha: float) -> ArcOutline:
    """The outline of a symmetrical ``kind`` ("circular arc", "tangent" or "eccentric") cam:
    base circle r₁ about O, nose r₂ about Q = (d, 0), the lift beginning α either side of the
    apex; an eccentric disc is its nose alone, the whole circle."""
    if kind == "eccentric":
        return ArcOutline((Arc((d, 0.0), r2, 0.0, 2 * math.pi),))
    if kind == "tangent":
        nx = (r1 - r2) / d
        ny = math.sqrt(1 - nx * nx)
        parts = []
        for s in (1.0, -1.0):
            n = (nx, s * ny)
            parts.append(Flat((r1 * n[0], r1 * n[1]), (d + r2 * n[0], r2 * n[1]), n))
        gamma = math.atan2(ny, nx)
        parts += [Arc((d, 0.0), r2, -gamma, 2 * gamma),
                  Arc((0.0, 0.0), r1, gamma, 2 * math.pi - 2 * gamma)]
        return ArcOutline(tuple(parts))
    big = flank_radius(r1, r2, d, alpha)
    p = (-(big - r1) * math.cos(alpha), -(big - r1) * math.sin(alpha))
    gamma = math.atan2(-p[1], d - p[0])            # the flank's normal where it meets the nose
    parts = [Arc(p, big, gamma, alpha - gamma),
             Arc((p[0], -p[1]), big, -alpha, alpha - gamma),
             Arc((d, 0.0), r2, -gamma, 2 * gamma),
             Arc((0.0, 0.0), r1, alpha, 2 * math.pi - 2 * alpha)]
    return ArcOutline(tuple(parts), p, big)


def _ends(part) -> list[Vec]:
    if isinstance(part, Flat):
        return [part.a, part.b]
    c, r = part.centre, part.radius
    return [(c[0] + r * math.cos(a), c[1] + r * math.sin(a))
            for a in (part.start, part.start + part.sweep)]


def face_place(cam: ArcOutline, psi: float) -> float:
    """How far from O a flat face square to the axis at ``psi`` stands: the outline's
    farthest point along the axis (each arc's top where its normal range holds the axis,
    else its ends; a segment's ends)."""
    u = (math.cos(psi), math.sin(psi))
    best = -math.inf
    for part in cam.parts:
        if isinstance(part, Arc) and part.holds(psi):
            best = max(best, _dot(part.centre, u) + part.radius)
        best = max([best] + [_dot(e, u) for e in _ends(part)])
    return best


def roller_place(cam: ArcOutline, psi: float, r: float) -> float:
    """How far from O the centre of a roller of radius ``r`` on the axis at ``psi`` stands:
    where the axis ray meets the outline grown by r (the greatest such meeting, each part's
    own taken only where it falls on that part)."""
    u = (math.cos(psi), math.sin(psi))
    best = -math.inf
    for part in cam.parts:
        if isinstance(part, Arc):
            c, grown = part.centre, part.radius + r
            across = c[0] * u[1] - c[1] * u[0]
            if abs(across) > grown:
                continue
            t = _dot(c, u) + math.sqrt(grown * grown - across * across)
            at = math.atan2(t * u[1] - c[1], t * u[0] - c[0])
            if part.holds(at):
                best = max(best, t)
        else:
            n = part.normal
            if _dot(n, u) <= 0:
                continue
            t = (_dot(n, part.a) + r) / _dot(n, u)
            run = (part.b[0] - part.a[0], part.b[1] - part.a[1])
            foot = (t * u[0] - r * n[0] - part.a[0], t * u[1] - r * n[1] - part.a[1])
            if -1e-12 <= _dot(foot, run) / _dot(run, run) <= 1 + 1e-12:
                best = max(best, t)
    return best


def _touched(cam: ArcOutline, psi: float, r: float, flat: bool, side: int):
    """The part the follower touches at ``psi`` and the axis a hair (10⁻⁷ rad) past it
    toward ``side`` (+1 the cam turning on, ψ falling; −1 back; 0 at ``psi`` itself): the
    part whose place is the follower's there, so that on a join it is that side's part."""
    at = psi - side * 1e-7
    one = ArcOutline
    part = max(cam.parts, key=lambda p: face_place(one((p,)), at) if flat
               else roller_place(one((p,)), at, r))
    return part, (math.cos(at), math.sin(at))


def place_rates(cam: ArcOutline, psi: float, r: float = 0.0, flat: bool = False,
                side: int = 0) -> tuple[float, float, float]:
    """The follower's place along the axis at ``psi`` (from O) and its first two
    derivatives in ψ, exact: the place on the part it touches (see :func:`_touched`)
    differentiated implicitly, so no step and no conditioning stands between the outline
    and the motion.

    - a flat face on an arc (centre c, radius ρ) stands at c·u + ρ, on a corner e at e·u:
      its rates are c·u⊥ and −c·u (u = (cos ψ, sin ψ), u⊥ = du/dψ);
    - a roller's centre t u on an arc grown to g keeps |t u − c| = g: with A = t − c·u and
      B = c·u⊥, t′ = tB/A and t″ = (t′B + tB′)/A − tBA′/A², B′ = −c·u, A′ = t′ − B;
    - on a straight flank moved out by r, n·(t u) = n·a + r = p: with q = n·u,
      t′ = −p q′/q² and t″ = p(1/q + 2q′²/q³).

    Examples
    --------
    A disc of radius 10 turning 5 off its centre, a knife edge on the axis at ψ = 0 (the
    apex): t = 15, t′ = 0, t″ = −e(1 + e/ρ) = −7.5.

    >>> disc = outline("eccentric", 5.0, 10.0, 5.0, math.pi)
    >>> [round(v, 12) for v in place_rates(disc, 0.0)]
    [15.0, 0.0, -7.5]
    """
    part, near = _touched(cam, psi, r, flat, side)
    u, w = (math.cos(psi), math.sin(psi)), (-math.sin(psi), math.cos(psi))
    if flat:
        if isinstance(part, Arc) and part.holds(math.atan2(near[1], near[0])):
            point, lift = part.centre, part.radius
        else:                                  # a corner: the end farthest along the axis
            point, lift = max(_ends(part), key=lambda e: _dot(e, near)), 0.0
        return _dot(point, u) + lift, _dot(point, w), -_dot(point, u)
    if isinstance(part, Arc):
        c, g = part.centre, part.radius + r
        cu, b = _dot(c, u), _dot(c, w)
        t = cu + math.sqrt(g * g - (c[0] * u[1] - c[1] * u[0]) ** 2)
        a = t - cu
        t1 = t * b / a
        return t, t1, (t1 * b - t * cu) / a - t * b * (t1 - b) / (a * a)
    n = part.normal
    p, q, q1 = _dot(n, part.a) + r, _dot(n, u), _dot(n, w)
    return p / q, -p * q1 / (q * q), p * (1 / q + 2 * q1 * q1 / q ** 3)
