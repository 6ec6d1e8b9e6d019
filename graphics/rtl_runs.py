"""A right-to-left line with subscripts in it, laid as runs of one direction each.

A subscript is a tspan, and cairosvg sets tspans left to right whatever the text's
direction, while a browser puts the same tspans in bidirectional order. So a Persian line
with a symbol in it ("V_B به روش دوران شعاع", "θ_2 = ۹۰°، ۲۷۰°") is set as runs of one
direction each, laid from its right end leftwards as the line reads: its words, each symbol
with its subscript (and what makes a formula of it), and its words again. A viewer sets a
run of one direction alike whether it reads the runs one by one or together. Both the
figures' labels (:mod:`.svg`) and the plots' texts (:mod:`.plot`) are laid here; they
differ only in how they find their symbols.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from .figure import Text, text_width
from .rtl import is_rtl

__all__ = ["lay_runs", "sign_left"]

_SIGN = re.compile(r"(?<![\w۰-۹])([+−])(?=[0-9۰-۹A-Za-z])")
"""A sign opening a number, or a direction (+x)."""

_A_NUMBER = r"[−+]?[0-9۰-۹][0-9۰-۹٫.]*°?"
_FORMULA = re.compile(rf"\s*=\s*{_A_NUMBER}(?:(?:، |…){_A_NUMBER})*")
"""What follows a symbol to make a formula with it: " = ۲۰۱٫۱°", " = ۹۰°، ۲۷۰°"."""


def sign_left(text: str) -> str:
    """Right-to-left ``text`` with each signed number (or +x) keeping its sign at its left,
    as a formula does: read right to left, the sign would go to its right, unless a
    left-to-right mark (of no width) opens it."""
    return _SIGN.sub("\u200e\\1", text) if is_rtl(text) else text


def lay_runs(at: tuple[float, float], runs: Sequence[tuple[str, str, str]], size: float,
             anchor: str, italic: bool = False, weight: str = "normal") -> list[Text]:
    """Lay ``runs`` (in reading order: words as ``(words, "", "")``, a symbol as
    ``(symbol, subscript, mark)``, its mark a prime after the subscript) from the line's
    right end leftwards; ``at`` and ``anchor`` place the line as a :class:`Text` is placed.

    A symbol followed by " = ۹۰°" is one left-to-right run with it. A run of neutrals only
    (a lone bracket) is marked right to left (U+200F), so that both viewers turn it. Spaces
    at a run's ends, which SVG drops, are kept as gaps between the runs.
    """
    runs = list(runs)
    gap = text_width(" ", size)
    laid: list[tuple[float, Text]] = []       # (how far its right end is from the line's)
    total = 0.0
    after_formula = False
    for k, (words, sub, mark) in enumerate(runs):
        if sub:
            t = Text((0.0, 0.0), words, size, "start", italic, weight, sub, mark)
            formula = _FORMULA.match(runs[k + 1][0]) if k + 1 < len(runs) else None
            after_formula = formula is not None
            if formula is None:
                laid.append((total, t))
                total += t.width
                continue
            # "θ_2 = ۹۰°" left to right: the symbol, then (a mark opening it so) the rest.
            said = formula.group().strip()
            said = "\u200e" + said if is_rtl(said) else said
            rest = Text((0.0, 0.0), said, size, "start", italic, weight)
            runs[k + 1] = (runs[k + 1][0][formula.end():], "", "")
            laid += [(total, rest), (total + rest.width + gap, t)]
            total += rest.width + gap + t.width
            continue
        # A space, or a "،" after "θ_2 = ۹۰°" (which would touch the θ at its left).
        total += gap if words[:1].isspace() or (after_formula and words[:1] not in ")]") \
            else 0.0
        after_formula = False
        said = words.strip()
        if not said:
            continue
        if is_rtl(said):
            said = sign_left(said)
        elif not any(c.isalnum() for c in said):
            said = "\u200f" + said            # neutrals only ("(", ":"): right to left
        t = Text((0.0, 0.0), said, size, "start", italic, weight)
        laid.append((total, t))
        total += t.width + (gap if words[-1:].isspace() else 0.0)
    right = at[0] + (total / 2 if anchor == "middle" else 0.0 if anchor == "end" else total)
    return [Text((right - before - t.width, at[1]), t.text, size, "start", italic, weight,
                 t.sub, t.tail) for before, t in laid]
