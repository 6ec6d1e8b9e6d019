"""Persian on the figures: their own words from the catalogue, laid out right to left.

A figure's words (captions, legends, scale statements, titles, table headings, notes)
are said in the language it is drawn in (``narration.speaking``); English stays as it was,
and its figures carry no right-to-left text at all.
"""

from __future__ import annotations

import re

import pytest
from click.testing import CliRunner

from tarsim.constructions.errors import InputError
from tarsim.constructions.narration import speaking, spoken, unit_words, words
from tarsim.constructions.phrases import fa
from tarsim.exercises.catalog import load
from tarsim.exercises.cli import cli
from tarsim.exercises.linkages.exercise_file import parse_exercise
from tarsim.exercises.linkages.solution_files import solve_worked
from tarsim.graphics.figure import Figure, Path, Text, text_width
from tarsim.graphics.rtl import is_rtl
from tarsim.graphics.scales import draw_caption, scale_text
from tarsim.graphics.svg import runs as _runs, to_svg

from tests.common import four_bar_toml


def test_words_are_the_text_itself_in_english_and_the_catalogues_in_persian():
    assert spoken() == "en"
    assert words("Velocity scale") == "Velocity scale"
    assert words("{name}: {what}", name="Four-bar", what="instant centres") == \
        "Four-bar: instant centres"
    with speaking("fa"):
        assert words("Velocity scale") == "مقیاس سرعت"
        assert unit_words("mm/s") == "میلی\u200cمتر بر ثانیه"
        assert words("{name}: {what} at {where}", name="چهار میله\u200cای", what="مراکز آنی",
                     where="θ2 = 90°") == "چهار میله\u200cای: مراکز آنی در \u202aθ2 = 90°\u202c"
    assert spoken() == "en"                  # the setting ends with its block


def test_the_issues_scale_statement_word_for_word():
    """"مقیاس سرعت ۱ سانتی‌متر = ۶۰ میلی‌متر بر ثانیه", as the issue writes it."""
    with speaking("fa"):
        assert f"{words('Velocity scale')} {scale_text(60.0, 'mm/s')}" == \
            "مقیاس سرعت ۱ سانتی\u200cمتر = ۶۰ میلی\u200cمتر بر ثانیه"
    with speaking("fa_latn"):
        assert scale_text(60.0, "mm/s") == "1 سانتی\u200cمتر = 60 میلی\u200cمتر بر ثانیه"
    assert scale_text(60.0, "mm/s") == "1 cm = 60 mm/s"


def _caption(lang: str) -> Figure:
    fig = Figure(0.0, 0.0, [Path(((0.0, 0.0), (120.0, 60.0)), "link")])
    with speaking(lang):
        draw_caption(fig, words("{name}: {what}", name="Four-bar", what=words("space diagram")),
                     ["θ₂ = 60°"], per_cm=50.0, unit="mm", legend=[("kennedy", "Kennedy line")],
                     notes=["note"])
    return fig


def test_a_persian_caption_reads_from_the_right_margin():
    """The heading, lines, legend and notes end at the right margin; the scale statement
    and its bar stand at the left, the bar still numbered left to right."""
    for lang, anchor in (("en", "start"), ("fa", "end")):
        fig = _caption(lang)
        texts = {t.text: t for t in fig.items if isinstance(t, Text)}
        head = next(t for t in texts.values() if t.weight == "bold")
        assert head.anchor == anchor
        if lang == "fa":
            assert head.at[0] == pytest.approx(fig.width - 8.0)
            scale = next(t for s, t in texts.items() if s.startswith("مقیاس"))
            ticks = sorted((t for s, t in texts.items() if re.fullmatch("[۰-۹]+", s)),
                           key=lambda t: t.at[0])
            assert [t.text for t in ticks] == ["۰", "۱۰۰"]     # 0, 100 left to right
            assert scale.box()[0] < fig.width / 2 < head.box()[0]
            legend = texts["خط کندی"]
            sample = next(p for p in fig.items if isinstance(p, Path) and p.style == "kennedy")
            assert legend.box()[2] < min(x for x, _ in sample.points)    # name left of it


