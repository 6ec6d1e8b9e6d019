"""What a figure keeps of what it draws (graphics/figure.py): the record's steps each
primitive is drawn for, and where each panel's world stands on its paper.

A page that shows a figure step by step reads the first; one that moves the figure with
the mechanism reads the second. Both are held to the figure itself: every circled step
number stands among the primitives of the step it numbers, and each pin, the pole and
each tip is drawn where the figure's view puts its point, after the figure is moved onto
its sheet and onto a worked page.
"""

import math

from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.linkages.kennedy import locate_centres
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tarsim.constructions.record import Panel, Role, Slice, slice
from tarsim.graphics.figure import Circle, Figure, Path, Text
from tarsim.graphics.linkages.polygon_panel import draw_polygon_panel
from tarsim.graphics.linkages.scene import draw_scene
from tarsim.graphics.linkages.worked_page import compose_worked_page
from tarsim.graphics.paper import PAPERS, on_sheet
from tarsim.constructions.units import Units
from tests.common import crank_shaper, four_bar

PAPER = 1e-6
"""mm: a view and the drawing compute a point's place in double precision from the same
world point, moved by the same shifts, so only rounding separates them."""


def _centres_scene(mech) -> tuple[Figure, Slice]:
    cs = locate_centres(assemble(mech))
    shown = Slice(cs.assembly, tuple(cs.construction_refs()))
    return draw_scene(shown, title="centres"), shown


def test_each_circled_number_stands_among_the_primitives_of_its_step():
    """Every badge's number is the slice's number of a step it is drawn for, and every
    numbered step has primitives of its own. A badge is drawn where a reader needs the
    number to find the step: a four-bar's centres by Kennedy's theorem, I13 and I24; the
    pins' centres and the Kennedy lines need none beside their names."""
    fig, shown = _centres_scene(four_bar(math.radians(60)))
    numbers = shown.numbers(Panel.SPACE)
    badges = [it for it in fig.items if isinstance(it, Text) and it.text.isdigit()
              and not it.italic and it.steps]
    assert {int(b.text) for b in badges} == {numbers["I:13"], numbers["I:24"]}
    for badge in badges:
        assert int(badge.text) in {numbers.get(s) for s in badge.steps}, badge
    drawn = {s for it in fig.items for s in it.steps}
    assert set(numbers) <= drawn
    # The mechanism is no step's: its links stand on every step.
    assert all(not it.steps for it in fig.items if getattr(it, "style", "") == "link")


def test_the_pins_stand_where_the_space_view_puts_the_joints():
    """A pin's circle is drawn where the figure's space view puts its joint, on the
    figure as drawn and centred on a sheet."""
    mech = crank_shaper(math.radians(90))
    fig, _ = _centres_scene(mech)
    asm = assemble(mech)
    for drawn in (fig, on_sheet(fig, PAPERS["A3"])):
        view = drawn.views["space"]
        pins = [it.centre for it in drawn.items if isinstance(it, Circle) and it.style == "pin"]
        at = [view(asm.xy(n)) for n in mech.point_names]
        assert len(pins) >= 3
        for pin in pins:
            assert min(math.dist(pin, p) for p in at) <= PAPER


def test_a_worked_page_keeps_each_panel_s_view():
    """On a worked page each panel keeps its view: the velocity polygon's pole dot and the
    heads of its arrows stand where the velocity view puts the pole and the tips."""
    mech = crank_shaper(math.radians(90))
    asm = assemble(mech)
    vp = draw_velocity_polygon(asm)
    shown = slice(asm, [s.id for s in asm if s.panel is Panel.VELOCITY
                        and s.role is Role.RESULT])
    space = draw_scene(Slice(asm, ()), title="space")
    polygon = draw_polygon_panel(shown, panel=Panel.VELOCITY, scale=vp.scale,
                                 units=Units("mm"), title="velocity")
    page = compose_worked_page("worked", [space, polygon], [("quantity",), ("V_B",)])
    view = page.views["velocity"]
    pole = view(asm.output(vp.pole).xy)
    dots = [it.centre for it in page.items if isinstance(it, Circle) and it.style == "dot"]
    assert min(math.dist(d, pole) for d in dots) <= PAPER
    heads = [it.points[0] for it in page.items if isinstance(it, Path)
             and it.style == "arrowhead" and it.steps]
    tips = [view(asm.output(ref).xy) for ref in vp.tips.values()]
    moving = [t for t in tips if math.dist(t, pole) > 1.0]
    assert moving
    for tip in moving:
        assert min(math.dist(h, tip) for h in heads) <= PAPER
    space_view = page.views["space"]
    pins = [it.centre for it in page.items if isinstance(it, Circle) and it.style == "pin"]
    assert min(math.dist(p, space_view(asm.xy("A"))) for p in pins) <= PAPER
