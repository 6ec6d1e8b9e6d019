"""Tests for constructions.reference.change_points (where a sampled turn passes a change point).

The steps a turn's search looks at are found all at once: the oracle is the step-by-step
rule they replace, a step between two solved ones that is refused or dips to DIP of its
larger neighbour.
"""

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.reference.change_points import DIP, _dips


def _looked_at(conditioning):
    n, out = len(conditioning), []
    for k in range(n):
        here, before, after = conditioning[k], conditioning[k - 1], conditioning[(k + 1) % n]
        if before is None or after is None:
            continue
        if here is None or here <= DIP * max(before, after):
            out.append(k)
    return out


@settings(max_examples=300, deadline=None, derandomize=True)
@given(st.lists(st.one_of(st.none(), st.floats(0.0, 1.0),
                          st.sampled_from([0.25, 0.5, 1.0])), max_size=40))
def test_the_steps_looked_at_are_the_rules(conditioning):
    # the sampled values make ties at exactly DIP of a neighbour, which the rule takes
    assert _dips(conditioning).tolist() == _looked_at(conditioning)


def test_a_smooth_turn_has_nothing_to_look_at_and_a_gap_only_its_ends():
    turn = [0.5 + 0.2 * math.sin(math.tau * k / 3600) for k in range(3600)]
    assert _dips(turn).tolist() == []
    turn[10:13] = [None] * 3                # a gap: the steps beside it have one None
    assert _dips(turn).tolist() == []
    turn[20] = None                         # one refused step between two solved ones
    assert _dips(turn).tolist() == [20]
