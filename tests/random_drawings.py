"""Random students' drawings for ``tarsim grade``: right and wrong, written the way real
programs export SVG, and hostile ones.

The contract is tests/random_mechanisms.py's, for the grader: every drawing is either
graded, its grade.json and grade.svg holding finite numbers only, or refused with one
``TarsimError`` line (under 200 characters) that names the file and, where there is one,
its line or element. ``generate(rng)`` makes one case, ``(family, svg)``, its exercise and
position in a comment (``<!-- tarsim-case: crank-shaper 2 -->``); ``run_case`` grades it
against that bundled exercise and judges the outcome: ok, refused, refused-unclear, or
other (a traceback, a non-finite number in grade.json or grade.svg, a message of several
lines, a hang).

A drawing is a sheet of marks in paper mm (:func:`sheet`): tarsim's own velocity and
acceleration polygons, turned, mirrored, at the exercise's scale or the drawing's own, each
tip labelled as a course writes it; often with a student's error (a tip moved, labels
swapped, a tip left out, a Coriolis component reversed, a wrong scale written), the space
diagram's instant centres, and the clutter of a real sheet (a frame, a title, a grid,
construction lines). tests/svg_writers.py then lays it out as Inkscape, LibreOffice Draw,
GeoGebra, a CAD program or a student writes SVG.

Hostile drawings (:func:`hostile`) are made to break a reader: ``<use>`` that doubles or
loops, nesting ten thousand deep, numbers that overflow, pages of no size, entities, DTDs,
external links, XInclude, broken or truncated XML, odd encodings, files past every bound.

Run ``python tests/random_drawings.py --cases 3000 --seed 1 --timeout 20`` for the counts.
"""

from __future__ import annotations

import json
import math
import random
import re
import sys
import traceback
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from random_mechanisms import Outcome, classify_error  # noqa: E402
from svg_writers import WRITERS, hand, inkscape  # noqa: E402

__all__ = ["FAMILIES", "EXERCISES", "WRITERS", "generate", "sheet", "hostile", "run_case",
           "nonfinite_in"]

FAMILIES = ("inkscape", "libreoffice", "geogebra", "cad", "hand", "hostile")
"""The programs a drawing is written by, and the hostile drawings, equally likely."""

EXERCISES = (("crank-shaper", 1), ("crank-shaper", 2), ("four-bar", 1), ("whitworth", 1),
             ("offset-slider-crank", 1), ("inverted-slider-crank", 1),
             ("six-link-homework-1", 1), ("hinkle-four-bar", 1))
"""The bundled exercises and positions (from 1, as ``--position`` counts) drawn."""

_TAG = re.compile(r"tarsim-case: (\S+) (\d+)")
_SOLVED: dict[str, list] = {}


def _positions(name: str) -> list:
    """The exercise's positions, solved once a process."""
    if name not in _SOLVED:
        import tarsim
        from tarsim.exercises.linkages.solution import solve_positions

        _SOLVED[name] = (tarsim.load(name), solve_positions(tarsim.load(name)))
    return _SOLVED[name]


# ----- the sheet: what a student drew, in paper mm, y down ------------------------------------
def _label(rng: random.Random, name: str, kind: str) -> list[tuple[str, str]]:
    """A tip's or pole's label as a course writes it, as (text, role) runs: role "sub" for a
    subscript set apart."""
    prime = rng.choice(["′", "'", "’"]) if kind == "a" else ""
    if name == "o":
        return rng.choice([[("o", ""), ("v" if not prime else "a", "sub")],
                           [("o" + prime, "")], [("O" + prime, "")],
                           [("o_" + ("a" if prime else "v"), "")]])
    letters, digits = name.rstrip("0123456789"), name[len(name.rstrip("0123456789")):]
    letters = letters.upper() if rng.random() < 0.2 else letters
    if not digits:
        return [(letters + prime, "")]
    sub = "".join(chr(0x2080 + int(d)) for d in digits)
    return rng.choice([[(letters, ""), (digits + prime, "sub")], [(letters + sub + prime, "")],
                       [(letters + digits + prime, "")], [(letters + "_" + digits + prime, "")]])


