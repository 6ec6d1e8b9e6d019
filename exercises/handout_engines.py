"""An engine's problem sheet (:mod:`.handout`): its cylinders' data and what is asked; for an
in-line engine the end view of its cranks as the solution draws it beside its polygons
(where the file gives the cranks' angles), the side view of its cylinders' planes and an
empty frame for each polygon at the solution's scale; for a single-cylinder, V or radial
engine the cylinders' lines and the crank at the angle given. No answer is on it.
"""

from __future__ import annotations

import math

from tarsim.constructions.narration import numerals, unit_words, words
from tarsim.constructions.units import LENGTH_UNITS
from tarsim.graphics.figure import Figure
from tarsim.graphics.handout import Line, compose_handout, draw_statement

from .handout_text import math_text, number

__all__ = ["engine_sheets"]

_ASKED = (
    (("primary_force",), "the unbalanced primary force"),
    (("primary_couple",), "the unbalanced primary couple"),
    (("secondary_force",), "the unbalanced secondary force"),
    (("secondary_couple",), "the unbalanced secondary couple"),
    (("primary_force_at", "primary_couple_at", "secondary_force_at", "secondary_couple_at"),
     "the crank angle at which each unbalanced one is greatest"),
    (("primary_resultant", "primary_max", "primary_min"),
     "the resultant primary force, its greatest and least"),
    (("secondary_resultant", "secondary_min", "secondary_max_at", "secondary_min_at"),
     "the resultant secondary force, its greatest and least, and where"),
    (("unbalanced_along", "unbalanced_across", "unbalanced_resultant"),
     "the unbalanced force along and across the line of stroke, and their resultant"),
    (("secondary_max",), "the greatest secondary force"),
    (("unbalanced_max", "unbalanced_max_at"),
     "the greatest unbalanced force, and where"),
    (("balance_mr", "balance_mass", "balance_radius"), "the balance mass"),
)
"""How the sheet asks an engine's results (by their keys in results.json), several keys
one line, each key by the first line that holds it."""

_ALSO = {"secondary_resultant": {"secondary_max"}}
"""What a line asks besides its own keys: a V's or a radial's resultant secondary force
with its greatest (a single cylinder's greatest is asked alone)."""


def engine_sheets(ex, sheet: tuple[float, float]) -> list[Figure]:
    """An engine's sheet: the crank arrangement, the data, what is asked and the polygons'
    empty frames (an in-line engine's)."""
    from .chapters import chapter_of

    sol = chapter_of(ex).solve(ex)
    e, name = ex.engine, ex.name
    statement = draw_statement(_given_engine(ex) + _asked_engine(sol))
    if e.radial or e.vee or len(e.cranks) == 1:
        panels = [_layout(ex), statement]
    else:
        panels = _in_line(ex, sol)
        panels.insert(1 if len(panels) > 1 else 0, statement)
    return compose_handout(words("{name}: {what}", name=name, what=words("problem sheet")),
                           panels, sheet=sheet)


def _layout(ex) -> Figure:
    """A single-cylinder, V or radial engine's lines of stroke and its crank."""
    from tarsim.graphics.handout_engine import draw_engine_layout

    e = ex.engine
    if e.radial:
        from tarsim.constructions.balancing.radial import radial_lines_at

        lines = [(str(i + 1), a) for i, a in enumerate(radial_lines_at(e))]
        reference = "cylinder 1's line"
    elif e.vee:
        lines = [("1", e.vee / 2), ("2", -e.vee / 2)]
        reference = "the centre line"
    else:
        lines, reference = [("1", 0.0)], "the line of stroke"
    return draw_engine_layout(words("{name}: {what}", name=ex.name,
                                    what=words("the cylinders and the crank")),
                              lines, e.at if e.at_given else None, reference=reference)


def _in_line(ex, sol) -> list[Figure]:
    """An in-line engine's side view of its cylinders' planes and an empty frame for each
    polygon, the end view of the cranks beside the first where the file gives their
    angles (a firing order's are found)."""
    from tarsim.constructions.balancing.engine import engine_kinds
    from tarsim.graphics.balancing.balance_figures import draw_side_view
    from tarsim.graphics.balancing.crank_view import CrankView

    from .handout_chapters import _empty_balance_polygon

    e, p = ex.engine, sol.engine_polygons
    unit, metre = ex.length_unit, LENGTH_UNITS[ex.length_unit]
    out = []
    if len(set(e.planes)) > 1:
        planes = [(words("cyl. {number}", number=numerals(str(i + 1))), x, "link")
                  for i, x in enumerate(e.planes)]
        out.append(draw_side_view(planes, words("{name}: side view", name=ex.name), unit,
                                  metre))
    cranks = None if e.firing_order else CrankView(
        words("end view of the cranks, at θᵢ"),
        tuple((str(i + 1), a) for i, a in enumerate(e.cranks)))
    per = e.speed ** 2 if e.speed is not None else 1.0
    for kind in engine_kinds(e):
        couple = kind.endswith("couple")
        unit_of = (("N·m" if couple else "N") if e.speed is not None
                   else ("kg·m²" if couple else "kg·m"))
        out.append(_empty_balance_polygon(
            p.construction, f"{ex.name}: {words(kind)}", p.tips[kind], p.closing[kind],
            unit_of, per=per, cranks=cranks if kind == "primary force" else None))
    return out


