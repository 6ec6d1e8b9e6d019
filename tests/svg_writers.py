"""A sheet of marks written as SVG the way each program writes it.

A sheet is a list of marks in paper mm, y down:

- ``("line", a, b)`` and ``("line", a, b, "thin")`` for a construction line;
- ``("arrow", a, b)``: a vector from ``a`` to its tip ``b``, its head as the program draws
  one;
- ``("dot", centre, r)``, ``("circle", centre, r)`` (a hollow pin), ``("poly", points,
  closed)``;
- ``("text", anchor, runs)`` or ``("text", anchor, runs, size)``: the baseline's start, runs
  of ``(text, role)`` with role ``"sub"`` for a subscript set as the program sets one, and
  the letters' size in mm (4 by default).

Each writer lays the sheet out as its program does, read off the program's own writer or
its files:

- Inkscape 1.2: mm with a viewBox, attributes one to a line, a layer (sometimes moved, so
  translated), relative path data with ``h``/``v``, its stock ``Arrow2`` marker that the
  path ends under, texts in ``sodipodi:role="line"`` tspans with subscripts by
  ``baseline-shift:sub``, circles, rectangles, a clone (``<use>``) now and then;
- LibreOffice Draw 7 (filter/source/svg/svgwriter.cxx): hundredths of a mm, a shape class
  and a BoundingBox rect round every shape, a line with an arrow end cut short inside a
  filled arrowhead, ellipses as Béziers, each text's position on a nested
  ``TextPosition`` tspan and a subscript on a further one that carries only its ``y``; the
  SVG 1.1 DOCTYPE, or none when exported as Tiny;
- GeoGebra (its web export through canvas2svg): a pixel page at its own zoom, a clip path
  of random id, ``paint-order`` on every path, a vector's line stopping at its filled
  arrowhead's base, points as a filled and a stroked Bézier circle, every label written
  three times (fill, white halo, fill) and a subscript as a separate smaller text;
- a CAD program writing through Qt's QSvgGenerator: mm page over a pixel viewBox, the
  drawing in model units under a flipping ``matrix(k,0,0,-k,…)`` group, polylines, a solid
  arrowhead, each text placed by its own group's transform at x = y = 0;
- by hand: sometimes no namespace, a style block, polylines, single quotes, unicode
  subscripts, CRLF line ends, a marker, a rotated group turned back.
"""

from __future__ import annotations

import math
import random
import re
import string
from xml.sax.saxutils import escape

__all__ = ["WRITERS", "inkscape", "libreoffice", "geogebra", "cad", "hand", "arrowhead"]

_PX = 96.0 / 25.4
"""CSS pixels a millimetre."""

A4 = (210.0, 297.0)


def _f(v: float, digits: int = 3) -> str:
    out = f"{v:.{digits}f}".rstrip("0").rstrip(".")
    return "0" if out in ("", "-0") else out


def _size(m) -> float:
    return m[3] if len(m) > 3 else 4.0


def _plain(runs) -> str:
    """The runs as one string, a subscript in unicode subscript digits and letters."""
    sub = str.maketrans("0123456789aeoxv", "₀₁₂₃₄₅₆₇₈₉ₐₑₒₓᵥ")
    return "".join(t.translate(sub) if role == "sub" else t for t, role in runs)


def arrowhead(a, b, length: float, half: float):
    """A vector's head at ``b``, pointing from ``a``: its tip, its two corners and the
    middle of its base."""
    d = math.dist(a, b) or 1.0
    ux, uy = (b[0] - a[0]) / d, (b[1] - a[1]) / d
    base = (b[0] - length * ux, b[1] - length * uy)
    return (b, (base[0] + half * uy, base[1] - half * ux), (base[0] - half * uy,
                                                            base[1] + half * ux), base)


# ----- Inkscape 1.2 ---------------------------------------------------------------------------
def _ink_d(pts, closed=False) -> str:
    """Path data as Inkscape 1.2 writes it: relative, ``h``/``v`` for a level or plumb step."""
    out = [f"m {_f(pts[0][0])},{_f(pts[0][1])}"]
    for p, q in zip(pts, pts[1:]):
        dx, dy = q[0] - p[0], q[1] - p[1]
        out.append(f"h {_f(dx)}" if abs(dy) < 5e-5 else f"v {_f(dy)}" if abs(dx) < 5e-5
                   else f"{_f(dx)},{_f(dy)}")
    return " ".join(out) + (" z" if closed else "")