def _polygon(rng: random.Random, sol, kind: str, pole, marks: list) -> None:
    """One of the position's polygons drawn about ``pole``, right or with a student's error."""
    from drawings import polygon_of

    tips, cor = polygon_of(sol, kind)
    per_cm = (sol.work.scales.velocity_polygon if kind == "v"
              else sol.work.scales.acceleration_polygon)
    biggest = max(math.hypot(*v) for v in tips.values()) or 1.0
    stated = 10.0 / (per_cm * sol.work.mechanism.units.metres) if per_cm else None
    scale = stated if stated and rng.random() < 0.6 else rng.uniform(40, 150) / biggest
    if rng.random() < 0.15:                              # a scale written on the sheet
        unit = "m/s²" if kind == "a" else "m/s"
        said = 1.0 / (scale / 10.0) * rng.choice([1.0, 1.0, 1.25, 0.8])
        marks.append(("text", (pole[0] - 40, pole[1] + 60), [(f"1 cm = {said:.4g} {unit}", "")]))
    turn, mirror = math.radians(rng.choice([0, 0, 90, rng.uniform(-180, 180)])), \
        rng.random() < 0.3
    error = rng.choice(["none"] * 4 + ["moved", "swapped", "left-out", "coriolis", "extra"])
    names = list(tips)
    moved = rng.choice(names)
    where = {}
    for n, v in tips.items():
        if error == "coriolis" and cor and n.rstrip("0123456789") in cor and n != \
                n.rstrip("0123456789"):
            c = cor[n.rstrip("0123456789")]
            v = (v[0] - 2 * c[0], v[1] - 2 * c[1])
        x, y = v[0] * scale, (v[1] if mirror else -v[1]) * scale
        p = (pole[0] + math.cos(turn) * x - math.sin(turn) * y,
             pole[1] + math.sin(turn) * x + math.cos(turn) * y)
        if error == "moved" and n == moved:
            p = (p[0] + rng.uniform(-15, 15), p[1] + rng.uniform(-15, 15))
        where[n] = p
    labels = {n: n.lower() for n in where}
    if error == "swapped" and len(names) > 1:
        a, b = rng.sample(names, 2)
        labels[a], labels[b] = labels[b], labels[a]
    for n, p in where.items():
        if error == "left-out" and n == moved or math.dist(p, pole) < 0.3:
            continue
        marks.append(("arrow" if rng.random() < 0.7 else "line", pole, p))
        if rng.random() < 0.3:                           # a dot at the tip
            marks.append(("dot", p, rng.uniform(0.3, 1.0)))
        off = (rng.uniform(-3, 3), rng.uniform(-3, 3))
        marks.append(("text", (p[0] + off[0], p[1] + off[1]), _label(rng, labels[n], kind)))
    if error == "extra":
        marks.append(("text", (pole[0] + 30, pole[1] - 30), [("z9", "")]))
        marks.append(("line", (pole[0] + 28, pole[1] - 28), (pole[0] + 10, pole[1] - 10)))
    marks.append(("text", (pole[0] - 4, pole[1] + 4), _label(rng, "o", kind)))
    if rng.random() < 0.4:                               # construction lines through tips
        for p in rng.sample(list(where.values()), min(2, len(where))):
            a = rng.uniform(0, math.pi)
            marks.append(("line", (p[0] - 30 * math.cos(a), p[1] - 30 * math.sin(a)),
                          (p[0] + 30 * math.cos(a), p[1] + 30 * math.sin(a))))


def _centres(rng: random.Random, sol, marks: list) -> None:
    """The space diagram: the mechanism's points and finite instant centres as dots."""
    points = sol.work.kinematics.points
    span = max(math.dist(p, q) for p in points.values() for q in points.values()) or 1.0
    k = rng.uniform(60, 120) / span
    turn, mirror = math.radians(rng.choice([0, 90, rng.uniform(-180, 180)])), \
        rng.random() < 0.2
    c, s = math.cos(turn), math.sin(turn)

    def place(p):
        x, y = p[0] * k, (p[1] if mirror else -p[1]) * k
        return (105.0 + c * x - s * y, 200.0 + s * x + c * y)
    for name, p in points.items():
        marks += [("dot", place(p), 0.8), ("text", (place(p)[0] + 1.2, place(p)[1] - 1.2),
                                           [(name, "")])]
    for name, q in sol.quantities.items():
        if re.fullmatch(r"I\d\d", name) and "point" in q.reference and rng.random() < 0.8:
            at = place(q.reference["point"])
            if abs(at[0]) < 2000 and abs(at[1]) < 2000:
                marks += [("dot", at, 0.6), ("text", (at[0] + 1.2, at[1] - 1.2),
                                             [(rng.choice([name, name[1:]]), "")])]


