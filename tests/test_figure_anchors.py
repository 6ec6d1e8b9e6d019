"""A label joining points that coincide ("I₂₃ ≡ I₂₄") keeps to them only while they do."""

from __future__ import annotations

import pytest

from tarsim.graphics.figure import Figure, Text, View
from tarsim.graphics.figure_anchors import anchors


def _drawn(label: str) -> Figure:
    fig = Figure(50.0, 50.0, views={"space": View(10.0, (20.0, 30.0))})
    at = fig.views["space"]((1.0, 0.0))
    fig.add(Text(at, label, owner=(at,)))
    return fig


@pytest.mark.parametrize("second, kept", [
    ((1.0, 0.0), True),        # still together (a pin and the centre it is): kept beside them
    ((1.0, 0.5), False),       # parted 5 mm on paper: "≡" held at the first position alone
])
def test_a_joined_label_is_carried_only_while_its_points_stay_together(second, kept):
    first = {"space": [(0.0, 0.0), (1.0, 0.0), (1.0, 0.0)]}
    later = {"space": [(0.0, 0.0), (1.0, 0.0), second]}
    found = anchors(_drawn("I23 ≡ I24"), [_drawn("I23 ≡ I24")], [first, later])
    assert (found[0] is not None) is kept
    # a label of one point keeps to it either way: the point it names is still there
    single = anchors(_drawn("A"), [_drawn("A")], [first, later])
    assert single[0] == ("space", [(1, -1, -1)])