def inkscape(rng: random.Random, marks: list, page=A4) -> str:
    """As Inkscape 1.2 saves an Inkscape SVG."""
    w, h = page
    tx, ty = rng.choice([(0.0, 0.0), (0.0, 0.0), (round(rng.uniform(-60, 60), 3),
                                                     round(rng.uniform(-60, 60), 3))])
    n = rng.randrange(100, 900)
    stroke = "stroke:#000000;stroke-width:0.264583px;stroke-linecap:butt;stroke-linejoin:" \
             "miter;stroke-opacity:1"

    def at(p):
        return (p[0] - tx, p[1] - ty)
    body = []
    for m in marks:
        n += 7
        if m[0] in ("line", "arrow"):
            thin = len(m) > 3 and m[3] == "thin"
            style = ("fill:none;stroke:#808080;stroke-width:0.15;stroke-dasharray:1.2,0.6"
                     if thin else "fill:none;" + stroke
                     + (";marker-end:url(#Arrow2)" if m[0] == "arrow" else ""))
            d = _ink_d([at(m[1]), at(m[2])])
            body.append(f'    <path\n       style="{style}"\n       d="{d}"\n'
                        f'       id="path{n}" />')
            if rng.random() < 0.03:                # a clone of it, left where it was
                body.append(f'    <use\n       x="0"\n       y="0"\n       xlink:href="#path{n}"'
                            f'\n       id="use{n + 1}" />')
        elif m[0] in ("dot", "circle"):
            fill = "fill:#000000;stroke:none" if m[0] == "dot" else \
                "fill:none;stroke:#000000;stroke-width:0.3"
            c = at(m[1])
            body.append(f'    <circle\n       style="{fill}"\n       id="path{n}"\n       '
                        f'cx="{_f(c[0])}"\n       cy="{_f(c[1])}"\n       r="{_f(m[2])}" />')
        elif m[0] == "poly":
            pts = [at(p) for p in m[1]]
            if m[2] and len(pts) == 4 and abs(pts[0][1] - pts[1][1]) < 1e-9 and \
                    abs(pts[1][0] - pts[2][0]) < 1e-9:
                x0, y0 = min(p[0] for p in pts), min(p[1] for p in pts)
                body.append(f'    <rect\n       style="fill:none;{stroke}"\n       id="rect{n}"'
                            f'\n       width="{_f(max(p[0] for p in pts) - x0)}"\n       '
                            f'height="{_f(max(p[1] for p in pts) - y0)}"\n       x="{_f(x0)}"'
                            f'\n       y="{_f(y0)}" />')
            else:
                body.append(f'    <path\n       style="fill:none;{stroke}"\n       '
                            f'd="{_ink_d(pts, m[2])}"\n       id="path{n}" />')
        else:
            (x, y), size = at(m[1]), _size(m)
            runs = "".join(escape(t) if not role else
                           f'<tspan\n         style="font-size:65%;baseline-shift:sub"\n'
                           f'         id="tspan{n + 3}">{escape(t)}</tspan>'
                           for t, role in m[2])
            body.append(f'    <text\n       xml:space="preserve"\n       style="font-size:'
                        f'{_f(size)}px;line-height:1.25;font-family:sans-serif;stroke-width:'
                        f'0.264583"\n       x="{_f(x)}"\n       y="{_f(y)}"\n       id="text{n}">'
                        f'<tspan\n         sodipodi:role="line"\n         id="tspan{n + 1}"\n'
                        f'         style="stroke-width:0.264583"\n         x="{_f(x)}"\n'
                        f'         y="{_f(y)}">{runs}</tspan></text>')
    layer = f'\n     transform="translate({_f(tx)},{_f(ty)})"' if (tx, ty) != (0, 0) else ""
    return (
        '<?xml version="1.0" encoding="UTF-8" standalone="no"?>\n'
        "<!-- Created with Inkscape (http://www.inkscape.org/) -->\n\n<svg\n"
        f'   width="{_f(w)}mm"\n   height="{_f(h)}mm"\n   viewBox="0 0 {_f(w)} {_f(h)}"\n'
        '   version="1.1"\n   id="svg5"\n   inkscape:version="1.2.2 (b0a8486541, 2022-12-01)"\n'
        '   sodipodi:docname="polygons.svg"\n'
        '   xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"\n'
        '   xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd"\n'
        '   xmlns:xlink="http://www.w3.org/1999/xlink"\n'
        '   xmlns="http://www.w3.org/2000/svg"\n   xmlns:svg="http://www.w3.org/2000/svg">\n'
        '  <sodipodi:namedview\n     id="namedview7"\n     pagecolor="#ffffff"\n'
        '     bordercolor="#000000"\n     borderopacity="0.25"\n     inkscape:showpageshadow="2"'
        '\n     inkscape:pageopacity="0.0"\n     inkscape:pagecheckerboard="0"\n'
        '     inkscape:deskcolor="#d1d1d1"\n     inkscape:document-units="mm"\n'
        '     showgrid="false"\n     inkscape:zoom="0.72"\n     inkscape:cx="396.5"\n'
        '     inkscape:cy="561.1"\n     inkscape:current-layer="layer1" />\n'
        '  <defs\n     id="defs2">\n    <marker\n       style="overflow:visible"\n'
        '       id="Arrow2"\n       refX="0"\n       refY="0"\n       orient="auto-start-reverse"'
        '\n       inkscape:stockid="Arrow2"\n       markerWidth="7.7"\n'
        '       markerHeight="5.5999999"\n       viewBox="0 0 7.7 5.6"\n'
        '       inkscape:isstock="true"\n       inkscape:collect="always"\n'
        '       preserveAspectRatio="xMidYMid">\n      <path\n         transform="scale(0.7)"'
        '\n         d="M -2,-4 9,0 -2,4 c 2,-2.33 2,-5.66 0,-8 z"\n'
        '         style="fill:context-stroke;fill-rule:evenodd;stroke:none"\n'
        '         id="arrow2L" />\n    </marker>\n  </defs>\n  <g\n     inkscape:label="Layer 1"\n'
        f'     inkscape:groupmode="layer"\n     id="layer1"{layer}>\n'
        + "\n".join(body) + "\n  </g>\n</svg>\n")


