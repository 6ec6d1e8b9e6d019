"""Where a mechanism stands in its file's axes changes none of its answers beyond rounding.

A line's equation, an intersection's rounding and every conditioning are measured from
the origin, so the solver works about the frame's first point
(``Mechanism.about_its_frame``) and says points back in the file's axes. The property:
the same file with every coordinate moved by an offset up to ten thousand times the
mechanism's size gives the same answers, each within the rounding its own check allows
plus the rounding of the moved file's numbers (``|offset| · eps`` over the size, through
the construction's conditioning), and its centres and points moved by the offset.
"""

from __future__ import annotations

import math
import random
import tomllib
from dataclasses import replace
from pathlib import Path

import pytest
from hypothesis import HealthCheck, Phase, assume, given, note, settings
from hypothesis import strategies as st

import tarsim
from tarsim.constructions.asks import parse_ask
from tarsim.constructions.checks import CEILING, EPS, Answer, _vouched
from tarsim.constructions.errors import IllConditioned, TarsimError
from tarsim.constructions.model import Link
from tarsim.constructions.reference.centres import mechanism_size
from tarsim.exercises import catalog

from tests.random_mechanisms import FAMILIES, generate, to_toml

HERE = Path(__file__).parent / "reproducers"


def with_points(text: str, place) -> str:
    """The mechanism file ``text`` with every coordinate it states, ``[x, y]``, made
    ``place([x, y])``: the frame's points, the frame guides' ``through`` points and the
    points an assembly is to be near."""
    data = tomllib.loads(text)
    data["frame"] = {k: place(v) for k, v in data["frame"].items()}
    for s in data.get("slider", []):
        if s.get("on", 1) == 1 and isinstance(s.get("through"), list):
            s["through"] = place(s["through"])
    data["assembly"] = {k: v if isinstance(v, str) else place(v)
                        for k, v in data.get("assembly", {}).items()}
    for many, one in (("links", "link"), ("sliders", "slider"), ("contacts", "contact")):
        data[many] = data.pop(one, [])
    return to_toml(data)


def moved_file(text: str, dx: float, dy: float) -> str:
    """The mechanism file ``text`` moved by ``(dx, dy)`` in its own units."""
    return with_points(text, lambda xy: [xy[0] + dx, xy[1] + dy])


def solved(text: str, folder: Path, name: str):
    path = folder / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    return tarsim.solve(tarsim.load(str(path)))


def answers(solution) -> dict[tuple[int, str, str], tuple]:
    """Every quantity of every position by (position, name, method): the quantity, its scale
    and the position's size."""
    out = {}
    for k, sol in enumerate(solution.positions):
        scales = {a.ask.name: sol.work.scale_of(a.ask) for a in sol.answers}
        size = mechanism_size(sol.work.kinematics)
        for name, q in sol.quantities.items():
            for qq in (q, *q.alternatives.values()):
                out[k, name, qq.method] = (qq.in_file_axes(sol.exercise.mechanism),
                                           scales[name], size)
    return out


def assert_same_answers(near, far) -> None:
    """``far`` answers as ``near`` does, to rounding; each is the other's file moved."""
    (nx, ny), (fx, fy) = near.exercise.mechanism.origin, far.exercise.mechanism.origin
    offset = math.hypot(fx - nx, fy - ny)          # metres: how far the files lie apart
    a, b = answers(near), answers(far)
    assert a.keys() == b.keys()
    for key, (qa, scale, size) in a.items():
        qb = b[key][0]
        # The moved file's coordinates carry |offset|·eps of rounding: beside the size,
        # through the construction's conditioning, on top of what each check allows.
        moved = 64 * EPS * offset / size / max(min(qa.conditioning, qb.conditioning), 1e-300)
        allowed = qa.tolerance + qb.tolerance + moved
        va, vb = qa.value, qb.value
        if "point" in va and not isinstance(va["point"], str):
            # A far centre is judged beside its own distance from the frame, as checked.
            shifted = [vb["point"][0] - fx + nx, vb["point"][1] - fy + ny]
            far_out = math.hypot(va["point"][0] - nx, va["point"][1] - ny)
            miss = math.dist(va["point"], shifted) / max(size, far_out)
        elif va.get("at_infinity") or vb.get("at_infinity"):
            assert va.get("at_infinity") == vb.get("at_infinity"), key
            miss = math.dist(va["direction"], vb["direction"])
        elif "vector" in va:
            miss = math.dist(va["vector"], vb["vector"]) / max(va["value"], scale, 1e-300)
        elif isinstance(va.get("value"), float):
            miss = abs(va["value"] - vb["value"]) / max(abs(va["value"]), scale, 1e-300)
        else:
            assert va == vb, key
            continue
        assert miss <= allowed, (key, va, vb, miss, allowed)


