"""The independent reference for forces: Newton–Euler for every moving link, one linear
system, and the driving torque again by the balance of power.

Each moving link j gives three equations (the course project, 003 §9, writes the same):

    Σ F_on_j + Σ F_ext + m_j·g − m_j·a_Gj = 0,
    Σ (r − O_j) × F + Σ M_ext − I_j·α_j + (G_j − O_j) × (m_j·g − m_j·a_Gj) = 0,

the accelerations from the analytic solver. The unknowns are the joint forces: at a pin
carried by links c₀ < c₁ < …, the force F_c₀cᵢ of c₀ on each other cᵢ (two components);
at a slide, the guide's push square to it, and for a block its couple too; and the
driving torque on the input link. A mechanism of one freedom whose joints constrain it
just once gives as many equations as unknowns; a redundant joint leaves the system short
of rank, and the unknowns that move in its null space name the joints.

The driving torque is found a second way, by power: T·ω_in = −Σ F·v − Σ M·ω over every
load, D'Alembert's inertia included, with no joint force in it.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..loads import (Loads, leaning, made_of, near_rest, near_rest_refusal,
                     resting_speed)
from ..model import Mechanism
from .joint_equations import JOINT_EQUATIONS
from .solver import Kinematics, point_acceleration, point_velocity

__all__ = ["JointForce", "Statics", "balance", "load_scale", "loads_on", "power_torque",
           "torque_rounding", "world_point"]


@dataclass(frozen=True)
class JointForce:
    """A joint's reaction: ``name`` (F_23: of link 2 on link 3), where it acts (m), and its
    value: a force (N) or, for a block's couple (T_15), a moment (N·m) in ``moment``."""

    name: str
    by: int
    on: int
    at: tuple[float, float]
    force: tuple[float, float] = (0.0, 0.0)
    moment: float = 0.0

    @property
    def size(self) -> float:
        """|F| (N), or |T| (N·m) for a couple."""
        return abs(self.moment) if self.name.startswith("T") else math.hypot(*self.force)


@dataclass(frozen=True)
class Statics:
    """Every joint's reaction and the driving torque (N·m, CCW +) on ``driver``."""

    joints: tuple[JointForce, ...]
    torque: float
    driver: int
    residual: float
    conditioning: float
    pushes: tuple[float, ...] = ()
    """Each slide's normal push N (N, along the normal to its guide), in the mechanism's
    order of slides: with friction, μ·|N| of sliding friction acts there."""

    def joint(self, name: str) -> JointForce:
        """The reaction called ``name`` (F_23, T_15)."""
        return next(j for j in self.joints if j.name == name)


def world_point(kin: Kinematics, mech: Mechanism, link: int, point) -> tuple[float, float]:
    """A point of ``link`` in the world: a name, or its own coordinates (m)."""
    if isinstance(point, str):
        return kin.points[point]
    o, a = kin.origins[link], kin.angles[link]
    c, s = math.cos(a), math.sin(a)
    return (o[0] + c * point[0] - s * point[1], o[1] + s * point[0] + c * point[1])


def _direction(kin: Kinematics, guide: int, d: tuple[float, float]) -> tuple[float, float]:
    a = kin.angles.get(guide, 0.0) if guide != 1 else 0.0
    c, s = math.cos(a), math.sin(a)
    return (c * d[0] - s * d[1], s * d[0] + c * d[1])


def _cross(r: tuple[float, float], f: tuple[float, float]) -> float:
    return r[0] * f[1] - r[1] * f[0]


def loads_on(kin: Kinematics, mech: Mechanism, loads: Loads, link: int
              ) -> list[tuple[tuple[float, float], tuple[float, float], float]]:
    """Every known load on ``link`` as (where, force, couple): its weight and inertia
    force at G with its inertia couple −Iα, and the external forces and couples."""
    out = []
    m = loads.mass_of(link)
    if m is not None:
        g = world_point(kin, mech, link, m.centre)
        a = point_acceleration(kin, mech, link, g)
        out.append((g, (-m.mass * a[0], -m.mass * (a[1] + loads.gravity)),
                    -m.inertia * kin.alphas[link]))
    for f in loads.forces:
        if f.link != link:
            continue
        at = world_point(kin, mech, link, f.point)
        force = f.force
        if f.resist:
            # A point no faster than the rounding of a zero stands still: its velocity must
            # not choose the force's way (a dead centre).
            v = point_velocity(kin, mech, link, at)
            speed = math.hypot(*v)
            where = f"its point {f.point}" if isinstance(f.point, str) else "its resisted point"
            _refuse_near_rest(mech, kin, speed, _fastest(kin), f"link {link} moves at {where}",
                              acting="the resistance")
            moving = speed > _resting(kin) and (
                f.along is None or v[0] * f.along[0] + v[1] * f.along[1] > 0)
            force = (-f.resist * v[0] / speed, -f.resist * v[1] / speed) if moving else (0.0, 0.0)
        out.append((at, force, 0.0))
    out += [((0.0, 0.0), (0.0, 0.0), c.moment) for c in loads.couples if c.link == link]
    return out


