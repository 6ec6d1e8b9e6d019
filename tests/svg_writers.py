"""A sheet of marks written as SVG the way each program writes it.

A sheet is a list of marks in paper mm, y down: ("line", a, b), ("arrow", a, b), ("dot",
centre, r) and ("text", anchor, runs), each run (text, role) with role "sub" for a
subscript set apart. Each writer lays it out as its program does, read off the program's
own files:

- Inkscape 1.2: mm with a viewBox, a translated layer, relative path data, markers, texts
  in ``sodipodi:role="line"`` tspans, clones (``<use>``), its namedview;
- LibreOffice Draw 7: hundredths of a mm, a BoundingBox rect round every shape, texts in
  nested TextParagraph/TextPosition tspans, arrowheads as closed paths, dots as Béziers,
  its DOCTYPE unless exported as Tiny;
- GeoGebra: a pixel page at its own zoom, a clip path, a path per segment, filled
  arrowheads, subscripts by baseline-shift;
- a CAD program: y up under one flipping group, each text flipped back by a matrix of its
  own;
- by hand: sometimes no namespace, a style block, polylines, single quotes, unicode
  subscripts, CRLF line ends, a rotated group turned back.
"""

from __future__ import annotations

import math
import random
from xml.sax.saxutils import escape

__all__ = ["WRITERS", "inkscape", "libreoffice", "geogebra", "cad", "hand"]

_PX = 96.0 / 25.4


def _f(v: float, digits: int = 4) -> str:
    return f"{v:.{digits}f}".rstrip("0").rstrip(".") or "0"


def _head(tag: str) -> str:
    return f'<?xml version="1.0" encoding="UTF-8" standalone="no"?>\n{tag}\n'


def _arrowhead(a, b, size: float = 3.0) -> list[tuple[float, float]]:
    """The three corners of a filled arrowhead at ``b``, pointing from ``a``."""
    d = math.dist(a, b) or 1.0
    ux, uy = (b[0] - a[0]) / d, (b[1] - a[1]) / d
    return [b, (b[0] - size * ux + size * 0.35 * uy, b[1] - size * uy - size * 0.35 * ux),
            (b[0] - size * ux - size * 0.35 * uy, b[1] - size * uy + size * 0.35 * ux)]


def inkscape(rng: random.Random, marks: list) -> str:
    """As Inkscape 1.2 saves an Inkscape SVG."""
    tx, ty = rng.choice([(0, 0), (rng.uniform(-50, 50), rng.uniform(-50, 50))])
    body, n = [], 0
    for m in marks:
        n += 1
        if m[0] in ("line", "arrow"):
            (x1, y1), (x2, y2) = (m[1][0] - tx, m[1][1] - ty), (m[2][0] - tx, m[2][1] - ty)
            d = rng.choice([f"m {_f(x1)},{_f(y1)} {_f(x2 - x1)},{_f(y2 - y1)}",
                            f"M {_f(x1)},{_f(y1)} L {_f(x2)},{_f(y2)}",
                            f"m {_f(x1)},{_f(y1)} {_f(x2 - x1)},{_f(y2 - y1)} z"
                            if m[0] == "line" and rng.random() < 0.1 else
                            f"M {_f(x1)} {_f(y1)} {_f(x2)} {_f(y2)}"])
            marker = ";marker-end:url(#Arrow2)" if m[0] == "arrow" else ""
            body.append(f'<path style="fill:none;stroke:#000000;stroke-width:0.264583px{marker}"'
                        f' d="{d}" id="path{n}" />')
            if rng.random() < 0.05:                      # a clone of it, put back in place
                body.append(f'<use x="0" y="0" xlink:href="#path{n}" id="use{n}" />')
        elif m[0] == "dot":
            body.append(f'<circle style="fill:#000000;stroke:none" id="circle{n}" '
                        f'cx="{_f(m[1][0] - tx)}" cy="{_f(m[1][1] - ty)}" r="{_f(m[2])}" />')
        else:
            x, y = _f(m[1][0] - tx), _f(m[1][1] - ty)
            runs = "".join(escape(t) if not role else
                           f'<tspan style="font-size:65%;baseline-shift:sub">{escape(t)}</tspan>'
                           for t, role in m[2])
            body.append(f'<text xml:space="preserve" style="font-size:4.23333px;line-height:1.25;'
                        f'font-family:sans-serif;stroke-width:0.264583" x="{x}" y="{y}" '
                        f'id="text{n}"><tspan sodipodi:role="line" id="tspan{n}" '
                        f'style="stroke-width:0.264583" x="{x}" y="{y}">{runs}</tspan></text>')
    return _head(
        '<!-- Created with Inkscape (http://www.inkscape.org/) -->') + (
        '<svg width="210mm" height="297mm" viewBox="0 0 210 297" version="1.1" id="svg5" '
        'inkscape:version="1.2.2 (b0a8486541, 2022-12-01)" sodipodi:docname="drawing.svg" '
        'xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" '
        'xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd" '
        'xmlns:xlink="http://www.w3.org/1999/xlink" xmlns="http://www.w3.org/2000/svg" '
        'xmlns:svg="http://www.w3.org/2000/svg">\n<sodipodi:namedview id="namedview7" '
        'pagecolor="#ffffff" inkscape:document-units="mm" />\n<defs id="defs2"><marker '
        'style="overflow:visible" id="Arrow2" refX="0" refY="0" orient="auto-start-reverse" '
        'inkscape:stockid="Arrow2"><path transform="scale(0.5)" style="fill:context-stroke" '
        'd="M 0,0 -3,2 V -2 Z" id="path900" /></marker></defs>\n<g inkscape:label="Layer 1" '
        f'inkscape:groupmode="layer" id="layer1" transform="translate({_f(tx)},{_f(ty)})">\n'
        + "\n".join(body) + "\n</g>\n</svg>\n")


