"""Fitting a figure to its sheet: the scale the step-by-step rule chooses, found with no
more drawings, and a figure too big drawn twice where its drawing shrinks with the scale."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from tarsim.constructions.scales import nice
from tarsim.graphics.figure import Figure
from tarsim.graphics.fitting import fit, foretold, held_by
from tarsim.graphics.paper import PAPERS

A4 = held_by(PAPERS["A4"])


def _step_by_step(draw, per_cm, holds, *, grow):
    """The rule :func:`fit` states, drawing every step it looks at (three coarser at most;
    two finer, each tried if four fifths of the figure grown whole is held)."""
    fig, first = draw(per_cm), per_cm
    for _ in range(3):
        if holds(fig):
            break
        per_cm = nice(per_cm * 1.01)
        fig = draw(per_cm)
    for _ in range(2 if grow and per_cm == first and holds(fig) else 0):
        finer = nice(per_cm * 0.99, up=False)
        k = 0.8 * per_cm / finer
        if not holds(Figure(fig.width * k, fig.height * k)):
            break
        bigger = draw(finer)
        if not holds(bigger):
            break
        fig, per_cm = bigger, finer
    return fig


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


def test_a_figure_four_times_too_big_is_drawn_twice_at_the_step_it_fits():
    # At 1 cm = 10 mm the drawing is 900 × 600 mm: at 20 it is 450 × 300 (466 × 356 with
    # margins and caption: no A4 holds it), at 50 it is 180 × 120 (196 × 176: A4 on its
    # side, 297 × 210, holds it). Step by step draws 10, 20 and 50; the forecast from the
    # first drawing says 20 cannot be held, so only 10 and 50 are drawn.
    draw, drawn = _figure(900.0, 600.0, at=10.0, caption=(100.0, 40.0))
    fig = fit(draw, 10.0, A4)
    assert drawn == [10.0, 50.0] and (fig.width, fig.height) == (196.0, 176.0)
    draw, drawn = _figure(900.0, 600.0, at=10.0, caption=(100.0, 40.0))
    _step_by_step(draw, 10.0, A4, grow=False)
    assert drawn == [10.0, 20.0, 50.0]


def test_a_stated_scale_is_drawn_once_however_big():
    draw, drawn = _figure(900.0, 600.0, at=10.0, caption=(100.0, 40.0))
    assert fit(draw, 10.0, A4, fixed=True).width == 916.0 and drawn == [10.0]


def test_the_forecast_shrinks_the_drawing_and_keeps_the_caption():
    # 200 mm of a 240 mm wide figure is drawing: at twice the scale, 100 + 40
    f = foretold(Figure(240.0, 150.0, drawing=(200.0, 100.0)), 10.0, 20.0)
    assert (f.width, f.height) == (140.0, 100.0)
    # a figure that does not say what its drawing is shrinks whole
    f = foretold(Figure(240.0, 150.0), 10.0, 20.0)
    assert (f.width, f.height) == (120.0, 75.0)


SCALES = st.sampled_from([0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0])


@settings(max_examples=400, deadline=None)
@given(width=st.floats(5.0, 3000.0), aspect=st.floats(0.05, 3.0), at=SCALES,
       caption=st.tuples(st.floats(40.0, 260.0), st.floats(15.0, 90.0)),
       marks=st.floats(0.0, 20.0), grow=st.booleans())
def test_fit_chooses_what_step_by_step_chooses_with_no_more_drawings(width, aspect, at,
                                                                      caption, marks, grow):
    # Labels that keep their size make the figure at a coarser scale bigger than the
    # forecast, never smaller, so a step the forecast rules out is one that fails.
    draw, drawn = _figure(width, width * aspect, at=at, caption=caption, marks=marks)
    fig = fit(draw, at, A4, grow=grow)
    ref, looked = _figure(width, width * aspect, at=at, caption=caption, marks=marks)
    want = _step_by_step(ref, at, A4, grow=grow)
    assert (fig.width, fig.height) == (want.width, want.height)
    assert drawn[-1] in looked and len(drawn) <= len(looked)


@settings(max_examples=300, deadline=None)
@given(width=st.floats(5.0, 3000.0), aspect=st.floats(0.05, 3.0), at=SCALES,
       caption=st.floats(15.0, 90.0))
def test_a_figure_too_big_whose_drawing_alone_sets_its_width_is_drawn_twice_at_most(
        width, aspect, at, caption):
    # The forecast is then exact: a step it does not rule out is held. (A caption wider
    # than the drawing keeps its width at every scale: the forecast, which shrinks the
    # drawing, then says too little and a step may be drawn that fails.)
    draw, drawn = _figure(width, width * aspect, at=at, caption=(0.0, caption))
    fig = fit(draw, at, A4)
    assert len(drawn) <= 2
    # and it is held, unless even three steps coarser it is too big
    assert A4(fig) or drawn[-1] == nice(nice(nice(at * 1.01) * 1.01) * 1.01)