def test_english_figures_hold_no_right_to_left_text(files):
    for name, text in files("crank-shaper").items():
        if name.endswith(".svg"):
            assert not is_rtl(text), name
            assert 'direction="rtl"' not in text


def test_a_subscript_among_persian_words_is_set_as_runs_of_one_direction():
    """"V_B به روش دوران شعاع": the symbol with its subscript at the right end, the words to
    its left, each run its own <text>, so that cairosvg and a browser agree."""
    label = Text((100.0, 10.0), "V", 3.6, "end", False, "bold", "B", " به روش دوران شعاع")
    runs = _runs(label)
    assert [(r.text, r.sub) for r in runs] == [("V", "B"), ("به روش دوران شعاع", "")]
    assert runs[0].box()[2] == pytest.approx(100.0)
    assert runs[1].box()[2] < runs[0].box()[0]
    svg = to_svg(Figure(110.0, 20.0, [label]))
    assert svg.count("<text") == 2 and "<tspan" in svg       # one run keeps its subscript


@pytest.fixture(scope="module")
def shaper_fa():
    with speaking("fa"):
        worked = solve_worked(load("crank-shaper").named_in("fa"))
        return worked, worked.files()


def test_the_worked_pages_table_mirrors_its_columns(shaper_fa):
    worked, _ = shaper_fa
    page = worked.figures["worked-theta2-90"]
    heads = {t.text: t for t in page.items if isinstance(t, Text) and t.weight == "bold"}
    xs = [heads[h].box()[2] for h in ("کمیت", "روش", "ترسیم", "تحلیلی", "خطای نسبی")]
    assert xs == sorted(xs, reverse=True)          # the first column at the right


def test_persian_titles_name_the_mechanism_as_the_file_does_in_persian(shaper_fa):
    _, files = shaper_fa
    assert "مکانیزم بازگشت سریع ماشین شیپر: مراکز آنی" in files["centres-theta2-90.svg"]
    assert files["steps.md"].startswith("# مکانیزم بازگشت سریع ماشین شیپر: حل کامل")
    assert not is_rtl(files["results.json"])       # data, in one language whatever is spoken


def test_a_given_rates_note_is_said_in_persian():
    with speaking("fa"):
        worked = solve_worked(load("piston-driven-slider-crank"))
        notes = worked.positions[0].notes
    assert any("داده شده است" in n and "۳۰۰ میلی\u200cمتر بر ثانیه" in n for n in notes)
    english = solve_worked(load("piston-driven-slider-crank")).positions[0].notes
    assert any(n.startswith("V_C along its guide = 300 mm/s is given") for n in english)


def test_names_in_a_file_are_checked():
    text = four_bar_toml() + '\n[names]\nfa = "چهار میله‌ای"\n'
    assert parse_exercise(text).named_in("fa").mechanism.name == "چهار میله‌ای"
    assert parse_exercise(text).named_in("en").mechanism.name != "چهار میله‌ای"
    for bad, says in (('de = "Viergelenk"', "names.de: there are words for fa only"),
                      ("fa = 3", "names.fa must be one line of text")):
        with pytest.raises(InputError, match=re.escape(says)) as err:
            parse_exercise(four_bar_toml() + f"\n[names]\n{bad}\n", "f.toml")
        assert "f.toml:" in str(err.value)


def test_persian_widths_are_the_joined_forms_not_the_letters():
    """A joined Persian word is narrower than its letters set apart: the layout measures
    the forms it is drawn in."""
    import arabic_reshaper

    word = "چندضلعی"
    apart = sum(text_width(ch, 1.0) for ch in word)
    assert text_width(word, 1.0) < apart
    assert text_width(word, 1.0) == pytest.approx(
        sum(text_width(ch, 1.0) for ch in arabic_reshaper.reshape(word)))


