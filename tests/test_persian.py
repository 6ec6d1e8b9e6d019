"""Persian: a second phrase catalogue, not a second code path.

Every English phrase has a Persian one with the same fields; numbers come out in Persian
digits in their logical order (which the bidirectional algorithm shows left to right inside
right-to-left text); the glossary's terms are the ones the catalogue uses; and
`tarsim solve --lang fa` writes steps.md in Persian.
"""

from __future__ import annotations

import string
import unicodedata
from pathlib import Path

import pytest
from click.testing import CliRunner

from tarsim.constructions.errors import InputError

from tarsim.constructions.narration import Quantity, narrate, phrase, render
from tarsim.constructions.phrases import en, fa
from tarsim.exercises.cli import cli

GLOSSARY = Path(__file__).resolve().parents[1] / "docs" / "glossary-fa.md"


def _fields(template: str) -> set[str]:
    return {f for _, f, _, _ in string.Formatter().parse(template) if f}


def test_every_phrase_has_a_persian_one_with_the_same_fields():
    assert set(fa.PHRASES) == set(en.PHRASES)
    for key, english in en.PHRASES.items():
        assert _fields(fa.PHRASES[key]) == _fields(english), key


def test_numbers_are_persian_digits_in_logical_order():
    """۲۵ stays ۲۵, never ۵۲: the digits keep the number's own order, and Persian digits
    are European-number class in the bidi algorithm, so they show left to right in a
    right-to-left line."""
    assert fa.digits("25") == "۲۵"
    assert render(Quantity(250.0, "mm"), "fa") == "۲۵۰ میلی\u200cمتر"
    assert render(Quantity(406.712, "mm", "/s", "rate"), "fa") == \
        "۴۰۶٫۷۱۲ میلی\u200cمتر بر ثانیه"
    assert all(unicodedata.bidirectional(d) == "EN" for d in "۰۱۲۳۴۵۶۷۸۹")
    said = narrate(phrase("position.bisect", a="O2", b="O4"), "fa")
    assert "O2O4" in said                    # point names stay as the notes write them


ELSEWHERE = {"مرکز لحظه": "an instant centre is مرکز آنی, as the notes say",
             "کرنک": "a crank is لنگ", "کوپلر": "a coupler is میلهٔ رابط",
             "اسلایدر": "a slider is لغزنده", "پولیگون": "a polygon is چندضلعی",
             "ي": "Persian writes ی, not the Arabic ي", "ك": "Persian writes ک, not the Arabic ك"}
"""Words other Persian texts use for the course's terms, which the notes do not."""


def test_the_catalogue_keeps_to_the_glossarys_terms():
    rows = [line.split("|")[1:4] for line in GLOSSARY.read_text(encoding="utf-8").splitlines()
            if line.startswith("| ") and "---" not in line][1:]
    assert len(rows) > 40
    assert all(persian.strip() and where.strip() for _, persian, where in rows)
    words = " ".join([*fa.PHRASES.values(), *fa.WORDS.values()])
    for other, why in ELSEWHERE.items():
        assert other not in words, why


def test_solve_writes_persian_steps(tmp_path):
    out = tmp_path / "fa"
    result = CliRunner().invoke(cli, ["solve", "four-bar", "--lang", "fa", "--no-pdf", "-o",
                                      str(out)])
    assert result.exit_code == 0, result.output
    steps = (out / "steps.md").read_text(encoding="utf-8")
    assert steps.startswith("# چهار میله\u200cای لنگ - آونگ: حل کامل")    # its [names] fa
    assert "## نتایج" in steps and "مراکز آنی" in steps and "قضیهٔ کندی" in steps
    english = (tmp_path / "en")
    CliRunner().invoke(cli, ["solve", "four-bar", "--no-pdf", "-o", str(english)])
    assert "## Results" in (english / "steps.md").read_text(encoding="utf-8")