def load_scale(mech: Mechanism, kin: Kinematics, loads: Loads, size: float) -> float:
    """The force (N) the joint forces are made of, and so round at (:func:`~..loads.made_of`),
    each mass's motion as the analytic solver finds it."""
    def motion(m) -> tuple[float, float, float]:
        g = world_point(kin, mech, m.link, m.centre)
        return (kin.omegas.get(m.link, 0.0), kin.alphas.get(m.link, 0.0),
                math.hypot(*point_acceleration(kin, mech, m.link, g)))
    return made_of(loads, motion, size=size, a_in=mech.input_acceleration)


def balance(mech: Mechanism, kin: Kinematics, loads: Loads) -> Statics:
    """Solve every joint force and the driving torque at the position ``kin`` solves.

    With friction at the slides, each slide's push leans against its sliding on the side
    it pushes from, which the solution itself decides: the system is solved with every
    push assumed on the side the last solution put it, until the sides hold.

    Raises
    ------
    InputError
        If the mechanism rolls or runs in a curved slot (not solved yet), if its joints
        constrain it more than once (statically indeterminate), naming them, or if no
        choice of sides holds (the friction locks it).
    """
    if any(JOINT_EQUATIONS[j.type.key].reactions is None for j in (*mech.slides, *mech.arcs)):
        raise InputError("forces through a rolling contact or a curved slot are not solved "
                         "yet", file=mech.source or None)
    sides = {i: 1.0 for i in range(len(mech.slides))}
    sizes: dict[tuple[str, int, int], float] = {}
    growing, last = 0, math.inf
    for _ in range(_ROUNDS):
        with np.errstate(over="ignore", invalid="ignore"):     # a runaway is caught below
            statics, pushes = _solve(mech, kin, loads, sides,
                                     pin_couples(mech, kin, loads, sizes))
        held = {i: (1.0 if n >= 0.0 else -1.0) for i, n in pushes.items()}
        now = {pin: math.hypot(*statics.joint(f"F_{pin[1]}{pin[2]}").force)
               for pin in mech.pin_pairs} if loads.friction_circle else {}
        biggest = max([j.size for j in statics.joints if j.name.startswith("F")] + [1e-300])
        if not math.isfinite(biggest):
            break                           # the pins' couples ran away: it locks
        change = max([abs(now[k] - sizes.get(k, math.inf)) for k in now] + [0.0])
        if (not loads.friction or held == sides) and change <= 1e-15 * biggest:
            if loads.friction:
                _one_way(mech, kin, loads, sides, pin_couples(mech, kin, loads, sizes))
            return statics
        # The pins' couples shrink each round's change when they settle; three rounds of
        # growth beyond the rounding mean they run away.
        growing = growing + 1 if last < change and change > 1e-12 * biggest else 0
        if growing >= 3:
            break
        sides, sizes, last = held, now, change
    raise InputError(f"with friction (μ = {loads.friction:g} at the slides, friction circles "
                     f"of {loads.friction_circle:g} m at the pins) the forces do not settle: "
                     "the mechanism locks at this position", file=mech.source or None)


def _one_way(mech: Mechanism, kin: Kinematics, loads: Loads, found: dict[int, float],
             couples: dict[int, float]) -> None:
    """Raise if the sliding slides' pushes hold on another choice of sides than ``found``
    as well: friction then leaves the forces unfixed (two sets of forces each consistent
    with the friction they take), and no one answer is the mechanism's."""
    sliding = [i for i, s in enumerate(mech.slides) if _sliding(mech, kin, s) != (0.0, 0.0)]
    for signs in itertools.product((1.0, -1.0), repeat=len(sliding)):
        sides = dict(found) | dict(zip(sliding, signs))
        if sides == found:
            continue
        with np.errstate(over="ignore", invalid="ignore"):
            _, pushes = _solve(mech, kin, loads, sides, couples)
        if all((1.0 if pushes[i] >= 0.0 else -1.0) == sides[i] for i in sliding):
            d = mech.drive
            raise InputError(f"at θ{d.link} = {mech.units.angle_brief(d.angle)} friction of "
                             f"μ = {loads.friction:g} holds the slides' pushes on two sets of "
                             "sides, so it leaves the forces unfixed: the mechanism jams here",
                             file=mech.source or None)


