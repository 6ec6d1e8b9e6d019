"""Tests for graphics.diagram (with graphics.svg and graphics.export): the kinematic diagram.

Every bundled example, and a four-bar whose coupler is a plate carrying a coupler
point C, is assembled, drawn and written as SVG; the SVG is read back with
xml.etree and checked for its symbols, its labels and a scale that measures true.
"""

import io
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path as FilePath

import pytest
from shapely.geometry import Point as SPoint, Polygon

from tarsim.constructions.linkages.assembly import assemble
from tarsim.exercises.catalog import bundled
from tarsim.exercises.linkages.mechanism_file import load_mechanism, parse_mechanism
from tarsim.graphics.linkages.diagram import draw_kinematic_diagram
from tarsim.graphics.export import svg_to
from tarsim.graphics.figure import Circle, Path
from tarsim.graphics.svg import to_svg
from tarsim.graphics.typeset import subscript

SVG = "{http://www.w3.org/2000/svg}"
DATA = FilePath(__file__).parent / "data"

# The bundled four-bar with a 3-4-5-scaled plate for its coupler: AB = 250, AC = 200,
# BC = 150 mm, C left of A → B.
PLATE = (bundled()["four-bar"].read_text(encoding="utf-8")
         .replace('points = ["A", "B"]\nlengths = { AB = 250 }',
                  'points = ["A", "B", "C"]\nlengths = { AB = 250, AC = 200, BC = 150 }\n'
                  'sides = { C = "left" }'))
assert "AC = 200" in PLATE

EXAMPLES = [*bundled(), "plate-coupler"]


def mechanism(name):
    if name == "plate-coupler":
        return parse_mechanism(PLATE, "plate-coupler.toml")
    if name.endswith(".toml"):
        return load_mechanism(DATA / name)
    return load_mechanism(bundled()[name])


class Drawn:
    """One example drawn: the mechanism, the Figure, its SVG text and parsed root."""

    def __init__(self, name):
        self.mech = mechanism(name)
        self.asm = assemble(self.mech)
        self.fig = draw_kinematic_diagram(self.asm)
        self.svg = to_svg(self.fig)
        self.root = ET.fromstring(self.svg)

    def groups(self, cls):
        return [g for g in self.root.iter(SVG + "g") if g.get("class") == cls]

    @property
    def classes(self):
        return {g.get("class") for g in self.root.iter(SVG + "g")}

    @property
    def texts(self):
        return [t.text for t in self.root.iter(SVG + "text")]

    def stated_scale(self):
        """The caption's "Scale 1 cm = N unit" as (N, unit)."""
        (m,) = [re.fullmatch(r"Scale 1 cm = ([\d.]+) (\w+)", t) for t in self.texts
                if t.startswith("Scale ")]
        return float(m.group(1)), m.group(2)

    @property
    def mm_per_metre(self):
        """Paper mm per world metre, from the stated scale."""
        n, _ = self.stated_scale()
        return 10.0 / (n * self.mech.units.metres)

    def paper(self, name_or_xy):
        """Where a point (a name or world xy) is on the page: the stated scale, laid off from
        the θ reference, which starts at the input link's pivot."""
        (ref,) = self.items(Path, "reference")
        o = self.asm.xy(self.mech.link(self.mech.drive.link).names[0])
        x, y = self.asm.xy(name_or_xy) if isinstance(name_or_xy, str) else name_or_xy
        s = self.mm_per_metre
        return (ref.points[0][0] + s * (x - o[0]), ref.points[0][1] - s * (y - o[1]))

    def items(self, cls, style):
        return [it for it in self.fig.items if isinstance(it, cls) and it.style == style]

    def at(self, cls, style, p, tol=1e-6):
        """The ``style`` circles centred at paper point ``p``, or paths with an end there."""
        if cls is Circle:
            return [c for c in self.items(Circle, style) if math.dist(c.centre, p) < tol]
        return [q for q in self.items(Path, style)
                if min(math.dist(q.points[0], p), math.dist(q.points[-1], p)) < tol]


@pytest.fixture(scope="module", params=EXAMPLES)
def drawn(request):
    return Drawn(request.param)