def test_wrong_deltoid_far_VB_passes(tmp_path):
    # A deltoid on its folded branch, 1 km from the origin: B has come round onto O2, where
    # it stands still, so V_B = 0 (to the rounding of the input speed, ω2·O2A = 3750 mm/s).
    # Drawn about the origin, the parallel lines once gave 19.4695 mm/s "check ok".
    text = (HERE / "wrong-deltoid-far-VB-passes.toml").read_text(encoding="utf-8")
    far = solved(text, tmp_path, "far")
    q = far.results["positions"][0]["quantities"]["V_B"]
    for got in (q, *q["by_method"].values()):
        assert got["passed"] and got["tolerance"] <= CEILING
        # Below what its check can tell from nothing, it is said as nothing, pointing nowhere.
        assert got["value"] == 0.0 and got["vector"] == [0.0, 0.0], got["method"]
    assert "| V_B | 0 mm/s | 0 mm/s |" in far.steps()
    near = solved(moved_file(text, -1000000.0, -5.0), tmp_path, "near")
    assert near.exercise.mechanism.origin == (0.0, 0.0)
    assert far.exercise.mechanism.origin == (1000.0, 0.005)        # metres
    assert_same_answers(near, far)


def test_a_centre_is_said_in_the_files_axes(tmp_path):
    # The four-bar's pivots are its centres I12 and I14, wherever the file puts them.
    text = (Path(catalog.__file__).parent / "four-bar.toml").read_text(
        encoding="utf-8").replace('find = ["', 'find = ["I12", "I14", "', 1)
    far = solved(moved_file(text, 5e5, -2.5e5), tmp_path, "far").results
    frame = tomllib.loads(moved_file(text, 5e5, -2.5e5))["frame"]
    got = far["positions"][0]["quantities"]
    assert got["I12"]["point"] == pytest.approx([c / 1000 for c in frame["O2"]], abs=1e-12)
    assert got["I14"]["point"] == pytest.approx([c / 1000 for c in frame["O4"]], abs=1e-12)


def on_grid(text: str, step: float) -> str:
    """The file ``text`` with every coordinate it states rounded to a multiple of ``step``."""
    return with_points(text, lambda xy: [round(xy[0] / step) * step,
                                         round(xy[1] / step) * step])


def random_file(family: str, seed: int) -> tuple[str, float]:
    """A random mechanism file of ``family`` and the distance between its frame points (or its
    longest length); a file broken on purpose is not drawn."""
    _, text = generate(random.Random(seed), family)
    try:
        data = tomllib.loads(text)
        xy = [v for v in data["frame"].values()]
        size = max(math.dist(p, q) for p in xy for q in xy) or max(
            abs(v) for k in data.get("link", []) for v in k.get("lengths", {}).values())
    except (tomllib.TOMLDecodeError, KeyError, TypeError, ValueError):
        assume(False)
    assume(math.isfinite(size) and size > 0)
    return text, size


SETTINGS = settings(max_examples=6, deadline=None, derandomize=True,
                    phases=[Phase.explicit, Phase.generate],
                    suppress_health_check=[HealthCheck.too_slow])


@pytest.mark.slow
@pytest.mark.parametrize("family", FAMILIES)
@SETTINGS
@given(seed=st.integers(0, 2**32 - 1), turn=st.floats(0.0, 2 * math.pi),
       decades=st.floats(0.0, 4.0))
def test_a_mechanism_moved_exactly_gives_the_same_answers_to_the_bit(family, seed, turn, decades,
                                                                     tmp_path_factory):
    # Its coordinates and the move on a grid the sum keeps exact (eight units in the last
    # place of twice the offset), the moved file's model is the first's to the bit: every
    # answer, refusal and conditioning is the same, and each point is moved by the offset,
    # to its rounding.
    text, size = random_file(family, seed)
    offset = size * 10 ** decades
    step = 8 * math.ulp(2 * offset)
    dx, dy = (round(offset * f(turn) / step) * step for f in (math.cos, math.sin))
    text = on_grid(text, step)
    note(text)
    folder = tmp_path_factory.mktemp("moved")
    try:
        near = solved(text, folder, "near")
    except TarsimError as e:
        with pytest.raises(TarsimError) as far:
            solved(moved_file(text, dx, dy), folder, "far")
        assert type(far.value) is type(e)
        return
    far = solved(moved_file(text, dx, dy), folder, "far")
    a, b = answers(near), answers(far)
    assert a.keys() == b.keys()
    for key, (qa, *_) in a.items():
        qb = b[key][0]
        assert (qa.rel_error, qa.tolerance, qa.conditioning) == (
            qb.rel_error, qb.tolerance, qb.conditioning), key
    assert_same_answers(near, far)


@pytest.mark.slow
@pytest.mark.parametrize("family", FAMILIES)
@SETTINGS
@given(seed=st.integers(0, 2**32 - 1), turn=st.floats(0.0, 2 * math.pi),
       decades=st.floats(0.0, 4.0))
def test_a_mechanism_moved_far_from_the_origin_gives_the_same_answers(family, seed, turn,
                                                                      decades, tmp_path_factory):
    # Moved anywhere, its coordinates round: where both files solve, they agree to the
    # rounding each check allows and that the move added. (At a singular position the
    # rounding may tip the moved one into a refusal: see the test above for exact moves.)
    text, size = random_file(family, seed)
    offset = size * 10 ** decades
    dx, dy = offset * math.cos(turn), offset * math.sin(turn)
    note(text)
    folder = tmp_path_factory.mktemp("moved")
    try:
        near = solved(text, folder, "near")
        far = solved(moved_file(text, dx, dy), folder, "far")
    except TarsimError:
        assume(False)
    assert_same_answers(near, far)


