"""A drawing's XML parsed with no trust: no entity is expanded and nothing is loaded.

defusedxml refuses entities and anything external. A DOCTYPE is read past when it only
names a DTD (as LibreOffice's ordinary export names SVG 1.1's): expat loads no external
subset here, so naming one costs nothing. A DOCTYPE whose subset declares anything (an
element, an attribute's default, a notation, a parameter entity's use) is refused: a
drawing needs none, and a default could put any attribute on its elements.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from tarsim.constructions.errors import InputError

__all__ = ["parse_xml"]


def parse_xml(data: bytes, name: str) -> tuple[ET.Element, dict[ET.Element, int]]:
    r"""The XML tree of the drawing ``data`` (the file ``name``), and each element's line.

    Raises
    ------
    InputError
        Naming the file: an entity, a DOCTYPE that declares anything, XML that cannot be
        read (at its line), an encoding Python does not know.

    Examples
    --------
    >>> root, lines = parse_xml(b'<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "x.dtd">'
    ...                         b'<svg>\n<g/></svg>', "s.svg")
    >>> [(e.tag, lines[e]) for e in root.iter()]
    [('svg', 1), ('g', 2)]
    """
    from defusedxml import DefusedXmlException, DTDForbidden
    from defusedxml.ElementTree import DefusedXMLParser

    lines: dict[ET.Element, int] = {}
    parser = DefusedXMLParser(target=ET.TreeBuilder(), forbid_dtd=False, forbid_entities=True,
                              forbid_external=True)
    expat = parser.parser

    def declared(*_):
        raise DTDForbidden(None, None, None)
    expat.ElementDeclHandler = expat.AttlistDeclHandler = declared
    expat.NotationDeclHandler = expat.SkippedEntityHandler = declared
    inside, other = [False], expat.DefaultHandlerExpand

    def rest(text):                           # a DOCTYPE's subset holds spaces at most
        if inside[0] and text.strip():
            declared()
        other(text)
    expat.DefaultHandlerExpand = rest
    expat.StartDoctypeDeclHandler = lambda *_: inside.__setitem__(0, True)
    expat.EndDoctypeDeclHandler = lambda: inside.__setitem__(0, False)
    start = expat.StartElementHandler

    def started(tag, attributes):
        element = start(tag, attributes)
        lines[element] = expat.CurrentLineNumber
        return element
    expat.StartElementHandler = started
    try:
        parser.feed(data)
        root = parser.close()
    except DefusedXmlException:
        raise InputError("the SVG declares a DTD, entities or external resources, which a "
                         "drawing never needs; export it again as plain SVG",
                         file=name) from None
    except ET.ParseError as e:
        line, column = e.position
        why = str(e).split(":")[0]
        raise InputError(f"not an SVG drawing: its XML is broken at column {column} ({why})",
                         file=name, line=line) from None
    except LookupError as e:                  # an encoding Python does not know
        raise InputError(f"not an SVG drawing: {e}; save it as UTF-8", file=name) from None
    return root, lines
