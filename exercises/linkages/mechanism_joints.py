"""The sliders and contacts of a mechanism file: each read into its joint of the model.

A ``[[slider]]`` puts a point of one link on a straight guide or slot of another, or on
a curved guide (given by its centre of curvature and radius); a ``[[contact]]`` puts a
circle of one link on a flat face or a circle of another. The caller turns a contact
into its equivalent slide or arc (:func:`~tarsim.constructions.joints.contact_slide`,
:func:`~tarsim.constructions.joints.contact_arc`).
"""

from __future__ import annotations

import math
from typing import Any

from tarsim.constructions.joints import Arc, Contact, Profile, Slide, SlideKind
from tarsim.constructions.model import Link
from .mechanism_values import TableReader

__all__ = ["read_slider", "read_contact"]


def read_slider(r: TableReader, i: int, t: dict[str, Any]) -> Slide | Arc:
    """Read the ``i``-th ``[[slider]]``: a slide on a straight guide, or an arc on a curved one."""
    where = {"table": "slider", "index": i}
    allowed = ("kind", "link", "point", "on", "through", "angle", "offset", "centre",
               "radius", "side")
    for k in t:
        if k not in allowed:
            raise r.unknown(k, allowed, "slider setting", key=k, **where)
    kind = t.get("kind", "block")
    if kind not in tuple(SlideKind):
        raise r.unknown(str(kind), tuple(SlideKind), "slider kind", key="kind", **where)
    link = r.link_number(t.get("link"), "link", where)
    point = r.name(t.get("point"), "the sliding point", key="point", **where)
    if point not in r.links[link].names:
        raise r.unknown(point, r.links[link].names, f"point of link {link}",
                        key="point", **where)
    on = r.link_number(t.get("on", 1), "on", where)
    if on == link:
        raise r.fail(f"link {link} cannot slide on itself", key="on", **where)
    if kind == "block" and len(r.links[link].names) != 1:
        raise r.fail(f"a sliding block carries one point; link {link} has "
                     f"{len(r.links[link].names)}", key="link", **where)
    if "centre" in t or "radius" in t:
        return _curved_guide(r, kind, link, point, on, t, where)
    if "side" in t:
        raise r.fail("side applies to a curved guide (with centre and radius)",
                     key="side", **where)
    offset = r.number(t.get("offset", 0.0), "offset", key="offset",
                      **where) * r.units.metres
    if on == 1:
        through = t.get("through")
        if isinstance(through, dict):     # placed once the mechanism stands: extremes.py
            base = _extremes_point(r, through, link, where)
        elif isinstance(through, str):
            if through not in r.links[1].names:
                raise r.unknown(through, r.links[1].names, "frame point",
                                key="through", **where)
            base = r.links[1].local(through)
        elif through is None:
            raise r.fail("a guide on the frame needs through = \"O2\" or [x, y]", **where)
        else:
            base = r.xy(through, "through", key="through", **where)
        if "angle" not in t:
            raise r.fail("a guide on the frame needs its angle", **where)
        a = r.angle(t["angle"], "angle", key="angle", **where)
        d = (math.cos(a), math.sin(a))
        return Slide(SlideKind(kind), link, point, 1,
                     (base[0] - offset * d[1], base[1] + offset * d[0]), d)
    for k in ("through", "angle"):
        if k in t:
            raise r.fail(f"a slot on moving link {on} runs along its axis; give only "
                         "offset, not " + k, key=k, **where)
    return Slide(SlideKind(kind), link, point, on, (0.0, offset), (1.0, 0.0))


def _extremes_point(r: TableReader, through: dict, link: int, where: dict
                    ) -> tuple[float, float]:
    """``through = { extremes = "Q" }``: the guide is laid through the two places a point Q
    of another link reaches at its link's limit positions, as the books lay a shaper's ram
    line "through the extreme positions of Q". Only checked here; the line is placed once
    the rest of the mechanism stands (:mod:`.extremes`), so (0, 0) holds its place."""
    if set(through) != {"extremes"} or not isinstance(through["extremes"], str):
        raise r.fail('through a point\'s extreme positions is written through = { extremes = '
                     '"Q" }', key="through", **where)
    q = through["extremes"]
    if not any(q in k.names for n, k in r.links.items() if n not in (1, link)):
        raise r.fail(f"through = {{ extremes = \"{q}\" }} needs a point {q} of a moving link "
                     f"other than link {link}", key="through", **where)
    r.extremes.append((link, q, where))
    return (0.0, 0.0)


