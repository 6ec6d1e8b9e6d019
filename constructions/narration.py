"""The words of a construction: a phrase key and its arguments, rendered from a catalogue.

A step does not hold prose. It holds a :class:`Phrase`: a key naming what the
sentence says ("velocity.swing_onto_line_of_centres") and the arguments it says
it of, typed so that a language can render them in its own way:

* point and link names are plain strings, written as the notes write them in every
  language (O2, A, I13);
* a number is a :class:`Number` (a format spec and the value);
* a length, speed, acceleration or angle is a :class:`Quantity` in the unit the
  exercise speaks (mm, cm, °, ...): "250 mm", "406.712 mm/s", "60°";
* a small word the catalogue may translate (ccw, left, forward) is a :class:`Word`;
* a clause is itself a :class:`Phrase` (or None, which reads as nothing).

:func:`narrate` renders a step's phrase from the catalogue of a language. Each
catalogue is a module of :mod:`.phrases` with ``PHRASES`` (key → template, in
:meth:`str.format` syntax), ``WORDS`` and ``UNITS`` (what a word or unit is
called), ``digits`` (how the language writes the ASCII digits of a number) and
``capitalized`` (how a clause opens a sentence). A new language is a new
catalogue and nothing else.
"""

from __future__ import annotations

import importlib
import math
import re
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass
from functools import cache
from types import ModuleType
from typing import Any

from .errors import TarsimError

__all__ = ["Phrase", "phrase", "Number", "Quantity", "Word", "Capitalized", "narrate", "render",
           "catalogue", "fixed", "significant", "LANGUAGES", "speaking", "spoken", "words",
           "unit_words", "numerals", "measure_words", "right_to_left"]

LANGUAGES = ("en", "fa", "fa_latn")
"""The languages with a catalogue, the first the default (fa_latn: Persian with Latin
digits)."""


_SPOKEN: ContextVar[str] = ContextVar("tarsim_spoken", default="en")
"""The language a figure's own words are set in while it is drawn (:func:`speaking`)."""


@contextmanager
def speaking(lang: str) -> Iterator[str]:
    """Draw in ``lang``: every :func:`words` said inside is from its catalogue.

    A figure's words are set deep in its drawing (a legend's samples, a scale's name), so
    the language is a setting of the drawing, as a locale is, rather than an argument
    every drawing function passes on.

    >>> with speaking("fa"):
    ...     words("Velocity scale")
    'مقیاس سرعت'
    """
    catalogue(lang)                     # an unknown language is refused here, not mid-figure
    token = _SPOKEN.set(lang)
    try:
        yield lang
    finally:
        _SPOKEN.reset(token)


def spoken() -> str:
    """The language being drawn in (English unless inside :func:`speaking`)."""
    return _SPOKEN.get()


def words(text: str, **args: Any) -> str:
    """A figure's ``text`` in the language being spoken, its ``{fields}`` filled with
    ``args`` rendered as a phrase's are; English is the text itself.

    >>> words("{name} circle", name="base")
    'base circle'
    """
    lang = spoken()
    template = catalogue(lang).WORDS.get(text, text)
    return template.format(**{k: render(v, lang) for k, v in args.items()}) if args else template


def unit_words(unit: str) -> str:
    """A compound unit ("mm/s²", "N·m") as the spoken language writes it.

    >>> with speaking("fa"):
    ...     unit_words("mm/s")
    'میلی‌متر بر ثانیه'
    """
    names = catalogue(spoken()).UNITS
    if unit in names:
        return names[unit]
    base, slash, per = unit.partition("/")
    return names.get(base, base) + (names.get(slash + per, slash + per) if slash else "")


def measure_words(text: str) -> str:
    """A measure as the file's units print it ("679.1 mm", "60°") in the spoken language's
    digits and unit names.

    >>> with speaking("fa"):
    ...     measure_words("679.1 mm")
    '۶۷۹٫۱ میلی\u200cمتر'
    """
    number, space, unit = text.rpartition(" ")
    if not space:
        return numerals(text)
    return f"{numerals(number)} {unit_words(unit)}"


