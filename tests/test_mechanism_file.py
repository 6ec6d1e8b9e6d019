"""Tests for exercises.mechanism_file: units to SI, link shapes, and errors that say file:line.

The texts are inline and based on exercises/catalog/four-bar.toml. Line numbers in
the error tests are counted by hand in FOUR_BAR (numbered in the comment below);
every edit replaces one line with one line, so the count holds.
"""

import math

import pytest

from tarsim.constructions.errors import InputError, TarsimError
from tarsim.exercises.linkages.mechanism_file import load_mechanism, parse_mechanism

FILE = "bench.toml"

# Line numbers:   1  name, 3 [units], 4 length, 8 [frame], 9 O2, 10 O4,
# 12 [[link]] (#1), 13 number = 2, 15 lengths O2A, 17 [[link]] (#2), 20 lengths AB,
# 22 [[link]] (#3), 25 lengths O4B, 27 [input], 28 link, 29 angle, 30 omega, 31 alpha,
# 33 [assembly], 34 B.
FOUR_BAR = """\
name = "Four-bar crank-rocker"

[units]
length = "mm"
angle = "deg"
angular_velocity = "rad/s"

[frame]
O2 = [0, 0]
O4 = [300, 0]

[[link]]
number = 2
points = ["O2", "A"]
lengths = { O2A = 100 }

[[link]]
number = 3
points = ["A", "B"]
lengths = { AB = 250 }

[[link]]
number = 4
points = ["O4", "B"]
lengths = { O4B = 200 }

[input]
link = 2
angle = 60
omega = 10
alpha = 0

[assembly]
B = "left"
"""

# A five-bar: 3(5 − 1) − 2·5 = 2 degrees of freedom with one input.
FIVE_BAR = """\
[frame]
O2 = [0, 0]
O5 = [400, 0]

[[link]]
number = 2
points = ["O2", "A"]
lengths = { O2A = 100 }

[[link]]
number = 3
points = ["A", "B"]
lengths = { AB = 250 }

[[link]]
number = 4
points = ["B", "C"]
lengths = { BC = 250 }

[[link]]
number = 5
points = ["O5", "C"]
lengths = { O5C = 200 }

[input]
link = 2
angle = 60
"""


def edit(text: str, old: str, new: str) -> str:
    """Replace ``old`` (which must occur exactly once) by ``new``."""
    assert text.count(old) == 1, old
    return text.replace(old, new)


def four_bar(units: str = "", **swap: str) -> str:
    """FOUR_BAR with its [units] body replaced by ``units`` and the ``swap`` edits made."""
    text = FOUR_BAR
    if units:
        text = edit(text, 'length = "mm"\nangle = "deg"\nangular_velocity = "rad/s"\n', units)
    for old, new in swap.values():
        text = edit(text, old, new)
    return text


def parse_error(text: str) -> InputError:
    with pytest.raises(InputError) as info:
        parse_mechanism(text, FILE)
    return info.value


# ----- units: every number leaves the parser in SI --------------------------------------
# Each value is one multiplication by the unit's size, so it is within an ulp or two of
# the exact SI number; rel=1e-15 leaves room for that and nothing more.
EXACT = dict(rel=1e-15, abs=1e-300)


def test_the_bundled_four_bar_text_parses_to_si():
    m = parse_mechanism(FOUR_BAR, FILE)
    assert m.name == "Four-bar crank-rocker"
    assert m.source == FILE
    assert m.frame.points == (("O2", (0.0, 0.0)), ("O4", pytest.approx((0.3, 0.0), **EXACT)))
    assert m.link(2).local("A") == pytest.approx((0.1, 0.0), **EXACT)
    assert m.link(3).span("A", "B") == pytest.approx(0.25, **EXACT)
    assert m.link(4).span("O4", "B") == pytest.approx(0.2, **EXACT)
    assert (m.drive.link, m.drive.angle, m.drive.omega) == (2, pytest.approx(math.pi / 3, **EXACT),
                                                            10.0)
    assert m.branches == {"B": "left"}
    assert m.mobility()[0] == 1


