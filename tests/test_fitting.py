"""Fitting a figure to its sheet: the scale the step-by-step rule chooses, found on drafts,
and the figure laid out (its labels placed) once, at that scale; a bundled figure drawn
as the rule followed on drawn figures draws it."""

from __future__ import annotations

import pytest
from hypothesis import given, settings, strategies as st

from tarsim import load
from tarsim.constructions.narration import speaking
from tarsim.constructions.scales import nice
from tarsim.exercises.linkages.solution_files import solve_worked
from tarsim.graphics import drafts, workers
from tarsim.graphics.figure import Figure
from tarsim.graphics.fitting import COARSER, finer, fit, foretold, held_by
from tarsim.graphics.forces import figures as force_figures
from tarsim.graphics.linkages import figures as linkage_figures
from tarsim.graphics.occupancy import Occupancy
from tarsim.graphics.paper import PAPERS
from tarsim.graphics.svg import to_svg

A4 = held_by(PAPERS["A4"])


def _step_by_step(draw, per_cm, holds, *, grow):
    """The rule :func:`fit` states, drawing every step it looks at (three 1-2-5 steps
    coarser at most, then back by the course's steps between while held; four of the
    course's steps finer, each tried if four fifths of the figure foretold at it is held):
    the figure and its scale."""
    fig, first = draw(per_cm), per_cm
    for _ in range(3):
        if holds(fig):
            break
        per_cm = nice(per_cm * 1.01)
        fig = draw(per_cm)
    if per_cm != first and holds(fig):
        refused = nice(per_cm * 0.99, up=False)
        while finer(per_cm) > refused * (1 + 1e-9) and holds(draw(finer(per_cm))):
            per_cm = finer(per_cm)
            fig = draw(per_cm)
    for _ in range(4 if grow and per_cm == first and holds(fig) else 0):
        step = finer(per_cm)
        ahead = foretold(fig, per_cm, step)
        if not holds(Figure(ahead.width * 0.8, ahead.height * 0.8)):
            break
        bigger = draw(step)
        if not holds(bigger):
            break
        fig, per_cm = bigger, step
    return fig, per_cm


def _figure(width: float, height: float, *, at: float, caption: tuple[float, float],
            marks: float = 0.0):
    """A figure whose drawing is ``width`` × ``height`` mm at 1 cm = ``at`` and scales
    with it, plus ``marks`` mm of labels that keep their size, under a caption at least
    ``caption[0]`` wide and ``caption[1]`` high, with 8 mm margins; and the scales it is
    drawn at, in order."""
    drawn: list[float] = []

    def draw(per_cm: float) -> Figure:
        drawn.append(per_cm)
        w, h = width * at / per_cm + marks, height * at / per_cm + marks
        return Figure(max(w + 16.0, caption[0]), h + 16.0 + caption[1], drawing=(w, h))
    return draw, drawn


def _drawings(width, aspect, at, caption, marks):
    """:func:`_figure` of one drawing, its labels taking ``extra`` mm more (or less)."""
    return lambda extra=0.0: _figure(width, width * aspect, at=at, caption=caption,
                                     marks=marks + extra)


def _coarsest(per_cm: float) -> float:
    for _ in range(COARSER):
        per_cm = nice(per_cm * 1.01)
    return per_cm


def test_a_figure_four_times_too_big_is_drawn_once_at_the_finest_step_it_fits():
    # At 1 cm = 10 mm the drawing is 900 × 600 mm: at 20 it is 450 × 300 (466 × 356 with
    # margins and caption: no A4 holds it), at 50 it is 180 × 120 (196 × 176: A4 on its
    # side, 297 × 210, holds it). The forecast from the first draft says 20 cannot be
    # held, so 10 and 50 are drafted; then the course's steps between, 40 (225 × 150:
    # 241 × 206, held) and 25 (360 × 240, not), and the figure is drawn at 40 alone.
    draw, drawn = _figure(900.0, 600.0, at=10.0, caption=(100.0, 40.0))
    draft, drafted = _figure(900.0, 600.0, at=10.0, caption=(100.0, 40.0))
    fig = fit(draw, 10.0, A4, draft=draft)
    assert drafted == [10.0, 50.0, 40.0, 25.0] and drawn == [40.0]
    assert (fig.width, fig.height) == (241.0, 206.0)


def test_a_stated_scale_is_drawn_once_however_big_and_not_drafted():
    draw, drawn = _figure(900.0, 600.0, at=10.0, caption=(100.0, 40.0))
    draft, drafted = _figure(900.0, 600.0, at=10.0, caption=(100.0, 40.0))
    assert fit(draw, 10.0, A4, fixed=True, draft=draft).width == 916.0
    assert drawn == [10.0] and drafted == []


def test_the_forecast_shrinks_the_drawing_and_keeps_the_caption():
    # 200 mm of a 240 mm wide figure is drawing: at twice the scale, 100 + 40
    f = foretold(Figure(240.0, 150.0, drawing=(200.0, 100.0)), 10.0, 20.0)
    assert (f.width, f.height) == (140.0, 100.0)
    # a figure that does not say what its drawing is shrinks whole
    f = foretold(Figure(240.0, 150.0), 10.0, 20.0)
    assert (f.width, f.height) == (120.0, 75.0)


SCALES = st.sampled_from([0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0])
FIGURES = dict(width=st.floats(5.0, 3000.0), aspect=st.floats(0.05, 3.0), at=SCALES,
               caption=st.tuples(st.floats(40.0, 260.0), st.floats(15.0, 90.0)),
               marks=st.floats(0.0, 20.0), grow=st.booleans())


