"""How a problem sheet (:mod:`.handout`) sets the numbers and formulas it gives: as the file
writes them, each link's number after a letter a subscript, in the spoken language's digits,
a formula kept left to right inside a Persian line."""

from __future__ import annotations

import re

from tarsim.constructions.narration import numerals, right_to_left, significant
from tarsim.graphics.typeset import subscript, typeset_span

__all__ = ["math_text", "number"]

_GREEK_INDEX = re.compile(r"(?<=[α-ω])\d+")
"""A link's number after θ, ω or α, set as a subscript (θ₂) as the figures set it."""


def math_text(text: str) -> str:
    """A formula or a point as the figures set it, kept left to right in a right-to-left
    line (an embedding the bidi algorithm and the PDF route both honour).

    >>> math_text("O2A = 100"), math_text("α2 = 0")
    ('O₂A = 100', 'α₂ = 0')
    """
    text = numerals(_GREEK_INDEX.sub(lambda k: subscript(k.group(0)), typeset_span(text)))
    return f"\u202a{text}\u202c" if right_to_left() else text


def number(x: float) -> str:
    """A given number as the file would write it: six significant figures, a true minus.

    >>> number(-500.0), number(0.000583)
    ('−500', '0.000583')
    """
    return significant(x + 0.0).replace("-", "−")
