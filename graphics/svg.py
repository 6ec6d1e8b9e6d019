"""Write a :class:`~graphics.figure.Figure` as SVG, byte-identical per input.

The page is sized in millimetres with a matching viewBox, so one user unit is one
millimetre on the printed page and a scale bar measures true with a ruler. Only
the subset cairosvg renders faithfully is used: plain paths, circles and text,
with arrowheads and hatching drawn as geometry rather than markers or patterns.

The elements are built by :mod:`.svg_tree`, on the standard library's ElementTree, as
svgwrite writes them: the same bytes, without the import of svgwrite's SVG grammar (and
the urllib and email it pulls in) on every solve.
"""

from __future__ import annotations

import re

from .figure import (FONT, PAGE_GAP, STYLES, SUB_DROP, SUB_SIZE, Circle, Figure, Path, Style,
                     Text, stack_layout)
from .rtl import RTL_FONT, flip_anchor, is_rtl
from .rtl_runs import lay_runs
from .svg_tree import Drawing, Element

__all__ = ["to_svg", "stacked_svg", "style_attributes", "text_attributes", "TEXT_ATTRIBUTES",
           "tspans", "runs", "coordinate"]

TEXT_ATTRIBUTES = {"font-family": FONT, "fill": "#000"}
"""What every text is written in, unless it says otherwise (a right-to-left face)."""


def _n(v: float) -> str:
    text = f"{v:.3f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def coordinate(v: float) -> str:
    """A length on paper (mm) as the SVG writes it: to a micrometre, no trailing zeros.

    >>> coordinate(12.34049), coordinate(-0.0001), coordinate(3.0)
    ('12.34', '0', '3')
    """
    return _n(v)


def style_attributes(style: Style) -> dict[str, str]:
    """The SVG attributes a primitive of ``style`` is written with: its fill, and its
    stroke, width, caps, joins and dashes (or none)."""
    a = {"fill": style.fill or "none"}
    if style.stroke:
        a.update({"stroke": style.stroke, "stroke-width": _n(style.width),
                  "stroke-linecap": style.cap, "stroke-linejoin": style.join})
        if style.dash:
            a["stroke-dasharray"] = ",".join(_n(d) for d in style.dash)
    else:
        a["stroke"] = "none"
    return a


def to_svg(fig: Figure) -> str:
    """Return the figure as an SVG document (a string).

    Examples
    --------
    >>> from tarsim.graphics.figure import Figure, Text
    >>> f = Figure(20, 10)
    >>> f.add(Text((10, 5), "A"))
    >>> to_svg(f).count("<text")
    1
    >>> f.add(Text((10, 5), "V", sub="A"))
    >>> '<tspan dy="0.98" font-size="2.52">A</tspan>' in to_svg(f)
    True
    """
    width, height = _n(fig.width), _n(fig.height)
    dwg = Drawing(size=(f"{width}mm", f"{height}mm"), viewBox=f"0 0 {width} {height}")
    if fig.title:
        dwg.elements.insert(0, Element("title", fig.title))     # before the defs
    dwg.add(dwg.rect((0, 0), (width, height), fill="#fff"))
    current = None
    for item in fig.items:
        key = "text" if isinstance(item, Text) else item.style
        if current is None or current[0] != key:
            attrs = {"class": key}
            if key == "text":
                attrs.update(TEXT_ATTRIBUTES)
            else:
                attrs.update(style_attributes(STYLES[key]))
            current = (key, dwg.add(Element("g", **attrs)))
        current[1].add(_element(item))
    return dwg.tostring()


def stacked_svg(pages: list[Figure], svgs: list[str], gap: float = PAGE_GAP) -> str:
    """The sheet :func:`~graphics.figure.stack_pages` sets ``pages`` on, written from their
    SVG documents (``svgs``, in order): each page's drawing is moved into place whole, not
    drawn and written again, so a solution's figures are written once."""
    width, height, tops = stack_layout(pages, gap)
    rules = Figure(width, height, title=pages[0].title)
    for top in tops[1:]:
        rules.line((0.0, top - gap / 2), (width, top - gap / 2), "page_rule")
    moved = "".join(f'<g transform="translate(0,{_n(top)})">{_drawing(svg)}</g>'
                    for top, svg in zip(tops, svgs))
    return to_svg(rules).removesuffix("</svg>") + moved + "</svg>"


