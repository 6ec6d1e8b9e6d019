"""The analytic value each kind of ask is checked against, read from the independent reference.

Every function takes the work of a position (or of the mechanism) and an ask,
and returns an :class:`~.checks.Expected` in results.json's shape. Their numbers
come only from :mod:`.reference` (the vector-loop solver, its instant centres,
limits, rotatability and mobility), never from a construction. Two things are
read off a construction's names alone, so that both sides speak of the same
thing: the output the limit positions measure (which block, which lever), and
the link a coincident point is taken on. A method names one of these as its
reference when it registers (:mod:`.registry`).
"""

from __future__ import annotations

import math
from itertools import combinations

from . import asks as A
from .checks import Expected, grashof_value, time_ratio_value, vector_value
from .linkages.coincident import taken
from .errors import DegenerateInput, InputError
from .linkages.limit_positions import WHY_NOT, drawn_limits
from .joints import SlideKind
from .model import Drive
from .reference import solver
from .reference.centres import MoveTogether, instant_centre, mechanism_size, shared_pin
from .reference.limits import limit_reference
from .reference.mobility import mobility_of
from .reference.rotatability import (class_by_rotation, four_bar_spans, grashof_class,
                                     length_range_by_rotation)

__all__ = ["position", "centre_count", "centre", "omega", "alpha", "velocity", "acceleration",
           "relative", "acceleration_part", "coriolis", "sliding", "mobility", "grashof",
           "length_range", "time_ratio", "stroke", "reading", "equivalent", "joint_force",
           "driving_torque"]


def position(work, ask: A.Position) -> Expected:
    """Where the vector-loop solver puts the point (on the first link that lists it)."""
    return Expected({"point": list(work.kinematics.points[ask.point])})


def centre_count(work, ask: A.CentreCount) -> Expected:
    """n(n − 1)/2 for n links; by inspection, each pair of links joined directly: by a
    pin, a block on a guide (straight or curved), or a wheel rolling without slip (a pin
    in a slot or a cam's contact leaves only a line for its centre). At infinity, each pair
    whose analytic velocity fields differ by a translation (Δω = 0) at this position."""
    m = work.mechanism
    n = len(m.numbers)
    joined = {tuple(sorted(pair)) for p in m.point_names
              for pair in combinations(m.links_at(p), 2)}
    joined |= {tuple(sorted((s.link, s.guide_link))) for s in m.slides
               if s.kind is SlideKind.BLOCK or s.rolling}
    total = n * (n - 1) // 2
    return Expected({"value": total, "by_inspection": len(joined),
                     "by_kennedy": total - len(joined), "far_centres": _far_centres(work)})


def _far_centres(work) -> int:
    """How many centres the reference puts at infinity. Two links moving together have every
    point for their centre; a block on a straight guide's joint then names the one at
    infinity, square to the guide, and any other pair is taken where it is drawn."""
    m, far = work.mechanism, 0
    blocks = {tuple(sorted((s.link, s.guide_link))) for s in m.slides
              if s.kind is SlideKind.BLOCK and not s.rolling}
    for i, j in combinations(sorted(m.numbers), 2):
        try:
            far += instant_centre(work.kinematics, i, j,
                                  pin=shared_pin(m, i, j)).is_at_infinity
        except MoveTogether:
            far += (i, j) in blocks
        except DegenerateInput:        # no relative motion to place it by
            continue
    return far


def centre(work, ask: A.Centre) -> Expected:
    """Where the two links' analytic velocity fields agree, or their pin (undefined if they
    move together)."""
    try:
        ref = instant_centre(work.kinematics, *ask.pair,
                             pin=shared_pin(work.mechanism, *ask.pair))
    except MoveTogether as e:      # any point is their centre, the one drawn among them
        return Expected({"undefined": str(e), "anywhere": True})
    except DegenerateInput as e:
        return Expected({"undefined": str(e)})
    value = ({"at_infinity": True, "direction": list(ref.direction)} if ref.is_at_infinity
             else {"point": list(ref.point)})
    return Expected(value, ref.rounding, ref)


def omega(work, ask: A.AngularVelocity) -> Expected:
    """ω of the link."""
    return Expected({"value": work.kinematics.omegas[ask.link]})


def alpha(work, ask: A.AngularAcceleration) -> Expected:
    """α of the link."""
    return Expected({"value": work.kinematics.alphas[ask.link]})


def velocity(work, ask: A.Velocity) -> Expected:
    """The velocity of the point, taken on its link (``A4``: A as a point of link 4)."""
    m = work.mechanism
    return Expected(vector_value(*solver.point_velocity(work.kinematics, m, *taken(m, ask.point))))


