"""The input of a mechanism file: the driven link, its angle, and its motion.

``[input]`` names the input link and its angle, and gives its motion as that link's ω
and α, or as another member's: a point's speed along a frame guide, the speed of a
point of the input link itself (ω·r about its pivot, in the sense given), or another link's
ω (:class:`~tarsim.constructions.model.GivenRate`).
"""

from __future__ import annotations

import math

from tarsim.constructions.model import Drive, GivenRate
from .mechanism_values import TableReader

__all__ = ["read_input"]


def read_input(r: TableReader) -> Drive:
    """Read ``[input]``: the input link's angle, and its ω and α or the motion given in
    their stead."""
    t = r.table("input", True)
    where = {"table": "input"}
    for k in t:
        if k not in ("link", "angle", "omega", "alpha", "speed"):
            raise r.unknown(k, ("link", "angle", "omega", "alpha", "speed"),
                            "input setting", key=k, **where)
    if "link" not in t:
        raise r.fail("must name the input link, e.g. link = 2", **where)
    link = r.link_number(t["link"], "link", where)
    if link == 1:
        raise r.fail("the frame (link 1) cannot be the input", key="link", **where)
    if "angle" not in t:
        raise r.fail(f"[input] needs the angle of link {link}", **where)
    angle = r.angle(t["angle"], "angle", key="angle", **where)
    r.given = _read_given(r, t, link, where)
    if r.given is not None:
        # The input's own rates follow from the member given; 1 rad/s stands in for now.
        return Drive(link, angle, 1.0, 0.0, r.given.second_given)
    omega = r.number(t.get("omega", 0.0), "omega", size=True, key="omega", **where)
    if r.units.angular_velocity == "rpm":
        omega *= 2 * math.pi / 60
    alpha = r.number(t.get("alpha", 0.0), "alpha", size=True, key="alpha", **where)
    return Drive(link, angle, omega, alpha, "alpha" in t)


def _read_given(r: TableReader, t: dict, link: int, where: dict) -> GivenRate | None:
    """``speed = { point = "C", value = 3000, acceleration = 0 }`` (a point on a frame
    guide, along the guide, in the file's length unit per second) or ``omega = { link =
    3, value = 5, alpha = 0 }`` (another link's ω): the input given by another member."""
    speed, omega = t.get("speed"), t.get("omega")
    if speed is None and not isinstance(omega, dict):
        return None
    if speed is not None and omega is not None:
        raise r.fail("give the input's omega or a speed, not both", key="speed", **where)
    if speed is not None:
        key, spec, allowed = "speed", speed, ("point", "value", "acceleration", "sense")
    else:
        key, spec, allowed = "omega", omega, ("link", "value", "alpha")
    if not isinstance(spec, dict) or "value" not in spec:
        raise r.fail(f"{key} = {{ {allowed[0]} = …, value = … }} gives the input by "
                     "another member's motion", key=key, **where)
    for k in spec:
        if k not in allowed:
            raise r.unknown(k, allowed, f"{key} setting", key=key, **where)
    value = r.number(spec["value"], f"{key} value", size=True, key=key, **where)
    if value == 0.0:
        raise r.fail(f"the {key} given is 0, which leaves the mechanism at rest; give a "
                     "nonzero one, or the input's own omega = 0", key=key, **where)
    if key == "speed" and spec.get("sense", "ccw") not in ("ccw", "cw"):
        raise r.fail(f"the sense of speed must be \"ccw\" or \"cw\", not {spec['sense']!r}",
                     key=key, **where)
    second_key = allowed[2]
    second = r.number(spec.get(second_key, 0.0), f"{key} {second_key}", size=True,
                      key=key, **where)
    if key == "speed":
        point = spec.get("point")
        m = r.units.metres
        on_guide = [s for s in r.slides if s.point == point and s.guide_link == 1]
        if on_guide and "sense" not in spec:
            return GivenRate("speed", point, value * m, second * m, second_key in spec)
        if point in r.links[link].names:
            sign = -1.0 if spec.get("sense") == "cw" else 1.0
            _about_pivot(r, link, point, where)
            return GivenRate("input_point", point, sign * value * m, sign * second * m,
                             second_key in spec)
        runs = sorted({s.point for s in r.slides if s.guide_link == 1})
        raise r.fail(f"speed gives the motion of a point of input link {link} "
                     f"({', '.join(r.links[link].names)}) or on a frame guide "
                     f"({', '.join(runs) or 'none here'}); '{point}' is neither",
                     key=key, **where)
    target = r.link_number(spec.get("link"), key, where)
    if target in (1, link):
        raise r.fail(f"omega = {{ link = {target}, … }} gives another link's ω; give the "
                     f"input link's own as omega = <number>", key=key, **where)
    if r.units.angular_velocity == "rpm":
        value *= 2 * math.pi / 60
    return GivenRate("omega", target, value, second, second_key in spec)


def _about_pivot(r: TableReader, link: int, point: str, where: dict) -> None:
    """Refuse a given speed of a point of the input link unless the link turns about a frame
    pivot other than the point: then the point's speed is ω·r, along its circle."""
    pivots = set(r.links[link].names) & set(r.links[1].names)
    if not pivots:
        raise r.fail(f"speed = {{ point = \"{point}\", … }} gives ω{link} as the speed over "
                     f"the radius about link {link}'s frame pivot, and link {link} has none; "
                     f"give omega = <number>", key="speed", **where)
    if point in pivots:
        raise r.fail(f"{point} is link {link}'s frame pivot, at rest: give the speed of "
                     f"another of its points", key="speed", **where)
