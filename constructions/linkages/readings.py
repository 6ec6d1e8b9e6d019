"""Numbers read off a drawn construction: speed and ω ratios, the mechanical advantage, the
distance from a point to an instant centre, the least velocity along a link, the rubbing
velocity at a pin, and a four-bar's transmission angle.

Each is read the way a student reads it with dividers and a protractor, from what is
already drawn: ω ratios from the centres on their line (as ω itself is), speed ratios
from the velocity polygon's vectors, a distance between two drawn points, an angle
between two drawn links.
"""

from __future__ import annotations

import math

from .. import asks as A
from .least_plate import nearest_on_plate
from .centre_answers import CENTRES_FIGURE, OMEGA_FIGURE, located, ratio_by_centres
from ..checks import Answer
from ..errors import InputError
from ..narration import phrase
from ..model import Mechanism, slider_crank
from ..record import Panel
from ..reference.rotatability import four_bar_spans
from .velocity_polygon import WORKED, drawn_velocity_polygon

__all__ = ["answer_reading", "transmission_pin", "slider_rod", "normal_angle", "angle_at",
           "pin_links",
           "mu_askable", "MU_WHY_NOT", "least_line", "LEAST_WHY_NOT"]

MU_WHY_NOT = {A.TransmissionAngle: "a transmission angle is asked of a four-bar of four pins "
                                   "(between coupler and output) or of a slider-crank (between "
                                   "the rod and the normal to the stroke), and this is neither"}
"""Why a mechanism that is neither a four-bar nor a slider-crank has no transmission angle."""


def slider_rod(m: Mechanism) -> tuple[str, str, int] | None:
    """A plain slider-crank's (four links) piston pin B, the rod's pin A on the crank, and
    the guide's slide index; None for any other mechanism."""
    parts = slider_crank(m) if len(m.links) == 4 else None
    return None if parts is None else (parts[2], parts[1], parts[3])


def transmission_pin(m: Mechanism) -> tuple[str, str, str]:
    """A four-bar's pin B that joins coupler and output, the coupler's other pin A, and the
    output's frame pivot O: μ is the angle ABO.

    Raises
    ------
    InputError
        If the mechanism is no four-bar of four pins.
    """
    if four_bar_spans(m) is None:
        raise InputError(MU_WHY_NOT[A.TransmissionAngle])
    d = m.drive.link
    pivots = {n for n in m.frame.names if len(m.links_at(n)) > 1}
    output = next(k.number for k in m.links if k.number not in (1, d)
                  and any(n in pivots for n in k.names))
    coupler = next(k.number for k in m.links if k.number not in (1, d, output))
    b = next(n for n in m.link(output).names if coupler in m.links_at(n))
    a = next(n for n in m.link(coupler).names if n != b and d in m.links_at(n))
    o = next(n for n in m.link(output).names if n in pivots)
    return b, a, o


def mu_askable(m: Mechanism) -> set[str]:
    """μ, of a four-bar of four pins or of a slider-crank."""
    return set() if four_bar_spans(m) is None and slider_rod(m) is None else {"mu"}


def answer_reading(work, ask) -> Answer:
    """A ratio, a mechanical advantage, a distance to a centre, or μ, read off the drawing."""
    m = work.mechanism
    if isinstance(ask, A.Ratio) and ask.letter == "omega":
        ratio, cond, refs = ratio_by_centres(work, int(ask.b), int(ask.a))
        return Answer(ask, {"value": ratio + 0.0}, cond, "instant centres (ω ratio)",
                      refs=refs, figures=(OMEGA_FIGURE,))
    if isinstance(ask, A.MechanicalAdvantage):
        ratio, cond, refs = ratio_by_centres(work, ask.link, m.drive.link)
        return Answer(ask, {"value": ratio + 0.0}, cond, "instant centres (ω_in / ω_out)",
                      refs=refs, figures=(OMEGA_FIGURE,))
    if isinstance(ask, A.Ratio):
        vp = drawn_velocity_polygon(work)
        (ax, ay), (bx, by) = vp.vector(ask.a), vp.vector(ask.b)
        below = math.hypot(bx, by)
        if below == 0.0:
            raise InputError(f"{ask.b} is at rest at this instant, so V_{ask.a}/V_{ask.b} has "
                             "no value; ask the ratio the other way round")
        value = {"value": math.hypot(ax, ay) / below}
        return Answer(ask, value, vp.worst(), "velocity polygon (o_v tips)",
                      refs=(vp.tip(ask.a), vp.tip(ask.b)), arrows=tuple(vp.steps),
                      figures=(WORKED,), panel=Panel.VELOCITY)
    asm = work.assembly
    if isinstance(ask, A.LeastVelocity):
        return _least_velocity(work, ask)
    if isinstance(ask, A.Rubbing):
        return _rubbing(work, ask)
    if isinstance(ask, A.Distance):
        cs = located(work)
        centre = cs.point(*ask.pair)
        if centre.is_at_infinity:
            raise InputError(f"{A.Centre(ask.pair).name} is at infinity at this position, so "
                             f"no distance from {ask.point} to it can be measured")
        ref = asm.points.get(ask.point)
        if ref is None:
            raise InputError(f"there is no point {ask.point}; the points are "
                             f"{', '.join(asm.points)}")
        value = {"value": math.dist(asm.xy(ask.point), centre.xy)}
        cond = min(asm[ref].conditioning, cs.conditioning(*ask.pair))
        return Answer(ask, value, cond, "dividers, on the centres figure",
                      refs=(cs.centre(*ask.pair).ref, ref), figures=(CENTRES_FIGURE,))
    rod = slider_rod(m)
    if rod is not None:
        b, a, i = rod
        (bx, by), (ax, ay) = asm.xy(b), asm.xy(a)
        dx, dy = asm.guide(i).direction
        value = {"value": normal_angle(ax - bx, ay - by, dx, dy)}
        cond = min(asm[asm.points[n]].conditioning for n in (a, b))
        return Answer(ask, value, cond, f"protractor: rod {b}{a} against the normal to the "
                                        "stroke", refs=(asm.points[a], asm.points[b]))
    b, a, o = transmission_pin(m)
    value = {"value": angle_at(asm.xy(b), asm.xy(a), asm.xy(o))}
    cond = min(asm[asm.points[n]].conditioning for n in (a, b, o))
    return Answer(ask, value, cond, f"protractor: angle {a}{b}{o} between coupler and output",
                  refs=tuple(asm.points[n] for n in (a, b, o)))


