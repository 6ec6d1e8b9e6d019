"""Tests for graphics.scene and graphics.circle_diagram: instant-centre and velocity figures.

Each figure is written as SVG and read back with xml.etree; the checks are on
what a reader sees: the chords of the circle diagram, the centre labels, the
"→ ∞" marker, the arrows at the page's edge, step numbers 1..k, and a velocity
scale statement that a ruler would confirm on the drawn vectors.
"""

import math
import re
import xml.etree.ElementTree as ET
from dataclasses import replace

import pytest

from tarsim.constructions.narration import narrate
from tarsim.constructions.reference.solver import solve
from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.linkages.kennedy import locate_centres
from tarsim.constructions.record import Kind, Role, Slice, slice
from tarsim.constructions.linkages.velocity_by_centres import velocity_by_radius_rotation
from tarsim.exercises.catalog import bundled
from tarsim.exercises.linkages.mechanism_file import load_mechanism
from tarsim.graphics.linkages.circle_diagram import draw_circle_diagram, triangle_text
from tarsim.graphics.linkages.diagram import draw_kinematic_diagram
from tarsim.graphics.figure import Figure, Path, Text
from tarsim.constructions.scales import choose_scales, velocity_per_cm
from tarsim.graphics.linkages.scene import draw_scene
from tarsim.graphics.linkages.scene_lines import line_style
from tarsim.graphics.svg import to_svg
from tarsim.graphics.typeset import typeset
from tests.common import four_bar, offset_slider_crank

SVG = "{http://www.w3.org/2000/svg}"
DATA = __import__("pathlib").Path(__file__).parent / "data"


def D(deg):
    return math.radians(deg)


def every_centre(cs) -> Slice:
    """The whole centre construction, in the order a student draws it."""
    return Slice(cs.assembly, tuple(cs.construction_refs()))


def circle_diagram(cs, **kw):
    """The circle diagram of every centre ``cs`` found."""
    c = cs.assembly
    return draw_circle_diagram(slice(c, [x.ref for x in cs.found.values()]),
                               title=cs.assembly.mechanism.name, **kw)


class Read:
    """An SVG read back: groups by class, texts, page box and every drawn coordinate."""

    def __init__(self, svg: str):
        self.svg = svg
        self.root = ET.fromstring(svg)
        _, _, w, h = (float(v) for v in self.root.get("viewBox").split())
        self.page = (w, h)

    def groups(self, cls):
        return [g for g in self.root.iter(SVG + "g") if g.get("class") == cls]

    def paths(self, cls):
        return [_points(p.get("d")) for g in self.groups(cls) for p in g.iter(SVG + "path")]

    @property
    def texts(self):
        return ["".join(t.itertext()) for t in self.root.iter(SVG + "text")]

    def all_points(self):
        for p in self.root.iter(SVG + "path"):
            yield from _points(p.get("d"))
        for c in self.root.iter(SVG + "circle"):
            x, y, r = (float(c.get(k)) for k in ("cx", "cy", "r"))
            yield from ((x - r, y - r), (x + r, y + r))

    def badges(self):
        """The numbers written in step circles: texts centred on a badge circle."""
        centres = [(float(c.get("cx")), float(c.get("cy")))
                   for g in self.groups("badge") for c in g.iter(SVG + "circle")]
        out = []
        for t in self.root.iter(SVG + "text"):
            x, y, size = float(t.get("x")), float(t.get("y")), float(t.get("font-size"))
            if any(abs(x - cx) < 1e-3 and abs(y - 0.35 * size - cy) < 1e-3 for cx, cy in centres):
                out.append(int(t.text))
        return out


def _points(d):
    nums = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", d)]
    return list(zip(nums[0::2], nums[1::2]))


def centres_of(mech):
    asm = assemble(mech)
    return asm, locate_centres(asm)


def watt():
    return centres_of(load_mechanism(DATA / "watt-six-bar.toml"))