@settings(max_examples=400, deadline=None)
@given(**FIGURES)
def test_a_figure_whose_draft_foretells_it_is_drawn_once_where_the_rule_puts_it(
        width, aspect, at, caption, marks, grow):
    # Labels that keep their size make the figure at a coarser scale bigger than the
    # forecast, never smaller, so a step the forecast rules out is one that fails: the
    # drafts looked at are no more than the drawings step by step.
    made = _drawings(width, aspect, at, caption, marks)
    (draw, drawn), (draft, drafted), (ref, looked) = made(), made(), made()
    fig = fit(draw, at, A4, grow=grow, draft=draft)
    want, scale = _step_by_step(ref, at, A4, grow=grow)
    assert drawn == [scale] and (fig.width, fig.height) == (want.width, want.height)
    assert len(drafted) <= len(looked)


@settings(max_examples=400, deadline=None)
@given(**FIGURES, missed=st.floats(0.5, 30.0))
def test_a_figure_its_labels_take_past_the_sheet_is_drawn_coarser_till_it_is_held(
        width, aspect, at, caption, marks, grow, missed):
    # The draft misses ``missed`` mm of the labels: the rule on drafts may choose a scale
    # the drawn figure is not held at. It is drawn there, then a step coarser each time
    # it is refused, up to three steps coarser than the solve's scale.
    made = _drawings(width, aspect, at, caption, marks)
    (draw, drawn), (draft, _), (sizes, _) = made(missed), made(), made(missed)
    fig = fit(draw, at, A4, grow=grow, draft=draft)
    _, scale = _step_by_step(made()[0], at, A4, grow=grow)
    steps = [scale]
    while not A4(sizes(steps[-1])) and steps[-1] < _coarsest(at):
        steps.append(nice(steps[-1] * 1.01))
    assert drawn == steps
    assert A4(fig) or drawn[-1] == _coarsest(at)


@settings(max_examples=400, deadline=None)
@given(**FIGURES, over=st.floats(0.5, 30.0))
def test_a_figure_whose_draft_is_bigger_is_drawn_once_no_finer_than_the_rule_puts_it(
        width, aspect, at, caption, marks, grow, over):
    # A draft bigger than the figure is held only where the figure is: each step the
    # rule takes on drafts it takes on drawn figures, so it stops no finer.
    made = _drawings(width, aspect, at, caption, marks)
    (draw, drawn), (draft, _) = made(), made(over)
    fit(draw, at, A4, grow=grow, draft=draft)
    _, scale = _step_by_step(made()[0], at, A4, grow=grow)
    assert len(drawn) == 1 and drawn[0] >= scale


# ----- the bundled figures ----------------------------------------------------------------
FITTED = [
    ("four-bar", "en", True),                 # its centres refused at 1 cm = 20 mm
    ("offset-slider-crank", "en", False),     # a finer step tried and refused
    ("grashof-double-crank", "fa", True),     # a finer step taken: its Persian caption is narrower
    ("parallelogram-four-bar", "fa", True),
    ("engine-forces", "en", False),           # the loads on the space diagram
]


def _fitted(monkeypatch, exercise_id: str, lang: str) -> list[tuple]:
    """Each figure of the exercise that is fitted at the solve's scale: its drawing, the
    scale, what holds it and whether it may grow."""
    calls = []

    def record(draw, per_cm, holds, *, fixed=False, grow=False):
        if not fixed:
            calls.append((draw, per_cm, holds, grow))
        return fit(draw, per_cm, holds, fixed=fixed, grow=grow)

    monkeypatch.setattr(linkage_figures, "fit", record)
    monkeypatch.setattr(force_figures, "fit", record)
    monkeypatch.setattr(workers, "_cores", lambda: 1)      # drawn here, not in workers
    with speaking(lang):
        _ = solve_worked(load(exercise_id).named_in(lang)).pages      # every figure drawn
    return calls


class _Laid(drafts.LabelPlacer):
    """A label placer that counts the layouts it places labels for."""

    made = 0

    def __init__(self, fig):
        _Laid.made += 1
        super().__init__(fig)


@pytest.mark.parametrize("exercise_id, lang, moves", FITTED)
def test_a_bundled_figure_is_laid_out_once_as_the_rule_on_drawn_figures_draws_it(
        monkeypatch, exercise_id, lang, moves):
    calls = _fitted(monkeypatch, exercise_id, lang)
    assert calls
    monkeypatch.setattr(drafts, "LabelPlacer", _Laid)
    scales = []
    with speaking(lang):
        for draw, per_cm, holds, grow in calls:
            want, scale = _step_by_step(draw, per_cm, holds, grow=grow)
            _Laid.made = 0
            got = fit(draw, per_cm, holds, grow=grow)
            assert _Laid.made == 1
            assert to_svg(got) == to_svg(want)
            scales.append(scale != per_cm)
    assert any(scales) == moves


def test_a_draft_reads_no_ink(monkeypatch):
    # Most of the cost of placing a label is reading the ink under its candidate spots:
    # a draft reads none, the figure drawn does.
    calls = _fitted(monkeypatch, "four-bar", "en")
    draw, per_cm = calls[0][:2]
    read = []
    ink = Occupancy.ink
    monkeypatch.setattr(Occupancy, "ink", lambda self, *a: read.append(1) or ink(self, *a))
    with drafts.drafting():
        draw(per_cm)
    assert read == []
    draw(per_cm)
    assert read