# ----- LibreOffice Draw 7 ---------------------------------------------------------------------
def libreoffice(rng: random.Random, marks: list, page=A4) -> str:
    """As LibreOffice Draw 7 exports a page to SVG (its DOCTYPE, unless exported as SVG
    Tiny)."""
    tiny = rng.random() < 0.4

    def h(v):
        return str(round(v * 100))

    def pts(ps):
        return " ".join(f"{h(x)},{h(y)}" for x, y in ps)

    def shape(kind: str, n: int, inner: str, box) -> str:
        x0, y0 = min(p[0] for p in box), min(p[1] for p in box)
        x1, y1 = max(p[0] for p in box), max(p[1] for p in box)
        return (f'<g class="com.sun.star.drawing.{kind}">\n <g id="id{n}">\n  <rect '
                f'class="BoundingBox" stroke="none" fill="none" x="{h(x0)}" y="{h(y0)}" '
                f'width="{h(x1 - x0 + 0.01)}" height="{h(y1 - y0 + 0.01)}"/>\n  {inner}\n '
                "</g>\n</g>")
    body = []
    for n, m in enumerate(marks, 3):
        if m[0] in ("line", "arrow"):
            a, b = m[1], m[2]
            colour = "rgb(128,128,128)" if len(m) > 3 and m[3] == "thin" else "rgb(0,0,0)"
            box = [a, b]
            if m[0] == "arrow":
                tip, left, right, base = arrowhead(a, b, 3.0, 1.05)
                # The line ends inside its arrowhead, which is drawn as a filled polygon.
                end = ((base[0] + tip[0]) / 2, (base[1] + tip[1]) / 2)
                inner = (f'<path fill="none" stroke="{colour}" d="M {pts([a])} L {pts([end])}"/>'
                         f'\n  <path fill="{colour}" stroke="none" d="M {pts([left, tip, right])}'
                         f' {pts([left])} Z"/>')
                box += [left, right]
            else:
                inner = f'<path fill="none" stroke="{colour}" d="M {pts([a])} L {pts([b])}"/>'
            body.append(shape("LineShape", n, inner, box))
        elif m[0] in ("dot", "circle"):
            (cx, cy), r = m[1], m[2]
            k = 0.5523 * r
            d = (f"M {h(cx)},{h(cy - r)} C {h(cx + k)},{h(cy - r)} {h(cx + r)},{h(cy - k)} "
                 f"{h(cx + r)},{h(cy)} C {h(cx + r)},{h(cy + k)} {h(cx + k)},{h(cy + r)} "
                 f"{h(cx)},{h(cy + r)} C {h(cx - k)},{h(cy + r)} {h(cx - r)},{h(cy + k)} "
                 f"{h(cx - r)},{h(cy)} C {h(cx - r)},{h(cy - k)} {h(cx - k)},{h(cy - r)} "
                 f"{h(cx)},{h(cy - r)} Z")
            paint = 'fill="rgb(0,0,0)" stroke="none"' if m[0] == "dot" else \
                'fill="none" stroke="rgb(0,0,0)"'
            body.append(shape("EllipseShape", n, f'<path {paint} d="{d}"/>',
                              [(cx - r, cy - r), (cx + r, cy + r)]))
        elif m[0] == "poly":
            ps = list(m[1]) + ([m[1][0]] if m[2] else [])
            kind = "PolyPolygonShape" if m[2] else "PolyLineShape"
            body.append(shape(kind, n, f'<path fill="none" stroke="rgb(0,0,0)" d="M '
                              f'{pts(ps[:1])} L {pts(ps[1:])}"/>', ps))
        else:
            (x, y), size = m[1], _size(m)
            font = round(size * 100)
            spans = []
            for k, (t, role) in enumerate(m[2]):
                if role == "sub":                   # a subscript: a new line's y, no x
                    spans.append(f'<tspan class="TextPosition" y="{h(y + 0.33 * size)}">'
                                 f'<tspan font-size="{round(font * 0.58)}px" fill="rgb(0,0,0)" '
                                 f'stroke="none" style="white-space: pre">{escape(t)}</tspan>'
                                 "</tspan>")
                elif k == 0 or m[2][k - 1][1] != "sub":
                    spans.append(f'<tspan class="TextPosition" x="{h(x)}" y="{h(y)}"><tspan '
                                 'fill="rgb(0,0,0)" stroke="none" style="white-space: pre">'
                                 f"{escape(t)}</tspan></tspan>")
                else:                               # back on the baseline after it
                    spans.append(f'<tspan class="TextPosition" y="{h(y)}"><tspan fill="rgb(0,'
                                 f'0,0)" stroke="none" style="white-space: pre">{escape(t)}'
                                 "</tspan></tspan>")
            inner = ('<text class="SVGTextShape"><tspan class="TextParagraph" font-family='
                     f'"Liberation Serif, serif" font-size="{font}px" font-style="italic" '
                     f'font-weight="400">{"".join(spans)}</tspan></text>')
            wide = 0.6 * size * len(_plain(m[2]))
            body.append(shape("TextShape", n, inner, [(x - 0.2, y - size),
                                                      (x + wide + 0.2, y + 0.3 * size)]))
    w, hg = page
    head = '<?xml version="1.0" encoding="UTF-8"?>\n'
    if tiny:
        svg = (f'<svg version="1.2" baseProfile="tiny" width="{_f(w)}mm" height="{_f(hg)}mm" '
               f'viewBox="0 0 {h(w)} {h(hg)}" preserveAspectRatio="xMidYMid" '
               'fill-rule="evenodd" stroke-width="28.222" stroke-linejoin="round" '
               'xmlns="http://www.w3.org/2000/svg" xmlns:ooo="http://xml.openoffice.org/svg/'
               'export" xmlns:xlink="http://www.w3.org/1999/xlink" xml:space="preserve">\n')
    else:
        head += ('<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" '
                 '"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd">\n')
        svg = (f'<svg version="1.2" width="{_f(w)}mm" height="{_f(hg)}mm" viewBox="0 0 '
               f'{h(w)} {h(hg)}" preserveAspectRatio="xMidYMid" fill-rule="evenodd" '
               'stroke-width="28.222" stroke-linejoin="round" xmlns="http://www.w3.org/2000/svg" '
               'xmlns:ooo="http://xml.openoffice.org/svg/export" '
               'xmlns:xlink="http://www.w3.org/1999/xlink" '
               'xmlns:presentation="http://sun.com/xmlns/staroffice/presentation" '
               'xmlns:smil="http://www.w3.org/2001/SMIL20/" '
               'xmlns:anim="urn:oasis:names:tc:opendocument:xmlns:animation:1.0" '
               'xml:space="preserve">\n <defs class="ClipPathGroup">\n  <clipPath '
               'id="presentation_clip_path" clipPathUnits="userSpaceOnUse">\n   <rect x="0" '
               f'y="0" width="{h(w)}" height="{h(hg)}"/>\n  </clipPath>\n </defs>\n'
               ' <defs class="TextShapeIndex">\n  <g ooo:slide="id1" '
               'ooo:id-list="' + " ".join(f"id{n}" for n in range(3, len(marks) + 3)
                                          if marks[n - 3][0] == "text") + '"/>\n </defs>\n')
    return head + svg + (
        ' <g>\n  <g id="id2" class="Master_Slide">\n   <g id="bg-id2" class="Background"/>\n'
        '   <g id="bo-id2" class="BackgroundObjects"/>\n  </g>\n </g>\n <g class="SlideGroup">'
        '\n  <g>\n   <g id="container-id1">\n    <g id="id1" class="Slide" clip-path="url('
        '#presentation_clip_path)">\n     <g class="Page">\n'
        + "\n".join(body) + "\n     </g>\n    </g>\n   </g>\n  </g>\n </g>\n</svg>")


