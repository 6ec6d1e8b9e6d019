"""The overlay a student reads their grade on (grade.svg): their drawing in grey, the
polygons tarsim expects over it in blue, each item graded wrong ringed in red with its
verdict, and under the drawing a legend and each wrong item's explanation in words.

A drawing may be 5 cm or 2 m across, so the overlay is laid out in *display* millimetres:
it is shown some 17 cm wide, and every text, stroke and ring is a size on that page, times
the drawing's millimetres per displayed one. Every text's box is counted into the viewBox
(its width reckoned from its letters), so nothing is cut at the edge, and a verdict's
label is set where it covers no other label.
"""

from __future__ import annotations

import math

from tarsim.constructions.narration import Number, measure_words, right_to_left, words
from tarsim.graphics.figure import text_width, wrap_text
from tarsim.graphics.rtl import RTL_FONT, is_rtl, joined
from tarsim.graphics.sans_advances import ADVANCE
from .grade import Grade, Item

__all__ = ["overlay_svg", "sans_width", "credited", "named", "BLUE", "RED", "GREY", "AMBER",
           "FOLLOWS"]

BLUE, RED, GREY, AMBER = "#1f5fbf", "#c62828", "#9e9e9e", "#b26a00"
"""tarsim's polygons, an item graded wrong, the student's drawing, and an item drawn
right from an earlier error."""

FOLLOWS = "follows from an earlier error"
"""The verdict of an item drawn correctly from an earlier wrong one."""


def credited(g: Grade, item: Item) -> bool:
    """Whether ``item`` earns its points: correct, or drawn rightly from an earlier error
    where the course lets that score (its ``follow`` setting, on unless it says not)."""
    return item.verdict == "correct" or item.verdict == FOLLOWS and getattr(g, "follow", True)


def named(text: str) -> str:
    """A name (a file's, an exercise's, an item's) to be set in a line of the language
    spoken: in a right-to-left one, a name of no right-to-left letters that opens or closes
    with anything but a letter between left-to-right marks, so that one opening with
    digits ("9818_ali.svg") or closing with a prime ("a′") keeps its order in a Persian
    line, in a browser and in cairo alike."""
    bare = not text or text[0].isalpha() and text[-1].isalpha()
    return text if bare or not right_to_left() or is_rtl(text) else f"\u200e{text}\u200e"


_SHOWN = (150.0, 180.0)
"""The box (display mm) the drawing itself is fitted in; labels and notes add to it."""

_TEXT, _SMALL, _RING, _STROKE = 3.0, 2.6, 2.2, 0.3
"""Display sizes (mm): a label's and a note's height, a ring's radius, a line's width."""

_ADVICE = "#333"
"""The colour of an item's advice under the drawing."""

_LINES_AVOIDED = 2000
"""The most lines a verdict's label is kept off (a drawing may hold many thousands)."""


def sans_width(text: str, size: float) -> float:
    """The width of ``text`` set in DejaVu Sans at ``size`` (its advances read from the
    font, a right-to-left text's in the joined forms it is drawn in).

    >>> round(sans_width("mm", 10.0), 2)
    19.48
    """
    return sum(ADVANCE.get(ch, 0.62) for ch in (joined(text) if is_rtl(text) else text)
               ) * size


