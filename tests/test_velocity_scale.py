"""A velocity construction on the space diagram is drawn big enough to read: the nice scale
that draws the input at least 20 mm long, the shortest vector at least 8 mm and the longest
at least 30 mm, unless the longest would then pass its room
(constructions/scales.readable_per_cm)."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.scales import READABLE_MM, SHORTEST_MM, nice, readable_per_cm
from tarsim.exercises.catalog import load
from tarsim.exercises.linkages.solution_files import solve_worked
from tarsim.graphics.figure import Path

speeds = st.floats(1e-3, 1e4)


def _is_nice(n: float) -> bool:
    mantissa = n / 10 ** math.floor(math.log10(n) + 1e-9)
    return min(abs(mantissa - m) for m in (1, 2, 5)) < 1e-9


@settings(max_examples=200, deadline=None)
@given(speed=speeds, others=st.lists(speeds, min_size=1, max_size=8),
       longest=st.floats(30.0, 120.0))
def test_the_scale_is_the_largest_nice_one_that_reads_or_else_the_roomiest(speed, others,
                                                                            longest):
    n = readable_per_cm(speed, others, longest)
    assert _is_nice(n)
    mm = [10.0 * v / n for v in others]
    high = max(max(mm), 10.0 * speed / n)
    assert high <= longest * (1 + 1e-9)                  # nothing passes its room
    readable = min(mm) >= SHORTEST_MM * (1 - 1e-9) and 10.0 * speed / n >= 20.0 * (1 - 1e-9) \
        and high >= READABLE_MM * (1 - 1e-9)
    up = nice(n * 1.01)                                  # the next nice scale up
    if readable:
        # No coarser nice scale still reads: the construction is no bigger than it need be.
        assert min(10.0 * v / up for v in others) < SHORTEST_MM or 10.0 * speed / up < 20.0 \
            or high * n / up < READABLE_MM
    else:
        # Too short beside the longest: the longest fills its room, within one nice step.
        down = nice(n * 0.99, up=False)
        assert high * n / down > longest


def test_the_coupler_plate_construction_draws_no_vector_under_8_mm():
    # Hinkle §5-3 states no velocity scale: the components of V_E were once 4.6 mm long.
    figures = solve_worked(load("hinkle-four-bar")).figures
    for stem in ("V_E-components", "V_D-components", "V_B-components"):
        fig = figures[stem]
        heads = [p.points[0] for p in fig.items if isinstance(p, Path) and p.closed
                 and p.style == "arrowhead"]
        for shaft in (p for p in fig.items if isinstance(p, Path)
                      and p.style in ("vector", "vector_result")):
            tail, end = shaft.points[0], shaft.points[-1]
            tip = min(heads, key=lambda h: math.dist(h, end))     # the shaft stops in its head
            assert math.dist(tail, tip) >= SHORTEST_MM - 1e-3, stem
