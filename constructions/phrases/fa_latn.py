"""Persian with Latin digits (``--digits latin``): the Persian catalogue, its numbers kept in
ASCII digits, as some course material writes them."""

from __future__ import annotations

from . import fa
from .fa import DIRECTION, UNITS, capitalized

__all__ = ["PHRASES", "WORDS", "UNITS", "digits", "capitalized", "DIRECTION"]

_LATIN = str.maketrans("۰۱۲۳۴۵۶۷۸۹", "0123456789")

# The numbers a phrase writes out itself ("به نسبت ۱ : ۳ : ۵", "داده نشده: ۰") in ASCII too.
PHRASES = {key: text.translate(_LATIN) for key, text in fa.PHRASES.items()}
WORDS = {key: text.translate(_LATIN) for key, text in fa.WORDS.items()}


def digits(text: str) -> str:
    """Numbers as formatted, in ASCII digits."""
    return text
