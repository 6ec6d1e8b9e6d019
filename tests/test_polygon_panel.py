"""Velocity and acceleration polygons drawn as figures (graphics/linkages/polygon_panel.py).

The checks are on what a reader with a ruler sees: the stated scale is nice and
true (an arrow measures |V| / N cm), every arrowhead sits at its tip and points
away from its tail, every tip is named once, no two labels overlap, the circled
numbers are 1..k as :meth:`Slice.numbered` counts them, a vector
of no length is written "= 0", and the same input gives the same SVG.

The acceleration polygons are built here by hand, as
constructions/linkages/acceleration_polygon.py will record them (the ``ap:`` conventions),
from the analytic solver's ω, α and Coriolis terms: the figure only has to draw
them, so where their numbers come from does not matter, and they are realistic.
Paper positions are compared to 1e-6 mm: the figure computes them in double
precision from the same outputs, so only rounding separates them.
"""

import math
import re

import pytest

from tarsim.constructions import geometry as g
from tarsim.constructions.reference import solver
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.model import Drive
from tarsim.constructions.units import Units
from tarsim.constructions.narration import Phrase
from tarsim.constructions.record import Construction, Panel, Role, Slice, slice
from tarsim.constructions.linkages.velocity_polygon import draw_velocity_polygon
from tarsim.graphics.figure import Circle, Path, Text
from tarsim.graphics.linkages.lanes import LANE
from tarsim.graphics.linkages.polygon_panel import POLYGON_BOX, draw_polygon_panel
from tarsim.graphics.svg import to_svg
from tarsim.graphics.typeset import typeset
from tests.common import badge_numbers, coupler_four_bar, crank_shaper

SHAPER_T = math.pi / 2 - 2.34       # seed 003 §2: t = 2.34 s, θ2 = 90° − t, ω2 = −1 rad/s
SHAPER_STILL = -math.asin(0.18 / 0.5)   # seed 003 §5: the ram's extreme, ω4 = 0
PAPER = 1e-6                        # mm


# ----- hand-built acceleration polygons ----------------------------------------------------
class _Builder:
    """Record an acceleration polygon step by step, with the ``ap:`` conventions."""

    def __init__(self, scale: float):
        self.c = Construction()
        self.scale = scale
        self.refs: list[str] = []
        self.c.give("ap:o_a", g.Point(0.0, 0.0), label="o_a", panel=Panel.ACCELERATION,
                    phrase=Phrase("test.pole"))
        self.refs.append("ap:o_a")

    def space_line(self, ref, p, q):
        """A line of the space diagram (not drawn in the panel) to take directions from."""
        self.c.give(ref, g.line_through(g.Point(*p), g.Point(*q))[0], label="")
        return ref

    def act(self, ref, verb, *inputs, label="", role=Role.CONSTRUCTION, **params):
        self.c.draw(ref, verb, *inputs, label=label, role=role, panel=Panel.ACCELERATION,
                    phrase=Phrase("test.step", (("ref", ref),)), **params)
        self.refs.append(ref)
        return ref

    def lay(self, ref, start, vector, label=""):
        """Lay off ``vector`` (m/s²) from ``start``; a null one marks the start again."""
        if math.hypot(*vector) == 0.0:
            return self.act(ref, "mark", start, label=label)
        self.c.give(ref + ":dir", g.Point.at_infinity(*vector), label="")
        u = self.c.output(ref + ":dir").direction
        length = (vector[0] * u[0] + vector[1] * u[1]) * self.scale
        return self.act(ref, "lay_off", start, ref + ":dir", length=length, label=label)

    def vector(self, ref, start, end, label, role=Role.CONSTRUCTION):
        return self.act(ref, "join", start, end, label=label, role=role)


def _sub(p, q):
    return (p[0] - q[0], p[1] - q[1])


def _times(k, v):
    return (k * v[0], k * v[1])


