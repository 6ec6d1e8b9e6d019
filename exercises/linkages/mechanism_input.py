"""The input of a mechanism file: the driven link, its angle, and its motion.

``[input]`` names the input link and its angle, and gives its motion as that link's ω
and α, or as another member's: a point's speed along a frame guide, the speed of a
point of the input link itself (ω·r about its pivot, in the sense given), or another link's
ω (:class:`~tarsim.constructions.model.GivenRate`). An engine's crank angle may be given as
the books give it, from a dead centre (``from = "t.d.c."``): turned that far, in the sense
ω turns, from the crank lying along the line of stroke toward the piston (or away from it,
the outer or bottom dead centre). A crank between two frame pivots, as a slotted lever's, may
be turned from its line of centres (``from = "line of centres produced"``, the books' "OC
produced": the crank beyond its pivot, away from the other).
"""

from __future__ import annotations

import math

from tarsim.constructions.model import Drive, GivenRate
from ..file_numbers import radians_in_turn
from .mechanism_values import TableReader

__all__ = ["read_input"]


def read_input(r: TableReader) -> Drive:
    """Read ``[input]``: the input link's angle, and its ω and α or the motion given in
    their stead."""
    t = r.table("input", True)
    where = {"table": "input"}
    for k in t:
        if k not in ("link", "angle", "omega", "alpha", "speed", "from"):
            raise r.unknown(k, ("link", "angle", "omega", "alpha", "speed", "from"),
                            "input setting", key=k, **where)
    if "link" not in t:
        raise r.fail("must name the input link, e.g. link = 2", **where)
    link = r.link_number(t["link"], "link", where)
    if link == 1:
        raise r.fail("the frame (link 1) cannot be the input", key="link", **where)
    if "angle" not in t:
        raise r.fail(f"[input] needs the angle of link {link}", **where)
    angle = r.angle(t["angle"], "angle", key="angle", **where)
    r.angle_from = None
    if "from" in t:
        turned = r.number(t["angle"], "angle", bounded=False, key="angle", **where)
        r.angle_from = (_line_of_centres if _said(t) in LINES_OF_CENTRES
                        else _dead_centre)(r, t, link, where)
        angle = file_angle(r.angle_from, turned, r.units.angle)
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


DEAD_CENTRES = {**dict.fromkeys(("t.d.c.", "tdc", "i.d.c.", "idc", "top dead centre",
                                 "inner dead centre", "dead centre"), 0.0),
                **dict.fromkeys(("b.d.c.", "bdc", "o.d.c.", "odc", "bottom dead centre",
                                 "outer dead centre"), math.pi)}
"""The dead centres a crank angle may be given from: the crank along the line of stroke
toward the piston (the top or inner), or away from it (the bottom or outer)."""


LINES_OF_CENTRES = {**dict.fromkeys(("line of centres", "line of centers"), math.pi),
                    **dict.fromkeys(("line of centres produced", "line of centers produced"),
                                    0.0)}
"""The directions along the line of centres a crank angle may be given from: toward the
other frame pivot, or produced beyond the crank's own pivot, away from it (the books' "OC
produced", O the other pivot and C the crank's)."""


def _said(t: dict) -> str | None:
    """``t["from"]`` as a key of :data:`DEAD_CENTRES` or :data:`LINES_OF_CENTRES`."""
    said = t.get("from")
    return said.strip().lower() if isinstance(said, str) else None


def _sense(t: dict) -> float:
    """The sense ω turns, +1 counter-clockwise unless [input] gives ω as a negative number."""
    omega = t.get("omega", 0.0)
    omega = omega.get("value", 0.0) if isinstance(omega, dict) else omega
    return -1.0 if isinstance(omega, (int, float)) and omega < 0 else 1.0


