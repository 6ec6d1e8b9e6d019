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