def shaper_acceleration(theta2=SHAPER_T, scale=1.0):
    """The crank-shaper's acceleration polygon (seed 003), with Coriolis and sliding parts.

    A_A3 = A_A4 + Aᶜ_A3/A4 + Aˢ_A3/A4, with A_A4 = Aⁿ_A4 + Aᵗ_A4 about O4: from a2′
    lay Aᶜ back to k, then the slot's parallel through k meets the tangential
    line through the end of Aⁿ_A4 at a4′. b4′ divides o_a a4′ as B divides O4A;
    A_B5 = A_B4 + Aᶜ_B5/B4 + Aˢ_B5/B4 with A_B5 along the ram's guide.
    """
    mech = crank_shaper(theta2)
    kin = solver.solve(mech)
    P, w4 = kin.points, kin.omegas[4]
    cor_a, cor_b = kin.slide_rates[0].coriolis, kin.slide_rates[2].coriolis
    b = _Builder(scale)
    slot = b.space_line("s:O4A", P["O4"], P["A"])
    guide = b.space_line("s:guide", (0.0, 0.38), (1.0, 0.38))
    b.lay("ap:tip:A2", "ap:o_a", solver.point_acceleration(kin, mech, 2, "A"), label="a2′")
    b.lay("ap:n:A4", "ap:o_a", _times(-w4 * w4, _sub(P["A"], P["O4"])))
    b.act("ap:A4:t", "perpendicular_through", "ap:n:A4", slot)
    b.lay("ap:k:A", "ap:tip:A2", _times(-1.0, cor_a))
    b.act("ap:A4:s", "parallel_through", "ap:k:A", slot)
    b.act("ap:tip:A4", "intersect_lines", "ap:A4:t", "ap:A4:s", label="a4′")
    ratio = math.dist(P["O4"], P["B"]) / math.dist(P["O4"], P["A"])
    side = math.dist(b.c.output("ap:tip:A4").xy, (0.0, 0.0))
    b.act("ap:tip:B4", "lay_off", "ap:o_a", "ap:tip:A4", length=ratio * side, label="b4′")
    b.lay("ap:k:B", "ap:tip:B4", cor_b)
    b.act("ap:B5:s", "parallel_through", "ap:k:B", slot)
    b.act("ap:B5:g", "parallel_through", "ap:o_a", guide)
    b.act("ap:tip:B5", "intersect_lines", "ap:B5:s", "ap:B5:g", label="b5′")
    b.vector("ap:A:A2", "ap:o_a", "ap:tip:A2", "A_A2", Role.GIVEN)
    b.vector("ap:c:An_A4", "ap:o_a", "ap:n:A4", "Aⁿ_A4")
    b.vector("ap:c:At_A4", "ap:n:A4", "ap:tip:A4", "Aᵗ_A4")
    b.vector("ap:c:As_A", "ap:tip:A4", "ap:k:A", "Aˢ_A3/A4")
    b.vector("ap:c:Ac_A", "ap:k:A", "ap:tip:A2", "Aᶜ_A3/A4")
    b.vector("ap:c:Ac_B", "ap:tip:B4", "ap:k:B", "Aᶜ_B5/B4")
    b.vector("ap:c:As_B", "ap:k:B", "ap:tip:B5", "Aˢ_B5/B4")
    b.vector("ap:A:A4", "ap:o_a", "ap:tip:A4", "A_A4", Role.RESULT)
    b.vector("ap:A:B4", "ap:o_a", "ap:tip:B4", "A_B4", Role.RESULT)
    b.vector("ap:A:B5", "ap:o_a", "ap:tip:B5", "A_B5", Role.RESULT)
    return b.c, b.refs, kin, mech


