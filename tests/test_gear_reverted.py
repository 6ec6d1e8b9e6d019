"""A reverted train's teeth from its pairs' modules, the coaxial condition and its ratios.

Two pairs, A (1) → B (2) and C (3) on B's shaft → D (4) on A's axis, each at its own module:
the shafts stand m₁(N₁ + N₂)/2 = m₂(N₃ + N₄)/2 apart. Whatever the data leave out (a pair's
counts with its ratio, the second pair's with the whole train's, every count with a least
one), the counts found must satisfy that equation and every ratio given, exactly.
"""

from __future__ import annotations

from fractions import Fraction as F

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises.gears.train_file import parse_train
from tarsim.exercises.gears.train_solution import solve_train

MODULES = ("1", "1.25", "1.5", "2", "2.5", "3", "3.125", "4", "5", "6", "8", "10")


def reverted(m1: str, m2: str, teeth: dict[int, int], ratios: list[tuple[str, F]],
             least: int | None = None, find: str = '"teeth1", "teeth2", "teeth3", "teeth4"',
             distance: F | None = None) -> str:
    """The train's file, the counts in ``teeth`` given, each ratio a ``[[ratio]]``, and
    the first pair's centre ``distance`` if given."""
    gears = "".join(f"[[gear]]\nnumber = {n}\nmodule = {m}\n"
                    + (f"teeth = {teeth[n]}\n" if n in teeth else "")
                    for n, m in ((1, m1), (2, m1), (3, m2), (4, m2)))
    tables = "".join(f'[[ratio]]\nof = "{of}"\nvalue = "{v.numerator}/{v.denominator}"\n'
                     + (f"least_teeth = {least}\n" if least is not None and i == 0 else "")
                     for i, (of, v) in enumerate(ratios))
    return (f'coaxial = [1, 4]\n[units]\nlength = "mm"\n{gears}[[shaft]]\nmembers = [2, 3]\n'
            "[[mesh]]\ngears = [1, 2]\n" + (f'centre_distance = "{distance}"\n' if distance
                                           else "")
            + f"[[mesh]]\ngears = [3, 4]\n{tables}"
            f"[input]\nmember = 1\nspeed = 1440\n[ask]\nfind = [{find}]\n")