def acceleration(work, ask: A.Acceleration) -> Expected:
    """The acceleration of the point, taken on its link."""
    m = work.mechanism
    return Expected(vector_value(*solver.point_acceleration(work.kinematics, m,
                                                            *taken(m, ask.point))))


def relative(work, ask: A.Relative) -> Expected:
    """V_P − V_Q (or A_P − A_Q), each point taken on its link."""
    m, kin = work.mechanism, work.kinematics
    of = solver.point_velocity if ask.letter == "V" else solver.point_acceleration
    (ax, ay), (bx, by) = (of(kin, m, *taken(m, n)) for n in (ask.point, ask.of))
    return Expected(vector_value(ax - bx, ay - by))


def acceleration_part(work, ask: A.AccelerationPart) -> Expected:
    """Of a relative acceleration on link k: −ω_k² r_B/A and α_k × r_B/A. Of an absolute
    one: its projection on the point's velocity (tangential) and the rest (normal)."""
    m, kin = work.mechanism, work.kinematics
    if ask.of is not None:
        from .linkages.acceleration_parts import common_link

        k = common_link(m, ask.point, ask.of)
        (_, p), (_, q) = taken(m, ask.point), taken(m, ask.of)
        rx, ry = (b - a for a, b in zip(kin.points[q], kin.points[p]))
        w, al = kin.omegas[k], kin.alphas[k]
        return Expected(vector_value(-w * w * rx, -w * w * ry) if ask.part == "n"
                        else vector_value(-al * ry, al * rx))
    ax, ay = solver.point_acceleration(kin, m, *taken(m, ask.point))
    vx, vy = solver.point_velocity(kin, m, *taken(m, ask.point))
    n2 = vx * vx + vy * vy
    if n2 == 0.0:
        raise InputError(f"{ask.point} is at rest at this instant, so its path has no tangent "
                         f"to part A_{ask.point} by; ask A_{ask.point} itself")
    k = (ax * vx + ay * vy) / n2
    tx, ty = k * vx, k * vy
    return Expected(vector_value(tx, ty) if ask.part == "t" else vector_value(ax - tx, ay - ty))


def coriolis(work, ask: A.Coriolis) -> Expected:
    """2ω_j × (V_P − V_Pj) at the slot, straight or curved, of link j that P runs in."""
    m, kin = work.mechanism, work.kinematics
    joint = next(s for s in m.slotted if s.point == ask.point)
    j = joint.guide_link
    (px, py), (qx, qy) = (solver.point_velocity(kin, m, k, ask.point) for k in (joint.link, j))
    w = kin.omegas[j]
    return Expected(vector_value(-2.0 * w * (py - qy), 2.0 * w * (px - qx)))


def sliding(work, ask: A.Sliding) -> Expected:
    """The point's travel along its slot seen from the slot's link: the slide rate's first (V)
    or second (A) derivative, along the guide."""
    from .linkages.sliding import slot_of

    i, _ = slot_of(work.mechanism, ask.point)
    rate = work.kinematics.slide_rates[i]
    k = rate.velocity if ask.letter == "V" else rate.acceleration
    return Expected(vector_value(k * rate.direction[0], k * rate.direction[1]))


