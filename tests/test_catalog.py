"""Tests for the bundled catalog: every exercise solves cleanly, and each matches its source.

Every bundled exercise is solved at each of its positions and every quantity it asks
for must agree with the independent analytic solver within its tolerance. Then
each exercise's published numbers are checked. Values inside tarsim are SI (m, m/s,
rad/s), so a number printed in mm is divided by 1000. A printed number is taken to
be exact to half a unit in its last printed digit, and that is its tolerance. The
constructions themselves agree with the analytic solver to ~1e-15 (tolerance 1e-9),
so the printed rounding is the only error that matters.
"""

import math
import re
import tomllib

import pytest

from tarsim.exercises.catalog import bundled

MM = 1e-3      # metres per millimetre


@pytest.fixture
def _solved(solved):
    """``_solved(id)``: the bundled exercise and its positions' solutions (solved once a run)."""
    def get(exercise_id):
        worked = solved(exercise_id)
        return worked.exercise, worked.positions
    return get


def _at(sols, slug=None):
    """The solution at the position with this slug (None: the file's only position)."""
    if slug is None:
        (sol,) = sols
        return sol
    return next(s for s in sols if s.position is not None and s.position.slug == slug)


def _numbers(d):
    """Every number in a results.json-shaped dict (``point``, ``vector``, ``value`` …)."""
    for key, v in d.items():
        if isinstance(v, bool) or isinstance(v, str):
            continue
        if isinstance(v, (int, float)):
            yield key, v
        elif isinstance(v, (list, tuple)):
            for x in v:
                yield key, x
        else:
            raise AssertionError(f"unexpected entry {key}: {v!r}")


# ----- every bundled exercise -----------------------------------------------------------------

@pytest.mark.parametrize("exercise_id", sorted(bundled()))
def test_every_bundled_exercise_solves_and_agrees_with_the_analytic_solver(exercise_id, _solved):
    ex, sols = _solved(exercise_id)
    if not ex.position_asks:
        pytest.skip("asks only for whole-mechanism quantities (dof, grashof, …)")
    assert sols
    for sol in sols:
        where = f"{exercise_id} at {sol.position.label if sol.position else 'its [input]'}"
        assert sol.quantities, where
        for name, q in sol.quantities.items():
            for method, qq in {q.method: q, **q.alternatives}.items():
                label = f"{where}: {name} by {method}"
                assert qq.rel_error <= qq.tolerance, label
                assert math.isfinite(qq.rel_error) and math.isfinite(qq.tolerance), label
                shapes = {"point", "value", "vector", "at_infinity", "undefined"}
                assert shapes & set(qq.value) and shapes & set(qq.reference), label
                for key, x in (*_numbers(qq.value), *_numbers(qq.reference)):
                    assert math.isfinite(x), f"{label}: {key} = {x}"
                if "undefined" in qq.reference:      # only a joint's own centre may say so
                    assert name.startswith("I") and "inspection" in qq.method, label
            assert q.passed, where


def test_the_new_exercises_are_bundled():
    ids = set(bundled())
    assert {"hinkle-four-bar", "hinkle-slider-crank", "six-link-homework-1",
            "six-link-homework-3", "velocity-homework-292", "inverted-slider-crank",
            "whitworth"} <= ids


# ----- peers.md §4: the four-bar benchmark ----------------------------------------------------

def test_four_bar_matches_the_peers_benchmark(_solved):
    # peers.md §4, open branch, θ2 = 60°, ω2 = 10 rad/s: printed to 12 decimals.
    _, sols = _solved("four-bar")
    q = _at(sols).quantities
    assert q["omega3"].value["value"] == pytest.approx(-2.578464796446, abs=5e-13)
    assert q["omega4"].value["value"] == pytest.approx(2.915957761501, abs=5e-13)
    # B = (273.679454, 198.260508) mm, printed to 6 decimals: I34 is the pin B.
    assert q["I34"].value["point"] == pytest.approx([273.679454 * MM, 198.260508 * MM],
                                                    abs=5e-7 * MM)


# ----- seed 003: the crank-shaper project at t = 2.34 s ----------------------------------------