def _line_of_centres(r: TableReader, t: dict, link: int,
                     where: dict) -> tuple[float, float, str]:
    """The line of centres ``t["from"]`` names, as :func:`_dead_centre` gives a dead centre:
    the line from the crank's frame pivot to the one other frame point a moving link turns
    about (a slotted lever's fulcrum), toward it or produced away from it."""
    pivots = [n for n in r.links[link].names if n in r.links[1].names]
    others = sorted({n for k, lk in r.links.items() if k not in (1, link) for n in lk.names
                     if n in r.links[1].names} - set(pivots))
    if len(pivots) != 1 or len(others) != 1:
        raise r.fail(f"a line of centres joins the crank's pivot to one other: link {link} "
                     f"turns about {', '.join(pivots) or 'none'}, the others about "
                     f"{', '.join(others) or 'none'}; give the angle from +x",
                     key="from", **where)
    (cx, cy), (ox, oy) = r.links[1].local(pivots[0]), r.links[1].local(others[0])
    # in degrees, the line's angle to the rounding of its direction, so 90° − 120° is −30°
    toward = math.degrees(math.atan2(cy - oy, cx - ox))
    toward = round(toward, 9) if abs(toward - round(toward, 9)) < 1e-12 else toward
    said = t["from"].strip()
    return toward + math.degrees(LINES_OF_CENTRES[_said(t)]), _sense(t), said


def file_angle(angle_from: tuple[float, float, str] | None, turned: float, unit: str) -> float:
    """An input angle as the file gives it (in ``unit``, "deg" or "rad") as the crank's
    angle from +x (rad): turned from the dead centre ``angle_from`` names in the sense the
    crank turns, where [input] names one (:func:`_dead_centre`), else from +x."""
    if angle_from is None:
        return radians_in_turn(turned, unit)
    toward, sense, _ = angle_from
    per = 1.0 if unit == "deg" else math.pi / 180
    return radians_in_turn(toward + sense * turned / per, "deg")


def _dead_centre(r: TableReader, t: dict, link: int, where: dict) -> tuple[float, float, str]:
    """The dead centre ``t["from"]`` names: its direction from the crank's pivot (degrees
    from +x), the sense ω turns (+1 counter-clockwise unless ω is a negative number), and
    its name as the file writes it: the line of stroke is the one slider's on the frame,
    through the crank's pivot, toward the piston as [assembly] places it ("forward" along
    the slider's angle, "backward" against it)."""
    said = t["from"]
    if _said(t) not in DEAD_CENTRES:
        raise r.fail(f"from names the dead centre the angle is turned from, \"t.d.c.\" (or "
                     f"\"i.d.c.\", the crank toward the piston) or \"b.d.c.\", or a \"line of "
                     f"centres (produced)\"; got {said!r:.40}", key="from", **where)
    guides = [s for s in r.slides if s.guide_link == 1 and s.contact is None]
    pivots = [n for n in r.links[link].names if n in r.links[1].names]
    if len(guides) != 1 or not pivots:
        raise r.fail(f"an angle from a dead centre is along the line of stroke: link {link} "
                     f"turns about a frame pivot and one slider runs on the frame; here "
                     f"{len(guides)} do, so give the angle from +x", key="from", **where)
    (s,), (ox, oy) = guides, r.links[1].local(pivots[0])
    (tx, ty), (dx, dy) = s.through, s.direction
    size = max(math.hypot(tx - ox, ty - oy), r.units.metres)
    off = abs((ox - tx) * dy - (oy - ty) * dx)
    if off > 1e-9 * size:
        raise r.fail(f"the line of stroke passes {off / r.units.metres:.6g} {r.units.length} "
                     f"from the crank's pivot {pivots[0]}: its dead centres are not along it, "
                     f"so give the angle from +x (or from its \"line of centres\")",
                     key="from", **where)
    branch = (r.d.get("assembly") or {}).get(s.point, "forward")
    if isinstance(branch, list) and len(branch) == 2:
        near = [r.number(v, "a near point's coordinate", key="from", **where) * r.units.metres
                for v in branch]
        back = (near[0] - ox) * dx + (near[1] - oy) * dy < 0
    else:
        back = branch == "backward"
    sense = _sense(t)
    # in degrees, the line's angle to the rounding of its direction, so 90° − 40° is 50°
    toward = math.degrees(math.atan2(dy, dx))
    toward = round(toward, 9) if abs(toward - round(toward, 9)) < 1e-12 else toward
    toward += (180.0 if back else 0.0) + math.degrees(DEAD_CENTRES[said.strip().lower()])
    return toward, sense, said.strip()

