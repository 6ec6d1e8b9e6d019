"""The force analysis's kinds of figure: the loads on the space diagram, the force
polygons and the free bodies (:mod:`tarsim.graphics.figure_kinds`)."""

from __future__ import annotations

from tarsim.constructions.forces.polygons import drawn_forces
from tarsim.constructions.record import Panel

from .force_figure import draw_force_figure
from .free_body_figure import draw_free_bodies
from .loads_figure import draw_loads
from ..figure_kinds import FigureOrder, FigurePlan, figure_kind
from ..fitting import fit, held_by
from ..paper import on_sheet

__all__: list[str] = []


@figure_kind("forces")
def _forces(order: FigureOrder) -> FigurePlan:
    """The force polygons; steps.md narrates with them the inertia loads read off the
    acceleration polygon, which they draw no figure of."""
    forces, shown = drawn_forces(order.work), order.shown()
    return FigurePlan(lambda: on_sheet(draw_force_figure(
        order.record, forces.scale, order.title("force polygons")), order.sheet), None,
        (("Inertia loads read off the acceleration polygon", Panel.ACCELERATION, shown,
          "not drawn"), ("The force polygons", Panel.FORCE, shown)))


@figure_kind("loads")
def _loads(order: FigureOrder) -> FigurePlan:
    """The loads on the space diagram, with the space diagram's part of the analysis
    (centres of mass, lines of action, the point three forces meet in)."""
    forces, shown = drawn_forces(order.work), order.shown()
    return FigurePlan(lambda: on_sheet(fit(
        lambda per_cm: draw_loads(shown, forces.loads, per_cm=per_cm,
                                  title=order.title("loads")),
        order.work.scales.space, held_by(order.sheet), fixed=order.stated), order.sheet), shown)


@figure_kind("bodies")
def _bodies(order: FigureOrder) -> FigurePlan:
    forces, c = drawn_forces(order.work), order.record
    at = {n: c.point(n).xy for n in c.mechanism.point_names}
    return FigurePlan(lambda: on_sheet(draw_free_bodies(
        c.mechanism, at, forces.bodies, order.title("free bodies"), c.mechanism.units.length),
        order.sheet))