def sheet(rng: random.Random, name: str, position: int) -> list[tuple]:
    """What a student drew for ``name`` at ``position``: marks ("line", a, b), ("arrow", a,
    b), ("dot", centre, r) and ("text", anchor, runs), in paper mm, y down."""
    ex, positions = _positions(name)
    sol = positions[position - 1]
    marks: list[tuple] = []
    kinds = ["v"] + (["a"] if sol.work.has("acceleration polygon") else [])
    for k, kind in enumerate(rng.sample(kinds, rng.randint(1, len(kinds)))):
        _polygon(rng, sol, kind, (rng.uniform(40, 90) + 100 * k, rng.uniform(60, 110)), marks)
    if rng.random() < 0.3 and any(q.startswith("I") for q in sol.quantities):
        _centres(rng, sol, marks)
    if rng.random() < 0.3:                               # a frame and a title block
        marks += [("line", (10, 10), (200, 10)), ("line", (200, 10), (200, 287)),
                  ("line", (200, 287), (10, 287)), ("line", (10, 287), (10, 10)),
                  ("text", (120, 280), [(f"{ex.id}, student 7", "")])]
    if rng.random() < 0.1:                               # a grid
        marks += [("line", (x, 10), (x, 287)) for x in range(10, 201, 10)]
    return marks


# ----- hostile drawings -----------------------------------------------------------------------
_SVG = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" ' \
       'width="210mm" height="297mm" viewBox="0 0 210 297">'
_OA = '<text x="10" y="10">o</text><text x="60" y="10">a</text>' \
      '<line x1="10" y1="10" x2="60" y2="10" stroke="black"/>'


def _doubling(levels: int, twice: int = 2) -> str:
    groups = ['<g id="l0">' + _OA + "</g>"]
    for k in range(1, levels + 1):
        groups.append(f'<g id="l{k}">' + f'<use xlink:href="#l{k - 1}"/>' * twice + "</g>")
    return _SVG + "".join(groups) + "</svg>"


def _nested(depth: int, open_: str, close: str) -> str:
    return _SVG + open_ * depth + _OA + close * depth + "</svg>"


HOSTILE_KINDS = ("use-doubling", "use-loop", "use-chain", "nesting", "overflow", "page",
                 "entity", "external", "broken", "encoding", "huge", "labels", "quirks",
                 "mutated")

