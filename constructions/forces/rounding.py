"""How far the force polygons' answers round: the inertia loads they take in are read off the
acceleration polygon, and carry its rounding, which the force polygons then multiply by
their own gain.

A tip of the acceleration polygon is drawn to about eps times the polygon's extent over its
worst conditioning, as :meth:`~..linkages.polygon.Polygon.conditioning` reads it; a link's α is
that rounding over the span it is read across, and an image laid off from it at an arm r
(a point of the link farther out) carries it times r. So a centre's a_G rounds at the
extent's rounding, however small a_G itself: where large vectors of the polygon nearly
cancel (a slotted lever at its extreme, its α the rounding of a zero), its inertia force is
all rounding. The force polygons are linear in their loads: the same polygons drawn with
one load's rounding alone give what that rounding makes of every answer, with the group's
gain in it (a ram's push crossing the slot at a shallow angle, levered onto a block close
by the pivot), which neither the polygons' crossings nor the size of the loads drawn shows.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from .. import asks as A
from ..linkages.acceleration_polygon import drawn_acceleration_polygon
from ..checks import EPS
from ..errors import TarsimError
from ..loads import made_of, resting_speed
from ..model import Mechanism
from ..linkages.velocity_polygon import drawn_velocity_polygon

__all__ = ["image_base", "load_roundings", "answer_roundings", "rate_roundings",
           "read_conditioning", "speed_rounding"]

Vec = tuple[float, float]


def image_base(mech: Mechanism, tips, link: int) -> str:
    """The point of ``link`` its centre's image is drawn from: the first with a tip on the
    polygon (``tips``), or one on the frame, whose tip is the pole."""
    return next(n for n in mech.link(link).names if n in tips or 1 in mech.links_at(n))


def _reader(polygon, mech: Mechanism, link: int) -> int | None:
    """The link whose rate ``link`` takes: its own where the polygon reads it across a span,
    its guide's for a block that turns with a slot; None where the rate is not read (the
    input's is given, a block on a frame guide does not turn)."""
    if link == mech.drive.link:
        return None
    if link in polygon.spans:
        return link
    block = next((s for s in mech.slides if s.link == link and s.type.turns_with_guide),
                 None)
    if block is not None:
        return None if block.guide_link == 1 else _reader(polygon, mech, block.guide_link)
    return min(polygon.spans, key=polygon.spans.get, default=None)


def speed_rounding(work, gain: float = 1.0) -> float:
    """The fastest a point may move, or slide on a link, as the velocity polygon reads it,
    and still rest (m/s): the rounding of a zero there, :func:`~.loads.resting_speed` of
    the polygon's extent at its worst conditioning, times ``gain``, what a lever multiplies
    the reading by beyond what its conditioning shows (its turning read off the block's pin
    near its pivot and laid off, by proportion, to a ram's pin far out)."""
    vp = drawn_velocity_polygon(work)
    return resting_speed(vp.extent(), vp.worst()) * gain


def rate_roundings(work, spans: dict[int, float] | None = None) -> dict[int, float]:
    """The fastest each link may turn, as the velocity polygon reads it, and still rest
    (rad/s): :func:`speed_rounding` over the span its rate is read across (a block in a
    swinging slot takes its slot's; ``spans`` stand for the polygon's where a rate is read
    nearer its pivot than the polygon's span says, a lever's at its block). The input's
    rate is given, and a block on a frame guide does not turn: theirs are 0."""
    vp, mech = drawn_velocity_polygon(work), work.mechanism
    across = vp.spans | (spans or {})
    zero = speed_rounding(work)
    out = {1: 0.0}
    for k in mech.links:
        if k.number != 1:
            reader = _reader(vp, mech, k.number)
            out[k.number] = zero / across[reader] if across.get(reader) else 0.0
    return out


def _sliding(vp, mech: Mechanism, link: int) -> float:
    """The fastest a point slides in a slot of ``link`` (m/s), off the velocity polygon."""
    out = 0.0
    for s in mech.slides:
        if s.guide_link == link:
            try:
                v, w = vp.vector(s.point), vp.vector(f"{s.point}{link}")
            except TarsimError:
                continue                   # a slot the polygon carries no tip for
            out = max(out, math.dist(v, w))
    return out