# ----- a check that cannot fail is no check ---------------------------------------------------
def far_deltoid():
    """The reproducer's deltoid as the model it once was: its file's coordinates taken as
    they stand, 1 km out, where the reader now works about the frame's first point."""
    ex = tarsim.load(str(HERE / "wrong-deltoid-far-VB-passes.toml"))
    data = tomllib.loads((HERE / "wrong-deltoid-far-VB-passes.toml").read_text("utf-8"))
    mm = 1e-3
    frame = Link(1, tuple((k, (x * mm, y * mm)) for k, (x, y) in data["frame"].items()), "frame")
    far = replace(ex.mechanism, links=(frame, *ex.mechanism.links[1:]), origin=(0.0, 0.0),
                  branches={"B": tuple(c * mm for c in data["assembly"]["B"])})
    return replace(ex, mechanism=far)


def test_a_construction_too_ill_conditioned_to_vouch_for_is_left_out():
    # 1 km out, the parallel lines' direction is taken through two points 1e-20 of their
    # distance from the origin apart (they once read V_B = 19.4695 mm/s "check ok"): the
    # method is left out, said under the figures, and radius rotation, conditioned well
    # enough, answers V_B = 0 (B stands on O2).
    sol = tarsim.solve(far_deltoid()).positions[0]
    q = sol.quantities["V_B"]
    assert [q.method, *q.alternatives] == ["radius-rotation", "components"]
    speed = 39.94336978890228 * 0.0938830469323322      # ω2 · O2A, m/s
    for got in (q, *q.alternatives.values()):
        assert got.passed and got.tolerance <= CEILING
        assert got.value["value"] <= 1e-9 * speed
    assert ("V_B by parallel lines is left out: it draws a line through two points all but "
            "together, so it cannot be vouched for here; radius rotation gives it.") in sol.notes
    assert not any(f.stem == "V_B-parallel-line" for a in sol.answers for f in a.figures)


def test_a_construction_no_method_can_vouch_for_is_refused_offering_another():
    ex = replace(far_deltoid(), methods=("parallel-line",))
    with pytest.raises(IllConditioned) as caught:
        tarsim.solve(ex)
    line = str(caught.value)
    assert line.startswith("V_B by parallel lines cannot be vouched for at θ2 = 337.725°: it "
                           "draws a line through two points all but together (conditioning ")
    assert line.endswith('of its scale; add "radius-rotation" to [ask] methods')
    assert "\n" not in line and len(line) < 250


def test_vectors_drawn_within_the_rounding_of_their_place_are_refused():
    # At t = 1e-25 s with α = −1e25 the crank's ω = 1 − αt cancels to 2e-16 rad/s: its
    # vectors are drawn some 1e-14 of the 3 km mechanism long, below the rounding of the
    # points they stand on, so V_B by components (once "check FAILED" by 2.2e-3) cannot be
    # vouched for, and says why: the shortness of its vectors, not its crossings.
    path = Path(__file__).parent / "data" / "edge" / "input-at-rest-by-cancellation.toml"
    with pytest.raises(IllConditioned) as caught:
        tarsim.solve(tarsim.load(path))
    line = str(caught.value)
    assert line.startswith("V_B by components cannot be vouched for at θ2 = 90°: its vectors "
                           "are drawn ")
    share = float(line.split("are drawn ")[1].split(" ")[0])
    assert 1e-15 < share < 1e-12
    assert line.endswith('add "radius-rotation" to [ask] methods')


@pytest.mark.parametrize("own, rounding, err, verdict", [
    (1e-9, 0.0, 5e-10, 1e-9),             # a well-conditioned construction: its own tolerance
    (1e-3, 0.0, 5e-10, CEILING),          # ill-conditioned but agreeing: held to the ceiling
    (1e-3, 0.0, 5e-4, "construction"),    # ill-conditioned and off: no check could fail
    (1e-3, 0.0, 5e-2, CEILING),           # off by more than even it allows: a failed check
    (1e-9, 1e-4, 5e-5, 1e-9 + 1e-4),      # the reference's own rounding widens the check
    (1e-9, 2.0, 5e-5, "reference"),       # a reference lost to rounding checks nothing
])
def test_a_checks_tolerance_never_exceeds_what_can_fail(own, rounding, err, verdict):
    answer = Answer(parse_ask("V_B"), {"value": 1.0, "vector": [1.0, 0.0]}, 1e-12, "components")
    if isinstance(verdict, float):
        assert _vouched(answer, err, own, rounding) == pytest.approx(verdict, rel=1e-12)
        return
    with pytest.raises(IllConditioned) as caught:
        _vouched(answer, err, own, rounding)
    assert caught.value.by_reference == (verdict == "reference")