# ----- the circle diagram --------------------------------------------------------------------
@pytest.mark.parametrize("make, n", [
    (lambda: centres_of(four_bar(D(60))), 4),
    (lambda: centres_of(replace(load_mechanism(bundled()["crank-shaper"]))), 5),
    (watt, 6),
])
def test_circle_diagram_has_a_chord_per_centre_dashed_for_the_secondaries(make, n):
    asm, cs = make()
    read = Read(to_svg(circle_diagram(cs)))
    solid, dashed = read.paths("chord"), read.paths("chord_secondary")
    assert len(dashed) == len(cs.secondaries)
    assert len(solid) == len(cs.primaries)
    assert len(solid) + len(dashed) == n * (n - 1) // 2
    # Every dashed chord carries its discovery number, once.
    assert sorted(read.badges()) == list(range(1, len(cs.secondaries) + 1))
    # n numbered nodes, link 1 at the top and link 2 clockwise from it (to the right).
    nodes = {int(t.text): (float(t.get("x")), float(t.get("y")))
             for t in read.root.iter(SVG + "text") if t.get("font-size") == "3.8"}
    assert sorted(nodes) == list(range(1, n + 1))
    assert nodes[1][1] == min(y for _, y in nodes.values())
    assert nodes[2][0] > nodes[1][0]


def test_circle_diagram_caption_counts_and_lists_the_secondaries_as_the_notes_do():
    asm, cs = watt()
    texts = Read(to_svg(circle_diagram(cs))).texts
    assert "n = 6 links, N = n(n−1)/2 = 15 centres: 7 by inspection, 8 by Kennedy" in texts
    # 000-part1 §3.8, homework 3 (Watt-I six-bar): I15 from Δ125 and Δ165, I14 from Δ124, Δ134.
    listed = [t for t in texts if re.match(r"\d+\. I", t)]
    assert len(listed) == 8
    assert "1. I₁₄: Δ124, Δ134" in listed
    assert "2. I₁₅: Δ125, Δ165" in listed


def test_a_common_normal_is_named_in_the_list():
    mech = load_mechanism(bundled()["crank-shaper"])
    asm, cs = centres_of(mech.with_drive(replace(mech.drive, angle=D(-44.072))))
    i45 = cs.centre(4, 5)
    assert triangle_text(i45) == ["common normal", "Δ415"]
    assert "3. I₄₅: common normal, Δ415" in Read(to_svg(circle_diagram(cs))).texts


def test_circle_diagram_up_to_a_discovery_shades_its_two_triangles():
    asm, cs = watt()
    read = Read(to_svg(circle_diagram(cs, upto=4)))
    assert len(read.paths("chord_secondary")) == 3
    assert len(read.paths("chord_current")) == 1
    triangles = read.paths("triangle") + read.paths("triangle_alt")
    assert len(triangles) == 2
    assert sorted(read.badges()) == [1, 2, 3, 4]
    assert "Found by Kennedy, the first 4 of 8:" in read.texts


# ----- the scene: centres ---------------------------------------------------------------
def test_every_centre_of_the_four_bar_is_labelled_and_numbered_in_order():
    asm, cs = centres_of(four_bar(D(60), omega2=10))
    shown = every_centre(cs)
    read = Read(to_svg(draw_scene(shown)))
    for c in cs.found.values():
        assert typeset(c.label)[0] in read.texts
    numbered = shown.numbered()
    # 4 pins, then for I13 and I24 two Kennedy lines and the centre: 10 steps. On the
    # figure only the two centres found by Kennedy carry theirs: a pin is found by the
    # mechanism and a Kennedy line by the two centres it joins.
    assert [n for n, _ in numbered] == list(range(1, 11))
    assert [s.id for _, s in numbered] == list(shown.refs)
    assert sorted(read.badges()) == [n for n, s in numbered
                                     if s.id in (cs.centre(1, 3).ref, cs.centre(2, 4).ref)]
    assert len(read.badges()) == 2
    assert len(read.paths("kennedy")) == 4 + 1          # and the legend's sample
    assert "Kennedy line" in read.texts