def four_bar_acceleration(theta2=math.pi / 3, omega2=2.0, alpha2=3.0, scale=1.0):
    """The coupler four-bar's polygon: normal and tangential components, d′ by the image."""
    base = coupler_four_bar(theta2, omega2=omega2)
    mech = base.with_drive(Drive(2, theta2, omega2, alpha2))
    kin = solver.solve(mech)
    P, w = kin.points, kin.omegas
    b = _Builder(scale)
    ab = b.space_line("s:AB", P["A"], P["B"])
    o4b = b.space_line("s:O4B", P["O4"], P["B"])
    o2a = b.space_line("s:O2A", P["O2"], P["A"])
    b.lay("ap:n:A", "ap:o_a", _times(-w[2] ** 2, _sub(P["A"], P["O2"])))
    b.act("ap:A:t", "perpendicular_through", "ap:n:A", o2a)
    b.lay("ap:tip:A", "ap:n:A", _times(alpha2, (-(P["A"][1]), P["A"][0])), label="a′")
    b.lay("ap:n:B/A", "ap:tip:A", _times(-w[3] ** 2, _sub(P["B"], P["A"])))
    b.act("ap:B:t@A", "perpendicular_through", "ap:n:B/A", ab)
    b.lay("ap:n:B", "ap:o_a", _times(-w[4] ** 2, _sub(P["B"], P["O4"])))
    b.act("ap:B:t@O4", "perpendicular_through", "ap:n:B", o4b)
    b.act("ap:tip:B", "intersect_lines", "ap:B:t@A", "ap:B:t@O4", label="b′")
    side = math.dist(b.c.output("ap:tip:A").xy, b.c.output("ap:tip:B").xy)
    b.act("ap:tip:D", "lay_off", "ap:tip:A", "ap:tip:B", length=1.28 * side, label="d′")
    b.vector("ap:c:An_A", "ap:o_a", "ap:n:A", "Aⁿ_A")
    b.vector("ap:c:At_A", "ap:n:A", "ap:tip:A", "Aᵗ_A")
    b.vector("ap:c:An_B/A", "ap:tip:A", "ap:n:B/A", "Aⁿ_B/A")
    b.vector("ap:c:At_B/A", "ap:n:B/A", "ap:tip:B", "Aᵗ_B/A")
    b.vector("ap:c:An_B", "ap:o_a", "ap:n:B", "Aⁿ_B")
    b.vector("ap:c:At_B", "ap:n:B", "ap:tip:B", "Aᵗ_B")
    b.vector("ap:A:A", "ap:o_a", "ap:tip:A", "A_A", Role.GIVEN)
    b.vector("ap:A:B", "ap:o_a", "ap:tip:B", "A_B", Role.RESULT)
    b.vector("ap:A:D", "ap:o_a", "ap:tip:D", "A_D", Role.RESULT)
    b.vector("ap:rel:3", "ap:tip:A", "ap:tip:B", "A_B/A", Role.RESULT)
    return b.c, b.refs, kin, mech


def shaper_velocity(theta2=SHAPER_T):
    mech = crank_shaper(theta2)
    vp = draw_velocity_polygon(assemble(mech))
    return vp, mech


def draw_velocity(vp, mech):
    return draw_polygon_panel(Slice(vp.construction, tuple(vp.steps)), panel=Panel.VELOCITY,
                              scale=vp.scale,
                              units=mech.units, title=f"{mech.name}: velocity polygon")


def draw_acceleration(c, refs, mech, scale=1.0, **kw):
    return draw_polygon_panel(Slice(c, tuple(refs)), panel=Panel.ACCELERATION, scale=scale,
                              units=mech.units,
                              title=f"{mech.name}: acceleration polygon", **kw)


# ----- reading a figure back --------------------------------------------------------------
def stated_per_cm(fig, quantity, unit):
    """N of the caption's "<Quantity> scale 1 cm = N <unit>"."""
    pattern = rf"{quantity} scale 1 cm = ([0-9.e+-]+) {re.escape(unit)}"
    found = [re.fullmatch(pattern, t.text) for t in fig.items if isinstance(t, Text)]
    (n,) = [float(m.group(1)) for m in found if m]
    return n


def pole_on_paper(fig):
    (dot,) = [it for it in fig.items if isinstance(it, Circle) and it.style == "dot"]
    return dot.centre


def arrowheads(fig):
    return [it.points for it in fig.items if isinstance(it, Path) and it.style == "arrowhead"]