def _given_engine(ex) -> list[Line]:
    """The engine as its file gives it: speed, crank (and stroke), rod, masses, balance,
    the cylinders' angles and planes (or the firing order), a V's or a radial's lines,
    the crank angle asked at."""
    from .table_file import SPEEDS

    e = ex.engine
    metre, mm = LENGTH_UNITS[ex.length_unit], unit_words(ex.length_unit)

    def length(symbol: str, x: float) -> str:
        return math_text(f"{symbol} = {number(x / metre)}") + f" {mm}"

    out = [Line(words("Given"), heading=True)]
    if e.speed is not None:
        out.append(Line(words("speed {speed}", speed=math_text(number(
            e.speed / SPEEDS[ex.speed_unit])) + f" {unit_words(ex.speed_unit)}")))
    out.append(Line(words("crank radius {r} (stroke {s})", r=length("r", e.crank),
                          s=math_text(number(2 * e.crank / metre)) + f" {mm}")))
    if e.rod is not None:
        out.append(Line(words("connecting rod {l}", l=length("l", e.rod))))
    if e.masses:
        out.append(Line(words("reciprocating masses {masses} kg", masses=words(", ").join(
            math_text(number(m)) for m in e.masses))))
    else:
        out.append(Line(words("reciprocating mass {m} kg a cylinder",
                              m=math_text(f"m = {number(e.reciprocating)}"))))
    if e.revolving:
        out.append(Line(words("revolving mass at the crank radius {m} kg",
                              m=math_text(number(e.revolving)))))
    if e.balanced:
        out.append(Line(words("{c} of the reciprocating mass balanced",
                              c=math_text(f"c = {number(e.balanced)}"))))
    if e.balance_radius is not None:
        out.append(Line(words("the balance mass at radius {b}",
                              b=length("b", e.balance_radius))))
    if e.balance_mass is not None:
        out.append(Line(words("the balance mass {m} kg", m=math_text(number(e.balance_mass)))))
    if e.radial:
        out.append(Line(words("{n} cylinders, their lines evenly round the crank shaft",
                              n=numerals(str(e.radial)))))
    if e.vee:
        out.append(Line(words("two cylinders, their lines {angle} apart", angle=math_text(
            f"{number(math.degrees(e.vee))}°"))))
    if not (e.radial or e.vee) and len(e.cranks) > 1:
        for i, (a, x) in enumerate(zip(e.cranks, e.planes)):
            plane = math_text(number(x / metre)) + f" {mm}"
            out.append(Line(words("cylinder {i}: plane at {plane}", i=numerals(str(i + 1)),
                                  plane=plane) if e.firing_order else
                            words("cylinder {i}: crank at {angle}, plane at {plane}",
                                  i=numerals(str(i + 1)), plane=plane,
                                  angle=math_text(f"{number(math.degrees(a))}°"))))
    if e.firing_order:
        out.append(Line(words("a {n}-stroke engine, firing order {order}",
                              n=numerals(str(e.strokes or 4)),
                              # listed as words are, read in the language's own order
                              order=words(", ").join(numerals(str(k))
                                                     for k in e.firing_order))))
    if e.at_given:
        out.append(Line(words("the crank at {theta}", theta=math_text(
            f"θ = {number(math.degrees(e.at))}°"))))
    return out


def _asked_engine(sol) -> list[Line]:
    """What the solve finds, each group of results asked once in the course's words."""
    keys = set(sol.results.get("quantities", {}))
    out = [Line(words("Find"), heading=True)]
    covered: set[str] = set()
    for group, said in _ASKED:            # a key asked once, by the first line that holds it
        if keys.intersection(group) - covered:
            out.append(Line(words(said)))
            covered |= set(group) | _ALSO.get(group[0], set())
    e = sol.exercise.engine
    if e.firing_order:
        out.insert(1, Line(words("the cranks' angles from the firing order")))
    if not (e.radial or e.vee) and len(e.cranks) > 1:
        out.append(Line(words("couples about the central plane")))
    return out