_ROUNDS = 200
"""The most rounds friction is solved in: the pins' couples shrink their change by about
the friction circle over the link each round, the slides' sides settle in a few."""


def pin_couples(mech: Mechanism, kin: Kinematics, loads: Loads,
                sizes: dict[tuple[str, int, int], float]) -> dict[int, float]:
    """Each link's friction couple from its pins (N·m, CCW +): at a pin whose force is
    ``sizes[pin]``, the force touches the friction circle of radius ρ on the side that
    resists the turning of one link on the other, a couple ρ·|F| against it on each. A pin
    that turns no faster than the rounding of a zero (:func:`~..loads.resting_speed` of the
    fastest link at the solver's conditioning) rests: its turning must not choose
    friction's side, and it takes no couple."""
    out: dict[int, float] = {}
    fastest = max([abs(w) for w in kin.omegas.values()] + [0.0])
    still = resting_speed(fastest, kin.conditioning)
    for pin in mech.pin_pairs:
        point, by, on = pin
        turning = kin.omegas.get(on, 0.0) - kin.omegas.get(by, 0.0)
        if loads.friction_circle:
            _refuse_near_rest(mech, kin, abs(turning), fastest, f"link {on} turns on link "
                              f"{by} at the pin {point}", of="rate")
        if abs(turning) <= still or pin not in sizes:
            continue
        m = -math.copysign(loads.friction_circle * sizes[pin], turning)
        out[on] = out.get(on, 0.0) + m
        out[by] = out.get(by, 0.0) - m
    return out


def _fastest(kin: Kinematics) -> float:
    """The fastest a point of the mechanism moves (m/s)."""
    return max([math.hypot(*v) for v in kin.velocities.values()] + [0.0])


def _resting(kin: Kinematics) -> float:
    """The fastest a point may move, or slide on another, and still rest (m/s): the rounding
    of a zero among the mechanism's speeds at the solver's conditioning
    (:func:`~..loads.resting_speed`)."""
    return resting_speed(_fastest(kin), kin.conditioning)


def _refuse_near_rest(mech: Mechanism, kin: Kinematics, speed: float, fastest: float,
                      moving: str, **said) -> None:
    """Raise if ``speed`` is too near rest to tell which way it moves
    (:func:`~..loads.near_rest` of the rounding of a zero among speeds, or rates, up to
    ``fastest``), saying where and what ``moving`` is."""
    if near_rest(speed, resting_speed(fastest, kin.conditioning)):
        raise InputError(near_rest_refusal(mech, moving, speed / fastest, **said),
                         file=mech.source or None)


def _sliding(mech: Mechanism, kin: Kinematics, slide) -> tuple[float, float]:
    """The unit velocity of the slider on its guide; nothing when it rests (within the
    rounding of a zero: friction's direction is then undefined, and it takes no side).

    Raises
    ------
    InputError
        If it slides too near rest to tell which way (:func:`~..loads.near_rest`).
    """
    rate = next((r for r in kin.slide_rates if r.slide is slide), None)
    if rate is not None:
        _refuse_near_rest(mech, kin, abs(rate.velocity), _fastest(kin),
                          f"link {slide.link} slides on link {slide.guide_link}")
    if rate is None or abs(rate.velocity) <= _resting(kin):
        return (0.0, 0.0)
    sign = 1.0 if rate.velocity > 0.0 else -1.0
    return (sign * rate.direction[0], sign * rate.direction[1])