def load_roundings(work, known: dict[int, list], at: dict[str, Vec]
                   ) -> dict[int, tuple[float, float]]:
    """Each massive link's inertia force (N) and couple (N·m) as the polygons round them.

    Every vector the acceleration polygon lays off, of size L, is off by eps·L over its
    worst conditioning (its direction is the space diagram's, its length read to that): the
    tips by that of the polygon's extent. A link's α is read across a span r out of vectors
    of about a_in, (ω² + |α|)·r and the Coriolis 2|ω|·v_slide, the largest of them ℓ: it
    rounds at eps·ℓ/(worst·r), and a tip that is the image of a point as far out as the
    mechanism's size at that times the size. ω rounds likewise off the velocity polygon,
    and each normal part ω²·r it makes by 2|ω|·δω·r. The image g′ of a centre G drawn from
    the link's point K carries K's tip's rounding (none for a point on the frame, at the
    pole), and its own parts' along KG. ``known`` are the loads as drawn, each inertia force
    at its centre and named ``Fi<link>``.
    """
    mech = work.mechanism
    ap, vp = drawn_acceleration_polygon(work), drawn_velocity_polygon(work)
    size = work.assembly.size
    slack = EPS / ap.worst()
    turning = EPS * vp.extent() / vp.worst()

    def omega(link: int) -> float:
        return mech.drive.omega if link == mech.drive.link else vp.rates.get(link, 0.0)

    def rates(link: int) -> tuple[float, float, float]:
        """How far ω and α round, and the scale α is read at, times its span."""
        a, v = _reader(ap, mech, link), _reader(vp, mech, link)
        d_omega = turning / vp.spans[v] if v is not None else 0.0
        if a is None:
            return d_omega, 0.0, 0.0
        r, w = ap.spans[a], omega(a)
        read = max(mech.input_acceleration, (w * w + abs(ap.rates.get(a, 0.0))) * r,
                   2.0 * abs(w) * _sliding(vp, mech, a))
        return d_omega, slack * read / r, slack * read * size / r

    moving = [k.number for k in mech.links if k.number != 1]
    tip = max([slack * ap.extent()] + [image for _, _, image in map(rates, moving)]) \
        + max([2.0 * abs(omega(k)) * rates(k)[0] for k in moving] + [0.0]) * size
    out = {}
    for m in work.loads.masses:
        base = image_base(mech, ap.tips, m.link)
        arm = math.dist(_centre(known, m.link), at[base])
        w = omega(m.link)
        d_omega, d_alpha, _ = rates(m.link)
        own = slack * (w * w + abs(ap.rates.get(m.link, mech.drive.alpha)))
        at_base = 0.0 if 1 in mech.links_at(base) else tip
        d_a = at_base + (d_alpha + 2.0 * abs(w) * d_omega + own) * arm
        out[m.link] = (m.mass * d_a, m.inertia * d_alpha)
    return out


def answer_roundings(known: dict[int, list], roundings: dict[int, tuple[float, float]],
                     redraw: Callable[[dict[int, list]], object], *, size: float, driver: int
                     ) -> dict[str, float] | None:
    """Each answer's rounding (N, or N·m for a couple, the torque and the turning moment):
    the polygons ``redraw`` draws (on a scratch sheet) with one load's rounding alone, a
    force along each axis at its centre and a couple, summed in size over every load.

    ``known`` are the loads as drawn; each trial is laid at the size of the largest of
    them, so it is drawn at the polygons' own scale, and scaled back. None where a trial
    cannot be drawn (its forces outgrow its load past their rounding: the group stands at
    a dead point for it), for every answer then rounds without bound.
    """
    unit = max([math.hypot(*f) + abs(m) / size for ls in known.values() for _, f, m, _ in ls]
               + [0.0]) or 1.0
    out: dict[str, float] = {}
    for link, (force, couple) in roundings.items():
        centre = _centre(known, link)
        for load, share in ((((unit, 0.0), 0.0), force / unit),
                            (((0.0, unit), 0.0), force / unit),
                            (((0.0, 0.0), unit * size), couple / (unit * size))):
            if not share:
                continue
            trial = {k: [] for k in known}
            trial[link] = [(centre, *load, f"Fi{link}")]
            try:
                found = redraw(trial)
            except TarsimError:
                return None
            for name, moved in _sizes_of(found, driver).items():
                out[name] = out.get(name, 0.0) + moved * share
    return out


def read_conditioning(work, forces, ask) -> float:
    """The conditioning the inertia loads' reading leaves ``ask``'s answer: eps over its
    rounding (``forces.rounding``) beside what its check measures it against, the loads
    the forces are made of (:func:`~.loads.made_of`, each mass moving as the polygons read
    it) or the largest joint force if more, times the mechanism's size for a moment; 1
    where nothing is read, 0 where the rounding is without bound."""
    if forces.rounding is None:
        return 0.0
    rounding = forces.rounding.get(ask.name, 0.0)
    if rounding == 0.0:
        return 1.0
    mech = work.mechanism
    ap, vp = drawn_acceleration_polygon(work), drawn_velocity_polygon(work)
    d = mech.drive

    def motion(m) -> tuple[float, float, float]:
        driven = m.link == d.link
        return (d.omega if driven else vp.rates.get(m.link, 0.0),
                d.alpha if driven else ap.rates.get(m.link, 0.0),
                math.hypot(*forces.inertia[m.link][0]) / m.mass)

    size = work.assembly.size
    scale = max([made_of(work.loads, motion, size=size, a_in=mech.input_acceleration)]
                + [math.hypot(*v) for v in forces.joints.values()])
    moment = isinstance(ask, A.DrivingTorque) or ask.name.startswith("T_") \
        or ask.name in A.MOMENTS
    return min(1.0, EPS * scale * (size if moment else 1.0) / rounding)


def _centre(known: dict[int, list], link: int) -> Vec:
    """Where ``link``'s inertia force acts: its centre of mass."""
    return next(p for p, _, _, name in known[link] if name == f"Fi{link}")


def _sizes_of(forces, driver: int) -> dict[str, float]:
    """The size of each answer of a force analysis: the joints', the couples', the driving
    torque's (named T<input>) and the efforts'."""
    out = {name: math.hypot(*f) for name, f in forces.joints.items()}
    out |= {name: abs(m) for name, m in forces.couples.items()}
    out |= {name: abs(v) for name, v in forces.efforts.items()}
    out[f"T{driver}"] = abs(forces.torque)
    return out
