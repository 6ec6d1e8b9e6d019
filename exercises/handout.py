"""The problem sheet of an exercise (``tarsim handout``): the mechanism drawn to scale with
its data, what is asked, and an empty frame at its scale for each polygon to be drawn.

The exercise is solved first, as ``tarsim solve`` solves it, for the sheet must hold what
the student is to draw (the frames are sized to the polygons, at the scales the solution
draws them at, so that a drawing handed in can be graded against it); but nothing the
solve found is put on the sheet: no centre, no vector, no number that is a result. A
position given by a time is stated by its time alone, for the crank's angle there is the
first thing the student works out.

Each chapter that has a sheet registers its maker in :data:`HANDOUTS` by its key: the
linkages (the course's main exercises, :func:`_linkage_sheets`), the gear trains, cams
and rotors (:mod:`.handout_chapters`), and the flywheels and connecting rods
(:mod:`.handout_flywheel`); a chapter with none is refused, naming those that have one.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

from tarsim.constructions import asks as A
from tarsim.constructions.errors import InputError
from tarsim.constructions.narration import numerals, unit_words, words
from tarsim.constructions.record import Panel, Slice
from tarsim.graphics.figure import Figure, stack_pages
from tarsim.graphics.handout import Line, compose_handout, draw_empty_polygon, draw_statement
from tarsim.graphics.paper import paper, room
from tarsim.graphics.typeset import typeset

from .handout_chapters import cam_sheets, gear_sheets, rotor_sheets
from .handout_flywheel import flywheel_sheets
from .handout_loads import force_frames, force_words, given_loads
from .handout_text import math_text, number

__all__ = ["Handout", "handout", "HANDOUTS"]


@dataclass
class Handout:
    """An exercise's problem sheet: its sheets, in order, and the files they make."""

    exercise_id: str
    sheets: list[Figure]

    @property
    def figure(self) -> Figure:
        """The sheets as one figure (one under another in its SVG, a page each in a PDF)."""
        return self.sheets[0] if len(self.sheets) == 1 else stack_pages(self.sheets)

    def files(self, *, pdf: bool) -> dict[str, str | bytes]:
        """``handout.svg`` and, with ``pdf``, ``handout.pdf`` (a page a sheet)."""
        from tarsim.graphics.export import figure_pdf
        from tarsim.graphics.svg import to_svg

        out: dict[str, str | bytes] = {"handout.svg": to_svg(self.figure)}
        if pdf:
            out["handout.pdf"] = figure_pdf(self.sheets)
        return out


def handout(exercise, chapter, *, paper_name: str = "A4") -> Handout:
    """The problem sheet of ``exercise``, a ``chapter``'s, in the language being spoken, on
    sheets of ``paper_name`` (A4, A3, letter).

    Raises
    ------
    InputError
        If the chapter has no problem sheet yet, naming those that have.
    TarsimError
        If the exercise cannot be solved (the sheet's frames are sized by its solution).
    """
    from .chapters import chapters

    make = HANDOUTS.get(chapter.key)
    if make is None:
        kinds = [c.kind for c in chapters() if c.key in HANDOUTS]
        kinds = " or ".join([", ".join(kinds[:-1]), kinds[-1]] if len(kinds) > 1 else kinds)
        raise InputError(f"{exercise.id} is {chapter.kind}, which has no problem sheet yet: "
                         f"tarsim handout writes one for {kinds}")
    sheet = paper(paper_name)
    return Handout(exercise.id, make(exercise, (sheet.width, sheet.height)))


# ----- linkages ------------------------------------------------------------------------------
_POLYGONS = {Panel.VELOCITY: ("Velocity polygon", "Velocity scale", "v", "/s", "velocity"),
             Panel.ACCELERATION: ("Acceleration polygon", "Acceleration scale", "a", "/s²",
                                  "acceleration")}
"""Each polygon's heading, scale name, pole subscript, time unit and scale's field."""

_ASKED: dict[type, str] = {
    A.Centre: "the instant centre",
    A.AngularVelocity: "the angular velocity of link {link}",
    A.Velocity: "the velocity of {point}",
    A.Relative: "the relative velocity",
    A.AngularAcceleration: "the angular acceleration of link {link}",
    A.Acceleration: "the acceleration of {point}",
    A.AccelerationPart: "a component of the acceleration of {point}",
    A.Coriolis: "the Coriolis component at {point}",
}
"""How the sheet says each kind of quantity after its symbol, in the course's words; any
other is asked by its symbol alone."""

_WHOLE: dict[type, str] = {
    A.Mobility: "the degrees of freedom (Grübler)",
    A.TimeRatio: "the time ratio of the quick return",
    A.Stroke: "the stroke",
}
"""How the sheet asks what is found of the mechanism as a whole, which it names by words."""


