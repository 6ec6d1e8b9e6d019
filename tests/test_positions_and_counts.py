"""Two quantities textbooks ask before any velocity: where a point is (``pos_B``, read off
the compass work of the assembly) and how many instant centres a mechanism has
(``n_centres``: n(n − 1)/2, so many by inspection, the rest by Kennedy's theorem). Each is
checked against the analytic side: the vector-loop solver's points, and a count of the
links joined directly, made from the mechanism's joints, not from the drawing."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from tarsim.constructions import asks as A
from tarsim.constructions.reference import solver
from tarsim.exercises.catalog import load
from tarsim.exercises.linkages.solution import solve_exercise, solve_overall
from tarsim.constructions.narration import speaking
from tarsim.exercises.linkages.answer_text import answer_line, overall_text
from tarsim.exercises.linkages.solution_files import solve_worked


def at_its_angle(name: str):
    ex = load(name)
    return replace(ex, positions=()) if ex.positions else ex


@pytest.mark.parametrize("name", ["four-bar", "crank-shaper", "six-link-homework-3",
                                  "whitworth", "hinkle-four-bar"])
def test_every_point_is_where_the_vector_loop_puts_it(name):
    ex = at_its_angle(name)
    names = tuple(f"pos_{p}" for p in ex.mechanism.point_names)
    sol = solve_exercise(ex.asking(names))
    kin = solver.solve(ex.mechanism)
    size = max(math.dist(p, q) for p in kin.points.values() for q in kin.points.values())
    for p in ex.mechanism.point_names:
        q = sol.quantities[f"pos_{p}"]
        # A dyad's intersection carries a few eps of the mechanism's size, over its
        # conditioning: well inside the tolerance the check grants it.
        assert math.dist(q.value["point"], kin.points[p]) <= 1e-12 * size, p
        assert q.passed and q.rel_error <= q.tolerance


def test_the_four_bars_crank_pin_is_where_its_crank_puts_it():
    # O2A = 100 mm at θ2 = 60°: A = (100 cos 60°, 100 sin 60°) mm, exactly as drawn.
    q = solve_exercise(at_its_angle("four-bar").asking(("pos_A",))).quantities["pos_A"]
    assert q.value["point"] == pytest.approx([0.05, 0.1 * math.sin(math.radians(60))],
                                             abs=1e-15)
    line = answer_line("pos_A", q, load("four-bar").mechanism.units)
    assert line.startswith("pos_A = (50, 86.6025) mm")


@pytest.mark.parametrize("name, total, inspected", [
    ("four-bar", 6, 4),                 # four pins; I13, I24 by Kennedy
    ("offset-slider-crank", 6, 4),      # three pins and the block: I14 at infinity
    ("crank-shaper", 10, 5),            # pins O2, A, O4; the blocks on link 4 and on 1
    ("six-link-homework-1", 15, 8),     # the course's own count (notes §3.8, homework 1)
    ("six-link-homework-3", 15, 7),     # a Watt-I six-bar: seven pins
])
def test_the_count_of_centres_is_n_n_minus_1_over_2_split_as_found(name, total, inspected):
    ex = load(name).asking(("n_centres",))
    q = solve_overall(ex).quantities["n_centres"]
    assert {k: q.value[k] for k in ("value", "by_inspection", "by_kennedy")} == {
        "value": total, "by_inspection": inspected, "by_kennedy": total - inspected}
    assert q.reference == q.value and q.passed
    n = len(ex.mechanism.numbers)
    assert total == n * (n - 1) // 2


def test_the_count_and_the_positions_are_in_the_grammar_and_the_files(tmp_path):
    mech = load("four-bar").mechanism
    assert A.parse_ask("pos_B") == A.Position("B")
    assert A.parse_ask("n_centres") == A.CentreCount()
    assert {"pos_O2", "pos_B", "n_centres"} <= A.ask_names(mech)
    ex = at_its_angle("four-bar").asking(("n_centres", "pos_B"))
    worked = solve_worked(ex)
    files = worked.files()
    assert "positions.svg" in files                    # the compass work that placed B
    assert '"n_centres"' in files["results.json"] and '"pos_B"' in files["results.json"]
    assert "With centre O4 and radius O4B = 200 mm" in files["steps.md"]


@pytest.mark.parametrize("name, far", [
    ("four-bar", 0),                    # every link turns at its own rate: no centre is far
    ("offset-slider-crank", 1),         # the block on the straight guide: I14 alone
    ("parallelogram-four-bar", 2),      # ω2 = ω4 and the coupler translates: I24 and I13
])
def test_n_centres_counts_the_centres_at_infinity(name, far):
    # Closed forms: I_ij is at infinity exactly where ω_i = ω_j. A slider-crank's block
    # never turns (ω4 = ω1 = 0) and nothing else shares a rate; a parallelogram's crank
    # and rocker turn alike (ω2 = ω4), and its coupler with the frame (ω3 = ω1 = 0).
    q = solve_overall(load(name).asking(("n_centres",))).quantities["n_centres"]
    assert q.value["far_centres"] == far
    assert q.reference["far_centres"] == far and q.passed


def test_the_centres_at_infinity_are_said_in_english_and_persian():
    ex = load("parallelogram-four-bar").asking(("n_centres",))
    q = solve_overall(ex).quantities["n_centres"]
    line = answer_line("n_centres", q, ex.mechanism.units, whole=True)
    assert "(4 by inspection, 2 by Kennedy; 2 at infinity)" in line
    with speaking("fa"):
        said = overall_text("n_centres", q.value, ex.mechanism.units)
    assert "در بی‌نهایت" in said and "۲" in said
