"""A figure's drawn elements in order, as an SVG document writes them and as the page's
data holds them: the one list both are held to."""

from __future__ import annotations

import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"


def svg_leaves(svg: str) -> list[tuple]:
    """The drawn elements of an SVG document in order: a path's d, a circle's centre and
    radius, a text's place, size, anchor, face, words and tspans (words, dy, size)."""
    out = []
    for el in ET.fromstring(svg).iter():
        tag = el.tag.removeprefix(SVG)
        if tag == "path":
            out.append(("path", el.get("d")))
        elif tag == "circle":
            out.append(("circle", el.get("cx"), el.get("cy"), el.get("r")))
        elif tag == "text":
            out.append(("text", el.get("x"), el.get("y"), el.get("font-size"),
                        el.get("text-anchor"), el.get("direction"), el.get("font-style"),
                        el.get("font-weight"), el.text,
                        tuple((t.text, t.get("dy"), t.get("font-size")) for t in el)))
    return out


PAGE_LEAVES = """() => [...document.querySelectorAll('#sheet [data-i]')].flatMap(el => {
  const a = k => el.getAttribute(k);
  if (el.tagName === 'path') return [['path', a('d')]];
  if (el.tagName === 'circle') return [['circle', a('cx'), a('cy'), a('r')]];
  return [...el.querySelectorAll('text')].map(t => {
    const b = k => t.getAttribute(k);
    return ['text', b('x'), b('y'), b('font-size'), b('text-anchor'), b('direction'),
            b('font-style'), b('font-weight'), t.firstChild ? t.firstChild.nodeValue : null,
            [...t.querySelectorAll('tspan')].map(s => [s.textContent, s.getAttribute('dy'),
                                                       s.getAttribute('font-size')])];
  });
})"""
"""The same, read from the page's figure in the browser (a list per element, for JSON)."""


def as_tuples(leaves: list) -> list[tuple]:
    """Leaves read from the page, as :func:`svg_leaves` gives them."""
    return [tuple(tuple(tuple(s) for s in v) if isinstance(v, list) else v for v in leaf)
            for leaf in leaves]
