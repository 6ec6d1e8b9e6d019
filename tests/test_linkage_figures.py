"""The linkages' figures as an instructor reads them: what a title says a figure shows, one
ground under a rolling wheel, each velocity named for its point, far centres named on
their own arrows, badges only where a construction needs its number.

Each test measures the Figure model of a bundled exercise (paper mm).
"""

import math
import re

import pytest

from tarsim.graphics.figure import Path, Text

pytestmark = pytest.mark.slow

_CENTRE = re.compile(r"I[₀-₉]{2,3}")


def _texts(fig) -> list[str]:
    return [t.text + (t.sub or "") + (t.tail or "") for t in fig.items if isinstance(t, Text)]


def _centres_named(fig) -> set[str]:
    return {m for t in _texts(fig) for m in _CENTRE.findall(t)}


def _title(fig) -> str:
    """The caption's heading, its wrapped lines joined."""
    lines = [t for t in fig.items if isinstance(t, Text) and t.weight == "bold"]
    return " ".join(t.text + (t.sub or "") for t in lines)


@pytest.mark.parametrize("exercise_id, shown, says", [
    # p. 292 asks I15 and I25: the figure shows them and the 8 they are found from.
    ("velocity-homework-292", 10, "the instant centres asked"),
    # Homework 3 asks every centre of its six links: 6·5/2 = 15.
    ("six-link-homework-3", 15, "instant centres")])
def test_a_centres_figure_is_titled_for_the_centres_it_shows(solved, exercise_id, shown, says):
    fig = solved(exercise_id).figures["centres"]
    assert len(_centres_named(fig)) == shown
    assert _title(fig).endswith(says)


def test_the_ground_a_wheel_rolls_on_and_its_sliders_guide_are_drawn_once(solved):
    """The wheel-driven slider's B slides on the floor its wheel rolls on: every hatched
    guide of each figure lies on one line, where the wheel touches it (it was drawn again
    2.5 mm lower, under B's block), and B's block stands on it."""
    for stem, fig in solved("wheel-driven-slider").figures.items():
        guides = [it.points for it in fig.items if isinstance(it, Path) and it.style == "guide"]
        if not guides:
            continue
        heights = {round(y, 2) for pts in guides for _, y in pts}
        assert max(heights) - min(heights) < 0.01, stem       # the floor is level
        (block,) = [it.points for it in fig.items if isinstance(it, Path)
                    and it.style == "block"]
        assert max(y for _, y in block) == pytest.approx(min(heights), abs=0.01), stem


@pytest.mark.parametrize("stem", ["V_B-radius-rotation", "V_B-parallel-line"])
def test_a_velocity_carried_to_a_pin_is_named_for_the_pin(solved, stem):
    """The wheel-driven slider's V_C is carried to I23, the pin A, before B's is found: the
    arrow at A is V_A, as the reader knows the point, not V_I23."""
    fig = solved("wheel-driven-slider").figures[stem]
    names = [t.text + (t.sub or "") for t in fig.items if isinstance(t, Text)
             and t.text.startswith("V") and not t.text.startswith("Velocity")]
    assert sorted(names) == ["VA", "VB", "VC"]
    assert not [n for n in names if _CENTRE.search(n)]


@pytest.mark.parametrize("exercise_id", ["hinkle-four-bar", "hinkle-slider-crank"])
def test_every_arrow_at_the_edge_names_the_far_centre_it_runs_to(solved, exercise_id):
    """Hinkle's I13 lies 923 mm off: the line through A and the line through B each end in
    an arrow at the page's edge. Each is named: the text nearest its tip names a centre,
    and every far centre is named at as many arrows as lines run to it (one arrow, the one
    named with its distance, was all a reader could place)."""
    from shapely.geometry import Point, box

    fig = solved(exercise_id).figures["centres"]
    heads = [it.points[0] for it in fig.items if isinstance(it, Path) and it.style == "arrowhead"]
    tips = [min(heads, key=lambda h: math.dist(h, it.points[-1])) for it in fig.items
            if isinstance(it, Path) and it.style == "edge_arrow"]
    assert len(tips) >= 2
    long = [t for t in fig.items if isinstance(t, Text) and t.text.startswith("to I")]
    centres = {_CENTRE.search(t.text)[0] for t in long}
    far = long + [t for t in fig.items if isinstance(t, Text) and t.text in centres]

    def gap(t, tip):
        return box(*t.box()).distance(Point(tip))
    for tip in tips:
        # A name within 10 mm (the long one reads on past its step badge), nearer this
        # arrow than any other arrow at the edge.
        mine = [t for t in far if gap(t, tip) < 10.0
                and all(gap(t, tip) <= gap(t, other) for other in tips)]
        assert mine, tip


def test_a_centres_figure_numbers_only_the_centres_found_by_kennedy(solved):
    """Homework 3's Watt-I six-bar: 15 centres, 7 at its pins by inspection, 8 by Kennedy,
    each from two Kennedy lines. It carried 31 circled numbers; the pins and the lines are
    found by what they are and what they join, so the 8 Kennedy centres alone are numbered,
    each badge beside its centre's name."""
    from tarsim.graphics.figure import Circle

    fig = solved("six-link-homework-3").figures["centres"]
    badges = [c for c in fig.items if isinstance(c, Circle) and c.style == "badge"]
    assert len(badges) == 8
    names = [t for t in fig.items if isinstance(t, Text) and _CENTRE.fullmatch(t.text)]
    for b in badges:
        nearest = min(names, key=lambda t: math.dist(b.centre, ((t.box()[0] + t.box()[2]) / 2,
                                                               (t.box()[1] + t.box()[3]) / 2)))
        x0, y0, x1, y1 = nearest.box()
        assert min(abs(b.centre[0] - x1), abs(b.centre[0] - x0)) < 4.0    # right beside it