def overlay_svg(g: Grade) -> str:
    """grade.svg of the drawing graded ``g``: see the module's docstring."""
    from tarsim.graphics.svg_tree import Drawing

    drawing, polygons = g.overlay
    unit = _unit(g)
    fs = _TEXT * unit
    boxes: list[tuple[float, float, float, float]] = []   # every text's box, for the bounds
    dwg = Drawing(profile="full", debug=False)
    student = dwg.add(dwg.g(stroke=GREY, stroke_width=_num(_STROKE * unit), fill="none"))
    if drawing.segments:                     # one path: a drawing may hold thousands
        student.add(dwg.path(d=" ".join(f"M{a[0]:.3f} {a[1]:.3f}L{b[0]:.3f} {b[1]:.3f}"
                                        for a, b in drawing.segments)))
    for c, r in drawing.circles:
        student.add(dwg.circle(c, r))
    lettering = dwg.add(dwg.g(fill=GREY, font_size=_num(fs), font_family="DejaVu Serif"))
    for label in drawing.labels:
        lettering.add(dwg.text(label.text, insert=label.at))
        boxes.append(_box(label.text, label.at, fs, text_width))
    right = dwg.add(dwg.g(stroke=BLUE, stroke_width=_num(_STROKE * unit), fill="none",
                          stroke_dasharray=f"{1.6 * unit:.4g},{0.8 * unit:.4g}"))
    lines = list(drawing.segments)
    for drawn in polygons:
        if drawn is None:
            continue
        _, _, pole, expected = drawn
        for tip in expected.values():
            if math.dist(tip, pole) > 0.3 * unit:
                right.add(dwg.line(pole, tip))
                right.add(dwg.circle(tip, 0.6 * unit))
                lines.append((tuple(pole), tuple(tip)))
    _rings(dwg, g.items, unit, boxes, lines[:_LINES_AVOIDED])
    x0, y0, x1, y1 = _bounds(g, boxes, unit)
    score = words("{source}: score {score} %", source=named(g.source),
                  score=Number(g.score, ".0f"))
    notes = _notes(g.items, x1 - x0, unit)
    x1 = max(x1, x0 + _legend_width(g.items, unit), x0 + sans_width(score, 1.3 * fs),
             *(x0 + sans_width(text, _SMALL * unit) for text, _ in notes))
    y = _legend(dwg, g.items, (x0, x1), y1 + 2.0 * fs, unit)
    block = dwg.add(dwg.g(font_size=_num(_SMALL * unit), font_family="DejaVu Sans"))
    y += 0.6 * fs
    for text, colour in notes:
        y += (1.35 if colour != _ADVICE else 1.3) * _SMALL * unit
        block.add(_line(dwg, text, (x0, x1), y, fill=colour))
    y += 2.2 * fs
    dwg.add(_line(dwg, score, (x0, x1), y, font_size=_num(1.3 * fs), fill="#000"))
    pad = 3.0 * unit
    x0, y0, x1, y1 = x0 - pad, y0 - pad, x1 + pad, y + 0.4 * fs + pad
    dwg["viewBox"] = f"{x0:.3f} {y0:.3f} {x1 - x0:.3f} {y1 - y0:.3f}"
    dwg["width"], dwg["height"] = f"{(x1 - x0) / unit:.2f}mm", f"{(y1 - y0) / unit:.2f}mm"
    dwg["direction"] = "ltr"         # inline in a right-to-left page, it must not inherit rtl
    return dwg.tostring()


def _unit(g: Grade) -> float:
    """Drawing mm per display mm: the drawing fitted in :data:`_SHOWN`."""
    pts = _points(g)
    w = max(p[0] for p in pts) - min(p[0] for p in pts)
    h = max(p[1] for p in pts) - min(p[1] for p in pts)
    return max(w / _SHOWN[0], h / _SHOWN[1], 0.05)


def _points(g: Grade) -> list[tuple[float, float]]:
    """Every point the overlay draws (or (0, 0) and (100, 100) if none)."""
    drawing, polygons = g.overlay
    pts = drawing.ends() + [lb.at for lb in drawing.labels]
    for c, r in drawing.circles:
        pts += [(c[0] - r, c[1] - r), (c[0] + r, c[1] + r)]
    for drawn in polygons:
        if drawn is not None:
            pts += [tuple(drawn[2]), *map(tuple, drawn[3].values())]
    for item in g.items:
        pts += [tuple(p) for p in (item.expected, item.found) if _at(p)]
    return pts or [(0.0, 0.0), (100.0, 100.0)]


def _at(p) -> bool:
    """Whether an item's expected or found value is a point on the paper."""
    return isinstance(p, list) and len(p) == 2 and all(math.isfinite(v) for v in p)


