"""A compound train designed as the books pose it: an overall ratio in equal steps, or each
pair's own ratio, with a least count for each pair's pinion."""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.catalog import load
from tarsim.exercises.gears.train_file import parse_train
from tarsim.exercises.gears.train_solution import solve_train

F = Fraction


def compound(pairs: int, ratio_tables: str, module: str = "3") -> str:
    """A compound train of ``pairs`` pairs: gears 2k and 2k+1 mesh, 2k+1 shares a shaft
    with 2k+2; the input is gear 2 at 1440 rpm."""
    last = 2 * pairs + 1
    gears = "".join(f"[[gear]]\nnumber = {n}\nmodule = {module}\n" for n in range(2, last + 1))
    shafts = "".join(f"[[shaft]]\nmembers = [{n}, {n + 1}]\n" for n in range(3, last - 1, 2))
    meshes = "".join(f"[[mesh]]\ngears = [{n}, {n + 1}]\n" for n in range(2, last, 2))
    teeth = ", ".join(f'"teeth{n}"' for n in range(2, last + 1))
    return (f'[units]\nspeed = "rpm"\nlength = "mm"\n{gears}{shafts}{meshes}{ratio_tables}'
            f'[input]\nmember = 2\nspeed = 1440\n[ask]\nfind = [{teeth}, "omega{last}", '
            '"centre_distance2_3"]\n')


EQUAL = '[[ratio]]\nof = "omega2/omega{last}"\nvalue = "{value}"\nsteps = "equal"\n{least}'


def equal(pairs: int, value: Fraction, least: int | None = 16) -> str:
    return compound(pairs, EQUAL.format(last=2 * pairs + 1, value=value,
                                        least=f"least_teeth = {least}\n" if least else ""))


def test_the_book_s_36_to_1_in_two_equal_steps():
    """Each step √36 = 6: pinions 16 (the least), wheels 6·16 = 96, each pair 3·(16 + 96)/2
    = 168 mm apart, the output 1440/36 = 40 rpm; exact counts, so no tolerance."""
    s = solve_train(parse_train(equal(2, F(36)), "c.toml"))
    q = s.quantities
    assert [q[f"teeth{n}"].exact for n in range(2, 6)] == [16, 96, 16, 96]
    assert q["centre_distance2_3"].exact == F(168, 1000)       # m
    assert q["omega5"].exact == 40 and s.passed
    assert "36^(1/2) = 6" in s.steps()


def test_the_bundled_compound_equal_steps_is_the_book_s_problem():
    """The bundled example states the same problem: 16, 96, 16, 96, 168 mm, 40 rpm."""
    q = solve_train(load("compound-equal-steps")).quantities
    assert [q[f"teeth{n}"].exact for n in range(2, 6)] == [16, 96, 16, 96]
    assert q["centre_distance4_5"].exact == F(168, 1000) and q["omega5"].exact == 40


def test_each_pair_s_own_ratio_with_its_least_count_gives_the_same():
    """The book's other wording: two [[ratio]] of 6, least_teeth 16 in each."""
    tables = "".join(f'[[ratio]]\nof = "omega{a}/omega{a + 1}"\nvalue = 6\nleast_teeth = 16\n'
                     for a in (2, 4))
    q = solve_train(parse_train(compound(2, tables), "c.toml")).quantities
    assert [q[f"teeth{n}"].exact for n in range(2, 6)] == [16, 96, 16, 96]


@settings(max_examples=25, deadline=None)
@given(st.integers(2, 3), st.integers(2, 9), st.integers(1, 4), st.integers(12, 30))
def test_equal_steps_give_each_pinion_the_fewest_from_least_making_its_wheel_whole(
        pairs, top, bottom, least):
    """Each pair's ratio r = p/q (lowest terms), the k-th root of r^k: its pinion takes the
    first multiple of q from ``least`` up, n = q·⌈least/q⌉, its wheel n·r, and the output
    turns (−1)^k·1440/r^k (each external mesh reversing it); the Willis reference agrees
    exactly."""
    r = F(top, bottom)
    if r <= 1:
        r = 1 + r
    s = solve_train(parse_train(equal(pairs, r ** pairs, least), "c.toml"))
    q = s.quantities
    n = r.denominator * -(-least // r.denominator)
    for k in range(pairs):
        assert (q[f"teeth{2 + 2 * k}"].exact, q[f"teeth{3 + 2 * k}"].exact) == (n, n * r)
    assert q[f"omega{2 * pairs + 1}"].exact == (-1) ** pairs * 1440 / r ** pairs
    assert s.passed


STEPS_LINE = equal(2, F(40)).splitlines().index('steps = "equal"') + 1


@pytest.mark.parametrize("text, words", [
    # √40 is irrational: no two equal pairs of whole teeth give 40
    (equal(2, F(40)), f"c.toml:{STEPS_LINE}: [ratio.steps] ω2/ω5 = 40 in 2 equal steps "
                      "needs each pair 6.32456"),
    (equal(2, F(36)).replace('"equal"', '"even"'), 'steps = "equal" shares the ratio'),
    # the overall ratio alone, steps left out: the refusal names the way to say them
    (equal(2, F(36)).replace('steps = "equal"\n', ""),
     'least_teeth for a pair, or steps = "equal" to share the ratio among the pairs'),
    # a least count in one pair's ratio leaves the other pair open
    (compound(2, '[[ratio]]\nof = "omega2/omega3"\nvalue = 6\nleast_teeth = 16\n'
                 '[[ratio]]\nof = "omega4/omega5"\nvalue = 6\n'),
     "gears 4 and 5 have no teeth, and their ratio ω4/ω5 = 6 fixes one count"),
])
def test_equal_steps_that_cannot_be_designed_are_refused_in_one_line(text, words):
    with pytest.raises(InputError) as e:
        parse_train(text, "c.toml")
    assert words in str(e.value) and "\n" not in str(e.value) and len(str(e.value)) < 200
