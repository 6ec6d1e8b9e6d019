"""The class of students' drawings (tests/grading_corpus.py) and its key: the truth it is
made from, the names it gives, its rule, and that it is made again byte for byte.

The truth is tests/loop_kinematics.py's closed-form loop equations, held here to the
analytic reference tarsim writes in results.json. Both are closed forms evaluated in double
precision, so they differ by rounding (some 1e-16 of the quantity); 1e-9 of the quantity's
own scale (the input's speed, its acceleration, the mechanism's size) is the checks'
ceiling, and a slip of sign, link or branch is of order one.
"""

from __future__ import annotations

import json
import math
import random
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import grading_corpus as corpus  # noqa: E402
from loop_kinematics import read_exercise, solve  # noqa: E402

from tarsim.constructions.linkages.acceleration_polygon import drawn_acceleration_polygon  # noqa: E402
from tarsim.constructions.linkages.velocity_polygon import drawn_velocity_polygon  # noqa: E402
from tarsim.exercises.catalog import load  # noqa: E402
from tarsim.exercises.linkages.results_json import results_document  # noqa: E402
from tarsim.exercises.linkages.solution import solve_positions  # noqa: E402

CLASS = Path(__file__).resolve().parent / "data" / "grading" / "class"
NAMES = [name for name, _ in corpus.EXERCISES]
REL = 1e-9


@pytest.fixture(scope="module")
def documents():
    """Each exercise of the class solved by tarsim: (its positions, results.json)."""
    out = {}
    for name in NAMES:
        ex = load(name)
        positions = solve_positions(ex)
        out[name] = (positions, results_document(positions, ex))
    return out


def _close(mine, reference, scale: float) -> None:
    mine, reference = [float(x) for x in mine], [float(x) for x in reference]
    assert math.dist(mine, reference) <= REL * max(math.hypot(*reference), scale), \
        (mine, reference)


@pytest.mark.parametrize("name", NAMES)
def test_kinematics_agree_with_results_json(name, documents):
    ex = read_exercise(name)
    _, doc = documents[name]
    assert len(doc["positions"]) == len(ex.angles)
    for k, p in enumerate(doc["positions"]):
        pos = solve(ex, k)
        q = {n: v["reference"] for n, v in p["quantities"].items()}
        speed = abs(ex.omega) * ex.lengths["O2A"]
        accel = math.hypot(ex.omega ** 2, ex.alpha) * ex.lengths["O2A"]
        size = max(math.dist(a, b) for a in pos.points.values() for b in pos.points.values())
        checked = 0
        for n, link in (("omega3", 3), ("omega4", 4)):
            if n in q:
                _close([pos.omega[link]], [q[n]["value"]], abs(ex.omega))
                checked += 1
        if "alpha4" in q:
            _close([pos.alpha[4]], [q["alpha4"]["value"]], ex.omega ** 2)
            checked += 1
        vectors = {"V_B": (pos.velocity["B"], speed), "A_B": (pos.acceleration["B"], accel),
                   "A_A4": (pos.acceleration.get("A4"), accel),
                   "V_A2/A4": (pos.relative.get("A"), speed),
                   "A_cor_A": (pos.coriolis.get("A"), accel),
                   "A_cor_B": (pos.coriolis.get("B"), accel)}
        for n, (mine, scale) in vectors.items():
            if n in q:
                _close(mine, q[n]["vector"], scale)
                checked += 1
        finite = {n for n, v in q.items() if n.startswith("I") and "point" in v}
        assert set(pos.centres) == finite
        for n in finite:
            _close(pos.centres[n], q[n]["point"], size)
        assert checked + len(finite) >= 4                  # the test compares something


@pytest.mark.parametrize("name", ["crank-shaper", "inverted-slider-crank"])
def test_reversed_coriolis_moves_its_tip_by_twice_the_component(name, documents):
    """The student's polygon, solved with the Coriolis term's sign flipped at A, puts a₄′
    twice results.json's Coriolis component away from its place and leaves a′ alone."""
    ex = read_exercise(name)
    _, doc = documents[name]
    k = len(ex.angles) - 1
    cor = doc["positions"][k]["quantities"]["A_cor_A"]["reference"]["vector"]
    true, wrong = solve(ex, k), solve(ex, k, coriolis=("A",))
    shift = [w - t for w, t in zip(wrong.acceleration["A4"], true.acceleration["A4"])]
    scale = ex.omega ** 2 * ex.lengths["O2A"]
    _close(shift, [2 * c for c in cor], scale)
    assert wrong.acceleration["A"] == true.acceleration["A"]
    assert math.hypot(*cor) > 0.1 * scale                 # a shift the drawing shows


@pytest.mark.parametrize("name", NAMES)
def test_tips_are_those_tarsim_draws(name, documents):
    """The kinematics name the tips tarsim's polygons draw (less the frame's pivots, drawn
    at the pole), so the key's item names are tarsim's."""
    ex = read_exercise(name)
    positions, _ = documents[name]
    frame = {p.lower() for p in ex.frame}
    for k, sol in enumerate(positions):
        pos = solve(ex, k)
        drawn = {t.lower() for t in drawn_velocity_polygon(sol.work).tips} - frame
        assert {t.lower() for t in pos.velocity} == drawn
        if ex.has_accelerations:
            drawn = {t.lower() for t in drawn_acceleration_polygon(sol.work).tips} - frame
            assert {t.lower() for t in pos.acceleration} == drawn