# ----- GeoGebra -------------------------------------------------------------------------------
_GG = 'paint-order="fill stroke markers"'


def geogebra(rng: random.Random, marks: list, page=A4, zoom: float | None = None) -> str:
    """As GeoGebra exports its graphics view to SVG (canvas2svg): pixels at its own zoom
    (``zoom`` times a paper mm's 96 dpi pixels; at random if not given, 1 exporting at true
    size)."""
    z = _PX * (zoom or rng.choice([1.0, 1.0, rng.uniform(0.6, 1.6)]))
    w, hg = round(page[0] * z), round(page[1] * z)
    colour = rng.choice(["rgb(0,0,0)", "rgb(97,97,97)", "rgb(21,101,192)"])

    def p(v):
        return _f(v * z, 2)

    def segment(a, b, width=2.5, stroke=colour):
        return (f'<path fill="none" stroke="{stroke}" {_GG} d=" M {p(a[0])} {p(a[1])} L '
                f'{p(b[0])} {p(b[1])}" stroke-opacity="0.8" stroke-linecap="round" '
                f'stroke-linejoin="round" stroke-miterlimit="10" stroke-width="{width}"/>')

    def bezier_circle(c, r):
        k = 0.5523 * r
        x, y = c
        return (f" M {p(x + r)} {p(y)} C {p(x + r)} {p(y + k)} {p(x + k)} {p(y + r)} {p(x)} "
                f"{p(y + r)} C {p(x - k)} {p(y + r)} {p(x - r)} {p(y + k)} {p(x - r)} {p(y)} C "
                f"{p(x - r)} {p(y - k)} {p(x - k)} {p(y - r)} {p(x)} {p(y - r)} C {p(x + k)} "
                f"{p(y - r)} {p(x + r)} {p(y - k)} {p(x + r)} {p(y)} Z")

    def text(x, y, t, px):
        attrs = (f'font-family="geogebra-sans-serif, sans-serif" font-size="{px}px" '
                 'font-style="normal" font-weight="normal" text-decoration="normal" '
                 f'x="{round(x)}" y="{round(y)}" text-anchor="start" '
                 'dominant-baseline="alphabetic"')
        fill = f'<text fill="{colour}" stroke="none" {attrs} fill-opacity="1">{escape(t)}</text>'
        return fill + (f'<text fill="none" stroke="rgb(255,255,255)" {attrs} stroke-opacity="1"'
                       ' stroke-linejoin="bevel" stroke-miterlimit="10" stroke-width="3">'
                       f"{escape(t)}</text>") + fill
    body = []
    for m in marks:
        if m[0] == "line":
            thin = len(m) > 3 and m[3] == "thin"
            body.append(segment(m[1], m[2], 1 if thin else 2.5,
                                "rgb(153,153,153)" if thin else colour))
        elif m[0] == "arrow":
            tip, left, right, base = arrowhead(m[1], m[2], 17 / z, 4.25 / z)
            body.append(segment(m[1], base))
            body.append(f'<path fill="{colour}" stroke="none" paint-order="stroke fill markers" '
                        f'fill-rule="evenodd" d=" M {p(tip[0])} {p(tip[1])} L {p(left[0])} '
                        f'{p(left[1])} L {p(right[0])} {p(right[1])} Z" fill-opacity="0.8"/>')
        elif m[0] in ("dot", "circle"):
            r = 4 / z if m[0] == "dot" else m[2]
            if m[0] == "dot":
                body.append(f'<path fill="{colour}" stroke="none" paint-order="stroke fill '
                            f'markers" d="{bezier_circle(m[1], r)}" fill-opacity="1"/>')
            body.append(f'<path fill="none" stroke="rgb(0,0,0)" {_GG} d="'
                        f'{bezier_circle(m[1], r)}" stroke-opacity="1" stroke-linecap="round" '
                        'stroke-linejoin="round" stroke-miterlimit="10"/>')
        elif m[0] == "poly":
            ps = list(m[1]) + ([m[1][0]] if m[2] else [])
            body.append(f'<path fill="none" stroke="{colour}" {_GG} d=" M {p(ps[0][0])} '
                        f'{p(ps[0][1])}' + "".join(f" L {p(x)} {p(y)}" for x, y in ps[1:])
                        + ('" stroke-opacity="0.8" stroke-linecap="round" stroke-linejoin='
                           '"round" stroke-miterlimit="10" stroke-width="2.5"/>'))
        else:                                    # a subscript is a text of its own
            x, y = m[1][0] * z, m[1][1] * z      # in pixels, as canvas2svg writes them
            px = max(round(_size(m) * z), 6)
            for t, role in m[2]:
                if role == "sub":
                    body.append(text(x, y + 7 * px / 16, t, round(px * 0.875)))
                    x += 0.5 * len(t) * px * 0.875
                else:
                    body.append(text(x, y, t, px))
                    x += 0.55 * len(t) * px
    clip = "".join(rng.choice(string.ascii_letters) for _ in range(12))
    svg = (f'<svg version="1.1" xmlns="http://www.w3.org/2000/svg" '
           f'xmlns:xlink="http://www.w3.org/1999/xlink" width="{w}" height="{hg}"><defs>'
           f'<clipPath id="{clip}"><path fill="none" stroke="none" d=" M 0 0 L {w} 0 L {w} {hg}'
           f' L 0 {hg} L 0 0 Z"/></clipPath></defs><g transform="scale(1,1)" clip-path="url(#'
           f'{clip})"><g><rect fill="rgb(255,255,255)" stroke="none" x="0" y="0" width="{w}" '
           f'height="{hg}" fill-opacity="1"/>' + "".join(body) + "</g></g></svg>")
    return svg if rng.random() < 0.5 else '<?xml version="1.0" encoding="UTF-8"?>\n' + svg


