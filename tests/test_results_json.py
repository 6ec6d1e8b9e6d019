"""results.json, the stable contract (DESIGN.md): its shape, its units, and its honesty.

Every bundled exercise's document is read back and held to the contract:

    {"exercise": id,
     "positions": [{"input": {...}, "quantities": {...}, "notes": [...]}],
     "quantities": {...}}

Each quantity carries its value in SI units in the shape its name says, the analytic
``reference`` in the same shape, ``rel_error``, ``tolerance``, ``conditioning``,
``passed`` and ``method``; a velocity found by several methods lists the others
under ``by_method``. No number is NaN or infinite.
"""

from __future__ import annotations

import json
import math

import pytest

from tarsim.constructions.asks import parse_ask
from tarsim.exercises.catalog import bundled
from tarsim.exercises.linkages.results_json import results_json

IDS = sorted(bundled())
CHECK_KEYS = {"reference", "rel_error", "tolerance", "conditioning", "passed", "method"}


def _document(solved, exercise_id):
    worked = solved(exercise_id)
    text = results_json(worked.positions, worked.exercise, worked.overall.quantities)
    assert "NaN" not in text and "Infinity" not in text
    return json.loads(text)


def _quantities(doc):
    yield from doc["quantities"].items()
    for p in doc["positions"]:
        yield from p["quantities"].items()


def _shape(name: str, v: dict) -> None:
    """The value's keys are those its name calls for."""
    kind = type(parse_ask(name)).__name__
    if kind == "Centre":
        assert ("point" in v) != bool(v.get("at_infinity")) or "undefined" in v, (name, v)
        if v.get("at_infinity"):
            assert math.hypot(*v["direction"]) == pytest.approx(1.0, abs=1e-12)
        elif "point" in v:
            assert len(v["point"]) == 2
    elif kind in ("Velocity", "Acceleration", "Relative", "Coriolis"):
        assert len(v["vector"]) == 2
        assert v["value"] == pytest.approx(math.hypot(*v["vector"]), rel=1e-12, abs=1e-300)
    elif kind in ("AngularVelocity", "AngularAcceleration", "Mobility", "TimeRatio", "Stroke"):
        assert isinstance(v["value"], (int, float)) and not isinstance(v["value"], bool)
    elif kind == "GrashofClass":
        assert {"class", "s_plus_l", "p_plus_q"} <= set(v)
    elif kind == "LengthRange":
        assert {"low", "high", "class"} <= set(v)


@pytest.mark.parametrize("exercise_id", IDS)
def test_the_document_has_the_contract_shape(solved, exercise_id):
    doc = _document(solved, exercise_id)
    assert set(doc) == {"exercise", "positions", "quantities"}
    assert doc["exercise"] == exercise_id
    for p in doc["positions"]:
        assert {"input", "quantities", "notes"} <= set(p) <= {"input", "position", "quantities",
                                                             "notes"}
        assert set(p["input"]) == {"link", "angle_deg", "omega", "alpha", "alpha_given"}
    for name in doc["quantities"]:
        assert parse_ask(name).scope == "mechanism", name
    assert doc["positions"] or doc["quantities"]


@pytest.mark.parametrize("exercise_id", IDS)
def test_every_quantity_stands_beside_its_reference(solved, exercise_id):
    for name, q in _quantities(_document(solved, exercise_id)):
        for entry in (q, *q.get("by_method", {}).values()):
            assert CHECK_KEYS <= set(entry), name
            _shape(name, entry)
            if "undefined" not in entry["reference"]:      # a joint's centre at no motion
                _shape(name, entry["reference"])
            assert entry["passed"] == (entry["rel_error"] <= (entry["tolerance"] or math.inf))
            assert 0.0 <= entry["conditioning"] <= 1.0
            assert isinstance(entry["method"], str) and entry["method"]


def test_lengths_are_in_metres_whatever_the_file_says(solved):
    # The four-bar's file is in mm: O4 at 300 mm is I14 at 0.3 m.
    doc = _document(solved, "four-bar")
    assert doc["positions"][0]["quantities"]["I14"]["point"] == pytest.approx([0.3, 0.0])
    # The offset slider-crank's is in cm: its stroke 63.34 cm is 0.6334 m.
    stroke = _document(solved, "offset-slider-crank")["quantities"]["stroke"]["value"]
    assert stroke == pytest.approx(0.633386, abs=1e-6)


def test_several_methods_stand_under_by_method(solved):
    v_b = _document(solved, "four-bar")["positions"][0]["quantities"]["V_B"]
    assert v_b["method"] == "radius-rotation"
    assert set(v_b["by_method"]) == {"parallel-line", "components"}
    for other in v_b["by_method"].values():
        assert other["vector"] == pytest.approx(v_b["vector"], rel=1e-12)


def test_several_positions_each_say_where_they_are(solved):
    doc = _document(solved, "crank-shaper")
    assert [p["position"] for p in doc["positions"]] == ["θ2 = 90°", "t = 2.34 s (θ2 = −44.0721°)"]
    assert doc["positions"][1]["input"]["angle_deg"] == pytest.approx(-44.0721, abs=1e-4)
