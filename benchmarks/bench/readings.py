"""Each graphical method's numbers, read off its construction, beside two references.

A method run on a mechanism gives :class:`Reading` s: a key naming the quantity, the
value read off the drawing, its conditioning (the worst, compounded, along the acts it
rests on, as the construction reports it) and the scale an error is measured against.
The same keys are answered by :class:`FloatReference` (the float64 analytic solver, as
``tarsim solve`` checks against) and by :class:`MpReference` (the 50-digit mpmath
reference of :mod:`.mpref`), and :func:`error` measures one against the other the way
``tarsim solve`` does (:mod:`tarsim.constructions.checks`): a point and a centre
relative to the mechanism's size (a far centre to its distance, one at infinity by
angle), a vector or a rate relative to the larger of itself and the input's, a time
ratio and a stroke relative to themselves.

Keys: ``("P", name)`` a joint, ``("I", i, j)`` a centre, ``("V", point, link)`` and
``("A", point, link)`` a velocity and an acceleration (``link`` None: the point on
the first link that carries it), ``("w", k)`` and ``("a", k)`` ω and α,
``("cor", point)`` a Coriolis component, ``("TR",)`` and ``("S",)`` the time ratio
and the stroke.
"""

from __future__ import annotations

import math
import statistics
import time
from collections.abc import Callable
from dataclasses import dataclass, field

from tarsim.constructions.linkages.acceleration_polygon import draw_acceleration_polygon
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.linkages.assembly_record import point_ref
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.linkages.kennedy import locate_centres
from tarsim.constructions.linkages.limit_positions import draw_limit_positions, limit_kind
from tarsim.constructions.model import Mechanism
from tarsim.constructions.reference import solver
from tarsim.constructions.reference.centres import instant_centre, shared_pin
from tarsim.constructions.reference.limits import limit_reference
from tarsim.constructions.scales import nice
from tarsim.constructions.linkages.velocity_by_centres import (velocity_by_parallel_lines,
                                                               velocity_by_radius_rotation)
from tarsim.constructions.linkages.velocity_by_components import velocity_by_components
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon

from .mpref import Unmodelled, at_angle, mp_limits, mp_solve
from .timing import median_time

__all__ = ["METHODS", "Reading", "Run", "run_method", "FloatReference", "MpReference",
           "error", "tip_key", "median_time"]

EPS = 2.220446049250313e-16


@dataclass(frozen=True)
class Reading:
    """One number read off a construction: its key, value, conditioning and error scale."""

    key: tuple
    value: tuple
    conditioning: float
    scale: float


@dataclass
class Run:
    """One method on one mechanism: its readings, the median seconds per run, or why not."""

    method: str
    readings: list[Reading] = field(default_factory=list)
    seconds: float = math.nan
    refused: list[str] = field(default_factory=list)
    limits: object = None


def tip_key(name: str, mech: Mechanism) -> tuple[str, int | None]:
    """A polygon tip's point and link: ``"A4"`` is A taken on link 4, ``"B"`` (or ``"O2"``, a
    point's own name) the point itself."""
    if name in mech.point_names:
        return name, None
    i = len(name.rstrip("0123456789"))
    return (name[:i], int(name[i:])) if i < len(name) else (name, None)


def _timed(setup: Callable[[], object], act: Callable[[object], object], repeat: int):
    """Run ``act(setup())`` ``repeat`` times; return the last result and the median seconds
    of ``act`` alone (each run on a fresh setup: a construction is drawn once)."""
    times, out = [], None
    for _ in range(repeat):
        given = setup()
        t0 = time.perf_counter()
        out = act(given)
        times.append(time.perf_counter() - t0)
    return out, statistics.median(times)


def _speed_scale(mech: Mechanism, asm) -> float:
    """Drawing metres per m/s: the input velocity about half the mechanism's size."""
    v = mech.input_speed
    return 1.0 if v == 0.0 else nice(asm.size / (2.0 * v), up=False)


def _positions(mech, repeat):
    asm, t = _timed(lambda: mech, assemble, repeat)
    return [Reading(("P", n), asm.xy(n), asm[point_ref(n)].conditioning, asm.size)
            for n in mech.point_names], t, []


def _centres(mech, repeat):
    cs, t = _timed(lambda: assemble(mech), locate_centres, repeat)
    size = cs.assembly.size
    out = []
    for (i, j) in cs.found:
        p = cs.point(i, j)
        value = (*p.direction, 0.0) if p.is_at_infinity else (*p.xy, 1.0)
        out.append(Reading(("I", i, j), value, cs.conditioning(i, j), size))
    return out, t, []


def _moving_points(mech: Mechanism) -> list[str]:
    return [n for n in mech.point_names if 1 not in mech.links_at(n)]


