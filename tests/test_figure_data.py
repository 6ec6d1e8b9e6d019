"""A figure as the page's data (graphics/figure_data.py) and what its primitives stand on
(graphics/figure_anchors.py).

The data is held to the SVG the same figure is written as: element for element, the same
numbers as the same characters, so that the page, which writes the data out as it comes,
draws what `tarsim solve` writes. What a primitive stands on is held to the figure drawn
at another position: the template, moved with the named points it stands on, is that
drawing, symbol for symbol.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest

from tarsim.constructions.linkages.assembly import assemble
from tarsim.constructions.linkages.kennedy import locate_centres
from tarsim.constructions.record import Slice
from tarsim.graphics.figure_anchors import anchors
from tarsim.graphics.figure_data import figure_data, style_data
from tarsim.graphics.figure import STYLES, Circle, Path
from tarsim.graphics.linkages.scene import draw_scene
from tarsim.graphics.svg import to_svg
from tests.common import crank_shaper, four_bar
from tests.figure_leaves import SVG, svg_leaves


def _centres(mech):
    cs = locate_centres(assemble(mech))
    return draw_scene(Slice(cs.assembly, tuple(cs.construction_refs())), title="centres"), cs


def _data_leaves(data: dict) -> list[tuple]:
    """The same, from the figure's data, printed as the page prints a JSON number."""
    def s(v):
        return str(v)

    out = []
    for kind, _, g, *_ in data["items"]:
        if kind in "pz":
            pairs = [f"{s(g[i])},{s(g[i + 1])}" for i in range(0, len(g), 2)]
            out.append(("path", "M" + " L".join(pairs) + (" Z" if kind == "z" else "")))
        elif kind == "c":
            out.append(("circle", *map(s, g)))
        else:
            for x, y, size, anchor, face, text, spans in g:
                out.append(("text", s(x), s(y), s(size), anchor,
                            "rtl" if "r" in face else None, "italic" if "i" in face else None,
                            "bold" if "b" in face else None, text,
                            tuple((t, s(dy), s(sz)) for t, sz, dy in spans)))
    return out


@pytest.mark.parametrize("lang", ["en", "fa"])
def test_the_data_is_the_svg_element_for_element(lang):
    """Every primitive of a centres figure, in English and in Persian (whose words are set
    right to left, some in runs), is the element the SVG writer writes, in order, with the
    same numbers written the same way."""
    from tarsim.constructions.narration import speaking

    with speaking(lang):
        fig, _ = _centres(crank_shaper(math.radians(30)))
    data = figure_data(fig)
    assert _data_leaves(data) == svg_leaves(to_svg(fig))
    assert len(data["items"]) == len(fig.items)
    assert data["views"]["space"] == [fig.views["space"].scale, *fig.views["space"].origin]


def test_each_style_is_named_once_as_the_svg_writes_it():
    """A style's data is the attributes the SVG writer gives its group."""
    fig, _ = _centres(four_bar(math.radians(60)))
    used = {it.style for it in fig.items if not hasattr(it, "text")}
    styles = style_data(used)
    groups = {g.get("class"): g.attrib for g in ET.fromstring(to_svg(fig)).iter(f"{SVG}g")
              if g.get("class") in used}
    assert set(groups) == used
    for name, attrs in groups.items():
        assert styles[name] == {k: v for k, v in attrs.items() if k != "class"}, name
    assert styles["text"]["font-family"] == "DejaVu Serif"
    assert set(styles) == used | {"text"} and used <= set(STYLES)


def _named(mech, cs) -> dict:
    asm = cs.assembly
    points = {n: asm.xy(n) for n in mech.point_names}
    for c in cs.primaries + cs.secondaries:
        p = cs.point(*c.pair)
        points[c.label] = None if p.is_at_infinity else p.xy
    return points


def _moved(v, b, now, was):
    """A point as the page moves it (graphics/page/view.js, carry)."""
    a, q, r = b
    turn = 0.0
    if q >= 0:
        turn = (math.atan2(now[r][1] - now[q][1], now[r][0] - now[q][0])
                - math.atan2(was[r][1] - was[q][1], was[r][0] - was[q][0]))
    dx, dy = v[0] - was[a][0], v[1] - was[a][1]
    return (now[a][0] + math.cos(turn) * dx - math.sin(turn) * dy,
            now[a][1] + math.sin(turn) * dx + math.cos(turn) * dy)


@pytest.mark.parametrize("make, at, later, styles", [
    (crank_shaper, 30.0, 75.0, ("block", "pin", "link")),
    (crank_shaper, 200.0, 140.0, ("block", "pin", "link")),   # near the lever's limit
    (four_bar, 60.0, 100.0, ("pin", "link"))])
def test_the_template_moved_is_the_figure_drawn_there(make, at, later, styles):
    """A centres figure drawn at θ2 = ``at``, each primitive moved with the named points it
    stands on (found from the figure drawn 0.05° and 15° on) to θ2 = ``later``, is the
    figure drawn at ``later``: every block, pin and bar of the mechanism at the same place
    beside the named point it stands on, to a micrometre's thousandth (rounding: both are
    computed in double precision, and so is the move). At 200° the slotted lever all but
    stands still, and only the farther drawing tells that the block turns with it."""
    figs, named = {}, {}
    for deg in (at, at + 0.05, at + 15.0, later):
        mech = make(math.radians(deg))
        figs[deg], cs = _centres(mech)
        named[deg] = _named(mech, cs)
    names = list(named[at])
    ordered = {deg: {"space": [named[deg][n] for n in names]} for deg in named}
    stand = anchors(figs[at], [figs[at + 0.05], figs[at + 15.0]],
                    [ordered[at], ordered[at + 0.05], ordered[at + 15.0]])

    def paper(deg):
        v = figs[deg].views["space"]
        return [v(p) if p else None for p in ordered[deg]["space"]]

    now, was = paper(later), paper(at)
    checked = 0
    for style in styles:
        mine = [(it, s) for it, s in zip(figs[at].items, stand)
                if getattr(it, "style", "") == style]
        theirs = [it for it in figs[later].items if getattr(it, "style", "") == style]
        assert len(mine) == len(theirs) and mine, style
        for (it, s), there in zip(mine, theirs):
            assert s is not None, (style, it)
            points = it.points if isinstance(it, Path) else (it.centre,)
            want = there.points if isinstance(there, Path) else (there.centre,)
            triples = s[1] * len(points) if len(s[1]) == 1 else s[1]
            for p, q, b in zip(points, want, triples):
                assert math.dist(_moved(p, b, now, was), q) <= 1e-6, (style, p, q)
                checked += 1
            if isinstance(it, Circle):
                assert it.radius == there.radius
    assert checked >= 10


def test_what_nothing_carries_stands_on_nothing():
    """A caption's words and the input's angle, which change with the position, stand on
    nothing: the page shows them at the figure's own position only."""
    figs = {deg: _centres(four_bar(math.radians(deg))) for deg in (60.0, 60.05)}
    named = {deg: _named(four_bar(math.radians(deg)), cs) for deg, (_, cs) in figs.items()}
    names = list(named[60.0])
    stand = anchors(figs[60.0][0], [figs[60.05][0]],
                    [{"space": [named[d][n] for n in names]} for d in (60.0, 60.05)])
    words = {getattr(it, "text", ""): s for it, s in zip(figs[60.0][0].items, stand)}
    caption = next(t for t in words if t.startswith("θ₂ = "))
    assert words[caption] is None
    assert words["A"] is not None and words["B"] is not None      # the joints' names