def test_digits_latin_and_a_files_lang(tmp_path):
    """--digits latin keeps ASCII digits in the Persian text; lang = "fa" in a file asks for
    Persian without --lang; an unknown lang is refused at its line."""
    from tarsim.exercises.catalog import resolve
    from tarsim.exercises.linkages.exercise_file import parse_exercise

    out = tmp_path / "latn"
    result = CliRunner().invoke(cli, ["solve", "four-bar", "--lang", "fa", "--digits", "latin",
                                      "--no-pdf", "-o", str(out)])
    assert result.exit_code == 0, result.output
    steps = (out / "steps.md").read_text(encoding="utf-8")
    body = steps.split("## نتایج")[0]
    assert "## نتایج" in steps and not any(d in body for d in "۰۱۲۳۴۵۶۷۸۹")
    assert "100 " in body or "250 " in body
    text = resolve("four-bar").read_text(encoding="utf-8")
    path = tmp_path / "fa.toml"
    path.write_text('lang = "fa"\n' + text, encoding="utf-8")
    out = tmp_path / "file-fa"
    result = CliRunner().invoke(cli, ["solve", str(path), "--no-pdf", "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "حل کامل" in (out / "steps.md").read_text(encoding="utf-8")
    with pytest.raises(InputError, match=r"bad.toml:1: lang is the language of the steps"):
        parse_exercise('lang = "de"\n' + text, "bad.toml")


SYMBOLS = {"rad", "rpm", "cos", "sin", "tan"}
"""Latin a Persian text keeps: units and the functions of a formula."""


@pytest.mark.parametrize("name", ["oscillating-roller", "offset-knife-edge",
                                  "eccentric-flat-face", "roller-harmonic-cycloidal",
                                  "four-mass-shaft", "single-cylinder", "inline-four",
                                  "involute-pair", "planetary-q1"])
def test_a_chapters_persian_steps_say_their_results_in_persian(name):
    """A cam's, a rotor's, an engine's and a train's steps.md in Persian: the steps and the
    results alike, their words and their digits; only what the file itself says (its name
    and description), the file names, the quantities' keys and the units stay Latin."""
    import re

    from tarsim.constructions.narration import speaking
    from tarsim.exercises.balancing.balance_solution import solve_balance
    from tarsim.exercises.cams.cam_solution import solve_cam
    from tarsim.exercises.catalog import load
    from tarsim.exercises.gears.train_solution import solve_train

    ex = load(name)
    solve = {"CamExercise": solve_cam, "BalanceExercise": solve_balance,
             "TrainExercise": solve_train}[type(ex).__name__]
    with speaking("fa"):
        md = solve(ex).steps()
    body = md.replace(ex.description, "").replace(ex.name, "")
    body = re.sub(r"`[^`]*`|\w*_\w*|^\| [^|]* \|", "", body, flags=re.M)
    assert set(re.findall(r"[A-Za-z]{3,}", body)) <= SYMBOLS, name
    # Every measured number in Persian digits (a whole number may be a name: gear 2).
    assert re.search("[۰-۹]٫[۰-۹]", body) and not re.search(r"\d\.\d", body), name
    with speaking("fa_latn"):                       # --digits latin: none at all
        assert not re.search("[۰-۹]", solve(ex).steps()), name


@pytest.mark.parametrize("name", ["planetary-q1", "planetary-q3", "planetary-q4"])
def test_a_persian_kutzbach_diagram_gives_each_omega_in_persian(name):
    """Each line's ω on the velocity diagram, in Persian digits and Persian units, as the
    train's table and scale bars give theirs."""
    from tarsim.constructions.narration import speaking
    from tarsim.exercises.catalog import load
    from tarsim.exercises.gears.train_solution import solve_train

    with speaking("fa"):
        fig = solve_train(load(name)).figures["kutzbach"]
    omegas = [t.text for t in fig.items if getattr(t, "text", "").startswith("ω") and "=" in t.text]
    assert omegas, name
    for text in omegas:
        value = text.split("=", 1)[1]
        assert not any(c in string.digits for c in value) and "rpm" not in value, text
        assert any("۰" <= c <= "۹" for c in value), text


def test_the_whole_mechanisms_results_are_persian_too(tmp_path):
    """The notes' crank-rocker question (001): AB may run from 65 to 135 mm. In Persian the
    class, the range and Grashof's sums are said in the notes' words and Persian digits."""
    out = tmp_path / "fa"
    result = CliRunner().invoke(cli, ["solve", "grashof-crank-rocker", "--lang", "fa",
                                      "--no-pdf", "-o", str(out)])
    assert result.exit_code == 0, result.output
    rows = {line.split("|")[1].strip(): [c.strip() for c in line.split("|")[2:-1]]
            for line in (out / "steps.md").read_text(encoding="utf-8").splitlines()
            if line.startswith("| ")}
    assert rows["range_AB"][0] == "۶۵ mm < AB < ۱۳۵ mm (لنگ - آونگ)"
    assert rows["grashof"][0] == "لنگ - آونگ"
    assert rows["grashof"][3].startswith("گراشف: S + L = ۱۳۰ میلی\u200cمتر در برابر P + Q = ۱۶۵")
    assert rows["dof"][:2] == ["۱", "۱"] and rows["dof"][3].startswith("گروبلر")
    assert "crank-rocker" in result.output           # the terminal's lines stay English