# ----- the page ---------------------------------------------------------------------------
def test_page_is_sized_in_mm_with_a_matching_viewbox(drawn):
    w, h = drawn.root.get("width"), drawn.root.get("height")
    assert w.endswith("mm") and h.endswith("mm")
    assert drawn.root.get("viewBox") == f"0 0 {w[:-2]} {h[:-2]}"
    assert (float(w[:-2]), float(h[:-2])) == pytest.approx((drawn.fig.width, drawn.fig.height))
    # It fits an A4 page in landscape with room to spare.
    assert 40 < float(w[:-2]) < 280 and 40 < float(h[:-2]) < 200


def test_everything_drawn_lies_on_the_page(drawn):
    x0, y0, x1, y1 = drawn.fig.bounds()
    assert 0 <= x0 and 0 <= y0 and x1 <= drawn.fig.width and y1 <= drawn.fig.height


# ----- symbols ------------------------------------------------------------------------------
def test_the_textbook_symbols_are_drawn(drawn):
    m = drawn.mech
    want = {"hatch", "pin", "link", "text", "scale", "scale_fill"}
    assert want <= drawn.classes
    # a ground symbol stands under each fixed pivot; a wheel rolling on the ground as the
    # input needs none
    assert ("ground" in drawn.classes) == any(len(m.links_at(n)) > 1 for n in m.frame.names)
    has_block = any(s.kind == "block" for s in m.slides)
    assert ("block" in drawn.classes) == has_block
    # a block's frame guide, or the ground a wheel rolls on, is drawn hatched
    assert ("guide" in drawn.classes) == any((s.kind == "block" or s.rolling) and
                                             s.guide_link == 1 for s in m.slides)
    # Three or more points make a plate, unless they lie on one line (a straight lever
    # with a third pin is drawn as a bar).
    plates = [k for k in m.links if k.number != 1 and len(k.names) >= 3
              and any(abs(y) > 1e-12 for _, (x, y) in k.points)]
    assert ("plate" in drawn.classes) == bool(plates)


def test_one_ground_symbol_per_fixed_pivot(drawn):
    m = drawn.mech
    pivots = [n for n in m.frame.names if len(m.links_at(n)) > 1]
    triangles = [p for g in drawn.groups("ground") for p in g.iter(SVG + "path")]
    assert len(triangles) == len(pivots)
    assert all(len(g) > 0 for g in drawn.groups("hatch"))


def test_a_pin_at_every_joint(drawn):
    m = drawn.mech
    # A contact stands for two profiles touching, not a pin: a wheel's centre on no other
    # link is drawn as its centre's dot.
    joints = [n for n in m.point_names
              if len(m.links_at(n)) >= 2 or any(s.point == n and s.contact is None
                                                for s in m.slides)]
    circles = [c for g in drawn.groups("pin") for c in g.iter(SVG + "circle")]
    assert len(circles) == len(joints)


def test_a_plate_is_drawn_through_its_three_points():
    d = Drawn("plate-coupler")
    (plate,) = [it for it in d.fig.items if isinstance(it, Path) and it.style == "plate"]
    assert len(plate.points) == 3 and plate.closed
    n, unit = d.stated_scale()
    s = 10.0 / n  # paper mm per mm
    sides = sorted(math.dist(p, q) / s for p, q in zip(plate.points, plate.points[1:] +
                                                          plate.points[:1]))
    assert sides == pytest.approx([150.0, 200.0, 250.0], rel=1e-9)


# ----- labels ---------------------------------------------------------------------------------
def test_every_point_and_link_is_labelled(drawn):
    m = drawn.mech
    texts = drawn.texts
    for name in m.point_names:
        assert subscript(name) in texts, name
    for k in m.links:
        assert str(k.number) in texts, k.number
    assert "θ₂" in texts and "ω₂" in texts


def test_trailing_digits_are_subscripts():
    assert subscript("O2") == "O₂"
    assert subscript("O24") == "O₂₄"
    assert subscript("A") == "A"
    assert subscript("B2x") == "B2x"