def reading(work, ask) -> Expected:
    """A ratio of speeds or of ω, the mechanical advantage ω_in/ω_out, a point's distance to
    an analytic centre, or μ from the solver's points."""
    m, kin = work.mechanism, work.kinematics
    if isinstance(ask, A.Ratio) and ask.letter == "omega":
        return Expected({"value": kin.omegas[int(ask.a)] / kin.omegas[int(ask.b)]})
    if isinstance(ask, A.MechanicalAdvantage):
        return Expected({"value": kin.omegas[m.drive.link] / kin.omegas[ask.link]})
    if isinstance(ask, A.Ratio):
        a, b = (solver.point_velocity(kin, m, *taken(m, n)) for n in (ask.a, ask.b))
        return Expected({"value": (a[0] ** 2 + a[1] ** 2) ** 0.5 / (b[0] ** 2 + b[1] ** 2) ** 0.5})
    if isinstance(ask, A.LeastVelocity):
        # |V(P)|² along the line P = A + t·(B − A) is a quadratic in t: its least is where
        # the velocity is square to the line's own motion, found without any centre.
        from .linkages.readings import least_line

        if ask.line is None and not A.on_one_line(m.link(ask.link).points):
            return _least_on_plate(work, ask)
        a, b = least_line(m, ask)
        (ax, ay), (bx, by) = kin.points[a], kin.points[b]
        va, vb = (solver.point_velocity(kin, m, ask.link, n) for n in (a, b))
        dx, dy = vb[0] - va[0], vb[1] - va[1]
        t = -(va[0] * dx + va[1] * dy) / (dx * dx + dy * dy)
        vx, vy = va[0] + t * dx, va[1] + t * dy
        return Expected({"point": [ax + t * (bx - ax), ay + t * (by - ay)],
                         "value": (vx * vx + vy * vy) ** 0.5, "from": a,
                         "along": t * ((bx - ax) ** 2 + (by - ay) ** 2) ** 0.5,
                         "floor": abs(kin.omegas[ask.link]) * mechanism_size(kin)})
    if isinstance(ask, A.Rubbing):
        from .linkages.readings import pin_links

        i, j = pin_links(m, ask.point)
        w = {1: 0.0, **kin.omegas}
        return Expected({"value": abs(w[i] - w[j]) * ask.diameter / 2})
    if isinstance(ask, A.Distance):
        ref = instant_centre(kin, *ask.pair, pin=shared_pin(m, *ask.pair))
        (px, py), (cx, cy) = kin.points[ask.point], ref.point
        return Expected({"value": ((px - cx) ** 2 + (py - cy) ** 2) ** 0.5})
    # μ by the protractor's own geometry, on the solver's points and guide direction
    from .linkages.readings import angle_at, normal_angle, slider_rod, transmission_pin

    rod = slider_rod(m)
    if rod is not None:       # the rod against the normal to the stroke
        (bx, by), (ax, ay) = (kin.points[n] for n in rod[:2])
        return Expected({"value": normal_angle(ax - bx, ay - by,
                                               *kin.slide_rates[rod[2]].direction)})
    b, a, o = (kin.points[n] for n in transmission_pin(m))
    return Expected({"value": angle_at(b, a, o)})


def _least_on_plate(work, ask: A.LeastVelocity) -> Expected:
    """The slowest point of a plate, from the solver's velocities alone: |V(P)| = |ω|·|P −
    P*| is least at P* = A + k × V_A / ω when P* lies in a triangle of the link's points;
    else on the segment between two of them where the quadratic |V(A + t·(B − A))|² is
    least for t in [0, 1] (every segment lies within the plate, and its sides are among
    them)."""
    m, kin, k = work.mechanism, work.kinematics, ask.link
    names, w = m.link(k).names, kin.omegas[k]
    xy = {n: kin.points[n] for n in names}
    vel = {n: solver.point_velocity(kin, m, k, n) for n in names}
    (ax, ay), (vx, vy) = xy[names[0]], vel[names[0]]
    best = None
    if w != 0.0:
        star = (ax - vy / w, ay + vx / w)
        for p, q, r in combinations(names, 3):
            d = _area(xy[p], xy[q], xy[r])
            parts = (_area(star, xy[q], xy[r]), _area(xy[p], star, xy[r]),
                     _area(xy[p], xy[q], star))
            if d != 0.0 and all(part / d >= 0.0 for part in parts):
                best = (0.0, star)
                break
    if best is None:
        for p, q in combinations(names, 2):
            (va, vb), (pa, pb) = (vel[p], vel[q]), (xy[p], xy[q])
            dx, dy = vb[0] - va[0], vb[1] - va[1]
            t = min(1.0, max(0.0, -(va[0] * dx + va[1] * dy) / (dx * dx + dy * dy)))
            speed = math.hypot(va[0] + t * dx, va[1] + t * dy)
            if best is None or speed < best[0]:
                best = (speed, (pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1])))
    speed, point = best
    near = min(names, key=lambda n: math.dist(xy[n], point))
    return Expected({"point": list(point), "value": speed, "from": near,
                     "along": math.dist(xy[near], point),
                     "floor": abs(w) * mechanism_size(kin)})


def _area(p, q, r) -> float:
    """Twice the signed area of the triangle pqr."""
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])


def equivalent(work, ask: A.Equivalent) -> Expected:
    """The two centres' distance, or the circle's centre's from the face, where the solver
    puts them: the contact's own invariant, r₁ ± r₂ or r."""
    from .linkages.equivalent import contact_at

    m, kin = work.mechanism, work.kinematics
    joint, index = contact_at(m, ask.point)
    if index is None:
        (px, py), (qx, qy) = kin.points[ask.point], kin.points[joint.centre]
        return Expected({"value": math.hypot(px - qx, py - qy)})
    face = joint.contact.face
    (fx, fy), (px, py) = kin.points[face.through], kin.points[ask.point]
    ux, uy = kin.slide_rates[index].direction
    return Expected({"value": abs((px - fx) * uy - (py - fy) * ux)})


