"""Persian with Latin digits (``--digits latin``): the Persian catalogue, its numbers kept in
ASCII digits, as some course material writes them."""

from __future__ import annotations

from .fa import DIRECTION, PHRASES, UNITS, WORDS, capitalized

__all__ = ["PHRASES", "WORDS", "UNITS", "digits", "capitalized", "DIRECTION"]


def digits(text: str) -> str:
    """Numbers as formatted, in ASCII digits."""
    return text
