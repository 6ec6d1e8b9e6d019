"""The problem sheets of the chapters besides the linkages (:mod:`.handout`): a gear train
drawn with its data and its table's rows left empty; a rotor's masses in its table, the
products left empty, and an empty frame for each polygon; each sheet with what is asked,
and no answer.

Each maker solves the exercise as ``tarsim solve`` does, for the sheet's figures are drawn
as the solution's are (the train at its scale, the table's rows as the notes set them), but
puts on it nothing the solve found.
"""

from __future__ import annotations

import math

from tarsim.constructions.asks import symbol
from tarsim.constructions.units import LENGTH_UNITS
from tarsim.constructions.narration import numerals, unit_words, words
from tarsim.graphics.figure import Figure
from tarsim.graphics.handout import Line, compose_handout, draw_statement

from .handout_text import math_text, number

__all__ = ["gear_sheets", "rotor_sheets", "cam_sheets"]


def _asked(asks) -> list[Line]:
    """What is asked, each quantity by its symbol as the course writes it (ω4, ω4/ω2)."""
    return [Line(words("Find"), heading=True)] + [Line(math_text(symbol(a))) for a in asks]


def gear_sheets(ex, sheet: tuple[float, float]) -> list[Figure]:
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
    return compose_handout(words("{name}: {what}", name=train.name,
                                 what=words("problem sheet")),
                           [drawing, statement, table], sheet=sheet)


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
        if g.circular_pitch:             # its module follows from it: not said
            said += words(", ") + math_text(f"p = {number(g.circular_pitch * 1e3)}") + " mm"
        elif g.module:
            said += words(", ") + math_text(f"m = {number(g.module * 1e3)}") + " mm"
        if g.diameter:
            said += words(", ") + math_text(f"d = {number(g.diameter * 1e3)}") + " mm"
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
    for m in train.meshes:
        if m.distance or m.about:
            out.append(Line(words("gears {a} and {b} {d} apart", a=numerals(str(m.a)),
                                  b=numerals(str(m.b)), d=math_text(number(
                                      float(m.distance or m.about) * 1e3)) + " mm")
                            + (" " + words("(about)") if m.about else "")))
    turning = [(train.input_member, train.input_speed)] if (
        train.speed_given and train.input_speed is not None) else []
    for member, speed in turning + ([train.second] if train.second else []):
        sense = words("ccw" if speed > 0 else "cw")
        out.append(Line(words("member {member} turns at {speed}", member=numerals(
            str(member)), speed=math_text(number(abs(float(speed))))
            + f" {unit_words(train.units.speed)} {sense}")))
    if train.input_power:
        out.append(Line(math_text(f"P = {number(train.input_power / 1e3)}") + " kW"))
    if train.input_torque:
        out.append(Line(math_text(f"T = {number(float(train.input_torque))}") + " N·m"))
    if train.efficiency != 1:
        out.append(Line(math_text(f"η = {number(float(train.efficiency))}")))
    return out


