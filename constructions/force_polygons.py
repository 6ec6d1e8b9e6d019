"""Graphical kinetostatics: the joint forces and the driving torque by force polygons, link by
link, as the textbooks teach it, the inertia loads read off the acceleration polygon.

**Inertia (D'Alembert).** Each link's centre of mass G gets its image g′ on the acceleration
polygon: from the tip k′ of a point K of the link, the normal part ω²·KG toward K, then the
tangential part α·KG square to it. Its inertia force −m·a_G is the vector g′ → o_a times
m; its inertia couple is −I·α. With its weight and the external loads, every load on each
link is then known.

**The dyad, from the output back to the driver** (a four-bar's coupler and rocker, or a
slider-crank's rod and block). The pin force F_A at the coupler's outer pin A is split
into its part square to AB, found from the coupler's moments about the middle pin B
(F_Aᵗ·AB = −ΣM_B), and its part along AB, unknown. A rocker's pin at its frame pivot C is
split the same way about B; a block's guide pushes square to the guide. The dyad's force
polygon lays every known load and the two square parts head to tail; a line along AB
through its start and a line along CB (or square to the guide) through its end close it
where they cross. The middle pin's force is read off one link's own polygon, and a block's
couple from its moments about B.

**The driver.** The coupler's pull on the crank and the crank's loads close on the frame's
force at its pivot, and the moments about the pivot give the driving torque.

Each act is a recorded step in the FORCE panel, drawn at a force scale (drawing metres per
newton); the forces are read back off it.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field

from . import geometry as g
from . import asks as A
from .acceleration_polygon import drawn_acceleration_polygon
from .checks import NOISE, Answer, FigureSpec, quiet, vector_value
from .errors import GeometryError, TarsimError
from .force_rounding import answer_roundings, image_base, load_roundings, read_conditioning
from .force_rounding import speed_rounding
from .force_sliding import (dyad_slides, lever_gain, lever_slides, link_rates, pin_rests,
                            pin_roundings, say_resting)
from .loads import Loads, crank_tangent, leaning, near_rest, near_rest_refusal, stroke_axis
from .model import Mechanism, SlideKind
from .narration import Number, Quantity, Word, phrase
from .record import Construction, Kind, Panel, Ref, Role
from .scales import nice
from .velocity_polygon import drawn_velocity_polygon

__all__ = ["BODIES", "FORCES", "FORCES_WHY_NOT", "LOADS", "Forces", "answer", "draw_forces",
           "force_names", "forces_askable", "drawn_forces"]

Vec = tuple[float, float]

FORCES = FigureSpec("forces", "Force polygons", "force polygons", kind="forces")
"""The figure the force polygons are drawn in."""

LOADS = FigureSpec("loads", "Loads", "space diagram with the loads", kind="loads")
"""The mechanism with every load and inertia force on it, at a force scale."""

BODIES = FigureSpec("free-bodies", "Free bodies", "free-body diagrams", kind="bodies")
"""Each link alone with every force on it."""

OBLIQUE = 10.0
"""How many times more obliquely than the split's the three-force construction's lines may
cross (a digit of the forces given up for the construction the course teaches for an
unloaded output): a couple that dwarfs the coupler's resultant throws X far off, where AX
and the output's line all but run together and the forces are lost to X's rounding."""


@dataclass
class Forces:
    """The drawn force analysis: each joint force (N, on link ``on`` from ``by``) as read off
    its polygon, each block's couple (N·m), the driving torque (N·m, CCW +), the scale, and
    the steps that are each answer."""

    scale: float
    joints: dict[str, Vec] = field(default_factory=dict)
    couples: dict[str, float] = field(default_factory=dict)
    torque: float = 0.0
    refs: dict[str, tuple[Ref, ...]] = field(default_factory=dict)
    inertia: dict[int, tuple[Vec, float]] = field(default_factory=dict)
    """Each massive link's inertia force (N) and couple (N·m), as read off the polygon."""
    every: tuple[Ref, ...] = ()
    """Every step of the analysis, for its figure and its steps: each answer shows it all."""
    loads: dict[int, list[tuple[Vec, Vec, float, str]]] = field(default_factory=dict)
    """Each moving link's known loads (where, force N, couple N·m, name): its inertia force
    and couple, its weight, the external forces and couples."""
    efforts: dict[str, float] = field(default_factory=dict)
    """The engine's efforts as the textbooks name them (:class:`~.asks.Effort`)."""
    bodies: dict[int, list[tuple[Vec, Vec, float, str]]] = field(default_factory=dict)
    """Each moving link as a free body: every force on it (where, force N, couple N·m, its
    name), the loads and the joints' forces as the polygons found them."""
    rounding: dict[str, float] | None = field(default_factory=dict)
    """What the rounding of the inertia loads read off the acceleration polygon makes of
    each answer (N, N·m), by :mod:`~.force_rounding`; None where it is without bound."""


@dataclass(frozen=True)
class _Shape:
    """The mechanism as the dyad method sees it: driver d (pivot O, pin A to the coupler),
    coupler i (pins A and B), output j (pin B; pivot C, or a block on a frame guide)."""

    d: int
    i: int
    j: int
    o: str
    a: str
    b: str
    c: str | None
    guide: tuple[float, float] | None


def force_names(mech: Mechanism) -> set[str]:
    """Every joint force, block couple and driving torque of ``mech``, as an exercise asks
    them: F_23 (of link 2 on link 3), T_14 (a block's couple from its guide), T2."""
    out = {f"T{mech.drive.link}"} | {f"F_{by}{on}" for _, by, on in mech.pin_pairs}
    for s in mech.slides:
        out.add(f"F_{s.guide_link}{s.link}")
        if s.kind is SlideKind.BLOCK:
            out.add(f"T_{s.guide_link}{s.link}")
    return out


def shape_of(mech: Mechanism) -> _Shape:
    """The driver and its dyad.

    Raises
    ------
    TarsimError
        If the mechanism is not a four-bar or a slider-crank.
    """
    why = _WHY
    moving = [k.number for k in mech.links if k.number != 1]
    d = mech.drive.link
    if len(moving) != 3 or mech.arcs or any(s.rolling or s.contact for s in mech.slides):
        raise TarsimError(why)
    crank = mech.link(d)
    if len(crank.names) != 2 or mech.links_at(crank.names[0]) != tuple(sorted((1, d))):
        raise TarsimError(why)
    o, a = crank.names
    coupler = [n for n in mech.links_at(a) if n != d]
    if len(coupler) != 1:
        raise TarsimError(why)
    i = coupler[0]
    j = next(n for n in moving if n not in (d, i))
    # The coupler and the output may carry points of their own besides their pins (a
    # coupler point, a point a load acts at): the dyad's lines run through the pins alone.
    shared = [p for p in mech.link(i).names if p != a and j in mech.links_at(p)]
    if len(shared) != 1:
        raise TarsimError(why)
    b = shared[0]
    if not mech.slides:
        pivots = [p for p in mech.link(j).names if p != b and 1 in mech.links_at(p)]
        if len(pivots) != 1 or set(mech.links_at(pivots[0])) != {1, j}:
            raise TarsimError(why)
        return _Shape(d, i, j, o, a, b, pivots[0], None)
    (s,) = mech.slides if len(mech.slides) == 1 else (None,)
    if (s is None or s.kind is not SlideKind.BLOCK or s.guide_link != 1 or s.link != j
            or s.point != b or mech.link(j).names != (b,)):
        raise TarsimError(why)
    return _Shape(d, i, j, o, a, b, None, s.direction)