def _drawing(svg: str) -> str:
    """What :func:`to_svg` drew on a page: its document less the root, title and defs."""
    return svg[svg.index("<defs />") + len("<defs />"):svg.rindex("</svg>")]


def _element(item: Path | Circle | Text) -> Element:
    if isinstance(item, Path):
        d = "M" + " L".join(f"{_n(x)},{_n(y)}" for x, y in item.points)
        return Element("path", d=d + " Z" if item.closed else d)
    if isinstance(item, Circle):
        return Drawing.circle((_n(item.centre[0]), _n(item.centre[1])), _n(item.radius))
    if (parts := runs(item)) is not None:
        group = Element("g")
        group.elements.extend(_element(run) for run in parts)
        return group
    text = Element("text", item.text, **text_attributes(item))
    for words, size, dy in tspans(item):
        text.add(Element("tspan", words, **{"dy": _n(dy), "font-size": _n(size)}))
    return text


def text_attributes(item: Text) -> dict[str, str]:
    """The attributes a text of one direction is written with: where it is set (x, y),
    its size and anchor, and its face where it is not the figure's upright serif."""
    x, y, anchor = text_origin(item)
    attrs = {"x": _n(x), "y": _n(y), "font-size": _n(item.size), "text-anchor": anchor}
    if is_rtl(item.text + item.sub + item.tail):
        # Persian: laid right to left by the viewer, in a face with its glyphs; the anchor
        # turned so the label keeps its box.
        attrs.update({"direction": "rtl", "font-family": RTL_FONT,
                      "text-anchor": flip_anchor(anchor)})
    elif item.italic:
        attrs["font-style"] = "italic"
    if item.weight != "normal":
        attrs["font-weight"] = item.weight
    return attrs


def tspans(item: Text) -> list[tuple[str, float, float]]:
    """What follows a text on its line, each part set after the last: its subscript,
    smaller and dropped, then its tail back on the baseline; as (text, font size, the
    drop from the part before). cairosvg ignores baseline-shift, so the drop is a dy."""
    parts = []
    if item.sub:
        parts.append((item.sub, SUB_SIZE * item.size, SUB_DROP * item.size))
    if item.tail:
        parts.append((item.tail, item.size, -SUB_DROP * item.size if item.sub else 0.0))
    return parts


def runs(item: Text) -> list[Text] | None:
    """A right-to-left label with a subscript ("V_B به روش دوران شعاع") as the runs of one
    direction each it is set as (:func:`~.rtl_runs.lay_runs`): the words before the symbol,
    the symbol with its subscript (and a prime after it: F_i3′), then the tail. None for
    any other text, which is set as it is."""
    if not ((item.sub or item.tail) and is_rtl(item.text + item.sub + item.tail)):
        return None
    symbol = item.text[-1:] if item.sub and not is_rtl(item.text[-1:]) else ""
    mark = re.match("[′″ᵗⁿᶜ]*", item.tail).group()
    parts = [(item.text[:len(item.text) - len(symbol)], "", ""), (symbol, item.sub, mark),
             (item.tail[len(mark):], "", "")]
    return lay_runs(item.at, parts, item.size, item.anchor, item.italic, item.weight)


def text_origin(item: Text) -> tuple[float, float, str]:
    """Where a text of one direction is set: the x its anchor stands at, its baseline's y
    (``at`` is the visual centre line; the baseline sits 0.35 em below it) and its anchor.
    cairosvg anchors a text by its own characters and ignores its tspans', so a
    subscripted label is set from its computed left end."""
    x, y = item.at[0], item.at[1] + 0.35 * item.size
    if (item.sub or item.tail) and item.anchor != "start":
        return x - (item.width / 2 if item.anchor == "middle" else item.width), y, "start"
    return x, y, item.anchor
