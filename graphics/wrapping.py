"""Break a caption's or a note's line between words, never inside a formula.

:func:`~tarsim.graphics.figure.wrap_text` breaks at any space, so "θ2 = −44.0721°" could end
one line with "θ2 =" and open the next with "−44.0721°", and a right-to-left line, read
from the other end, would set the two halves apart in the wrong order. Here a formula
(a symbol, "=", its value and the unit after it) is one word to the breaker.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from .figure import text_width, wrap_text

__all__ = ["formula_words", "wrap_formulas"]

_GLUE = "\u2060"
"""What joins a formula's parts while the line is broken: a word joiner, which
:meth:`str.split` keeps (a no-break space it would split at)."""

_UNIT = re.compile(r"^[A-Za-zµ°′″/²³·%]{1,6}[,;:.)]*$")
"""A unit after a number ("s", "mm", "rad/s", "rad/s²,"), kept with it."""

_RELATIONS = ("=", "≈", "<", ">", "≤", "≥")

_NUMBER = re.compile(r"^[(−+\-]?[0-9۰-۹]")


def formula_words(text: str) -> list[str]:
    """``text``'s words, each formula one word (its parts joined by :data:`_GLUE`).

    >>> [w.replace(_GLUE, "+") for w in formula_words("at t = 2.34 s (θ2 = −44.0721°)")]
    ['at', 't+=+2.34+s', '(θ2+=+−44.0721°)']
    """
    words = text.split()
    out: list[str] = []
    k = 0
    while k < len(words):
        w = words[k]
        if k + 1 < len(words) and words[k + 1] in _RELATIONS:
            part = [w, words[k + 1]]
            k += 2
            if k < len(words):
                part.append(words[k])
                k += 1
                if (_NUMBER.match(part[-1]) and k < len(words) and _UNIT.match(words[k])):
                    part.append(words[k])
                    k += 1
            out.append(_GLUE.join(part))
            continue
        out.append(w)
        k += 1
    return out


def wrap_formulas(text: str, size: float, width: float,
                  measure: Callable[[str], float] | None = None) -> list[str]:
    """``text`` broken into lines no wider than ``width`` mm at ``size`` (a word or a
    formula wider than that stands alone), never inside a formula (:func:`formula_words`);
    a line's width is ``measure(line)``, by default its :func:`text_width`.

    >>> wrap_formulas("space diagram at t = 2.34 s (θ2 = −44.0721°)", 3.6, 60.0)
    ['space diagram at t = 2.34 s', '(θ2 = −44.0721°)']
    """
    glued = " ".join(formula_words(text))
    size_of = measure or (lambda line: text_width(line, size))
    lines = wrap_text(glued, size, width,
                      measure=lambda line, _: size_of(line.replace(_GLUE, " ")))
    return [line.replace(_GLUE, " ") for line in lines]
