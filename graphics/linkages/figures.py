"""The linkages' kinds of figure: each construction's scene, the compass work of the
positions, the circle diagram, the worked page, the limit positions and the mechanism
alone (:mod:`tarsim.graphics.figure_kinds`)."""

from __future__ import annotations

from tarsim.constructions.linkages.acceleration_polygon import drawn_acceleration_polygon
from tarsim.constructions.linkages.velocity_polygon import drawn_velocity_polygon
from tarsim.constructions.record import Kind, Panel, Slice, slice

from .circle_diagram import draw_circle_diagram
from .polygon_panel import POLYGON_BOX, draw_polygon_panel
from .scene import draw_scene
from .worked_page import compose_worked_sheets, holds_panel, holds_together
from ..figure import Figure, stack_pages
from ..figure_kinds import FigureOrder, FigurePlan, figure_kind
from ..fitting import fit, held_by, labels_on_lines
from ..hiding import hidden, shown_columns
from ..paper import on_sheet, room

__all__ = ["CIRCLE"]

CIRCLE = 76.0
"""The circle diagram's radius on A4 (mm), grown with the sheet: the diagram has no
scale, so it is drawn to fill half its sheet, as every figure does (tests/test_sheet_fill.py)."""


@figure_kind("scene")
def _scene(order: FigureOrder) -> FigurePlan:
    return _space(order, order.shown(), order.under(Panel.SPACE) if order.spec.notes else [])


@figure_kind("positions")
def _positions(order: FigureOrder) -> FigurePlan:
    # The compass work that put the points there: the walk back stops only at the frame.
    return _space(order, order.shown(base=()),
                  order.under(Panel.SPACE) if order.spec.notes else [])


@figure_kind("limits")
def _limits(order: FigureOrder) -> FigurePlan:
    # Its notes state the stroke and the time ratio found: answers, which may be hidden.
    return _space(order, order.shown(),
                  [] if "answers" in hidden() else order.under(Panel.SPACE))


def _space(order: FigureOrder, shown: Slice, notes: list[str]) -> FigurePlan:
    """The space diagram with ``shown`` drawn on it and ``notes`` under it, fitted to the
    sheet; one that draws velocities at their own scale is not grown (its caption states
    that scale), and one at a velocity scale the exercise states is drawn at its scale."""
    spec = order.spec

    def draw(per_cm: float) -> Figure:
        return draw_scene(shown, title=order.title(spec.caption, placed=False), notes=notes,
                          velocity_scale=spec.velocity_scale, per_cm=per_cm,
                          velocity_stated=spec.velocity_stated)

    return FigurePlan(lambda: on_sheet(fit(
        draw, order.work.scales.space, held_by(order.sheet),
        fixed=order.stated or bool(spec.velocity_stated), grow=spec.velocity_scale is None),
        order.sheet), shown)


@figure_kind("mechanism")
def _mechanism(order: FigureOrder) -> FigurePlan:
    bare = Slice(order.record, ())
    return FigurePlan(lambda: on_sheet(fit(
        lambda per_cm: draw_scene(bare, title=order.mechanism.name, per_cm=per_cm),
        order.work.scales.space, held_by(order.sheet), fixed=order.stated, grow=True),
        order.sheet))


@figure_kind("circle diagram")
def _circle_diagram(order: FigureOrder) -> FigurePlan:
    c = order.record
    every = slice(c, [s.id for s in c if s.kind is Kind.CENTRE], base=c.position_steps)
    radius = CIRCLE * room(order.sheet, (1.0, 1.0))[0]
    return FigurePlan(lambda: on_sheet(draw_circle_diagram(
        every, title=order.mechanism.name, radius=radius), order.sheet))