def normal_angle(rx: float, ry: float, dx: float, dy: float) -> float:
    """The acute angle (rad) between a rod along (rx, ry) and the normal to a guide along
    (dx, dy): 0 when the rod stands square to the stroke, π/2 when it lies along it."""
    along = abs(rx * dx + ry * dy) / (math.hypot(rx, ry) * math.hypot(dx, dy))
    return math.asin(min(1.0, along))


LEAST_WHY_NOT = {A.LeastVelocity: "Vmin_<k> is asked of a moving link (the frame is at rest "
                                   "everywhere); along a line of link k, name it: "
                                   "Vmin_<k>_<P>_<Q>, its slowest point measured from P"}
"""Why the frame has no slowest point."""


def least_line(m: Mechanism, ask: A.LeastVelocity) -> tuple[str, str]:
    """The two points of link k the least velocity's line runs through, the first the one
    its distance is measured from: those asked, or the link's first point and the one
    farthest from it on the line they all lie on.

    Raises
    ------
    InputError
        If no line is named and the link's points are not on one line.
    """
    link = m.link(ask.link)
    if ask.line is not None:
        missing = [p for p in ask.line if p not in link.names]
        if missing or ask.line[0] == ask.line[1]:
            raise InputError(f"{ask.name}: link {ask.link}'s points are "
                             f"{', '.join(link.names)}; name two of them")
        return ask.line
    if not A.on_one_line(link.points):
        raise InputError(f"{ask.name}: link {ask.link}'s points {', '.join(link.names)} are "
                         f"not on one line; {LEAST_WHY_NOT[A.LeastVelocity].split('; ')[1]}")
    (a, (x0, y0)), *rest = link.points
    b = max(rest, key=lambda p: math.hypot(p[1][0] - x0, p[1][1] - y0))[0]
    return a, b


def _least_velocity(work, ask: A.LeastVelocity) -> Answer:
    """Drop the perpendicular from I_1k onto the link's line: its foot is the point of the
    line nearest the centre the link turns about, so the slowest, at |ω_k| times that
    distance (ω_k from the centres); its distance along the line from the line's first
    point is read with the dividers."""
    m, asm, k = work.mechanism, work.assembly, ask.link
    plate = ask.line is None and not A.on_one_line(m.link(k).points)
    a, b = (None, None) if plate else least_line(m, ask)
    cs = located(work)
    centre = cs.centre(1, k)
    if asm.output(centre.ref).is_at_infinity:
        raise InputError(f"link {k} translates at this instant ({A.Centre((1, k)).name} is at "
                         "infinity): every point of it has one velocity, none the least")
    d = m.drive.link
    ratio, cond, refs = ratio_by_centres(work, d, k) if k != d else (1.0, 1.0, ())
    if plate:
        return _least_on_plate(work, ask, centre, ratio, cond, refs)
    line, at = f"vmin:{k}:{a}:{b}:line", f"vmin:{k}:{a}:{b}"
    alone = sum(q.link == k for q in work.asked(A.LeastVelocity)) == 1
    label = f"M{k}" if alone or ask.line is None else f"M{k}{a}{b}"
    if line not in asm:
        asm.draw(line, "line_through", asm.points[a], asm.points[b],
                 phrase=phrase("readings.link_line", a=a, b=b, link=k))
        asm.draw(at, "project_onto", centre.ref, line, label=label,
                 phrase=phrase("readings.least_velocity", centre=centre.label, a=a, b=b,
                               link=k, point=label))
    foot = asm.output(at).xy
    speed = abs(ratio * m.drive.omega) * math.dist(foot, asm.output(centre.ref).xy)
    (ax, ay), (bx, by) = asm.xy(a), asm.xy(b)
    along = ((foot[0] - ax) * (bx - ax) + (foot[1] - ay) * (by - ay)) / math.dist((ax, ay),
                                                                                  (bx, by))
    cond = min(cond, cs.conditioning(1, k), asm[at].conditioning)
    return Answer(ask, {"point": [foot[0] + 0.0, foot[1] + 0.0], "value": speed,
                        "from": a, "along": along + 0.0}, cond,
                  f"foot of the perpendicular from {centre.label}",
                  refs=(at, centre.ref, *refs), figures=(OMEGA_FIGURE,))


