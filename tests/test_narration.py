"""Tests for constructions.narration and its catalogues: every step says something, in words
the catalogue holds, and a second language needs nothing but a catalogue.

The keys are held two ways: statically (every key a method names is in the
catalogue, every key in the catalogue is named by some method), and by narrating
every step of every bundled exercise's solution.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import tarsim.constructions as constructions
from tarsim.constructions.errors import TarsimError
from tarsim.constructions.narration import (LANGUAGES, Capitalized, Number, Phrase, Quantity,
                                            Word, catalogue, narrate, phrase, render)
from tarsim.exercises.catalog import bundled

_EXERCISES = Path(constructions.__file__).parent.parent / "exercises"
SOURCE = [p for p in Path(constructions.__file__).parent.rglob("*.py")
          if "phrases" not in p.parts] + sorted(_EXERCISES.rglob("*.py"))
NAMED = re.compile(r"""phrase\(\s*["']([\w.]+)["']|phrase\(\s*\(?["']([\w.]+)["'] if """)


def _named_keys() -> set[str]:
    """Every phrase key the constructions name, read off their source."""
    keys = set()
    for path in SOURCE:
        text = path.read_text(encoding="utf-8")
        keys |= {a or b for a, b in NAMED.findall(text)}
        # a key chosen between two: phrase("a" if … else "b", …)
        keys |= set(re.findall(r"""phrase\(\s*["'][\w.]+["']\s+if\b[^)]*?else\s+["']([\w.]+)["']""",
                               text))
    return keys


def test_every_key_a_method_names_is_in_every_catalogue():
    named = _named_keys()
    assert len(named) > 100
    for lang in LANGUAGES:
        missing = named - set(catalogue(lang).PHRASES)
        assert not missing, f"{lang} lacks {sorted(missing)}"


def test_every_key_of_a_catalogue_is_named_by_a_method():
    source = "\n".join(p.read_text(encoding="utf-8") for p in SOURCE)
    for lang in LANGUAGES:
        unused = [k for k in catalogue(lang).PHRASES if f'"{k}"' not in source]
        assert not unused, f"{lang} has phrases no method says: {unused}"


def test_the_catalogues_hold_one_set_of_keys():
    keys = {lang: set(catalogue(lang).PHRASES) for lang in LANGUAGES}
    assert all(k == keys[LANGUAGES[0]] for k in keys.values())


@pytest.mark.parametrize("exercise_id", sorted(bundled()))
def test_every_step_of_a_bundled_solution_is_said_in_full(solved, exercise_id):
    worked = solved(exercise_id)
    works = [worked.overall.work] if worked.overall.work else []
    works += [sol.work for sol in worked.positions]
    said = 0
    for work in works:
        for step in work.assembly:
            words = narrate(step)
            if step.phrase is None:
                assert words == ""
                continue
            said += 1
            assert words and "{" not in words and "}" not in words, step.id
            assert "None" not in words and "Phrase(" not in words, (step.id, words)
    assert said >= 5


def test_arguments_render_in_the_exercise_units():
    assert render(Quantity(250.0, "mm")) == "250 mm"
    assert render(Quantity(12.5, "cm")) == "12.5 cm"
    assert render(Quantity(406.7123456, "mm", "/s", "rate")) == "406.712 mm/s"
    assert render(Quantity(1.0471975512, "rad", style="fixed")) == "1.0472 rad"
    assert render(Number(0.2915958, ".6g")) == "0.291596"
    assert render(Word("ccw")) == "ccw"
    assert render(Capitalized(phrase("components.say_guide", point="B"))) == "The guide of B"
    assert render(None) == "" and render(("a", None, "b")) == "a b"


def test_a_language_without_a_catalogue_is_refused_in_one_line():
    with pytest.raises(TarsimError, match=r"^there are no words for the language 'xx'; "
                                          r"choose one of en, fa, fa_latn$"):
        narrate(phrase("position.bisect", a="O2", b="O4"), "xx")
    with pytest.raises(TarsimError, match="has no phrase 'nowhere'"):
        narrate(Phrase("nowhere"))
