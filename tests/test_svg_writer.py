"""The SVG writer builds its elements with ElementTree; svgwrite, which wrote them before
(and still writes the grading's overlays), is the reference the bytes are held to."""

from __future__ import annotations

import svgwrite

from tarsim.graphics.figure import STYLES, Circle, Figure, Path, Text
from tarsim.graphics.svg import (TEXT_ATTRIBUTES, runs, style_attributes, text_attributes,
                                 to_svg, tspans)


def _by_svgwrite(fig: Figure) -> str:
    """The figure as svgwrite writes it, element for element as to_svg lays it out."""
    n = "{:.3f}"

    def num(v: float) -> str:
        t = n.format(v).rstrip("0").rstrip(".")
        return "0" if t in ("-0", "") else t

    dwg = svgwrite.Drawing(size=(f"{num(fig.width)}mm", f"{num(fig.height)}mm"),
                           viewBox=f"0 0 {num(fig.width)} {num(fig.height)}", profile="full",
                           debug=False)
    if fig.title:
        dwg.set_desc(title=fig.title)
    dwg.add(dwg.rect((0, 0), (num(fig.width), num(fig.height)), fill="#fff"))

    def element(item):
        if isinstance(item, Path):
            d = "M" + " L".join(f"{num(x)},{num(y)}" for x, y in item.points)
            return dwg.path(d=d + (" Z" if item.closed else ""))
        if isinstance(item, Circle):
            return dwg.circle((num(item.centre[0]), num(item.centre[1])), num(item.radius))
        if (parts := runs(item)) is not None:
            group = dwg.g()
            for run in parts:
                group.add(element(run))
            return group
        attrs = text_attributes(item)
        attrs.update({"x": [attrs["x"]], "y": [attrs["y"]]})
        text = dwg.text(item.text, **attrs)
        for words, size, dy in tspans(item):
            text.add(dwg.tspan(words, dy=[num(dy)], font_size=num(size)))
        return text

    current = None
    for item in fig.items:
        key = "text" if isinstance(item, Text) else item.style
        if current is None or current[0] != key:
            attrs = {"class": key, **(TEXT_ATTRIBUTES if key == "text"
                                      else style_attributes(STYLES[key]))}
            current = (key, dwg.g(**attrs))
            dwg.add(current[1])
        current[1].add(element(item))
    return dwg.tostring()


def _figure(title: str) -> Figure:
    fig = Figure(123.4567, 80.0, title=title)
    fig.add(Path(((1.0, 2.0), (30.25, -0.00001), (50.0, 60.5)), "link"))
    fig.add(Path(((5.0, 5.0), (9.0, 5.0), (7.0, 9.0)), "ground", closed=True))
    fig.add(Circle((40.0, 40.0), 1.2345, "pin"))
    fig.add(Path(((0.0, 0.0), (10.0, 10.0)), "kennedy"))      # dashed
    fig.add(Text((20.0, 20.0), "A"))
    fig.add(Text((30.0, 25.0), "V", sub="B", tail=" by radius rotation & <parallel>",
                 anchor="start", italic=False, weight="bold"))
    fig.add(Text((60.0, 30.0), "V", sub="B", tail=" به روش دوران شعاع"))     # runs
    fig.add(Text((70.0, 50.0), "مقیاس ۱ سانتی‌متر = ۲۰ میلی‌متر", anchor="end"))
    fig.add(Path(((2.0, 2.0), (3.0, 3.0)), "link"))           # a second group of a style
    return fig


def test_every_kind_of_element_is_written_as_svgwrite_writes_it():
    for title in ("Four-bar: V_B & the <worked> page", ""):
        fig = _figure(title)
        assert to_svg(fig) == _by_svgwrite(fig)