@st.composite
def trains(draw):
    """Two modules and four counts that stand the pairs equally far apart: m₁/m₂ = p/q in
    lowest terms, so N₁ + N₂ = q·t and N₃ + N₄ = p·t."""
    m1, m2 = (draw(st.sampled_from(MODULES)) for _ in range(2))
    p, q = (F(m1) / F(m2)).numerator, (F(m1) / F(m2)).denominator
    t = draw(st.integers(max(1, -(-24 // min(p, q))), max(1, 240 // max(p, q))))
    s1, s2 = q * t, p * t
    n1 = draw(st.integers(max(1, s1 // 6), max(1, s1 // 2)))
    n3 = draw(st.integers(max(1, s2 // 6), max(1, s2 // 2)))
    return m1, m2, {1: n1, 2: s1 - n1, 3: n3, 4: s2 - n3}


def counts(text: str) -> dict[int, int]:
    return {g.number: g.teeth for g in parse_train(text, "r.toml").train.gears}


def holds(m1: str, m2: str, n: dict[int, int], ratios: list[tuple[str, F]]) -> bool:
    """The coaxial condition in length, and each ratio by the train value (two external
    meshes: |ω₁/ω₂| = N₂/N₁, |ω₃/ω₄| = N₄/N₃, |ω₁/ω₄| = N₂N₄/(N₁N₃))."""
    speed = {"omega1/omega2": F(n[2], n[1]), "omega3/omega4": F(n[4], n[3]),
             "omega1/omega4": F(n[2] * n[4], n[1] * n[3])}
    return (F(m1) * (n[1] + n[2]) == F(m2) * (n[3] + n[4])
            and all(speed[of] == v for of, v in ratios))


@settings(max_examples=60, deadline=None)
@given(trains(), st.sampled_from(["second pair", "whole train", "one pinion", "distance"]))
def test_the_coaxial_condition_and_the_ratios_fix_the_counts_left_out(train, left):
    """The first pair given and the second's ratio (or the whole train's), or only the
    first pinion, or the shafts' distance m₁(N₁ + N₂)/2, with both pairs' ratios: the counts
    are the one solution, N₃ = m₁(N₁ + N₂)/(m₂(1 + N₄/N₃)) and the rest, which the
    generated train is."""
    m1, m2, n = train
    both = [("omega1/omega2", F(n[2], n[1])), ("omega3/omega4", F(n[4], n[3]))]
    ratios = {"second pair": both[1:],
              "whole train": [("omega1/omega4", F(n[2] * n[4], n[1] * n[3]))],
              "one pinion": both, "distance": both}[left]
    given_teeth = {"one pinion": {1: n[1]}, "distance": {}}.get(left, {1: n[1], 2: n[2]})
    distance = F(m1) * (n[1] + n[2]) / 2 if left == "distance" else None
    found = counts(reverted(m1, m2, given_teeth, ratios, distance=distance))
    assert found == n and holds(m1, m2, found, ratios)


@settings(max_examples=40, deadline=None)
@given(trains(), st.integers(1, 30))
def test_a_least_count_never_overrides_the_coaxial_condition(train, least):
    """Both pairs' ratios and a least count, every count left out: whatever counts are
    chosen stand the shafts equally far apart, give both ratios, and none is below the
    least (the generated train, its smallest count at least ``least`` if that is, shows
    one exists); with the first pair given, the least count changes nothing."""
    m1, m2, n = train
    ratios = [("omega1/omega2", F(n[2], n[1])), ("omega3/omega4", F(n[4], n[3]))]
    try:
        found = counts(reverted(m1, m2, {}, ratios, least))
    except InputError as e:     # only where no train of the least count may exist
        assert min(n.values()) < least and "\n" not in str(e), str(e)
    else:
        assert holds(m1, m2, found, ratios) and min(found.values()) >= least
    second = ratios[1:]
    if min(n[3], n[4]) >= least:
        found = counts(reverted(m1, m2, {1: n[1], 2: n[2]}, second, least))
        assert found == n and holds(m1, m2, found, second)


def test_the_book_s_reverted_train_with_two_modules():
    """4·(20 + 60)/2 = 160 mm = 5·(N₃ + 3N₃)/2: N₃ = 16, N₄ = 48, as the books give it,
    with no least count; ω₄ = 1440·(20·16)/(60·48) = 160 rpm, A's sense."""
    text = reverted("4", "5", {1: 20, 2: 60}, [("omega3/omega4", F(3))],
                    find='"teeth3", "teeth4", "omega4"')
    s = solve_train(parse_train(text, "r.toml"))
    q = s.quantities
    assert (q["teeth3"].exact, q["teeth4"].exact, q["omega4"].exact) == (16, 48, 160)
    assert q["teeth3"].reference == 16 and s.passed
    assert "4 mm·(20 + 60)/2 = 5 mm·(N4 + 16)/2" in s.steps()


def test_a_least_count_above_the_counts_the_data_fix_is_refused():
    """The data fix N₃ = 16: least_teeth = 20 cannot hold, and is refused, not dropped."""
    text = reverted("4", "5", {1: 20, 2: 60}, [("omega3/omega4", F(3))], least=20)
    with pytest.raises(InputError, match=r"^r\.toml:\d+: the speed ratios and the coaxial "
                                         r"condition give gear 3 16 teeth, fewer than "
                                         r"least_teeth = 20: .*$"):
        parse_train(text, "r.toml")


@pytest.mark.parametrize("m2, teeth, words", [
    ("5", {1: 20, 2: 60, 3: 16, 4: 50}, "4 mm·(20 + 60)/2 ≠ 5 mm·(50 + 16)/2"),
    ("4", {1: 20, 2: 60, 3: 30, 4: 40}, "4 mm·(20 + 60)/2 ≠ 4 mm·(40 + 30)/2"),
])
def test_teeth_given_that_put_the_coaxial_gears_apart_are_refused(m2, teeth, words):
    """Every count given, the two pairs at different distances: coaxial cannot hold."""
    text = reverted("4", m2, teeth, [], find='"omega4"')
    with pytest.raises(InputError) as e:
        parse_train(text, "r.toml")
    said = str(e.value)
    assert said.startswith("r.toml:1: [coaxial] gears 1 and 4 are not on one axis")
    assert words in said
    assert "\n" not in said and len(said) < 200


@pytest.mark.parametrize("teeth, ratios, least, words", [
    # 4·80/6 = 53⅓ = N₃ + N₄: no whole pair, whatever the ratio
    ({1: 20, 2: 60}, [("omega3/omega4", F(3))], None,
     "the speed ratio ω3/ω4 = 3, the coaxial condition and the centre distances give gears "
     "3, 4 no whole counts"),
    # the whole train's ratio alone leaves how it splits between the pairs open
    ({}, [("omega1/omega4", F(9))], 20, "leave them open: give each pair's ratio"),
    # each pair's ratio and the coaxial condition leave the size open
    ({}, [("omega1/omega2", F(4)), ("omega3/omega4", F(3))], None,
     "leave them open: give least_teeth"),
])
def test_counts_the_data_cannot_give_are_refused_saying_why(teeth, ratios, least, words):
    text = reverted("4", "6", teeth, ratios, least)
    with pytest.raises(InputError) as e:
        parse_train(text, "r.toml")
    assert words in str(e.value) and "\n" not in str(e.value) and len(str(e.value)) < 220


@pytest.mark.parametrize("coaxial", ["[1, 2]", "[2, 3]", "[1, 3]"])
def test_coaxial_gears_that_end_no_two_pairs_on_a_shaft_are_refused(coaxial):
    """A meshing pair, one shaft's two gears, or a gear and its pair's layshaft gear stand
    no two pairs equally far apart: the condition could not be used, so it is refused."""
    text = reverted("4", "5", {1: 20, 2: 60}, [("omega3/omega4", F(3))]).replace(
        "coaxial = [1, 4]", f"coaxial = {coaxial}")
    with pytest.raises(InputError) as e:
        parse_train(text, "r.toml")
    assert str(e.value) == (f"r.toml:1: [coaxial] coaxial = {coaxial} names gears that end no "
                            "two pairs joined by a shaft: name a reverted train's input and "
                            "output gears, coaxial = [1, 4]")
    # named the other way round, the train's ends are as good
    text = text.replace(f"coaxial = {coaxial}", "coaxial = [4, 1]")
    assert counts(text) == {1: 20, 2: 60, 3: 16, 4: 48}