def shafts(fig):
    return [it.points for it in fig.items
            if isinstance(it, Path) and it.style in ("vector", "vector_result")]


def paper_of(fig, c, pole_ref, per_mm):
    """Map a step's drawing point to paper, through the pole: y flips, lengths scale."""
    px, py = c.output(pole_ref).xy
    ox, oy = pole_on_paper(fig)
    return lambda xy: (ox + per_mm * (xy[0] - px), oy - per_mm * (xy[1] - py))


def texts(fig):
    return [it for it in fig.items if isinstance(it, Text)]


def is_nice(n):
    mantissa = n / 10.0 ** math.floor(math.log10(n))
    return any(abs(mantissa - m) < 1e-9 for m in (1.0, 2.0, 5.0))


def boxes_overlap(a, b):
    return a[0] < b[2] - 1e-9 and b[0] < a[2] - 1e-9 and a[1] < b[3] - 1e-9 and b[1] < a[3] - 1e-9


# ----- the scale ---------------------------------------------------------------------------
def test_the_velocity_scale_is_nice_and_a_ruler_confirms_it_on_v_b():
    vp, mech = shaper_velocity()
    fig = draw_velocity(vp, mech)
    n = stated_per_cm(fig, "Velocity", "mm/s")
    assert is_nice(n)
    # seed 003 §2 at t = 2.34 s: the ram moves at ṗ = −189.192 mm/s (printed to 1e-3).
    vb = vp.vector("B")
    assert vb[0] * 1000 == pytest.approx(-189.192, abs=5e-4) and vb[1] == pytest.approx(0.0)
    length = 10.0 * 189.1924275387919 / n          # mm on paper: |V| / N cm
    ox, oy = pole_on_paper(fig)
    tip = (ox - length, oy)
    assert any(math.dist(h[0], tip) < PAPER for h in arrowheads(fig))
    assert any(math.dist(s[0], (ox, oy)) < PAPER and abs(s[-1][1] - oy) < PAPER
               and s[-1][0] < ox for s in shafts(fig))
    # The bar under the statement is four of those centimetres.
    assert f"{4 * n:g} mm/s" in [t.text for t in texts(fig)]


def test_the_polygon_fills_its_box_at_the_smallest_nice_scale_that_fits():
    vp, mech = shaper_velocity()
    fig = draw_velocity(vp, mech)
    n = stated_per_cm(fig, "Velocity", "mm/s")
    pts = [vp.construction.output(r).xy for r in vp.steps
           if isinstance(vp.construction.output(r), g.Point)]
    extent = [(max(p[k] for p in pts) - min(p[k] for p in pts)) / vp.scale * 1000 for k in (0, 1)]
    fits = [e / n * 10.0 <= room + 1e-9 for e, room in zip(extent, POLYGON_BOX)]
    assert all(fits)
    # The next nice step down (5 → 2, 2 → 1, 1 → 0.5) would overflow the box.
    mantissa = round(n / 10.0 ** math.floor(math.log10(n)))
    smaller = n / 2.5 if mantissa == 5 else n / 2
    assert any(e / smaller * 10.0 > room for e, room in zip(extent, POLYGON_BOX))