def draw_forces(work) -> Forces:
    """Draw the force analysis of the work's position (its loads in ``work.loads``): the
    group the crank drives (a dyad, or a slotted lever with its block and ram), then the
    crank.

    Raises
    ------
    TarsimError
        If the mechanism is not one drawn here, or has no loads.
    """
    mech: Mechanism = work.mechanism
    loads: Loads | None = getattr(work, "loads", None)
    if loads is None:
        raise TarsimError("forces need loads: give [[mass]], [[force]] or [[couple]] tables")
    group = _group_of(mech)
    c: Construction = work.assembly
    at = {name: c.point(name).xy for name in mech.point_names}
    inertia = _inertia(work, loads, at)
    known = {k.number: _loads(work, loads, k.number, at, inertia, group) for k in mech.links
             if k.number != 1}
    # The largest load about 80 drawing mm; a couple counts as the force it makes across
    # the mechanism, so loads of couples alone still get a scale.
    size = work.assembly.size
    biggest = max([max(math.hypot(*f), abs(m) / size) for ls in known.values()
                   for _, f, m, _ in ls] + [1e-300])
    scale = 0.08 / nice(biggest)
    # Friction leans each slide's push against its sliding; a slide at rest, to the
    # velocity polygon's rounding, takes none (a dyad's block then pushes as without).
    slides = _slides(work, group, at) if loads.friction else []
    slip = None
    if isinstance(group, _Shape) and slides and slides[0].direction != (0.0, 0.0):
        slip = (loads.friction, slides[0].direction)
    elif isinstance(group, _Lever) and slides:
        slip = (loads.friction, {s.key: s.direction for s in slides})
    still = pin_roundings(work, _lever_span(group, at)) if loads.friction_circle else None
    if still is not None:
        known = _with_pin_friction(work, c, group, at, known, scale, slip, still)
    say_resting(work, slides, still)
    rounding = {} if not loads.masses else answer_roundings(
        known, load_roundings(work, known, at),
        lambda trial: _analyse(c.scratch(), mech, group, at, trial, scale, slip),
        size=size, driver=mech.drive.link)
    out = _analyse(c, mech, group, at, known, scale, slip)
    out.inertia, out.loads, out.rounding = inertia, known, rounding
    return out


def _analyse(c, mech: Mechanism, group, at, known, scale: float, slip) -> Forces:
    """The polygons of the group the crank drives, then the crank's, drawn in ``c`` with
    the ``known`` loads.

    Raises
    ------
    TarsimError
        If the group's forces outgrow its loads past what rounding leaves of them (a dead
        point: the lines that close its polygon stand in line).
    """
    out = Forces(scale)
    draw = _Drafter(c, scale)
    if isinstance(group, _Shape):
        crank_pin, pull, o, a = _dyad(c, draw, out, group, at, known, slip)
    else:
        crank_pin, pull, o, a = _slotted(c, draw, out, group, at, known, slip)
    size = max(math.dist(p, q) for p in at.values() for q in at.values()) or 1.0
    loads = math.fsum(math.hypot(*f) + abs(m) / size for ls in known.values()
                      for _, f, m, _ in ls)
    biggest = max([math.hypot(*v) for v in out.joints.values()] + [math.hypot(*pull)])
    if not biggest * 64 * sys.float_info.epsilon <= loads:      # inf and nan fail it too
        links = " and ".join(str(n) for n in sorted({group.i, group.j})) \
            if isinstance(group, _Shape) else f"{group.b} and {group.l}"
        raise TarsimError(f"links {links} stand at a dead point: the forces that hold the "
                          "loads there outgrow them past their rounding; choose another "
                          "position")
    _crank(c, draw, out, mech.drive.link, crank_pin, pull, o, a, at, known)
    out.every = tuple(s.id for s in c if s.id.startswith("force:"))
    out.bodies = _bodies(mech, out, at, known)
    return out


def _with_pin_friction(work, c, group, at, known, scale: float, slip,
                       still: dict[int, float]) -> dict:
    """The loads with each pin's friction couple: a pin's force touches the friction circle
    (radius ρ) on the side that resists the turning of one link on the other, which is the
    force at the pin's centre and a couple ρ·|F| against the turning. |F| comes from the
    polygons themselves, so they are drawn by trial on a scratch sheet, each round with the
    last round's couples, until the forces settle; the polygons are then drawn with those.

    Raises
    ------
    TarsimError
        If the forces do not settle (the friction would lock the mechanism).
    """
    mech, loads = work.mechanism, work.loads
    rates = link_rates(work)
    pins = mech.pin_pairs
    sizes: dict = {}
    rounds = 0
    for _ in range(_ROUNDS):
        rounds += 1
        trial = c.scratch()                        # a scratch sheet over the drawing so far
        with_couples = _pin_couples(known, pins, sizes, rates, at, loads.friction_circle,
                                    still)
        locks = TarsimError(f"with friction circles of {loads.friction_circle * 1e3:g} mm "
                            "the pins' forces do not settle: the mechanism locks at this "
                            "position")
        try:
            found = _analyse(trial, mech, group, at, with_couples, scale, slip)
        except GeometryError:
            raise locks from None          # the trial ran away: its forces outgrew the sheet
        now = {pin: math.hypot(*found.joints[f"F_{pin[1]}{pin[2]}"]) for pin in pins}
        biggest = max(list(now.values()) + [1e-300])
        if not math.isfinite(biggest):
            raise locks
        if all(abs(now[k] - sizes.get(k, math.inf)) <= 1e-15 * biggest for k in now):
            break
        sizes = now
    else:
        raise locks
    # Said first among the force polygons, at their origin.
    origin = c.give("force:circles:at", g.Point(0.0, 0.0), label="", panel=Panel.FORCE)
    c.draw("force:say:circles", "mark", origin, panel=Panel.FORCE, phrase=phrase(
        "force.circles", rho=Quantity(loads.friction_circle / mech.units.metres,
                                      mech.units.length), rounds=rounds))
    return _pin_couples(known, pins, sizes, rates, at, loads.friction_circle, still)


_ROUNDS = 200
"""The most rounds of trial for the pins' friction: each round shrinks the change by about
the friction circle over the links' lengths."""


def _pin_couples(known, pins, sizes, rates, at, rho: float, still: dict[int, float]) -> dict:
    """``known`` with each pin's friction couple, ρ·|F| against the turning, on each of the
    two links (the frame's left out); a pin turning no faster than its links' rates round
    at (``still``, :func:`~.force_sliding.pin_roundings`) rests, and takes none."""
    out = {k: list(v) for k, v in known.items()}
    for pin in pins:
        point, by, on = pin
        if pin_rests(rates, still, by, on) or pin not in sizes:
            continue
        turning = rates.get(on, 0.0) - rates.get(by, 0.0)
        m = -math.copysign(rho * sizes[pin], turning)
        out[on].append((at[point], (0.0, 0.0), m, f"Mf_{by}{on}"))       # of by on on
        if by != 1:
            out[by].append((at[point], (0.0, 0.0), -m, f"Mf_{on}{by}"))
    return out


def _bodies(mech: Mechanism, out: Forces, at, known) -> dict[int, list]:
    """Every force on each moving link: its loads, each joint's force on it (F_ab on b, its
    reaction on a) and each block's couple, with the driving torque on the input."""
    where = {f"F_{by}{on}": point for point, by, on in mech.pin_pairs}
    where |= {f"F_{s.guide_link}{s.link}": s.point for s in mech.slides}
    bodies = {k: list(v) for k, v in known.items()}
    for name, f in out.joints.items():
        by, on = int(name[2]), int(name[3])
        p = at[where[name]]
        if on != 1:
            bodies[on].append((p, f, 0.0, name))
        if by != 1:
            bodies[by].append((p, (-f[0], -f[1]), 0.0, f"F_{on}{by}"))
    for name, m in out.couples.items():
        by, on = int(name[2]), int(name[3])
        p = at[where[f"F_{by}{on}"]]
        bodies[on].append((p, (0.0, 0.0), m, name))
        if by != 1:
            bodies[by].append((p, (0.0, 0.0), -m, f"T_{on}{by}"))
    d = mech.drive.link
    bodies[d].append((at[mech.link(d).names[0]], (0.0, 0.0), out.torque, f"T{d}"))
    return bodies


