"""The problem sheets of the chapters besides the linkages (:mod:`.handout`): a gear train
drawn with its data and its table's rows left empty; each sheet with what is asked, and no
answer.

Each maker solves the exercise as ``tarsim solve`` does, for the sheet's figures are drawn
as the solution's are (the train at its scale, the table's rows as the notes set them), but
puts on it nothing the solve found.
"""

from __future__ import annotations

from tarsim.constructions.asks import symbol
from tarsim.constructions.narration import numerals, unit_words, words
from tarsim.graphics.figure import Figure
from tarsim.graphics.handout import Line, compose_handout, draw_statement
from tarsim.graphics.paper import paper

from .handout_text import math_text, number

__all__ = ["gear_sheets"]


def _asked(asks) -> list[Line]:
    """What is asked, each quantity by its symbol as the course writes it (ω4, ω4/ω2)."""
    return [Line(words("Find"), heading=True)] + [Line(math_text(symbol(a))) for a in asks]


def gear_sheets(ex) -> list[Figure]:
    """A gear train's sheet: the train in side view as the solution draws it, the data (each
    gear's teeth and its size, the arm, the member held, the meshes, the input), what is
    asked, and the tabular method's table (or an ordinary train's row of speeds) with every
    cell left empty, each row named as the notes name it."""
    from tarsim.graphics.gears.train_schematic import draw_train_schematic
    from tarsim.graphics.train_table import draw_train_table

    from .chapters import chapter_of

    sol = chapter_of(ex).solve(ex)
    train = sol.train
    heads, rows = sol._table()
    found = sol.found.table
    scaled = (words("× {scale} {unit}: speed", scale=numerals(_fraction(found.scale)),
                    unit=unit_words(train.units.speed))
              if found is not None and train.speed_given else None)
    empty = [(words("× {scale} {unit}: speed", scale="x", unit=unit_words(train.units.speed))
              if name == scaled else name, [""] * len(heads)) for name, _ in rows]
    table = draw_train_table(words("{name}: {what}", name=train.name,
                                   what=words("the table to fill in")), heads, empty,
                             ruled=(2, 3) if found is not None else ())
    drawing = draw_train_schematic(train, words("{name}: {what}", name=train.name,
                                                what=words("the train")))
    statement = draw_statement(_given_train(train) + _asked(ex.asks))
    sheet = paper("A4")
    return compose_handout(words("{name}: {what}", name=train.name,
                                 what=words("problem sheet")),
                           [drawing, statement, table], sheet=(sheet.width, sheet.height))


def _fraction(x) -> str:
    from tarsim.constructions.gears.tabular import fraction_text

    return fraction_text(x)


def _given_train(train) -> list[Line]:
    """A train's data as its file gives them: the teeth found by the solve are left out."""
    out = [Line(words("Given"), heading=True)]
    implied = set(train.implied_teeth or ())
    for g in train.gears:
        said = words("gear {gear}", gear=numerals(str(g.number)))
        if g.name:
            said += f" ({words(g.name)})"
        if g.number not in implied and g.teeth:
            said += ": " + math_text(f"N{g.number} = {g.teeth}")
        if g.module:
            said += words(", ") + math_text(f"m = {number(g.module * 1e3)}") + " mm"
        if g.carrier:
            said += words(", ") + words("on arm {arm}", arm=numerals(str(g.carrier)))
        out.append(Line(said))
    for shaft in train.shafts:
        out.append(Line(words("gears {gears} on one shaft", gears=words(" and ").join(
            numerals(str(n)) for n in shaft))))
    if train.arm is not None:
        out.append(Line(words("arm {arm}", arm=numerals(str(train.arm)))
                        + (f" ({words(train.arm_name)})" if train.arm_name else "")))
    if train.fixed is not None:
        out.append(Line(words("member {member} fixed", member=numerals(str(train.fixed)))))
    meshes = words(", ").join(math_text(f"{m.a}–{m.b}")
                              + (f" ({words('internal')})" if m.internal else "")
                              for m in train.meshes)
    out.append(Line(words("meshes: {meshes}", meshes=meshes)))
    if train.speed_given and train.input_speed is not None:
        sense = words("ccw" if train.input_speed > 0 else "cw")
        out.append(Line(words("member {member} turns at {speed}", member=numerals(
            str(train.input_member)), speed=math_text(number(abs(float(train.input_speed))))
            + f" {unit_words(train.units.speed)} {sense}")))
    return out