@pytest.mark.parametrize("which", ["velocity", "acceleration"])
def test_every_vector_measures_true_and_its_head_is_at_its_tip(which):
    if which == "velocity":
        vp, mech = shaper_velocity()
        c, refs, scale, pole = vp.construction, vp.steps, vp.scale, "vp:o_v"
        fig = draw_velocity(vp, mech)
        n = stated_per_cm(fig, "Velocity", "mm/s")
    else:
        c, refs, _, mech = shaper_acceleration()
        scale, pole = 1.0, "ap:o_a"
        fig = draw_acceleration(c, refs, mech)
        n = stated_per_cm(fig, "Acceleration", "mm/s²")
    assert is_nice(n)
    per_mm = 10.0 / (n * mech.units.metres * scale)    # paper mm per drawing metre
    to_paper = paper_of(fig, c, pole, per_mm)
    heads = arrowheads(fig)
    segments = [c[r] for r in refs if isinstance(c.output(r), g.Segment)]
    assert len(heads) == len(segments)
    for step in segments:
        a, b = to_paper(step.output.start.xy), to_paper(step.output.end.xy)
        # Its paper length is |v| / N cm, |v| in the file's unit per second.
        assert math.dist(a, b) == pytest.approx(
            10.0 * step.output.length / scale / mech.units.metres / n, rel=1e-9)
        u = ((b[0] - a[0]) / math.dist(a, b), (b[1] - a[1]) / math.dist(a, b))
        # A head has its point at the tip and its base behind it, toward the tail
        # (several arrows may end at one tip: one of them is this one's), or at the tip
        # moved into a lane square to the arrow (the Coriolis component at B, along A_B4).
        tips = [(b[0] - k * LANE * u[1], b[1] + k * LANE * u[0]) for k in range(-4, 5)]
        ok = []
        for head, tip in ((h, t) for h in heads for t in tips if math.dist(h[0], t) < PAPER):
            back = ((head[1][0] + head[3][0]) / 2, (head[1][1] + head[3][1]) / 2)
            ok.append((tip[0] - back[0]) * u[0] + (tip[1] - back[1]) * u[1] > 1.0
                      and abs((tip[0] - back[0]) * u[1] - (tip[1] - back[1]) * u[0]) < 1e-6)
        assert any(ok), step.id


def test_the_acceleration_scale_is_stated_in_mm_per_s_squared_and_measures_true_on_a_b():
    c, refs, kin, mech = shaper_acceleration()
    fig = draw_acceleration(c, refs, mech)
    n = stated_per_cm(fig, "Acceleration", "mm/s²")
    # seed 003 §7 at t = 2.34 s: p̈ = −535.635 mm/s² (printed to 1e-3).
    assert kin.accelerations["B"][0] * 1000 == pytest.approx(-535.635, abs=5e-4)
    ox, oy = pole_on_paper(fig)
    tip = (ox - 10.0 * 535.6354497652059 / n, oy)
    assert any(math.dist(h[0], tip) < PAPER for h in arrowheads(fig))
    assert f"{4 * n:g} mm/s²" in [t.text for t in texts(fig)]


# ----- labels --------------------------------------------------------------------------------
@pytest.mark.parametrize("case", ["shaper velocity", "four-bar velocity", "shaper acceleration",
                                  "four-bar acceleration"])
def test_every_tip_is_named_once_and_no_two_labels_overlap(case):
    if case.endswith("velocity"):
        mech = crank_shaper(SHAPER_T) if case.startswith("shaper") else coupler_four_bar(1.0)
        vp = draw_velocity_polygon(assemble(mech))
        c, refs, fig = vp.construction, vp.steps, draw_velocity(vp, mech)
    else:
        build = shaper_acceleration if case.startswith("shaper") else four_bar_acceleration
        c, refs, _, mech = build()
        fig = draw_acceleration(c, refs, mech)
    written = [(t.text, t.sub) for t in texts(fig)]
    names = {typeset(c[r].label) for r in refs
             if isinstance(c.output(r), g.Point) and c[r].label}
    for name in names:
        assert written.count(name) == 1, name
    for r in refs:
        if isinstance(c.output(r), g.Segment) and c.output(r).length > 0:
            assert written.count(typeset(c[r].label)) == 1, c[r].label
    boxes = [t.box() for t in texts(fig)]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert not boxes_overlap(a, b), (a, b)


def test_the_poles_and_primes_are_typeset_as_the_notes_write_them():
    vp, mech = shaper_velocity()
    written = [(t.text, t.sub) for t in texts(draw_velocity(vp, mech))]
    assert ("o", "v") in written and ("a₄", "") in written and ("V", "B₅") in written
    c, refs, _, mech = shaper_acceleration()
    written = [(t.text, t.sub, t.italic) for t in texts(draw_acceleration(c, refs, mech))]
    for label in [("o", "a"), ("a₄′", ""), ("Aᶜ", "A₃/A₄"), ("Aˢ", "B₅/B₄"), ("Aⁿ", "A₄"),
                  ("Aᵗ", "A₄")]:
        assert (*label, True) in written, label


