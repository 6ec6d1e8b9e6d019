"""Labels as a textbook prints them: true subscripts, and digits set as subscripts.

A step's label is recorded as plain text (``V_I23``, ``A_B/A``, ``a4′``, ``O2G``);
figures print it with a true subscript after the underscore and a name's trailing
digits set down (V with I₂₃, a₄′, O₂G), so that ``I13`` on a figure reads I₁₃ as in
the course's books.
"""

from __future__ import annotations

import re

from tarsim.constructions.narration import numerals

__all__ = ["typeset", "subscript", "typeset_span", "spoken_numbers"]

_SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
_TRAILING = re.compile(r"^(.*?[^\d,])([\d,]+)([′″]*)$")


def typeset(label: str) -> tuple[str, str]:
    """Split a recorded label into text and true subscript, as a textbook prints it.

    ``V_A`` is V with subscript A; digits that end a name become Unicode
    subscripts (``I13`` → I₁₃, ``ω2`` → ω₂), inside a subscript too
    (``V_I23`` → V with subscript I₂₃), before primes too (``a4′`` → a₄′, an
    acceleration tip), and on each side of a relative vector's slash
    (``A_A3/A4`` → A with subscript A₃/A₄).

    Examples
    --------
    >>> typeset("V_I23")
    ('V', 'I₂₃')
    >>> typeset("I13")
    ('I₁₃', '')
    >>> typeset("A_B/A")
    ('A', 'B/A')
    >>> typeset("Aᶜ_A3/A4"), typeset("a4′")
    (('Aᶜ', 'A₃/A₄'), ('a₄′', ''))
    """
    head, _, sub = label.partition("_")
    return _digits_down(head), "/".join(_digits_down(part) for part in sub.split("/"))


def subscript(name: str) -> str:
    """Write a name's trailing digits as subscripts, as a textbook prints them ("O2" → "O₂").

    >>> subscript("O24")
    'O₂₄'
    """
    head = name.rstrip("0123456789")
    return head + name[len(head):].translate(_SUBSCRIPT)


def typeset_span(label: str) -> str:
    """A span named by its end points, as a textbook prints it: each number that follows a
    letter becomes a subscript.

    >>> typeset_span("O2G"), typeset_span("AB + O2A"), typeset_span("stroke")
    ('O₂G', 'AB + O₂A', 'stroke')
    """
    return _NAMED.sub(lambda m: m.group(0).translate(_SUBSCRIPT), label)


_NAMED = re.compile(r"(?<=[A-Za-z])\d+")

_NUMBER = re.compile(r"(?<![\w.])[0-9]+(?:\.[0-9]+)?(?:e[−+-]?[0-9]+)?")
"""A number standing alone ("2.34", "−44.0721" after its sign), not a name's digits
("θ2", "O2A", "I13")."""


def spoken_numbers(text: str) -> str:
    """``text`` with each number in it set in the digits of the language being spoken, a
    name's digits kept: a Persian figure's title and caption then use the digits its table
    does ("t = ۲٫۳۴ s", "θ2 = ۶۰°"), one system a figure.

    >>> from tarsim.constructions.narration import speaking
    >>> with speaking("fa"):
    ...     spoken_numbers("at t = 2.34 s (θ2 = −44.0721°), O2A = 100 mm")
    'at t = ۲٫۳۴ s (θ2 = −۴۴٫۰۷۲۱°), O2A = ۱۰۰ mm'
    >>> spoken_numbers("t = 2.34 s")
    't = 2.34 s'
    """
    return _NUMBER.sub(lambda m: numerals(m.group(0)), text)


def _digits_down(name: str) -> str:
    m = _TRAILING.match(name)
    if m is None or " " in name or not m.group(1).strip():
        return name
    return m.group(1) + m.group(2).translate(_SUBSCRIPT) + m.group(3)