def test_caption_states_name_input_and_scale(drawn):
    m = drawn.mech
    texts = drawn.texts
    # the name stands whole, or wrapped to the sheet at its spaces, line after line
    assert m.name in texts or m.name in " ".join(texts)
    (params,) = [t for t in texts if t.startswith("θ₂ = ")]
    d = m.drive
    # ω in the file's unit: rad/s, or rpm (60 / 2π of them to the rad/s)
    rpm = m.units.angular_velocity == "rpm"
    said = f"{abs(d.omega) * 30 / math.pi:.6g} rpm" if rpm else f"{abs(d.omega):.6g} rad/s"
    assert params == (f"θ₂ = {math.degrees(d.angle):.6g}°,  ω₂ = {said} "
                      f"{'ccw' if d.omega > 0 else 'cw'}")
    n, unit = drawn.stated_scale()
    assert unit == m.units.length
    # The bar's labels, drawn last: 0, 2N and 4N with the unit.
    assert texts[-3:] == ["0", f"{2 * n:g}", f"{4 * n:g} {unit}"]


@pytest.mark.parametrize("units, angle, omega, caption", [
    ('angle = "rad"', 0.5, -2.0, "θ₂ = 0.5 rad,  ω₂ = 2 rad/s cw"),
    ('angular_velocity = "rpm"', 60, 120, "θ₂ = 60°,  ω₂ = 120 rpm ccw"),
    ('angle = "deg"', 60, 0, "θ₂ = 60°"),
])
def test_caption_speaks_the_files_units(units, angle, omega, caption):
    text = (bundled()["four-bar"].read_text(encoding="utf-8")
            .replace('angle = "deg"\nangular_velocity = "rad/s"', units)
            .replace("angle = 60 ", f"angle = {angle} ")
            .replace("omega = 10 ", f"omega = {omega} "))
    fig = draw_kinematic_diagram(assemble(parse_mechanism(text, "units.toml")))
    texts = [t.text for t in ET.fromstring(to_svg(fig)).iter(SVG + "text")]
    assert caption in texts
    assert ("ω₂" in texts) == bool(omega)


# ----- determinism ------------------------------------------------------------------------------
def test_same_input_gives_byte_identical_svg(drawn):
    again = to_svg(draw_kinematic_diagram(assemble(drawn.mech)))
    assert again == drawn.svg


def test_svg_does_not_depend_on_the_hash_seed():
    code = ("import sys; from tarsim.exercises.catalog import bundled; "
            "from tarsim.exercises.linkages.mechanism_file import load_mechanism; "
            "from tarsim.constructions.linkages.assembly import assemble; "
            "from tarsim.graphics.linkages.diagram import draw_kinematic_diagram; "
            "from tarsim.graphics.svg import to_svg; "
            "sys.stdout.buffer.write(to_svg(draw_kinematic_diagram(assemble("
            "load_mechanism(bundled()['slotted-lever-p37'])))).encode())")
    runs = [subprocess.run([sys.executable, "-c", code], capture_output=True, check=True,
                           timeout=120, env={**os.environ, "PYTHONHASHSEED": seed}).stdout
            for seed in ("1", "2")]
    assert runs[0] == runs[1]
    assert runs[0] == Drawn("slotted-lever-p37").svg.encode()


# ----- the scale is true ----------------------------------------------------------------------
def _rect(d):
    xs, ys = zip(*((float(x), float(y)) for x, y in re.findall(r"([-\d.]+),([-\d.]+)", d)))
    return min(xs), min(ys), max(xs), max(ys)


def test_scale_bar_cells_are_one_centimetre(drawn):
    cells = sorted(_rect(p.get("d")) for cls in ("scale", "scale_fill")
                   for g in drawn.groups(cls) for p in g.iter(SVG + "path"))
    assert len(cells) == 4
    for (x0, _, x1, _), nxt in zip(cells, cells[1:] + [None]):
        assert x1 - x0 == pytest.approx(10.0, abs=2e-3)  # 1 cm; coordinates printed to 0.001
        if nxt is not None:
            assert nxt[0] == pytest.approx(x1, abs=1e-9)  # contiguous
    fills = [_rect(p.get("d"))[0] for g in drawn.groups("scale_fill") for p in g.iter(SVG + "path")]
    assert sorted(fills) == [cells[0][0], cells[2][0]]  # alternate centimetres filled


