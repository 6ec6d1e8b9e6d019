"""Graphical kinetostatics: the joint forces and the driving torque by force polygons, link by
link, as the textbooks teach it, the inertia loads read off the acceleration polygon.

The analysis of a position runs in the order its unknowns allow:

1. every load on each link, its inertia force and couple (D'Alembert) among them
   (:mod:`~.link_loads`);
2. the group the crank drives, from the output back to the crank: a dyad
   (:mod:`~.dyad`), or a slotted lever with its block and ram (:mod:`~.lever`);
3. the crank, whose polygon closes on the frame's force at its pivot and whose moments
   about the pivot give the driving torque (:mod:`~.crank`).

Each act is a recorded step in the FORCE panel, drawn at a force scale (drawing metres per
newton); the forces are read back off it. Friction leans a slide's push against its
sliding (:mod:`~.sliding`); a pin's friction circle adds a couple against its turning,
found here by drawing the polygons by trial until the forces settle.
"""

from __future__ import annotations

import math
import sys

from .. import geometry as g
from ..errors import GeometryError, TarsimError
from ..loads import Loads
from ..model import Mechanism
from ..narration import Quantity, phrase
from ..record import Construction, Panel
from ..scales import nice
from .crank import crank_polygon
from .drafting import Drafter, as_said
from .dyad import dyad_polygon
from .groups import Dyad, Lever, group_of, lever_span
from .lever import lever_polygons
from .link_loads import inertia_loads, link_loads
from .result import Forces, free_bodies
from .rounding import answer_roundings, load_roundings
from .sliding import dyad_slides, lever_slides, link_rates, pin_rests, pin_roundings, say_resting

__all__ = ["draw_forces", "drawn_forces", "inertia_torque"]


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
    group = group_of(mech)
    c: Construction = work.assembly
    at = {name: c.point(name).xy for name in mech.point_names}
    inertia = inertia_loads(work, loads, at)
    known = {k.number: link_loads(work, loads, k.number, at, inertia, group)
             for k in mech.links if k.number != 1}
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
    if isinstance(group, Dyad) and slides and slides[0].direction != (0.0, 0.0):
        slip = (loads.friction, slides[0].direction)
    elif isinstance(group, Lever) and slides:
        slip = (loads.friction, {s.key: s.direction for s in slides})
    still = pin_roundings(work, lever_span(group, at)) if loads.friction_circle else None
    if still is not None:
        known = _with_pin_friction(work, c, group, at, known, scale, slip, still)
    say_resting(work, slides, still)
    rounding = {} if not loads.masses else answer_roundings(
        known, load_roundings(work, known, at),
        lambda trial: _analyse(c.scratch(), mech, group, at, trial, scale, slip),
        size=size, driver=mech.drive.link)
    out = _analyse(c, mech, group, at, known, scale, slip)
    out.inertia, out.loads, out.rounding = inertia, known, rounding
    if loads.flywheel is not None and loads.resisting is not None:
        _flywheel_alpha(c, mech, loads, out)
    return out


def _flywheel_alpha(c, mech: Mechanism, loads: Loads, out: Forces) -> None:
    """The flywheel's angular acceleration here, the turning moment along the rotation less
    the mean resisting torque, over its I: α = (T − T_mean)/I, + where the shaft speeds up."""
    along = out.efforts["turning_moment"] * (-1.0 if mech.drive.omega < 0 else 1.0)
    alpha = (along - loads.resisting) / loads.flywheel
    out.efforts["flywheel_alpha"] = alpha
    said = c.draw("force:say:flywheel", "mark", out.refs["turning_moment"][0],
                  panel=Panel.FORCE, phrase=phrase(
                      "force.flywheel", inertia=as_said(loads.flywheel, "kg·m²", ".6g"),
                      mean=as_said(loads.resisting, "N·m", ".6g"),
                      torque=as_said(along, "N·m", ".6g"),
                      alpha=as_said(alpha, "rad/s²", ".6g")))
    out.refs["flywheel_alpha"] = (*out.refs["turning_moment"], said)
    out.every = (*out.every, said)


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
    draw = Drafter(c, scale)
    if isinstance(group, Dyad):
        crank_pin, pull, o, a = dyad_polygon(c, draw, out, group, at, known, slip)
    else:
        crank_pin, pull, o, a = lever_polygons(c, draw, out, group, at, known, slip)
    size = max(math.dist(p, q) for p in at.values() for q in at.values()) or 1.0
    loads = math.fsum(math.hypot(*f) + abs(m) / size for ls in known.values()
                      for _, f, m, _ in ls)
    biggest = max([math.hypot(*v) for v in out.joints.values()] + [math.hypot(*pull)])
    if not biggest * 64 * sys.float_info.epsilon <= loads:      # inf and nan fail it too
        links = " and ".join(str(n) for n in sorted({group.i, group.j})) \
            if isinstance(group, Dyad) else f"{group.b} and {group.l}"
        raise TarsimError(f"links {links} stand at a dead point: the forces that hold the "
                          "loads there outgrow them past their rounding; choose another "
                          "position")
    crank_polygon(c, draw, out, mech.drive.link, crank_pin, pull, o, a, at, known)
    out.every = tuple(s.id for s in c if s.id.startswith("force:"))
    out.bodies = free_bodies(mech, out, at, known)
    return out


def _slides(work, group, at) -> list:
    """The slides of the group the crank drives, as the velocity polygon reads them
    (:mod:`~.sliding`): a slider-crank's block, a slotted lever's block and ram.

    Raises
    ------
    TarsimError
        If one slides too near rest to tell which way (:func:`~.loads.near_rest`).
    """
    if isinstance(group, Dyad):
        return [] if group.guide is None else dyad_slides(work, group.j, group.b)
    return lever_slides(work, at, lever=group.l, block=group.b, pivot=group.p, pin=group.a,
                        ram=group.r, ram_pin=group.q)


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
    at (``still``, :func:`~.sliding.pin_roundings`) rests, and takes none."""
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


def drawn_forces(work) -> Forces:
    """The position's force polygons, drawn once."""
    return work.shared("forces", lambda: draw_forces(work))


def inertia_torque(work, link: int) -> float:
    """The turning moment on the crankshaft of ``link``'s inertia loads alone (N·m, CCW +),
    as the books split the inertia torque between the reciprocating parts and the rod: the
    same polygons drawn again, on a scratch sheet at the same scale, with only that link's
    inertia force and couple (no weight, gas or friction) — what that part asks of the crank.
    ``link`` has a mass (0 without one)."""
    def part() -> float:
        forces, mech = drawn_forces(work), work.mechanism
        c = work.assembly
        at = {name: c.point(name).xy for name in mech.point_names}
        known = {k: [ld for ld in ls if ld[3] == f"Fi{link}"] if k == link else []
                 for k, ls in forces.loads.items()}
        sheet = c.scratch()                 # the drawing so far, without its polygons
        sheet.steps = {k: st for k, st in c.steps.items() if not k.startswith("force:")}
        found = _analyse(sheet, mech, group_of(mech), at, known, forces.scale, None)
        return found.efforts["turning_moment"]

    return work.shared(f"inertia torque {link}", part)