# ----- a CAD program through QSvgGenerator ----------------------------------------------------
def cad(rng: random.Random, marks: list, page=A4, model: float = 1.0) -> str:
    """As a CAD program plots to SVG through Qt: the drawing in model units (``model`` of
    them a paper mm, the plot scale 1:model), y up under one flipping group; each text in a
    group of its own that places it."""
    k = _PX / model
    w, hg = page
    vw, vh = round(w * _PX), round(hg * _PX)
    ox, oy = rng.uniform(-500, 500) * model, rng.uniform(-500, 500) * model

    def world(p):
        """Paper mm, y down, as the model's coordinates, y up."""
        return (p[0] * model + ox, -(p[1] * model) + oy)

    def q(v):
        return _f(v, 3)
    flip = f"matrix({_f(k, 6)},0,0,{_f(-k, 6)},{_f(-ox * k, 4)},{_f(oy * k, 4)})"
    group = ('<g fill="none" stroke="#000000" stroke-opacity="1" stroke-width="1" '
             'stroke-linecap="round" stroke-linejoin="round" transform="{t}"\n'
             'font-family="ISOCPEUR" font-size="9" font-weight="400" font-style="normal" \n>\n')
    lines, thin, texts = [], [], []
    for m in marks:
        if m[0] in ("line", "arrow"):
            a, b = world(m[1]), world(m[2])
            (thin if len(m) > 3 and m[3] == "thin" else lines).append(
                f'<polyline fill="none" vector-effect="non-scaling-stroke" '
                f'points="{q(a[0])},{q(a[1])} {q(b[0])},{q(b[1])} " />')
            if m[0] == "arrow":                   # a solid, as the student hatched it
                tip, left, right, _ = arrowhead(m[1], m[2], 2.5, 0.6)
                t, lft, rgt = world(tip), world(left), world(right)
                lines.append(f'<path vector-effect="none" fill="#000000" fill-rule="evenodd" '
                             f'd="M{q(lft[0])},{q(lft[1])} L{q(t[0])},{q(t[1])} L{q(rgt[0])},'
                             f'{q(rgt[1])} L{q(lft[0])},{q(lft[1])}"/>')
        elif m[0] in ("dot", "circle"):
            c = world(m[1])
            fill = "#000000" if m[0] == "dot" else "none"
            lines.append(f'<circle vector-effect="non-scaling-stroke" fill="{fill}" '
                         f'cx="{q(c[0])}" cy="{q(c[1])}" r="{q(m[2] * model)}"/>')
        elif m[0] == "poly":
            ps = [world(p) for p in list(m[1]) + ([m[1][0]] if m[2] else [])]
            lines.append('<polyline fill="none" vector-effect="non-scaling-stroke" points="'
                         + " ".join(f"{q(x)},{q(y)}" for x, y in ps) + ' " />')
        else:
            (x, y), size = m[1], _size(m)
            place = f"matrix(1,0,0,1,{_f(x * _PX, 3)},{_f(y * _PX, 3)})"
            texts.append(group.format(t=place) + '<text fill="#000000" fill-opacity="1" '
                         'stroke="none" xml:space="preserve" x="0" y="0" font-family="ISOCPEUR"'
                         f' font-size="{_f(size * _PX, 2)}" font-weight="400" '
                         f'font-style="normal" >{escape(_plain(m[2]))}</text>\n</g>\n')
    return ('<?xml version="1.0" encoding="UTF-8" standalone="no"?>\n'
            f'<svg width="{_f(w)}mm" height="{_f(hg)}mm"\n viewBox="0 0 {vw} {vh}"\n'
            ' xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink"  '
            'version="1.2" baseProfile="tiny">\n<title>polygons</title>\n'
            '<desc>Generated with Qt</desc>\n<defs>\n</defs>\n<g fill="none" stroke="black" '
            'stroke-width="1" fill-rule="evenodd" stroke-linecap="square" '
            'stroke-linejoin="bevel" >\n\n' + group.format(t=flip) + "\n".join(lines)
            + "\n</g>\n\n" + (group.format(t=flip).replace(
                'stroke="#000000"', 'stroke="#808080" stroke-dasharray="6,3"') + "\n".join(thin)
                + "\n</g>\n\n" if thin else "") + "".join(texts) + "</g>\n</svg>\n")