def rotor_sheets(ex, sheet: tuple[float, float]) -> list[Figure]:
    """A rotor's sheet: its side view (two planes), the data and what is asked, its table with
    the masses given and every product and balancing mass left empty, and an empty frame
    for the force polygon (and the couple polygon) at the scale the solution draws it at.

    A rotor with unknowns besides its balancing masses has its own
    (:func:`~.handout_rotors.open_rotor_sheets`), as an engine has
    (:func:`~.handout_engines.engine_sheets`).
    """
    from tarsim.graphics.balancing.balance_figures import draw_side_view

    from .chapters import chapter_of

    r = ex.rotor
    if ex.open is not None:
        from .handout_rotors import open_rotor_sheets

        return open_rotor_sheets(ex, sheet)
    if r is None:
        from .handout_engines import engine_sheets

        return engine_sheets(ex, sheet)
    if not r.planes:                                 # its out-of-balance asked
        from .handout_rotors import unbalance_sheets

        return unbalance_sheets(ex, sheet)
    s = chapter_of(ex).solve(ex)
    unit, metre = ex.length_unit, LENGTH_UNITS[ex.length_unit]
    name = s.exercise.name
    panels = []
    two = len(r.planes) == 2
    if two or len({m.plane for m in r.masses}) > 1:
        planes = [(m.name, m.plane, "link") for m in r.masses]
        planes += [(p.name, p.position, "normal") for p in r.planes]
        panels.append(draw_side_view(planes, words("{name}: side view", name=name), unit, metre))
    panels.append(draw_statement(_given_rotor(ex, unit, metre) + _asked_rotor(r, ex.weights)))
    panels.append(_rotor_table(ex, unit, metre))
    b = s.balance
    polygons = []
    if two and any(m.plane != r.planes[0].position for m in r.masses):
        couple = words("{name}: couple polygon (reference plane {plane})", name=name,
                       plane=r.planes[0].name)
        polygons.append((couple, b.couple, b.closing[f"{r.planes[1].name}·l"], "kg·m²"))
    polygons.append((words("{name}: force polygon", name=name), b.force,
                     b.closing[r.planes[0].name], "kg·m"))
    panels += [_empty_balance_polygon(b.construction, *p) for p in polygons]
    return compose_handout(words("{name}: {what}", name=name, what=words("problem sheet")),
                           panels, sheet=sheet)


def _given_rotor(ex, unit: str, metre: float) -> list[Line]:
    """The masses as the file gives them, the balancing planes, the speed."""
    r = ex.rotor
    out = [Line(words("Given"), heading=True)]
    mm = unit_words(unit)
    said = ("weight {name}: {mass} N at {radius}, {angle}, plane at {plane}" if ex.weights
            else "mass {name}: {mass} kg at {radius}, {angle}, plane at {plane}")
    for m in r.masses:
        out.append(Line(words(said, name=m.name, mass=math_text(number(_held(ex, m.mass))),
                              radius=math_text(number(m.radius / metre)) + f" {mm}",
                              angle=math_text(f"{number(math.degrees(m.angle))}°"),
                              plane=math_text(number(m.plane / metre)) + f" {mm}")))
    for p in r.planes:
        held = (words("its weight at {radius}" if ex.weights else "its mass at {radius}",
                      radius=math_text(number(p.radius / metre)) + f" {mm}")
                if p.radius is not None else
                words("its weight {mass} N" if ex.weights else "its mass {mass} kg",
                      mass=math_text(number(_held(ex, p.mass)))))
        out.append(Line(words("balancing plane {name} at {plane}, {held}", name=p.name,
                              plane=math_text(number(p.position / metre)) + f" {mm}",
                              held=held)))
    if r.speed:
        rpm = ex.speed_unit == "rpm"
        speed = r.speed * 30 / math.pi if rpm else r.speed
        out.append(Line(words("speed {speed}", speed=math_text(number(speed))
                              + f" {unit_words('rpm' if rpm else 'rad/s')}")))
    return out


def _held(ex, mass: float) -> float:
    """A mass as its file gives it: in kg, or its weight in N where the file gives weights."""
    from .balancing.rotor_weights import GRAVITY

    return mass * GRAVITY if ex.weights else mass


def _asked_rotor(r, weights: bool = False) -> list[Line]:
    """The balancing masses asked, one a plane: its mass (or its radius, where the file
    gives the mass) and its angle; a balance weight where the file gives weights."""
    out = [Line(words("Find"), heading=True)]
    for p in r.planes:
        out.append(Line(words("in plane {name}: the balance weight and its angle", name=p.name)
                        if p.radius is not None and weights else
                        words("in plane {name}: the balancing mass and its angle", name=p.name)
                        if p.radius is not None else
                        words("in plane {name}: the given mass's radius and its angle",
                              name=p.name)))
    return out


