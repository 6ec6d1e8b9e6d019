"""The few SVG elements the grading's sheets draw (an overlay, feedback, a class summary),
built with the standard library's ElementTree the way svgwrite builds them.

svgwrite loads its whole SVG grammar, and the urllib and email modules it pulls in, on
import: most of the time ``tarsim grade`` spends before it reads a drawing. These
drawings need a drawing, groups, lines, circles, rectangles, polygons, paths and text,
so this module gives those, with svgwrite's calls and svgwrite's bytes: keyword
attributes lose a trailing underscore and turn inner underscores to hyphens
(``stroke_width``), values are written as ``str`` gives them, and each element's
attributes are set in name order, an empty one left out.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from typing import Any

__all__ = ["Drawing", "Element"]

_NAMESPACES = {"xmlns": "http://www.w3.org/2000/svg",
               "xmlns:ev": "http://www.w3.org/2001/xml-events",
               "xmlns:xlink": "http://www.w3.org/1999/xlink"}


def _spaced(values) -> str:
    """A list of numbers as an attribute holds it: each as ``str`` writes it, spaced."""
    return " ".join(str(v) for v in values if v is not None)


class Element:
    """An SVG element: its attributes, its children and its text."""

    def __init__(self, tag: str, content: str | None = None, **attrs: Any):
        self.tag, self.content = tag, content
        self.attribs: dict[str, Any] = {}
        self.elements: list[Element] = []
        self.update(attrs)

    def update(self, attrs: dict[str, Any]) -> None:
        """Set attributes given as keywords: ``class_`` is ``class``, ``font_size``
        ``font-size``."""
        for key, value in attrs.items():
            self.attribs[key.rstrip("_").replace("_", "-")] = value

    def __setitem__(self, key: str, value: Any) -> None:
        self.attribs[key] = value

    def add(self, element: Element) -> Element:
        """Append ``element`` and return it."""
        self.elements.append(element)
        return element

    def xml(self) -> ET.Element:
        """The element as ElementTree holds it."""
        out = ET.Element(self.tag)
        for key, value in sorted(self.attribs.items()):
            if value is not None and str(value):
                out.set(key, str(value))
        if self.content is not None:
            out.text = str(self.content)
        out.extend(e.xml() for e in self.elements)
        return out


class Drawing(Element):
    """An SVG document (``svgwrite.Drawing``'s calls); ``tostring`` writes it."""

    def __init__(self, size: tuple[str, str] = ("100%", "100%"), profile: str = "full",
                 debug: bool = False, **attrs: Any):
        super().__init__("svg", **attrs)
        self.profile = profile
        self["width"], self["height"] = size
        self.add(Element("defs"))

    def tostring(self) -> str:
        """The document, its root declaring SVG 1.1's namespaces."""
        self.attribs.update(_NAMESPACES)
        self.attribs.update({"baseProfile": self.profile, "version": "1.1"})
        return ET.tostring(self.xml(), encoding="unicode")

    @staticmethod
    def g(**attrs: Any) -> Element:
        """A group."""
        return Element("g", **attrs)

    @staticmethod
    def path(d: str = "", **attrs: Any) -> Element:
        """A path of commands ``d``."""
        return Element("path", d=d, **attrs)

    @staticmethod
    def line(start=(0, 0), end=(0, 0), **attrs: Any) -> Element:
        """A straight line from ``start`` to ``end``."""
        return Element("line", x1=start[0], y1=start[1], x2=end[0], y2=end[1], **attrs)

    @staticmethod
    def circle(center=(0, 0), r=1, **attrs: Any) -> Element:
        """A circle about ``center``."""
        return Element("circle", cx=center[0], cy=center[1], r=r, **attrs)

    @staticmethod
    def rect(insert=(0, 0), size=(1, 1), **attrs: Any) -> Element:
        """A rectangle from its corner ``insert``."""
        return Element("rect", x=insert[0], y=insert[1], width=size[0], height=size[1],
                       **attrs)

    @staticmethod
    def polygon(points=(), **attrs: Any) -> Element:
        """A closed polygon through ``points``."""
        return Element("polygon", points=" ".join("%s,%s" % (x, y) for x, y in points),
                       **attrs)

    @staticmethod
    def text(text: str, insert=None, **attrs: Any) -> Element:
        """A text set at ``insert``."""
        if insert is not None:
            attrs.update(x=_spaced([insert[0]]), y=_spaced([insert[1]]))
        return Element("text", text, **attrs)