def _solve(mech: Mechanism, kin: Kinematics, loads: Loads, sides: dict[int, float],
           couples: dict[int, float]) -> tuple[Statics, dict[int, float]]:
    """Every link's three equations with the slides' pushes on the ``sides`` given and the
    pins' friction ``couples`` (link → N·m) as known loads; the solution, and each slide's
    normal push."""
    moving = [k.number for k in mech.links if k.number != 1]
    row = {n: 3 * i for i, n in enumerate(moving)}
    columns: list[tuple[str, int, int, tuple[float, float], str, tuple[float, float]]] = []
    cols: list[np.ndarray] = []

    def fresh(name: str) -> str:
        """A joint's name, primed if the same two links already have one (F_14′)."""
        while any(c[0] == name for c in columns):
            name += "′"
        return name

    def add(name, by, on, at, kind, effect, along=(0.0, 0.0)) -> None:
        """One unknown: ``effect`` maps a link to its (Fx, Fy, M about origin) per unit."""
        col = np.zeros(3 * len(moving))
        for link, (fx, fy, mz) in effect.items():
            if link in row:
                r = row[link]
                col[r:r + 3] += (fx, fy, mz)
        columns.append((name, by, on, at, kind, along))
        cols.append(col)

    def arm(link: int, at) -> tuple[float, float]:
        o = kin.origins[link] if link != 1 else (0.0, 0.0)
        return (at[0] - o[0], at[1] - o[1])

    for point, by, other in mech.pin_pairs:
        at = kin.points.get(point)
        name = fresh(f"F_{by}{other}")
        for axis, unit in (("x", (1.0, 0.0)), ("y", (0.0, 1.0))):
            add(name, by, other, at, axis, {
                other: (unit[0], unit[1], _cross(arm(other, at), unit)),
                by: (-unit[0], -unit[1], -_cross(arm(by, at), unit))})
    slide_column = {}
    for k, s in enumerate(mech.slides):
        at = kin.points[s.point] if s.point in kin.points else world_point(
            kin, mech, s.link, mech.link(s.link).local(s.point))
        d = _direction(kin, s.guide_link, s.direction)
        sliding = _sliding(mech, kin, s) if loads.friction else (0.0, 0.0)
        n = leaning((-d[1], d[0]), sliding, loads.friction, sides[k])
        slide_column[k] = len(columns)
        add(fresh(f"F_{s.guide_link}{s.link}"), s.guide_link, s.link, at, "n", {
            s.link: (n[0], n[1], _cross(arm(s.link, at), n)),
            s.guide_link: (-n[0], -n[1], -_cross(arm(s.guide_link, at), n))}, n)
        if "T" in JOINT_EQUATIONS[s.type.key].reactions:
            add(fresh(f"T_{s.guide_link}{s.link}"), s.guide_link, s.link, at, "m",
                {s.link: (0.0, 0.0, 1.0), s.guide_link: (0.0, 0.0, -1.0)})
    driver = mech.drive.link
    add(f"T_{driver}", 1, driver, kin.origins[driver], "drive", {driver: (0.0, 0.0, 1.0)})
    a = np.column_stack(cols)
    b = np.zeros(3 * len(moving))
    for link in moving:
        r = row[link]
        for at, f, mz in loads_on(kin, mech, loads, link):
            b[r:r + 3] -= (f[0], f[1], _cross(arm(link, at), f) + mz)
        b[r + 2] -= couples.get(link, 0.0)
    _refuse_redundancy(a, columns, mech)
    # Equilibrated: each row and column over its largest entry, so a moment row (lever arms
    # of a small mechanism) weighs as a force row does, and a small joint force is found to
    # its own rounding, not to the largest one's times the system's spread of scales.
    rows = np.max(np.abs(a), axis=1)
    rows[rows == 0.0] = 1.0
    cols = np.max(np.abs(a / rows[:, None]), axis=0)
    cols[cols == 0.0] = 1.0
    scaled = a / rows[:, None] / cols[None, :]
    y, *_ = np.linalg.lstsq(scaled, b / rows, rcond=None)
    x = _refined(a, b, y / cols, lambda r: np.linalg.lstsq(scaled, r / rows, rcond=None)[0]
                 / cols)
    sv = np.linalg.svd(scaled, compute_uv=False)
    residual = float(np.max(np.abs(a @ x - b))) if len(b) else 0.0
    joints, i = [], 0
    while i < len(columns):
        name, by, on, at, kind, along = columns[i]
        if kind == "x":
            joints.append(JointForce(name, by, on, at, (float(x[i]), float(x[i + 1]))))
            i += 2
            continue
        if kind == "n":
            joints.append(JointForce(name, by, on, at, (float(along[0] * x[i]),
                                                         float(along[1] * x[i]))))
        elif kind == "m":
            joints.append(JointForce(name, by, on, at, moment=float(x[i])))
        i += 1
    pushes = {k: float(x[i]) for k, i in slide_column.items()}
    return (Statics(tuple(joints), float(x[-1]), driver, residual,
                    float(sv[-1] / sv[0]) if len(sv) and sv[0] else 0.0,
                    tuple(pushes[k] for k in range(len(mech.slides)))), pushes)


