"""The problem sheet of a rotor some of whose data are unknown (:mod:`.handout`): its end view
with each mass whose radial line is given (an unknown mass left as a gap in its label), the
masses whose angle is to be found left out; its side view with the planes given; its table
with the unknown cells empty; an empty frame for each polygon at the solution's scale; its
data and what is asked, and no answer.

The end and side views are the solution's (:mod:`~tarsim.graphics.balancing.
balance_figures`), drawn with the answers hidden (:func:`~tarsim.graphics.hiding.hiding`),
given only what the file gives.
"""

from __future__ import annotations

import math

from tarsim.constructions.narration import numerals, unit_words, words
from tarsim.constructions.units import LENGTH_UNITS
from tarsim.graphics.figure import Figure
from tarsim.graphics.handout import Line, compose_handout, draw_statement

from .handout_text import math_text, number

__all__ = ["open_rotor_sheets", "unbalance_sheets"]

_UNKNOWN = {"mass": "its mass", "radius": "its radius", "angle": "its angle",
            "plane": "its plane"}
"""How the sheet asks each unknown of a mass."""


def open_rotor_sheets(ex, sheet: tuple[float, float]) -> list[Figure]:
    """A rotor with unknowns' sheet: the end view, the side view (masses in more than one
    plane), the statement, the table, and the polygons' empty frames."""
    from tarsim.graphics.balancing.balance_figures import draw_end_view, draw_side_view
    from tarsim.graphics.hiding import hiding

    from .balancing.open_rotor_solution import _label
    from .chapters import chapter_of
    from .handout_chapters import _empty_balance_polygon

    sol = chapter_of(ex).solve(ex)
    closure, rotor = sol.closure, ex.open
    unit, metre = ex.length_unit, LENGTH_UNITS[ex.length_unit]
    name = sol.exercise.name
    gaps = [p.name for p in rotor.parts if p.angle is None or p.radius is None]
    panels = []
    with hiding(frozenset({"answers"})):
        drawn = [(p.name, p.radius, _label(closure.parts[p.name], unit, metre, p.unknowns()))
                 for p in rotor.parts if p.name not in gaps]
        notes = ([words("not drawn, its radial line to be found: {names}",
                        names=words(", ").join(gaps))] if gaps else [])
        panels.append(draw_end_view(closure.construction, drawn,
                                    words("{name}: space diagram", name=name), unit, metre,
                                    notes=notes))
        if not rotor.static:
            planes = [(p.name, p.plane, "link") for p in rotor.parts if p.plane is not None]
            panels.append(draw_side_view(planes, words("{name}: side view", name=name), unit,
                                         metre))
    # the statement and the table under the end view: the views and they fill one sheet
    panels[1:1] = [draw_statement(_given_parts(ex, unit, metre)
                                  + _asked_parts(rotor, engine=ex.engine is not None)),
                   _parts_table(ex, unit, metre)]
    for which in closure.order:
        tips = closure.force if which == "force" else closure.couple
        title = (words("{name}: force polygon", name=name) if which == "force" else
                 words("{name}: couple polygon (reference plane {plane})", name=name,
                       plane=closure.reference[0]))
        panels.append(_empty_balance_polygon(closure.construction, title, tips,
                                             closure.closing[which],
                                             "kg·m" if which == "force" else "kg·m²"))
    return compose_handout(words("{name}: {what}", name=name, what=words("problem sheet")),
                           panels, sheet=sheet)


def _given_parts(ex, unit: str, metre: float) -> list[Line]:
    """Each mass as the file gives it, "?" where it is unknown, and the speed if given."""
    mm = unit_words(unit)

    def told(value, text: str) -> str:
        return "?" if value is None else text

    out = [Line(words("Given"), heading=True)]
    for p in ex.open.parts:
        said = words("mass {name}: {mass} kg at {radius}, {angle}, plane at {plane}",
                     name=p.name, mass=math_text(told(p.mass, number(p.mass or 0.0))),
                     radius=math_text(told(p.radius, number((p.radius or 0.0) / metre)))
                     + f" {mm}",
                     angle=math_text(told(p.angle, f"{number(math.degrees(p.angle or 0))}°")),
                     plane=math_text(told(p.plane, number((p.plane or 0.0) / metre)))
                     + f" {mm}")
        if ex.open.static:                  # one plane: no plane to state
            said = said.rsplit(words(", "), 1)[0]
        out.append(Line(said))
        if p.between is not None:
            lo, hi = (math.degrees(a) for a in p.between)
            out.append(Line(words("the angle of {name} between {lo} and {hi}, counter-clockwise",
                                  name=p.name, lo=math_text(f"{number(lo)}°"),
                                  hi=math_text(f"{number(hi)}°"))))
    if ex.open.speed:
        rpm = ex.speed_unit == "rpm"
        speed = ex.open.speed * 30 / math.pi if rpm else ex.open.speed
        out.append(Line(words("speed {speed}", speed=math_text(number(speed))
                              + f" {unit_words('rpm' if rpm else 'rad/s')}")))
    return out