def test_crank_shaper_matches_the_project_at_t_2_34_s(_solved):
    # seed 003 §7 (θ2 = −44.072°, ω2 = −1 rad/s): ω4 = +0.192118 rad/s (ccw), V_B = 189.192
    # mm/s to the left, α4 = +0.56939 rad/s² (ccw), A_B = 535.635 mm/s² to the left, Coriolis
    # 62.6646 mm/s² at A and 23.7113 mm/s² at B. Each is half a unit of its last digit.
    _, sols = _solved("crank-shaper")
    q = _at(sols, "t-2.34s").quantities
    assert q["omega4"].value["value"] == pytest.approx(0.192118, abs=5e-7)
    vx, vy = q["V_B"].value["vector"]
    assert vx == pytest.approx(-189.192 * MM, abs=5e-4 * MM) and vy == pytest.approx(0, abs=1e-12)
    assert q["alpha4"].value["value"] == pytest.approx(0.56939, abs=5e-6)
    ax, ay = q["A_B"].value["vector"]
    assert ax == pytest.approx(-535.635 * MM, abs=5e-4 * MM) and ay == pytest.approx(0, abs=1e-12)
    assert q["A_cor_A"].value["value"] == pytest.approx(62.6646 * MM, abs=5e-5 * MM)
    assert q["A_cor_B"].value["value"] == pytest.approx(23.7113 * MM, abs=5e-5 * MM)


# ----- seed 004 (Hinkle ch. 5): the digest's §11 checks ----------------------------------------

def test_hinkle_four_bar_matches_the_digest_check(_solved):
    # seed 004 §11: O2 = (0, 0), O4 = (100, 0), 40/120/80 mm, θ2 = 60°, ω2 = 10 rad/s ccw.
    ex, sols = _solved("hinkle-four-bar")
    q = _at(sols).quantities
    # Joints printed to 3 decimals (mm): 23 = (20, 34.641), 34 = (133.881, 72.471).
    assert q["I23"].value["point"] == pytest.approx([20 * MM, 34.641 * MM], abs=5e-4 * MM)
    assert q["I34"].value["point"] == pytest.approx([133.881 * MM, 72.471 * MM], abs=5e-4 * MM)
    # Centres, 3 decimals: 13 = (525.623, 910.406), 24 = (−84.280, 0).
    assert q["I13"].value["point"] == pytest.approx([525.623 * MM, 910.406 * MM], abs=5e-4 * MM)
    assert q["I24"].value["point"] == pytest.approx([-84.280 * MM, 0.0], abs=5e-4 * MM)
    # |ω3| = 0.39555, cw by Eq. 5.1 (I23 lies between I12 and I13); ω4 = 4.57349, ccw.
    assert q["omega3"].value["value"] == pytest.approx(-0.39555, abs=5e-6)
    assert q["omega4"].value["value"] == pytest.approx(4.57349, abs=5e-6)
    # V at the 3-4 pin (B) by rotated radius = 365.879 mm/s = 14-34·ω4, by every method.
    vb = q["V_B"]
    for qq in (vb, *vb.alternatives.values()):
        assert qq.value["value"] == pytest.approx(365.879 * MM, abs=5e-4 * MM), qq.method
    assert set(vb.alternatives) == {"parallel-line", "components"}
    # The plate's points D and E: asked by the three methods of §5-3 and §5-8.
    for p in ("V_D", "V_E"):
        assert {q[p].method, *q[p].alternatives} == {"radius-rotation", "parallel-line",
                                                      "components"}
    assert ex.mechanism.link(3).names == ("A", "B", "D", "E")


def test_hinkle_slider_crank_matches_the_digest_check(_solved):
    # seed 004 §11 (Fig. 5.7 procedure): crank 40, rod 120 mm, in line, θ2 = 60°, ω2 = 10.
    ex, sols = _solved("hinkle-slider-crank")
    sol = _at(sols)
    q = sol.quantities
    # Piston speed |V_C| = 406.712 mm/s (3 decimals), by every method; it moves along the guide.
    vc = q["V_C"]
    for qq in (vc, *vc.alternatives.values()):
        assert qq.value["value"] == pytest.approx(406.712 * MM, abs=5e-4 * MM), qq.method
        assert qq.value["vector"][1] == pytest.approx(0.0, abs=1e-12)
    # ω3 = 1.74078 rad/s (5 decimals) in magnitude.
    assert abs(q["omega3"].value["value"]) == pytest.approx(1.74078, abs=5e-6)
    # The components of Fig. 5.7: V_C′ (along BC) = V_B′ = 389.398 mm/s, V_C″ (⟂ BC)
    # = 117.408 mm/s, and P, where the rod has no velocity ⟂ BC, at PB = 52.554 mm.
    xy = {n: sol.assembly.output(sol.assembly.points[n]).xy for n in "BC"}
    bc = math.dist(xy["B"], xy["C"])
    ux, uy = ((xy["C"][0] - xy["B"][0]) / bc, (xy["C"][1] - xy["B"][1]) / bc)
    vx, vy = vc.value["vector"]
    along, across = abs(vx * ux + vy * uy), abs(-vx * uy + vy * ux)
    assert along == pytest.approx(389.398 * MM, abs=5e-4 * MM)
    assert across == pytest.approx(117.408 * MM, abs=5e-4 * MM)
    pb = bc - across / abs(q["omega3"].value["value"])       # PC = V_C″ / ω3
    assert pb == pytest.approx(52.554 * MM, abs=5e-4 * MM)
    assert bc == pytest.approx(120 * MM, rel=1e-12)
    assert ex.mechanism.link(3).names == ("B", "C", "D")