def _by_centres(draw):
    """A velocity method that rests on the centres: V of every moving point."""
    def run(mech, repeat):
        def setup():
            asm = assemble(mech)
            return asm, locate_centres(asm)

        def act(given):
            asm, cs = given
            found, refused = [], []
            for p in _moving_points(mech):
                try:
                    found.append((p, draw(asm, cs, p)))
                except TarsimError as e:
                    refused.append(f"V_{p}: {e}")
            return asm, found, refused
        (asm, found, refused), t = _timed(setup, act, repeat)
        s = mech.input_speed
        return [Reading(("V", p, r.link), r.value(asm), asm[r.vector].conditioning, s)
                for p, r in found], t, refused
    return run


def _rr(asm, cs, p):
    return velocity_by_radius_rotation(asm, cs, p, scale=_speed_scale(asm.mechanism, asm))


def _pl(asm, cs, p):
    return velocity_by_parallel_lines(asm, cs, p, scale=_speed_scale(asm.mechanism, asm))


def _components(mech, repeat):
    return _by_centres(lambda asm, cs, p: velocity_by_components(
        asm, p, scale=_speed_scale(mech, asm)))(mech, repeat)


def _velocity_polygon(mech, repeat):
    vp, t = _timed(lambda: assemble(mech), draw_velocity_polygon, repeat)
    cond, s = vp.worst(), mech.input_speed
    out = [Reading(("V", *tip_key(k, mech)), vp.vector(k), cond, s) for k in vp.tips]
    out += [Reading(("w", k), (w,), cond, abs(mech.drive.omega)) for k, w in vp.rates.items()]
    return out, t, []


def _acceleration_polygon(mech, repeat):
    def setup():
        asm = assemble(mech)
        return asm, draw_velocity_polygon(asm)
    (ap, vp), t = _timed(setup, lambda g: (draw_acceleration_polygon(*g), g[1]), repeat)
    cond, a_in = ap.worst() * vp.worst(), mech.input_acceleration
    d = mech.drive
    out = [Reading(("A", *tip_key(k, mech)), ap.vector(k), cond, a_in) for k in ap.tips]
    out += [Reading(("a", k), (a,), cond, math.hypot(d.omega ** 2, d.alpha))
            for k, a in ap.rates.items()]
    out += [Reading(("cor", p), ap.coriolis_of(p), cond, a_in) for p in ap.coriolis]
    return out, t, []


def _limits(mech, repeat):
    lp, t = _timed(lambda: mech, draw_limit_positions, repeat)
    out = [Reading(("TR",), (lp.time_ratio,), lp.conditioning, lp.time_ratio)]
    if lp.stroke is not None:
        out.append(Reading(("S",), (lp.stroke,), lp.conditioning, lp.stroke))
    return out, t, [], lp


METHODS: dict[str, Callable] = {
    "position by compass": _positions,
    "centres by Kennedy": _centres,
    "radius rotation": _by_centres(_rr),
    "parallel lines": _by_centres(_pl),
    "components": _components,
    "velocity polygon": _velocity_polygon,
    "acceleration polygon (with Coriolis)": _acceleration_polygon,
    "limit positions": _limits,
}
"""The course's methods, each run on a mechanism as ``fn(mech, repeat)``."""


def run_method(method: str, mech: Mechanism, repeat: int = 3) -> Run:
    """Run ``method`` on ``mech``; a refusal (a TarsimError) is kept as its one line."""
    if method == "limit positions" and limit_kind(mech) is None:
        return Run(method)              # not a crank-driven dyad: the method does not apply
    try:
        got = METHODS[method](mech, repeat)
    except TarsimError as e:
        return Run(method, refused=[str(e)])
    readings, seconds, refused = got[:3]
    return Run(method, readings, seconds, refused, got[3] if len(got) > 3 else None)


# ----- the references ------------------------------------------------------------------------
class _Reference:
    """What both references answer, by key; subclasses give the kinematics."""

    mech: Mechanism
    drawn_limits = None
    """The limit positions as drawn (their crank angles start the reference's search)."""

    def _coriolis(self, point: str) -> tuple:
        slide = next(s for s in (*self.mech.slides, *self.mech.arcs)
                     if s.point == point and s.guide_link != 1)
        (px, py), (qx, qy) = (self._velocity(point, k) for k in (slide.link, slide.guide_link))
        w = self._omega(slide.guide_link)
        return -2 * w * (py - qy), 2 * w * (px - qx)

    def value(self, key: tuple) -> tuple | None:
        """The reference value of ``key``, as floats; None where it has none."""
        kind = key[0]
        if kind == "P":
            out = self._point(key[1])
        elif kind == "I":
            out = self._centre(key[1], key[2])
        elif kind == "V":
            out = self._velocity(key[1], key[2])
        elif kind == "A":
            out = self._acceleration(key[1], key[2])
        elif kind == "w":
            out = (self._omega(key[1]),)
        elif kind == "a":
            out = (self._alpha(key[1]),)
        elif kind == "cor":
            out = self._coriolis(key[1])
        else:
            out = self._limit(kind)
        return None if out is None else tuple(float(v) for v in out)