def _curved_guide(r: TableReader, kind: str, link: int, point: str, on: int, t: dict[str, Any],
                  where: dict) -> Arc:
    """Read a slider on a circular guide: its centre of curvature and radius.

    A block turns with the guide's radius, so it is given a pin at the centre of
    curvature, on the ``side`` of its axis (its local +x, the tangent at its point).
    """
    for k in ("through", "angle", "offset"):
        if k in t:
            raise r.fail(f"a curved guide is given by its centre and radius, not {k}",
                         key=k, **where)
    for k in ("centre", "radius"):
        if k not in t:
            raise r.fail(f"a curved guide needs its {k}: centre = a point of link {on} "
                         f"(the centre of curvature) and radius = its radius", **where)
    guide = r.links[on]
    centre = r.name(t["centre"], "the centre of curvature", key="centre", **where)
    if centre not in guide.names:
        raise r.unknown(centre, guide.names, f"point of link {on}", key="centre", **where)
    radius = r.length(t["radius"], "the guide's radius", key="radius", **where)
    side = t.get("side", "left")
    if side not in ("left", "right"):
        raise r.unknown(str(side), ("left", "right"), "side", key="side", **where)
    if kind == "block":
        block = r.links[link]
        if centre in block.names:
            raise r.fail(f"link {link} already has a point {centre}; the block's pin at "
                         "the centre of curvature takes that name", key="centre", **where)
        across = radius if side == "left" else -radius
        r.links[link] = Link(link, block.points + ((centre, (0.0, across)),), block.name)
    return Arc(SlideKind(kind), link, point, on, centre, radius, side=side)


def read_contact(r: TableReader, i: int, t: dict[str, Any]) -> Contact:
    """Read a circle-on-face contact; the caller turns it into its equivalent slide."""
    where = {"table": "contact", "index": i}
    allowed = ("circle", "face", "side", "rolling")
    for k in t:
        if k not in allowed:
            raise r.unknown(k, allowed, "contact setting", key=k, **where)
    for k in ("circle", "face"):
        if k not in t:
            raise r.fail(f"a contact needs its {k}, e.g. "
                         + ('circle = { link = 2, centre = "C", radius = 40 }'
                            if k == "circle" else
                            'face = { link = 3, through = "F", angle = 0 }'), **where)
    circle = _read_profile(r, t["circle"], "circle", where)
    face = _read_profile(r, t["face"], "face", where)
    if circle.link == face.link:
        raise r.fail(f"the circle and the face are both on link {face.link}; a contact "
                     "joins two links", key="face", **where)
    rolling = t.get("rolling", False)
    if not isinstance(rolling, bool):
        raise r.fail(f"rolling must be true or false, got {rolling!r}", key="rolling",
                     **where)
    side = t.get("side")
    if face.is_circle:
        sides = ("outside", "inside")
        side = "outside" if side is None else side
        if rolling and side == "inside" and not circle.radius < face.radius:
            raise r.fail(f"a wheel rolls inside a circle only if it is the smaller: "
                         f"the circle of link {circle.link} is not smaller than that of "
                         f"link {face.link}", key="side", **where)
    else:
        sides = ("left", "right")
        if side is None:
            raise r.fail(f"say on which side of the face of link {face.link} the circle "
                         'lies: side = "left" or "right" of the face\'s direction', **where)
    if side not in sides:
        raise r.unknown(str(side), sides, "side", key="side", **where)
    return Contact(circle, face, side, rolling)


def _read_profile(r: TableReader, v: Any, key: str, where: dict) -> Profile:
    """Read ``circle = { … }`` or ``face = { … }``: only a circle on a flat face."""
    if not isinstance(v, dict):
        raise r.fail(f"{key} must be an inline table such as "
                     + ('{ link = 2, centre = "C", radius = 40 }' if key == "circle"
                        else '{ link = 3, through = "F", angle = 0 }'), key=key, **where)
    allowed = ("link", "centre", "radius", "through", "angle")
    for k in v:
        if k not in allowed:
            raise r.unknown(k, allowed, f"{key} setting", key=key, **where)
    if "link" not in v:
        raise r.fail(f"the {key} needs the number of the link that carries it, "
                     "e.g. link = 2", key=key, **where)
    link = r.link_number(v["link"], key, where)
    round_, flat = "centre" in v or "radius" in v, "through" in v or "angle" in v
    if round_ and flat:
        raise r.fail(f"the {key} of link {link} is given both a centre and radius (a "
                     "circle) and a point and angle (a flat face): give one", key=key,
                     **where)
    if key == "circle" and flat:
        raise r.fail(f"the circle of link {link} is given a point and an angle: a contact "
                     "puts a circle (centre and radius) on a face or on another circle "
                     "(a roller on a flat cam face is written with the roller as the "
                     "circle)", key=key, **where)
    names = r.links[link].names

    def point(name_key: str, what: str) -> str:
        p = r.name(v[name_key], what, key=key, **where)
        if p not in names:
            raise r.unknown(p, names, f"point of link {link}", key=key, **where)
        return p

    if key == "circle" or round_:
        if "centre" not in v:
            raise r.fail(f"the circular profile of link {link} needs a centre, a point "
                         "of that link (the common normal runs through it)", key=key,
                         **where)
        if "radius" not in v:
            raise r.fail(f"the circular profile of link {link} needs a radius (the "
                         "common normal runs through its centre)", key=key, **where)
        return Profile(link, centre=point("centre", "the circle's centre"),
                       radius=r.length(v["radius"], f"the radius of the circle of link "
                                       f"{link}", key=key, **where))
    if "through" not in v:
        raise r.fail(f"the flat face of link {link} needs a point of that link it runs "
                     "through (through = \"F\")", key=key, **where)
    if "angle" not in v:
        raise r.fail(f"the flat face of link {link} needs an angle in the link's own frame "
                     "(the common normal is perpendicular to it)", key=key, **where)
    return Profile(link, through=point("through", "the face's point"),
                   angle=r.angle(v["angle"], "the face's angle", key=key, **where))
