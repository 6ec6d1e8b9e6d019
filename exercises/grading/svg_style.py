"""What an SVG element's presentation says that grading reads: how big its letters are,
whether it paints anything, whether a marker (an arrowhead) ends it, and which elements
place a text's first letter.

A property is read as SVG gives it, from the element's ``style`` (which wins) or its own
attribute, and inherited from the elements that hold it. A style sheet (``<style>``) is
not read: the programs a drawing comes from write these properties on the element.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, replace

from .svg_transform import PX

__all__ = ["Inherited", "inherit", "first_letter", "MEDIUM"]

MEDIUM = 16.0
"""The font size SVG gives text that states none (CSS's ``medium``, in px)."""

_KEYWORDS = {"xx-small": 9.0, "x-small": 10.0, "small": 13.0, "medium": 16.0, "large": 18.0,
             "x-large": 24.0, "xx-large": 32.0}
_SIZE = re.compile(r"\s*([+]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(px|pt|pc|mm|cm|in|em|ex|%)?"
                   r"\s*(?:!important)?\s*")
_ANCHORS = {"start": 0.0, "middle": 0.5, "end": 1.0}
_STYLE = 10_000
"""The longest style attribute read (characters): a style states a few dozen properties."""
_LARGEST = 1e12
"""The largest font size kept, in its own units, as any number a drawing holds."""


@dataclass(frozen=True, slots=True)
class Inherited:
    """What an element passes on to those it holds: its font size (user units; None where
    none is said), whether its fill and its stroke are said to be none, whether a marker
    starts or ends its strokes, and where a text's x stands along its letters (0 at their
    start, as ``text-anchor: start``; 0.5 ``middle``; 1 ``end``)."""

    size: float | None = None
    no_fill: bool = False
    no_stroke: bool = False
    marked: tuple[bool, bool] = (False, False)
    anchor: float = 0.0

    @property
    def unseen(self) -> bool:
        """Whether a shape with this presentation paints nothing: its fill and its stroke
        both said to be none (as LibreOffice's bounding box round every shape is)."""
        return self.no_fill and self.no_stroke


def _property(e: ET.Element, name: str) -> str | None:
    """The property ``name`` as ``e`` states it: in its style, else as an attribute."""
    style = e.get("style")
    if style and name in style:
        found = None
        for part in style[:_STYLE].split(";"):
            key, sep, value = part.partition(":")
            if sep and key.strip().lower() == name:
                found = value.strip()
        if found:
            return found
    value = e.get(name)
    return value.strip() if value is not None else None


def _font_size(value: str, parent: float | None) -> float | None:
    """A ``font-size`` in user units, ``parent`` the size it inherits (None: SVG's
    medium, unsaid); the inherited size for a value that is none SVG has."""
    value = value[:100].lower()
    said, parent = parent, MEDIUM if parent is None else parent
    if value in _KEYWORDS:
        return _KEYWORDS[value]
    if value in ("smaller", "larger"):
        return parent / 1.2 if value == "smaller" else parent * 1.2
    m = _SIZE.fullmatch(value)
    if m is None:
        return said
    number, unit = float(m[1]), m[2]
    if unit == "%":
        size = parent * number / 100.0
    elif unit in ("em", "ex"):
        size = parent * number * (1.0 if unit == "em" else 0.5)
    else:
        size = number * PX[unit]
    return size if math.isfinite(size) and 0.0 < size <= _LARGEST else said


def _marker(value: str | None, before: bool) -> bool:
    if value is None:
        return before
    return value.strip().lower() not in ("", "none")


def inherit(e: ET.Element, outer: Inherited) -> Inherited:
    """What ``e`` states of its presentation, over what it inherits from ``outer``.

    >>> g = inherit(ET.fromstring('<g font-size="10" fill="none"/>'), Inherited())
    >>> r = inherit(ET.fromstring('<rect style="stroke:none;font-size:50%"/>'), g)
    >>> r.size, r.unseen, inherit(ET.fromstring('<path stroke="red"/>'), r).unseen
    (5.0, True, False)
    """
    out = outer
    size = _property(e, "font-size")
    if size:
        out = replace(out, size=_font_size(size, out.size))
    for name in ("fill", "stroke"):
        paint = _property(e, name)
        if paint:
            out = replace(out, **{f"no_{name}": paint.lower() == "none"})
    anchor = _property(e, "text-anchor")
    if anchor:
        out = replace(out, anchor=_ANCHORS.get(anchor.lower(), out.anchor))
    every = _property(e, "marker")
    start, end = (_marker(every, m) for m in out.marked)
    start = _marker(_property(e, "marker-start"), start)
    end = _marker(_property(e, "marker-end"), end)
    if (start, end) != out.marked:
        out = replace(out, marked=(start, end))
    return out


def first_letter(text: ET.Element, svg: str) -> list[ET.Element]:
    """The ``<text>`` element and the tspans (of the namespace ``svg``) that hold its first
    letter that is not a space, outermost first: their x, y, dx and dy place it, and the
    innermost's font size is its. Only the text itself when it holds no letter.

    >>> t = ET.fromstring('<text><tspan> </tspan><tspan x="5"><tspan>a</tspan>b</tspan>'
    ...                   '</text>')
    >>> [e.get("x") for e in first_letter(t, "")]
    [None, '5', None]
    """
    def walk(e: ET.Element, chain: list[ET.Element]) -> list[ET.Element] | None:
        chain = chain + [e]
        if (e.text or "").strip():
            return chain
        for child in e:
            if child.tag in (f"{{{svg}}}tspan" if svg else "tspan", "tspan"):
                found = walk(child, chain)
                if found:
                    return found
            elif "".join(child.itertext()).strip():
                return chain
            if (child.tail or "").strip():
                return chain
        return None
    return walk(text, []) or [text]