def _polygon_regrow(shown: Slice, how: dict, drawn: Figure):
    """A polygon panel drawn again, from the scale ``drawn`` was fitted to its room at, at
    the finest of the course's scales a sheet holds (:func:`fit`); None for one at the
    scale the exercise states, which is kept."""
    if how["per_cm"] is not None:
        return None
    paper_per_metre = drawn.views[how["panel"].value].scale   # paper mm a drawing metre
    per_cm = float(f"{10.0 / (paper_per_metre * how['units'].metres * how['scale']):.12g}")

    def draw(per_cm: float) -> Figure:
        return draw_polygon_panel(shown, **{**how, "per_cm": per_cm})

    return lambda holds: fit(draw, per_cm, holds, grow=True)


def _grown_beside(scene, figures: list[Figure], per_cm: float, sheet: tuple[float, float],
                  title: str) -> Figure:
    """The space diagram ``figures[0]`` drawn again at the finest of the course's scales at
    which its sheet still holds it and the first polygon (an A3 sheet, or a small
    mechanism, has room to spare beside them); itself where none does, or where the bigger
    one's labels find less room. Its caller takes it where the page runs on over no more
    sheets."""
    space, first = figures[0], figures[1]
    if not holds_together(sheet, [space, first], title):
        return space
    grown = fit(scene, per_cm, lambda fig: holds_together(sheet, [fig, first], title),
                grow=True)
    if grown.width * grown.height > space.width * space.height + 1e-6 and \
            holds_together(sheet, [grown, first], title) and \
            labels_on_lines(grown) <= labels_on_lines(space):
        return grown
    return space


@figure_kind("polygons", last=True)
def _worked_page(order: FigureOrder) -> FigurePlan:
    """The space diagram, the polygons and the results table on one page.

    Each polygon shows the slice of what is asked of it, and every vector whose two
    ends that slice draws (the absolute vectors from the pole, the components, the
    relative velocities ω is read from); one asked nothing shows its pole alone.
    """
    work, c, sheet = order.work, order.record, order.sheet
    polygons = [(drawn_velocity_polygon(work), Panel.VELOCITY, "Velocity polygon",
                 work.scales.velocity_polygon)]
    if work.has("acceleration polygon"):
        polygons.append((drawn_acceleration_polygon(work), Panel.ACCELERATION,
                         "Acceleration polygon", work.scales.acceleration_polygon))
    panels, drawn = [], []
    for poly, panel, heading, stated in polygons:
        shown = order.shown(panel=panel)
        if not shown.steps(panel):
            shown = slice(c, [poly.pole], base=c.position_steps)
        drawn.append(dict(panel=panel, scale=poly.scale, units=order.mechanism.units,
                          title=order.said(heading), notes=order.under(panel), per_cm=stated))
        panels.append((heading, panel, shown))
    table = shown_columns(order.table())
    upright = (sheet.width, sheet.height)

    def scene(per_cm: float) -> Figure:
        return draw_scene(Slice(c, ()), title=order.title("space diagram"), per_cm=per_cm)

    title = order.title("worked solution")

    def draw() -> Figure:
        space = fit(scene, work.scales.space, lambda fig: holds_panel(upright, fig),
                    fixed=order.stated)
        figures = [space] + [draw_polygon_panel(shown, room=room(sheet, POLYGON_BOX), **how)
                             for (_, _, shown), how in zip(panels, drawn)]
        # A panel alone on a run-on sheet is drawn again at the finest scale it holds.
        regrow = [lambda holds: fit(scene, work.scales.space, holds, fixed=order.stated,
                                    grow=True)]
        regrow += [_polygon_regrow(shown, how, fig)
                   for (_, _, shown), how, fig in zip(panels, drawn, figures[1:])]

        def composed(figures: list[Figure]) -> list[Figure]:
            return compose_worked_sheets(title, figures, table, order.under(Panel.SPACE),
                                         sheet=upright, regrow=regrow)

        sheets = composed(figures)
        grown = space if order.stated else _grown_beside(scene, figures, work.scales.space,
                                                         upright, title)
        if grown is not space:      # taken where it sets the page on no more sheets
            bigger = composed([grown, *figures[1:]])
            sheets = bigger if len(bigger) <= len(sheets) else sheets
        return sheets[0] if len(sheets) == 1 else stack_pages(sheets)

    return FigurePlan(draw, None, tuple(panels))