def _refined(a: np.ndarray, b: np.ndarray, x: np.ndarray, solve, rounds: int = 2) -> np.ndarray:
    """``x`` refined against its residual b − a·x, each row summed exactly (``math.fsum``
    of its products): a joint force many times smaller than the loads (a light dyad beside
    a heavy load at the crank's pivot) is then found to the rounding of its own equations,
    not to the largest force's times the system's spread of scales."""
    rows, rhs = a.tolist(), b.tolist()
    for _ in range(rounds):
        xs = x.tolist()
        r = np.array([math.fsum([bi] + [-aij * xj for aij, xj in zip(row, xs)])
                      for row, bi in zip(rows, rhs)])
        if not r.any():
            break
        x = x + solve(r)
    return x


def _refuse_redundancy(a: np.ndarray, columns, mech: Mechanism) -> None:
    """Raise if the joints constrain the mechanism more than once, naming them."""
    rows, unknowns = a.shape
    u, sv, vt = np.linalg.svd(a)
    tol = max(a.shape) * np.finfo(float).eps * (sv[0] if len(sv) else 1.0)
    rank = int(np.sum(sv > tol))
    if rank == unknowns and unknowns == rows:
        return
    if unknowns > rank:
        null = vt[rank:]
        weight = np.max(np.abs(null), axis=0)
        names = list(dict.fromkeys(columns[k][0] for k in range(unknowns)
                                   if weight[k] > 1e-8))
        raise InputError(f"the force system is statically indeterminate: the joints "
                         f"{', '.join(names)} constrain the mechanism more than once, so "
                         "their forces cannot be told apart", file=mech.source or None)
    raise InputError(f"the joints leave the mechanism {rows - rank} freedom(s) more than the "
                     "driver can hold: no force balance", file=mech.source or None)


def power_torque(mech: Mechanism, kin: Kinematics, loads: Loads,
                 statics: Statics | None = None) -> float:
    """The driving torque by the balance of power, T·ω_in + Σ F·v + Σ M·ω = D, over every
    load and inertia load. Frictionless joints do no work (D = 0), so no joint force
    enters; with friction at the slides each dissipates D = Σ μ·|N|·|v_slide|, its push N
    from ``statics`` (solved here if not given).

    Raises
    ------
    InputError
        If the input stands still: power then fixes no torque.
    """
    power, _ = _power(mech, kin, loads, statics)
    return -power / kin.omegas[mech.drive.link]


def torque_rounding(mech: Mechanism, kin: Kinematics, loads: Loads,
                    statics: Statics | None = None) -> float:
    """The size (N·m) the driving torque is made of, and so rounds at: the balance of
    power's terms taken each at its full size, |F|·|v| and |M·ω| (a force square to its
    point's path, a crank's own inertia force, does no work but rounds at that size in the
    moment that cancels it), and what each joint's friction dissipates, over |ω_in|.

    Raises
    ------
    InputError
        If the input stands still.
    """
    _, size = _power(mech, kin, loads, statics)
    return size / abs(kin.omegas[mech.drive.link])


def _power(mech: Mechanism, kin: Kinematics, loads: Loads, statics: Statics | None
           ) -> tuple[float, float]:
    """The power of every load and inertia load less what friction dissipates (W), and the
    sum of its terms' full sizes (W)."""
    driver = mech.drive.link
    if kin.omegas[driver] == 0.0:
        raise InputError("the input stands still, so the balance of power fixes no torque",
                         file=mech.source or None)
    terms, sizes = [], []
    for k in mech.links:
        if k.number == 1:
            continue
        for at, f, mz in loads_on(kin, mech, loads, k.number):
            v = point_velocity(kin, mech, k.number, at)
            w = kin.omegas[k.number]
            terms.append(f[0] * v[0] + f[1] * v[1] + mz * w)
            sizes.append(math.hypot(*f) * math.hypot(*v) + abs(mz * w))
    if loads.friction or loads.friction_circle:
        statics = statics or balance(mech, kin, loads)
        speeds = {id(r.slide): abs(r.velocity) for r in kin.slide_rates
                  if loads.friction and _sliding(mech, kin, r.slide) != (0.0, 0.0)}
        lost = [loads.friction * abs(n) * speeds.get(id(s), 0.0)
                for s, n in zip(mech.slides, statics.pushes)]
        lost += [loads.friction_circle * math.hypot(*statics.joint(f"F_{by}{on}").force)
                 * abs(kin.omegas.get(on, 0.0) - kin.omegas.get(by, 0.0))
                 for _, by, on in mech.pin_pairs]
        terms.append(-math.fsum(lost))
        sizes += lost
    return math.fsum(terms), math.fsum(sizes)