def test_a_vector_of_no_length_is_written_equal_to_zero_and_not_drawn():
    # seed 003 §5: at the ram's extreme ω4 = 0, so Aⁿ_A4 and both Coriolis parts vanish;
    # the crank stands square to the lever, so A_A2 is square to the slot: no Aˢ_A3/A4.
    c, refs, kin, mech = shaper_acceleration(SHAPER_STILL)
    assert kin.omegas[4] == pytest.approx(0.0, abs=1e-12)
    fig = draw_acceleration(c, refs, mech)
    zero = [(t.text, t.sub) for t in texts(fig) if t.tail == " = 0"]
    assert sorted(zero) == sorted([("Aᶜ", "A₃/A₄"), ("Aᶜ", "B₅/B₄"), ("Aⁿ", "A₄"),
                                   ("Aˢ", "A₃/A₄")])
    # Aⁿ_A4 = ω4²·O4A is 1e-34 here: nothing a pen could draw.
    drawn = [r for r in refs if isinstance(c.output(r), g.Segment) and c.output(r).length > 1e-9]
    assert len(arrowheads(fig)) == len(drawn)


# ----- working lines and numbers -------------------------------------------------------------
def test_each_line_spans_its_points_and_runs_a_little_past_them():
    mech = coupler_four_bar(math.radians(60))
    vp = draw_velocity_polygon(assemble(mech))
    fig = draw_velocity(vp, mech)
    n = stated_per_cm(fig, "Velocity", "m/s")
    to_paper = paper_of(fig, vp.construction, "vp:o_v", 10.0 / (n * vp.scale))
    lines = [it.points for it in fig.items if isinstance(it, Path) and it.style == "working"]
    # ⟂ O2A through o_v, ⟂ AB through a, ⟂ O4B through o_v, ⟂ AC through a, ⟂ BC through b.
    assert len(lines) == 5
    # The line ⟂ AB through a carries a, b and d (D lies on AB): it runs from a to d.
    a, d = (to_paper(vp.construction.output(f"vp:tip:{x}").xy) for x in "AD")
    line = next(p for p in lines if min(math.dist(e, a) for e in p) < 5.0
                and min(math.dist(e, d) for e in p) < 5.0)
    assert sorted(min(math.dist(e, q) for e in line) for q in (a, d)) == pytest.approx([4.0, 4.0])
    assert math.dist(*line) == pytest.approx(math.dist(a, d) + 8.0)


@pytest.mark.parametrize("which", ["velocity", "acceleration"])
def test_the_circled_numbers_are_those_numbered_steps_gives_for_the_panel(which):
    if which == "velocity":
        vp, mech = shaper_velocity()
        c, refs, panel, fig = vp.construction, vp.steps, Panel.VELOCITY, draw_velocity(vp, mech)
    else:
        c, refs, _, mech = four_bar_acceleration()
        panel, fig = Panel.ACCELERATION, draw_acceleration(c, refs, mech)
    numbered = Slice(c, tuple(refs)).numbered(panel)
    # Every narrated act but the givens (the pole, the input's vector) is numbered.
    given = [r for r in refs if c[r].role is Role.GIVEN]
    assert [s.id for _, s in numbered] == [r for r in refs if r not in given]
    assert badge_numbers(fig) == list(range(1, len(numbered) + 1))
    # The space panel's numbering is unchanged: none of these steps are in it.
    assert Slice(c, tuple(refs)).numbered() == []


def test_a_slice_is_drawn_in_record_order_and_other_panels_are_left_out():
    vp, mech = shaper_velocity()
    whole = to_svg(draw_velocity(vp, mech))
    mixed = slice(vp.construction, [*vp.steps, *vp.space_steps])
    assert to_svg(draw_polygon_panel(mixed, panel=Panel.VELOCITY,
                                     scale=vp.scale, units=mech.units,
                                     title=f"{mech.name}: velocity polygon")) == whole