def libreoffice(rng: random.Random, marks: list) -> str:
    """As LibreOffice Draw 7 exports SVG: hundredths of a mm, a BoundingBox round each
    shape, text positions on nested tspans; with its DOCTYPE unless exported as Tiny."""
    def h(v):
        return str(round(v * 100))

    def shape(kind: str, n: int, inner: str, box) -> str:
        x0, y0 = min(p[0] for p in box), min(p[1] for p in box)
        x1, y1 = max(p[0] for p in box), max(p[1] for p in box)
        return (f'<g class="com.sun.star.drawing.{kind}"><g id="id{n}"><rect class="BoundingBox"'
                f' stroke="none" fill="none" x="{h(x0)}" y="{h(y0)}" width="{h(x1 - x0 + 0.01)}"'
                f' height="{h(y1 - y0 + 0.01)}"/>{inner}</g></g>')
    body = []
    for n, m in enumerate(marks, 3):
        if m[0] in ("line", "arrow"):
            inner = (f'<path fill="none" stroke="rgb(0,0,0)" d="M {h(m[1][0])},{h(m[1][1])} '
                     f'L {h(m[2][0])},{h(m[2][1])}"/>')
            box = [m[1], m[2]]
            if m[0] == "arrow":
                head = _arrowhead(m[1], m[2])
                inner += ('<path fill="rgb(0,0,0)" stroke="none" d="M '
                          + " ".join(f"{h(x)},{h(y)}" for x, y in head) + ' Z"/>')
                box += head
            body.append(shape("LineShape", n, inner, box))
        elif m[0] == "dot":
            (cx, cy), r = m[1], m[2]
            k = 0.5523 * r
            d = (f"M {h(cx)},{h(cy - r)} C {h(cx + k)},{h(cy - r)} {h(cx + r)},{h(cy - k)} "
                 f"{h(cx + r)},{h(cy)} C {h(cx + r)},{h(cy + k)} {h(cx + k)},{h(cy + r)} "
                 f"{h(cx)},{h(cy + r)} C {h(cx - k)},{h(cy + r)} {h(cx - r)},{h(cy + k)} "
                 f"{h(cx - r)},{h(cy)} C {h(cx - r)},{h(cy - k)} {h(cx - k)},{h(cy - r)} "
                 f"{h(cx)},{h(cy - r)} Z")
            body.append(shape("EllipseShape", n, f'<path fill="rgb(0,0,0)" stroke="none" '
                              f'd="{d}"/>', [(cx - r, cy - r), (cx + r, cy + r)]))
        else:
            (x, y), text = m[1], "".join(t for t, _ in m[2])
            inner = ('<text class="SVGTextShape"><tspan class="TextParagraph" '
                     'font-family="Liberation Sans, sans-serif" font-size="423px" '
                     f'font-weight="400"><tspan class="TextPosition" x="{h(x)}" y="{h(y)}">'
                     f'<tspan fill="rgb(0,0,0)" stroke="none" style="white-space: pre">'
                     f'{escape(text)}</tspan></tspan></tspan></text>')
            body.append(shape("TextShape", n, inner, [(x - 1, y - 4), (x + 2 * len(text), y)]))
    doctype = ('<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" '
               '"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd">\n'
               if rng.random() < 0.5 else "")
    return (_head(doctype.rstrip()) if doctype else _head("").rstrip() + "\n") + (
        '<svg version="1.2" width="210mm" height="297mm" viewBox="0 0 21000 29700" '
        'preserveAspectRatio="xMidYMid" fill-rule="evenodd" stroke-width="28.222" '
        'stroke-linejoin="round" xmlns="http://www.w3.org/2000/svg" '
        'xmlns:ooo="http://xml.openoffice.org/svg/export" '
        'xmlns:xlink="http://www.w3.org/1999/xlink" xml:space="preserve">\n'
        '<defs class="ClipPathGroup"><clipPath id="presentation_clip_path" '
        'clipPathUnits="userSpaceOnUse"><rect x="0" y="0" width="21000" height="29700"/>'
        '</clipPath></defs>\n<defs class="EmbeddedBulletChars"><g id="bullet-char-template-57356"'
        ' transform="scale(0.00048828125,-0.00048828125)"><path d="M 580,1141 L 1163,571 580,0 '
        '-4,571 580,1141 Z"/></g></defs>\n<g><g id="id2" class="Master_Slide"><g '
        'id="bg-id2" class="Background"/><g id="bo-id2" class="BackgroundObjects"/></g></g>\n'
        '<g class="SlideGroup"><g><g id="container-id1"><g id="id1" class="Slide" '
        'clip-path="url(#presentation_clip_path)"><g class="Page">\n'
        + "\n".join(body) + "\n</g></g></g></g></g>\n</svg>")