@pytest.mark.parametrize("unit, o4, crank, coupler", [
    ("mm", 300, 100, 250),
    ("cm", 30, 10, 25),
    ("m", 0.3, 0.1, 0.25),
    ("in", 12, 4, 10),
])
def test_lengths_convert_to_metres(unit, o4, crank, coupler):
    size = {"mm": 1e-3, "cm": 1e-2, "m": 1.0, "in": 0.0254}[unit]
    text = four_bar(f'length = "{unit}"\n',
                    a=("O4 = [300, 0]", f"O4 = [{o4}, 0]"),
                    b=("O2A = 100", f"O2A = {crank}"),
                    c=("AB = 250", f"AB = {coupler}"),
                    d=("O4B = 200", f"O4B = {coupler * 0.8}"))
    m = parse_mechanism(text, FILE)
    assert m.units.length == unit
    assert m.frame.local("O4") == pytest.approx((o4 * size, 0.0), **EXACT)
    assert m.link(2).span("O2", "A") == pytest.approx(crank * size, **EXACT)
    assert m.link(3).span("A", "B") == pytest.approx(coupler * size, **EXACT)


def test_inches_are_exactly_25_4_mm():
    m = parse_mechanism(four_bar('length = "in"\n'), FILE)
    assert m.frame.local("O4") == pytest.approx((7.62, 0.0), **EXACT)  # 300 in
    assert m.link(2).span("O2", "A") == pytest.approx(2.54, **EXACT)  # 100 in


@pytest.mark.parametrize("units, angle, omega, want_angle, want_omega", [
    ('angle = "deg"\nangular_velocity = "rad/s"\n', "60", "10", math.pi / 3, 10.0),
    ('angle = "rad"\n', "0.5", "10", 0.5, 10.0),
    ('angular_velocity = "rpm"\n', "60", "60", math.pi / 3, 2 * math.pi),
    ('angle = "deg"\nangular_velocity = "rpm"\n', "-90", "-30", -math.pi / 2, -math.pi),
    ("", "60", "10", math.pi / 3, 10.0),  # defaults: mm, deg, rad/s
])
def test_angles_and_speeds_convert_to_radians(units, angle, omega, want_angle, want_omega):
    text = FOUR_BAR.replace('[units]\nlength = "mm"\nangle = "deg"\nangular_velocity = "rad/s"\n',
                            f"[units]\n{units}")
    text = edit(edit(text, "angle = 60", f"angle = {angle}"), "omega = 10", f"omega = {omega}")
    d = parse_mechanism(text, FILE).drive
    assert d.angle == pytest.approx(want_angle, **EXACT)
    assert d.omega == pytest.approx(want_omega, **EXACT)


def test_file_name_is_the_default_mechanism_name():
    m = parse_mechanism(edit(FOUR_BAR, 'name = "Four-bar crank-rocker"\n', "\n"), "my-linkage.toml")
    assert m.name == "my-linkage"


# ----- a ternary link from the lengths of its sides ---------------------------------------
def ternary(side: str | None, ac=4, bc=3) -> str:
    sides = f'\nsides = {{ C = "{side}" }}' if side else ""
    same_lines = 'length = "cm"\nangle = "deg"\nangular_velocity = "rad/s"\n'
    return edit(four_bar(same_lines,
                         a=("O4 = [300, 0]", "O4 = [12, 0]"),
                         b=("O2A = 100", "O2A = 2"),
                         d=("O4B = 200", "O4B = 6")),
                'points = ["A", "B"]\nlengths = { AB = 250 }',
                f'points = ["A", "B", "C"]\nlengths = {{ AB = 5, AC = {ac}, BC = {bc} }}{sides}')