def _crank(fig, angle=None):
    """Paper positions of the input link's pivot and tip, from the Figure itself.

    The pivot is where the dashed θ reference starts; the tip is the other end of the
    link bar that starts or ends there, and both carry a pin circle.
    """
    (ref,) = [it for it in fig.items if isinstance(it, Path) and it.style == "reference"]
    pivot = ref.points[0]
    pins = [it.centre for it in fig.items if isinstance(it, Circle) and it.style == "pin"]
    assert min(math.dist(pivot, c) for c in pins) < 1e-9
    bars = [it.points for it in fig.items if isinstance(it, Path) and it.style == "link"]
    # A plate (a ternary input link) is drawn as a closed outline: its edges are bars too.
    bars += [(p, q) for it in fig.items if isinstance(it, Path) and it.style == "plate"
             for p, q in zip(it.points, it.points[1:] + it.points[:1])]
    ends = [q if math.dist(p, pivot) < 1e-9 else p for p, q in bars
            if min(math.dist(p, pivot), math.dist(q, pivot)) < 1e-9]
    tips = [e for e in ends if min(math.dist(e, c) for c in pins) < 1e-9]
    if len(tips) > 1 and angle is not None:     # the one along the input's axis, at θ
        tips = [e for e in tips if abs(math.remainder(
            math.atan2(pivot[1] - e[1], e[0] - pivot[0]) - angle, math.tau)) < 1e-9]
    assert len(tips) == 1
    return pivot, tips[0]


def test_stated_scale_is_the_drawn_crank_over_its_true_length(drawn):
    m = drawn.mech
    n, unit = drawn.stated_scale()
    if m.rolling_input is not None:       # no crank: the wheel's circle about its centre
        (ref,) = [it for it in drawn.fig.items if isinstance(it, Path) and it.style == "reference"]
        (wheel,) = [it for it in drawn.fig.items if isinstance(it, Circle) and it.style == "link"
                    and math.dist(it.centre, ref.points[0]) < 1e-9]
        true = m.rolling_input.contact.circle.radius / m.units.metres
        assert wheel.radius * n / 10.0 == pytest.approx(true, rel=1e-9)
        return
    k = m.link(m.drive.link)
    true = k.span(k.names[0], k.names[1]) / m.units.metres  # in the file's unit
    pivot, tip = _crank(drawn.fig, m.drive.angle)
    # In the Figure, coordinates are unrounded floats: a few ulps of 100 mm.
    assert math.dist(pivot, tip) * n / 10.0 == pytest.approx(true, rel=1e-9)
    # In the SVG, each coordinate is printed to 0.001 mm, so the distance between two
    # pin centres is good to 2·√2·0.0005 < 0.0015 mm of paper.
    centres = [(float(c.get("cx")), float(c.get("cy")))
               for g in drawn.groups("pin") for c in g.iter(SVG + "circle")]
    near = [min(centres, key=lambda c: math.dist(c, p)) for p in (pivot, tip)]
    assert all(math.dist(c, p) < 1e-3 for c, p in zip(near, (pivot, tip)))  # the SVG is the Figure
    assert math.dist(*near) * n / 10.0 == pytest.approx(true, abs=0.0015 * n / 10.0)


def test_four_bar_crank_measures_100_mm_at_the_stated_scale():
    d = Drawn("four-bar")
    n, unit = d.stated_scale()
    assert (n, unit) == (20.0, "mm")  # 1 cm = 20 mm: 337.9 mm wide fits 150 mm of paper
    pivot, tip = _crank(d.fig)
    assert math.dist(pivot, tip) == pytest.approx(50.0, rel=1e-12)  # 100 mm at 1:2
    assert math.dist(pivot, tip) * n / 10.0 == pytest.approx(100.0, rel=1e-12)


# ----- PDF and PNG --------------------------------------------------------------------------------
def test_pdf_page_is_the_svg_page_in_points(drawn):
    pdf = svg_to(drawn.svg, "pdf")
    assert pdf.startswith(b"%PDF")
    boxes = re.findall(rb"/MediaBox\s*\[\s*([-\d.]+)\s+([-\d.]+)\s+([-\d.]+)\s+([-\d.]+)\s*\]", pdf)
    assert len(boxes) == 1
    x0, y0, x1, y1 = map(float, boxes[0])
    pt = 72 / 25.4
    # cairo prints the box to 6 decimals of a point.
    assert (x0, y0) == (0.0, 0.0)
    assert (x1, y1) == pytest.approx((drawn.fig.width * pt, drawn.fig.height * pt), abs=1e-5)