QUIRKS = ('<rect x="0" y="0" width="10" height="5" rx="20" ry="-3"/>',
          '<ellipse cx="1" cy="1" rx="0" ry="5"/>', '<path d="M 0 0 A 0 0 0 0 1 10 10"/>',
          '<path d="M0,0a5,5 0 011,1"/>', '<path d="M 0 0 L"/>', '<path d="L 5 5"/>',
          '<path d="M 0 0 Q 1 1"/>', '<path d="M0 0zzzz"/>',
          '<path d="m1e-320 1e-320 l 1e-320 0"/>',
          '<path d="M 0 0 C 1 1 2 2"/>', '<path d=""/>', '<polyline points="1 2 3"/>',
          '<polygon points=""/>', '<text x="5mm" y="1in">b</text>',
          '<text x="5%" y="7em">b</text>', '<circle cx="5%" cy="2em" r="1ex"/>',
          '<text dx="3" dy="2">b</text>', '<text x="1 2 3" y="4,5">b</text>',
          '<use href="#t"/><text id="t" x="1" y="1">b</text>',
          '<use href="#d"/><defs id="d"><line x1="0" y1="0" x2="1" y2="1"/></defs>',
          '<svg x="5" y="5" width="50%" height="50%" viewBox="0 0 1 1" preserveAspectRatio="none">'
          '<line x1="0" y1="0" x2="1" y2="1"/></svg>', '<use href="#"/>', '<use href=""/>',
          '<use/>', '<use href="#missing"/>', '<circle r="-1"/>', '<circle/>', '<line/>',
          '<text/>', '<tspan>b</tspan>', '<g transform="rotate(90deg)"><line x2="3"/></g>',
          '<g transform="translate(1mm 2in)"><line x2="3"/></g>', '<g transform="  "/>',
          '<g transform="scale(0)"><line x1="0" y1="0" x2="5" y2="5"/><text x="1">b</text></g>',
          '<g transform="matrix(0 0 0 0 0 0)"><circle cx="1" cy="1" r="1"/></g>',
          '<g transform="scale(1e-300)"><circle cx="1" cy="1" r="1"/></g>',
          '<text><textPath href="#p">b</textPath></text><path id="p" d="M 0 0 L 9 9"/>',
          '<a href="#x"><line x1="0" y1="0" x2="5" y2="0"/></a>', '<switch><text>b</text></switch>',
          '<symbol id="s2"><circle r="1"/></symbol>', '<use href="#s2" transform="skewX(89.99)"/>',
          '<text x="1" y="1">\u202eb\u200d</text>', '<text x="1" y="1">b&#x0301;</text>',
          '<text x="3" y="3"><tspan x="1" y="1">o</tspan><tspan x="9" y="9">′</tspan></text>',
          '<line x1="1" y1="1" x2="1" y2="1"/>', '<circle cx="1" cy="1" r="0"/>',
          '<svg width="0" height="0"><line x2="1"/></svg>')


