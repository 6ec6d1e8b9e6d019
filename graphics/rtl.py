"""Right-to-left text (Persian) in the figures: kept in logical order in the SVG, shaped
for cairosvg.

A browser or Inkscape shapes Persian and lays it right to left from the SVG's own text,
given ``direction="rtl"`` and a font with the glyphs (DejaVu Sans has them; DejaVu Serif,
the figures' Latin face, has not). cairosvg does neither: it draws the characters unjoined,
left to right. So the SVG a user gets keeps the text as written, and the copy handed to
cairosvg for a PDF or PNG has each right-to-left run reshaped into its joined presentation
forms (arabic-reshaper) and put in visual order (python-bidi, the Unicode bidirectional
algorithm), its anchor turned back to the left-to-right one. The published SVG never
carries shaped text: a browser would shape and reverse it a second time.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache

from tarsim.constructions.narration import right_to_left

__all__ = ["is_rtl", "RTL_FONT", "for_cairo", "visual", "joined", "Reading", "reading"]

RTL_FONT = "DejaVu Sans"
"""A face with the Persian glyphs, usually present wherever DejaVu is."""

_RTL = re.compile("[\u0590-\u08ff\ufb1d-\ufdff\ufe70-\ufefc\u200f]")
"""Right-to-left letters, and the right-to-left mark a run of neutrals is given (svg.py)."""

_FLIP = {"start": "end", "end": "start"}


def is_rtl(text: str) -> bool:
    """Whether ``text`` has right-to-left letters (Hebrew or Arabic script).

    >>> is_rtl("مقیاس ۱ سانتی‌متر"), is_rtl("V_B = 0.23 m/s")
    (True, False)
    """
    return bool(_RTL.search(text))


def flip_anchor(anchor: str) -> str:
    """The text-anchor that keeps a label's box in place when its direction turns: a
    right-to-left run's start is its right end."""
    return _FLIP.get(anchor, anchor)


def visual(text: str) -> str:
    """``text`` as cairosvg must be given it: joined presentation forms, in visual order
    (numbers keep their own order: ۲۵ stays ۲۵)."""
    from bidi.algorithm import get_display

    # The base direction is the SVG's own (rtl), not guessed from the first letter: a line
    # that opens with a Latin name ("Four-bar: مقیاس …") still reads right to left.
    return get_display(joined(text), base_dir="R")


@cache
def _reshaper():
    import arabic_reshaper

    # Marks kept: the ezafe of "دایرهٔ" is a combining hamza, which the default deletes.
    return arabic_reshaper.ArabicReshaper(configuration={"delete_harakat": False})


def joined(text: str) -> str:
    """``text`` with each Arabic-script letter in the presentation form it takes beside its
    neighbours (the glyphs a shaper would draw), its marks kept; still in logical order."""
    return _reshaper().reshape(text)


def for_cairo(svg: str) -> str:
    """A copy of ``svg`` (tarsim's own) with every right-to-left run shaped and in visual
    order, its anchor turned back, for cairosvg; ``svg`` itself if it has none."""
    if not is_rtl(svg):
        return svg
    import xml.etree.ElementTree as ET

    ET.register_namespace("", "http://www.w3.org/2000/svg")
    ET.register_namespace("xlink", "http://www.w3.org/1999/xlink")
    ET.register_namespace("ev", "http://www.w3.org/2001/xml-events")
    root = ET.fromstring(svg)
    for el in root.iter():
        if el.tag.rsplit("}", 1)[-1] != "text" or el.get("direction") != "rtl":
            continue
        del el.attrib["direction"]
        el.set("text-anchor", flip_anchor(el.get("text-anchor", "start")))
        for part in el.iter():
            if part.text and is_rtl(part.text):
                part.text = visual(part.text)
    return ET.tostring(root, encoding="unicode")


@dataclass(frozen=True)
class Reading:
    """Which way a figure's lines run across a page ``width`` wide: from the left margin,
    or, in a right-to-left language (``rtl``), mirrored from the right one."""

    width: float
    rtl: bool

    def x(self, at: float) -> float:
        """Where ``at``, laid out from the left, stands on the page as the language reads."""
        return self.width - at if self.rtl else at

    @property
    def anchor(self) -> str:
        """The anchor of a line that starts at its reading edge."""
        return "end" if self.rtl else "start"

    @property
    def way(self) -> float:
        """+1 if the lines run rightwards, −1 if leftwards."""
        return -1.0 if self.rtl else 1.0


def reading(width: float) -> Reading:
    """How the language being spoken reads a page ``width`` wide (:class:`Reading`)."""
    return Reading(width, right_to_left())