def mobility(work, ask: A.Mobility) -> Expected:
    """The nullity of the loop equations' Jacobian, turning the input; and at this position,
    where it differs (a change point)."""
    m = mobility_of(work.mechanism)
    return Expected({"value": m.value} if m.here == m.value else {"value": m.value, "here": m.here})


def grashof(work, ask: A.GrashofClass) -> Expected:
    """The class found by turning each link a revolution."""
    gc = grashof_class(work.mechanism)
    return Expected(grashof_value(class_by_rotation(gc.lengths), gc.lengths))


def length_range(work, ask: A.LengthRange) -> Expected:
    """The lengths that keep the class, by bisecting the turning test."""
    gc = grashof_class(work.mechanism)
    lo, hi = length_range_by_rotation(gc.lengths, four_bar_spans(work.mechanism)[ask.span])
    return Expected({"low": lo, "high": hi, "class": class_by_rotation(gc.lengths)})


def _limits(work):
    """Where the analytic output's velocity changes sign, found once for time ratio and stroke:
    the output the limit construction measures (a block's travel, a lever's swing)."""
    lp = drawn_limits(work)
    return work.shared("limit reference",
                       lambda: limit_reference(work.mechanism, point=lp.point, link=lp.output))


def time_ratio(work, ask: A.TimeRatio) -> Expected:
    """Slow stroke over quick stroke, between the output's reversals."""
    ref = _limits(work)
    return Expected(time_ratio_value(ref.slow, ref.quick))


def swing(work, ask: A.Swing) -> Expected:
    """The lever's (rocker's) swing between the reversals of its own ω, from the solver's
    positions there; a slotted lever's inclination to the line of centres at one of them."""
    from .linkages.limit_swing import SWING_WHY_NOT

    lp = drawn_limits(work)
    if lp.output != ask.link or lp.held is None:
        raise InputError(SWING_WHY_NOT.format(k=ask.link))
    m = solver.follow_branches(work.mechanism)
    ref = limit_reference(m, link=ask.link)
    pivot, held = lp.pivot, lp.assembly[lp.held[0]].label.rstrip("′″")
    d = m.drive
    dirs = []
    for theta in ref.crank_angles:
        kin = solver.solve(m.with_drive(Drive(d.link, theta, d.omega, 0.0)))
        (px, py), (hx, hy) = kin.points[pivot], kin.points[held]
        dirs.append(math.atan2(hy - py, hx - px))
    turn = abs(dirs[1] - dirs[0]) % (2 * math.pi)
    out = {"value": min(turn, 2 * math.pi - turn)}
    if lp.kind == "slotted lever":
        crank = m.link(d.link).names[0]
        (px, py), (cx, cy) = m.link(1).local(pivot), m.link(1).local(crank)
        tilt = abs(dirs[0] - math.atan2(cy - py, cx - px)) % (2 * math.pi)
        out["inclination"] = min(tilt, 2 * math.pi - tilt)
    return Expected(out)


def stroke_event(work, ask: A.StrokeEvent) -> Expected:
    """The block's acceleration zeros found by the scalar solver, one position at a time."""
    from .linkages.stroke_events import event_value
    from .reference.stroke_events import bisected_zeros, stroke_events

    return Expected(event_value(stroke_events(work.mechanism, ask.point, bisected_zeros), ask))


def stroke(work, ask: A.Stroke) -> Expected:
    """The block's travel between its two reversals."""
    point = drawn_limits(work).point
    if point is None:
        raise InputError(WHY_NOT[A.Stroke])
    return Expected({"value": _limits(work).stroke, "point": point})


def _statics(work):
    """The Newton–Euler solution of the position's forces, solved once."""
    from .reference.kinetostatics import balance

    return work.shared("statics", lambda: balance(work.reference, work.kinematics,
                                                  work.loads))


def joint_force(work, ask: A.JointForce) -> Expected:
    """The joint's force (or a block's couple) by every link's Newton–Euler equations."""
    j = _statics(work).joint(ask.name)
    return Expected({"value": j.moment} if ask.letter == "T" else vector_value(*j.force))


def effort(work, ask: A.Effort) -> Expected:
    """An engine's effort by its textbook definition, from the same equations' joint
    forces and the loads' closed forms."""
    from .reference.engine_efforts import efforts

    return Expected({"value": efforts(work.reference, work.kinematics, work.loads,
                                      _statics(work))[ask.word]})


def driving_torque(work, ask: A.DrivingTorque) -> Expected:
    """The driving torque by the same equations (the balance of power agrees with it: see
    :func:`~.reference.kinetostatics.power_torque`)."""
    return Expected({"value": _statics(work).torque})