class FloatReference(_Reference):
    """The float64 analytic solver (the check ``tarsim solve`` makes)."""

    def __init__(self, mech: Mechanism):
        self.mech = mech
        self.places = solver.solve_positions(mech)
        try:
            self.kin = solver.solve(mech)
        except solver.SingularPosition:
            self.kin = None
        self._limits = None

    def _point(self, name):
        return self.places[name]

    def _centre(self, i, j):
        if self.kin is None:
            return None
        try:
            c = instant_centre(self.kin, i, j, pin=shared_pin(self.mech, i, j))
        except TarsimError:
            return None
        return (*c.direction, 0.0) if c.is_at_infinity else (*c.point, 1.0)

    def _velocity(self, point, link):
        return self._on_link(point, link, "velocities", solver.point_velocity)

    def _acceleration(self, point, link):
        return self._on_link(point, link, "accelerations", solver.point_acceleration)

    def _on_link(self, point, link, table: str, of_link):
        """A point's velocity or acceleration: as the solver gives it, or taken on ``link``."""
        if self.kin is None:
            return None
        if link is None:       # a point the mechanism does not name (a wheel's contact): none
            return getattr(self.kin, table).get(point)
        return of_link(self.kin, self.mech, link, point)

    def _omega(self, k):
        return None if self.kin is None else (0.0 if k == 1 else self.kin.omegas[k])

    def _alpha(self, k):
        return None if self.kin is None else (0.0 if k == 1 else self.kin.alphas[k])

    def _coriolis(self, point):
        return None if self.kin is None else super()._coriolis(point)

    def _limit(self, kind):
        if self._limits is None:
            lp = self.drawn_limits
            try:
                self._limits = limit_reference(self.mech, point=lp.point, link=lp.output)
            except TarsimError:         # a crank that stops at a change point has none
                return None
        return (self._limits.time_ratio,) if kind == "TR" else (self._limits.stroke,)


class MpReference(_Reference):
    """The 50-digit mpmath reference of :mod:`.mpref`; Newton starts from ``places``."""

    def __init__(self, mech: Mechanism, places: dict):
        self.mech = mech
        self.kin = mp_solve(mech, places)
        self._limits = None

    def _point(self, name):
        return self.kin.points[name]

    def _centre(self, i, j):
        c = self.kin.centre(i, j)
        if c is None:
            return None                     # moving together: no centre
        if c.point is not None:
            return (*c.point, 1)
        dx, dy = c.direction
        n = math.hypot(float(dx), float(dy))
        return (float(dx) / n, float(dy) / n, 0)

    def _velocity(self, point, link):
        return self.kin.velocity(point, link)

    def _acceleration(self, point, link):
        return self.kin.acceleration(point, link)

    def _omega(self, k):
        return self.kin.omega(k)

    def _alpha(self, k):
        return 0 if k == 1 else self.kin.alphas[k]

    def _limit(self, kind):
        if self._limits is None:
            lp = self.drawn_limits
            m = solver.follow_branches(self.mech)
            starts = [solver.solve_positions(at_angle(m, a)) for a in lp.crank_angles]
            try:
                self._limits = mp_limits(self.mech, lp.crank_angles, starts, point=lp.point,
                                         link=lp.output)
            except (ArithmeticError, Unmodelled):   # singular there (a change point)
                return None
        return (self._limits.time_ratio,) if kind == "TR" else (self._limits.stroke,)


# ----- the measure -----------------------------------------------------------------------
FAR = 1e6
"""A finite centre beyond FAR × size may be compared with a direction (by angle)."""


def error(reading: Reading, ref: tuple | None, size: float) -> float:
    """The relative error of ``reading`` against ``ref`` (see the module); nan if no ref."""
    if ref is None:
        return math.nan
    kind, v = reading.key[0], reading.value
    if kind == "P":
        return math.dist(v, ref) / size
    if kind == "I":
        return _centre_error(v, ref, size)
    if kind in ("TR", "S"):
        return abs(v[0] - ref[0]) / abs(ref[0])
    return math.dist(v, ref) / max(math.hypot(*ref), reading.scale, 1e-300)


def _centre_error(v: tuple, ref: tuple, size: float) -> float:
    """Finite: distance over max(size, |ref|); at infinity: |sin| of the angle between."""
    if v[2] and ref[2]:
        return math.dist(v[:2], ref[:2]) / max(size, math.hypot(*ref[:2]))
    if not v[2] and not ref[2]:
        return abs(v[0] * ref[1] - v[1] * ref[0])
    (px, py), (dx, dy) = (ref[:2], v[:2]) if v[2] == 0 else (v[:2], ref[:2])
    r = math.hypot(px, py)
    if r <= FAR * size:
        return math.inf
    return abs(px * dy - py * dx) / (r * math.hypot(dx, dy))