def _rotor_table(ex, unit: str, metre: float, reference: float | None = None) -> Figure:
    """The rotor's table as the solution sets it (m, r, θ, l, m·r, m·r·l), the given cells
    filled and every product, and what the balancing planes' masses are to be, empty; l
    from the first balancing plane, or from ``reference`` (m) where there is none."""
    from tarsim.graphics.train_table import draw_train_table

    r = ex.rotor
    ref = r.planes[0].position if r.planes else reference
    two = len(r.planes) == 2 or (not r.planes and len({m.plane for m in r.masses}) > 1)
    flat = not two and len({m.plane for m in r.masses} | {ref}) == 1
    length, kg = unit_words(unit), unit_words("kg")
    held, mr, mrl = (("W (N)", f"W·r ({unit_words('N·m')})", f"W·r·l ({unit_words('N·m²')})")
                  if ex.weights else (f"m ({kg})", f"m·r ({unit_words('kg·m')})",
                                      f"m·r·l ({unit_words('kg·m²')})"))
    heads = [held, f"r ({length})", "θ"] + ([] if flat else [f"l ({length})"]) + [mr] + (
        [mrl] if two else [])
    empty = [""] * (2 if two else 1)
    rows = [(m.name, [numerals(number(_held(ex, m.mass))), numerals(number(m.radius / metre)),
                      numerals(f"{number(math.degrees(m.angle))}°")]
             + ([] if flat else [numerals(number((m.plane - ref) / metre))]) + empty)
            for m in r.masses]
    rows += [(p.name, [numerals(number(_held(ex, p.mass))) if p.mass is not None else "",
                       numerals(number(p.radius / metre)) if p.radius is not None else "", ""]
              + ([] if flat else [numerals(number((p.position - ref) / metre))]) + empty)
             for p in r.planes]
    return draw_train_table(words("{name}: {what}", name=ex.name,
                                  what=words("the table to fill in")), heads, rows,
                            ruled=[len(r.masses)])


def _empty_balance_polygon(c, title: str, tips, closing, unit: str, *, per: float = 1.0,
                           cranks=None) -> Figure:
    """An empty frame for a rotor's polygon, at the scale the solution draws it at (the
    1-2-5 scale that fits it in its room), its pole marked where its first side starts; an
    engine's drawn in N (N·m), ``per`` (ω²) of them to the construction's kg·m, with the
    end view of its ``cranks`` beside it."""
    from tarsim.graphics.balancing.balance_figures import _ROOM
    from tarsim.graphics.handout import draw_empty_polygon
    from tarsim.graphics.scales import nice_per_cm

    start = c[closing].inputs[1]
    points = [c.output(start).xy] + [c.output(ref).xy for _, ref in tips]
    xs, ys = [x for x, _ in points], [y for _, y in points]
    per_cm = nice_per_cm(max(max(xs) - min(xs), max(ys) - min(ys), 1e-12) * per, _ROOM)
    k = 10.0 * per / per_cm                           # paper mm a unit of the polygon
    o = points[0]
    across, up = [(x - o[0]) * k for x in xs], [(o[1] - y) * k for y in ys]
    reach = (max(0.0, -min(across)), max(0.0, -min(up)), max(0.0, max(across)),
             max(0.0, max(up)))
    return draw_empty_polygon(title, reach=reach, per_cm=per_cm, unit=unit, scale_name="Scale",
                              pole=("o", ""), cranks=cranks)