# ----- seed 000-part1 §3.8: the six-link homeworks -------------------------------------------

def _kennedy_distance(q, i, j, k):
    """How far I_ij lies off the line through I_ik and I_jk (m)."""
    def pt(a, b):
        a, b = sorted((a, b))
        return q[f"I{a}{b}"].value["point"]
    (x, y), (ax, ay), (bx, by) = pt(i, j), pt(i, k), pt(j, k)
    dx, dy = bx - ax, by - ay
    return abs(dx * (y - ay) - dy * (x - ax)) / math.hypot(dx, dy)


HOMEWORK = {
    # The notes' table of triangle pairs: for each secondary centre, the third link of each
    # triangle, in the notes' order of discovery (000-part1 §3.8).
    "six-link-homework-1": {
        "primaries": {"I12", "I14", "I16", "I23", "I34", "I35", "I45", "I56"},
        "notes": {"I13": (2, 4), "I15": (6, 4), "I24": (3, 1), "I25": (3, 1), "I26": (1, 5),
                  "I36": (1, 2), "I46": (5, 1)},
        # tarsim's choice, the first two well-crossing lines from the lowest third link.
        # It differs from the notes at I15 (Δ135 for Δ145: the same line, since I13 lies on
        # the rocker line I14-I34 and I35 = I45) and at I46 (Δ426 for Δ456).
        "tarsim": {"I13": (2, 4), "I15": (3, 6), "I24": (1, 3), "I25": (1, 3), "I26": (1, 5),
                   "I36": (1, 2), "I46": (1, 2)},
        "order": ["I13", "I15", "I24", "I25", "I26", "I36", "I46"],   # the notes' order too
    },
    "six-link-homework-3": {
        "primaries": {"I12", "I13", "I16", "I24", "I25", "I34", "I56"},
        "notes": {"I15": (2, 6), "I26": (1, 5), "I14": (2, 3), "I45": (1, 2), "I46": (1, 5),
                  "I35": (4, 1), "I36": (5, 1), "I23": (1, 4)},
        # It differs from the notes at I35 (Δ325 for Δ345), I36 (Δ326 for Δ356) and I46
        # (Δ426 for Δ456): tarsim scans from the lowest pair and the lowest third link, so it
        # meets these centres before I45 (and takes link 2's centres first).
        "tarsim": {"I14": (2, 3), "I15": (2, 6), "I23": (1, 4), "I26": (1, 5), "I35": (1, 2),
                   "I36": (1, 2), "I45": (1, 2), "I46": (1, 2)},
        # The notes' order is I15, I26, I14, I45, I46, I35, I36, I23.
        "order": ["I14", "I15", "I23", "I26", "I35", "I36", "I45", "I46"],
    },
}


@pytest.mark.parametrize("exercise_id", sorted(HOMEWORK))
def test_six_link_homework_finds_the_notes_secondary_centres(exercise_id, _solved):
    table = HOMEWORK[exercise_id]
    ex, sols = _solved(exercise_id)
    sol = _at(sols)
    q = sol.quantities
    centres = [a for a in ex.asks if a.name.startswith("I")]
    assert len(ex.mechanism.links) == 6 and len(centres) == 15
    cs = sol.work.made("centres")
    assert {c.label for c in cs.primaries} == table["primaries"]
    assert {c.label for c in cs.secondaries} == set(table["notes"])
    # Each secondary is found by Kennedy (two lines cut) and agrees with the analytic centre.
    for c in cs.secondaries:
        assert c.rule == "kennedy", c.label
        assert q[c.label].method == "Kennedy (circle diagram)"
        assert q[c.label].passed, c.label
    # Each lies on both lines of the notes' triangles (Kennedy's theorem, as the notes use it).
    size = max(math.hypot(*q[p].value["point"]) for p in table["primaries"])
    for label, thirds in table["notes"].items():
        i, j = int(label[1]), int(label[2])
        for k in thirds:
            assert _kennedy_distance(q, i, j, k) <= 1e-12 * size, (label, k)
    # tarsim's own triangle pairs and order of discovery, as recorded in the circle diagram.
    assert {c.label: c.triangles for c in cs.secondaries} == table["tarsim"]
    assert [c.label for c in cs.secondaries] == table["order"]


