"""Random gear trains (tests/random_trains.py) are solved to their closed form or refused in
one located line, whatever member drives them.

The closed form is the generator's own: with the arm held each member turns e_k times the
reference gear (driver over driven teeth along the meshes, − for each external one), so
ω_k = ω_arm + e_k·x, and the fixed member's 0 and the input's speed give ω_arm and x. It
shares nothing with the tabular method or the Willis system but the tooth numbers.
"""

from __future__ import annotations

import math
import random
from fractions import Fraction
from itertools import permutations
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from tarsim.exercises.gears.train_file import parse_train
from tarsim.exercises.gears.train_solution import TrainSolution, solve_train
from tests.random_trains import FAMILIES, _body, build, generate, oracle, run_train_case, train_toml


def ratios(speeds: dict[int, Fraction]) -> dict[tuple[int, int], Fraction]:
    """ω_a/ω_b for every pair of members that turn."""
    return {(a, b): speeds[a] / speeds[b] for a, b in permutations(speeds, 2) if speeds[b]}


@settings(max_examples=120, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), family=st.sampled_from(FAMILIES),
       speed=st.fractions(Fraction(-5000), Fraction(5000), max_denominator=7).filter(bool))
def test_any_member_driving_gives_the_closed_form_ratios(seed, family, speed):
    """Each member but the fixed one in turn drives the train, at any speed: the speeds found
    are Willis', and the ratio of every pair of turning members is the closed form's,
    whichever member drove."""
    t = build(random.Random(seed), family)
    if t.expect != "answer" or len(t.members) > 24:
        return                          # a steep chain of dozens of stages is refused
    spec = t.spec
    spec["ask"] = {"find": [f"omega{m}" for m in t.members]}
    spec["input"] |= {"speed": float(abs(speed)), "sense": "ccw" if speed > 0 else "cw"}
    free = [m for m in t.members if "fixed" not in spec or m not in _body(spec, spec["fixed"])]
    want = None
    for member in free:
        spec["input"]["member"] = member
        closed = oracle(t)
        if closed is None:              # it turns with the fixed member: it cannot drive
            continue
        s = solve_train(parse_train(train_toml(spec), "t.toml"))
        assert s.found.speeds == s.reference == closed
        assert s.found.speeds[member] == Fraction(repr(float(abs(speed)))) * (speed / abs(speed))
        got = ratios(s.found.speeds)
        want = want or ratios(closed)
        assert got == want, member


def test_an_answer_the_closed_form_contradicts_is_caught(tmp_path):
    """The runner is no check that cannot fail: a case whose oracle is altered by one tooth's
    worth is judged wrong, and so is an answer to a file that must be refused."""
    rng = random.Random(4)
    while True:
        family, text = generate(rng, "compound")
        if "# oracle expect = answer" in text and "omega3" in text.split("[ask]")[1]:
            break
    assert run_train_case(text, tmp_path / "a.toml").outcome == "ok"
    line = next(x for x in text.splitlines() if x.startswith("# oracle omega3 = "))
    value = Fraction(line.split(" = ")[1])
    bent = text.replace(line, f"# oracle omega3 = {value * Fraction(41, 40)}")
    got = run_train_case(bent, tmp_path / "b.toml")
    assert got.outcome == "wrong" and "omega3" in got.message
    refuse = text.replace("# oracle expect = answer", "# oracle expect = refused")
    assert run_train_case(refuse, tmp_path / "c.toml").outcome == "wrong"


def test_an_infinity_in_a_trains_results_is_caught(tmp_path, monkeypatch):
    """A sun at rest beside members at 1e28 rpm is solved to finite numbers; were its velocity
    diagram's error measured against its own nil speed (an infinity, as it once was), the
    runner would judge the case ``other``, whether it reads the results or writes the files
    (whose writer refuses a number JSON has not)."""
    text = (Path(__file__).parent / "reproducers" / "inf-gear-kutzbach-sun-at-rest.toml"
            ).read_text(encoding="utf-8")
    assert run_train_case(text, tmp_path / "a.toml", render=True).outcome == "ok"
    monkeypatch.setattr(TrainSolution, "diagram_check", lambda self, m: (math.inf, 1e-12))
    got = run_train_case(text, tmp_path / "b.toml")
    assert got.outcome == "other" and "velocity_diagram.rel_error is not finite" in got.message
    got = run_train_case(text, tmp_path / "c.toml", render=True)
    assert got.outcome == "other" and "JSON compliant" in got.message
