"""The independent reference for balancing: vector sums in closed form.

- Static balance (001 ch. 7 eq. 15–17): ΣF_x = Σ mᵢrᵢω² cos θᵢ, ΣF_y = Σ mᵢrᵢω² sin θᵢ, the
  resultant's size √(ΣF_x² + ΣF_y²) and its angle from tan θ = ΣF_y/ΣF_x with the quadrant
  read off the signs (Note 2); the balancing mass–radius product is the resultant's,
  turned through 180°.
- Dynamic balance in two planes A and B: moments about A give (m r)_B = −Σ mᵢrᵢlᵢ / l_B,
  lᵢ measured from A; then forces give (m r)_A = −Σ mᵢrᵢ − (m r)_B.
- An engine's unbalanced inertia forces: primary m·ω²·r·cos θ and secondary
  m·ω²·r·cos 2θ / n along the line of stroke (n = l/r); a rotating mass c·m opposite the
  crank leaves (1 − c)·m·ω²·r·cos θ along it and c·m·ω²·r·sin θ across it, a resultant of
  m·ω²·r·√((1 − c)² cos² θ + c² sin² θ); that mass, with the revolving masses m_rev it takes
  whole, has the product B·b = (m_rev + c·m)·r. For cylinders in
  line, the primary forces and couples sum as vectors at the crank angles θᵢ, the
  secondary ones at 2θᵢ (the direct-crank reading), each a 1/n of the primary's size.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..balancing.rotor import Engine, Mass

__all__ = ["EngineSums", "balance_product", "couple_about", "quadrant_angle", "resultant",
           "single_cylinder", "engine_along", "engine_greatest_at", "engine_sums",
           "one_axial_plane", "open_residual", "open_rotor_roots", "polygon_roots",
           "two_planes", "unbalanced_resultant", "vee_resultants", "radial_along_lines",
           "radial_constants"]


def resultant(masses: tuple[Mass, ...] | list[Mass]) -> tuple[float, float]:
    """Σ mᵢrᵢ as a vector (kg·m): the x and y sums of eq. (15) without ω²."""
    return (math.fsum(m.mr[0] for m in masses), math.fsum(m.mr[1] for m in masses))


def quadrant_angle(x: float, y: float) -> float:
    """The notes' eq. (17) and Note 2: θ′ = tan⁻¹|y/x|, then put in its quadrant by the
    signs of x and y (degrees, 0 to 360)."""
    if x == 0.0:
        return 90.0 if y > 0 else 270.0 if y < 0 else 0.0
    base = math.degrees(math.atan(abs(y / x)))
    if x > 0:
        return base if y >= 0 else 360.0 - base
    return 180.0 - base if y >= 0 else 180.0 + base


def two_planes(masses, a: float, b: float) -> tuple[tuple[float, float], tuple[float, float]]:
    """The mass–radius products (kg·m vectors) to put in the planes at ``a`` and ``b``."""
    lever = b - a
    couple = (math.fsum(m.mr[0] * (m.plane - a) for m in masses),
              math.fsum(m.mr[1] * (m.plane - a) for m in masses))
    in_b = (-couple[0] / lever, -couple[1] / lever)
    sx, sy = resultant(masses)
    return (-sx - in_b[0], -sy - in_b[1]), in_b


def couple_about(masses, z: float) -> tuple[float, float]:
    """Σ mᵢrᵢ(zᵢ − z) e^{iθᵢ} (kg·m² vector, × ω² a couple): the masses' couple about the
    plane at ``z``, what a static balance there leaves (its own mass adds none about it)."""
    total = sum(complex(*m.mr) * (m.plane - z) for m in masses)
    return total.real, total.imag


def one_axial_plane(masses) -> tuple[tuple[float, float], float] | None:
    """The notes' cases 2-1 and 2-2: masses in one axial plane (their radii 0° or 180°
    apart) are balanced, force and couple together, by one mass in the plane where the
    moments vanish. Returns its mass–radius product (kg·m) and that plane's position (m),
    or None if the masses are not in one axial plane or their forces cancel already."""
    if not masses:
        return None
    base = masses[0].angle
    if any(abs(math.sin(m.angle - base)) > 1e-12 for m in masses):
        return None
    along = [m.mass * m.radius * math.cos(m.angle - base) for m in masses]
    total = math.fsum(along)
    if abs(total) <= 1e-12 * max(abs(a) for a in along):
        return None
    place = math.fsum(a * m.plane for a, m in zip(along, masses)) / total
    return (-total * math.cos(base), -total * math.sin(base)), place


def single_cylinder(e: Engine, theta: float) -> tuple[float, float | None, float, float]:
    """At crank angle θ: the primary and secondary forces along the stroke (N; the secondary
    None with no rod given), and with the rotating balance mass, the unbalanced force along
    and across the stroke (N)."""
    f = e.reciprocating * e.speed ** 2 * e.crank
    secondary = None if e.rod is None else f * math.cos(2 * theta) / (e.rod / e.crank)
    return (f * math.cos(theta), secondary, (1 - e.balanced) * f * math.cos(theta),
            e.balanced * f * math.sin(theta))


def unbalanced_resultant(e: Engine, theta: float) -> float:
    """The size of the primary force left unbalanced at θ (N): the revolving masses are
    balanced whole, and of the reciprocating mass m, (1 − c)·m·ω²·r·cos θ is left along the
    stroke and c·m·ω²·r·sin θ across it, so m·ω²·r·√((1 − c)² cos² θ + c² sin² θ)."""
    c = e.balanced
    return e.reciprocating * e.speed ** 2 * e.crank * math.sqrt(
        ((1 - c) * math.cos(theta)) ** 2 + (c * math.sin(theta)) ** 2)


def balance_product(e: Engine) -> float:
    """The balance mass's product B·b (kg·m) opposite the crank: all the revolving mass and
    the fraction c of the reciprocating, at the crank radius, (m_rev + c·m)·r."""
    return (e.revolving + e.balanced * e.reciprocating) * e.crank


@dataclass(frozen=True)
class EngineSums:
    """An in-line engine's unbalanced primary and secondary force and couple, as the
    vector sums of its cranks (N, N·m: the sizes of the rotating vectors' resultants)."""

    primary_force: float
    primary_couple: float
    secondary_force: float
    secondary_couple: float


def engine_sums(e: Engine, reference: float | None = None) -> EngineSums:
    """Sum each cylinder's primary (at θᵢ) and secondary (at 2θᵢ, a 1/n share) force and
    couple, the couples about the plane at ``reference`` (default: the central plane,
    midway between the end cylinders)."""
    if reference is None:
        reference = (min(e.planes) + max(e.planes)) / 2
    f = e.speed ** 2 * e.crank
    n = math.inf if e.rod is None else e.rod / e.crank     # no rod: no secondary asked

    def size(angles, arms) -> float:
        return math.hypot(math.fsum(a * math.cos(t) for t, a in zip(angles, arms)),
                          math.fsum(a * math.sin(t) for t, a in zip(angles, arms)))
    ones = list(e.each)                                     # each cylinder's mass
    arms = [m * (p - reference) for m, p in zip(e.each, e.planes)]
    twice = [2 * t for t in e.cranks]
    return EngineSums(f * size(e.cranks, ones), f * size(e.cranks, arms),
                      f / n * size(twice, ones), f / n * size(twice, arms))


def engine_along(e: Engine, theta: float, reference: float | None = None) -> dict[str, float]:
    """Each primary and secondary force and couple along the line of stroke (N, N·m) with
    crank 1 at ``theta`` (rad) from the inner dead centre: Σ aᵢ·mᵢ·ω²·r·cos(θ − θ₁ + θᵢ), the
    secondary's Σ aᵢ·mᵢ·ω²·r·cos 2(θ − θ₁ + θᵢ)/n (aᵢ 1, or the arm from the central plane)."""
    if reference is None:
        reference = (min(e.planes) + max(e.planes)) / 2
    turn = theta - e.cranks[0]
    f = e.speed ** 2 * e.crank
    out = {}
    for kind, k in (("primary force", 1), ("primary couple", 1), ("secondary force", 2),
                    ("secondary couple", 2)):
        if k == 2 and e.rod is None:
            continue
        arms = [1.0 if kind.endswith("force") else z - reference for z in e.planes]
        share = f / (1.0 if k == 1 else e.rod / e.crank)
        out[kind] = share * math.fsum(a * m * math.cos(k * (turn + t))
                                      for a, m, t in zip(arms, e.each, e.cranks))
    return out


def engine_greatest_at(e: Engine, reference: float | None = None) -> dict[str, float | None]:
    """Crank 1's angle from the inner dead centre (degrees) where each unbalanced primary
    and secondary force and couple is greatest, or None where its sum vanishes.

    At a turn θ of the shaft cylinder i's primary force is m·ω²·r·cos(θ + θᵢ), so the sum is
    Re(R·e^{iθ}) = |R|·cos(θ + arg R), R = Σ aᵢ·e^{iθᵢ} (aᵢ 1 or the arm lᵢ): greatest at
    θ = −arg R, every 180°, with crank 1 then at θ₁ − arg R. The secondary sum is
    |S|·cos(2θ + arg S), S = Σ aᵢ·e^{2iθᵢ}: greatest every 90° from θ = −arg S / 2. The
    smallest such crank-1 angle, in [0°, 180°) or [0°, 90°), is returned."""
    if reference is None:
        reference = (min(e.planes) + max(e.planes)) / 2
    arms = [m * (p - reference) for m, p in zip(e.each, e.planes)]
    ones = list(e.each)
    out: dict[str, float | None] = {}
    for kind, order, weights in (("primary force", 1, ones), ("primary couple", 1, arms),
                                 ("secondary force", 2, ones), ("secondary couple", 2, arms)):
        x = math.fsum(a * math.cos(order * t) for t, a in zip(e.cranks, weights))
        y = math.fsum(a * math.sin(order * t) for t, a in zip(e.cranks, weights))
        size = math.fsum(abs(a) for a in weights)
        if math.hypot(x, y) <= 1e-12 * size:
            out[kind] = None
            continue
        period = 180.0 / order
        out[kind] = (math.degrees(e.cranks[0]) - math.degrees(math.atan2(y, x)) / order) \
            % period
    return out


def vee_resultants(e: Engine, theta: float) -> tuple[float, float | None]:
    """A V engine's resultant primary and secondary forces (N) at θ from its centre line,
    by the books' closed forms with α half the V's angle and F = m·ω²·r:
    primary √((2F·cos²α·cos θ)² + (2F·sin²α·sin θ)²), secondary (F/n)·
    √((2·cos α·cos 2α·cos 2θ)² + (2·sin α·sin 2α·sin 2θ)²); the secondary None with no rod."""
    a = e.vee / 2
    f = e.reciprocating * e.speed ** 2 * e.crank
    primary = 2 * f * math.hypot(math.cos(a) ** 2 * math.cos(theta),
                                 math.sin(a) ** 2 * math.sin(theta))
    if e.rod is None:
        return primary, None
    secondary = 2 * f / (e.rod / e.crank) * math.hypot(
        math.cos(a) * math.cos(2 * a) * math.cos(2 * theta),
        math.sin(a) * math.sin(2 * a) * math.sin(2 * theta))
    return primary, secondary


def radial_along_lines(e: Engine, theta: float
                       ) -> tuple[tuple[float, float], tuple[float, float] | None]:
    """A radial engine's resultant primary and secondary forces (N, along and across
    cylinder 1's line) with the crank at θ from cylinder 1's line, summed over the cylinders
    along their own lines at φᵢ = 360°·i/n: m·ω²·r·cos(θ − φᵢ) and m·ω²·r·cos 2(θ − φᵢ)/n
    along (cos φᵢ, sin φᵢ), the secondary None with no rod."""
    f = e.reciprocating * e.speed ** 2 * e.crank
    lines = [2 * math.pi * i / e.radial for i in range(e.radial)]

    def total(size: float, k: int) -> tuple[float, float]:
        return (math.fsum(size * math.cos(k * (theta - p)) * math.cos(p) for p in lines),
                math.fsum(size * math.cos(k * (theta - p)) * math.sin(p) for p in lines))
    return total(f, 1), None if e.rod is None else total(f / (e.rod / e.crank), 2)


def radial_constants(e: Engine) -> tuple[float, float | None]:
    """A radial engine's primary and secondary resultants (N), of one size at every crank
    angle for n ≥ 3 cylinders: Σ cos(θ − φᵢ)·e^{iφᵢ} = (n/2)·e^{iθ} + ½·e^{−iθ}·Σ e^{2iφᵢ},
    the last sum 0 unless n divides 2, so the primary is (n/2)·m·ω²·r; likewise
    Σ cos 2(θ − φᵢ)·e^{iφᵢ} = ½·e^{2iθ}·Σ e^{−iφᵢ} + ½·e^{−2iθ}·Σ e^{3iφᵢ}, the first 0 and
    the second n where n divides 3, so the secondary is (3/2)·m·ω²·r/n for three cylinders
    and 0 for more; the secondary None with no rod."""
    f = e.reciprocating * e.speed ** 2 * e.crank
    primary = e.radial / 2 * f
    if e.rod is None:
        return primary, None
    return primary, (1.5 * f / (e.rod / e.crank) if e.radial == 3 else 0.0)


TANGENT = 1e-9
"""How far (relative to the sizes) two carriers may miss and still be taken as touching:
a rotor balanced with two masses along one line closes its polygon on arcs that touch,
which rounding leaves a hair apart or across."""


def polygon_roots(known: complex, unknown: list[tuple[float | None, float | None]]
                  ) -> list[list[complex]]:
    """The vectors that close a polygon whose known vectors sum to ``known``: one wholly
    unknown (−known), or two, each given as (signed size or None, angle or None) with one
    of the two unknown, by algebra on v₁ + v₂ = −known: two sizes by Cramer's rule, two
    directions by the law of cosines, a size and a direction by the quadratic
    |−known − a·e^{iθ₁}| = |s₂|. Every real root is returned (none where they miss)."""
    target = -known
    if len(unknown) == 1:
        return [[target]]
    (s1, a1), (s2, a2) = unknown
    if a1 is None and a2 is not None:
        return [v[::-1] for v in polygon_roots(known, [(s2, a2), (s1, a1)])]
    if a1 is not None and a2 is not None:
        e1, e2 = complex(math.cos(a1), math.sin(a1)), complex(math.cos(a2), math.sin(a2))
        det = e1.real * e2.imag - e1.imag * e2.real
        if det == 0.0:
            return []
        a = (target.real * e2.imag - target.imag * e2.real) / det
        b = (e1.real * target.imag - e1.imag * target.real) / det
        return [[a * e1, b * e2]]
    if a1 is not None:
        e1 = complex(math.cos(a1), math.sin(a1))
        # |target − a·e1|² = s2²: a² − 2a·Re(target·conj e1) + |target|² − s2² = 0
        p = (target * e1.conjugate()).real
        disc = p * p - (abs(target) ** 2 - s2 * s2)
        if disc < -TANGENT * (abs(target) ** 2 + s2 * s2):
            return []
        disc = max(disc, 0.0)                   # touching, to rounding
        roots = (p + math.sqrt(disc), p - math.sqrt(disc))
        return [[a * e1, target - a * e1] for a in roots]
    d = abs(target)
    r1, r2 = abs(s1), abs(s2)
    slack = TANGENT * (r1 + r2 + d)
    if d == 0.0 or d > r1 + r2 + slack or d < abs(r1 - r2) - slack:
        return []
    # v1 = a·u ± h·(i·u), u along the target: a by the law of cosines, h the triangle's
    # height over d, its area by Kahan's stable Heron formula (a thin triangle's angle
    # taken by acos would lose half its digits)
    x, y, w = sorted((r1, r2, d), reverse=True)
    area = 0.25 * math.sqrt(max(0.0, (x + (y + w)) * (w - (x - y)) * (w + (x - y))
                                * (x + (y - w))))
    h = 2.0 * area / d
    a = ((r1 - r2) * (r1 + r2) + d * d) / (2.0 * d)
    u = target / d
    return [[a * u + sign * h * 1j * u, target - (a * u + sign * h * 1j * u)]
            for sign in (1.0, -1.0)]


def open_residual(masses) -> tuple[float, float]:
    """|Σ mᵢrᵢ e^{iθᵢ}| (kg·m) and |Σ mᵢrᵢlᵢ e^{iθᵢ}| (kg·m², about plane 0) of masses
    whose data are all known: a rotor in complete balance leaves both zero."""
    fx = math.fsum(m.mass * m.radius * math.cos(m.angle) for m in masses)
    fy = math.fsum(m.mass * m.radius * math.sin(m.angle) for m in masses)
    cx = math.fsum(m.mass * m.radius * m.plane * math.cos(m.angle) for m in masses)
    cy = math.fsum(m.mass * m.radius * m.plane * math.sin(m.angle) for m in masses)
    return math.hypot(fx, fy), math.hypot(cx, cy)


def open_rotor_roots(parts, order: list[str], z: float) -> list[dict]:
    """Every way the rotor's unknowns (None in ``parts``, each with name, mass, radius,
    angle, plane) close its polygons, taken in ``order`` ("force", "couple"), couples about
    the plane at ``z``: each a dict of name → (mass, radius, angle, plane). A root with a
    mass not positive is dropped.

    A mass whose m·r and plane are both unknown takes from the couple polygon the product
    m·r·(l − z) (and its angle, where unknown, to a half turn), from the force polygon its
    m·r, signed along that angle (a negative one turns the angle half round), and so its
    plane; each state carries the product and whether the half turn is open."""
    states = [{p.name: [p.mass, p.radius, p.angle, p.plane, None, False] for p in parts}]
    for which in order:
        grown = []
        for state in states:
            grown += _polygon_states(state, which, z)
        states = grown
    return [{k: tuple(v[:4]) for k, v in s.items()} for s in states]


def _polygon_states(state: dict, which: str, z: float) -> list[dict]:
    known, unknown = 0j, []
    for name, (m, r, a, z_i, _, _) in state.items():
        size = None if m is None or r is None else m * r
        if which == "couple":
            if z_i is not None and z_i == z:
                continue
            lever = None if z_i is None else z_i - z
            size = None if size is None or lever is None else size * lever
        if size is not None and a is not None:
            known += size * complex(math.cos(a), math.sin(a))
        else:
            unknown.append((name, size, a))
    out = []
    for root in polygon_roots(known, [(s, a) for _, s, a in unknown]):
        new = {k: list(v) for k, v in state.items()}
        ok = True
        for (name, _, _), v in zip(unknown, root):
            m, r, a, z_i, moment, loose = new[name]
            lever = 1.0 if which == "force" else (None if z_i is None else z_i - z)
            product = which == "couple" and (m is None or r is None) and z_i is None
            if a is None:
                a = math.atan2(v.imag, v.real) + (math.pi if lever is not None and lever < 0
                                                  else 0.0)
                a %= 2 * math.pi
                loose = product
            along = v.real * math.cos(a) + v.imag * math.sin(a)
            if product:
                moment = along
            elif m is None or r is None:
                if loose and along < 0:
                    a, along, moment = (a + math.pi) % (2 * math.pi), -along, -moment
                size = along / lever
                ok = ok and size > 0
                m, r = (size / r, r) if m is None else (m, size / m)
                if moment is not None:
                    z_i = z + moment / size
            elif z_i is None and which == "couple":
                z_i = z + along / (m * r)
            new[name] = [m, r, a, z_i, moment, loose]
        if ok:
            out.append(new)
    return out