@pytest.mark.parametrize("side, sign", [("left", 1.0), ("right", -1.0)])
def test_a_3_4_5_plate_gets_local_coordinates_from_its_sides(side, sign):
    # A at the origin, B on +x at 5 cm; C with AC = 4, BC = 3: x = (16 − 9 + 25)/10 = 3.2,
    # y = ±√(16 − 3.2²) = ±2.4 cm, left of A→B being +y.
    k = parse_mechanism(ternary(side), FILE).link(3)
    assert k.names == ("A", "B", "C")
    assert k.local("A") == (0.0, 0.0)
    assert k.local("B") == pytest.approx((0.05, 0.0), **EXACT)
    assert k.local("C") == pytest.approx((0.032, sign * 0.024), rel=1e-12)
    assert k.span("A", "C") == pytest.approx(0.04, rel=1e-12)
    assert k.span("B", "C") == pytest.approx(0.03, rel=1e-12)


def test_a_plate_point_needs_its_side():
    e = parse_error(ternary(None))
    assert 'sides = { C = "left" }' in str(e)
    assert str(e).startswith(f"{FILE}:20: ")  # the lengths line of link #2 (link 3)


def test_a_plate_whose_sides_cannot_close_is_refused():
    e = parse_error(ternary("left", ac=1, bc=1))  # 1 + 1 < 5
    assert "do not close a triangle" in str(e)
    assert str(e).startswith(f"{FILE}:20: ")


def test_a_collinear_plate_point_needs_no_side():
    k = parse_mechanism(ternary(None, ac=2, bc=3), FILE).link(3)  # 2 + 3 = 5: C on AB
    assert k.local("C") == pytest.approx((0.02, 0.0), abs=1e-12)


# ----- errors: InputError, the file, the line, and a hint ----------------------------------
@pytest.mark.parametrize("old, new, line, words", [
    # lengths
    ("AB = 250", "AB = -250", 20, ["link 3", "must be a positive length", "-250"]),
    ("O4B = 200", "O4B = 0", 25, ["link 4", "must be a positive length", "got 0"]),
    ("O2A = 100", 'O2A = "100 mm"', 15, ["must be a number"]),
    ("lengths = { AB = 250 }", "lengths = { ABB = 250 }", 20, ["did you mean 'AB'?"]),
    ("lengths = { AB = 250 }", "# no lengths", 17, ["link 3 needs the length AB"]),
    # names of links and points
    ("link = 2", "link = 7", 28, ["unknown link '7'", "1, 2, 3, 4"]),
    ("link = 2", "link = 1", 28, ["the frame (link 1) cannot be the input"]),
    ("link = 2", "# no input link", 27, ["must name the input link"]),
    ('B = "left"', 'Bb = "left"', 34, ["unknown point 'Bb'", "did you mean 'B'?"]),
    ('B = "left"', 'B = "lefft"', 34, ["unknown branch 'lefft'", "did you mean 'left'?"]),
    ("number = 3", "number = 2", 18, ["link 2 is defined twice"]),
    ('points = ["A", "B"]', 'points = ["A", "A"]', 19, ["lists a point twice"]),
    # keys and units
    ("omega = 10", "omgea = 10", 30, ["unknown input setting 'omgea'", "did you mean 'omega'?"]),
    ('length = "mm"', 'length = "mmm"', 4, ["unknown length unit 'mmm'", "did you mean 'mm'?"]),
    ('angle = "deg"', 'angle = "degree"', 5, ["did you mean 'deg'?"]),
    ("number = 4", "numbr = 4", 23, ["unknown link setting 'numbr'", "did you mean 'number'?"]),
    ('name = "Four-bar crank-rocker"', 'nmae = "Four-bar"', 1, ["did you mean 'name'?"]),
])
def test_bad_input_names_file_line_and_fix(old, new, line, words):
    e = parse_error(edit(FOUR_BAR, old, new))
    assert isinstance(e, TarsimError)
    assert (e.file, e.line) == (FILE, line)
    assert str(e).startswith(f"{FILE}:{line}: ")
    assert "\n" not in str(e)
    for w in words:
        assert w in str(e)