def test_key_items_are_the_tips_and_centres_tarsim_draws(documents):
    key = json.loads((CLASS / "key.json").read_text(encoding="utf-8"))
    assert len(key["files"]) == 5 * 60
    for name, entry in key["files"].items():
        assert (CLASS / name).is_file(), name
        positions, doc = documents[entry["exercise"]]
        k = entry.get("position_matched", entry["position"]) - 1
        work = positions[k].work
        frame = {p.lower() for p in read_exercise(entry["exercise"]).frame}
        tips = {t.lower() for t in drawn_velocity_polygon(work).tips} - frame
        want = {corpus.item_name(t, "v") for t in tips}
        if work.has("acceleration polygon"):
            tips = {t.lower() for t in drawn_acceleration_polygon(work).tips} - frame
            want |= {corpus.item_name(t, "a") for t in tips}
        centres = {n for n, v in doc["positions"][k]["quantities"].items()
                   if n.startswith("I") and "point" in v["reference"]}
        items = set(entry["items"])
        assert {i for i in items if not i.startswith("I")} == want, name
        assert {i for i in items if i.startswith("I")} in (set(), centres), name


def test_the_committed_class_is_the_generators():
    """The committed class is what ``python tests/grading_corpus.py --seed 1`` writes: the
    same drawings and key, byte for byte."""
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        corpus.make_class(1, Path(tmp))
        made = sorted(p.relative_to(tmp) for p in Path(tmp).rglob("*") if p.is_file())
        kept = sorted(p.relative_to(CLASS) for p in CLASS.rglob("*") if p.is_file())
        assert made == kept
        for rel in made:
            assert (Path(tmp) / rel).read_bytes() == (CLASS / rel).read_bytes(), rel


def test_the_generator_is_deterministic(tmp_path):
    one = corpus.make_class(7, tmp_path / "one", per_program=2)
    two = corpus.make_class(7, tmp_path / "two", per_program=2)
    assert one == two
    for f in one["files"]:
        assert (tmp_path / "one" / f).read_bytes() == (tmp_path / "two" / f).read_bytes()


@pytest.mark.parametrize("expected, got, verdict", [
    ((50.0, 0.0), (50.3, 0.0), "correct"),          # 0.3 mm: well within 0.5 + 50 tan 0.5°
    ((50.0, 0.0), (52.0, 0.0), "wrong magnitude"),  # 4 % long, true to the set square
    ((50.0, 0.0), (-50.0, 0.0), "wrong sense"),
    ((50.0, 0.0), (50 * math.cos(0.1), 50 * math.sin(0.1)), "wrong direction"),  # 5.7°
    ((0.0, 40.0), (40.0, 0.0), "wrong direction"),  # normal laid along the tangent
])
def test_rule(expected, got, verdict):
    assert corpus.rule(expected, got) == (verdict, True)


VERDICTS = {"correct", "follows from an earlier error", "wrong magnitude", "wrong direction",
            "wrong sense", "reversed Coriolis", "swapped", "missing", "wrong position"}


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 10 ** 6), program=st.sampled_from(corpus.PROGRAMS))
def test_every_drawing_keeps_the_contract(seed, program):
    """A drawing's verdicts are the key's nine; a drawing with no mistake is right in every
    item; one with a mistake has a wrong item, and a tip follows an earlier error only on
    a polygon with a wrong tip."""
    svg, key = corpus.make_drawing(random.Random(seed), program)
    assert svg.lstrip().startswith(("<?xml", "<svg"))
    assert set(key["items"].values()) <= VERDICTS
    wrong = {i for i, v in key["items"].items() if v != "correct"}
    if not key["mistakes"] or "position_matched" in key:
        assert not wrong
    else:
        assert wrong
    for kind in ("′", ""):
        follows = {i for i in wrong if key["items"][i].startswith("follows")
                   and i.endswith("′") == bool(kind)}
        roots = {i for i in wrong - follows if not i.startswith("I")
                 and i.endswith("′") == bool(kind)}
        assert not follows or roots


def test_score_counts_every_item_once(tmp_path):
    """The benchmark's score accounts for each item of the key once, as correct or wrong,
    and counts no more credited, named or not graded than there are."""
    from benchmarks.grading_corpus import score

    key = corpus.make_class(11, tmp_path, per_program=2)
    result = score(tmp_path)
    items = sum(len(e["items"]) for e in key["files"].values() if "position_matched" not in e)
    every = result["all"]
    assert every["files"] == len(key["files"])
    assert every["correct"] + every["wrong"] == items
    assert sum(v[0] for v in every["verdicts"].values()) == items
    assert every["verdicts"].get("correct", [0])[0] == every["correct"]
    assert every["credited"] <= every["correct"] and every["named"] <= every["wrong"]
    assert every["not_graded"] <= items


@pytest.mark.slow
def test_the_class_is_graded_as_its_key_says():
    """The committed class of 300 drawings, five programs' SVG, made from the loop equations:
    at least 98 % of the items drawn right are credited and 95 % of those drawn wrong get
    the key's verdict, in every program; no file is skipped, no penalty is invented, and
    each drawing of a position not asked is said to be of the one it is."""
    from benchmarks.grading_corpus import score

    counts = score()
    every = counts["all"]
    assert every["files"] == 300 and every["skipped"] == 0 and every["invented"] == 0
    assert every["credited"] >= 0.98 * every["correct"], every
    assert every["named"] >= 0.95 * every["wrong"], every
    assert every["position_named"] == every["other_position"] > 0
    for program, c in counts["programs"].items():
        assert c["credited"] >= 0.95 * c["correct"] and c["named"] >= 0.9 * c["wrong"], program
