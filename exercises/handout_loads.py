"""A loaded linkage's part of its problem sheet (:mod:`.handout`): the loads as the file gives
them, the forces asked in the course's words, and an empty frame for each link's force
polygon at the force scale the solution draws it at."""

from __future__ import annotations

import math

from tarsim.constructions import asks as A
from tarsim.constructions.narration import numerals, words
from tarsim.constructions.record import Panel
from tarsim.graphics.figure import Figure
from tarsim.graphics.handout import Line, draw_empty_polygon

from .handout_text import math_text, number

__all__ = ["given_loads", "force_words", "force_frames"]

_EFFORTS = {
    "piston_effort": "the piston effort", "wall_thrust": "the thrust on the cylinder wall",
    "inertia_force": "the inertia force of the reciprocating parts",
    "reversal_speed": "the crank speed at which the inertia force equals the rest of the load",
    "crank_effort": "the crank effort", "turning_moment": "the turning moment",
    "bearing_thrust": "the thrust on the crank shaft's bearings",
    "correction_couple": "the correction couple",
    "flywheel_alpha": "the flywheel's angular acceleration",
    "rod_radius_of_gyration": "the rod's radius of gyration about G",
    "inertia_torque_reciprocating": "the inertia torque of the reciprocating parts",
    "inertia_torque_rod": "the inertia torque of the connecting rod",
}
"""An engine's efforts as the course names them (:data:`~tarsim.constructions.asks.EFFORTS`)."""


def given_loads(loads) -> list[Line]:
    """The loads' lines: each link's mass, its centre and moment of inertia as given (or the
    rule assumed for it), each force and couple, gravity, the speed's fluctuation, a
    flywheel, friction."""
    if loads is None:
        return []
    out = [Line(words("Loads"), heading=True)]
    for m in loads.masses:
        k = m.link
        parts = [math_text(f"m{k} = {number(m.mass)}") + " kg"]
        g = math_text(f"G{k}")
        if m.centre_name == "mid":
            parts.append(words("{g} midway along the link", g=g))
        elif m.centre_name:
            parts.append(math_text(f"G{k} = {m.centre_name}"))
        else:
            parts.append(words("{g} at {xy} mm in the link's axes", g=g,
                               xy=math_text(f"({number(m.centre[0] * 1e3)}, "
                                            f"{number(m.centre[1] * 1e3)})")))
        parts.append(_assumed(m.assumed, k) if m.assumed
                     else math_text(f"I{k} = {number(m.inertia)}") + " kg·m²")
        out.append(Line(words(", ").join(parts)))
    for f in loads.forces:
        size = f.resist or math.hypot(*f.force)
        at = f.point if isinstance(f.point, str) else math_text(
            f"({number(f.point[0] * 1e3)}, {number(f.point[1] * 1e3)}) mm")
        said = words("{name} at {point}: {size} N", name=words(f.name or "a force"), point=at,
                     size=math_text(number(size)))
        if f.resist:
            said += " " + words("against the motion")
        elif f.force != (0.0, 0.0):      # as the file gives it: its components
            said += " " + math_text(f"({number(f.force[0])}, {number(f.force[1])}) N")
        out.append(Line(said))
    for c in loads.couples:
        out.append(Line(words("a couple on link {link}: {moment} N·m", link=math_text(str(c.link)),
                              moment=math_text(number(c.moment)))))
    if loads.gravity:
        out.append(Line(math_text(f"g = {number(loads.gravity)}") + " m/s²"))
    if loads.speed_fluctuation is not None:
        out.append(Line(words("coefficient of fluctuation of speed {cs}",
                              cs=math_text(f"Cs = {number(loads.speed_fluctuation)}"))))
    if loads.flywheel is not None:
        out.append(Line(words("flywheel: {i}", i=math_text(f"I = {number(loads.flywheel)}"))
                        + " kg·m²"))
    if loads.friction:
        out.append(Line(math_text(f"μ = {number(loads.friction)}")))
    return out


def _assumed(rule: str, link: int) -> str:
    """The rule a moment of inertia is taken by ("slender rod (1/12)·m·L², L = 180 mm"), its
    words in the language spoken and its formula as written."""
    word, _, formula = rule.partition(" (")
    return (math_text(f"I{link}") + ": " + words(word)
            + (" " + math_text(f"({formula}") if formula else ""))


def force_words(ask) -> tuple[str, bool] | None:
    """What a force analysis's ask is, in the course's words, and whether its symbol leads
    it (``F_23``; an effort is asked by its words alone); None for any other ask."""
    if isinstance(ask, A.JointForce):
        said = ("the couple of link {by} on link {on}" if ask.letter == "T"
                else "the force of link {by} on link {on}")
        return words(said, by=numerals(str(ask.by)), on=numerals(str(ask.on))), True
    if isinstance(ask, A.DrivingTorque):
        return words("the driving torque on link {link}", link=numerals(str(ask.link))), True
    if isinstance(ask, A.Effort):
        return words(_EFFORTS.get(ask.word, ask.word.replace("_", " "))), False
    return None


def force_frames(sol, title) -> list[Figure]:
    """An empty frame for each link's force polygon at a position, at the force scale the
    solution's panel states, sized to hold the polygon, its first point marked."""
    from tarsim.constructions.forces.polygons import drawn_forces
    from tarsim.graphics.forces.force_figure import _polygon_title, _polygons, polygon_fit

    if not sol.work.has("forces"):
        return []
    c, scale = sol.assembly, drawn_forces(sol.work).scale
    out = []
    for mark, group in _polygons([s for s in c if s.panel is Panel.FORCE]):
        joins = [s for s in group if s.verb == "join"]
        if not joins:
            continue
        xs, ys, per_cm = polygon_fit(joins, scale)
        mm = 10.0 / (per_cm * scale)                     # paper mm a drawing metre
        o = c.output(mark.inputs[0]).xy
        across, up = [(x - o[0]) * mm for x in xs], [(o[1] - y) * mm for y in ys]
        reach = (max(0.0, -min(across)), max(0.0, -min(up)), max(0.0, max(across)),
                 max(0.0, max(up)))
        heading = title(words("{what}, {links}", what=words("Force polygon"),
                              links=_polygon_title(mark.label)))
        out.append(draw_empty_polygon(heading, reach=reach, per_cm=per_cm, unit="N",
                                      scale_name="Force scale", pole=("o", "")))
    return out