def hostile(rng: random.Random) -> str | bytes:
    """A drawing made to break a reader."""
    kind = rng.choice(HOSTILE_KINDS)
    if kind == "use-doubling":
        return _doubling(rng.randint(3, 40), rng.randint(2, 5))
    if kind == "use-loop":
        return rng.choice([
            _SVG + '<g id="a"><use xlink:href="#a"/></g>' + _OA + "</svg>",
            _SVG + '<g id="a"><use href="#b"/></g><g id="b"><use href="#a"/></g></svg>',
            _SVG + '<use id="u" xlink:href="#u"/>' + _OA + "</svg>",
            _SVG.replace("<svg ", '<svg id="root" ') + '<use href="#root"/></svg>',
            _SVG + '<defs><symbol id="s"><use href="#s" x="1"/></symbol></defs>'
                   '<use href="#s"/></svg>'])
    if kind == "use-chain":
        n = rng.randint(10, 3000)
        return (_SVG + '<g id="c0">' + _OA + "</g>"
                + "".join(f'<g id="c{k}"><use href="#c{k - 1}" transform="translate(0.1,0)"/>'
                          "</g>" for k in range(1, n)) + "</svg>")
    if kind == "nesting":
        depth = rng.choice([63, 64, 65, 100, 1000, 10_000, 100_000])
        return rng.choice([_nested(depth, "<g>", "</g>"),
                           _nested(depth, '<g transform="scale(1.01)">', "</g>"),
                           _nested(depth, '<svg width="10" height="10">', "</svg>"),
                           _SVG + "<text>" + "<tspan>" * depth + "b" + "</tspan>" * depth
                           + "</text></svg>"])
    if kind == "overflow":
        big = rng.choice(["1e308", "1e309", "-1e400", "nan", "inf", "NaN", "1e12", "1e13",
                          "9" * 400, "1e-400", "0x10", "1e+308", "- 5", "5 mm", "3e38"])
        deep = rng.randint(1, 4)
        where = rng.choice([
            f'<circle cx="5" cy="5" r="{big}"/>', f'<circle cx="{big}" cy="5" r="1"/>',
            f'<line x1="0" y1="0" x2="{big}" y2="1"/>', f'<rect x="0" y="0" width="{big}" '
            'height="3"/>', f'<path d="M 0 0 L {big} 10"/>', f'<path d="M 0 0 A {big} {big} 0 '
            '0 1 10 10"/>', f'<polyline points="0,0 {big},5 7"/>',
            f'<g transform="scale({big})"><line x1="1" y1="1" x2="2" y2="2"/></g>',
            f'<g transform="matrix(1 0 0 1 {big} 0)"><circle cx="1" cy="1" r="1"/></g>',
            '<g transform="scale(1e200)">' * deep + '<circle cx="1" cy="1" r="1"/>' + "</g>" * deep,
            f'<text x="{big}" y="3">b</text>',
            f'<use href="#p" x="{big}"/><line id="p" x1="0" y1="0" x2="1" y2="1"/>',
            '<g transform="skewX(90)"><line x1="0" y1="0" x2="0" y2="5"/></g>',
            '<g transform="rotate(1e308)"><line x1="0" y1="0" x2="0" y2="5"/></g>',
            f'<text x="1" y="1">1 cm = {big} m/s</text>'])
        return _SVG + _OA + where + "</svg>"
    if kind == "page":
        attrs = rng.choice(['viewBox="0 0 0 0"', 'viewBox="0 0 -10 10"', 'viewBox="0 0 1e400 1"',
                            'viewBox="nan 0 10 10"', 'viewBox="0 0 10"', 'width="1e400"',
                            'width="0"', 'height="-5mm"', 'width="auto" height="auto"',
                            'width="100%" height="100%"', 'viewBox="0 0 1e-300 1e-300"',
                            'width="1e11mm" viewBox="0 0 1e-11 1e-11"',
                            'preserveAspectRatio="' + "x" * 5000 + '"'])
        return f'<svg xmlns="http://www.w3.org/2000/svg" {attrs}>{_OA}</svg>'
    if kind == "entity":
        return rng.choice([
            '<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;'
            '&a;&a;&a;&a;&a;"><!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;">]><svg xmlns="http://www.w3.'
            'org/2000/svg"><text x="1" y="1">&c;</text></svg>',
            '<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY x SYSTEM "file:///etc/passwd">]>'
            '<svg xmlns="http://www.w3.org/2000/svg"><text x="1" y="1">&x;</text></svg>',
            '<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY % p SYSTEM "http://127.0.0.1:9/x">%p;]>'
            '<svg xmlns="http://www.w3.org/2000/svg"/>',
            '<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "http://www.w3.org/Graphics/SVG/1.1/'
            'DTD/svg11.dtd"><svg xmlns="http://www.w3.org/2000/svg">' + _OA + "</svg>",
            '<svg xmlns="http://www.w3.org/2000/svg"><text x="1" y="1">&undefined;</text></svg>'])
    if kind == "external":
        return _SVG + _OA + rng.choice([
            '<use xlink:href="other.svg#a"/>', '<use href="http://127.0.0.1:9/x.svg#a"/>',
            '<image xlink:href="file:///etc/passwd" width="10" height="10"/>',
            '<image href="data:image/png;base64,iVBORw0KGgo=" width="10" height="10"/>',
            '<xi:include xmlns:xi="http://www.w3.org/2001/XInclude" href="/etc/passwd" '
            'parse="text"/>', '<style>@import url(http://127.0.0.1:9/x.css);</style>',
            '<foreignObject width="10" height="10"><div xmlns="http://www.w3.org/1999/xhtml">'
            'b</div></foreignObject>', '<script>while(1){}</script>',
            '<line x1="0" y1="0" x2="5" y2="5" style="fill:url(http://127.0.0.1:9/#x)"/>',
            '<a href="http://example.com"><text x="3" y="3">b</text></a>']) + "</svg>"
    if kind == "broken":
        good = inkscape(rng, sheet(rng, "crank-shaper", 2))
        cut = rng.randint(0, len(good))
        return rng.choice([good[:cut], good[:cut] + "<" + good[cut:], good.replace("</g>", "", 1),
                           good.replace("<text", "<text x=", 1), good.replace(">", "", 1),
                           good[:cut] + "\x00" + good[cut:], good[:cut] + "\x07" + good[cut:],
                           "not xml at all", "", " \n\t ", "<svg", "<svg/>",
                           '<svg xmlns="http://www.w3.org/2000/svg"></svg>',
                           "<html><body>b</body></html>",
                           '<svg xmlns="http://example.com/not-svg">' + _OA + "</svg>"])
    if kind == "encoding":
        good = hand(rng, sheet(rng, "four-bar", 1))
        plain = good.replace("′", "'")
        return rng.choice([
            good.encode("utf-16"), good.encode("utf-16-le"), b"\xef\xbb\xbf" + good.encode(),
            ('<?xml version="1.0" encoding="ISO-8859-1"?>' + plain.replace("o<", "\xf6<"))
            .encode("latin-1", "replace"), plain.replace("o<", "\xf6<").encode("latin-1",
                                                                                "replace"),
            ('<?xml version="1.0" encoding="klingon"?>' + plain).encode(),
            ('<?xml version="1.0" encoding="utf-32"?>' + plain).encode("utf-32"),
            bytes(rng.randrange(256) for _ in range(rng.randint(1, 3000))),
            good.replace(">b<", ">b\u202e4<").encode(),
            ("<svg xmlns='http://www.w3.org/2000/svg'><text x='1' y='1'>\ud800</text></svg>")
            .encode("utf-8", "surrogatepass")])
    if kind == "huge":
        which = rng.choice(["bytes", "elements", "path", "text", "attribute", "points",
                            "transform", "style", "ids"])
        if which == "bytes":
            return _SVG + _OA + "<!--" + "x" * 5_000_001 + "--></svg>"
        if which == "elements":
            return _SVG + _OA + '<line x1="0" y1="0" x2="1" y2="1"/>' * rng.choice(
                [19_990, 20_001, 60_000]) + "</svg>"
        if which == "path":
            return _SVG + _OA + '<path d="M 0 0' + " L 1 1" * rng.choice([150_000, 400_000]) \
                + '"/></svg>'
        if which == "points":
            return _SVG + _OA + ''.join(f'<polyline points="{"1,1 2,2 " * 2000}"/>'
                                        for _ in range(rng.randint(1, 60))) + "</svg>"
        if which == "text":
            return _SVG + _OA + '<text x="5" y="5">' + "1" * rng.choice([10_000, 2_000_000]) \
                + "</text></svg>"
        if which == "attribute":
            return _SVG + _OA + f'<g id="{"x" * 3_000_000}"><line x1="0" y1="0" x2="1" y2="1"/>' \
                + "</g></svg>"
        if which == "transform":
            return _SVG + '<g transform="' + "translate(1,1) " * rng.choice([60, 5000]) + '">' \
                + _OA * 50 + "</g></svg>"
        if which == "style":
            return _SVG + "<style>" + "a" * 100_000 + "</style>" + _OA * 500 + "</svg>"
        return _SVG + "".join(f'<line id="i{k}" x1="0" y1="0" x2="1" y2="1"/>'
                              for k in range(15_000)) + _OA + "</svg>"
    if kind == "labels":
        n = rng.choice([100, 499, 501, 3000])
        spot = rng.choice(["spread", "heap"])
        body = []
        for k in range(n):
            x, y = ((k % 70) * 3, (k // 70) * 3) if spot == "spread" else (50 + k * 1e-4, 50)
            body.append(f'<text x="{x}" y="{y}">{rng.choice("ob")}</text><line x1="{x}" '
                        f'y1="{y}" x2="{x + 0.5}" y2="{y}"/>')
        return _SVG + "".join(body) + "</svg>"
    if kind == "quirks":                               # valid, or nearly, and unusual
        return _SVG + _OA + "".join(rng.sample(QUIRKS, rng.randint(1, 6))) + "</svg>"
    good = rng.choice(list(WRITERS.values()))(rng, sheet(rng, *rng.choice(EXERCISES)))
    chars = list(good)
    for _ in range(rng.randint(1, 20)):                # a file damaged here and there
        k = rng.randrange(len(chars))
        chars[k] = rng.choice(['"', "<", ">", "&", "/", "e", "9", "-", ".", " ", "#", "\u2212"])
    return "".join(chars)


def generate(rng: random.Random, family: str | None = None) -> tuple[str, str | bytes]:
    """One case: its family and its drawing (text; bytes for an encoding that is not UTF-8),
    the exercise and position it is graded against named in its first comment."""
    family = family or rng.choice(FAMILIES)
    name, position = rng.choice(EXERCISES)
    tag = f"<!-- tarsim-case: {name} {position} -->"
    if family == "hostile":
        svg = hostile(rng)
        if isinstance(svg, str) and not svg.startswith("<?xml"):
            svg = tag + svg
        return family, svg
    svg = WRITERS[family](rng, sheet(rng, name, position))
    head, sep, rest = svg.partition("?>")
    return family, (head + sep + tag + rest) if sep and svg.startswith("<?xml") else tag + svg


# ----- grading a case -------------------------------------------------------------------------
_NUMERIC = ("x", "y", "x1", "y1", "x2", "y2", "cx", "cy", "r", "width", "height", "viewBox",
            "font-size", "stroke-width")


def nonfinite_in(files: dict[str, str]) -> str | None:
    """Where grade.json or grade.svg holds a number that is not finite, if anywhere."""
    def refuse(word):
        raise ValueError(word)
    if "grade.json" in files:
        try:
            json.loads(files["grade.json"], parse_constant=refuse)
        except ValueError as e:
            return f"grade.json holds {e}"
    for key, value in re.findall(r'\s([\w:-]+)="([^"]*)"', files.get("grade.svg", "")):
        if key in _NUMERIC:
            for n in re.split(r"[\s,]+", value.strip().removesuffix("mm")):
                try:
                    if not math.isfinite(float(n.removesuffix("mm"))):
                        return f"grade.svg has {key}={value!r}"
                except ValueError:
                    return f"grade.svg has {key}={value!r}"
    return None


def run_case(text: str | bytes, path: str | Path, *, render: bool = True) -> Outcome:
    """Write the drawing beside ``path`` (as ``<stem>.svg``), grade it as the command line
    does (``tarsim grade EXERCISE FILE -o FOLDER --position N``, the exercise and position
    its comment names, else the crank-shaper's second), and classify the outcome: the
    command must write finite grade.json and grade.svg, or print one ``Error:`` line naming
    the drawing. ``render`` is accepted for random_rotors.run_many; the files are always
    made."""
    from click.testing import CliRunner
    from tarsim.exercises.cli import cli

    data = text if isinstance(text, bytes) else text.encode("utf-8", "surrogatepass")
    svg = Path(path).with_suffix(".svg")
    svg.write_bytes(data)
    tag = _TAG.search(data[:400].decode("latin-1"))
    name, position = (tag[1], int(tag[2])) if tag else ("crank-shaper", 2)
    out = svg.with_name(svg.stem + "-graded")
    got = CliRunner().invoke(cli, ["grade", name, str(svg), "-o", str(out), "--position",
                                   str(position)], prog_name="tarsim")
    if got.exception is not None and not isinstance(got.exception, SystemExit):
        e = got.exception
        return Outcome("other", f"{type(e).__name__}: {e}".splitlines()[0][:300],
                       "".join(traceback.format_exception(e)))
    lines = got.output.strip().splitlines()
    if got.exit_code != 0:
        if got.exit_code != 1 or len(lines) != 1 or not lines[0].startswith("Error: "):
            return Outcome("other", f"exit {got.exit_code}, not one Error: line",
                           got.output[-2000:])
        message = lines[0].removeprefix("Error: ")
        outcome, why = classify_error(message, svg.name)
        if not message.startswith(svg.name):
            outcome, why = "refused-unclear", "does not lead with the drawing's name"
        if len(message) > 200:
            outcome, why = "refused-unclear", f"{len(message)} characters long"
        return Outcome(outcome, message, why)
    files = {f.name: f.read_text(encoding="utf-8") for f in out.glob("grade.*")}
    bad = "grade.json is not written" if "grade.json" not in files else nonfinite_in(files)
    if bad:
        return Outcome("other", bad)
    # Text quoted from the drawing (cx='inf' in a note) is the student's own.
    if re.search(r"(?i)(?<![a-z])[-+]?(nan|inf)(?![a-z])", re.sub(r"'[^']*'", "", got.output)):
        return Outcome("other", "the grade's table prints nan or inf", got.output)
    return Outcome("ok")


if __name__ == "__main__":
    from random_rotors import run_many

    sys.exit(run_many(generate, run_case, FAMILIES, "drawings"))
