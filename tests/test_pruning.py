"""A scene leaves out what it does not need, tested on the SVG a user gets (DESIGN.md, idea 2).

An exercise is solved in memory (``solve_to_files``) and its SVG read back with
xml.etree: the text labels say which centres, velocities and panels a figure
draws, and a step number is the text inside a circled badge (a ``badge`` circle).
The numbers of steps.md must be exactly the figure's circled numbers.
"""

import re
import xml.etree.ElementTree as ET

import pytest

from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution_files import solve_to_files

SVG = "{http://www.w3.org/2000/svg}"
SUBSCRIPT = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")

# The four-bar of peers.md §4 with a coupler point C, driven at ω2 = 10 rad/s.
FOUR_BAR = """\
name = "Four-bar with a coupler point"
[frame]
O2 = [0, 0]
O4 = [300, 0]
[[link]]
number = 2
points = ["O2", "A"]
lengths = { O2A = 100 }
[[link]]
number = 3
points = ["A", "B", "C"]
lengths = { AB = 250, AC = 150, BC = 180 }
sides = { C = "left" }
[[link]]
number = 4
points = ["O4", "B"]
lengths = { O4B = 200 }
[input]
link = 2
angle = 60
omega = 10
[assembly]
B = "left"
[ask]
find = {find}
methods = {methods}
"""


def solve(find, methods='["radius-rotation"]'):
    text = FOUR_BAR.replace("{find}", find).replace("{methods}", methods)
    return solve_to_files(parse_exercise(text, "coupler.toml", "coupler"))[1]


# ----- reading the SVG --------------------------------------------------------------------------

def texts(svg: str) -> list[str]:
    """Every text element's characters (a subscript tspan joined on: "VB", "I₁₃")."""
    return ["".join(e.itertext()) for e in ET.fromstring(svg).iter(SVG + "text")]


def centre_labels(svg: str) -> set[str]:
    """The instant centres a figure labels, as "I13" (a multiple pin reads I34 ≡ I35 …)."""
    out = set()
    for t in texts(svg):
        out |= set(re.findall(r"I\d+", t.translate(SUBSCRIPT)))
    return out


def velocity_labels(svg: str) -> set[str]:
    """The point velocities a figure labels: "VA", "VB" (a title is not a label)."""
    return {t for t in texts(svg) if re.fullmatch(r"V[A-Z][A-Za-z0-9′]*", t)}


def _badges(root) -> list[tuple[float, float, float]]:
    return [(float(c.get("cx")), float(c.get("cy")), float(c.get("r")))
            for g in root.iter(SVG + "g") if g.get("class") == "badge"
            for c in g.iter(SVG + "circle")]


def circled_numbers(svg: str, box=None) -> list[int]:
    """The step numbers in badges, sorted: digits whose anchor lies inside a badge circle.

    ``box`` (x0, y0, x1, y1) keeps only the badges inside it (one panel of a page).
    """
    root = ET.fromstring(svg)
    badges = _badges(root)
    out = []
    for e in root.iter(SVG + "text"):
        t = "".join(e.itertext())
        if not t.isdigit():
            continue
        x, y = float(e.get("x")), float(e.get("y"))
        inside = [b for b in badges if (x - b[0]) ** 2 + (y - b[1]) ** 2 < b[2] ** 2]
        if not inside:
            continue
        if box is not None and not (box[0] <= x <= box[2] and box[1] <= y <= box[3]):
            continue
        out.append(int(t))
    return sorted(out)


def frames(svg: str) -> list[tuple[float, float, float, float]]:
    """The boxes of a worked page's panels (the thin ``frame`` rectangles)."""
    out = []
    for g in ET.fromstring(svg).iter(SVG + "g"):
        if g.get("class") != "frame":
            continue
        for p in g.iter(SVG + "path"):
            xs, ys = zip(*((float(a), float(b)) for a, b in
                           re.findall(r"(-?[\d.]+),(-?[\d.]+)", p.get("d"))))
            out.append((min(xs), min(ys), max(xs), max(ys)))
    return out


def panel_box(svg: str, caption: str) -> tuple[float, float, float, float]:
    """The frame that holds the text ``caption`` ("Velocity polygon")."""
    root = ET.fromstring(svg)
    (x, y), = [(float(e.get("x")), float(e.get("y"))) for e in root.iter(SVG + "text")
               if "".join(e.itertext()) == caption]
    (box,) = [b for b in frames(svg) if b[0] <= x <= b[2] and b[1] <= y <= b[3]]
    return box


def steps_of(steps_md: str, title: str, file: str) -> list[int]:
    """The numbers of the list under ``## title (`file`)`` in steps.md."""
    lines = steps_md.splitlines()
    start = lines.index(f"## {title} (`{file}`)")
    out = []
    for line in lines[start + 1:]:
        if line.startswith("#"):
            break
        m = re.match(r"(\d+)\. ", line)
        if m:
            out.append(int(m.group(1)))
    return out


