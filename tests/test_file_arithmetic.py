"""Numbers written as a book derives them from its data ("120/2", "2/3", "45 + 70"): taken
exactly at their value, in every kind of file, and nothing else in a string is run."""

import json
from fractions import Fraction

from click.testing import CliRunner
from hypothesis import given
from hypothesis import strategies as st

from tarsim.exercises.cli import cli
from tarsim.exercises.file_numbers import arithmetic
from tarsim.exercises.templates import template


@given(st.integers(-10**6, 10**6), st.integers(1, 10**6), st.integers(-999, 999))
def test_quotients_and_sums_are_exact(a, b, c):
    assert arithmetic(f"{a}/{b}") == Fraction(a, b)
    assert arithmetic(f"({a} + {c}) * {b}") == (a + c) * b
    assert arithmetic(f"{a} - -{c}") == a + c


def test_decimals_are_taken_at_their_digits():
    assert arithmetic("0.1 + 0.2") == Fraction(3, 10)          # not 0.30000000000000004


def test_names_calls_powers_and_nonsense_are_not_numbers():
    for text in ["A + 45", "pi/2", "__import__('os')", "2**10", "1/0", "3 +", "", "  ",
                 "True", "1e400", "[1]", "9" * 81]:
        assert arithmetic(text) is None, text


def _solved(tmp_path, kind, old, new):
    """results.json's quantities of ``kind``'s starting file with ``old`` written ``new``."""
    text = template(kind)
    assert old in text
    path = tmp_path / f"{kind}.toml"
    path.write_text(text.replace(old, new, 1), encoding="utf-8")
    out = tmp_path / "out"
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(out), "--no-pdf"])
    assert run.exit_code == 0, run.output
    found = json.loads((out / "results.json").read_text(encoding="utf-8"))
    q = found["quantities"] or found["positions"][0]["quantities"]
    return {k: v["value"] for k, v in q.items() if "value" in v}


def test_a_crank_written_as_half_the_stroke_is_that_crank(tmp_path):
    plain = _solved(tmp_path, "linkage", "O2A = 100", "O2A = 100")
    halved = _solved(tmp_path, "linkage", "O2A = 100", 'O2A = "200/2"')
    assert halved == plain          # the same number in, bit for bit the same answers out


def test_an_angle_written_from_the_last_one_is_their_sum(tmp_path):
    plain = _solved(tmp_path, "rotor", "angle = 210", "angle = 210")
    summed = _solved(tmp_path, "rotor", "angle = 210", 'angle = "90 + 120"')
    assert summed == plain


def test_a_bad_expression_is_named_at_its_line(tmp_path):
    text = template("linkage").replace("O2A = 100", 'O2A = "200/x"', 1)
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    run = CliRunner().invoke(cli, ["solve", str(path), "-o", str(tmp_path / "o"), "--no-pdf"])
    assert run.exit_code == 1
    line = next(i for i, t in enumerate(text.splitlines(), 1) if "200/x" in t)
    assert f"bad.toml:{line}:" in run.output and "'200/x'" in run.output
    assert "Traceback" not in run.output and not (tmp_path / "o").exists()


def test_a_gear_speed_written_as_a_quotient_stays_exact(tmp_path):
    plain = _solved(tmp_path, "train", "speed = 1000", "speed = 1000")
    quotient = _solved(tmp_path, "train", "speed = 1000", 'speed = "3000/3"')
    assert quotient == plain        # exact fractions through the train: the same answers
