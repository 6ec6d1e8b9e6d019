"""The cam's profile laid out by kinematic inversion, as the textbooks lay it out.

Hold the cam still and turn the follower round it the other way. Divide the circles about
the cam centre at the stations of the displacement diagram (each segment's divisions),
turning the follower's rest position back by each station's cam angle; at each station,
lay off the lift taken from the diagram with dividers and draw the follower there:

- a **translating** follower's line through its turned rest point, radial or tangent to
  the offset circle (radius e); the lift laid off along it from the prime circle;
- an **oscillating** follower's pivot turned round the pivot circle, and its arm, turned
  back with it, swung about it through the follower's angle (the lift as an arc over
  the arm's length);
- then the knife edge as that point, the roller as a circle about it, the flat face as
  the square to the follower's line through it.

The profile is the curve through the knife-edge points, or the envelope of the roller
circles or face lines: :mod:`..reference.cam_profile` gives it in closed form, and the
solution checks it against every circle and line drawn here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .. import geometry as g
from ..narration import Phrase, Word, drawn_angle, drawn_length, phrase
from ..record import Construction, Kind, Ref
from ..reference.cam_profile import Follower, arm_start, prime_radius
from .displacement import Displacement

__all__ = ["Layout", "Place", "lay_out_profile"]


@dataclass(frozen=True)
class Place:
    """One station of the layout: its number, cam angle (rad), the lift laid off (m), the
    follower's turned rest point, the trace point drawn, and the follower drawn there (the
    roller circle, the face line, or the trace point again for a knife edge); for an
    oscillating follower the turned pivot."""

    number: int
    theta: float
    lift: float
    rest: Ref
    trace: Ref
    follower: Ref
    pivot: Ref | None = None
    axis: Ref | None = None
    source: Ref | None = None
    """The diagram's point the lift was taken from with dividers."""


@dataclass
class Layout:
    """The layout's record, its circles by name, and its stations in order round the cam."""

    construction: Construction
    follower: Follower
    circles: dict[str, Ref] = field(default_factory=dict)
    places: list[Place] = field(default_factory=list)
    closing: Phrase | None = None
    """What the profile is, said after the stations: it is drawn, not constructed."""


def stations(d: Displacement) -> list[tuple[float, float, Ref]]:
    """The diagram's constructed points as (cam angle, lift, the point), once each round
    the turn."""
    out: list[tuple[float, float, Ref]] = []
    for curve, start in zip(d.curves, d.starts):
        for t, ref in curve:
            theta, y = start + t, d.point(ref)[1]
            if out and abs(theta - out[-1][0]) < 1e-12:
                continue
            if theta >= 2 * math.pi - 1e-12:
                continue                              # 360° is 0° again
            out.append((theta, y, ref))
    return out


def lay_out_profile(d: Displacement, base_radius: float, f: Follower, sigma: float
                    ) -> Layout:
    """Lay the profile out for a cam turning in the sense ``sigma`` (+1 counter-clockwise),
    its stations and lifts taken from the diagram ``d``.

    Raises
    ------
    ValueError
        From :func:`..reference.cam_profile.arm_start`, for an arm that cannot reach.
    """
    c = Construction()
    out = Layout(c, f)
    o = c.give("O", g.Point(0.0, 0.0), label="O", phrase=phrase("cam.centre"))
    turn_word = Word("clockwise" if sigma > 0 else "counter-clockwise")
    out.circles["base"] = c.draw("base", "swing_arc", o, radius=base_radius, kind=Kind.ARC,
                                 phrase=phrase("cam.base", r=drawn_length(base_radius)))
    rp = prime_radius(base_radius, f)
    if f.kind == "roller":
        out.circles["prime"] = c.draw("prime", "swing_arc", o, radius=rp, kind=Kind.ARC,
                                      phrase=phrase("cam.prime", r=drawn_length(rp),
                                                    roller=drawn_length(f.radius)))
    if f.oscillating:
        psi0, kappa = arm_start(base_radius, f)
        a0 = c.give("A", g.Point(*f.pivot), label="A")
        out.circles["pivot"] = c.draw("pivots", "swing_arc", o, radius=math.hypot(*f.pivot),
                                      kind=Kind.ARC, phrase=phrase(
                                          "cam.pivot_circle", arm=drawn_length(f.arm)))
        rest0 = c.give("C", g.Point(f.pivot[0] + f.arm * math.cos(psi0),
                                     f.pivot[1] + f.arm * math.sin(psi0)), label="",
                       phrase=phrase("cam.stations", turn=turn_word, follower=Word(f.kind)))
    else:
        if f.offset:
            out.circles["offset"] = c.draw("offsets", "swing_arc", o, radius=abs(f.offset),
                                           kind=Kind.ARC,
                                           phrase=phrase("cam.offset",
                                                         e=drawn_length(abs(f.offset))))
        s0 = math.sqrt(rp * rp - f.offset * f.offset) if f.kind != "flat-faced" else rp
        x0 = f.offset if f.kind != "flat-faced" else 0.0
        rest0 = c.give("F", g.Point(x0, s0), label="", phrase=phrase(
            "cam.stations", turn=turn_word, follower=Word(f.kind)))
        foot0 = c.give("T", g.Point(x0, 0.0), label="") if x0 else o
    then = phrase(_THEN[f.kind], r=drawn_length(f.radius)) if f.kind in _THEN else None
    for i, (theta, lift, source) in enumerate(stations(d)):
        back = -sigma * theta
        rest = c.draw(f"rest{i}", "rotate_about", rest0, o, angle=back, label=str(i))
        if f.oscillating:
            pivot = c.draw(f"A{i}", "rotate_about", a0, o, angle=back)
            trace = c.draw(f"P{i}", "rotate_about", rest, pivot, angle=kappa * lift / f.arm,
                           phrase=phrase("cam.swing", i=i, deg=drawn_angle(theta),
                                         swing=drawn_angle(lift / f.arm), then=then))
            axis = c.draw(f"arm{i}", "line_through", pivot, trace, kind=Kind.LINE)
        else:
            pivot = None
            foot = c.draw(f"T{i}", "rotate_about", foot0, o, angle=back) if foot0 != o else o
            axis = c.draw(f"axis{i}", "line_through", foot, rest, kind=Kind.LINE)
            trace = c.draw(f"P{i}", "lay_off", rest, axis, length=lift, phrase=phrase(
                "cam.lift", i=i, deg=drawn_angle(theta), lift=drawn_length(lift), then=then))
        if f.kind == "roller":
            body = c.draw(f"roller{i}", "swing_arc", trace, radius=f.radius, kind=Kind.ARC)
        elif f.kind == "flat-faced":
            body = c.draw(f"face{i}", "perpendicular_through", trace, axis, kind=Kind.LINE)
        else:
            body = trace
        out.places.append(Place(i, theta, lift, rest, trace, body, pivot, axis, source))
    out.closing = phrase(_PROFILE[f.kind])
    return out


_THEN = {"roller": "cam.then.roller", "flat-faced": "cam.then.flat-faced"}
"""What is drawn at each station's trace point, by follower."""

_PROFILE = {"knife-edge": "cam.profile.knife-edge", "roller": "cam.profile.roller",
            "flat-faced": "cam.profile.flat-faced"}
"""How the profile is drawn through the stations, by follower."""
