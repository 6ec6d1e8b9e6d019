"""A gear train solved, or refused in one line where its answer would divide by zero or
leave what a float holds: exit 1 and nothing written."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from tarsim.constructions.reference.willis import willis_speeds
from tarsim.exercises.catalog import bundled
from tarsim.exercises.cli import cli
from tarsim.exercises.gears.train_file import parse_train


def test_a_ratio_over_a_member_that_stands_still_is_refused(tmp_path):
    """A reverted planet of 60 and 60 teeth between suns of 40 and 40, the sun 2 fixed:
    (ω5 − ω6)/(0 − ω6) = (40/60)(60/40) = 1, so the sun 5 stands still whatever the arm
    does, and ω6/ω5 divides by 0: one line, exit 1, nothing written."""
    text = Path(bundled("gears")["planetary-q3"]).read_text(encoding="utf-8")
    for old, new in (("number = 4\nname = \"planet\"\nteeth = 40", "number = 4\nname = "
                      "\"planet\"\nteeth = 60"), ("number = 5\nname = \"output sun\"\nteeth = 60",
                                                 "number = 5\nname = \"output sun\"\nteeth = 40")):
        assert old in text
        text = text.replace(old, new, 1)
    text = text.replace('find = ["omega5/omega6"', 'find = ["omega6/omega5"', 1)
    path = tmp_path / "still.toml"
    path.write_text(text, encoding="utf-8")
    assert willis_speeds(parse_train(text, str(path)).train)[5] == 0
    result = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "out"),
                                      "--no-pdf"])
    assert result.exit_code == 1
    assert result.output == (f"Error: {path}: omega6/omega5 divides by the speed of gear 5 "
                             "(output sun), which stands still in this train; ask a ratio "
                             "over a turning member\n")
    assert not (tmp_path / "out").exists()


def test_a_train_whose_ratios_pass_what_a_float_holds_is_refused(tmp_path):
    """22 stages of 100000 teeth driving 1: the last gear turns 1e5²² = 1e110 times the
    first, past 1e100 (a float holds 1e308, but a ratio or a figure's scale of such speeds
    would not): one line naming the gear."""
    n = 22
    text = "\n".join(
        [f"[[gear]]\nnumber = {2 + 2 * k}\nteeth = 100000\n\n[[gear]]\nnumber = {3 + 2 * k}\n"
         f"teeth = 1\n\n[[mesh]]\ngears = [{2 + 2 * k}, {3 + 2 * k}]\n" for k in range(n)]
        + [f"[[shaft]]\nmembers = [{3 + 2 * k}, {4 + 2 * k}]\n" for k in range(n - 1)]
        + ["[input]\nmember = 2\nspeed = 1\n"])
    path = tmp_path / "steep.toml"
    path.write_text(text, encoding="utf-8")
    result = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "out"),
                                      "--no-pdf"])
    assert result.exit_code == 1
    # gear 3 turns 1e5 and each stage 1e5 more: gear 43 (the 21st driven) is the first past
    assert result.output == (f"Error: {path}: gear 43 would turn about 1e+105 rpm: the tooth "
                             "ratios carry its speed beyond 1e±100; no train turns so, check "
                             "the teeth\n")
    assert not (tmp_path / "out").exists()