@pytest.mark.parametrize("old, new, line, column", [
    ("angle = 60", "angle = = 60", 29, 9),
    ("O2 = [0, 0]", "O2 = [0; 0]", 9, 8),
    ("[input]", "[input", 27, 7),
])
def test_malformed_toml_gives_file_line_column(old, new, line, column):
    e = parse_error(edit(FOUR_BAR, old, new))
    assert (e.line, e.column) == (line, column)
    assert str(e).startswith(f"{FILE}:{line}:{column}: not valid TOML: ")


def test_toml_that_ends_too_soon_still_gives_a_line():
    # tomllib says "(at end of document)" here, with no line: the error should still
    # point at the last line, 35, where the value is missing.
    e = parse_error(FOUR_BAR + "C = ")
    assert "not valid TOML" in str(e)
    assert e.line == 35
    assert str(e).startswith(f"{FILE}:35:")


def test_a_misspelt_table_header_gives_its_line():
    e = parse_error(edit(FOUR_BAR, "[assembly]", "[asembly]"))
    assert "did you mean 'assembly'?" in str(e)
    assert e.line == 33  # the header; not 0, which is no line of the file
    assert str(e).startswith(f"{FILE}:33: ")


def test_an_inline_table_gives_its_line():
    head, tail = FOUR_BAR.split("[input]\n")
    text = 'input = { lnk = 2, angle = 60 }\n' + head + "# " + tail.replace("\n", "\n# ")
    e = parse_error(text)
    assert "did you mean 'link'?" in str(e)
    assert e.line == 1
    assert str(e).startswith(f"{FILE}:1: ")


@pytest.mark.parametrize("old, new, where", [
    ("link = 2", "# no input link", "[input]"),       # "…:27: [input] [input] must name…"
    ("O2 = [0, 0]\nO4 = [300, 0]", "#\n#", "[frame]"),  # "…:8: [frame] [frame] names no…"
])
def test_the_where_is_not_said_twice(old, new, where):
    e = parse_error(edit(FOUR_BAR, old, new))
    assert str(e).count(where) == 1, str(e)


def test_a_missing_table_names_the_file():
    e = parse_error(FOUR_BAR.split("[input]")[0])
    assert str(e) == f"{FILE}: the file has no [input] table"


# Line numbers: 14 [[slider]], 15 link, 16 point, 17 through, 18 angle.
SLIDER_CRANK = """\
[frame]
O2 = [0, 0]
[[link]]
number = 2
points = ["O2", "A"]
lengths = { O2A = 30 }
[[link]]
number = 3
points = ["A", "B"]
lengths = { AB = 70 }
[[link]]
number = 4
points = ["B"]
[[slider]]
link = 4
point = "B"
through = "O2"
angle = 0
[input]
link = 2
angle = 45
"""


def test_a_slider_guide_is_read_in_si():
    m = parse_mechanism(edit(SLIDER_CRANK, "angle = 0", "angle = 90\noffset = 20"), FILE)
    (s,) = m.slides
    assert (s.kind, s.link, s.point, s.guide_link) == ("block", 4, "B", 1)
    assert s.direction == pytest.approx((0.0, 1.0), abs=1e-15)
    # 20 mm to the left of the upward guide through O2 is x = −0.02 m.
    assert s.through == pytest.approx((-0.02, 0.0), abs=1e-15)
    assert m.mobility()[0] == 1


@pytest.mark.parametrize("old, new, line, words", [
    ('point = "B"', 'point = "Q"', 16, ["unknown point of link 4 'Q'"]),
    ('through = "O2"', 'through = "O3"', 17, ["unknown frame point 'O3'", "one of: O2"]),
    ("link = 4", "link = 9", 15, ["unknown link '9'", "1, 2, 3, 4"]),
    ('through = "O2"', 'kind = "blok"', 17, ["unknown slider kind 'blok'",
                                               "did you mean 'block'?"]),
    ("angle = 0", "angel = 0", 18, ["unknown slider setting 'angel'", "did you mean 'angle'?"]),
    ("angle = 0", "# no angle", 14, ["needs its angle"]),
])
def test_slider_errors_name_the_slider(old, new, line, words):
    e = parse_error(edit(SLIDER_CRANK, old, new))
    assert str(e).startswith(f"{FILE}:{line}: [slider 1"), str(e)
    for w in words:
        assert w in str(e)