# ----- determinism and errors ----------------------------------------------------------------
@pytest.mark.slow
def test_the_same_input_gives_a_byte_identical_svg():
    first = to_svg(draw_velocity(*shaper_velocity()))
    second = to_svg(draw_velocity(*shaper_velocity()))
    assert first == second
    c, refs, _, mech = four_bar_acceleration()
    c2, refs2, _, _ = four_bar_acceleration()
    assert to_svg(draw_acceleration(c, refs, mech)) == to_svg(draw_acceleration(c2, refs2, mech))


def test_notes_are_printed_under_the_caption():
    c, refs, _, mech = four_bar_acceleration()
    fig = draw_acceleration(c, refs, mech, notes=("α2 not given: taken as 0",))
    assert "α2 not given: taken as 0" in [t.text for t in texts(fig)]


def test_a_polygon_at_rest_is_drawn_at_a_stated_scale():
    b = _Builder(1.0)
    b.act("ap:tip:B", "mark", "ap:o_a", label="b′")
    b.vector("ap:A:B", "ap:o_a", "ap:tip:B", "A_B", Role.RESULT)
    fig = draw_polygon_panel(Slice(b.c, tuple(b.refs)), panel=Panel.ACCELERATION, scale=1.0,
                             units=Units("mm"), title="at rest")
    assert stated_per_cm(fig, "Acceleration", "mm/s²") == 1.0
    written = [(t.text, t.sub, t.tail) for t in texts(fig)]
    assert ("A", "B", " = 0") in written and ("o", "a", " ≡ b′") in written


@pytest.mark.parametrize("panel, scale, match", [
    (Panel.SPACE, 1.0, "not a polygon panel"),
    (Panel.VELOCITY, 0.0, "positive number"),
    (Panel.VELOCITY, float("nan"), "positive number"),
])
def test_a_wrong_panel_or_scale_is_refused(panel, scale, match):
    vp, mech = shaper_velocity()
    with pytest.raises(TarsimError, match=match):
        draw_polygon_panel(Slice(vp.construction, tuple(vp.steps)), panel=panel, scale=scale,
                           units=mech.units, title="x")


def test_refs_with_nothing_in_the_panel_are_refused():
    vp, mech = shaper_velocity()
    with pytest.raises(TarsimError, match="nothing to draw"):
        draw_polygon_panel(Slice(vp.construction, tuple(vp.space_steps)), panel=Panel.VELOCITY,
                           scale=vp.scale, units=mech.units, title="x")


def test_an_unknown_ref_is_refused():
    vp, mech = shaper_velocity()
    with pytest.raises(TarsimError, match="vp:tip:Z"):
        slice(vp.construction, [*vp.steps, "vp:tip:Z"])


# ----- what a reader takes a tip's name for -------------------------------------------------
_NAMED = {
    "shaper velocity": lambda: draw_velocity(*shaper_velocity()),
    "shaper acceleration": lambda: draw_acceleration(*_without_kin(shaper_acceleration())),
    # seed 003 at θ2 = 90°: both polygons on one line, arrows moved into lanes beside it.
    "shaper velocity at 90°": lambda: draw_velocity(*shaper_velocity(math.pi / 2)),
    "shaper acceleration at 90°": lambda: draw_acceleration(
        *_without_kin(shaper_acceleration(math.pi / 2))),
    "four-bar acceleration": lambda: draw_acceleration(*_without_kin(four_bar_acceleration())),
}


def _without_kin(built):
    c, refs, _, mech = built
    return c, refs, mech


