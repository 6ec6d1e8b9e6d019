"""tarsim's own worked page, exported as SVG and graded as a student's drawing is, at every
bundled position of every bundled exercise that has one, in English and in Persian (whose
polygons' labels are the same letters): every item correct, every tip of every polygon
the page draws graded, and no label left ungraded.

The worked page is read as any drawing is (exercises/grading/): its space diagram told
from the polygons beside it, the step numbers in their rings and the results table left
out, each tip's label paired with the mark nearest it. Nothing in the grader knows the
page is tarsim's. What a tip's grade is held to comes from the exercise's own analytic
solution, so the page grades correct only where it draws and labels each tip where the
analytic solution puts it, within a pen's width at its scale.
"""

from __future__ import annotations

import pytest

import tarsim
from tarsim.constructions.linkages.acceleration_polygon import drawn_acceleration_polygon
from tarsim.constructions.narration import speaking
from tarsim.constructions.linkages.velocity_polygon import drawn_velocity_polygon
from tarsim.exercises.catalog import everything
from tarsim.exercises.grading.grade import grade
from tarsim.exercises.linkages.solution_files import solve_worked

WORKED = ("crank-pin-speed", "crank-shaper", "inverted-slider-crank", "klein-slider-crank",
          "piston-driven-slider-crank", "rolling-wheel", "wheel-driven-slider",
          "wheel-round-circle", "whitworth")
"""The bundled exercises that draw a worked page."""

def _tips(sol) -> tuple[set[str], set[str]]:
    """The tips of the polygons the position draws, as a grade names them (``a4′``): those
    of its moving points and slot points (``A4``), which a page must label, and those of
    any point but the frame's (at the pole; a helper's, such as a wheel's contact point,
    graded where the page labels it)."""
    work = sol.work
    mech = work.mechanism
    fixed = {n for n in mech.point_names if 1 in mech.links_at(n)}
    polygons = [(drawn_velocity_polygon(work), "")]
    if work.has("acceleration polygon"):
        polygons.append((drawn_acceleration_polygon(work), "′"))
    tips = [(n, n.lower() + mark) for poly, mark in polygons for n in poly.tips
            if n not in fixed]
    return ({name for n, name in tips if n.rstrip("0123456789") in mech.point_names},
            {name for _, name in tips})


@pytest.mark.slow
def test_these_are_the_bundled_exercises_with_a_worked_page():
    """A bundled exercise that gains a worked page is graded here too."""
    drawn = {name for name in everything()
             if any(stem.startswith("worked") for stem in tarsim.solve(tarsim.load(name))
                    .figures)}
    assert drawn == set(WORKED)


def _graded(tmp_path, name: str, lang: str):
    """Each position's grade of the exercise's worked page drawn in ``lang``, with the
    position's solution."""
    ex = tarsim.load(name)
    with speaking(lang):
        worked = solve_worked(ex)
        pages = [f for f in worked.pages if f.stem.startswith("worked")]
    assert len(pages) == len(worked.positions)
    for k, sol in enumerate(worked.positions):
        (page,) = [f for f in pages if f.owner is sol]
        path = tmp_path / f"{lang}-{page.stem}.svg"
        path.write_text(page.svg, encoding="utf-8")
        yield k, sol, grade(ex, path, k, positions=worked.positions)


@pytest.mark.slow
@pytest.mark.parametrize("lang", ["en", "fa"])
@pytest.mark.parametrize("name", WORKED)
def test_the_worked_page_grades_correct_at_every_position(tmp_path, name, lang):
    for k, sol, g in _graded(tmp_path, name, lang):
        where = f"{name} position {k + 1} ({lang})"
        wrong = [(i.name, i.verdict, i.message) for i in g.items if i.verdict != "correct"]
        assert not wrong, (where, wrong)
        graded = {i.name for i in g.items if not i.name.startswith("I")}
        required, drawn = _tips(sol)
        assert required <= graded <= drawn, (where, graded)
        assert not [n for n in g.notes if "not graded" in n or "needs its pole" in n], \
            (where, g.notes)


@pytest.mark.slow
@pytest.mark.parametrize("lang", ["en", "fa"])
def test_a_tip_a_quarter_millimetre_from_the_pole_grades_correct(tmp_path, lang):
    """The wheel-driven slider's c′ stands 0.25 mm from o_a on an acceleration polygon drawn
    at 0.3 of the course's 10 cm: held to no less than a pen on that paper (0.5 mm), not
    the pen at 10 cm scaled down (0.22 mm), it is right where the page draws it."""
    for _, _, g in _graded(tmp_path, "wheel-driven-slider", lang):
        (item,) = [i for i in g.items if i.name == "c′"]
        assert item.verdict == "correct" and item.tolerance >= 0.5, item