def test_png_renders_and_is_not_blank(drawn):
    from PIL import Image

    png = svg_to(drawn.svg, "png", dpi=200)
    img = Image.open(io.BytesIO(png))
    px = 200 / 25.4
    assert img.size[0] == pytest.approx(drawn.fig.width * px, abs=1)
    assert img.size[1] == pytest.approx(drawn.fig.height * px, abs=1)
    grey = img.convert("L")
    hist = grey.histogram()
    inked = sum(hist[:250]) / sum(hist)
    # A thin-line drawing: a few percent of the page, never empty and never a black page.
    assert 0.01 < inked < 0.60, inked


# ----- curved guides, curved slots, circle contacts, rolling --------------------------------
def test_a_block_on_a_curved_guide_rides_a_hatched_arc_with_its_centre_a_bare_dot():
    d = Drawn("curved-guide-slider-crank.toml")
    (arc,) = d.mech.arcs
    b, c = d.paper(arc.point), d.paper(arc.centre)
    # The block's stand-in pin at the centre is no part of the figure: no bar B–C, no
    # pin or ground pivot at C (the one ground symbol is O2's), only a dot.
    assert not [q for q in d.at(Path, "link", b)
                if min(math.dist(e, c) for e in q.points) < 1e-6]
    assert not d.at(Circle, "pin", c) and d.at(Circle, "pin", b)
    assert len(d.items(Path, "ground")) == 1 and d.at(Circle, "arrowhead", c)
    # The guide is an arc about C, half the block's height (2.5 mm) off B's path.
    r = arc.radius * d.mm_per_metre
    (guide,) = d.items(Path, "guide")
    offs = [math.dist(p, c) - r for p in guide.points]
    assert offs == pytest.approx([offs[0]] * len(offs), abs=1e-9)
    assert abs(offs[0]) == pytest.approx(2.5, abs=1e-9)
    assert any(math.dist(p, b) < 25.0 for p in guide.points)  # round the block, not elsewhere
    # Hatched on its far side from B, in the band 1.8 mm deep.
    side = math.copysign(1.0, offs[0])
    hatch = [p for h in d.items(Path, "hatch") for p in h.points
             if abs(math.dist(p, c) - r) < 5.0]
    assert len(hatch) > 20
    # (The band is a polygon of 1.2 mm chords, so it cuts inside the arc by up to 0.002 mm.)
    assert all(-0.01 <= side * (math.dist(p, c) - r - offs[0]) <= 1.8 + 0.01 for p in hatch)
    # The block stands at B tangent to the arc: its long sides square to the radius CB.
    (block,) = d.items(Path, "block")
    corners = block.points
    assert math.dist(_centroid(corners), b) < 1e-9
    e = max(((p, q) for p, q in zip(corners, corners[1:] + corners[:1])),
            key=lambda pq: math.dist(*pq))
    along = (e[1][0] - e[0][0], e[1][1] - e[0][1])
    assert abs(along[0] * (b[0] - c[0]) + along[1] * (b[1] - c[1])) < 1e-9 * r * r
    assert "C" in d.texts


def test_a_roller_on_a_circular_cam_is_two_circles_touching_at_p():
    d = Drawn("roller-cam.toml")
    (arc,) = d.mech.arcs
    s = d.mm_per_metre
    cam, roller = d.paper(arc.centre), d.paper(arc.point)
    circles = d.items(Circle, "link")
    for centre, radius in ((cam, arc.contact.face.radius), (roller, arc.contact.circle.radius)):
        assert [c for c in circles if math.dist(c.centre, centre) < 1e-6
                and c.radius == pytest.approx(radius * s, rel=1e-12)], radius
    # P is on the line of centres, on the cam's rim: the circles' radii add to CR.
    assert math.dist(cam, roller) == pytest.approx(
        (arc.contact.face.radius + arc.contact.circle.radius) * s, rel=1e-9)
    f = arc.contact.face.radius * s / math.dist(cam, roller)
    p = (cam[0] + f * (roller[0] - cam[0]), cam[1] + f * (roller[1] - cam[1]))
    assert d.at(Circle, "arrowhead", p) and "P" in d.texts
    # The roller's centre is the follower's pin; the cam's centre, no joint, is a dot.
    assert d.at(Circle, "pin", roller) and not d.at(Circle, "pin", cam)
    assert d.at(Circle, "arrowhead", cam)


