"""Tests for constructions.record: conditioning along paths, replay, slice, errors."""

import dataclasses
import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tarsim.constructions import record
from tarsim.constructions.errors import GeometryError, NoIntersection, TarsimError
from tarsim.constructions.geometry import (Circle, Line, Point, Segment, intersect_circles,
                                           line_through)
from tarsim.constructions.measures import Angle, Dimension
from tarsim.constructions.narration import Phrase
from tarsim.constructions.record import (VERBS, Construction, Panel, Role, Slice, Step, replay,
                                         toposort)


def _give(c, ref, x, y):
    return c.give(ref, Point(x, y), label=ref)


@pytest.fixture
def figure():
    """O, A, B, F given; P cut from two arcs, Q its foot on OA; m through F and B."""
    c = Construction()
    for ref, xy in ("O", (0, 0)), ("A", (4, 0)), ("B", (0, 3)), ("F", (10, 10)):
        _give(c, ref, *xy)
    c.draw("k1", "circle_through", "O", "B")
    c.draw("k2", "swing_arc", "A", radius=4.0)
    c.draw("P", "intersect_circles", "k1", "k2", pick="left", role=Role.RESULT)
    c.draw("l", "line_through", "O", "A")
    c.draw("Q", "project_onto", "P", "l", label="Q")
    c.draw("m", "line_through", "F", "B")
    return c


def test_draw_records_the_act(figure):
    step = figure["P"]
    assert (step.verb, step.inputs, step.params, step.role) == (
        "intersect_circles", ("k1", "k2"), (("pick", "left"),), Role.RESULT)
    assert step.output == intersect_circles(Circle(Point(0, 0), 3.0), Circle(Point(4, 0), 4.0),
                                            "left")[0]
    assert (figure["Q"].label, figure["Q"].panel) == ("Q", Panel.SPACE)
    assert figure["O"].role == Role.GIVEN and figure["l"].role == Role.CONSTRUCTION


# ---- conditioning compounds along the DAG path


def test_conditioning_compounds_along_the_path():
    c = Construction()
    for ref, xy in ("O", (0, 0)), ("C", (5, 0)), ("A", (0, 9)), ("Z", (1, 1)):
        _give(c, ref, *xy)
    c.draw("k1", "swing_arc", "O", radius=3.0)
    c.draw("k2", "swing_arc", "C", radius=2.0 + 1e-10)       # nearly tangent: cond ~ 1e-5
    c.draw("T", "intersect_circles", "k1", "k2", pick="left")
    c.draw("M", "midpoint", "T", "A")                         # well-posed act downstream
    c.draw("l", "line_through", "O", "A")                     # a sibling off the path
    c.draw("N", "project_onto", "M", "l")
    c.draw("S", "lay_off", "O", "Z", length=2.0)              # cond |OZ| / |Z| = 1
    c.draw("R", "line_through", "S", "N")
    near_tangent = c["T"].conditioning
    assert 0 < near_tangent < 1e-4
    assert near_tangent == intersect_circles(c.output("k1"), c.output("k2"), "left")[1]
    assert c["M"].conditioning == c["N"].conditioning == near_tangent
    own_r = VERBS["line_through"](c.output("S"), c.output("N"))[1]
    assert c["R"].conditioning == own_r * near_tangent
    assert c["l"].conditioning == c["S"].conditioning == c["O"].conditioning == 1.0


# ---- random small constructions