def _bounds(g: Grade, boxes, unit: float) -> tuple[float, float, float, float]:
    """The box holding every point and every text drawn so far, a ring's width about it."""
    pts = _points(g)
    ring = (_RING + 0.5) * unit
    x0, y0 = min(p[0] for p in pts) - ring, min(p[1] for p in pts) - ring
    x1, y1 = max(p[0] for p in pts) + ring, max(p[1] for p in pts) + ring
    for bx0, by0, bx1, by1 in boxes:
        x0, y0, x1, y1 = min(x0, bx0), min(y0, by0), max(x1, bx1), max(y1, by1)
    return x0, y0, x1, y1


def _box(text: str, at, fs: float, measure=sans_width) -> tuple[float, float, float, float]:
    """The box a text of size ``fs`` set from ``at`` (its baseline's left end) covers."""
    return (at[0], at[1] - fs, at[0] + measure(text, fs), at[1] + 0.3 * fs)


def _overlaps(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _wrong(items: list[Item]) -> list[Item]:
    """The items the overlay marks: every one not correct."""
    return [i for i in items if i.verdict != "correct"]


def _rings(dwg, items: list[Item], unit: float, boxes: list, lines: list) -> None:
    """Ring each item not correct (at what was found, else where it was expected), draw
    an arrow from where it was found to where it belongs, and set its verdict beside the
    ring where the label covers no other label and crosses the fewest ``lines``."""
    fs = _TEXT * unit
    lines = list(lines) + [(tuple(i.found), tuple(i.expected)) for i in _wrong(items)
                           if _at(i.found) and _at(i.expected)]
    marks = dwg.add(dwg.g(stroke_width=_num(0.4 * unit), fill="none"))
    said = dwg.add(dwg.g(font_size=_num(fs), font_family="DejaVu Sans"))
    for item in _wrong(items):
        at = item.found if _at(item.found) else item.expected
        if not _at(at):
            continue
        colour = AMBER if item.verdict == FOLLOWS else RED
        marks.add(dwg.circle(tuple(at), _RING * unit, stroke=colour))
        if _at(item.found) and _at(item.expected) and \
                math.dist(item.found, item.expected) > _RING * unit:
            marks.add(dwg.line(tuple(item.found), tuple(item.expected), stroke=colour))
            marks.add(_head(dwg, item.found, item.expected, unit, colour))
        text = f"{named(item.name)}: {words(item.verdict)}"
        box = _place(text, at, fs, unit, boxes, lines)
        boxes.append(box)
        said.add(_said(dwg, text, (box[0], box[3] - 0.3 * fs), fill=colour))


def _head(dwg, tail, tip, unit: float, colour: str):
    """An arrowhead at ``tip`` of the line from ``tail``: where the item belongs."""
    ux, uy = tip[0] - tail[0], tip[1] - tail[1]
    n = math.hypot(ux, uy)
    ux, uy = ux / n, uy / n
    size = 1.6 * unit
    left = (tip[0] - size * ux + 0.45 * size * uy, tip[1] - size * uy - 0.45 * size * ux)
    right = (tip[0] - size * ux - 0.45 * size * uy, tip[1] - size * uy + 0.45 * size * ux)
    return dwg.polygon([tuple(tip), left, right], fill=colour, stroke="none")


def _place(text: str, at, fs: float, unit: float, boxes: list, lines: list) -> tuple:
    """The box of a verdict's label beside the ring at ``at``: of the eight places about
    it, the first that covers no label and crosses no line, else the one that covers the
    fewest labels and then crosses the fewest lines."""
    r = (_RING + 0.6) * unit
    w = sans_width(text, fs)
    h = 1.3 * fs
    best, fewest = None, None
    for dx, dy in ((1, -1), (1, 1), (-1, -1), (-1, 1), (1, 0), (-1, 0), (0, -1), (0, 1)):
        x = at[0] + (r if dx > 0 else -r - w if dx < 0 else -w / 2)
        y = at[1] + (-r - h if dy < 0 else r if dy > 0 else -h / 2)
        box = (x, y, x + w, y + h)
        hits = (sum(_overlaps(box, b) for b in boxes),
                sum(_crosses(box, a, b) for a, b in lines))
        if hits == (0, 0):
            return box
        if fewest is None or hits < fewest:
            best, fewest = box, hits
    return best


def _crosses(box, a, b) -> bool:
    """Whether the segment ``a``–``b`` passes through ``box`` (Liang–Barsky clipping)."""
    t0, t1 = 0.0, 1.0
    dx, dy = b[0] - a[0], b[1] - a[1]
    for p, q in ((-dx, a[0] - box[0]), (dx, box[2] - a[0]), (-dy, a[1] - box[1]),
                 (dy, box[3] - a[1])):
        if p == 0:
            if q < 0:
                return False
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return False
    return True


def _legend_entries(items: list[Item]) -> list[tuple[str, str]]:
    """The legend's samples (their kind) and words."""
    out = [("grey", words("your drawing")), ("blue", words("expected")),
           ("red", words("graded wrong"))]
    if any(i.verdict == FOLLOWS for i in items):
        out.append(("amber", words(FOLLOWS)))
    return out


def _legend_width(items: list[Item], unit: float) -> float:
    fs = _SMALL * unit
    return sum(9.0 * unit + sans_width(t, fs) + 4.0 * unit for _, t in _legend_entries(items))


def _legend(dwg, items: list[Item], span: tuple[float, float], y: float, unit: float) -> float:
    """The legend on one line at ``y`` (from the right in Persian); the y under it."""
    fs = _SMALL * unit
    rtl = right_to_left()
    x = span[1] if rtl else span[0]
    way = -1.0 if rtl else 1.0
    key = dwg.add(dwg.g(font_size=_num(fs), font_family="DejaVu Sans", fill="#333"))
    for kind, text in _legend_entries(items):
        a, b = x, x + way * 7.0 * unit
        mid = y - 0.35 * fs
        if kind == "grey":
            key.add(dwg.line((a, mid), (b, mid), stroke=GREY, stroke_width=_num(0.35 * unit)))
        elif kind == "blue":
            key.add(dwg.line((a, mid), (b, mid), stroke=BLUE, stroke_width=_num(0.35 * unit),
                             stroke_dasharray=f"{1.6 * unit:.4g},{0.8 * unit:.4g}"))
        else:
            key.add(dwg.circle(((a + b) / 2, mid), 1.3 * unit, fill="none",
                               stroke=RED if kind == "red" else AMBER,
                               stroke_width=_num(0.4 * unit)))
        start = b + way * 2.0 * unit
        width = sans_width(text, fs)
        left = start if not rtl else start - width
        key.add(_said(dwg, text, (left, y)))
        x = start + way * (width + 4.0 * unit)
    return y + 0.6 * fs


def _notes(items: list[Item], width: float, unit: float) -> list[tuple[str, str]]:
    """The lines under the legend, with their colours: each item not correct, its verdict
    and tolerance, then its advice wrapped to ``width``."""
    fs = _SMALL * unit
    out = []
    for item in _wrong(items):
        head = f"{named(item.name)}: {words(item.verdict)}"
        if item.tolerance is not None:
            head += " (± " + measure_words(f"{item.tolerance:.3g} mm") + ")"
        out.append((head, AMBER if item.verdict == FOLLOWS else RED))
        out += [(part, _ADVICE) for part in wrap_text(item.message, fs, width,
                                                      measure=sans_width)]
    return out


def _line(dwg, text: str, span: tuple[float, float], y: float, **style):
    """A line of text across ``span``, set from its reading edge: the left, or in a
    right-to-left language the right (a Persian line there, an English one aligned to
    it)."""
    if not right_to_left():
        return dwg.text(text, insert=(span[0], y), **style)
    if is_rtl(text):
        style |= {"direction": "rtl", "text_anchor": "start", "font_family": RTL_FONT}
    else:
        style |= {"text_anchor": "end"}
    return dwg.text(text, insert=(span[1], y), **style)


def _said(dwg, text: str, at: tuple[float, float], **style):
    """A text that reads on rightwards from ``at`` in either language: a Persian one is
    set right to left with its logical end at ``at``."""
    if is_rtl(text):
        style |= {"direction": "rtl", "text_anchor": "end", "font_family": RTL_FONT}
    return dwg.text(text, insert=at, **style)


def _num(v: float) -> str:
    """A size for an attribute, short and finite."""
    return f"{v:.4g}"