def test_a_pin_in_a_curved_slot_sits_in_a_slot_about_k_carried_by_the_lever():
    d = Drawn("curved-slot.toml")
    (arc,) = d.mech.arcs
    k, a = d.paper(arc.centre), d.paper(arc.point)
    r = arc.radius * d.mm_per_metre
    lever = d.mech.link(arc.guide_link)
    pivot = d.paper(lever.names[0])
    # The slot: a closed outline within a pin's width of the arc about K, round the pin.
    slots = [q for q in d.items(Path, "link") if q.closed]
    (slot,) = slots
    assert all(abs(math.dist(p, k) - r) <= 1.6 + 1e-9 for p in slot.points)
    assert Polygon(slot.points).contains(SPoint(a).buffer(1.25))
    assert d.at(Circle, "pin", a)
    # The lever runs from its pivot to the slot, not to K, which is a bare dot.
    (bar,) = d.at(Path, "link", pivot)
    end = bar.points[-1] if math.dist(bar.points[0], pivot) < 1e-6 else bar.points[0]
    assert abs(math.dist(end, k) - r) == pytest.approx(1.6, abs=1e-9)
    assert not d.at(Path, "link", k) and not d.at(Circle, "pin", k)
    assert d.at(Circle, "arrowhead", k)


def test_the_ground_a_wheel_rolls_on_is_hatched_on_the_far_side():
    d = Drawn("rolling-wheel.toml")
    (s,) = d.mech.slides
    g, wheel = d.paper(s.contact.face.through), d.paper(s.point)
    (ground,) = d.items(Path, "guide")
    ys = [p[1] for p in ground.points]
    assert ys == pytest.approx([g[1]] * 2, abs=1e-9)  # the face through G, level
    lo, hi = sorted(p[0] for p in ground.points)
    assert lo <= wheel[0] <= hi
    # The wheel stands above the face (paper y grows down), so the hatching is below it.
    assert wheel[1] < g[1]
    hatch = [p for h in d.items(Path, "hatch") for p in h.points if lo - 1 <= p[0] <= hi + 1
             and abs(p[1] - g[1]) < 3.0]
    assert len(hatch) > 40
    assert all(g[1] - 1e-6 <= p[1] <= g[1] + 1.8 + 1e-6 for p in hatch)


def _centroid(pts):
    return (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))


def test_a_lever_with_its_block_behind_the_pivot_runs_through_the_pivot_to_the_block():
    """The block A rides the slot on the far side of O4 from B: the bar is B → O4 → A, not
    O4 → B with the block left floating."""
    from dataclasses import replace

    from tests.common import inverted_slider_crank
    m = replace(inverted_slider_crank(math.radians(60)), branches={"A": "backward"})
    asm = assemble(m)
    fig = draw_kinematic_diagram(asm)
    (per_cm,) = [float(t.text.split("=")[1].split()[0]) for t in fig.items
                 if getattr(t, "text", "").startswith("Scale 1 cm =")]
    bars = [math.dist(*it.points) for it in fig.items if isinstance(it, Path)
            and it.style == "link"]
    span_ab = math.dist(asm.xy("A"), asm.xy("B")) * 1000.0 * 10.0 / per_cm   # paper mm
    assert max(bars) >= span_ab - 1e-9 and max(bars) <= span_ab + 2.0 + 1e-9


def test_a_plates_tint_lies_under_every_construction_line():
    """A Kennedy line across the coupler plate shows through it: the tint is drawn first."""
    from tarsim.constructions.linkages.kennedy import locate_centres
    from tarsim.constructions.record import Kind, Slice
    from tarsim.graphics.linkages.scene import draw_scene
    asm = assemble(load_mechanism(bundled()["hinkle-four-bar"]))
    locate_centres(asm)
    c = asm
    shown = Slice(c, tuple(s.id for s in c if s.kind in (Kind.CENTRE, Kind.KENNEDY_LINE)))
    styles = [getattr(it, "style", "") for it in draw_scene(shown).items]
    assert "plate_fill" in styles and "plate" in styles
    lines = [i for i, s in enumerate(styles) if s in ("kennedy", "construction", "working")]
    assert lines and max(i for i, s in enumerate(styles) if s == "plate_fill") < min(lines)