def numerals(text: str) -> str:
    """A number already formatted ("12.5", "−3") in the spoken language's digits."""
    return catalogue(spoken()).digits(text)


def numeral(value: float, spec: str = ".6g") -> str:
    """``value`` formatted by ``spec``, in the spoken language's digits: a result as the
    results print it ("25.7472", "5.0e-15").

    >>> with speaking("fa"):
    ...     numeral(25.7472)
    '۲۵٫۷۴۷۲'
    """
    return numerals(format(value, spec))


def right_to_left() -> bool:
    """Whether the spoken language reads right to left (a caption then aligns right)."""
    return getattr(catalogue(spoken()), "DIRECTION", "ltr") == "rtl"


@dataclass(frozen=True, slots=True)
class Phrase:
    """What a sentence says: a catalogue key and the arguments it says it of."""

    key: str
    args: tuple[tuple[str, Any], ...] = ()


def phrase(key: str, **args: Any) -> Phrase:
    """Make a :class:`Phrase` with keyword arguments.

    Examples
    --------
    >>> narrate(phrase("position.bisect", a="O2", b="O4"))
    'Bisect O2O4.'
    """
    return Phrase(key, tuple(args.items()))


@dataclass(frozen=True, slots=True)
class Number:
    """A number as the sentence prints it: ``spec`` is a :func:`format` spec ("", ".6g")."""

    value: float
    spec: str = ".6g"


@dataclass(frozen=True, slots=True)
class Quantity:
    """A length, speed, acceleration or angle: ``value`` in ``unit`` per ``per``.

    ``style`` is ``"length"`` (up to four decimals, trailing zeros dropped: "250
    mm", "12.5 cm", "60°"), ``"rate"`` (six significant figures: "406.712 mm/s"),
    ``"fixed"`` (four decimals kept: "1.0472 rad") or ``"drawn"`` (four significant
    figures, as a cam's or a gear's construction is measured: "2.778 mm", "120°").
    """

    value: float
    unit: str
    per: str = ""
    style: str = "length"


@dataclass(frozen=True, slots=True)
class Word:
    """A small word a language may say in its own way: ``ccw``, ``left``, ``forward``."""

    text: str


@dataclass(frozen=True, slots=True)
class Capitalized:
    """A clause that opens a sentence: English sets its first letter in capitals."""

    clause: Phrase


def drawn_length(metres: float) -> Quantity:
    """A length a cam's or a gear's step measures off (m), as the step says it: in
    millimetres, to four figures.

    >>> render(drawn_length(0.0027778)), render(drawn_length(0.05), "fa")
    ('2.778 mm', '۵۰ میلی‌متر')
    """
    return Quantity(metres * 1e3, "mm", style="drawn")


def counted(n: int) -> Number:
    """A count a step says ("into 6 equal parts"): a number, in the language's digits, where
    a bare integer is a name (link 2, segment 1) and keeps its Latin digits."""
    return Number(n, "d")


def drawn_angle(rad: float) -> Quantity:
    """An angle a cam's or a gear's step measures off (rad), as the step says it: in
    degrees, to four figures."""
    return Quantity(math.degrees(rad), "°", style="drawn")