_WHY = ("the force polygons draw a four-bar, a slider-crank or a slotted lever only; this "
        "mechanism's forces are in the turning-moment diagram (tarsim sweep)")


def _slides(work, group, at) -> list:
    """The slides of the group the crank drives, as the velocity polygon reads them
    (:mod:`~.force_sliding`): a slider-crank's block, a slotted lever's block and ram.

    Raises
    ------
    TarsimError
        If one slides too near rest to tell which way (:func:`~.loads.near_rest`).
    """
    if isinstance(group, _Shape):
        return [] if group.guide is None else dyad_slides(work, group.j, group.b)
    return lever_slides(work, at, lever=group.l, block=group.b, pivot=group.p, pin=group.a,
                        ram=group.r, ram_pin=group.q)


def _gain(group, at, point: str) -> float:
    """What a slotted lever multiplies the rounding of a reading at ``point`` by
    (:func:`~.force_sliding.lever_gain`); 1 off a lever and at the crank's points."""
    if not isinstance(group, _Lever) or point in (group.o, group.a):
        return 1.0
    return lever_gain(at, group.p, group.a, point)


def _lever_span(group, at) -> tuple[int, float] | None:
    """A slotted lever and where its turning is read, |PA| from its pivot."""
    return (group.l, math.dist(at[group.p], at[group.a])) if isinstance(group, _Lever) \
        else None


def _group_of(mech: Mechanism):
    """The group the crank drives: a dyad, or a slotted lever."""
    try:
        return shape_of(mech)
    except TarsimError:
        pass
    try:
        return slotted_of(mech)
    except TarsimError:
        raise TarsimError(_WHY) from None


def _dyad(c, draw, out: Forces, sh: _Shape, at, known, slip=None):
    """A four-bar's or slider-crank's dyad: returns the coupler's link, its pull on the
    crank at A, and the crank's pivot and pin. With no load on the output the coupler is a
    three-force member, solved by :func:`_concurrent` where its lines cross squarely enough;
    else by the tangential and normal split."""
    if not _carries(known[sh.j]):
        done = _concurrent(c, draw, out, sh, at, known[sh.i], slip)
        if done is not None:
            return done
    line_ab = c.draw("force:line:AB", "line_through", c.points[sh.a], c.points[sh.b],
                     kind=Kind.LINE, panel=Panel.FORCE)
    pole = c.give("force:S", g.Point(0.0, 0.0), label="", panel=Panel.FORCE)
    c.draw("force:say:dyad", "mark", pole, panel=Panel.FORCE, label=f"links {sh.i}, {sh.j}",
           phrase=phrase("force.dyad", i=sh.i, j=sh.j))
    tip = pole
    for k in (sh.i, sh.j):
        tip = draw.loads(k, tip, known[k])
    t_a = _square(at[sh.a], at[sh.b], known[sh.i])       # F_{d i}ᵗ on i at A
    tip = draw.vector(f"t:{sh.d}{sh.i}", tip, t_a, phrase(
        "force.tangential", name=f"F_{sh.d}{sh.i}", pin=sh.a, link=sh.i, about=sh.b),
        label=f"F_{sh.d}{sh.i}ᵗ")
    if sh.c is not None:
        t_c = _square(at[sh.c], at[sh.b], known[sh.j])   # F_{1 j}ᵗ on j at C
        tip = draw.vector(f"t:1{sh.j}", tip, t_c, phrase(
            "force.tangential", name=f"F_1{sh.j}", pin=sh.c, link=sh.j, about=sh.b),
            label=f"F_1{sh.j}ᵗ")
        far = c.draw("force:line:CB", "line_through", c.points[sh.c], c.points[sh.b],
                     kind=Kind.LINE, panel=Panel.FORCE)
    else:
        t_c = (0.0, 0.0)
        if slip is None:
            far = draw.square_to(pole, sh.guide, "N")
        else:
            laid = _sum([f for k in (sh.i, sh.j) for _, f, _, _ in known[k]] + [t_a])
            along_ab = (at[sh.b][0] - at[sh.a][0], at[sh.b][1] - at[sh.a][1])
            far = draw.leaning(pole, sh.guide, _side(laid, sh.guide, slip, along_ab), slip)
    cross, end_vec, start_vec = draw.close(tip, far, pole, line_ab, phrase(
        "force.close", i=sh.i, j=sh.j), f"F_1{sh.j}" + ("ⁿ" if sh.c else ""),
        f"F_{sh.d}{sh.i}ⁿ")
    n_far, n_a = draw.read(end_vec), draw.read(start_vec)
    f_di = (t_a[0] + n_a[0], t_a[1] + n_a[1])
    joint_j = (t_c[0] + n_far[0], t_c[1] + n_far[1])
    out.joints[f"F_{min(sh.d, sh.i)}{max(sh.d, sh.i)}"] = _on(f_di, sh.d < sh.i)
    out.joints[f"F_1{sh.j}"] = joint_j
    # The middle pin, from the output's own balance: F_ij = −(its loads + the frame's).
    loads_j = _sum(f for _, f, _, _ in known[sh.j])
    f_ij = (-(loads_j[0] + joint_j[0]), -(loads_j[1] + joint_j[1]))    # i on j
    out.joints[f"F_{min(sh.i, sh.j)}{max(sh.i, sh.j)}"] = _on(f_ij, sh.i < sh.j)
    refs = (cross, end_vec, start_vec)
    out.refs = {name: refs for name in out.joints}
    if sh.c is None:
        # The block's couple from the guide: its moments about B vanish.
        out.couples[f"T_1{sh.j}"] = -_moment(at[sh.b], known[sh.j])
        out.refs[f"T_1{sh.j}"] = refs
        _piston_effort(c, out, sh, at, known[sh.j], joint_j, refs)
    return sh.i, (-f_di[0], -f_di[1]), sh.o, sh.a


def _friction_angle(slip):
    """φ = atan μ as a step says it."""
    return None if slip is None else Quantity(math.degrees(math.atan(slip[0])), "°",
                                              style="rate")


def _crossing(p: Vec, u: Vec, q: Vec, w: Vec) -> Vec | None:
    """Where the line through ``p`` along ``u`` meets the one through ``q`` along ``w``."""
    det = u[0] * w[1] - u[1] * w[0]
    if abs(det) <= 1e-12 * math.hypot(*u) * math.hypot(*w):
        return None
    t = ((q[0] - p[0]) * w[1] - (q[1] - p[1]) * w[0]) / det
    return (p[0] + t * u[0], p[1] + t * u[1])


def _side(laid: Vec, guide: Vec, slip, other: Vec | None, other_at=None) -> float:
    """Which side a guide's push comes from when friction leans it: the side whose leaned
    line, with the polygon's other closing line (along ``other``, or ``other_at(u)`` for a
    line that hangs on u), closes the ``laid`` loads with a push from that same side — the
    check a draftsman makes of the side assumed. The frictionless side when neither holds
    (a push of nothing)."""
    mu, sliding = slip
    normal = (-guide[1], guide[0])
    for side in (1.0, -1.0):
        u = leaning(normal, sliding, mu, side)
        w = other if other_at is None else other_at(u)
        parts = None if w is None else _closing(laid, u, w)
        if parts is not None and parts[0] * side >= 0.0:
            return side
    return 1.0


def _sides(laid: Vec, first, second, mu: float) -> tuple[float, float]:
    """The sides two leaning pushes come from, each (guide direction, unit sliding): the
    pair whose leaned lines close the ``laid`` loads with pushes from those same sides
    (both square to their guides, the first pair, when none holds)."""
    n1, n2 = (-first[0][1], first[0][0]), (-second[0][1], second[0][0])
    for s1 in (1.0, -1.0):
        for s2 in (1.0, -1.0):
            parts = _closing(laid, leaning(n1, first[1], mu, s1),
                             leaning(n2, second[1], mu, s2))
            if parts is not None and parts[0] * s1 >= 0.0 and parts[1] * s2 >= 0.0:
                return s1, s2
    return 1.0, 1.0