def _asked_parts(rotor, *, engine: bool = False) -> list[Line]:
    """Each mass's unknowns, for the rotor to be in complete balance (static alone where
    its masses are in one plane; an engine's cylinders, in primary balance)."""
    out = [Line(words("Find"), heading=True),
           Line(words("for the engine in primary balance (force and couple)") if engine
                else words("for the rotor in static balance") if rotor.static
                else words("for the rotor in complete balance (force and couple)"))]
    for p in rotor.parts:
        unknown = p.unknowns()
        if unknown:
            out.append(Line(words("mass {name}: {what}", name=p.name, what=words(", ").join(
                words(_UNKNOWN.get(u, u)) for u in unknown))))
    return out


def _parts_table(ex, unit: str, metre: float) -> Figure:
    """The table the solution sets (m, r, θ, plane, m·r, m·r·l), each given cell filled and
    every unknown and product left empty."""
    from tarsim.graphics.train_table import draw_train_table

    rotor = ex.open
    length, kg = unit_words(unit), unit_words("kg")
    heads = [f"m ({kg})", f"r ({length})", "θ"] + ([] if rotor.static else [
        f"l ({length})"]) + [f"m·r ({unit_words('kg·m')})"] + ([] if rotor.static else [
            f"m·r·l ({unit_words('kg·m²')})"])

    def cell(value, text: str) -> str:
        return "" if value is None else numerals(text)

    rows = [(numerals(p.name), [cell(p.mass, number(p.mass or 0.0)),
                      cell(p.radius, number((p.radius or 0.0) / metre)),
                      cell(p.angle, f"{number(math.degrees(p.angle or 0.0))}°")]
             + ([] if rotor.static else [cell(p.plane, number((p.plane or 0.0) / metre))])
             + [""] * (1 if rotor.static else 2)) for p in rotor.parts]
    return draw_train_table(words("{name}: {what}", name=ex.name,
                                  what=words("the table to fill in")), heads, rows)


def unbalance_sheets(ex, sheet: tuple[float, float]) -> list[Figure]:
    """A rotor with no balancing plane, its out-of-balance force and couple (and the loads on
    its bearings) asked: its end view and side view as the solution draws them (every mass
    given), the statement, its table with the products empty, and an empty frame for each
    polygon at the solution's scale."""
    from tarsim.graphics.balancing.balance_figures import draw_end_view, draw_side_view

    from .balancing.rotor_unbalance import about
    from .chapters import chapter_of
    from .handout_chapters import _empty_balance_polygon, _given_rotor, _held, _rotor_table

    sol = chapter_of(ex).solve(ex)
    r, u, name = ex.rotor, sol.unbalance, sol.exercise.name
    unit, metre = ex.length_unit, LENGTH_UNITS[ex.length_unit]
    held = "N" if ex.weights else "kg"
    masses = [(m.name, m.radius, words("{name}: {mass} {kg} at {radius} {unit}, {angle}°",
                                       name=m.name, mass=numerals(number(_held(ex, m.mass))),
                                       kg=unit_words(held),
                                       radius=numerals(number(m.radius / metre)),
                                       unit=unit_words(unit),
                                       angle=numerals(number(math.degrees(m.angle)))))
              for m in r.masses]
    panels = [draw_end_view(u.construction, masses, words("{name}: space diagram", name=name),
                            unit, metre)]
    asked = [Line(words("Find"), heading=True), Line(words("the out-of-balance force"))]
    if "couple" in u.closing:
        asked.append(Line(words("the out-of-balance couple about the plane at {place}",
                                place=math_text(number(about(r) / metre))
                                + f" {unit_words(unit)}")))
    asked += [Line(words("the load on bearing {name}", name=b)) for b, _ in r.bearings]
    bearings = [Line(words("bearing {name} at {plane}", name=b, plane=math_text(
        number(x / metre)) + f" {unit_words(unit)}")) for b, x in r.bearings]
    panels.append(draw_statement(_given_rotor(ex, unit, metre) + bearings + asked))
    panels.append(_rotor_table(ex, unit, metre, reference=about(r)))
    if "couple" in u.closing:
        panels.insert(1, draw_side_view([(m.name, m.plane, "link") for m in r.masses]
                                        + [(b, x, "normal") for b, x in r.bearings],
                                        words("{name}: side view", name=name), unit, metre,
                                        found="a bearing"))
    for which in u.closing:
        panels.append(_empty_balance_polygon(
            u.construction, words("{name}: force polygon", name=name) if which == "force"
            else words("{name}: couple polygon about the plane at {place} {unit}", name=name,
                       place=numerals(number(about(r) / metre)), unit=unit_words(unit)),
            u.tips[which], u.closing[which], "kg·m" if which == "force" else "kg·m²"))
    return compose_handout(words("{name}: {what}", name=name, what=words("problem sheet")),
                           panels, sheet=sheet)