def fixed(value: float, digits: int) -> str:
    """``value`` to ``digits`` decimals, with trailing zeros dropped ("250", "0.5").

    A size of a million or more, or too small to show in those decimals, is said to six
    significant figures instead (:func:`significant`), so no line spells out a 26-digit
    number or rounds a crank of 4.6e-10 mm to "0 mm".

    >>> fixed(250.0, 4), fixed(1.5e25, 4), fixed(-2.5e-7, 4)
    ('250', '1.5e25', '−2.5e-7')
    """
    if abs(value) >= 1e6 or 0.0 < abs(value) < 0.5 * 10.0 ** -digits:
        return significant(value)
    text = f"{value:.{digits}f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def significant(value: float, figures: int = 6) -> str:
    """``value`` to ``figures`` significant figures, with a true minus, an exponent written
    short ("1.5e25").

    >>> significant(264.57513110645906), significant(1.5e25), significant(-2.5e-7)
    ('264.575', '1.5e25', '−2.5e-7')
    """
    text = _short_exponent(f"{value:.{figures}g}")
    return "0" if text == "-0" else "−" + text[1:] if text.startswith("-") else text


def _short_exponent(text: str) -> str:
    """"1.5e+25" as "1.5e25", "2.5e-07" as "2.5e-7": one way to write every exponent."""
    return re.sub(r"e\+?(-?)0*(\d)", r"e\1\2", text)


def render(arg: Any, lang: str = "en") -> str:
    """Render one argument of a phrase in ``lang``.

    Examples
    --------
    >>> render(Quantity(250.0, "mm"))
    '250 mm'
    >>> render(Quantity(406.712, "mm", "/s", "rate"))
    '406.712 mm/s'
    >>> render(Quantity(60.00000000000001, "°"))
    '60°'
    """
    cat = catalogue(lang)
    if arg is None:
        return ""
    if isinstance(arg, Phrase):
        return narrate(arg, lang)
    if isinstance(arg, Capitalized):
        return cat.capitalized(narrate(arg.clause, lang))
    if isinstance(arg, str):
        return arg
    if isinstance(arg, Word):
        return cat.WORDS.get(arg.text, arg.text)
    if isinstance(arg, Number):
        return cat.digits(_short_exponent(format(arg.value, arg.spec)))
    if isinstance(arg, Quantity):
        text = {"length": lambda v: fixed(v, 4), "rate": significant,
                "fixed": lambda v: f"{v:.4f}", "drawn": lambda v: f"{v:.4g}"}[arg.style](
            arg.value)
        unit = cat.UNITS.get(arg.unit, arg.unit) + cat.UNITS.get(arg.per, arg.per)
        return cat.digits(text) + ("" if arg.unit == "°" else " ") + unit
    if isinstance(arg, (list, tuple)):
        return " ".join(t for t in (render(a, lang) for a in arg) if t)
    if isinstance(arg, int):
        return str(arg)             # a link's number is its name (ω2, link 2) in every language
    raise TarsimError(f"a phrase argument must be a name, a number, a quantity, a word or a "
                      f"clause, not {type(arg).__name__}")


def narrate(item: Any, lang: str = "en") -> str:
    """Render the words of a step (or of a :class:`Phrase`) in ``lang``; "" if it has none.

    Raises
    ------
    TarsimError
        If ``lang`` has no catalogue, or the catalogue has no phrase of that key.
    """
    if isinstance(item, str):         # words already said (a user's, or a note's)
        return item
    p = item if isinstance(item, Phrase) or item is None else item.phrase
    if p is None:
        return ""
    cat = catalogue(lang)
    try:
        template = cat.PHRASES[p.key]
    except KeyError:
        raise TarsimError(f"the '{lang}' catalogue has no phrase '{p.key}'") from None
    return template.format(**{name: render(value, lang) for name, value in p.args})


@cache
def catalogue(lang: str) -> ModuleType:
    """The phrase catalogue of ``lang`` (a module of :mod:`.phrases`).

    Raises
    ------
    TarsimError
        If there is none.
    """
    if lang not in LANGUAGES:
        raise TarsimError(f"there are no words for the language '{lang}'; choose one of "
                          f"{', '.join(LANGUAGES)}")
    return importlib.import_module(f"{__package__}.phrases.{lang}")


def keys(lang: str = "en") -> Iterable[str]:
    """Every phrase key of ``lang``'s catalogue (a test holds the catalogues to one set)."""
    return catalogue(lang).PHRASES.keys()