# verb -> (input kinds, keyword-parameter strategies)
SIGNATURES = {
    "line_through": (("point", "point"), {}),
    "perpendicular_through": (("point", "line"), {}),
    "parallel_through": (("point", "line"), {}),
    "swing_arc": (("point",), {"radius": st.floats(0.5, 20)}),
    "circle_through": (("point", "point"), {}),
    "intersect_lines": (("line", "line"), {}),
    "intersect_line_circle": (("line", "circle"),
                              {"pick": st.sampled_from(["forward", "backward"])}),
    "intersect_circles": (("circle", "circle"), {"pick": st.sampled_from(["left", "right"])}),
    "rotate_about": (("point", "point"), {"angle": st.floats(-7, 7)}),
    "project_onto": (("point", "line"), {}),
    "lay_off": (("point", "point"), {"length": st.floats(-20, 20)}),
    "midpoint": (("point", "point"), {}),
    "mark": (("point",), {}),
    "normal_direction": (("line",), {}),
    "join": (("point", "point"), {}),
    "transfer": (("point", "point", "point"), {}),
    "measure": (("point", "point"), {}),
    "measure_angle": (("point", "point", "point"), {"turn": st.sampled_from([-1.0, 1.0])}),
}
KINDS = {Point: "point", Line: "line", Circle: "circle", Segment: "segment",
         Dimension: "dimension", Angle: "angle"}
# Small integers make coincidences, parallels and tangencies likely; floats make the rest.
COORDS = st.one_of(st.integers(-6, 6).map(float), st.floats(-20, 20))


def test_signatures_cover_every_verb():
    assert set(SIGNATURES) == set(VERBS)


@st.composite
def constructions(draw):
    """A random construction, and the refs whose act raised (and so must be absent)."""
    c, failed = Construction(), []
    for i in range(draw(st.integers(2, 4))):
        _give(c, f"G{i}", draw(COORDS), draw(COORDS))
    for i in range(draw(st.integers(1, 12))):
        pools = {kind: [s.id for s in c if KINDS[type(s.output)] == kind]
                 for kind in KINDS.values()}
        verb = draw(st.sampled_from([v for v, (kinds, _) in SIGNATURES.items()
                                     if all(pools[k] for k in kinds)]))
        kinds, param_strategies = SIGNATURES[verb]
        inputs = [draw(st.sampled_from(pools[kind])) for kind in kinds]
        params = {k: draw(v) for k, v in param_strategies.items()}
        try:
            c.draw(f"S{i}", verb, *inputs, **params)
        except GeometryError:  # anything else escaping the kernel is a bug
            failed.append(f"S{i}")
    return c, failed


@given(constructions())
def test_replay_reproduces_every_step(made):
    c, failed = made
    for step in c:
        assert replay(c, step.id) == step.output  # same inputs, same floats: exact
    assert not any(ref in c for ref in failed)


@given(constructions())
def test_every_step_compounds_its_own_conditioning_with_its_worst_input(made):
    c, _ = made
    for step in c:
        assert 0.0 <= step.conditioning <= 1.0
        if step.verb == "given":
            assert step.conditioning == 1.0
            continue
        own = VERBS[step.verb](*(c.output(r) for r in step.inputs), **dict(step.params))[1]
        assert step.conditioning == own * min([1.0] + [c[r].conditioning for r in step.inputs])


def _ancestors(c):
    """Each step's ancestry by forward propagation in record order (not slice's search)."""
    anc = {}
    for step in c:
        anc[step.id] = {step.id}.union(*(anc[r] for r in step.inputs))
    return anc


@given(constructions(), st.data())
def test_slice_is_exactly_the_ancestry(made, data):
    c, _ = made
    refs = [s.id for s in c]
    targets = data.draw(st.lists(st.sampled_from(refs), max_size=3))
    anc = _ancestors(c)
    shown = record.slice(c, targets)
    assert set(shown.refs) == set().union(*(anc[t] for t in targets))
    assert list(shown.refs) == [s.id for s in c if s.id in shown]       # record order


@given(constructions(), st.data())
def test_toposort_puts_inputs_first_and_numbered_counts_in_record_order(made, data):
    c, _ = made
    refs = [s.id for s in c]
    wanted = set(data.draw(st.lists(st.sampled_from(refs))))
    order = [s.id for s in toposort(c)]
    assert order == refs
    assert all(order.index(r) < order.index(s.id) for s in c for r in s.inputs)
    assert [s.id for s in toposort(c, wanted)] == [r for r in refs if r in wanted]
    # A slice numbers its narrated acts 1, 2, … in record order: not the givens, nor an
    # act that says nothing.
    said = {r for r in wanted if c[r].role is not Role.GIVEN and data.draw(st.booleans())}
    for r in said:
        c.steps[r] = dataclasses.replace(c[r], phrase=Phrase("test.step"))
    numbered = Slice(c, tuple(r for r in refs if r in wanted)).numbered()
    assert [s.id for _, s in numbered] == [r for r in refs if r in said and c[r].draws]
    assert [n for n, _ in numbered] == list(range(1, len(numbered) + 1))