def _closing(laid: Vec, u: Vec, w: Vec) -> tuple[float, float] | None:
    """The multiples a, b with laid + a·u + b·w = 0: what two lines of known direction close
    a polygon with; None when they run parallel."""
    det = u[0] * w[1] - u[1] * w[0]
    if det == 0.0:
        return None
    return ((-laid[0] * w[1] + laid[1] * w[0]) / det, (-u[0] * laid[1] + u[1] * laid[0]) / det)


def _carries(loads) -> bool:
    """Whether any of ``loads`` is a force or a couple at all."""
    return any(f != (0.0, 0.0) or m != 0.0 for _, f, m, _ in loads)


def _concurrent(c, draw, out: Forces, sh: _Shape, at, loads, slip=None):
    """The dyad when its output carries nothing: the output is a two-force member (a rocker
    pulls along CB; a massless block only across its guide), so the coupler holds three
    forces, its loads' resultant R, the output's push along that known line through B, and
    the crank's at A. Three forces in balance meet in one point: X, where R's line crosses
    the output's; the crank's force runs along AX. The coupler's polygon, R closed by a
    parallel to each line, gives both. Returns as :func:`_dyad` does, or None when R is
    nothing, runs parallel to the output's line (X at infinity), or its lines cross
    :data:`OBLIQUE` times less squarely than the split's AB does with the output's line
    (:func:`_squareness`): the split then serves.
    """
    r = _sum(f for _, f, _, _ in loads)
    size = math.hypot(*r)
    if size == 0.0:
        return None
    # R's line: where R alone has the loads' moment about B; Q on it is the foot of the
    # loads' middle (a single load's own point).
    m_b = _moment(at[sh.b], loads)
    on = (at[sh.b][0] + m_b * r[1] / size ** 2, at[sh.b][1] - m_b * r[0] / size ** 2)
    mid = _sum(p for p, f, _, _ in loads if f != (0.0, 0.0))
    count = sum(f != (0.0, 0.0) for _, f, _, _ in loads)
    mid = (mid[0] / count, mid[1] / count) if count else on
    t = ((mid[0] - on[0]) * r[0] + (mid[1] - on[1]) * r[1]) / size ** 2
    q = (on[0] + t * r[0], on[1] + t * r[1])
    if sh.c is not None:
        dx, dy = at[sh.b][0] - at[sh.c][0], at[sh.b][1] - at[sh.c][1]
    elif slip is None:
        dx, dy = -sh.guide[1], sh.guide[0]
    else:
        # The block's push leans against its sliding, on the side the coupler's balance
        # puts it: R and the push meet at X, the crank's force runs along AX.
        def balance_at(u):
            x_at = _crossing(q, r, at[sh.b], u)
            return None if x_at is None else (x_at[0] - at[sh.a][0], x_at[1] - at[sh.a][1])
        side = _side(r, sh.guide, slip, None, balance_at)
        dx, dy = leaning((-sh.guide[1], sh.guide[0]), slip[1], slip[0], side)
    if abs(r[0] * dy - r[1] * dx) <= 1e-9 * size * math.hypot(dx, dy):
        return None
    split = abs(_sine((at[sh.b][0] - at[sh.a][0], at[sh.b][1] - at[sh.a][1]), (dx, dy)))
    if _squareness(at, sh, q, r, (dx, dy)) * OBLIQUE < split:
        return None
    qp = c.give("force:cc:Q", g.Point(*q), label="")
    along_r = c.give("force:cc:r", g.Line(-r[1] / size, r[0] / size, 0.0), label="",
                     panel=Panel.FORCE)
    line_r = c.draw("force:cc:lineR", "parallel_through", qp, along_r, kind=Kind.LINE,
                    phrase=phrase("force.resultant", i=sh.i, size=_said(size, "N"), b=sh.b))
    if sh.c is not None:
        line_j = c.draw("force:cc:lineCB", "line_through", c.points[sh.c], c.points[sh.b],
                        kind=Kind.LINE, phrase=phrase("force.two_force", j=sh.j, c=sh.c,
                                                      b=sh.b))
    else:
        # The block's line: square to the guide, or leaned (dx, dy) with friction.
        push = c.give("force:cc:push", g.Line(-dy / math.hypot(dx, dy), dx / math.hypot(dx, dy),
                                              0.0), label="", panel=Panel.FORCE)
        line_j = c.draw("force:cc:lineN", "parallel_through", c.points[sh.b], push,
                        kind=Kind.LINE, phrase=phrase(
                            "force.massless_block" if slip is None else "force.leaning_block",
                            j=sh.j, b=sh.b, phi=_friction_angle(slip)))
    x = c.draw("force:cc:X", "intersect_lines", line_r, line_j, label="X",
               phrase=phrase("force.concurrent", i=sh.i, a=sh.a))
    line_a = c.draw("force:cc:lineAX", "line_through", c.points[sh.a], x, kind=Kind.LINE)
    pole = c.give("force:S", g.Point(0.0, 0.0), label="", panel=Panel.FORCE)
    c.draw("force:say:three", "mark", pole, panel=Panel.FORCE, label=f"link {sh.i}",
           phrase=phrase("force.three", i=sh.i))
    tip = draw.loads(sh.i, pole, loads)
    cross, end_vec, start_vec = draw.close(tip, line_j, pole, line_a, phrase(
        "force.close_three", i=sh.i, j=sh.j, a=sh.a), f"F_{sh.j}{sh.i}", f"F_{sh.d}{sh.i}")
    f_ji, f_di = draw.read(end_vec), draw.read(start_vec)
    out.joints[f"F_{min(sh.d, sh.i)}{max(sh.d, sh.i)}"] = _on(f_di, sh.d < sh.i)
    out.joints[f"F_{min(sh.i, sh.j)}{max(sh.i, sh.j)}"] = _on((-f_ji[0], -f_ji[1]),
                                                              sh.i < sh.j)
    out.joints[f"F_1{sh.j}"] = f_ji             # the frame holds the output against it
    refs = (x, cross, end_vec, start_vec)
    out.refs = {name: refs for name in out.joints}
    if sh.c is None:
        out.couples[f"T_1{sh.j}"] = 0.0          # every force on the block acts through B
        out.refs[f"T_1{sh.j}"] = refs
        _piston_effort(c, out, sh, at, [], f_ji, refs)
    return sh.i, (-f_di[0], -f_di[1]), sh.o, sh.a


def _sine(u: Vec, w: Vec) -> float:
    """The sine of the angle from ``u`` to ``w``."""
    return (u[0] * w[1] - u[1] * w[0]) / (math.hypot(*u) * math.hypot(*w))


def _squareness(at, sh: _Shape, q: Vec, r: Vec, push: Vec) -> float:
    """How squarely the three-force construction's lines cross (the sine of the worse of its
    two crossings): R's line through ``q`` with the output's line (along ``push``) at X, and
    then AX with that line, which closes the polygon. X far beyond the mechanism (a couple
    that dwarfs the resultant throws R's line there) makes AX and the output's line nearly
    parallel: their difference, and every force, is then lost to the rounding of X."""
    x = _crossing(q, r, at[sh.b], push)
    if x is None:
        return 0.0
    ax = (x[0] - at[sh.a][0], x[1] - at[sh.a][1])
    return min(abs(_sine(r, push)), abs(_sine(ax, push)) if ax != (0.0, 0.0) else 0.0)