def cam_sheets(ex, sheet: tuple[float, float]) -> list[Figure]:
    """A cam's sheet: the base circle with the follower at the start of the turn, the data
    (the base circle, the follower, the speed, each segment as given), what is asked, and the
    displacement diagram's axes, empty, at the scales the solution draws it at."""
    from tarsim.graphics.handout_cam import draw_base_circle, draw_empty_displacement

    from .chapters import chapter_of

    if getattr(ex, "follower", None) is None:        # a cam given by its arcs
        from .handout_arc_cam import arc_cam_sheets

        return arc_cam_sheets(ex, sheet)
    s = chapter_of(ex).solve(ex)
    f, unit, metre = ex.follower, ex.length_unit, ex.metre
    top = max(s.curves[1]) if s.curves[1] else max(g.lift for g in ex.segments)
    # A disc turning off its centre is given as the disc: its motion and lift are answers.
    spans = [] if ex.disc else [(words(g.kind), g.angle) for g in ex.segments]
    axes = draw_empty_displacement(words("{name}: {what}", name=ex.name,
                                         what=words("the displacement diagram to draw")),
                                   lift=top, segments=spans, per_rad=s.diagram.per_rad,
                                   unit=unit, metre=metre, lift_given=not ex.disc)
    circle = draw_base_circle(words("{name}: {what}", name=ex.name, what=_cam_term("base circle")
                                    if not ex.disc else words("the disc")),
                              base=ex.base_radius, offset=f.offset, roller=f.radius,
                              flat=f.kind == "flat-faced",
                              pivot=f.pivot if f.oscillating else None, arm=f.arm,
                              disc=tuple(v * metre for v in ex.disc) if ex.disc else None,
                              unit=unit, metre=metre)
    statement = draw_statement(_given_cam(ex) + _asked_cam(ex))
    return compose_handout(words("{name}: {what}", name=ex.name, what=words("problem sheet")),
                           [circle, statement, axes], sheet=sheet)


def _given_cam(ex) -> list[Line]:
    """The cam as its file gives it: base circle, follower, speed, and each segment."""
    f, mm = ex.follower, unit_words(ex.length_unit)

    def length(x: float) -> str:
        return math_text(number(x / ex.metre)) + f" {mm}"

    out = [Line(words("Given"), heading=True),
           Line(words("a disc of radius {r} turning {e} off its centre",
                      r=length(ex.disc[0] * ex.metre), e=length(ex.disc[1] * ex.metre))
                if ex.disc else words("base circle radius {r}", r=length(ex.base_radius)))]
    said = words("follower: {kind}", kind=words(f.kind))
    if f.radius:
        said += words(", ") + words("roller radius {r}", r=length(f.radius))
    if f.offset:
        said += words(", ") + words("offset {e}", e=length(f.offset))
    if f.oscillating:
        said += words(", ") + words("arm {arm}, pivot at {xy}", arm=length(f.arm), xy=math_text(
            f"({number(f.pivot[0] / ex.metre)}, {number(f.pivot[1] / ex.metre)})") + f" {mm}")
    out.append(Line(said))
    rpm = ex.speed_unit == "rpm"
    speed = abs(ex.omega) * 30 / math.pi if rpm else abs(ex.omega)
    out.append(Line(words("the cam turns at {speed}", speed=math_text(number(speed))
                          + f" {unit_words('rpm' if rpm else 'rad/s')} "
                          + words("cw" if ex.omega < 0 else "ccw"))))
    for g in () if ex.disc else ex.segments:
        said = f"{words(g.kind)} {math_text(number(math.degrees(g.angle)) + '°')}"
        if g.kind != "dwell":        # an arm's lift is the swing its file gives, in degrees
            lift = (math_text(f"{number(math.degrees(g.lift / f.arm))}°") if f.oscillating
                    else length(g.lift))
            said += words(", ") + lift + words(", ") + words(g.law)
            if g.law == "modified uniform velocity":
                said += words(", ") + words("blended over {blend} of it at each end",
                                            blend=math_text(number(g.blend)))
            said += words(", ") + words("in {n} divisions", n=numerals(str(g.divisions)))
        out.append(Line(said))
    return out


def _asked_cam(ex) -> list[Line]:
    out = [Line(words("Find"), heading=True),
           Line(words("the displacement diagram, by construction")),
           Line(words("the cam's profile, by inversion")),
           Line(words("the follower's greatest velocity and acceleration"))]
    out += [Line(words("the follower's lift at {theta}", theta=math_text(f"θ = {number(d)}°")))
            for d in ex.at]
    return out


def _cam_term(text: str) -> str:
    """A term as a cam's figures say it where a gear's say it otherwise (a base circle)."""
    said = words(f"cam: {text}")
    return words(text) if said == f"cam: {text}" else said