@pytest.mark.parametrize("command", [
    ["draw", "crank-shaper-forces", "-o", "{out}/loaded.svg", "--lang", "fa"],
    ["draw", "four-bar", "-o", "{out}/four-bar.svg", "--lang", "fa", "--digits", "latin"],
    ["sweep", "four-bar", "--steps", "36", "--no-pdf", "-o", "{out}/sweep", "--lang", "fa"],
])
def test_the_figure_commands_speak_persian(tmp_path, command):
    result = CliRunner().invoke(cli, [c.format(out=tmp_path) for c in command])
    assert result.exit_code == 0, result.output
    svgs = list(tmp_path.rglob("*.svg"))
    assert svgs and all(is_rtl(p.read_text(encoding="utf-8")) for p in svgs)
    if "latin" in command:
        assert not re.search("[۰-۹]", svgs[0].read_text(encoding="utf-8"))


def test_the_catalogue_has_no_english_left_in_its_persian_words():
    """A Persian entry that is still English (a copy of its key) would pass every lookup."""
    for key, said in fa.WORDS.items():
        latin = re.sub(r"\{\w+\}|[A-Za-z]_?\w*\d|[A-Z]\w*\b", "", said)
        assert is_rtl(said) or not re.search("[a-z]{4,}", latin), (key, said)


def test_the_ezafe_survives_the_pdf_routes_shaping():
    """"دایرهٔ کمکی": the ezafe is a combining hamza over the heh, which arabic-reshaper
    deletes unless told to keep marks; drawn before its letter in visual order, cairosvg sets
    it over the letter."""
    from tarsim.graphics.rtl import visual

    import unicodedata

    shown = visual("دایرهٔ کمکی")
    mark = shown.index("\u0654")
    assert unicodedata.name(shown[mark + 1]).startswith("ARABIC LETTER HEH")   # its letter


LATIN_ALLOWED = {"rad", "rpm", "tan", "rel", "Fij", "Tij", "Fik", "Mik", "Mfij"}
"""Latin words a Persian figure keeps: unit symbols, formulas' own (tan φ, v_rel), and the
force key's general symbols F_ij, T_ij, F_ik, M_ik and M_f,ij (a letter, its subscripts)."""


@pytest.mark.slow
@pytest.mark.parametrize("exercise_id", [
    "crank-shaper", "hinkle-slider-crank", "klein-slider-crank", "piston-driven-slider-crank",
    "whitworth", "engine-friction", "crank-shaper-forces", "planetary-q4", "compound-train",
    "involute-pair", "oscillating-roller", "eccentric-flat-face", "four-mass-shaft",
    "inline-four", "single-cylinder"])
def test_a_persian_solution_leaves_no_english_on_its_figures(tmp_path, exercise_id):
    """Every chapter's figures, solved with --lang fa: no English word is left on them but
    symbols, units and formulas; point names (O2, A, I13) are one or two letters."""
    result = CliRunner().invoke(cli, ["solve", exercise_id, "--lang", "fa", "--no-pdf", "-o",
                                      str(tmp_path)])
    assert result.exit_code == 0, result.output
    svgs = [p for p in tmp_path.glob("*.svg") if p.name != "solution.svg"]
    assert svgs
    for svg in svgs:
        for text in re.findall(r"<text[^>]*>(.*?)</text>", svg.read_text(encoding="utf-8"),
                               re.S):
            text = re.sub(r"<[^>]+>", "", text)
            left = set(re.findall(r"[A-Za-z]{3,}", text)) - LATIN_ALLOWED
            assert not left, (svg.name, text)


def test_a_bracket_among_persian_runs_reads_right_to_left():
    """"(V_B به روش …)": the lone "(" before the symbol is a run of its own, marked right
    to left (U+200F) so that a browser and the PDF route both mirror it to open on the
    right, as the closing bracket at the far end closes on the left."""
    label = Text((100.0, 10.0), "(V", 3.6, "end", False, "normal", "B", " به روش دوران شعاع)")
    runs = _runs(label)
    assert [r.text for r in runs] == ["\u200f(", "V", "به روش دوران شعاع)"]
    assert 'direction="rtl"' in to_svg(Figure(110.0, 20.0, [runs[0]]))
    from tarsim.graphics.rtl import visual

    assert visual(runs[0].text)[0] == ")"        # mirrored, as cairosvg is given it