def test_a_centre_at_infinity_gets_the_infinity_marker():
    asm, cs = centres_of(offset_slider_crank(D(60), omega2=10))
    read = Read(to_svg(draw_scene(every_centre(cs))))
    assert "I₁₄ → ∞" in read.texts
    # A two-headed arrow: two arrowheads whose tips lie in opposite senses across the guide.
    heads = read.paths("arrowhead")
    vertical = [h for h in heads if abs(h[0][0] - h[2][0]) < 1e-6]   # tip over the notch
    assert len(vertical) >= 2


def test_a_far_centre_is_an_arrow_at_the_edge_and_nothing_leaves_the_page():
    # At θ2 = 130° crank and rocker are nearly parallel: I13 lies some 20 m away.
    asm, cs = centres_of(four_bar(D(130), omega2=10))
    far = cs.point(1, 3).xy
    assert math.dist(far, asm.xy("O4")) > 10.0
    read = Read(to_svg(draw_scene(every_centre(cs))))
    assert read.paths("edge_arrow")
    (label,) = [t for t in read.texts if t.startswith("to I₁₃")]
    metres = float(re.search(r"([\d.]+) m from", label).group(1))
    nearest = min(math.dist(far, asm.xy(n)) for n in asm.mechanism.point_names)
    assert metres == pytest.approx(nearest, rel=1e-3)
    w, h = read.page
    for x, y in read.all_points():
        assert -1e-6 <= x <= w + 1e-6 and -1e-6 <= y <= h + 1e-6


def test_coincident_centres_share_one_label():
    # An in-line slider-crank at dead centre: I13 ≡ I34 at the piston pin, I24 ≡ I12 at O2.
    asm, cs = centres_of(offset_slider_crank(0.0, offset=0.0, omega2=5))
    texts = Read(to_svg(draw_scene(every_centre(cs)))).texts
    assert "I₁₂ ≡ I₂₄" in texts
    assert "I₃₄ ≡ I₁₃" in texts


def test_common_normals_and_kennedy_lines_read_differently_with_a_legend():
    mech = load_mechanism(bundled()["crank-shaper"])
    asm, cs = centres_of(mech.with_drive(replace(mech.drive, angle=D(-44.072))))
    notes = ["I24 is ill-conditioned: lines meet at 0.002°"]
    read = Read(to_svg(draw_scene(every_centre(cs), notes=notes)))
    assert read.paths("normal") and read.paths("kennedy")
    styles = {g.get("class"): g.get("stroke-dasharray") for g in read.root.iter(SVG + "g")}
    assert styles["normal"] != styles["kennedy"]
    assert {"Kennedy line", "common normal"} <= set(read.texts)
    assert notes[0] in read.texts
    assert {"I₃₄ → ∞", "I₁₅ → ∞"} <= set(read.texts)


@pytest.mark.slow
def test_the_output_is_byte_identical_on_repeat():
    def once():
        asm, cs = watt()
        return to_svg(draw_scene(every_centre(cs), notes=[narrate(w) for w in cs.warnings()])), \
            to_svg(circle_diagram(cs))
    assert once() == once()


# ----- the scene: velocities ----------------------------------------------------------------------
def velocity_scene(theta=60.0):
    mech = four_bar(D(theta), omega2=10)
    asm, cs = centres_of(mech)
    scale = choose_scales(asm).vector      # for V_A = ω2·O2A = 1 m/s
    r = velocity_by_radius_rotation(asm, cs, "B", scale=scale)
    refs = [cs.centre(1, 2).ref, cs.centre(2, 3).ref, cs.centre(3, 4).ref,
            *cs.centre(1, 3).lines, cs.centre(1, 3).ref, *r.steps]
    shown = Slice(asm, tuple(dict.fromkeys(refs)))
    fig = draw_scene(shown, title="V_B by radius rotation", velocity_scale=scale)
    return mech, asm, shown, fig, scale


def arrow_length(read, cls):
    """Length of each arrow drawn in ``cls``: shaft start to the tip of its arrowhead."""
    tips = [h[0] for h in read.paths("arrowhead")]
    out = []
    for start, end in read.paths(cls):
        tip = min(tips, key=lambda t: math.dist(t, end))
        out.append(math.dist(start, tip))
    return out


