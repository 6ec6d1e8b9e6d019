"""Every load on each link, as the force polygons take it in: the inertia force and couple
(D'Alembert), the weight, the external forces and couples.

**Inertia.** Each link's centre of mass G gets its image g′ on the acceleration polygon:
from the tip k′ of a point K of the link, the normal part ω²·KG toward K, then the
tangential part α·KG square to it. Its inertia force −m·a_G is the vector g′ → o_a times
m; its inertia couple is −I·α. A resistance acts against its point's velocity as the
velocity polygon draws it, and only on the stroke it is given for.
"""

from __future__ import annotations

import math

from .. import geometry as g
from ..linkages.acceleration_polygon import drawn_acceleration_polygon
from ..checks import quiet
from ..errors import TarsimError
from ..loads import Loads, near_rest, near_rest_refusal, pendulum_radius
from ..narration import Word, phrase
from ..record import Construction, Kind, Panel
from ..linkages.velocity_polygon import drawn_velocity_polygon
from .drafting import as_said
from .groups import gain
from .rounding import image_base, speed_rounding

__all__ = ["inertia_loads", "link_loads"]

Vec = tuple[float, float]


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
    block = next((s for s in mech.slides if s.link == link and s.type.turns_with_guide),
                 None)
    if block is not None:
        guide = 0.0 if block.guide_link == 1 else _turn(work, block.guide_link, at)
        return guide + math.atan2(block.direction[1], block.direction[0])
    return 0.0


def inertia_loads(work, loads: Loads, at) -> dict[int, tuple[Vec, float]]:
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
        if m.swing is not None:
            _say_pendulum(c, m, c.points[ref])
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
                               n=as_said(omega * omega * size, "m/s²"),
                               t=as_said(abs(alpha_said) * size, "m/s²"),
                               h=_offset(m, alpha_said, ap.between(ap.pole, n_end),
                                         (-r[1] * alpha, r[0] * alpha))))
        a_g = ap.between(ap.pole, image)
        out[m.link] = ((-m.mass * a_g[0], -m.mass * a_g[1]), -m.inertia * alpha)
    return out


def _say_pendulum(c, m, at) -> None:
    """The step that finds a link's inertia from its pendulum test: hung h from G it swings
    as a compound pendulum, T = 2π·√((k² + h²)/(g·h)), so k² = g·h·T²/(4π²) − h²."""
    period, h, about, knife = m.swing
    k = pendulum_radius(period, h)
    c.draw(f"force:say:pendulum{m.link}", "mark", at, phrase=phrase(
        "force.pendulum_knife" if knife else "force.pendulum", link=m.link, about=about,
        period=as_said(period, "s", ".6g"), h=as_said(h * 1e3, "mm", ".6g"),
        k=as_said(k * 1e3, "mm", ".6g"),
        inertia=as_said(m.inertia, "kg·m²", ".6g")))


def _offset(m, alpha: float, normal: Vec, tangential: Vec):
    """Where the inertia force and couple act as one force: h = I·α/(m·a_G) from G."""
    a_g = math.hypot(normal[0] + tangential[0], normal[1] + tangential[1])
    if a_g == 0.0 or alpha == 0.0:
        return Word("0 (no couple)")
    return as_said(m.inertia * abs(alpha) / (m.mass * a_g) * 1e3, "mm")


def link_loads(work, loads: Loads, link: int, at, inertia, group
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
            still = speed_rounding(work, gain(group, at, f.point))
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