def test_homework_1_has_the_multiple_pin(_solved):
    # 000-part1 §3.8 Homework 1: links 3, 4 and 5 share one pin P (two joints), so DOF = 1.
    ex, sols = _solved("six-link-homework-1")
    m = ex.mechanism
    assert sorted(m.links_at("P")) == [3, 4, 5]
    assert m.mobility() == (1, 6, 7, 0)
    q = _at(sols).quantities
    assert q["I34"].value == q["I35"].value == q["I45"].value


def test_homework_3_is_a_watt_six_bar(_solved):
    # 000-part1 §3.8 Homework (3): ground pivots for 2, 3 and 6; link 2 ternary (1, 4, 5).
    ex, _ = _solved("six-link-homework-3")
    m = ex.mechanism
    assert {n for p in m.link(1).names for n in m.links_at(p)} == {1, 2, 3, 6}
    assert {n for p in m.link(2).names for n in m.links_at(p)} == {1, 2, 4, 5}
    assert m.mobility() == (1, 6, 7, 0)


# ----- seed 000-part2 §3.9: the homework on p. 292 -------------------------------------------

def test_velocity_homework_292_uses_the_notes_data(_solved):
    # 000-part2 §3.9: V_A = 635 mm/s ccw, O2A = 76.2, AB = 178, CD = 305, CB = 152 mm (the
    # notes print whole mm, so ±0.5 mm/s and exact lengths). No answer is printed for V_D.
    ex, sols = _solved("velocity-homework-292")
    m = ex.mechanism
    assert m.drive.omega > 0
    assert m.input_speed == pytest.approx(635 * MM, abs=0.5 * MM)
    spans = {"O2A": (2, "O2", "A", 76.2), "AB": (3, "A", "B", 178), "CD": (5, "C", "D", 305),
             "CB": (4, "C", "B", 152)}
    for name, (link, a, b, length) in spans.items():
        assert m.link(link).span(a, b) == pytest.approx(length * MM, rel=1e-12), name
    q = _at(sols).quantities
    # V_D is reached through the transfer point I25 and the rod's centre I15, both by Kennedy.
    assert q["I15"].method == q["I25"].method == "Kennedy (circle diagram)"
    vd = q["V_D"]
    assert {vd.method, *vd.alternatives} == {"radius-rotation", "parallel-line"}
    assert vd.value["vector"][1] == pytest.approx(0.0, abs=1e-12)    # along the guide


# ----- seed 000-part2 §2.11: the Coriolis exercises -------------------------------------------

@pytest.mark.parametrize("exercise_id, lever", [("inverted-slider-crank", 4), ("whitworth", 4)])
def test_coriolis_follows_the_notes_rule(exercise_id, lever, _solved):
    # 000-part2 §2.11: the Coriolis component is 2ω·v_rel, its direction v_rel turned 90°
    # the way the slotted link turns. Checked on the solution's own numbers (rounding only).
    _, sols = _solved(exercise_id)
    q = _at(sols).quantities
    w = q[f"omega{lever}"].value["value"]
    vx, vy = q["V_A2/A4"].value["vector"]
    cx, cy = q["A_cor_A"].value["vector"]
    turned = (-vy, vx) if w > 0 else (vy, -vx)
    scale = 2 * abs(w) * math.hypot(vx, vy)
    assert scale > 0
    assert q["A_cor_A"].value["value"] == pytest.approx(scale, rel=1e-12)
    assert (cx, cy) == pytest.approx((2 * abs(w) * turned[0], 2 * abs(w) * turned[1]),
                                     abs=1e-12 * scale)
    assert "alpha4" in q and "A_A4" in q


def test_every_source_speaks_to_a_student():
    # A source names the course's text, chapter or section and example, never a digest's
    # file, line numbers or a seed number that only the developers know.
    for name, path in bundled().items():
        source = tomllib.loads(path.read_text(encoding="utf-8"))["source"]
        assert re.match(r"(course project|a four-bar|a slider-crank|exam-prep text, ch\. \d|"
                        r"textbook ch\. \d|lecture notes, part \d)", source), (name, source)
        assert not re.search(r"\bseed\b|\bl\.\d|digest|\.md\b|\b00\d\b", source), (name, source)