def _names_nearer_another(fig) -> tuple[int, list]:
    """How many tips' names (their boxes; a polygon's tips are named in lower case) the
    figure sets, and each that stands nearer the tip of an arrow ending elsewhere, labelled
    or not, or either end of a leader to an arrow moved into a lane, than its own point
    (marks within half a millimetre of its point are its own): (name, its point, the
    nearer mark)."""
    from shapely.geometry import Point as SPoint, box as sbox

    marked = [head[0] for head in arrowheads(fig)] + [
        end for it in fig.items if isinstance(it, Path) and it.style == "leader"
        for end in (it.points[0], it.points[-1])]
    names = [t for t in texts(fig) if t.owner is not None and len(t.owner) == 1
             and t.text[:1].islower()]
    nearer = []
    for t in names:
        own, name = t.owner[0], sbox(*t.box())
        mine = name.distance(SPoint(own))
        nearer += [(t.text, own, p) for p in marked if math.dist(p, own) > 0.5
                   and name.distance(SPoint(p)) < mine - 1e-9]
    return len(names), nearer


@pytest.mark.parametrize("case", _NAMED)
def test_a_tips_name_stands_nearer_its_tip_than_any_other_arrows(case):
    """A reader takes a name for the point marked nearest it: an unlabelled foot between
    two components, or the end of an arrow moved into a lane, is no nearer a tip's name
    than the tip it names."""
    named, nearer = _names_nearer_another(_NAMED[case]())
    assert named > 0 and nearer == []


@pytest.mark.slow
@pytest.mark.parametrize("exercise_id", ["crank-shaper", "inverted-slider-crank",
                                         "klein-slider-crank", "piston-driven-slider-crank",
                                         "rolling-wheel", "wheel-driven-slider",
                                         "wheel-round-circle", "whitworth"])
def test_every_worked_pages_tip_names_stand_nearer_their_tips_than_any_other(solved,
                                                                            exercise_id):
    """The same on each bundled worked page: at the crank-shaper's θ2 = 90° b₄′ beside its
    arrows' lanes, the wheel-driven slider's a′ beside the unlabelled foot of Aⁿ_B/A."""
    pages = {stem: fig for stem, fig in solved(exercise_id).figures.items()
             if stem.startswith("worked")}
    assert pages
    for stem, fig in pages.items():
        named, nearer = _names_nearer_another(fig)
        assert named > 0 and nearer == [], stem


def test_an_arrow_the_poles_dot_covers_is_not_drawn_and_its_tip_is_dotted():
    """V_C a quarter millimetre long from o_v (1 cm = 5 mm/s, V_B 50 mm/s across 100 mm):
    its head, 3.2 mm long at most and 1.6 mm wide, would lie wholly under the pole's dot of
    1 mm, so it is not drawn, and c is dotted where it stands instead; V_B keeps its head."""
    c = Construction()
    c.give("vp:o_v", g.Point(0, 0), label="o_v", panel=Panel.VELOCITY)
    c.give("vp:tip:B", g.Point(0.03, 0.04), label="b", panel=Panel.VELOCITY)
    c.give("vp:tip:C", g.Point(0.000125, 0.0), label="c", panel=Panel.VELOCITY)
    c.draw("vp:V:B", "join", "vp:o_v", "vp:tip:B", label="V_B", role=Role.RESULT,
           panel=Panel.VELOCITY)
    c.draw("vp:V:C", "join", "vp:o_v", "vp:tip:C", label="V_C", role=Role.RESULT,
           panel=Panel.VELOCITY)
    fig = draw_polygon_panel(slice(c, ["vp:V:B", "vp:V:C"]), panel=Panel.VELOCITY, scale=1.0,
                             units=Units("mm"), title="V_C under the pole")
    (head,) = arrowheads(fig)
    dots = [it.centre for it in fig.items if isinstance(it, Circle) and it.style == "dot"]
    pole = dots[0]                          # the pole's, drawn first
    assert math.dist(head[0], pole) == pytest.approx(100.0, abs=PAPER)
    # Beside the pole's own, c's dot: 0.125 mm/s at 5 mm/s a cm.
    near = sorted(math.dist(d, pole) for d in dots if math.dist(d, pole) < 1.0)
    assert near == [pytest.approx(0.0, abs=PAPER), pytest.approx(0.25, abs=PAPER)]
