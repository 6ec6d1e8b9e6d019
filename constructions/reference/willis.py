"""The independent reference for gear trains: the Willis equation of every mesh, solved as
one exact linear system.

Relative to the arm c that carries a mesh (the frame, speed 0, for a fixed axis) the
pitch-line speeds of two meshing gears agree: N_a·(ω_a − ω_c) = ∓N_b·(ω_b − ω_c), minus
for an external mesh, plus for an internal one. Members on one shaft turn alike, the
fixed member not at all, and the input at its given speed. Gauss–Jordan elimination over
:class:`~fractions.Fraction` solves the square system exactly; it shares nothing with the
tabular method but the train itself.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ..errors import InputError
from ..gears.train import GearTrain

__all__ = ["willis_speeds", "willis_torques", "coaxial_teeth", "pitch_distance",
           "pitch_distance_times_pi", "teeth_to_about"]


def pitch_distance(train: GearTrain, a: int, b: int, internal: bool) -> Fraction | None:
    """The distance between two meshing gears' axes from their pitch circles alone, each
    radius N·m/2 at its own gear's module: their sum, or inside a ring their difference;
    None where a gear gives no module."""
    radii = []
    for n in (a, b):
        g = train.gear(n)
        if g.module is None or g.teeth is None:
            return None
        radii.append(g.teeth * g.module / 2)
    return abs(radii[0] - radii[1]) if internal else radii[0] + radii[1]


def pitch_distance_times_pi(train: GearTrain, a: int, b: int, internal: bool
                            ) -> Fraction | None:
    """π times the distance between two meshing gears' axes, from their pitch circles at
    their circular pitches: each radius N·p/(2π), so π·r = N·p/2 exactly; None unless both
    gears give a circular pitch."""
    gears = [train.gear(n) for n in (a, b)]
    if any(g.circular_pitch is None or g.teeth is None for g in gears):
        return None
    ra, rb = (g.teeth * g.circular_pitch / 2 for g in gears)
    return abs(ra - rb) if internal else ra + rb


def teeth_to_about(about: float, pitch: float, ratio: float, internal: bool,
                   least: int | None) -> tuple[int, int]:
    """The counts (smaller, larger) a pair designed to an approximate centre distance takes,
    in floats: the smaller gear's circumference over the circular pitch, π·d/p with
    d = 2a/(k ± 1), taken up to the next whole count (or ``least``), the larger k times it
    (rounded: the caller compares it with the design's)."""
    k = max(ratio, 1 / ratio)
    d = 2 * about / (k - 1 if internal else k + 1)
    # a count under 1e5 is good to ~1e-11 in floats: one within 1e-9 of a whole one is it
    n = max(math.ceil(math.pi * d / pitch - 1e-9), least or 1)
    return n, round(n * k)


def willis_speeds(train: GearTrain) -> dict[int, Fraction]:
    """Every member's speed (exact, CCW-positive, in the train's unit).

    Raises
    ------
    InputError
        If the equations do not fix every speed (the train is not one degree of freedom).
    """
    members = list(train.members)
    col = {m: i for i, m in enumerate(members)}
    rows: list[list[Fraction]] = []

    def equation(terms: dict[int, Fraction], rhs: Fraction = Fraction(0)) -> None:
        row = [Fraction(0)] * (len(members) + 1)
        for m, c in terms.items():
            row[col[m]] += c
        row[-1] = rhs
        rows.append(row)

    for mesh in train.meshes:
        a, b = train.gear(mesh.a), train.gear(mesh.b)
        carrier = next((g.carrier for g in (a, b) if g.carrier is not None), None)
        if carrier is None:
            carrier = next((train.arm for m in train.body(mesh.a) + train.body(mesh.b)
                            if m != train.arm and train.gear(m).carrier is not None), None)
        sign = mesh.sign          # −1 external, +1 internal, a bevel pair's own
        terms = {mesh.a: Fraction(a.teeth), mesh.b: Fraction(-sign * b.teeth)}
        if carrier is not None:
            terms[carrier] = terms.get(carrier, Fraction(0)) - a.teeth + sign * b.teeth
        equation(terms)
    for shaft in train.shafts:
        for m in shaft[1:]:
            equation({shaft[0]: Fraction(1), m: Fraction(-1)})
    if train.fixed is not None:
        equation({train.fixed: Fraction(1)})
    equation({train.input_member: Fraction(1)}, train.input_speed)
    if train.second is not None:              # two given speeds, no member fixed
        equation({train.second[0]: Fraction(1)}, train.second[1])
    return dict(zip(members, _solve(rows, len(members), train)))


def willis_torques(train: GearTrain, speeds: dict[int, Fraction], loads: dict[int, Fraction],
                   output: int, holder: int | None) -> dict[int, Fraction]:
    """The output's and the holder's torques from the input's (``loads``, one member's):
    the equilibrium of the whole train, ΣT = 0 (where a holder takes the rest), and its
    energy, Σ T·ω = −(1 − η)·T_in·ω_in
    (what the losses take), solved as one exact linear system in (T_out, T_holder). The
    torques are in whatever unit ``loads`` is (a coefficient of 1/π, too).

    Raises
    ------
    InputError
        If the two equations do not fix the torques (output and holder turn alike).
    """
    (i, t_in), = loads.items()
    members = [output] + ([holder] if holder is not None else [])
    loss = (1 - train.efficiency) * t_in * speeds[i]
    rows = [[speeds[m] for m in members] + [-t_in * speeds[i] + loss]]
    if holder is not None:          # with no holder the housing takes the rest of ΣT
        rows.append([Fraction(1)] * len(members) + [-t_in])
    solved = _solve(rows, len(members), train)
    return {i: t_in, **dict(zip(members, solved))}


def coaxial_teeth(train: GearTrain, number: int) -> Fraction:
    """Gear ``number``'s teeth as the coaxial condition fixes them, found apart from the
    step that did: a mesh of ``number`` and another mesh that must stand as far apart (both
    on one planet body, or across the shaft of an ordinary reverted train); the centre
    distance is linear in the count, so a secant through N and N + 1 on train.py's own
    distances lands on it. Returns the count, or 0 where no such pair is found."""
    from dataclasses import replace

    def related(mesh, other) -> bool:
        if not train.planetary and (train.coaxial is None or not (
                set(train.coaxial) & {mesh.a, mesh.b} and set(train.coaxial) & {other.a,
                                                                                 other.b})):
            return False            # an ordinary train's pairs, only across its named axis
        def partner(m, g):
            return m.b if g == m.a else m.a

        return any(train.body(x) == train.body(y) and (
            train.carried(x) and not train.carried(partner(mesh, x))
            and not train.carried(partner(other, y)) if train.planetary else x != y)
            for x in (mesh.a, mesh.b) for y in (other.a, other.b))

    def gap(n: int, mesh, other) -> Fraction:
        t = replace(train, gears=tuple(replace(g, teeth=n) if g.number == number else g
                                       for g in train.gears))
        return t._centre_distance(mesh) - t._centre_distance(other)

    n0 = train.gear(number).teeth
    for mesh in train.meshes:
        for other in train.meshes:
            if other is mesh or number not in (mesh.a, mesh.b) or not related(mesh, other):
                continue
            slope = gap(n0 + 1, mesh, other) - gap(n0, mesh, other)
            if slope:
                return n0 - gap(n0, mesh, other) / slope
    return _series_teeth(train, number) if train.planetary else Fraction(0)


def _series_teeth(train: GearTrain, number: int) -> Fraction:
    """Gear ``number``'s teeth where planets in series carry it: each planet's carrier
    radius, the sum of the pitch radii out from the main axis along its chain, is the ring's
    radius less its own for the planet that meshes the ring; a secant through N and N + 1
    on train.py's own distances, as :func:`coaxial_teeth`. 0 where no such chain holds it."""
    from dataclasses import replace

    def radii(t: GearTrain) -> dict[int, Fraction]:
        """Each carried gear's distance from the axis, reached gear by gear from the
        main-axis gears it meshes externally."""
        out: dict[int, Fraction] = {}
        todo = [(m, a, b) for m in t.meshes if not m.internal
                for a, b in ((m.a, m.b), (m.b, m.a)) if not t.carried(a) and t.carried(b)]
        while todo:
            mesh, a, b = todo.pop(0)
            if b in out:
                continue
            out[b] = out.get(a, Fraction(0)) + t._centre_distance(mesh)
            todo += [(m, b, c) for m in t.meshes if not m.internal and b in (m.a, m.b)
                     for c in (m.a if m.b == b else m.b,) if t.carried(c) and c not in out]
        return out

    def gap(n: int) -> Fraction | None:
        t = replace(train, gears=tuple(replace(g, teeth=n) if g.number == number else g
                                       for g in train.gears))
        r = radii(t)
        for m in t.meshes:
            for ring, p in ((m.a, m.b), (m.b, m.a)):
                if m.internal and not t.carried(ring) and p in r and len(t.body(p)) == 1:
                    return r[p] - t._centre_distance(m)
        return None

    n0 = train.gear(number).teeth
    g0, g1 = gap(n0), gap(n0 + 1)
    if g0 is None or g1 is None or g1 == g0:
        return Fraction(0)
    return n0 - g0 / (g1 - g0)


def _solve(rows: list[list[Fraction]], n: int, train: GearTrain) -> list[Fraction]:
    """Gauss–Jordan on the augmented ``rows``; every unknown must have a pivot, and a row
    left over must read 0 = 0."""
    rows = [r[:] for r in rows]
    pivot_row = 0
    for c in range(n):
        p = next((r for r in range(pivot_row, len(rows)) if rows[r][c] != 0), None)
        if p is None:
            raise InputError("the gear train's speeds are not fixed by its meshes, shafts, "
                             "fixed member and input", file=train.source or None)
        rows[pivot_row], rows[p] = rows[p], rows[pivot_row]
        head = rows[pivot_row][c]
        rows[pivot_row] = [v / head for v in rows[pivot_row]]
        for r in range(len(rows)):
            if r != pivot_row and rows[r][c] != 0:
                f = rows[r][c]
                rows[r] = [v - f * w for v, w in zip(rows[r], rows[pivot_row])]
        pivot_row += 1
    if any(row[-1] != 0 for row in rows[n:]):
        raise InputError("the gear train's meshes, shafts, fixed member and input contradict "
                         "one another: it cannot move", file=train.source or None)
    return [rows[i][-1] for i in range(n)]