def _piston_effort(c, out: Forces, sh: _Shape, at, loads, wall: Vec, refs) -> None:
    """A slider-crank's piston effort, its loads along the stroke (laid off head to tail in
    the polygon, so their sum runs from its start to the end of the piston's part), and the
    wall's thrust, the guide's push the polygon closed on.

    Raises
    ------
    TarsimError
        Where the piston stands level with the crank's pivot along the stroke (to the
        rounding of the drawing): "toward the crank" has no sense there.
    """
    (ox, oy), (bx, by) = at[sh.o], at[sh.b]
    size = max(math.dist(at[sh.o], p) for p in at.values())
    if abs((ox - bx) * sh.guide[0] + (oy - by) * sh.guide[1]) <= 64 * sys.float_info.epsilon * size:
        m = c.mechanism
        raise TarsimError(f"piston_effort at θ{m.drive.link} = "
                          f"{m.units.angle_brief(m.drive.angle)}: the piston {sh.b} stands level "
                          f"with the crank's pivot {sh.o} along its stroke, so 'toward the crank' "
                          f"has no sense; ask F_{sh.i}{sh.j} and F_1{sh.j}")
    u = stroke_axis(at[sh.o], at[sh.b], sh.guide)
    piston = _sum(f for _, f, _, _ in loads)
    out.efforts["piston_effort"] = piston[0] * u[0] + piston[1] * u[1]
    out.efforts["wall_thrust"] = abs(-wall[0] * sh.guide[1] + wall[1] * sh.guide[0])
    said = c.draw("force:say:piston", "mark", refs[0], panel=Panel.FORCE, phrase=phrase(
        "force.piston", j=sh.j, effort=_said(out.efforts["piston_effort"], "N", ".6g"),
        thrust=_said(out.efforts["wall_thrust"], "N", ".6g")))
    out.refs["piston_effort"] = out.refs["wall_thrust"] = (*refs, said)


def _crank(c, draw, out: Forces, d: int, i: int, f_id: Vec, o: str, a: str, at, known):
    """The crank's polygon, to the right of the rest and clear of it: its loads and the pull
    ``f_id`` of link ``i`` at ``a``, closed by the frame's force at ``o``; its moments about
    ``o`` give the driving torque."""
    drawn = [s.output.xy for s in c if s.panel is Panel.FORCE and isinstance(s.output, g.Point)
             and not s.output.is_at_infinity and not s.id.startswith(("force:o:", "force:h:"))]
    chain = [(0.0, 0.0)]
    for f in [f for _, f, _, _ in known[d]] + [f_id]:
        chain.append((chain[-1][0] + f[0] * out.scale, chain[-1][1] + f[1] * out.scale))
    right = max(x for x, _ in drawn) - min(x for x, _ in chain) + 0.03
    start = c.give("force:S2", g.Point(right, 0.0), label="", panel=Panel.FORCE)
    c.draw("force:say:driver", "mark", start, panel=Panel.FORCE, label=f"link {d}",
           phrase=phrase("force.driver", d=d, i=i, o=o))
    tip = draw.loads(d, start, known[d])
    pulled = tip
    tip = draw.vector(f"{i}on{d}", tip, f_id, label=f"F_{i}{d}")
    _crank_effort(c, draw, out, pulled, tip, f"F_{i}{d}", o, a, at)
    closing = draw.join("frame", tip, start, role=Role.RESULT, label=f"F_1{d}")
    out.joints[f"F_1{d}"] = draw.read(closing)
    out.refs[f"F_1{d}"] = (closing,)
    arm = (at[a][0] - at[o][0], at[a][1] - at[o][1])
    torque = -(_moment(at[o], known[d]) + arm[0] * f_id[1] - arm[1] * f_id[0])
    out.torque = torque
    arm_size = math.hypot(*arm)
    said = c.draw("force:say:torque", "mark", start, panel=Panel.FORCE, phrase=phrase(
        "force.torque", d=d, o=o,
        torque=_said(quiet(torque, 0.08 / out.scale * arm_size), "N·m", ".6g")))
    out.refs[f"T{d}"] = (closing, said)


def _crank_effort(c, draw, out: Forces, tail: Ref, head: Ref, name: str, o: str, a: str,
                  at) -> None:
    """Split the push on the crank pin (drawn from ``tail`` to ``head``) along the crank and
    square to it: through its tail a parallel to the crank, through its head a parallel to
    the crank circle's tangent at the pin; they cross where the radial part ends and the
    tangential part, the crank effort, begins. Its moment about the pivot, effort × crank,
    is the turning moment."""
    t = crank_tangent(at[o], at[a])
    (tx, ty), (hx, hy) = c.output(tail).xy, c.output(head).xy
    push = math.hypot(hx - tx, hy - ty)
    if abs((hx - tx) * t[1] - (hy - ty) * t[0]) <= NOISE * push:
        # Square to the crank already: all of it is crank effort, nothing to split off.
        cross, part, key = head, None, "force.effort_square"
        pushed = ((hx - tx) / draw.scale, (hy - ty) / draw.scale)
    else:
        crank = c.draw("force:line:crank", "line_through", c.points[o], c.points[a],
                       kind=Kind.LINE, panel=Panel.FORCE)
        tangent = c.draw("force:line:tangent", "perpendicular_through", c.points[a], crank,
                         kind=Kind.LINE, panel=Panel.FORCE)
        radial = c.draw("force:n:radial", "parallel_through", tail, crank, kind=Kind.LINE,
                        panel=Panel.FORCE)
        square = c.draw("force:n:tangential", "parallel_through", head, tangent,
                        kind=Kind.LINE, panel=Panel.FORCE)
        cross = c.draw("force:X:effort", "intersect_lines", radial, square, label="t",
                       panel=Panel.FORCE)
        draw.join("radial", tail, cross, label="F_R")
        part = draw.join("effort", cross, head, label="F_T")
        pushed, key = draw.read(part), "force.effort"
    effort = pushed[0] * t[0] + pushed[1] * t[1]
    r = math.dist(at[o], at[a])
    out.efforts["crank_effort"], out.efforts["turning_moment"] = effort, effort * r
    loads = 0.08 / draw.scale                    # the largest load, to the rounding of it
    said = c.draw("force:say:effort", "mark", cross, panel=Panel.FORCE, phrase=phrase(
        key, name=name, o=o, a=a, effort=_said(quiet(effort, loads), "N", ".6g"),
        moment=_said(quiet(effort * r, loads * r), "N·m", ".6g")))
    out.refs["crank_effort"] = out.refs["turning_moment"] = tuple(
        r for r in (cross, part, said) if r is not None)


@dataclass(frozen=True)
class _Lever:
    """A slotted lever: crank d (pivot o, pin a) drives block b in the slot of lever l.

    The lever turns about p; a ram r may ride on a frame guide (direction ``guide``) with
    its pin q in the same slot."""

    d: int
    b: int
    l: int  # noqa: E741 - the lever, as the notes number it
    o: str
    a: str
    p: str
    r: int | None = None
    q: str | None = None
    guide: tuple[float, float] | None = None


def slotted_of(mech: Mechanism) -> _Lever:
    """The crank and the slotted lever it drives, with its ram if it has one.

    Raises
    ------
    TarsimError
        If the mechanism is not a slotted lever whose slot runs through its pivot.
    """
    d = mech.drive.link
    crank = mech.link(d)
    if mech.arcs or len(crank.names) != 2 or set(mech.links_at(crank.names[0])) != {1, d}:
        raise TarsimError(_WHY)
    o, a = crank.names
    block = [s for s in mech.slides if s.point == a and s.kind is SlideKind.BLOCK
             and s.guide_link != 1 and not s.contact]
    if len(block) != 1 or mech.link(block[0].link).names != (a,):
        raise TarsimError(_WHY)
    s = block[0]
    lever = mech.link(s.guide_link)
    # The lever turns about its first point; it may carry points of its own besides (a
    # point B of an inverted slider-crank), but no other joint.
    if (set(mech.links_at(lever.names[0])) != {1, lever.number} or s.through != (0.0, 0.0)
            or any(mech.links_at(p) != (lever.number,) for p in lever.names[1:])):
        raise TarsimError(_WHY)
    rest = [k.number for k in mech.links if k.number not in (1, d, s.link, lever.number)]
    if not rest:
        if len(mech.slides) != 1:
            raise TarsimError(_WHY)
        return _Lever(d, s.link, lever.number, o, a, lever.names[0])
    ram = mech.link(rest[0]) if len(rest) == 1 else None
    if ram is None or len(ram.names) != 1 or len(mech.slides) != 3:
        raise TarsimError(_WHY)
    q = ram.names[0]
    pin = [t for t in mech.slides if t.link == ram.number and t.point == q
           and t.kind is SlideKind.PIN and t.guide_link == lever.number
           and t.through == s.through and t.direction == s.direction]
    frame = [t for t in mech.slides if t.link == ram.number and t.point == q
             and t.kind is SlideKind.BLOCK and t.guide_link == 1]
    if len(pin) != 1 or len(frame) != 1:
        raise TarsimError(_WHY)
    return _Lever(d, s.link, lever.number, o, a, lever.names[0], ram.number, q,
                  frame[0].direction)