def _linkage_sheets(ex, upright: tuple[float, float]) -> list[Figure]:
    """The mechanism at its [input] position, the statement, then each position's empty
    polygons, on as few sheets of ``upright`` (mm) as hold them."""
    from tarsim.constructions.linkages.assembly import assemble
    from tarsim.constructions.scales import space_per_cm
    from tarsim.graphics.fitting import fit
    from tarsim.graphics.linkages.worked_page import holds_panel
    from tarsim.graphics.linkages.scene import draw_scene

    from .linkages.solution_files import solve_worked

    worked = solve_worked(ex)            # read for the frames' sizes and scales, never shown
    m, sheet = ex.mechanism, paper(ex.paper)
    # An input given by another member's motion is drawn at ω = 1 by the solution: the sheet
    # draws no ω it was not given (the statement gives the motion as the file does).
    given = Slice(assemble(replace(m, drive=replace(m.drive, omega=0.0)) if m.given else m), ())
    first = worked.positions[0].work if worked.positions else worked.overall.work
    # The solution's space scale, so that a drawing on the sheet lies over its figures.
    space = (first.scales.space if first is not None
             else space_per_cm(given.construction, room(sheet)))
    velocity = next((s for sol in worked.positions for a in sol.answers for s in a.figures
                     if s.velocity_scale), None)
    mechanism = fit(lambda per_cm: draw_scene(
        given, title=words("{name}: {what}", name=m.name, what=words("space diagram")),
        per_cm=per_cm, velocity_scale=velocity.velocity_scale if velocity else None,
        velocity_stated=velocity.velocity_stated if velocity else None),
        space, lambda fig: holds_panel(upright, fig), fixed=bool(m.scale))
    frames = [frame for sol in worked.positions for frame in _frames(sol, sheet)]
    statement = draw_statement(_given(ex) + _asked(ex, worked))
    return compose_handout(words("{name}: {what}", name=m.name, what=words("problem sheet")),
                           [mechanism, statement, *frames], sheet=upright)


def _given(ex) -> list[Line]:
    """The data as the file gives them: the frame's points, every link's lengths, the frame's
    guides, the input's position and motion."""
    m = ex.mechanism
    u, mm = m.units, unit_words(m.units.length)
    out = [Line(words("Given"), heading=True)]
    frame = next(k for k in m.links if k.number == 1)
    if frame.names:
        points = words(", ").join(math_text(f"{p} {_xy(frame.local(p), m)}") for p in frame.names)
        out.append(Line(words("fixed points: {points}", points=points) + f" {mm}"))
    for k in sorted(m.links, key=lambda k: k.number):
        if k.number == 1 or len(k.names) < 2:
            continue
        spans = words(", ").join(math_text(f"{p}{q} = {number(k.span(p, q) / u.metres)}")
                                 + f" {mm}" for i, p in enumerate(k.names)
                                 for q in k.names[i + 1:])
        out.append(Line(words("link {link}: {spans}", link=numerals(str(k.number)),
                              spans=spans)))
    for s in m.slides:
        if s.guide_link == 1 and s.contact is None:
            angle = math.degrees(math.atan2(s.direction[1], s.direction[0]))
            out.append(Line(words("{point} slides on the line through {through} at {angle}",
                                  point=s.point, through=f"{math_text(_xy(s.through, m))} {mm}",
                                  angle=math_text(f"{number(angle)}°"))))
    d = m.drive
    if m.given is not None:
        out.append(Line(math_text(_input_words(replace(m, drive=replace(d, omega=0.0))))))
        out.append(_given_rate(m))
        return out + given_loads(ex.loads)
    out.append(Line(math_text(_input_words(m))))
    alpha = f"α{d.link}"
    out.append(Line(math_text(f"{alpha} = {number(d.alpha)} rad/s²") if d.alpha_given
                    else words("{alpha} not given: taken as 0", alpha=math_text(alpha))))
    return out + given_loads(ex.loads)


def _given_rate(m) -> Line:
    """The input's motion as the file gives it, by another member's: "V_A = 1000 mm/s cw,
    its rate of change 5000 mm/s² cw" (a point on a guide: signed along the guide)."""
    r, u = m.given, m.units
    turning = r.kind != "speed"          # a turning member's sense; a guide's runs along it
    if r.kind == "omega":
        symbol, value, per, rate_per = f"ω{r.target}", r.value, "rad/s", "rad/s²"
        rate = r.second
    else:
        symbol, value = f"V_{r.target}", r.value / u.metres
        per, rate_per = unit_words(u.length + "/s"), unit_words(u.length + "/s²")
        rate = r.second / u.metres

    def said(x: float, unit: str) -> str:
        if not turning:
            return math_text(number(x)) + f" {unit}"
        return math_text(number(abs(x))) + f" {unit} " + words("ccw" if x > 0 else "cw")

    text = " = " + said(value, per)
    if r.second_given:
        text += words(", ") + words("its rate of change {rate}", rate=said(rate, rate_per))
    return Line(text, symbol=typeset(symbol))