# ----- by hand --------------------------------------------------------------------------------
def hand(rng: random.Random, marks: list, page=A4) -> str:
    """As a student types it: sometimes no namespace, a style block, polylines, single quotes,
    unicode subscripts or baseline-shifted tspans, CRLF line ends, a marker, a rotated group
    put back; a page of no stated size (so in pixels) only where no scale is written on it."""
    q = rng.choice(['"', "'"])
    marker = rng.random() < 0.5
    body = []
    for m in marks:
        if m[0] in ("line", "arrow"):
            (x1, y1), (x2, y2) = m[1], m[2]
            end = f" marker-end={q}url(#head){q}" if m[0] == "arrow" and marker else ""
            cls = "c" if len(m) > 3 and m[3] == "thin" else "v"
            if rng.random() < 0.5:
                body.append(f"<line class={q}{cls}{q} x1={q}{_f(x1, 2)}{q} y1={q}{_f(y1, 2)}{q} "
                            f"x2={q}{_f(x2, 2)}{q} y2={q}{_f(y2, 2)}{q}{end}/>")
            else:
                body.append(f"<polyline class={q}{cls}{q} points={q}{_f(x1, 2)},{_f(y1, 2)} "
                            f"{_f(x2, 2)},{_f(y2, 2)}{q}{end}/>")
            if m[0] == "arrow" and not marker:
                tip, left, right, _ = arrowhead(m[1], m[2], 2.5, 0.8)
                body.append(f"<polygon points={q}" + " ".join(
                    f"{_f(x, 2)},{_f(y, 2)}" for x, y in (tip, left, right)) + f"{q}/>")
        elif m[0] in ("dot", "circle"):
            fill = "" if m[0] == "dot" else f" fill={q}none{q}"
            body.append(f"<circle cx={q}{_f(m[1][0], 2)}{q} cy={q}{_f(m[1][1], 2)}{q} "
                        f"r={q}{_f(m[2], 2)}{q}{fill}/>")
        elif m[0] == "poly":
            tag = "polygon" if m[2] else "polyline"
            body.append(f"<{tag} class={q}v{q} points={q}" + " ".join(
                f"{_f(x, 2)},{_f(y, 2)}" for x, y in m[1]) + f"{q}/>")
        else:
            size = _size(m)
            if rng.random() < 0.6:
                text = escape(_plain(m[2]))
            else:
                text = "".join(escape(t) if not role else
                               f"<tspan baseline-shift={q}sub{q} font-size={q}"
                               f"{_f(0.7 * size, 2)}{q}>{escape(t)}</tspan>" for t, role in m[2])
            body.append(f"<text x={q}{_f(m[1][0], 2)}{q} y={q}{_f(m[1][1], 2)}{q} "
                        f"font-size={q}{_f(size, 1)}{q}>{text}</text>")
    space = ' xmlns="http://www.w3.org/2000/svg"' if rng.random() < 0.8 else ""
    w, h = page
    scaled = any(m[0] == "text" and re.search(r"\d\s*cm\s*=", _plain(m[2])) for m in marks)
    size = f' width="{_f(w)}mm" height="{_f(h)}mm" viewBox="0 0 {_f(w)} {_f(h)}"'
    if not scaled and rng.random() < 0.5:
        size = f' viewBox="0 0 {_f(w)} {_f(h)}"'
    if rng.random() < 0.3:                     # turned by a group, drawn turned back
        body = [f'<g transform="rotate(30 {_f(w / 2)} {_f(h / 2)})"><g transform="rotate(-30 '
                f'{_f(w / 2)} {_f(h / 2)})">'] + body + ["</g></g>"]
    end = "\r\n" if rng.random() < 0.3 else "\n"
    defs = (f"<defs><marker id={q}head{q} markerWidth={q}6{q} markerHeight={q}4{q} refX={q}6{q}"
            f" refY={q}2{q} orient={q}auto{q}><path d={q}M0,0 L6,2 L0,4 z{q}/></marker></defs>"
            + end) if marker else ""
    return (f"<svg{space}{size}>{end}<style>.v {{ stroke: black; stroke-width: 0.3 }} "
            f".c {{ stroke: grey; stroke-width: 0.15; stroke-dasharray: 1 1 }}</style>{end}"
            f"{defs}<!-- my polygons -->{end}" + end.join(body) + f"{end}</svg>{end}")


WRITERS = {"inkscape": inkscape, "libreoffice": libreoffice, "geogebra": geogebra, "cad": cad,
           "hand": hand}