# ----- one velocity asked ---------------------------------------------------------------------

def test_one_velocity_gets_one_figure_and_no_polygon_page():
    files = solve(find='["V_B"]')
    svgs = {name: text for name, text in files.items() if name.endswith(".svg")}
    assert "V_B-radius-rotation.svg" in svgs
    # No worked page, no polygons, no circle diagram, no centres figure, no other velocity.
    assert not any(name.startswith(("worked", "circle-diagram", "centres", "V_C"))
                   for name in svgs)
    for name, text in svgs.items():
        assert "Acceleration polygon" not in text and "Velocity polygon" not in text, name
        assert "Circle diagram" not in text, name
    assert "Acceleration polygon" not in files["steps.md"]
    assert "Velocity polygon" not in files["steps.md"]


def test_the_velocity_figure_draws_only_the_centres_its_method_uses():
    svg = solve(find='["V_B"]')["V_B-radius-rotation.svg"]
    # B is taken on the coupler 3 (its transfer point I23 is the pin A): the line of centres
    # I13-I23 needs I13, found from I12, I23, I14 and I34. I24 serves only link 4: left out.
    assert centre_labels(svg) == {"I12", "I14", "I23", "I34", "I13"}
    # Only the known velocity and the asked one; the coupler point C is drawn, not its velocity.
    assert velocity_labels(svg) == {"VA", "VB"}
    labels = texts(svg)
    assert "C" in labels and "B′" in labels and "C′" not in labels


def test_asking_more_draws_more():
    # The converse of the two tests above: each asked quantity brings its own construction.
    files = solve(find='["V_B", "V_C", "I24"]')
    assert "V_C-radius-rotation.svg" in files
    assert velocity_labels(files["V_C-radius-rotation.svg"]) == {"VA", "VC"}
    assert "I24" in centre_labels(files["centres.svg"])
    assert "I24" not in centre_labels(files["V_B-radius-rotation.svg"])


def test_steps_md_numbers_are_the_figures_circled_numbers():
    files = solve(find='["V_B"]', methods='["radius-rotation", "parallel-line"]')
    for method, words in (("radius-rotation", "radius rotation"),
                          ("parallel-line", "parallel lines")):
        name = f"V_B-{method}.svg"
        numbers = steps_of(files["steps.md"], f"V_B by {words}", name)
        assert numbers == list(range(1, len(numbers) + 1)) and len(numbers) > 5
        # The steps of the construction are circled on the figure, each once, and nothing
        # else is: the centres found by inspection before them need no badge, their names
        # standing at the pins.
        circled = circled_numbers(files[name])
        assert circled and circled == numbers[numbers.index(circled[0]):], method


# ----- accelerations bring the polygons -------------------------------------------------------

def test_asking_an_acceleration_brings_the_acceleration_polygon():
    files = solve(find='["A_B"]')
    worked = [name for name in files if name.startswith("worked") and name.endswith(".svg")]
    assert worked == ["worked.svg"]
    page = files["worked.svg"]
    assert "Acceleration polygon" in texts(page) and "Velocity polygon" in texts(page)
    assert "## Acceleration polygon (`worked.svg`)" in files["steps.md"]
    # No velocity by centres was asked: no centres, no construction figure.
    assert not any(name.startswith(("V_B", "centres", "circle-diagram")) for name in files)


def test_a_velocity_by_the_polygon_brings_no_acceleration_panel():
    files = solve(find='["V_B"]', methods='["polygon"]')
    page = files["worked.svg"]
    assert "Velocity polygon" in texts(page)
    assert "Acceleration polygon" not in texts(page)
    assert "Acceleration polygon" not in files["steps.md"]


# ----- the crank-shaper's worked page -----------------------------------------------------------

@pytest.fixture(scope="module")
def crank_shaper_files(files):
    return files("crank-shaper")


@pytest.mark.parametrize("slug", ["theta2-90", "t-2.34s"])
@pytest.mark.parametrize("panel", ["Velocity polygon", "Acceleration polygon"])
def test_crank_shaper_polygon_numbers_match_steps_md(crank_shaper_files, slug, panel):
    name = f"worked-{slug}.svg"
    page = crank_shaper_files[name]
    numbers = steps_of(crank_shaper_files["steps.md"], panel, name)
    assert numbers == list(range(1, len(numbers) + 1)) and len(numbers) > 5
    assert circled_numbers(page, panel_box(page, panel)) == numbers


def test_crank_shaper_space_diagram_on_the_worked_page_has_no_step_numbers(crank_shaper_files):
    page = crank_shaper_files["worked-t-2.34s.svg"]
    boxes = frames(page)
    polygons = [panel_box(page, p) for p in ("Velocity polygon", "Acceleration polygon")]
    (space,) = [b for b in boxes if b not in polygons]
    assert circled_numbers(page, space) == []
    # Every badge on the page lies in one of the two polygon panels.
    assert sum(len(circled_numbers(page, b)) for b in polygons) == len(circled_numbers(page))