def geogebra(rng: random.Random, marks: list) -> str:
    """As GeoGebra exports its graphics view: pixels at its own zoom, a clip path, a path for
    each segment, filled arrowheads, subscripts shifted by baseline."""
    z = _PX * rng.uniform(0.5, 2.0)
    w, hgt = round(210 * z), round(297 * z)
    body = []
    for m in marks:
        if m[0] in ("line", "arrow"):
            body.append(f'<path d="M {_f(m[1][0] * z, 2)} {_f(m[1][1] * z, 2)} L '
                        f'{_f(m[2][0] * z, 2)} {_f(m[2][1] * z, 2)}" stroke="#000000" '
                        'stroke-width="2" fill="none" stroke-linecap="round"/>')
            if m[0] == "arrow":
                head = _arrowhead(m[1], m[2], 2.5)
                body.append('<path d="M ' + " L ".join(f"{_f(x * z, 2)} {_f(y * z, 2)}"
                                                       for x, y in head)
                            + ' Z" fill="#000000" stroke="none"/>')
        elif m[0] == "dot":
            (cx, cy), r = m[1], m[2] * z
            body.append(f'<circle cx="{_f(cx * z, 2)}" cy="{_f(cy * z, 2)}" r="{_f(r, 2)}" '
                        'fill="#1565c0" stroke="#000000" stroke-width="1"/>')
        else:
            runs = "".join(escape(t) if not role else
                           f'<tspan baseline-shift="sub" font-size="12">{escape(t)}</tspan>'
                           for t, role in m[2])
            body.append(f'<text x="{_f(m[1][0] * z, 2)}" y="{_f(m[1][1] * z, 2)}" '
                        'font-family="SansSerif" font-size="16" fill="#000000">'
                        f'{runs}</text>')
    return _head("").rstrip() + "\n" + (
        f'<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" '
        f'width="{w}" height="{hgt}" viewBox="0 0 {w} {hgt}"><defs><clipPath id="clip1">'
        f'<rect x="0" y="0" width="{w}" height="{hgt}"/></clipPath></defs>'
        '<g clip-path="url(#clip1)"><rect x="0" y="0" width="100%" height="100%" '
        'fill="#ffffff"/>' + "".join(body) + "</g></svg>\n")