def test_the_stated_velocity_scale_is_true_on_the_drawn_vectors():
    mech, asm, refs, fig, scale = velocity_scene()
    read = Read(to_svg(fig))
    (stated,) = [re.fullmatch(r"Velocity scale 1 cm = ([\d.]+) m/s", t) for t in read.texts
                 if t.startswith("Velocity scale")]
    per_cm = float(stated.group(1))
    assert per_cm in (0.1, 0.2, 0.5, 1.0, 2.0, 5.0)
    kin = solve(mech)
    # SVG coordinates are written to 0.001 mm: about 1e-4 of a 10 mm vector.
    (v_a,) = arrow_length(read, "vector")
    assert v_a / 10 * per_cm == pytest.approx(math.hypot(*kin.velocities["A"]), rel=3e-4)
    (v_b,) = arrow_length(read, "vector_result")
    assert v_b / 10 * per_cm == pytest.approx(math.hypot(*kin.velocities["B"]), rel=3e-4)
    # The input speed is drawn 20–35 mm long, as velocity_per_cm promises.
    assert 20.0 - 1e-2 <= v_a <= 35.0


@pytest.mark.parametrize("omega", [0.123, 3.0, 10.0, 27.2, 77.0, 400.0, 9500.0])
def test_the_chosen_velocity_scale_is_nice_and_about_20_to_35_mm(omega):
    asm = assemble(four_bar(D(60), omega2=omega))
    speed = omega * 0.1                             # V_A = ω2·O2A, m/s
    scale = choose_scales(asm).vector
    mm_per_m = 10.0 / 0.02                          # the four-bar is drawn at 1 cm = 0.02 m
    mm = speed * scale * mm_per_m
    per_cm = 10.0 * speed / mm                      # m/s per cm of paper
    mantissa = per_cm / 10 ** math.floor(math.log10(per_cm) + 1e-9)
    assert min(abs(mantissa - m) for m in (1, 2, 5)) < 1e-9
    assert 16.0 <= mm <= 44.0                       # within a nice step of the 20–35 band


def test_a_velocity_scale_needs_a_moving_input():
    with pytest.raises(TarsimError, match="positive speed"):
        velocity_per_cm(0.0)
    assert choose_scales(assemble(four_bar(D(60)))).velocity is None


def test_a_vector_label_has_a_true_subscript():
    _, _, _, fig, _ = velocity_scene()
    read = Read(to_svg(fig))
    subs = [(t.text, s.text) for t in read.root.iter(SVG + "text") for s in t.iter(SVG + "tspan")]
    assert ("V", "A") in subs and ("V", "B") in subs
    assert read.paths("gauge") and "gauge line" in read.texts


def test_the_swung_radius_ends_in_an_arrowhead_at_the_rotated_point():
    _, asm, _, fig, _ = velocity_scene()
    arcs = [it for it in fig.items if isinstance(it, Path) and it.style == "compass"]
    (arc,) = arcs
    heads = [it.points[0] for it in fig.items if isinstance(it, Path) and it.style == "arrowhead"]
    assert min(math.dist(arc.points[-1], h) for h in heads) < 1e-9
    assert min(math.dist(arc.points[0], h) for h in heads) > 1.0
    # The start is the pin B (the swung point); B′, the rotated one, is labelled at the end.
    assert "B′" in [it.text for it in fig.items if isinstance(it, Text)]


def test_step_numbers_run_from_one_and_skip_givens_and_the_mechanism():
    _, asm, shown, fig, _ = velocity_scene()
    numbered = shown.numbered()
    k = len(numbered)
    assert [n for n, _ in numbered] == list(range(1, k + 1))
    assert all(s.role is not Role.GIVEN for _, s in numbered)
    assert "V:A" in shown and "V:A" not in [s.id for _, s in numbered]   # the given V_A
    # On the figure, all but the pins' centres and the Kennedy lines (found by what they
    # join): I13 and the radius rotation's steps, but for I14, the pin O4 it swings about.
    plain = [n for n, s in numbered if s.kind is not Kind.KENNEDY_LINE
             and not (s.about is not None and getattr(s.about, "order", None) == 0)]
    assert sorted(Read(to_svg(fig)).badges()) == plain
    assert len(plain) == k - 6          # I12, I23, I34, I14 and the two lines to I13