def _asked(ex, worked) -> list[Line]:
    """What is asked: of the mechanism as a whole, then at the positions (each is asked the
    same), each quantity by its symbol and in the course's words, with the methods it is
    found by when the file names more than one."""
    out = [Line(words("Find"), heading=True)]
    out += [Line(words(_WHOLE.get(type(a), a.symbol))) for a in ex.asks
            if a.scope == "mechanism"]
    if not worked.positions:
        return out
    wheres = [sol.position.label.split(" (")[0] for sol in worked.positions if sol.position]
    if wheres:
        both = words(" and ").join(math_text(w) for w in wheres)
        out.append(Line(words("at {where}:", where=both), heading=True))
    sol = worked.positions[0]
    # The centres by their names: their count may be asked (n_centres), so it is not said.
    centres = [a for a in sol.exercise.asks if isinstance(a, A.Centre)]
    if "centres" in ex.find:
        out.append(Line(words("every instant centre")))
    elif centres:
        out.append(Line(words("the instant centres {names}", names=words(", ").join(
            math_text(a.name) for a in centres))))
    out += [_ask_line(a, _methods(sol, a)) for a in sol.exercise.asks
            if a.scope == "position" and not isinstance(a, A.Centre)]
    return out


def _ask_line(ask, methods: list[str]) -> Line:
    """One asked quantity: its symbol (a true subscript), what it is, and the methods it is
    found by when more than one is asked."""
    force = force_words(ask)
    if force is not None and not force[1]:          # an effort, asked by its words alone
        return Line(force[0])
    template = _ASKED.get(type(ask))
    fields = {k: numerals(str(getattr(ask, k))) for k in ("link", "point") if hasattr(ask, k)}
    said = (words(", ") + (force[0] if force else words(template, **fields))
            if force or template else "")
    if len(methods) > 1:
        said += f" ({words('by {methods}', methods=words(', ').join(methods))})"
    return Line(said, symbol=typeset(ask.symbol))


def _methods(sol, ask) -> list[str]:
    """The methods a quantity is found by at a position, as the course names them."""
    from tarsim.constructions.linkages.velocity_drawing import method_words

    q = sol.quantities.get(ask.name)
    if q is None:
        return []
    return [words(method_words(qq.method)) for qq in (q, *q.alternatives.values())]


def _frames(sol, sheet) -> list[Figure]:
    """An empty frame for each polygon the position draws, at the scale its worked page
    states (the exercise's, or the one that fits the polygon), big enough to hold the
    polygon drawn from its pole where the solution's stands."""
    from tarsim.graphics.linkages.polygon_panel import POLYGON_BOX, _per_cm, finite_points

    from .linkages.solution_files import figure_parts

    units, where = sol.exercise.mechanism.units, sol.position

    def titled(heading: str) -> str:
        if where is None:
            return heading
        return words("{what} at {where}", what=heading, where=math_text(where.label.split(" (")[0]))

    out = []
    polygons = {}
    for _, _, parts in figure_parts(sol):
        for _, panel, shown in parts:
            if panel in _POLYGONS:
                polygons.setdefault(panel, shown)
    for panel, shown in polygons.items():
        heading, scale_name, pole, per_time, field = _POLYGONS[panel]
        poly = sol.work.made(f"{field} polygon")
        points = [p for s in shown.steps(panel) for p in finite_points(s)] or [(0.0, 0.0)]
        stated = getattr(sol.work.scales, f"{field}_polygon")
        per_cm = stated or _per_cm(points, poly.scale, units, room(sheet, POLYGON_BOX))
        mm = 10.0 / (per_cm * units.metres * poly.scale)     # paper mm a drawing metre
        o = sol.assembly[poly.pole].output.xy
        xs, ys = [(p[0] - o[0]) * mm for p in points], [(o[1] - p[1]) * mm for p in points]
        reach = (max(0.0, -min(xs)), max(0.0, -min(ys)), max(0.0, max(xs)), max(0.0, max(ys)))
        out.append(draw_empty_polygon(titled(words(heading)), reach=reach, per_cm=per_cm,
                                      unit=units.length + per_time, scale_name=scale_name,
                                      pole=("o", pole)))
    return out + force_frames(sol, titled)




def _input_words(m) -> str:
    from tarsim.graphics.linkages.diagram_labels import input_caption

    return input_caption(m)


def _xy(p: tuple[float, float], m) -> str:
    """A frame point in the file's axes and length unit: "(0, −500)"."""
    k = m.units.metres
    return f"({number((p[0] + m.origin[0]) / k)}, {number((p[1] + m.origin[1]) / k)})"


HANDOUTS: dict[str, Callable] = {"linkages": _linkage_sheets, "gears": gear_sheets,
                                  "cams": cam_sheets, "balancing": rotor_sheets,
                                  "forces": flywheel_sheets}
"""Each chapter's problem sheet, by the chapter's key."""