def cad(rng: random.Random, marks: list) -> str:
    """As a CAD program plots to SVG: y up under one flipping group, each text flipped back
    by a matrix of its own, a stated scale."""
    height = 297.0
    body = []
    for m in marks:
        if m[0] in ("line", "arrow"):
            body.append(f'<line x1="{_f(m[1][0])}" y1="{_f(height - m[1][1])}" '
                        f'x2="{_f(m[2][0])}" y2="{_f(height - m[2][1])}" />')
            if m[0] == "arrow":
                head = _arrowhead(m[1], m[2], 2.0)
                body.append('<polyline points="' + " ".join(
                    f"{_f(x)},{_f(height - y)}" for x, y in (head[1], head[0], head[2]))
                    + '" fill="none" />')
        elif m[0] == "dot":
            body.append(f'<circle cx="{_f(m[1][0])}" cy="{_f(height - m[1][1])}" '
                        f'r="{_f(m[2])}" />')
        else:
            text = "".join(t for t, _ in m[2])
            body.append(f'<text transform="matrix(1 0 0 -1 {_f(m[1][0])} '
                        f'{_f(height - m[1][1])})" x="0" y="0" font-size="3.5">'
                        f'{escape(text)}</text>')
    return _head("").rstrip() + "\n" + (
        '<svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="210mm" height="297mm" '
        'viewBox="0 0 210 297">\n<title>PLOT-A4</title>\n<g stroke="black" '
        'stroke-width="0.25" fill="none" transform="matrix(1 0 0 -1 0 297)">\n'
        + "\n".join(body) + "\n</g>\n</svg>\n")


def hand(rng: random.Random, marks: list) -> str:
    """As a student types it: sometimes no namespace, a style block, polylines, single quotes,
    unicode subscripts, CRLF line ends, a rotated group put back."""
    q = rng.choice(['"', "'"])
    body = []
    for m in marks:
        if m[0] in ("line", "arrow"):
            if rng.random() < 0.5:
                body.append(f"<line class={q}v{q} x1={q}{_f(m[1][0], 2)}{q} "
                            f"y1={q}{_f(m[1][1], 2)}{q} x2={q}{_f(m[2][0], 2)}{q} "
                            f"y2={q}{_f(m[2][1], 2)}{q}/>")
            else:
                body.append(f"<polyline points={q}{_f(m[1][0], 2)},{_f(m[1][1], 2)} "
                            f"{_f(m[2][0], 2)},{_f(m[2][1], 2)}{q}/>")
        elif m[0] == "dot":
            body.append(f"<circle cx={q}{_f(m[1][0], 2)}{q} cy={q}{_f(m[1][1], 2)}{q} "
                        f"r={q}{_f(m[2], 2)}{q}/>")
        else:
            text = "".join(t if not role else "".join(chr(0x2080 + int(c)) if c.isdigit()
                                                      else c for c in t)
                           for t, role in m[2])
            body.append(f"<text x={q}{_f(m[1][0], 2)}{q} y={q}{_f(m[1][1], 2)}{q}>"
                        f"{escape(text)}</text>")
    space = ' xmlns="http://www.w3.org/2000/svg"' if rng.random() < 0.8 else ""
    size = rng.choice([' width="210mm" height="297mm" viewBox="0 0 210 297"',
                       ' viewBox="0 0 210 297"'])
    if rng.random() < 0.3:                     # turned by a group, drawn turned back
        body = ['<g transform="rotate(30 105 148)"><g transform="rotate(-30 105 148)">']\
            + body + ["</g></g>"]
    end = "\r\n" if rng.random() < 0.3 else "\n"
    return (f"<svg{space}{size}>{end}<style>.v {{ stroke: black; }} line {{ stroke-width: 0.3 }}"
            f"</style>{end}<!-- my polygon -->{end}" + end.join(body) + f"{end}</svg>{end}")


WRITERS = {"inkscape": inkscape, "libreoffice": libreoffice, "geogebra": geogebra, "cad": cad,
           "hand": hand}