def test_numbered_steps_of_a_slice_follow_the_record():
    _, asm, _, _, _ = velocity_scene()
    c = asm
    numbered = slice(c, ["rr:B:V"]).numbered()
    order = list(c.steps)
    ids = [s.id for _, s in numbered]
    assert ids == sorted(ids, key=order.index)
    assert not any(i.startswith("P:") for i in ids)
    with pytest.raises(TarsimError, match="nothing in the construction is called 'nope'"):
        slice(c, ["nope"])


def test_line_styles_follow_the_kind_of_step():
    asm, cs = centres_of(four_bar(D(60)))
    c = asm
    assert line_style(c["K:13/2"]) == "kennedy"
    assert line_style(c["axis:2"]) == "working"          # the mechanism's own line
    _, asm, _, _, _ = velocity_scene()
    assert line_style(asm["rr:B:gauge:j"]) == "gauge"
    assert line_style(asm["v:perp:A"]) == "working"


def test_typeset_sets_subscripts_as_the_notes_write_them():
    assert typeset("V_A") == ("V", "A")
    assert typeset("V_I23") == ("V", "I₂₃")
    assert typeset("I13") == ("I₁₃", "")
    assert typeset("gauge line of link 3") == ("gauge line of link 3", "")


def test_a_subscript_is_a_tspan_dropped_below_the_baseline_and_set_from_its_left_end():
    fig = Figure(40, 20)
    fig.add(Text((20, 10), "V", 4.0, "middle", sub="I₂₃"))
    text = ET.fromstring(to_svg(fig)).find(f".//{SVG}text")
    (tspan,) = text.iter(SVG + "tspan")
    assert text.get("text-anchor") == "start"           # cairosvg would anchor "V" alone
    assert float(text.get("x")) == pytest.approx(20 - Text((20, 10), "V", 4.0, sub="I₂₃").width / 2,
                                                abs=1e-3)
    assert float(tspan.get("dy")) > 0 and float(tspan.get("font-size")) < 4.0


def test_a_vector_at_a_far_centre_stays_off_the_page_and_its_number_rides_the_edge_arrow():
    """Rolling wheel at 70°: V_M by radius rotation transfers through I24, 342 mm off the
    page. Drawn whole, V_I24 would stretch the page several times over; it is left out,
    and its step number goes beside the edge arrow pointing to I24."""
    mech = load_mechanism(DATA / "rolling-wheel.toml")
    asm, cs = centres_of(mech)
    scale = choose_scales(asm).vector
    r = velocity_by_radius_rotation(asm, cs, "M", scale=scale)
    shown = slice(asm, r.answer)
    plain = Read(to_svg(draw_kinematic_diagram(asm)))
    read = Read(to_svg(draw_scene(shown, velocity_scale=scale)))
    # The caption's velocity scale bar adds a 13 mm row the plain diagram has not.
    assert read.page[0] < 1.6 * plain.page[0] and read.page[1] < 1.6 * plain.page[1] + 13.0
    at_i24 = next(s for s in r.steps if asm[s].label.startswith("V_I"))
    numbers = dict(shown.numbered())
    number = next(n for n, s in numbers.items() if s.id == at_i24)
    assert number in read.badges()
    far = next(t for t in read.texts if t.startswith("to I"))
    assert "342.2 mm" in far


def test_a_scene_is_a_slice_of_a_mechanisms_record():
    from tarsim.constructions.record import Construction
    with pytest.raises(TarsimError, match="a scene is a slice of a mechanism's record"):
        draw_scene(Slice(Construction(), ()))
    asm = assemble(four_bar(D(60)))          # the position's record itself
    assert isinstance(asm, Construction) and asm.position_steps == frozenset(asm.steps)
    read = Read(to_svg(draw_scene(slice(asm, []))))
    assert not read.paths("working") and not read.badges()   # the mechanism alone