def _least_on_plate(work, ask: A.LeastVelocity, centre, ratio: float, cond: float,
                    refs: tuple) -> Answer:
    """The plate's point nearest I_1k (:mod:`.least_plate`): I_1k itself within the
    plate, the foot of the perpendicular on the side nearest it, or a corner; its speed
    |ω_k| times its distance from I_1k, its distance from the plate's nearest named point."""
    m, asm, k = work.mechanism, work.assembly, ask.link
    names = m.link(k).names
    xy = {n: asm.xy(n) for n in names}
    where, side = nearest_on_plate(xy, asm.output(centre.ref).xy)
    at = f"vmin:{k}"
    if at not in asm:
        if where == "inside":
            asm.draw(at, "mark", centre.ref, phrase=phrase("readings.least_inside",
                                                            centre=centre.label, link=k))
        elif where == "corner":
            asm.draw(at, "mark", asm.points[side[0]], phrase=phrase(
                "readings.least_corner", centre=centre.label, a=side[0], link=k))
        else:
            a, b = side
            asm.draw(f"{at}:line", "line_through", asm.points[a], asm.points[b],
                     phrase=phrase("readings.link_line", a=a, b=b, link=k))
            asm.draw(at, "project_onto", centre.ref, f"{at}:line", label=f"M{k}",
                     phrase=phrase("readings.least_side", centre=centre.label, a=a, b=b,
                                   link=k, point=f"M{k}"))
    foot = asm.output(at).xy
    speed = abs(ratio * m.drive.omega) * math.dist(foot, asm.output(centre.ref).xy)
    near = min(names, key=lambda n: math.dist(xy[n], foot))
    cond = min(cond, located(work).conditioning(1, k), asm[at].conditioning)
    return Answer(ask, {"point": [foot[0] + 0.0, foot[1] + 0.0], "value": speed,
                        "from": near, "along": math.dist(xy[near], foot)}, cond,
                  f"nearest point of the plate to {centre.label}",
                  refs=(at, centre.ref, *refs), figures=(OMEGA_FIGURE,))


def _rubbing(work, ask: A.Rubbing) -> Answer:
    """The two links' ω from the centres, their difference times the pin's radius."""
    m = work.mechanism
    i, j = pin_links(m, ask.point)
    d = m.drive.link
    omegas, refs, cond = [], [], 1.0
    for k in (i, j):
        if k in (1, d):
            omegas.append(0.0 if k == 1 else m.drive.omega)
            continue
        ratio, c, r = ratio_by_centres(work, d, k)
        omegas.append(ratio * m.drive.omega)
        refs += r
        cond = min(cond, c)
    value = {"value": abs(omegas[0] - omegas[1]) * ask.diameter / 2}
    return Answer(ask, value, cond, f"instant centres: |ω{i} − ω{j}| × pin radius",
                  refs=tuple(dict.fromkeys(refs)), figures=(OMEGA_FIGURE,))


def pin_links(m: Mechanism, point: str) -> tuple[int, int]:
    """The two links pin ``point`` joins.

    Raises
    ------
    InputError
        If it joins other than two (no pin, or a multiple pin).
    """
    links = m.links_at(point)
    if len(links) != 2:
        raise InputError(f"{point} joins {len(links)} links ({', '.join(map(str, links))}); a "
                         "rubbing velocity is asked at a pin that joins two")
    return links[0], links[1]


def angle_at(vertex, p, q) -> float:
    """The angle pVq (rad, 0 to π)."""
    ux, uy = p[0] - vertex[0], p[1] - vertex[1]
    vx, vy = q[0] - vertex[0], q[1] - vertex[1]
    return math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy)