def _slotted(c, draw, out: Forces, lv: _Lever, at, known, slip=None):
    """The slotted lever's group, in the order its unknowns allow.

    1. the ram: its loads closed by the slot's push and the guide's, each square to its
       line, crossing; its guide couple from its moments about its pin;
    2. the block's couple from the slot, from the block's moments about A;
    3. the slot's push on the block, from the lever's moments about its pivot;
    4. the block's polygon closed by the crank's force on it, the lever's by its pivot's.

    Returns the block's link, its pull on the crank at A, and the crank's pivot and pin.
    """
    slot = c.draw("force:line:slot", "line_through", c.points[lv.p], c.points[lv.a],
                  kind=Kind.LINE, panel=Panel.FORCE)
    u = _unit((at[lv.a][0] - at[lv.p][0], at[lv.a][1] - at[lv.p][1]))
    n = (-u[1], u[0])                                    # square to the slot
    f_rl = (0.0, 0.0)
    origin = c.give("force:S", g.Point(0.0, 0.0), label="", panel=Panel.FORCE)
    refs: list[str] = []
    if lv.r is not None:
        c.draw("force:say:ram", "mark", origin, panel=Panel.FORCE, label=f"link {lv.r}",
               phrase=phrase("force.ram", r=lv.r, l=lv.l))
        tip = draw.loads(lv.r, origin, known[lv.r])
        if slip is None or slip[1]["guide"] == slip[1]["pin"] == (0.0, 0.0):
            guide = draw.square_to(origin, lv.guide, "N")
            across = c.draw("force:line:slotN", "perpendicular_through", origin, slot,
                            kind=Kind.LINE, panel=Panel.FORCE)
        else:
            mu, sliding = slip
            laid = _sum(f for _, f, _, _ in known[lv.r])
            s_guide, s_slot = _sides(laid, (lv.guide, sliding["guide"]), (u, sliding["pin"]),
                                     mu)
            guide = draw.leaning(origin, lv.guide, s_guide, (mu, sliding["guide"]),
                                 what=phrase("force.the_frame_guide"))
            across = draw.leaning(origin, u, s_slot, (mu, sliding["pin"]), "slotN",
                                  what=phrase("force.the_slot", link=lv.l))
        cross, end_vec, start_vec = draw.close(tip, guide, origin, across, phrase(
            "force.ram_close", r=lv.r, l=lv.l), f"F_1{lv.r}", f"F_{lv.l}{lv.r}")
        n_guide, n_slot = draw.read(end_vec), draw.read(start_vec)
        out.joints[f"F_1{lv.r}"] = n_guide
        out.joints[f"F_{lv.l}{lv.r}"] = n_slot
        out.couples[f"T_1{lv.r}"] = -_moment(at[lv.q], known[lv.r])
        f_rl = (-n_slot[0], -n_slot[1])                  # the ram's pin on the lever
        refs += [cross, end_vec, start_vec]
    # The block: its couple from the slot (the slot's push and the crank's pin both at A).
    t_lb = -_moment(at[lv.a], known[lv.b])
    out.couples[f"T_{lv.l}{lv.b}"] = t_lb
    # The lever's moments about its pivot give the slot's push ν·n on the block.
    pa = (at[lv.a][0] - at[lv.p][0], at[lv.a][1] - at[lv.p][1])
    ram_moment = 0.0
    if lv.r is not None:
        pq = (at[lv.q][0] - at[lv.p][0], at[lv.q][1] - at[lv.p][1])
        ram_moment = pq[0] * f_rl[1] - pq[1] * f_rl[0]
    nu = (_moment(at[lv.p], known[lv.l]) + ram_moment - t_lb) / (pa[0] * n[1] - pa[1] * n[0])
    n_lb = (nu * n[0], nu * n[1])
    if slip is not None:
        # Friction along the slot acts on the slot's line, through the pivot: it leaves the
        # lever's moments, and so ν, as they were, and leans the push against the sliding.
        lean = leaning(n, slip[1]["block"], slip[0], 1.0 if nu >= 0.0 else -1.0)
        n_lb = (nu * lean[0], nu * lean[1])
    out.joints[f"F_{lv.l}{lv.b}"] = n_lb
    # The block's polygon: its loads and the slot's push, closed by the crank's force.
    low = min([s.output.xy[1] for s in c if s.panel is Panel.FORCE
               and isinstance(s.output, g.Point) and not s.id.startswith(("force:o:",
                                                                          "force:h:"))]
              + [0.0])
    start_b = c.give("force:Sb", g.Point(0.0, low - 0.03), label="", panel=Panel.FORCE)
    c.draw("force:say:block", "mark", start_b, panel=Panel.FORCE, label=f"link {lv.b}",
           phrase=phrase(
        "force.block", b=lv.b, l=lv.l, p=lv.p, nu=_said(abs(nu), "N")))
    tip = draw.loads(lv.b, start_b, known[lv.b])
    tip = draw.vector(f"{lv.l}on{lv.b}", tip, n_lb, label=f"F_{lv.l}{lv.b}")
    closing_b = draw.join("crank", tip, start_b, role=Role.RESULT, label=f"F_{lv.d}{lv.b}")
    f_db = draw.read(closing_b)
    out.joints[f"F_{min(lv.d, lv.b)}{max(lv.d, lv.b)}"] = _on(f_db, lv.d < lv.b)
    # The lever's polygon: its loads, the block's and the ram's pushes, closed at its pivot,
    # below the block's.
    low = min(s.output.xy[1] for s in c if s.panel is Panel.FORCE
              and isinstance(s.output, g.Point) and not s.id.startswith(("force:o:",
                                                                         "force:h:")))
    start_l = c.give("force:Sl", g.Point(0.0, low - 0.03), label="", panel=Panel.FORCE)
    c.draw("force:say:lever", "mark", start_l, panel=Panel.FORCE, label=f"link {lv.l}",
           phrase=phrase("force.lever", l=lv.l, p=lv.p))
    tip = draw.loads(lv.l, start_l, known[lv.l])
    tip = draw.vector(f"{lv.b}on{lv.l}", tip, (-n_lb[0], -n_lb[1]), label=f"F_{lv.b}{lv.l}")
    if lv.r is not None:
        tip = draw.vector(f"{lv.r}on{lv.l}", tip, f_rl, label=f"F_{lv.r}{lv.l}")
    closing_l = draw.join("pivot", tip, start_l, role=Role.RESULT, label=f"F_1{lv.l}")
    out.joints[f"F_1{lv.l}"] = draw.read(closing_l)
    refs += [closing_b, closing_l]
    for name in list(out.joints) + list(out.couples):
        out.refs[name] = tuple(refs)
    return lv.b, (-f_db[0], -f_db[1]), lv.o, lv.a


def _unit(v: Vec) -> Vec:
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n)


def _on(f: Vec, forward: bool) -> Vec:
    """A pin force named F_lo hi (of the lower-numbered link on the higher): ``f`` is of the
    first-named link on the second when ``forward``, else turned round."""
    return f if forward else (-f[0], -f[1])