# ----- degrees of freedom --------------------------------------------------------------
def test_a_five_bar_with_one_input_is_refused():
    e = parse_error(FIVE_BAR)
    assert "2 degrees of freedom" in str(e)
    assert "3(5 − 1) − 2·5 − 0 = 2" in str(e)
    assert str(e).startswith(f"{FILE}:25: [input] ")  # the [input] header


def test_a_structure_with_one_input_is_refused():
    # A fifth link O2B braces the four-bar: 3(5 − 1) − 2·6 = 0.
    text = edit(FOUR_BAR, "[input]", '[[link]]\nnumber = 5\npoints = ["O2", "B"]\n'
                                     "lengths = { O2B = 300 }\n\n[input]")
    e = parse_error(text)
    assert "0 degrees of freedom" in str(e)
    assert "cannot move" in str(e)


# ----- reading files ---------------------------------------------------------------------
def test_load_mechanism_names_the_file_it_read(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(edit(FOUR_BAR, "AB = 250", "AB = 0"), encoding="utf-8")
    with pytest.raises(InputError) as info:
        load_mechanism(path)
    assert str(info.value).startswith(f"{path}:20: ")


def test_load_mechanism_of_a_missing_file_is_an_input_error(tmp_path):
    path = tmp_path / "missing.toml"
    with pytest.raises(InputError) as info:
        load_mechanism(path)
    assert str(info.value).startswith(f"{path}: cannot read the file")


# ----- contacts: a circle on a flat face -------------------------------------------------------
# Line numbers: 16 [[contact]], 17 circle, 18 face, 19 side.
CAM = """\
[frame]
O2 = [0, 0]
[[link]]
number = 2
name = "cam"
points = ["O2", "C"]
lengths = { O2C = 25 }
[[link]]
number = 3
points = ["F"]
[[slider]]
link = 3
point = "F"
through = "O2"
angle = 90
[[contact]]
circle = { link = 2, centre = "C", radius = 40 }
face = { link = 3, through = "F", angle = -90 }
side = "right"
[input]
link = 2
angle = 30
"""


def test_a_contact_is_read_as_its_equivalent_pin_in_a_slot():
    m = parse_mechanism(CAM, FILE)
    guide, slot = m.slides
    c = slot.contact
    assert (c.circle.link, c.circle.centre, c.circle.radius) == (2, "C", pytest.approx(0.04))
    assert (c.face.link, c.face.through, c.side) == (3, "F", "right")
    assert c.face.angle == pytest.approx(-math.pi / 2)
    assert (slot.kind, slot.link, slot.point, slot.guide_link) == ("pin", 2, "C", 3)
    # The face runs along the follower's −y (global +x); the cam below it, to its right,
    # so the slot is 40 mm along the follower's −x (global −y) from F.
    assert slot.direction == pytest.approx((0.0, -1.0), abs=1e-15)
    assert slot.through == pytest.approx((-0.04, 0.0), abs=1e-15)
    assert guide.contact is None
    assert m.mobility() == (1, 3, 2, 1)


def test_a_contact_radius_is_in_the_files_unit():
    m = parse_mechanism("[units]\nlength = \"cm\"\nangle = \"rad\"\n" + CAM.replace(
        "angle = -90", "angle = 1.5"), FILE)
    assert m.slides[1].contact.circle.radius == pytest.approx(0.40)
    assert m.slides[1].contact.face.angle == 1.5


@pytest.mark.parametrize("old, new, line, words", [
    # what is missing, and on which link
    (", radius = 40 }", " }", 17,
     ["the circular profile of link 2 needs a radius", "common normal runs through its centre"]),
    ('centre = "C", ', "", 17, ["the circular profile of link 2 needs a centre"]),
    ('through = "F", angle', "angle", 18, ["the flat face of link 3 needs a point"]),
    (', angle = -90 }', " }", 18,
     ["the flat face of link 3 needs an angle", "common normal is perpendicular to it"]),
    ('side = "right"', "# no side", 16, ["which side of the face of link 3", '"left" or "right"']),
    ("circle = { link = 2, ", "circle = { ", 17, ["the circle needs the number of the link"]),
    ('circle = { link = 2, centre = "C", radius = 40 }', "# no circle", 16,
     ["a contact needs its circle"]),
    # bad values
    ("radius = 40", "radius = 0", 17, ["radius of the circle of link 2",
                                        "must be a positive length", "got 0"]),
    ("radius = 40", "radius = -40", 17, ["must be a positive length", "got -40"]),
    ('side = "right"', 'side = "rigth"', 19, ["unknown side 'rigth'", "did you mean 'right'?"]),
    # names
    ('centre = "C"', 'centre = "F"', 17, ["unknown point of link 2 'F'", "O2, C"]),
    ('through = "F"', 'through = "C"', 18, ["unknown point of link 3 'C'", "one of: F"]),
    ("circle = { link = 2", "circle = { link = 7", 17, ["unknown link '7'", "1, 2, 3"]),
    ('face = { link = 3, through = "F"', 'face = { link = 2, through = "C"', 18,
     ["both on link 2", "a contact joins two links"]),
    ("radius = 40", "raduis = 40", 17, ["unknown circle setting 'raduis'",
                                         "did you mean 'radius'?"]),
    ('side = "right"', 'sied = "right"', 19, ["unknown contact setting 'sied'",
                                               "did you mean 'side'?"]),
    # a circle on a face or on a circle, never a mixture
    ('face = { link = 3, through = "F", angle = -90 }', 'face = { link = 3, centre = "F", '
     'radius = 10 }', 19, ["unknown side 'right'", "outside, inside"]),
    ('face = { link = 3, through = "F", angle = -90 }', 'face = { link = 3, centre = "F", '
     'radius = 10, angle = 0 }', 18, ["the face of link 3 is given both a centre and radius",
                                     "give one"]),
    ('circle = { link = 2, centre = "C", radius = 40 }', 'circle = { link = 2, through = "C", '
     'angle = 0 }', 17, ["the circle of link 2 is given a point and an angle",
                        "a circle (centre and radius) on a face or on another circle"]),
    ('side = "right"', 'side = "right"\nrolling = 1', 20, ["rolling must be true or false"]),
])
def test_contact_errors_name_the_link_and_what_is_missing(old, new, line, words):
    e = parse_error(edit(CAM, old, new))
    assert (e.file, e.line) == (FILE, line), str(e)
    assert str(e).startswith(f"{FILE}:{line}: [contact 1"), str(e)
    assert "\n" not in str(e)
    for w in words:
        assert w in str(e), str(e)


@pytest.mark.parametrize("order", [["B", "A", "G"], ["A", "B", "G"], ["G", "A", "B"]])
def test_a_point_on_a_links_line_is_on_it_in_any_order(order):
    # BA = 500, AG = 275, BG = 225: G lies on BA, 225 mm from B. Listed B, A, G, rounding
    # once left h² = 1.4e-17 m², h = 3.7e-9 m, and the file was refused for want of a side.
    text = edit(four_bar(), 'points = ["A", "B"]\nlengths = { AB = 250 }',
                f'points = {order!r}\nlengths = {{ BA = 500, AG = 275, BG = 225 }}'
                .replace("'", '"'))
    text = edit(text, "O4B = 200", "O4B = 600")
    k = parse_mechanism(text, FILE).link(3)
    assert k.span("B", "G") == pytest.approx(0.225, rel=1e-12)
    assert k.span("A", "G") == pytest.approx(0.275, rel=1e-12)
    assert k.span("A", "B") == pytest.approx(0.5, rel=1e-12)
    # exactly on the line: the triangle A, B, G has no area
    (ax, ay), (bx, by), (gx, gy) = (k.local(n) for n in "ABG")
    assert (bx - ax) * (gy - ay) - (by - ay) * (gx - ax) == 0.0
