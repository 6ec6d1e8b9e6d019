"""No bundled figure, of any chapter, has a label over another label or over an arrowhead,
nor a point's name nearer another named point than its own; none covers more lines with
its labels than tests/data/label_overlaps.json records (tests/label_overlaps.py counts all
this from the figure's primitives). A change that places labels faster or better must keep
every count at or below its record; lower it in the record when it falls."""

from __future__ import annotations

import json

import pytest

from tarsim.exercises.catalog import everything
from tests.label_overlaps import KINDS, RECORD, count, strays

RECORDED = json.loads(RECORD.read_text(encoding="utf-8"))


@pytest.mark.slow
@pytest.mark.parametrize("exercise_id", sorted(everything()))
def test_no_figure_covers_more_than_its_record(solved, exercise_id):
    for stem, fig in solved(exercise_id).figures.items():
        key = f"{exercise_id}/{stem}"
        assert key in RECORDED, f"{key} is not recorded: run python tests/label_overlaps.py"
        got = count(fig)
        assert got["label-label"] == 0 and got["label-arrowhead"] == 0, (key, got)
        for kind in KINDS:
            assert got[kind] <= RECORDED[key][kind], (key, kind, got, RECORDED[key])
        assert strays(fig) == [], key


def test_the_counter_sees_two_labels_over_one_another():
    from tarsim.graphics.figure import Figure, Path, Text

    fig = Figure(100.0, 100.0)
    fig.add(Text((50.0, 50.0), "I13"))
    fig.add(Text((51.0, 50.5), "I24"))                    # over the first
    fig.add(Text((80.0, 80.0), "A"))                      # clear
    fig.add(Path(((75.0, 80.0), (85.0, 80.0)), "link"))   # through "A"
    assert count(fig) == {"label-label": 1, "label-arrowhead": 0, "label-line": 1}


def test_the_counter_sees_a_name_nearer_another_point_or_vector():
    from tarsim.graphics.figure import Figure, Text

    fig = Figure(100.0, 100.0)
    fig.add(Text((50.0, 44.0), "A", owner=((50.0, 50.0),)))   # 6 mm above its own point
    fig.add(Text((50.0, 37.0), "B", owner=((50.0, 40.0),)))   # but 4 mm below B's
    v_a, v_b = ((0.0, 80.0), (30.0, 80.0)), ((0.0, 70.0), (30.0, 70.0))
    fig.add(Text((15.0, 71.5), "V", sub="A", owner=v_a))      # beside V_B's shaft, not V_A's
    fig.add(Text((15.0, 67.0), "V", sub="B", owner=v_b))
    assert [name for name, _, _ in strays(fig)] == ["A", "VA"]