class _Drafter:
    """Lays vectors head to tail in the FORCE panel at a force scale."""

    def __init__(self, c: Construction, scale: float):
        self.c, self.scale, self.count = c, scale, 0

    def vector(self, name: str, tip: Ref, f: Vec, said=None, label: str = "") -> Ref:
        """From ``tip`` lay off ``f`` (N): carried with dividers to the tip."""
        self.count += 1
        base = self.c.give(f"force:o:{self.count}", g.Point(0.0, 0.0), label="",
                           panel=Panel.FORCE)
        head = self.c.give(f"force:h:{self.count}", g.Point(f[0] * self.scale,
                                                            f[1] * self.scale),
                           label="", panel=Panel.FORCE)
        nxt = self.c.draw(f"force:{name}", "transfer", tip, base, head, panel=Panel.FORCE)
        self.c.draw(f"force:v:{name}", "join", tip, nxt, panel=Panel.FORCE, label=label,
                    phrase=said or phrase("force.lay", label=label or "the load",
                                          size=_said(math.hypot(*f), "N")))
        return nxt

    def loads(self, link: int, tip: Ref, loads) -> Ref:
        """Lay off each load of ``link`` with a force, head to tail from ``tip``."""
        for n, (_, f, _, name) in enumerate(loads):
            if f != (0.0, 0.0):
                tip = self.vector(f"{link}:{n}", tip, f, label=name)
        return tip

    def square_to(self, through: Ref, direction: Vec, name: str) -> Ref:
        """The line through ``through`` square to a frame guide of ``direction``: the
        guide's push, which has no part along it."""
        guide = self.c.give(f"force:guide:{name}", g.Line(-direction[1], direction[0], 0.0),
                            label="", panel=Panel.FORCE)
        return self.c.draw(f"force:line:{name}", "perpendicular_through", through, guide,
                           kind=Kind.LINE, panel=Panel.FORCE)

    def leaning(self, through: Ref, guide: Vec, side: float, slip, name: str = "N",
                what=None) -> Ref:
        """The line through ``through`` of a frame guide's push with friction: square to
        the guide, leaned by the friction angle against the sliding, for a push from
        ``side``."""
        u = leaning((-guide[1], guide[0]), slip[1], slip[0], side)
        n = math.hypot(*u)
        raw = self.c.give(f"force:guide:{name}", g.Line(-u[1] / n, u[0] / n, 0.0), label="",
                          panel=Panel.FORCE)
        # A guide at rest pushes square to itself, as its resting step says.
        said = None if slip[1] == (0.0, 0.0) else phrase(
            "force.leaning", what=what or phrase("force.the_guide"), phi=_friction_angle(slip),
            side=Word("the guide's left (a quarter turn counter-clockwise from its direction)"
                      if side > 0 else
                      "the guide's right (a quarter turn clockwise from its direction)"))
        return self.c.draw(f"force:line:{name}", "parallel_through", through, raw,
                           kind=Kind.LINE, panel=Panel.FORCE, phrase=said)

    def close(self, tip: Ref, far: Ref, start: Ref, near: Ref, said, far_name: str,
              near_name: str) -> tuple[Ref, Ref, Ref]:
        """Close a polygon from ``start`` to ``tip`` with two forces of known lines: a
        parallel to ``far`` through its end, to ``near`` through its start; returns where
        they cross and the two forces drawn."""
        n = self.count = self.count + 1
        along_end = self.c.draw(f"force:n:end{n}", "parallel_through", tip, far,
                                kind=Kind.LINE, panel=Panel.FORCE)
        along_start = self.c.draw(f"force:n:start{n}", "parallel_through", start, near,
                                  kind=Kind.LINE, panel=Panel.FORCE)
        cross = self.c.draw(f"force:X{n}", "intersect_lines", along_end, along_start,
                            label="x", panel=Panel.FORCE, phrase=said)
        return (cross, self.join(f"far{n}", tip, cross, label=far_name),
                self.join(f"near{n}", cross, start, label=near_name))

    def join(self, name: str, a: Ref, b: Ref, role: Role = Role.CONSTRUCTION,
             label: str = "") -> Ref:
        return self.c.draw(f"force:v:{name}", "join", a, b, panel=Panel.FORCE, role=role,
                           label=label)

    def read(self, seg: Ref) -> Vec:
        s = self.c.output(seg)
        (ax, ay), (bx, by) = s.start.xy, s.end.xy
        return ((bx - ax) / self.scale, (by - ay) / self.scale)


def _sum(vectors) -> Vec:
    vs = list(vectors)
    return (math.fsum(v[0] for v in vs), math.fsum(v[1] for v in vs))


def _moment(about: Vec, loads) -> float:
    """Σ (p − about) × F + Σ M of ``loads`` (where, force, couple, name)."""
    return math.fsum((p[0] - about[0]) * f[1] - (p[1] - about[1]) * f[0] + m
                     for p, f, m, _ in loads)


def _square(pin: Vec, middle: Vec, loads) -> Vec:
    """The part of a pin force at ``pin`` square to pin → middle that holds the link's other
    loads about ``middle``: F ᵗ·|pin middle| balances their moment."""
    dx, dy = pin[0] - middle[0], pin[1] - middle[1]
    length = math.hypot(dx, dy)
    u = (-dy / length, dx / length)                # square to the line
    t = -_moment(middle, loads) / (dx * u[1] - dy * u[0])
    return (t * u[0], t * u[1])


def _world(work, link: int, local: Vec, at) -> Vec:
    """A point of ``link`` given in its own frame, where the compass drew the link."""
    k = work.mechanism.link(link)
    (ox, oy), (lx, ly) = at[k.names[0]], k.local(k.names[0])
    turn = _turn(work, link, at)
    cx, cy = math.cos(turn), math.sin(turn)
    rx, ry = local[0] - lx, local[1] - ly
    return (ox + cx * rx - cy * ry, oy + cy * rx + cx * ry)


def _turn(work, link: int, at) -> float:
    """How far ``link``'s own frame stands turned from the file's, where the compass drew it:
    by the line of its first two points; a one-point link by a slot cut in it (the slot's
    line as drawn, which runs the slot's way), or, a block, by the guide it runs on,
    turning with that guide when the guide is a moving link's slot."""
    mech = work.mechanism
    k = mech.link(link)
    names = k.names
    (ox, oy) = at[names[0]]
    if len(names) >= 2:
        (lx, ly), (mx, my) = k.local(names[0]), k.local(names[1])
        (px, py) = at[names[1]]
        return math.atan2(py - oy, px - ox) - math.atan2(my - ly, mx - lx)
    slot = next((i for i, s in enumerate(mech.slides) if s.guide_link == link), None)
    if slot is not None:
        # The slot as drawn runs the way its own direction does, forward or backward of the
        # block as the file's branch puts it (Assembly.swing_slot).
        (wx, wy), (dx, dy) = work.assembly.guide(slot).direction, mech.slides[slot].direction
        return math.atan2(wy, wx) - math.atan2(dy, dx)
    block = next((s for s in mech.slides if s.link == link and s.kind is SlideKind.BLOCK),
                 None)
    if block is not None:
        guide = 0.0 if block.guide_link == 1 else _turn(work, block.guide_link, at)
        return guide + math.atan2(block.direction[1], block.direction[0])
    return 0.0