# ---- slice, replay and errors on the fixed figure


@pytest.mark.parametrize("targets, expected", [
    (["Q"], {"O", "A", "B", "k1", "k2", "P", "l", "Q"}),
    (["P"], {"O", "A", "B", "k1", "k2", "P"}),
    (["m"], {"F", "B", "m"}),
    (["l", "m"], {"O", "A", "F", "B", "l", "m"}),
    (["F"], {"F"}),
    ([], set()),
])
def test_slice_returns_exactly_the_ancestors(figure, targets, expected):
    assert set(record.slice(figure, targets).refs) == expected


def test_slice_stops_at_the_base_and_takes_the_arrows_between_its_points(figure):
    figure.draw("v", "join", "P", "Q", label="V_P")        # an arrow: both ends in the slice
    figure.draw("w", "join", "F", "B")                      # one whose ends it does not hold
    shown = record.slice(figure, ["Q"], base=["O", "A", "B"], arrows=["v", "w"])
    assert shown.refs == ("k1", "k2", "P", "l", "Q", "v")
    assert record.slice(figure, ["Q"]).refs == ("O", "A", "B", "k1", "k2", "P", "l", "Q")


def test_replay_recomputes_from_the_current_inputs(figure):
    assert replay(figure, "O") == figure.output("O")
    # Move A under the record: replay must follow it, not echo the stored output.
    figure.steps["A"] = dataclasses.replace(figure["A"], output=Point(4, 1))
    assert replay(figure, "l") == line_through(Point(0, 0), Point(4, 1))[0]
    assert replay(figure, "l") != figure.output("l")


def test_replay_uses_the_recorded_branch(figure):
    figure.draw("P2", "intersect_circles", "k1", "k2", pick="right")
    left, right = replay(figure, "P"), replay(figure, "P2")
    assert left.y > 0 > right.y and (left.x, -left.y) == pytest.approx(right.xy, abs=1e-15)
    assert left == figure.output("P") and right == figure.output("P2")


@pytest.mark.parametrize("act", [
    lambda c: c.draw("P", "midpoint", "O", "A"),             # drawn twice
    lambda c: _give(c, "O", 1, 1),                            # given twice
    lambda c: c.draw("X", "midpoint", "O", "nowhere"),        # unknown input
    lambda c: c.draw("X", "line_through", "O", "O"),          # the kernel's DegenerateInput
])
def test_bad_acts_raise_and_leave_the_record_untouched(figure, act):
    before = dict(figure.steps)
    with pytest.raises(TarsimError):
        act(figure)
    assert figure.steps == before


def test_a_missed_cut_raises_no_intersection_with_its_margin(figure):
    figure.draw("k3", "swing_arc", "F", radius=1.0)
    with pytest.raises(NoIntersection) as err:
        figure.draw("X", "intersect_circles", "k1", "k3", pick="left")
    assert err.value.margin == pytest.approx(math.hypot(10, 10) - 4.0, rel=1e-15)
    assert "X" not in figure


def test_slice_of_an_unknown_step_raises(figure):
    with pytest.raises(TarsimError):
        record.slice(figure, ["Q", "nowhere"])


def test_an_unknown_verb_raises_tarsim_error(figure):
    with pytest.raises(TarsimError):
        figure.draw("X", "bisect", "O", "A")


def test_steps_are_frozen(figure):
    with pytest.raises(dataclasses.FrozenInstanceError):
        figure["P"].conditioning = 1.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        figure["P"].output = Point(0, 0)
    assert isinstance(figure["P"], Step)