def _inertia(work, loads: Loads, at) -> dict[int, tuple[Vec, float]]:
    """Each massive link's inertia force and couple, its a_G read off the acceleration
    polygon (G's image drawn by the normal and tangential parts from a tip of the link)."""
    mech = work.mechanism
    ap, vp = drawn_acceleration_polygon(work), drawn_velocity_polygon(work)
    c: Construction = work.assembly
    out = {}
    for m in loads.masses:
        g_at = _world(work, m.link, m.centre, at)
        omega = mech.drive.omega if m.link == mech.drive.link else vp.rates.get(m.link, 0.0)
        alpha = mech.drive.alpha if m.link == mech.drive.link else ap.rates.get(m.link, 0.0)
        ref = image_base(mech, ap.tips, m.link)
        k_tip = ap.tips[ref] if ref in ap.tips else ap.pole
        r = (g_at[0] - at[ref][0], g_at[1] - at[ref][1])
        size = math.hypot(*r)
        if size == 0.0:
            image = k_tip
        else:
            gp = c.give(f"force:G{m.link}", g.Point(*g_at), label=f"G{m.link}")
            line = c.draw(f"force:KG{m.link}", "line_through", gp, c.points[ref],
                          kind=Kind.LINE, phrase=phrase("force.centre", link=m.link, k=ref))
            normal = c.draw(f"force:an{m.link}", "parallel_through", k_tip, line,
                            kind=Kind.LINE, panel=Panel.ACCELERATION)
            n_end = c.draw(f"force:anG{m.link}", "lay_off", k_tip, normal,
                           length=omega * omega * size * ap.scale, panel=Panel.ACCELERATION)
            across = c.draw(f"force:at{m.link}", "perpendicular_through", n_end, normal,
                            kind=Kind.LINE, panel=Panel.ACCELERATION)
            d = c.output(across).direction
            want = (-r[1] * alpha, r[0] * alpha)             # α × r
            sign = 1.0 if d[0] * want[0] + d[1] * want[1] >= 0 else -1.0
            # Said to the rounding of the accelerations drawn: a rate of 1e-18 is a zero.
            beside = max(omega * omega * size, abs(alpha) * size,
                         math.hypot(*ap.between(ap.pole, k_tip)))
            alpha_said = alpha if quiet(alpha * size, beside) else 0.0
            image = c.draw(f"force:g{m.link}", "lay_off", n_end, across,
                           length=sign * abs(alpha) * size * ap.scale, label=f"g{m.link}′",
                           panel=Panel.ACCELERATION, phrase=phrase(
                               "force.image", link=m.link,
                               k=ref, start="o_a" if 1 in mech.links_at(ref)
                               else f"{ref[0].lower()}{ref[1:]}′",
                               n=_said(omega * omega * size, "m/s²"),
                               t=_said(abs(alpha_said) * size, "m/s²"),
                               h=_offset(m, alpha_said, ap.between(ap.pole, n_end),
                                         (-r[1] * alpha, r[0] * alpha))))
        a_g = ap.between(ap.pole, image)
        out[m.link] = ((-m.mass * a_g[0], -m.mass * a_g[1]), -m.inertia * alpha)
    return out


def _offset(m, alpha: float, normal: Vec, tangential: Vec):
    """Where the inertia force and couple act as one force: h = I·α/(m·a_G) from G."""
    a_g = math.hypot(normal[0] + tangential[0], normal[1] + tangential[1])
    if a_g == 0.0 or alpha == 0.0:
        return Word("0 (no couple)")
    return _said(m.inertia * abs(alpha) / (m.mass * a_g) * 1e3, "mm")


def _said(value: float, unit: str, spec: str = ".4g") -> tuple[Number, str]:
    """A number and its unit as a step says them, the number in the language's digits."""
    return (Number(value, spec), unit)


def _loads(work, loads: Loads, link: int, at, inertia, group
           ) -> list[tuple[Vec, Vec, float, str]]:
    """Every load on ``link`` as (where, force N, couple N·m, its name): its inertia force
    and couple, its weight, the external forces and couples (a resistance only where its
    point moves, beyond the rounding of a zero, on its stroke)."""
    out = []
    m = loads.mass_of(link)
    if m is not None:
        g_at = _world(work, link, m.centre, at)
        force, couple = inertia[link]
        out.append((g_at, force, couple, f"Fi{link}"))
        if loads.gravity:
            out.append((g_at, (0.0, -m.mass * loads.gravity), 0.0, f"W{link}"))
    for f in loads.forces:
        if f.link != link:
            continue
        p = at[f.point] if isinstance(f.point, str) else _world(work, link, f.point, at)
        force = f.force
        if f.resist:
            # Against the point's velocity as the velocity polygon draws it, on its stroke.
            if not isinstance(f.point, str):
                raise TarsimError("a resisting force acts at a named point of its link")
            vp = drawn_velocity_polygon(work)
            v = vp.vector(f.point)
            speed = math.hypot(*v)
            # A point no faster than the rounding of a zero stands still (a dead centre);
            # one just past it moves no known way.
            still = speed_rounding(work, _gain(group, at, f.point))
            if near_rest(speed, still):
                raise TarsimError(near_rest_refusal(
                    work.mechanism, f"link {link} moves at its point {f.point}",
                    speed / (vp.extent() or 1.0), acting="the resistance"))
            moving = speed > still and (
                f.along is None or v[0] * f.along[0] + v[1] * f.along[1] > 0.0)
            if not moving:
                continue                                # the return stroke: no cut
            force = (-f.resist * v[0] / speed, -f.resist * v[1] / speed)
        out.append((p, force, 0.0, f.name or f"P{link}"))
    out += [(at[work.mechanism.link(link).names[0]], (0.0, 0.0), cp.moment, cp.name or "M")
            for cp in loads.couples if cp.link == link]
    return out


FORCES_WHY_NOT = {kind: "the force polygons draw a four-bar, a slider-crank or a slotted lever, "
                        "naming its joints F_<by><on>, T_<guide><block> and T<input>"
                  for kind in (A.JointForce, A.DrivingTorque, A.Effort)}
"""Why a force is not askable: the mechanism is none the polygons draw, or has no such
joint. (The turning-moment diagram of ``tarsim sweep`` gives any mechanism's forces.)"""


def forces_askable(mech: Mechanism) -> set[str]:
    """The forces an exercise may ask of ``mech``, if the polygons draw it: its joints', the
    driving torque, the crank effort and its turning moment, and a slider-crank's piston
    effort and wall thrust."""
    try:
        group = _group_of(mech)
    except TarsimError:
        return set()
    out = force_names(mech) | {"crank_effort", "turning_moment"}
    if isinstance(group, _Shape) and group.guide is not None:
        out |= {"piston_effort", "wall_thrust"}
    return out


def _amplification(forces: Forces, size: float) -> float:
    """How many times the largest joint force outgrows the loads it comes from (1 at the
    least): a lever that multiplies its load so multiplies the rounding of everything drawn
    before it (a slot's direction through a block near its pivot), which no single act's
    conditioning sees."""
    loads = math.fsum(math.hypot(*f) + abs(m) / size for ls in forces.loads.values()
                      for _, f, m, _ in ls)
    biggest = max([math.hypot(*v) for v in forces.joints.values()] + [0.0])
    return max(1.0, biggest / loads) if loads > 0.0 else 1.0


def drawn_forces(work) -> Forces:
    """The position's force polygons, drawn once."""
    return work.shared("forces", lambda: draw_forces(work))


def answer(work, ask) -> Answer:
    """A joint force, a block's couple or the driving torque, read off the force polygons.

    Its conditioning is the worst of the acts it rests on: the crossing that closes the
    dyad's polygon (or the lever's), whose forces every later polygon takes in as numbers,
    so the crank's answers inherit it; and the acceleration polygon the inertia loads are
    read off, both its worst act and what its rounding of each load, levered through the
    group, makes of this answer beside the loads' scale (:mod:`~.force_rounding`).
    """
    forces = drawn_forces(work)
    c = work.assembly
    if isinstance(ask, A.DrivingTorque):
        value = {"value": forces.torque}
    elif isinstance(ask, A.Effort):
        value = {"value": forces.efforts[ask.word]}
    elif ask.letter == "T":
        value = {"value": forces.couples[ask.name]}
    else:
        value = vector_value(*forces.joints[ask.name])
    cond = min([c[r].conditioning for refs in forces.refs.values() for r in refs] + [1.0])
    if work.has("acceleration polygon"):
        cond *= drawn_acceleration_polygon(work).worst()
    cond = min(cond / _amplification(forces, work.assembly.size),
               read_conditioning(work, forces, ask))
    return Answer(ask, value, cond, "force polygons", refs=forces.every,
                  figures=(LOADS, FORCES, BODIES), panel=Panel.FORCE)
